// A graded worked solution written: text, JSON and a grading platform's results file.
#include <fmt/format.h>

#include "core/utf8.hpp"
#include "report/verdicts.hpp"

namespace tackle {

namespace {

std::string part_line(const SolutionGrade::Part& p) {
  if (!p.not_graded.empty()) return fmt::format("{}: not graded: {}\n", p.name, p.not_graded);
  return fmt::format("{}: {:g} of {:g} ({} of {})\n", p.name, p.score, p.max, p.done, p.of);
}

// What the wrong steps took: "2 incorrect steps, 0.5 points each".
std::string penalty_phrase(const SolutionGrade& g) {
  std::string out =
      fmt::format("{} incorrect step{}, {:g} points each", g.wrong, g.wrong == 1 ? "" : "s", g.penalty_each);
  if (g.penalty < g.penalty_each * static_cast<double>(g.wrong) - 1e-12) out += "; no more than the parts earned";
  return out;
}

}  // namespace

std::string solution_text(const SolutionGrade& g) {
  std::string out;
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r, note] = g.steps[i];
    out += fmt::format("step {} ({}): {}: {}\n", i + 1, step_name(step), verdict_name(r.verdict), r.summary);
    if (!note.empty()) out += "  " + note + "\n";
  }
  if (g.first_wrong) out += fmt::format("first wrong step: {}\n", *g.first_wrong);
  if (!g.used.empty()) out += "used: " + join(g.used) + "\n";
  if (!g.missing.empty()) out += "missing (needed for the unknowns asked): " + join(g.missing) + "\n";
  for (const auto& p : g.parts) out += part_line(p);
  if (g.wrong > 0 && g.penalty_each > 0) out += fmt::format("wrong steps: -{:g} ({})\n", g.penalty, penalty_phrase(g));
  out += fmt::format("score: {:g} of {:g}\n", g.score, g.max_score);
  return out;
}

std::string solution_json(const SolutionGrade& g) {
  std::string out = "{\n  \"version\": 1,\n  \"steps\": [";
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r, note] = g.steps[i];
    std::string line = result_line(r, step.text, "step " + std::to_string(i + 1));
    if (!note.empty()) line.insert(line.size() - 1, ",\"note\":" + json_quoted(note));
    out += (i ? ",\n    " : "\n    ") + line;
  }
  out += g.steps.empty() ? "],\n" : "\n  ],\n";
  auto list = [](const std::vector<std::string>& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + json_quoted(v[i]);
    return s + "]";
  };
  out += "  \"used\": " + list(g.used) + ",\n";
  out += "  \"missing\": " + list(g.missing) + ",\n";
  out += "  \"first_wrong\": " + (g.first_wrong ? std::to_string(*g.first_wrong) : std::string("null")) + ",\n";
  out += "  \"parts\": [";
  for (std::size_t i = 0; i < g.parts.size(); ++i) {
    const auto& p = g.parts[i];
    out += fmt::format(
        "{}{{\"name\": {}, \"graded\": {}, \"score\": {}, \"max_score\": {}, \"done\": {}, \"of\": {}{}}}",
        i ? ", " : "", json_quoted(p.name), p.not_graded.empty() ? "true" : "false", json_number(p.score),
        json_number(p.max), p.done, p.of, p.not_graded.empty() ? "" : ", \"not_graded\": " + json_quoted(p.not_graded));
  }
  out += "],\n";
  out += fmt::format("  \"wrong\": {},\n  \"penalty_each\": {},\n  \"penalty\": {},\n", g.wrong,
                     json_number(g.penalty_each), json_number(g.penalty));
  out += "  \"score\": " + json_number(g.score) + ",\n  \"max_score\": " + json_number(g.max_score) + "\n}\n";
  return out;
}

std::string solution_results(const SolutionGrade& g, ResultsFormat format) {
  // One test per step (feedback, no points of its own), one per part of the rubric, and what
  // the wrong steps took.
  const bool gradescope = format == ResultsFormat::gradescope;
  std::string tests;
  auto test = [&](const std::string& name, double score, double max, bool passed, const std::string& output) {
    tests += (tests.empty() ? "\n    " : ",\n    ") + platform_test(format, name, score, max, passed, output);
  };
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r, note] = g.steps[i];
    test("step " + std::to_string(i + 1) + ": " + step_name(step), 0, 0, r.verdict == Verdict::correct,
         verdict_name(r.verdict) + ": " + r.summary + (note.empty() ? "" : "; " + note));
  }
  for (const auto& p : g.parts) {
    if (!p.not_graded.empty()) {
      test(p.name, 0, 0, true, "not graded: " + p.not_graded);
      continue;
    }
    std::string output = fmt::format("{} of {}", p.done, p.of);
    if (!p.missing.empty()) output += (p.name == "answers" ? "; not answered: " : "; missing: ") + join(p.missing);
    test(p.name, p.score, p.max, p.score >= p.max, output);
  }
  if (g.wrong > 0 && g.penalty_each > 0) test("wrong steps", -g.penalty, 0, false, penalty_phrase(g));
  std::string out = "{\n  \"tests\": [" + tests + (tests.empty() ? "],\n" : "\n  ],\n");
  const std::string said = fmt::format("{:g} of {:g} points", g.score, g.max_score);
  if (gradescope)
    out += "  \"score\": " + json_number(g.score) + ",\n  \"output\": " + json_quoted(said) + "\n}\n";
  else
    out += "  \"gradable\": true,\n  \"score\": " + json_number(g.max_score > 0 ? g.score / g.max_score : 0.0) +
           ",\n  \"message\": " + json_quoted(said) + "\n}\n";
  return out;
}

}  // namespace tackle

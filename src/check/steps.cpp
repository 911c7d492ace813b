#include "check/steps.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "check/batch.hpp"
#include "description/yaml_reader.hpp"

namespace tackle {

namespace {

// At most this many steps in a solution: a worked solution is a page, not a batch.
constexpr std::size_t max_steps = 200;

bool is_balance(const Equation& e) { return e.kind == Equation::Kind::lmb || e.kind == Equation::Kind::amb; }

}  // namespace

std::vector<SolutionStep> read_solution(const std::string& text, const std::string& file) {
  Diagnostics diags;
  const yaml::Document doc = yaml::load(text, file, diags);
  diags.throw_if_any();
  const yaml::Node root = doc.root();
  std::vector<SolutionStep> out;
  if (!yaml::check_map(root, {"steps"}, "the solution", file, diags)) {
    diags.throw_if_any();
    return out;
  }
  const yaml::Node steps = root["steps"];
  if (!steps) diags.error(yaml::where(root, file), "the solution has no 'steps' (expected a list of {equation: ...} and {answer: ..., unknown: ...})");
  else if (yaml::is_list(steps, "'steps'", file, diags)) {
    if (steps.size() > max_steps)
      diags.error(yaml::where(steps, file), "'steps' has " + std::to_string(steps.size()) + " steps (at most " + std::to_string(max_steps) + ")");
    for (const yaml::Node item : steps) {
      if (!yaml::check_map(item, {"equation", "answer", "unknown"}, "a step", file, diags)) continue;
      SolutionStep s;
      if (item["equation"] && (item["answer"] || item["unknown"])) {
        diags.error(yaml::where(item, file), "a step is an equation or an answer, not both (expected {equation: ...} or {answer: ..., unknown: ...})");
        continue;
      }
      if (item["equation"]) {
        if (auto t = yaml::scalar(item["equation"], "'equation'", file, diags)) s.text = t->text;
      } else if (item["answer"]) {
        s.kind = SolutionStep::Kind::answer;
        if (auto t = yaml::scalar(item["answer"], "'answer'", file, diags)) s.text = t->text;
        if (!item["unknown"]) diags.error(yaml::where(item, file), "an answer needs its 'unknown' (e.g. {answer: \"2*m_B*F/(9*m_A + 4*m_B)\", unknown: T})");
        else if (auto u = yaml::scalar(item["unknown"], "'unknown'", file, diags)) s.unknown = u->text;
      } else {
        diags.error(yaml::where(item, file), "a step needs 'equation' or 'answer'");
        continue;
      }
      out.push_back(std::move(s));
    }
  }
  diags.throw_if_any();
  return out;
}

Rubric read_rubric(const std::string& text, const std::string& file) {
  Diagnostics diags;
  const yaml::Document doc = yaml::load(text, file, diags);
  diags.throw_if_any();
  const yaml::Node root = doc.root();
  Rubric r;
  if (!yaml::check_map(root, {"balances", "constraints", "answers"}, "the rubric", file, diags)) {
    diags.throw_if_any();
    return r;
  }
  for (const auto& [key, field] : {std::pair{"balances", &r.balances}, std::pair{"constraints", &r.constraints}, std::pair{"answers", &r.answers}}) {
    const yaml::Node n = root[key];
    if (!n) {
      *field = 0;  // a part the rubric does not name is not graded
      continue;
    }
    const auto t = yaml::scalar(n, std::string("'") + key + "'", file, diags);
    if (!t) continue;
    char* end = nullptr;
    const double v = std::strtod(t->text.c_str(), &end);
    if (t->text.empty() || *end != '\0' || !(v >= 0) || v > 1000)
      diags.error(yaml::where(n, file), std::string("'") + key + "' is not a number of points (expected a number from 0 to 1000)");
    else
      *field = v;
  }
  diags.throw_if_any();
  return r;
}

SolutionGrade grade_solution(const Checker& checker, const std::vector<SolutionStep>& steps, const Rubric& rubric) {
  SolutionGrade g;
  std::set<std::string> used;
  std::set<std::string> answered;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const SolutionStep& s = steps[i];
    CheckResult r = s.kind == SolutionStep::Kind::equation ? checker.check_equation(s.text) : checker.check(s.unknown, s.text);
    if (r.verdict == Verdict::correct) {
      for (const auto& l : r.follows_from) used.insert(l);
      if (s.kind == SolutionStep::Kind::answer) answered.insert(s.unknown);
    } else if (!g.first_wrong) {
      g.first_wrong = i + 1;
    }
    g.steps.push_back({s, std::move(r)});
  }
  // What the asked unknowns need, in the derivation's order of asking.
  std::vector<std::string> needed;
  for (const auto& u : checker.asked())
    for (const auto& l : checker.needed_for(u))
      if (std::find(needed.begin(), needed.end(), l) == needed.end()) needed.push_back(l);
  for (const auto& l : needed)
    if (!used.count(l)) g.missing.push_back(l);
  // Used, in the order the derivation has them (the needed ones first, then any other).
  for (const auto& l : needed)
    if (used.count(l)) g.used.push_back(l);
  for (const auto& l : used)
    if (std::find(g.used.begin(), g.used.end(), l) == g.used.end()) g.used.push_back(l);
  auto part = [&](const std::string& name, double points, std::size_t done, std::size_t of, std::vector<std::string> missing) {
    if (points <= 0) return;
    SolutionGrade::Part p{name, of == 0 ? points : points * static_cast<double>(done) / static_cast<double>(of), points, done, of,
                          std::move(missing)};
    g.parts.push_back(p);
    g.score += p.score;
    g.max_score += p.max;
  };
  std::size_t balances = 0, balances_done = 0, constraints = 0, constraints_done = 0;
  std::vector<std::string> balances_missing, constraints_missing, answers_missing;
  for (const auto& l : needed) {
    const Equation* e = checker.derivation_equation(l);
    const bool balance = e && is_balance(*e);
    (balance ? balances : constraints) += 1;
    if (used.count(l)) (balance ? balances_done : constraints_done) += 1;
    else (balance ? balances_missing : constraints_missing).push_back(l);
  }
  part("balances", rubric.balances, balances_done, balances, balances_missing);
  part("constraints", rubric.constraints, constraints_done, constraints, constraints_missing);
  std::size_t answers_done = 0;
  for (const auto& u : checker.asked()) {
    answers_done += answered.count(u);
    if (!answered.count(u)) answers_missing.push_back(u);
  }
  part("answers", rubric.answers, answers_done, checker.asked().size(), answers_missing);
  return g;
}

std::string solution_text(const SolutionGrade& g) {
  std::string out;
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r] = g.steps[i];
    out += fmt::format("step {} ({}): {}: {}\n", i + 1, step.kind == SolutionStep::Kind::equation ? "equation" : "answer for " + step.unknown,
                       verdict_name(r.verdict), r.summary);
  }
  if (g.first_wrong) out += fmt::format("first wrong step: {}\n", *g.first_wrong);
  if (!g.used.empty()) out += "used: " + join(g.used) + "\n";
  if (!g.missing.empty()) out += "missing (needed for the unknowns asked): " + join(g.missing) + "\n";
  for (const auto& p : g.parts) out += fmt::format("{}: {:g} of {:g} ({} of {})\n", p.name, p.score, p.max, p.done, p.of);
  out += fmt::format("score: {:g} of {:g}\n", g.score, g.max_score);
  return out;
}

std::string solution_json(const SolutionGrade& g) {
  std::string out = "{\n  \"version\": 1,\n  \"steps\": [";
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r] = g.steps[i];
    out += (i ? ",\n    " : "\n    ") + result_line(r, step.text, "step " + std::to_string(i + 1));
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
    out += fmt::format("{}{{\"name\": {}, \"score\": {}, \"max_score\": {}, \"done\": {}, \"of\": {}}}", i ? ", " : "",
                       json_quoted(p.name), json_number(p.score), json_number(p.max), p.done, p.of);
  }
  out += "],\n";
  out += "  \"score\": " + json_number(g.score) + ",\n  \"max_score\": " + json_number(g.max_score) + "\n}\n";
  return out;
}

std::string solution_results(const SolutionGrade& g, ResultsFormat format) {
  // One test per step (feedback, no points of its own) and one per part of the rubric.
  const bool gradescope = format == ResultsFormat::gradescope;
  std::string tests;
  auto test = [&](const std::string& name, double score, double max, bool passed, const std::string& output) {
    tests += (tests.empty() ? "\n    " : ",\n    ") + platform_test(format, name, score, max, passed, output);
  };
  for (std::size_t i = 0; i < g.steps.size(); ++i) {
    const auto& [step, r] = g.steps[i];
    test("step " + std::to_string(i + 1) + (step.kind == SolutionStep::Kind::equation ? ": equation" : ": answer for " + step.unknown), 0, 0,
         r.verdict == Verdict::correct, verdict_name(r.verdict) + ": " + r.summary);
  }
  for (const auto& p : g.parts) {
    std::string output = fmt::format("{} of {}", p.done, p.of);
    if (!p.missing.empty()) output += (p.name == "answers" ? "; not answered: " : "; missing: ") + join(p.missing);
    test(p.name, p.score, p.max, p.score >= p.max, output);
  }
  std::string out = "{\n  \"tests\": [" + tests + (tests.empty() ? "],\n" : "\n  ],\n");
  const std::string said = fmt::format("{:g} of {:g} points", g.score, g.max_score);
  if (gradescope) out += "  \"score\": " + json_number(g.score) + ",\n  \"output\": " + json_quoted(said) + "\n}\n";
  else out += "  \"gradable\": true,\n  \"score\": " + json_number(g.max_score > 0 ? g.score / g.max_score : 0.0) +
              ",\n  \"message\": " + json_quoted(said) + "\n}\n";
  return out;
}

}  // namespace tackle

#include "check/steps.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "check/batch.hpp"
#include "description/yaml_reader.hpp"

namespace tackle {

namespace {

// At most this many steps in a solution: a worked solution is a page, not a batch.
constexpr std::size_t max_steps = 200;

bool is_balance(const Equation& e) { return e.kind == Equation::Kind::lmb || e.kind == Equation::Kind::amb; }

std::string step_name(const SolutionStep& s) {
  switch (s.kind) {
    case SolutionStep::Kind::equation: return "equation";
    case SolutionStep::Kind::answer: return "answer for " + s.unknown;
    default: return s.text;
  }
}

}  // namespace

std::vector<SolutionStep> read_solution(const std::string& text, const std::string& file, const Model& m) {
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
  if (!steps) diags.error(yaml::where(root, file), "the solution has no 'steps' (expected a list of {equation: ...}, {answer: ..., unknown: ...} and {fbd: ...})");
  else if (yaml::is_list(steps, "'steps'", file, diags)) {
    if (steps.size() > max_steps)
      diags.error(yaml::where(steps, file), "'steps' has " + std::to_string(steps.size()) + " steps (at most " + std::to_string(max_steps) + ")");
    for (const yaml::Node item : steps) {
      if (!yaml::check_map(item, {"equation", "answer", "unknown", "fbd"}, "a step", file, diags)) continue;
      SolutionStep s;
      if (item["fbd"]) {
        if (item["equation"] || item["answer"] || item["unknown"]) {
          diags.error(yaml::where(item, file), "a free body diagram is a step of its own (expected {fbd: {body: ..., forces: [...]}})");
          continue;
        }
        s.kind = SolutionStep::Kind::fbd;
        s.fbd = read_fbd(item["fbd"], m, file, diags);
        s.text = "free body diagram of " + join(s.fbd.bodies);
        out.push_back(std::move(s));
        continue;
      }
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
        diags.error(yaml::where(item, file), "a step needs 'equation', 'answer' or 'fbd'");
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
  if (!yaml::check_map(root, {"fbds", "balances", "constraints", "answers", "fbd"}, "the rubric", file, diags)) {
    diags.throw_if_any();
    return r;
  }
  double fbds = 0;
  for (const auto& [key, field] : {std::pair{"fbds", &fbds}, std::pair{"balances", &r.balances}, std::pair{"constraints", &r.constraints},
                                   std::pair{"answers", &r.answers}}) {
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
  if (root["fbds"]) r.fbds = fbds;
  if (root["fbd"]) r.fbd = read_fbd_rubric(root["fbd"], file, diags);
  diags.throw_if_any();
  return r;
}

SolutionGrade grade_solution(const Checker& checker, const Model& model, const std::vector<SolutionStep>& steps, const Rubric& rubric) {
  SolutionGrade g;
  std::set<std::string> used;
  std::set<std::string> answered;
  std::map<std::vector<std::string>, double> diagrams;  // sorted bodies -> the best score of a diagram of them (a fraction)
  bool any_diagram = false;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const SolutionStep& s = steps[i];
    CheckResult r;
    if (s.kind == SolutionStep::Kind::fbd) {
      any_diagram = true;
      std::vector<Diagnostic> problems;
      r = fbd_result(check_fbd(model, s.fbd, rubric.fbd, problems));
      if (!problems.empty()) r.summary = format(problems.front());
      std::vector<std::string> key = s.fbd.bodies;
      std::sort(key.begin(), key.end());
      if (r.verdict == Verdict::correct || r.verdict == Verdict::incorrect) diagrams[key] = std::max(diagrams[key], r.score);
      if (r.verdict != Verdict::correct && !g.first_wrong) g.first_wrong = i + 1;
      g.steps.push_back({s, std::move(r)});
      continue;
    }
    r = s.kind == SolutionStep::Kind::equation ? checker.check_equation(s.text) : checker.check(s.unknown, s.text);
    if (r.verdict == Verdict::correct) {
      for (const auto& l : r.follows_from) {
        used.insert(l);
        // A length sum counts for its derivatives (differentiating it is mechanical).
        if (const std::string d = checker.differentiated(l); !d.empty()) used.insert(d);
      }
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
  // The diagrams the needed balances are written from: one per body or system balanced.
  if (const double points = rubric.fbds.value_or(any_diagram ? 1.0 : 0.0); points > 0) {
    std::vector<std::vector<std::string>> wanted;
    for (const auto& l : needed) {
      const Equation* e = checker.derivation_equation(l);
      if (!e || !is_balance(*e) || e->bodies.empty()) continue;
      std::vector<std::string> key;
      for (int b : e->bodies) key.push_back(model.bodies[static_cast<std::size_t>(b)].name);
      std::sort(key.begin(), key.end());
      if (std::find(wanted.begin(), wanted.end(), key) == wanted.end()) wanted.push_back(key);
    }
    double done = 0;
    std::size_t whole = 0;  // diagrams with every force right
    std::vector<std::string> absent;
    for (const auto& key : wanted) {
      const auto it = diagrams.find(key);
      if (it != diagrams.end()) {
        done += it->second;
        whole += it->second >= 1 - 1e-9;
      }
      else absent.push_back(key.size() == 1 ? key.front() : "the system of " + join(key));
    }
    // A diagram of a body no needed balance is written for still counts when none is wanted.
    std::size_t of = wanted.size();
    if (wanted.empty())
      for (const auto& [key, score] : diagrams) {
        done += score;
        whole += score >= 1 - 1e-9;
        ++of;
      }
    SolutionGrade::Part p{"fbds", of == 0 ? 0.0 : points * done / static_cast<double>(of), points, 0, of, absent};
    p.done = whole;
    g.parts.push_back(p);
    g.score += p.score;
    g.max_score += p.max;
  }
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
    out += fmt::format("step {} ({}): {}: {}\n", i + 1, step_name(step), verdict_name(r.verdict), r.summary);
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
    test("step " + std::to_string(i + 1) + ": " + step_name(step), 0, 0, r.verdict == Verdict::correct, verdict_name(r.verdict) + ": " + r.summary);
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

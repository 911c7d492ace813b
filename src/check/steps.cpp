#include "check/steps.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "description/yaml_reader.hpp"

namespace tackle {

namespace {

// At most this many steps in a solution: a worked solution is a page, not a batch.
constexpr std::size_t max_steps = 200;

bool is_balance(const Equation& e) { return e.kind == Equation::Kind::lmb || e.kind == Equation::Kind::amb; }

}  // namespace

std::string step_name(const SolutionStep& s) {
  switch (s.kind) {
    case SolutionStep::Kind::equation: return "equation";
    case SolutionStep::Kind::answer: return "answer for " + s.unknown;
    default: return s.text;
  }
}

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
  if (!steps)
    diags.error(
        yaml::where(root, file),
        "the solution has no 'steps' (expected a list of {equation: ...}, {answer: ..., unknown: ...} and {fbd: ...})");
  else if (yaml::is_list(steps, "'steps'", file, diags)) {
    if (steps.size() > max_steps)
      diags.error(yaml::where(steps, file),
                  "'steps' has " + std::to_string(steps.size()) + " steps (at most " + std::to_string(max_steps) + ")");
    for (const yaml::Node item : steps) {
      if (!yaml::check_map(item, {"equation", "answer", "unknown", "fbd"}, "a step", file, diags)) continue;
      SolutionStep s;
      if (item["fbd"]) {
        if (item["equation"] || item["answer"] || item["unknown"]) {
          diags.error(yaml::where(item, file),
                      "a free body diagram is a step of its own (expected {fbd: {body: ..., forces: [...]}})");
          continue;
        }
        s.kind = SolutionStep::Kind::fbd;
        s.fbd = read_fbd(item["fbd"], m, file, diags);
        s.text = "free body diagram of " + join(s.fbd.bodies);
        out.push_back(std::move(s));
        continue;
      }
      if (item["equation"] && (item["answer"] || item["unknown"])) {
        diags.error(
            yaml::where(item, file),
            "a step is an equation or an answer, not both (expected {equation: ...} or {answer: ..., unknown: ...})");
        continue;
      }
      if (item["equation"]) {
        if (auto t = yaml::scalar(item["equation"], "'equation'", file, diags)) s.text = t->text;
      } else if (item["answer"]) {
        s.kind = SolutionStep::Kind::answer;
        if (auto t = yaml::scalar(item["answer"], "'answer'", file, diags)) s.text = t->text;
        if (!item["unknown"])
          diags.error(yaml::where(item, file),
                      "an answer needs its 'unknown' (e.g. {answer: \"2*m_B*F/(9*m_A + 4*m_B)\", unknown: T})");
        else if (auto u = yaml::scalar(item["unknown"], "'unknown'", file, diags))
          s.unknown = u->text;
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

Rubric read_rubric(const std::string& text, const std::string& file, const Model& m) {
  Diagnostics diags;
  const yaml::Document doc = yaml::load(text, file, diags);
  diags.throw_if_any();
  const yaml::Node root = doc.root();
  Rubric r;
  if (!yaml::check_map(root, {"fbds", "balances", "constraints", "answers", "penalty", "fbd"}, "the rubric", file,
                       diags)) {
    diags.throw_if_any();
    return r;
  }
  double fbds = 0, penalty = 0;
  for (const auto& [key, field] :
       {std::pair{"fbds", &fbds}, std::pair{"balances", &r.balances}, std::pair{"constraints", &r.constraints},
        std::pair{"answers", &r.answers}, std::pair{"penalty", &penalty}}) {
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
      diags.error(yaml::where(n, file),
                  std::string("'") + key + "' is not a number of points (expected a number from 0 to 1000)");
    else
      *field = v;
  }
  r.fbds = fbds;  // (only without a rubric do diagrams get a point of their own)
  if (root["penalty"]) r.penalty = penalty;
  if (root["fbd"]) {
    r.fbd = read_fbd_rubric(root["fbd"], file, diags);
    for (auto& d : fbd_rubric_problems(m, r.fbd)) diags.error(std::move(d.where), std::move(d.message));
  }
  diags.throw_if_any();
  return r;
}

std::vector<std::string> equations_given(const CheckResult& r) {
  if (r.combination.empty())
    return r.identified_as.empty() ? std::vector<std::string>{} : std::vector<std::string>{r.identified_as.front()};
  std::vector<std::string> out;
  for (const auto& p : r.combination) {
    if (!p.plain) return {};  // derived by eliminating unknowns
    out.push_back(p.label);
  }
  return out;
}

namespace {

// What the correct steps gave, as they are checked in turn.
struct Given {
  std::set<std::string> equations;  // the derivation's labels
  std::set<std::string> answered;
  std::map<std::vector<std::string>, double>
      diagrams;  // sorted bodies -> the best score of a diagram of them (a fraction)
  bool any_diagram = false;
};

std::string and_list(const std::vector<std::string>& v) {
  if (v.size() < 2) return join(v);
  return join(std::vector<std::string>(v.begin(), v.end() - 1)) + " and " + v.back();
}

// Why a correct equation that gives none of the derivation's equations earns nothing for them
// (with no combination known, the algebra could not tell a sum apart: none is assumed).
std::string derived_note(const CheckResult& r) {
  return "it earns no balance or constraint points: it is derived from " + and_list(r.follows_from) +
         " by eliminating unknowns, not written as " + (r.follows_from.size() == 1 ? "it" : "them or as their sum");
}

CheckResult grade_diagram(const Model& model, const SolutionStep& s, const FbdRubric& rubric, Given& given) {
  given.any_diagram = true;
  std::vector<Diagnostic> problems;
  CheckResult r = checked_fbd(model, s.fbd, rubric, problems);
  if (!problems.empty()) r.summary = format(problems.front());
  std::vector<std::string> key = s.fbd.bodies;
  std::sort(key.begin(), key.end());
  if (r.verdict == Verdict::correct || r.verdict == Verdict::incorrect)
    given.diagrams[key] = std::max(given.diagrams[key], r.score);
  return r;
}

SolutionGrade::Step grade_step(const Checker& checker, const Model& model, const SolutionStep& s,
                               const FbdRubric& rubric, Given& given) {
  if (s.kind == SolutionStep::Kind::fbd) return {s, grade_diagram(model, s, rubric, given), ""};
  CheckResult r =
      s.kind == SolutionStep::Kind::equation ? checker.check_equation(s.text) : checker.check(s.unknown, s.text);
  if (r.verdict != Verdict::correct) return {s, std::move(r), ""};
  if (s.kind == SolutionStep::Kind::answer) {
    given.answered.insert(s.unknown);
    return {s, std::move(r), ""};
  }
  const std::vector<std::string> labels = equations_given(r);
  for (const auto& l : labels) {
    given.equations.insert(l);
    // A length sum counts for its derivatives (differentiating it is mechanical).
    if (const std::string d = checker.differentiated(l); !d.empty()) given.equations.insert(d);
  }
  std::string note = labels.empty() ? derived_note(r) : "";
  return {s, std::move(r), std::move(note)};
}

// What the asked unknowns need: the fewest equations that determine each (in the order of
// asking), and the unknowns for which those cannot be determined.
struct Needs {
  std::vector<std::string> equations;
  std::vector<std::string> undetermined;
  std::string why_not;  // why no part that rests on the needed equations can be graded; empty: they can
};

Needs needs_of(const Checker& checker) {
  Needs n;
  for (const auto& u : checker.asked()) {
    const std::vector<std::string> labels = checker.needed_for(u);
    if (labels.empty()) n.undetermined.push_back(u);
    for (const auto& l : labels)
      if (std::find(n.equations.begin(), n.equations.end(), l) == n.equations.end()) n.equations.push_back(l);
  }
  if (checker.asked().empty())
    n.why_not = "the problem asks for no unknown that can be checked";
  else if (!n.undetermined.empty())
    n.why_not = "tackle cannot tell which equations " + and_list(n.undetermined) +
                (n.undetermined.size() == 1 ? " needs" : " need");
  return n;
}

SolutionGrade::Part not_graded(const std::string& name, const std::string& why) {
  SolutionGrade::Part p;
  p.name = name;
  p.not_graded = why;
  return p;
}

// `earned` (a sum of fractions) of `of` items, for `points`.
SolutionGrade::Part graded(const std::string& name, double points, double earned, std::size_t done, std::size_t of,
                           std::vector<std::string> missing) {
  return {name, points * earned / static_cast<double>(of), points, done, of, std::move(missing), ""};
}

std::string group_name(const std::vector<std::string>& key) {
  return key.size() == 1 ? key.front() : "the system of " + and_list(key);
}

// The diagrams the needed balances are written from: one per body or system balanced, each
// earning in proportion to its best diagram's score.
SolutionGrade::Part diagrams_part(const Checker& checker, const Model& model, const Needs& needs, const Given& given,
                                  double points) {
  if (!needs.why_not.empty()) return not_graded("fbds", needs.why_not);
  std::vector<std::vector<std::string>> wanted;
  for (const auto& l : needs.equations) {
    const Equation* e = checker.derivation_equation(l);
    if (!e || !is_balance(*e) || e->bodies.empty()) continue;
    std::vector<std::string> key;
    for (int b : e->bodies) key.push_back(model.bodies[static_cast<std::size_t>(b)].name);
    std::sort(key.begin(), key.end());
    if (std::find(wanted.begin(), wanted.end(), key) == wanted.end()) wanted.push_back(key);
  }
  if (wanted.empty()) return not_graded("fbds", "no balance is needed for the unknowns asked, so no diagram is");
  double earned = 0;
  std::size_t whole = 0;  // diagrams with every force right
  std::vector<std::string> absent;
  for (const auto& key : wanted) {
    const auto it = given.diagrams.find(key);
    if (it == given.diagrams.end()) {
      absent.push_back(group_name(key));
      continue;
    }
    earned += it->second;
    whole += it->second >= 1 - 1e-9;
  }
  return graded("fbds", points, earned, whole, wanted.size(), absent);
}

// The balances' and the constraints' parts: the needed ones the steps give.
void equation_parts(const Checker& checker, const Needs& needs, const Given& given, const Rubric& rubric,
                    std::vector<SolutionGrade::Part>& out) {
  std::size_t of[2] = {0, 0}, done[2] = {0, 0};
  std::vector<std::string> missing[2];
  for (const auto& l : needs.equations) {
    const Equation* e = checker.derivation_equation(l);
    const int k = e && is_balance(*e) ? 0 : 1;
    ++of[k];
    if (given.equations.count(l))
      ++done[k];
    else
      missing[k].push_back(l);
  }
  const char* names[2] = {"balances", "constraints"};
  const double points[2] = {rubric.balances, rubric.constraints};
  const char* none[2] = {"no balance is needed for the unknowns asked",
                         "no constraint is needed for the unknowns asked"};
  for (int k = 0; k < 2; ++k) {
    if (points[k] <= 0) continue;
    if (!needs.why_not.empty())
      out.push_back(not_graded(names[k], needs.why_not));
    else if (of[k] == 0)
      out.push_back(not_graded(names[k], none[k]));
    else
      out.push_back(graded(names[k], points[k], static_cast<double>(done[k]), done[k], of[k], missing[k]));
  }
}

SolutionGrade::Part answers_part(const Checker& checker, const Given& given, double points) {
  if (checker.asked().empty()) return not_graded("answers", "the problem asks for no unknown that can be checked");
  std::size_t done = 0;
  std::vector<std::string> missing;
  for (const auto& u : checker.asked()) {
    if (given.answered.count(u))
      ++done;
    else
      missing.push_back(u);
  }
  return graded("answers", points, static_cast<double>(done), done, checker.asked().size(), missing);
}

// Each incorrect step takes its share back: the rubric's `penalty`, else half of what one item
// graded is worth on average; never more than the parts earned.
void take_penalty(SolutionGrade& g, const Rubric& rubric) {
  std::size_t items = 0;
  for (const auto& p : g.parts)
    if (p.not_graded.empty()) items += p.of;
  g.penalty_each = rubric.penalty.value_or(items > 0 ? g.max_score / (2.0 * static_cast<double>(items)) : 0.0);
  for (const auto& s : g.steps) g.wrong += s.result.verdict == Verdict::incorrect;
  g.penalty = std::min(g.score, g.penalty_each * static_cast<double>(g.wrong));
  g.score -= g.penalty;
}

}  // namespace

SolutionGrade grade_solution(const Checker& checker, const Model& model, const std::vector<SolutionStep>& steps,
                             const Rubric& rubric, std::optional<std::chrono::steady_clock::time_point> deadline) {
  SolutionGrade g;
  Given given;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (deadline && std::chrono::steady_clock::now() >= *deadline) {
      CheckResult late;
      late.unknown = steps[i].unknown;
      late.equation = steps[i].kind == SolutionStep::Kind::equation;
      late.conclude(Verdict::undecided, "time_limit",
                    "not checked: the solution took longer than its time limit to check");
      g.steps.push_back({steps[i], std::move(late), ""});
    } else {
      g.steps.push_back(grade_step(checker, model, steps[i], rubric.fbd, given));
    }
    if (g.steps.back().result.verdict != Verdict::correct && !g.first_wrong) g.first_wrong = i + 1;
  }
  const Needs needs = needs_of(checker);
  // Used, in the order the derivation has them (the needed ones first, then any other).
  for (const auto& l : needs.equations) (given.equations.count(l) ? g.used : g.missing).push_back(l);
  for (const auto& l : given.equations)
    if (std::find(g.used.begin(), g.used.end(), l) == g.used.end()) g.used.push_back(l);
  if (const double points = rubric.fbds.value_or(given.any_diagram ? 1.0 : 0.0); points > 0)
    g.parts.push_back(diagrams_part(checker, model, needs, given, points));
  equation_parts(checker, needs, given, rubric, g.parts);
  if (rubric.answers > 0) g.parts.push_back(answers_part(checker, given, rubric.answers));
  for (const auto& p : g.parts) {
    g.score += p.score;
    g.max_score += p.max;
  }
  take_penalty(g, rubric);
  return g;
}

}  // namespace tackle

// Grading a worked solution as a whole (issue 41, "rubrics that measure work"): what the steps
// give, the parts not awarded, what wrong steps cost. Every figure is from the examples' hand
// derivations (their notes), never from tackle's own output. Sample 12.3 by hand: LMB A:
// 2T - F = m_A a_A; LMB B: -3T = m_B a_B; the string's length 3 x_B - 2 x_A + const, so
// 3 ddot(x_B) = 2 ddot(x_A); T = 2 m_B F/(9 m_A + 4 m_B), a_A = -9F/(9 m_A + 4 m_B),
// a_B = -6F/(9 m_A + 4 m_B). The three asked unknowns need the three equations.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>

#include "grade/batch.hpp"
#include "check/steps.hpp"

#include <nlohmann/json.hpp>
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

struct Made {
  std::unique_ptr<const Analysis> analysis;
  std::unique_ptr<const Checker> checker;
};

const Made& made(const std::string& example) {
  static std::map<std::string, Made> all;
  auto it = all.find(example);
  if (it == all.end()) {
    Made m;
    m.analysis = analyze_file(TACKLE_SOURCE_DIR "/examples/" + example + ".yaml", test::rules());
    m.checker = std::make_unique<const Checker>(*m.analysis);
    it = all.emplace(example, std::move(m)).first;
  }
  return it->second;
}

SolutionGrade grade(const std::string& example, const std::string& steps, const std::string& rubric) {
  const Made& m = made(example);
  const Model& model = m.analysis->model;
  return grade_solution(*m.checker, model, read_solution(steps, "s.yaml", model), read_rubric(rubric, "r.yaml", model));
}

// `steps` graded as examples/PLATFORM/pulley-solution/ grades them: its problem (sample 12.3
// asking T only), its rubric.
SolutionGrade grade_platform_example(const std::string& platform, const std::string& steps) {
  const std::string dir = TACKLE_SOURCE_DIR "/examples/" + platform + "/pulley-solution/";
  const auto a = analyze_file(dir + "problem.yaml", test::rules());
  const Checker c(*a);
  return grade_solution(c, a->model, read_solution(steps, "s.yaml", a->model),
                        read_rubric(read_text_file(dir + "rubric.yaml"), "rubric.yaml", a->model));
}

const char* const pulley = "sample-12.3-two-mass-pulley";
const char* const rubric10 = "balances: 4\nconstraints: 2\nanswers: 4\n";

// Every sign of each of sample 12.3's balances and of its constraint (the first of each as
// the derivation writes it, one right), and each answer with both signs: 14 steps, 6 right.
const char* const guessed_pulley = R"Y(steps:
  - equation: "2*T - F = m_A*ddot(x_A)"
  - equation: "2*T + F = m_A*ddot(x_A)"
  - equation: "-2*T - F = m_A*ddot(x_A)"
  - equation: "-2*T + F = m_A*ddot(x_A)"
  - equation: "-3*T = m_B*ddot(x_B)"
  - equation: "3*T = m_B*ddot(x_B)"
  - equation: "3*ddot(x_B) = 2*ddot(x_A)"
  - equation: "3*ddot(x_B) = -2*ddot(x_A)"
  - {answer: "2*F*m_B/(9*m_A + 4*m_B)", unknown: T}
  - {answer: "-2*F*m_B/(9*m_A + 4*m_B)", unknown: T}
  - {answer: "-9*F/(9*m_A + 4*m_B)", unknown: ddot(x_A)}
  - {answer: "9*F/(9*m_A + 4*m_B)", unknown: ddot(x_A)}
  - {answer: "-6*F/(9*m_A + 4*m_B)", unknown: ddot(x_B)}
  - {answer: "6*F/(9*m_A + 4*m_B)", unknown: ddot(x_B)}
)Y";

// Each sign of each term of `terms` (the left side's, then the right side's after '|'),
// every pattern: a YAML list of equation steps.
std::string every_sign(const std::vector<std::string>& lhs, const std::vector<std::string>& rhs) {
  std::string out;
  const std::size_t n = lhs.size() + rhs.size();
  for (std::size_t mask = 0; mask < (std::size_t{1} << n); ++mask) {
    auto side = [&](const std::vector<std::string>& terms, std::size_t first) {
      std::string s;
      for (std::size_t k = 0; k < terms.size(); ++k) s += ((mask >> (first + k)) & 1 ? " - " : " + ") + terms[k];
      return s;
    };
    out += "  - equation: \"0" + side(lhs, 0) + " = 0" + side(rhs, lhs.size()) + "\"\n";
  }
  return out;
}

// Each arrow of `arrows` (the start of a YAML flow map, and its direction) drawn each way:
// every pattern, a diagram of `body` each.
std::string every_sense(const std::string& body,
                        const std::vector<std::pair<std::string, std::vector<double>>>& arrows) {
  std::string out;
  for (std::size_t mask = 0; mask < (std::size_t{1} << arrows.size()); ++mask) {
    out += "  - fbd: {body: " + body + ", forces: [";
    for (std::size_t k = 0; k < arrows.size(); ++k) {
      std::string dir;
      for (const double d : arrows[k].second)
        dir += (dir.empty() ? "" : ", ") + fmt::format("{:g}", (mask >> k) & 1 ? -d : d);
      out += (k ? ", " : "") + arrows[k].first + ", direction: [" + dir + "]}";
    }
    out += "]}\n";
  }
  return out;
}

}  // namespace

TEST_CASE("Steps: a worked solution graded as a whole, with the rubric's points", "[check][steps]") {
  // The rubric gives 9 points over 2 balances, 1 constraint and 3 answers (6 items): a wrong
  // step costs 9/12 = 0.75. One balance right, one wrong, one answer: 2 + 0 + 1 - 0.75 = 2.25.
  const SolutionGrade g = grade(pulley, R"Y(steps:
  - equation: "2*T - F = m_A*ddot(x_A)"
  - equation: "-2*T = m_B*ddot(x_B)"
  - {answer: "2*m_B*F/(9*m_A + 4*m_B)", unknown: T}
)Y",
                                "balances: 4\nconstraints: 2\nanswers: 3\n");
  REQUIRE(g.steps.size() == 3);
  CHECK(g.steps[1].result.findings.front().code == "missing_force");
  CHECK(g.first_wrong == std::optional<std::size_t>(2));
  CHECK(g.used == std::vector<std::string>{"LMB A (x)"});
  CHECK(g.missing == std::vector<std::string>{"LMB B (x)", "string s: acceleration"});
  CHECK(solution_text(g) ==
        "step 1 (equation): correct: it is LMB A (x)\n"
        "step 2 (equation): incorrect: a strand of string s at pB is missing (LMB B (x))\n"
        "step 3 (answer for T): correct: equal to the closed form\n"
        "first wrong step: 2\n"
        "used: LMB A (x)\n"
        "missing (needed for the unknowns asked): LMB B (x), string s: acceleration\n"
        "balances: 2 of 4 (1 of 2)\n"
        "constraints: 0 of 2 (0 of 1)\n"
        "answers: 1 of 3 (1 of 3)\n"
        "wrong steps: -0.75 (1 incorrect step, 0.75 points each)\n"
        "score: 2.25 of 9\n");
  // For the platforms: a test per step, one per part of the rubric, one for the wrong steps.
  const auto results = nlohmann::json::parse(solution_results(g, ResultsFormat::gradescope));
  REQUIRE(results["tests"].size() == 7);
  CHECK(results["tests"][1]["status"] == "failed");
  CHECK(results["tests"][1]["output"] == "incorrect: a strand of string s at pB is missing (LMB B (x))");
  CHECK(results["tests"][3]["name"] == "balances");
  CHECK(results["tests"][3]["score"] == 2.0);
  CHECK(results["tests"][3]["output"] == "1 of 2; missing: LMB B (x)");
  CHECK(results["tests"][5]["output"] == "1 of 3; not answered: ddot(x_A), ddot(x_B)");
  CHECK(results["tests"][6]["name"] == "wrong steps");
  CHECK(results["tests"][6]["score"] == -0.75);
  CHECK(results["tests"][6]["output"] == "1 incorrect step, 0.75 points each");
  CHECK(results["score"] == 2.25);
  const auto pl = nlohmann::json::parse(solution_results(g, ResultsFormat::prairielearn));
  CHECK(pl["gradable"] == true);
  CHECK(pl["score"] == Approx(2.25 / 9.0));
  const auto json = nlohmann::json::parse(solution_json(g));
  CHECK(json["wrong"] == 1);
  CHECK(json["penalty_each"] == 0.75);
  CHECK(json["penalty"] == 0.75);
  CHECK(json["parts"][0]["graded"] == true);
  CHECK(json["score"] == 2.25);
}

TEST_CASE("Steps: past the deadline a step is not checked, and gives nothing", "[check][steps]") {
  // The step service's time limit: a deadline already past leaves every step undecided
  // (time_limit); none is used, so the three equations sample 12.3 needs are all missing.
  const Made& m = made(pulley);
  const Model& model = m.analysis->model;
  const auto steps = read_solution(R"Y(steps:
  - equation: "2*T - F = m_A*ddot(x_A)"
  - {answer: "2*m_B*F/(9*m_A + 4*m_B)", unknown: T}
)Y",
                                   "s.yaml", model);
  const Rubric rubric = read_rubric(rubric10, "r.yaml", model);
  const SolutionGrade late = grade_solution(*m.checker, model, steps, rubric, std::chrono::steady_clock::now());
  REQUIRE(late.steps.size() == 2);
  for (const auto& s : late.steps) {
    CHECK(s.result.verdict == Verdict::undecided);
    CHECK(s.result.findings.front().code == "time_limit");
  }
  CHECK(late.used.empty());
  CHECK(late.missing.size() == 3);
  CHECK(late.wrong == 0);  // not checked is not wrong: no penalty
  CHECK(late.score == 0);
  // A deadline far off: the grade without one.
  const SolutionGrade in_time =
      grade_solution(*m.checker, model, steps, rubric, std::chrono::steady_clock::now() + std::chrono::hours(1));
  CHECK(solution_text(in_time) == solution_text(grade_solution(*m.checker, model, steps, rubric)));
  CHECK(in_time.steps[0].result.verdict == Verdict::correct);
}

TEST_CASE("Steps: an empty solution scores 0, and a part with nothing needed is not awarded", "[check][steps]") {
  const SolutionGrade g = grade(pulley, "steps: []\n", rubric10);
  CHECK(solution_text(g) ==
        "missing (needed for the unknowns asked): LMB A (x), LMB B (x), string s: acceleration\n"
        "balances: 0 of 4 (0 of 2)\n"
        "constraints: 0 of 2 (0 of 1)\n"
        "answers: 0 of 4 (0 of 3)\n"
        "score: 0 of 10\n");
  // Sample 12.2: the string's length alone gives A's acceleration (by hand), so no balance is
  // needed and none is graded; the diagrams neither, since no balance is written from them.
  const SolutionGrade k =
      grade("sample-12.2-pulley-kinematics", "steps: []\n", "fbds: 2\nbalances: 4\nconstraints: 2\nanswers: 4\n");
  CHECK(solution_text(k) ==
        "missing (needed for the unknowns asked): string s: acceleration\n"
        "fbds: not graded: no balance is needed for the unknowns asked, so no diagram is\n"
        "balances: not graded: no balance is needed for the unknowns asked\n"
        "constraints: 0 of 2 (0 of 1)\n"
        "answers: 0 of 4 (0 of 1)\n"
        "score: 0 of 6\n");
  const auto json = nlohmann::json::parse(solution_json(k));
  CHECK(json["parts"][1] ==
        nlohmann::json::parse(R"J({"name": "balances", "graded": false, "score": 0.0, "max_score": 0.0, "done": 0,
                                                      "of": 0, "not_graded": "no balance is needed for the unknowns asked"})J"));
  const auto results = nlohmann::json::parse(solution_results(k, ResultsFormat::gradescope));
  CHECK(results["tests"][1]["name"] == "balances");
  CHECK(results["tests"][1]["max_score"] == 0.0);
  CHECK(results["tests"][1]["output"] == "not graded: no balance is needed for the unknowns asked");
  // The forced damped block asks for ddot(x) in its state (by hand: m ddot(x) = F_0 cos(w t) -
  // c dot(x) - k x, its one balance; no constraint): nothing given, nothing earned, and the
  // constraints are not graded.
  CHECK(solution_text(grade("damped-block-on-spring-forced", "steps: []\n", rubric10)) ==
        "missing (needed for the unknowns asked): LMB block (x)\n"
        "balances: 0 of 4 (0 of 1)\n"
        "constraints: not graded: no constraint is needed for the unknowns asked\n"
        "answers: 0 of 4 (0 of 1)\n"
        "score: 0 of 8\n");
}

TEST_CASE("Steps: a part whose needed equations tackle cannot tell is not awarded", "[check][steps]") {
  // A block pushed by F: ddot(x) = F/m needs LMB A (x); W = m g, a quantity of the parameters
  // alone, needs no equation, so which equations the unknowns need cannot be told.
  const auto a = test::run_text(R"Y(title: a block pushed along a smooth floor
axes: [x]
parameters: {m: {value: 2, unit: kg}, F: {value: 6, unit: N}, g: {value: 9.81, unit: m/s^2}}
bodies: {A: {mass: m, position: x}}
loads: [{on: A, force: F}]
find: [ddot(x), {name: W, expr: "m*g", unit: N}]
)Y");
  const Checker c(*a);
  const auto steps = read_solution("steps:\n  - equation: \"F = m*ddot(x)\"\n  - {answer: \"F/m\", unknown: ddot(x)}\n",
                                   "s.yaml", a->model);
  const SolutionGrade g = grade_solution(c, a->model, steps, read_rubric(rubric10, "r.yaml", a->model));
  CHECK(solution_text(g) ==
        "step 1 (equation): correct: it is LMB A (x)\n"
        "step 2 (answer for ddot(x)): correct: equal to the closed form\n"
        "used: LMB A (x)\n"
        "balances: not graded: tackle cannot tell which equations W needs\n"
        "constraints: not graded: tackle cannot tell which equations W needs\n"
        "answers: 2 of 4 (1 of 2)\n"
        "score: 2 of 4\n");
}

TEST_CASE("Steps: an equation gives what it is, or a sum the student wrote, never what it was derived from",
          "[check][steps]") {
  // The documented meaning of CheckResult::combination, case by case.
  CheckResult one;
  one.identified_as = {"LMB A (x)"};
  CHECK(equations_given(one) == std::vector<std::string>{"LMB A (x)"});
  CheckResult sum;
  sum.follows_from = {"LMB A (x)", "LMB B (x)"};
  sum.combination = {{"LMB A (x)", true}, {"LMB B (x)", true}};
  CHECK(equations_given(sum) == std::vector<std::string>{"LMB A (x)", "LMB B (x)"});
  CheckResult derived = sum;
  derived.combination[1].plain = false;
  CHECK(equations_given(derived).empty());
  CheckResult unknown_combination;
  unknown_combination.follows_from = {"LMB A (x)", "LMB B (x)"};
  CHECK(equations_given(unknown_combination).empty());
  // The answer restated as one equation, with each platform example's own rubric: only the
  // answer's points (Gradescope: 3 of 10, the diagrams' 2 counted and not given;
  // PrairieLearn: 4 of 10).
  const std::string restated =
      "steps:\n  - equation: \"T = 2*F*m_B/(9*m_A + 4*m_B)\"\n  - {answer: \"2*F*m_B/(9*m_A + 4*m_B)\", unknown: T}\n";
  for (const auto& [platform, score] : {std::pair{"gradescope", 3.0}, std::pair{"prairielearn", 4.0}}) {
    const SolutionGrade g = grade_platform_example(platform, restated);
    INFO(platform);
    CHECK(g.score == Approx(score));
    CHECK(g.max_score == Approx(10));
    CHECK(g.used.empty());
    CHECK(
        g.steps[0].note ==
        "it earns no balance or constraint points: it is derived from LMB A (x), LMB B (x) and string s: acceleration "
        "by eliminating unknowns, not written as them or as their sum");
  }
  // Sample 12.3 (by hand): LMB A, 2T - F = m_A ddot(x_A), plus LMB B, -3T = m_B ddot(x_B), is
  // -T - F = m_A ddot(x_A) + m_B ddot(x_B): the student's sum of the two balances earns both.
  const SolutionGrade added =
      grade("sample-12.3-two-mass-pulley", "steps:\n  - equation: \"-T - F = m_A*ddot(x_A) + m_B*ddot(x_B)\"\n",
            "balances: 2\nconstraints: 1\nanswers: 3\n");
  CHECK(added.used == std::vector<std::string>{"LMB A (x)", "LMB B (x)"});
  REQUIRE(!added.parts.empty());
  CHECK(added.parts[0].name == "balances");
  CHECK(added.parts[0].score == Approx(2));
}

TEST_CASE("Steps: each wrong step takes its share back, as the rubric sets it", "[check][steps]") {
  // 8 wrong of 14 (every item given, 10 points): 10 - 8 x 10/12 = 3.33333, at most half.
  const SolutionGrade g = grade(pulley, guessed_pulley, rubric10);
  CHECK(g.wrong == 8);
  CHECK(g.penalty_each == Approx(10.0 / 12));
  CHECK(g.score == Approx(10 - 8 * 10.0 / 12));
  // penalty: 0 turns it off; a penalty of 2 a step takes everything the parts earned, not more.
  CHECK(grade(pulley, guessed_pulley, std::string(rubric10) + "penalty: 0\n").score == Approx(10));
  const SolutionGrade all = grade(pulley, guessed_pulley, std::string(rubric10) + "penalty: 2\n");
  CHECK(all.penalty == Approx(10));
  CHECK(all.score == 0);
  CHECK(
      solution_text(all).find("wrong steps: -10 (8 incorrect steps, 2 points each; no more than the parts earned)\n") !=
      std::string::npos);
  // An unreadable step is not a wrong one.
  CHECK(grade(pulley, "steps:\n  - equation: \"2*T - F\"\n", rubric10).wrong == 0);
}

TEST_CASE(
    "Steps: guessing every sign of every balance, arrow and answer scores at most half, with each example's rubric",
    "[check][steps]") {
  // Sample 12.3 asking only T (the platform examples' problem). By hand: A has F along -x and
  // two strands along +x at pA (all at one place in 1-D), B three strands along -x at pB. Every
  // sense of every arrow: 8 diagrams of A, three right (arrows are matched by where they act
  // and which way, not by name: any two along +x and one along -x is A's diagram), 8 of B, one
  // right; every sign of every term of the two balances and the constraint: 8 + 4 + 4
  // equations, two right each (an equation and its negation); T with both signs. 34 steps, 11
  // right, 23 wrong.
  std::string steps = "steps:\n";
  steps += every_sense("A", {{"{name: F", {-1}}, {"{name: T, at: pA", {1}}, {"{name: T, at: pA", {1}}});
  steps += every_sense("B", {{"{name: T, at: pB", {-1}}, {"{name: T, at: pB", {-1}}, {"{name: T, at: pB", {-1}}});
  steps += every_sign({"2*T", "F"}, {"m_A*ddot(x_A)"});
  steps += every_sign({"3*T"}, {"m_B*ddot(x_B)"});
  steps += every_sign({"3*ddot(x_B)"}, {"2*ddot(x_A)"});
  steps +=
      "  - {answer: \"2*F*m_B/(9*m_A + 4*m_B)\", unknown: T}\n  - {answer: \"-2*F*m_B/(9*m_A + 4*m_B)\", unknown: T}\n";
  // Gradescope's rubric: 2 + 3 + 2 + 3 = 10 over 2 diagrams, 2 balances, 1 constraint, 1
  // answer: a wrong step costs 10/12, and 23 of them take all 10. PrairieLearn's: 4 + 2 + 4
  // over 4 items, 10/8 each: all 10 too.
  for (const char* platform : {"gradescope", "prairielearn"}) {
    const SolutionGrade g = grade_platform_example(platform, steps);
    INFO(platform);
    REQUIRE(g.steps.size() == 34);
    CHECK(g.wrong == 23);
    CHECK(g.score == 0);
    CHECK(g.max_score == Approx(10));
  }
}

TEST_CASE("Steps: guessing every sign on the incline scores nothing, with each rubric", "[check][steps]") {
  // By hand (the example's notes, theta = 30 deg): A has the normal force at 120 deg, the string
  // at 30 deg and its weight down, three lines: one of the 8 diagrams right; B the string up
  // and its weight down, on one line at one point: 2 of 4 right (names aside). The balances as
  // the derivation writes them (LMB A (x): T cos - N_A sin = m_A s'' cos; LMB A (y): N_A cos +
  // T sin - m_A g = m_A s'' sin; LMB B (y): T - m_B g = m_B y_B''; the string: s'' + y_B'' = 0)
  // with every sign of every term: 8 + 16 + 8 + 4 equations, two right each; the three answers
  // with both signs. 54 steps, 14 right, 40 wrong: however many items are graded (at most 9),
  // 40 wrong steps take back more than 20 of them, all there is.
  std::string steps = "steps:\n";
  steps += every_sense(
      "A", {{"{name: N, at: A", {-0.5, 0.866025}}, {"{name: T, at: A", {0.866025, 0.5}}, {"{name: W, at: A", {0, -1}}});
  steps += every_sense("B", {{"{name: T, at: B", {0, 1}}, {"{name: W, at: B", {0, -1}}});
  steps += every_sign({"T*cos(theta)", "N_A*sin(theta)"}, {"m_A*ddot(s)*cos(theta)"});
  steps += every_sign({"N_A*cos(theta)", "T*sin(theta)", "g*m_A"}, {"m_A*ddot(s)*sin(theta)"});
  steps += every_sign({"T", "g*m_B"}, {"m_B*ddot(y_B)"});
  steps += every_sign({"ddot(s)"}, {"ddot(y_B)"});
  for (const auto& [u, a] :
       {std::pair{"ddot(s)", "g*(m_B - m_A*sin(theta))/(m_A + m_B)"},
        std::pair{"T", "m_A*m_B*g*(1 + sin(theta))/(m_A + m_B)"}, std::pair{"N_A", "m_A*g*cos(theta)"}})
    steps += fmt::format("  - {{answer: \"{}\", unknown: {}}}\n  - {{answer: \"-({})\", unknown: {}}}\n", a, u, a, u);
  for (const std::string rubric :
       {std::string(rubric10), std::string("fbds: 2\n") + rubric10,
        read_text_file(TACKLE_SOURCE_DIR "/examples/gradescope/pulley-solution/rubric.yaml")}) {
    INFO(rubric);
    const SolutionGrade g = grade("incline-and-hanging-block", steps, rubric);
    REQUIRE(g.steps.size() == 54);
    CHECK(g.wrong == 40);
    CHECK(g.score == 0);
  }
}

TEST_CASE("Steps: a solution or rubric file with problems says each, located", "[check][steps]") {
  const Model& model = made(pulley).analysis->model;
  auto errors = [](const std::function<void(const std::string&)>& read, const std::string& text) {
    std::vector<std::string> out;
    try {
      read(text);
    } catch (const InputError& e) {
      for (const auto& d : e.diagnostics()) out.push_back(format(d));
    }
    return out;
  };
  auto solution = [&](const std::string& text) { (void)read_solution(text, "f.yaml", model); };
  auto rubric = [&](const std::string& text) { (void)read_rubric(text, "f.yaml", model); };
  CHECK(errors(solution, "steps:\n  - equation: \"x = 1\"\n    answer: \"1\"\n  - {answer: \"3\"}\n") ==
        std::vector<std::string>{
            "f.yaml:2:5: a step is an equation or an answer, not both (expected {equation: ...} or {answer: ..., "
            "unknown: ...})",
            "f.yaml:4:5: an answer needs its 'unknown' (e.g. {answer: \"2*m_B*F/(9*m_A + 4*m_B)\", unknown: T})"});
  CHECK(errors(solution, "stepz: []\n") ==
        std::vector<std::string>{"f.yaml:1:1: unknown key 'stepz' in the solution (did you mean 'steps'?)",
                                 "f.yaml:1:1: the solution has no 'steps' (expected a list of {equation: ...}, "
                                 "{answer: ..., unknown: ...} and {fbd: ...})"});
  CHECK(
      errors(rubric, "balances: -1\nanswers: lots\npenalty: -0.5\n") ==
      std::vector<std::string>{"f.yaml:1:11: 'balances' is not a number of points (expected a number from 0 to 1000)",
                               "f.yaml:2:10: 'answers' is not a number of points (expected a number from 0 to 1000)",
                               "f.yaml:3:10: 'penalty' is not a number of points (expected a number from 0 to 1000)"});
  // A weight that names no force of the problem: sample 12.3 has no gravity; its forces are F
  // on A and the string's strands (path pB, C, pB, C, pA, C: two at pB, two at pA), tension T.
  CHECK(errors(rubric, "fbd:\n  weights:\n    T: 2\n    gravity on B: 1\n    'string s: strand pB-C': 1\n") ==
        std::vector<std::string>{
            "f.yaml:4:5: 'gravity on B' names no force of the problem (expected a force's unknown or source: T, "
            "force on A, string s: strand pB-C, string s: strand C-pB, string s: strand C-pA, string s: strand pA-C)"});
}

namespace {

// The section "How a rubric scores" of docs/checking.md: its files (a yaml block whose first
// line is `# NAME`) and its commands (`$ tackle check examples/E --steps S --rubric R`), each
// followed by its output as shown: every line, or the shown ones in order where `...` leaves
// lines out.
struct DocCommand {
  std::vector<std::string> words, shown;
};

void read_scoring_section(std::map<std::string, std::string>& files, std::vector<DocCommand>& commands) {
  std::ifstream in(TACKLE_SOURCE_DIR "/docs/checking.md");
  std::string line, fence, file;
  bool inside = false;
  std::vector<std::string> block;
  while (std::getline(in, line)) {
    if (fence.empty() && line.rfind("#", 0) == 0) {
      if (inside) break;  // the next heading ends the section
      inside = line == "#### How a rubric scores";
      continue;
    }
    if (!inside) continue;
    if (line.rfind("```", 0) != 0) {
      if (!fence.empty()) block.push_back(line);
      continue;
    }
    if (fence.empty()) {
      fence = line.substr(3);
      block.clear();
      continue;
    }
    if (fence == "yaml" && !block.empty() && block.front().rfind("# ", 0) == 0) {
      std::string text;
      for (std::size_t k = 1; k < block.size(); ++k) text += block[k] + "\n";
      files[block.front().substr(2)] = text;
    } else if (fence == "console") {
      for (const auto& l : block) {
        if (l.rfind("$ ", 0) == 0) {
          commands.push_back({});
          std::istringstream words(l.substr(2));
          for (std::string w; words >> w;) commands.back().words.push_back(w);
        } else if (!commands.empty()) {
          commands.back().shown.push_back(l);
        }
      }
    }
    fence.clear();
  }
}

// Whether `shown` is `got`, or (with `...` lines) its lines in order.
bool shown_in(const std::vector<std::string>& shown, const std::vector<std::string>& got) {
  if (std::find(shown.begin(), shown.end(), "...") == shown.end()) return shown == got;
  std::size_t at = 0;
  for (const auto& want : shown) {
    if (want == "...") continue;
    while (at < got.size() && got[at] != want) ++at;
    if (at == got.size()) return false;
    ++at;
  }
  return true;
}

}  // namespace

TEST_CASE("Steps: the scoring examples of docs/checking.md, replayed", "[check][steps][docs]") {
  std::map<std::string, std::string> files;
  std::vector<DocCommand> commands;
  read_scoring_section(files, commands);
  REQUIRE(commands.size() >= 5);  // a section that lost its examples would pass the rest
  for (const auto& c : commands) {
    INFO(Catch::Detail::stringify(c.words));
    REQUIRE(c.words.size() == 7);
    REQUIRE(c.words[0] == "tackle");
    REQUIRE(c.words[1] == "check");
    REQUIRE(c.words[2].rfind("examples/", 0) == 0);
    REQUIRE(c.words[3] == "--steps");
    REQUIRE(c.words[5] == "--rubric");
    REQUIRE(files.count(c.words[4]));
    REQUIRE(files.count(c.words[6]));
    const std::string example = c.words[2].substr(9, c.words[2].size() - 9 - 5);
    const SolutionGrade g = grade(example, files[c.words[4]], files[c.words[6]]);
    std::vector<std::string> got;
    std::istringstream out(solution_text(g));
    for (std::string l; std::getline(out, l);) got.push_back(l);
    INFO(solution_text(g));
    CHECK(shown_in(c.shown, got));
  }
}

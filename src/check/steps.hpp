// A worked solution graded as a whole (issue "check the student's work", part 3; issue 41,
// "rubrics that measure work"): its steps (diagrams, equations and final answers) each
// checked, the derivation's equations the student wrote (each one, or a sum of them), those
// the asked unknowns need and the student did not write, the first wrong step, and a rubric's
// score: points for diagrams, balances, constraints and answers, less a share for each wrong
// step. A part whose needed equations cannot be determined is not awarded, and says why.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "check/check.hpp"
#include "check/check.hpp"
#include "check/fbd.hpp"

namespace tackle {

struct SolutionStep {
  enum class Kind { equation, answer, fbd } kind = Kind::equation;
  std::string text;     // the equation, or the answer
  std::string unknown;  // an answer's unknown
  StudentFbd fbd;       // a free body diagram
};

/// Points per part of the solution (a part with 0 points is not graded), and what a wrong step
/// costs.
struct Rubric {
  double balances = 1;     // the balances the asked unknowns need (LMB, AMB)
  double constraints = 1;  // the constraints they need (length sums, fixed points, rolling)
  double answers = 1;      // the asked unknowns answered correctly
  // The free body diagrams of the bodies (or systems) whose balances the asked unknowns need,
  // each in proportion to its own score; unset: 1 when the solution has a diagram, else not graded.
  std::optional<double> fbds;
  // Points each incorrect step takes back (the score never below 0); unset: half of what one
  // item graded is worth on average (the points graded over twice the items: the needed
  // equations, the asked unknowns and the wanted diagrams of the parts graded).
  std::optional<double> penalty;
  FbdRubric fbd;  // how each diagram is scored
};

struct SolutionGrade {
  struct Step {
    SolutionStep step;
    CheckResult result;
    // Why a correct equation earns no balance or constraint points (it was derived from them by
    // eliminating unknowns); empty otherwise.
    std::string note;
  };
  std::vector<Step> steps;
  // The derivation's equations the correct steps give: each is one of them (up to a factor) or
  // a sum of them the student wrote (every coefficient a plain number); a length sum gives its
  // derivatives too.
  std::vector<std::string> used;
  std::vector<std::string> missing;        // those the asked unknowns need that no correct step gives
  std::optional<std::size_t> first_wrong;  // 1-based: the first step that is not correct
  struct Part {
    std::string name;  // balances, constraints, answers
    double score = 0, max = 0;
    std::size_t done = 0, of = 0;      // equations (or answers) given, of those wanted
    std::vector<std::string> missing;  // the needed equations of this part no step gives (unknowns not answered)
    // Why the part is not awarded (nothing is needed of it, or what is needed cannot be
    // determined): its points are then neither given nor counted in max_score. Empty: graded.
    std::string not_graded;
  };
  std::vector<Part> parts;
  std::size_t wrong = 0;                 // incorrect steps
  double penalty_each = 0, penalty = 0;  // what each takes back; what they took in all (at most what the parts earned)
  double score = 0, max_score = 0;
};

/// Reads a solution file: `steps:` a list of `{equation: "..."}`, `{answer: "...", unknown:
/// NAME}` and `{fbd: {body: B, forces: [...]}}` (see read_fbd);
/// every problem in the file reported at once (InputError, located).
[[nodiscard]] std::vector<SolutionStep> read_solution(const std::string& text, const std::string& file, const Model& m);
/// Reads a rubric file: `{fbds: 2, balances: 4, constraints: 2, answers: 4, penalty: 0.5}`
/// (points, from 0 to 1000), and `fbd:` how a diagram is scored (see read_fbd_rubric), whose
/// weights must name forces of `m`; every problem reported at once (InputError, located).
[[nodiscard]] Rubric read_rubric(const std::string& text, const std::string& file, const Model& m);

/// The derivation's equations a correct equation `r` gives a worked solution: the one it is (up
/// to a factor), or those it adds up when every coefficient of its combination is a plain
/// number (a sum the student wrote); none when one is not (it was derived from them by
/// eliminating unknowns), or when what it combines is not known.
[[nodiscard]] std::vector<std::string> equations_given(const CheckResult& r);

/// Grades the steps; a free body diagram's against `model` (the checker's problem). With a
/// deadline, a step not begun by then is not checked: its verdict is undecided (code
/// `time_limit`), it gives nothing, and the parts are graded on the steps checked (a step
/// begun finishes within its own budget: an answer's 250 ms, an equation's size limits).
[[nodiscard]] SolutionGrade grade_solution(
    const Checker& checker, const Model& model, const std::vector<SolutionStep>& steps, const Rubric& rubric,
    std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

/// A step as its feedback names it: "equation", "answer for T", or its text.
[[nodiscard]] std::string step_name(const SolutionStep& s);

}  // namespace tackle

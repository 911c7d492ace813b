// A worked solution graded as a whole (issue "check the student's work", part 3): its steps
// (equations and final answers) each checked, the derivation's equations the student used,
// those the asked unknowns need and the student did not write, the first wrong step, and a
// rubric's score (points for balances, constraints and answers).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "check/batch.hpp"
#include "check/check.hpp"
#include "check/fbd.hpp"

namespace tackle {

struct SolutionStep {
  enum class Kind { equation, answer, fbd } kind = Kind::equation;
  std::string text;     // the equation, or the answer
  std::string unknown;  // an answer's unknown
  StudentFbd fbd;       // a free body diagram
};

/// Points per part of the solution (a part with 0 points is not graded).
struct Rubric {
  double balances = 1;     // the balances the asked unknowns need (LMB, AMB)
  double constraints = 1;  // the constraints they need (length sums, fixed points, rolling)
  double answers = 1;      // the asked unknowns answered correctly
  // The free body diagrams of the bodies (or systems) whose balances the asked unknowns need,
  // each in proportion to its own score; unset: 1 when the solution has a diagram, else not graded.
  std::optional<double> fbds;
  FbdRubric fbd;  // how each diagram is scored
};

struct SolutionGrade {
  struct Step {
    SolutionStep step;
    CheckResult result;
  };
  std::vector<Step> steps;
  std::vector<std::string> used;     // the derivation's equations the correct steps are or follow from
  std::vector<std::string> missing;  // those the asked unknowns need that no correct step gives
  std::optional<std::size_t> first_wrong;  // 1-based: the first step that is not correct
  struct Part {
    std::string name;  // balances, constraints, answers
    double score = 0, max = 0;
    std::size_t done = 0, of = 0;  // equations (or answers) given, of those wanted
    std::vector<std::string> missing;  // the needed equations of this part no step gives (unknowns not answered)
  };
  std::vector<Part> parts;
  double score = 0, max_score = 0;
};

/// Reads a solution file: `steps:` a list of `{equation: "..."}`, `{answer: "...", unknown:
/// NAME}` and `{fbd: {body: B, forces: [...]}}` (see read_fbd);
/// every problem in the file reported at once (InputError, located).
[[nodiscard]] std::vector<SolutionStep> read_solution(const std::string& text, const std::string& file, const Model& m);
/// Reads a rubric file: `{fbds: 2, balances: 4, constraints: 2, answers: 4}` (points, from 0 to
/// 1000), and `fbd:` how a diagram is scored (see read_fbd_rubric).
[[nodiscard]] Rubric read_rubric(const std::string& text, const std::string& file);

/// Grades the steps; a free body diagram's against `model` (the checker's problem).
[[nodiscard]] SolutionGrade grade_solution(const Checker& checker, const Model& model, const std::vector<SolutionStep>& steps, const Rubric& rubric);

/// The grade as text (what a student reads) and as JSON.
[[nodiscard]] std::string solution_text(const SolutionGrade& g);
[[nodiscard]] std::string solution_json(const SolutionGrade& g);
/// A grading platform's results file: one test per step (its verdict, no points of its own)
/// and one per part of the rubric (its points); the total.
[[nodiscard]] std::string solution_results(const SolutionGrade& g, ResultsFormat format);

}  // namespace tackle

// Checking a student's free body diagram (issue "check the student's work", part 2): the
// student's arrows (where each acts, which way it points) compared with the forces tackle's own
// diagram of that body (or system) has, at the position the problem's sketch shows. Each force
// is matched by what it must stand for (its point, line and kind), not by its name: drawn, drawn
// the wrong way, drawn at the wrong point, or missing; every arrow left over is an extra force,
// said why where it can be (it acts on another body, it is internal to the system, it is drawn
// twice). Partial credit per force, with weights an instructor sets.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "check/check.hpp"
#include "core/diagnostics.hpp"
#include "description/yaml_reader.hpp"
#include "model/model.hpp"

namespace tackle {

/// A student's arrow.
struct StudentForce {
  std::string name;  // the student's own name for it (only echoed)
  std::string at;    // a point's or a body's name (its center of mass); empty: not said
  Location at_where;
  std::optional<std::array<double, 3>> direction;  // in the problem's axes; none: `any` (not known)
  // What sort of force the student means it for: weight, tension (a string's or a cable's),
  // spring, damper, applied (a given force) or support (a pin's, a contact's, a rod's...);
  // empty: not said (any).
  std::string kind;
  Location where;
};

/// A student's couple (2-D): counterclockwise (+1), clockwise (-1) or either (0, `any`).
struct StudentCouple {
  std::string name;
  int sense = 0;
  Location where;
};

struct StudentFbd {
  std::vector<std::string> bodies;  // one body, or the bodies of a system
  std::vector<Location> body_where;
  std::vector<StudentForce> forces;
  std::vector<StudentCouple> couples;
  Location where;
};

/// How an FBD is scored: each of tackle's forces is worth its weight (1 unless `weights` names
/// it by its source, "gravity on B", or its unknown, "T"); a force drawn the wrong way or at the
/// wrong point earns that fraction of it; each extra arrow takes `extra` points off (never
/// below 0). Directions within `tolerance` degrees of a force's line count as along it.
struct FbdRubric {
  double wrong_direction = 0.5;
  double wrong_point = 0.5;
  double extra = 1;
  double tolerance = 5;
  std::map<std::string, double> weights;
  std::map<std::string, Location> weight_where;  // where each weight is named (its key), for fbd_rubric_problems
};

/// Reads a free body diagram: `body: B` (or `bodies: [A, B]`, a system), `forces:` a list of
/// `{name: T, at: pB, direction: [-1]}` (`direction`: one number per axis, or `any`; in 2-D
/// `angle:` in degrees from the first axis instead) and, in 2-D, `couples:` a list of
/// `{name: M, sense: counterclockwise | clockwise | any}`. Every problem with the data, and every
/// body or point that is not the problem's, reported into `diags`.
[[nodiscard]] StudentFbd read_fbd(const yaml::Node& node, const Model& m, const std::string& file, Diagnostics& diags);
/// A file holding one free body diagram (InputError, located, with every problem at once).
[[nodiscard]] StudentFbd read_fbd_file(const std::string& text, const std::string& file, const Model& m);
/// The names of `fbd` that are not the problem's bodies and points (located).
[[nodiscard]] std::vector<Diagnostic> fbd_name_problems(const Model& m, const StudentFbd& fbd);
/// The `fbd:` part of a rubric: `{wrong_direction: 0.5, wrong_point: 0.5, extra: 1, tolerance: 5,
/// weights: {T: 2}}`.
[[nodiscard]] FbdRubric read_fbd_rubric(const yaml::Node& node, const std::string& file, Diagnostics& diags);
/// The weights of `r` that name no force of `m` (neither a force's unknown nor its source),
/// each located at its key.
[[nodiscard]] std::vector<Diagnostic> fbd_rubric_problems(const Model& m, const FbdRubric& r);

struct FbdGrade {
  std::string of;  // "B", or "the system of A and B"
  Verdict verdict = Verdict::undecided;
  std::string summary;
  std::vector<Finding> findings;
  struct Force {
    std::string source;  // as the derivation names it: "string s: strand pB-C at pB"
    std::string phrase;  // as a student reads it: "a strand of string s at pB"
    std::string label;   // tackle's symbol for it where it has one ("T", "mu*N_A"), else ""
    // drawn, wrong_direction, wrong_point, off_line, missing; `zero` for a force that is nothing
    // at the sketch's position (a spring at its natural length), left out: not needed, its share
    // earned (drawn, it is graded as any force, along the line it has when not nothing)
    std::string status;
    std::vector<std::string> drawn_as;  // the student's names for it
    double weight = 1, score = 0;
  };
  std::vector<Force> forces;
  struct Extra {
    std::string name;  // the student's
    std::string code, message;
  };
  std::vector<Extra> extras;
  double score = 0, max_score = 0;
};

/// Grades `fbd` against the model's own diagram (check/fbd_grade.cpp). Problems with the names (a body, point or
/// body that is not the problem's, a 2-D couple in 1-D) are put in `problems` and the grade is
/// then `invalid`; a diagram whose directions depend on a parameter without a value is
/// `undecided` (the student's numbers cannot be compared).
[[nodiscard]] FbdGrade check_fbd(const Model& m, const StudentFbd& fbd, const FbdRubric& rubric,
                                 std::vector<Diagnostic>& problems);

/// The grade as a check result (for a worked solution's step and a platform's test): its
/// verdict, summary, findings and score (a fraction of 1).
[[nodiscard]] CheckResult fbd_result(const FbdGrade& g);
/// check_fbd() as a check result, guarded as Checker::check is: what goes wrong inside is the
/// verdict undecided, code `internal` (one diagram's, never a batch's or a solution's end).
[[nodiscard]] CheckResult checked_fbd(const Model& m, const StudentFbd& fbd, const FbdRubric& rubric,
                                      std::vector<Diagnostic>& problems);

}  // namespace tackle

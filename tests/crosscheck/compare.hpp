// Comparing the numeric model with tackle: tackle's closed forms (its pipeline's solution)
// evaluated at the model's random states, quantity by quantity; and the motion integrated
// from the model against `tackle simulate`.
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "ruleset/ruleset.hpp"

namespace crosscheck {

struct Disagreement {
  std::string quantity;
  double tackle = 0, model = 0;
  std::string state;  // the values it was found at
};

struct Outcome {
  enum class Kind { agree, disagree, skipped, tackle_refused } kind = Kind::agree;
  std::string reason;      // skipped / refused: why
  int states = 0;          // states compared
  int compared = 0;        // quantity comparisons made
  int not_determined = 0;  // quantities tackle gives that the model leaves free
  std::vector<Disagreement> disagreements;
  // The motion: times compared, and the largest difference of a coordinate.
  int motion_points = 0;
  double motion_error = 0;
  std::string motion_note;             // why the motion was not compared, when it was not
  std::string motion_event;            // the first event of the motion, the model's and tackle's alike
  std::set<std::string> not_compared;  // claims of tackle's the model cannot judge (claims.hpp)
};

struct Options {
  int states = 5;
  double tolerance = 1e-9;  // relative
  double motion_tolerance = 1e-6;
  bool motion = true;
  std::uint64_t seed = 1;
  double perturb = 0;            // the model's masses times 1 + perturb (a deliberately wrong model)
  double perturb_inertia = 0;    // its moments of inertia times 1 + perturb_inertia
  bool perturb_winding = false;  // its wound strings winding the other way
  // A deliberately wrong tackle (claims.hpp): the first answer asked for left out, the first
  // validity condition inverted.
  bool perturb_drop_answer = false;
  bool perturb_invert_condition = false;
};

/// Compares one description (YAML text; `file` names it).
[[nodiscard]] Outcome compare(const std::string& text, const std::string& file, const tackle::RuleSet& rules,
                              const Options& options);

/// A random mechanism as a description (YAML), from its seed; `kind` says which family.
[[nodiscard]] std::string generate(std::uint64_t seed, std::string* kind = nullptr);

}  // namespace crosscheck

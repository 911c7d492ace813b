// The oracle of verdicts (issue 41, item 2): students' equations, answers and free body
// diagrams over the examples and the generated mechanisms, each decided by the cross-check's
// model (worlds.hpp, diagram.hpp) and checked by tackle's checker; a verdict that does not
// follow the model's truth is a disagreement.
#pragma once

#include <cstdint>
#include <string>

#include "ruleset/ruleset.hpp"

namespace crosscheck {

struct OracleOptions {
  enum class Kind { equations, answers, fbds } kind = Kind::equations;
  long count = 300;
  std::uint64_t seed = 1;
  std::string examples;  // the directory of the examples
  int per_visit = 10;    // items made from one source at one draw of its worlds
  int shown = 3;         // disagreements printed per source and family (0: all)
  bool silent = false;   // a tackle that says nothing (an empty verdict): every item must disagree
};

/// Runs the oracle; prints every disagreement (up to `shown` of a kind), the tallies and
/// `N equations, K disagreements` (answers, diagrams). Returns the number of disagreements.
long run_oracle(const OracleOptions& o, const tackle::RuleSet& rules);
/// One equation (or, with `unknown`, one answer) on one description: the model's worlds, its
/// truth and tackle's verdict, printed (a reproducer for a disagreement).
int explain_one(const std::string& file, const std::string& text, const std::string& unknown,
                const tackle::RuleSet& rules, std::uint64_t seed);

}  // namespace crosscheck

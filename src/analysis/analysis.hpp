// The solved analysis of one description: read, build, balance, solve, and the stages that
// follow from the solution (the power balance, the interval's end or an impact, the motion in
// time, the connections decided at the numbers). Each stage's result is kept (immutable) so
// that the checker, the reports, tests and benchmarks can look at any of them. Nothing here
// narrates or draws: report/ reads an analysis, and check/ reads it without report/.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "description/description.hpp"
#include "energy/power.hpp"
#include "equations/equations.hpp"
#include "model/model.hpp"
#include "motion/motion.hpp"
#include "motion/phases.hpp"
#include "ruleset/ruleset.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct Analysis;

/// One phase of a phased description: its own analysis, and what it carries into the next
/// (each a defined parameter there).
struct Phase {
  std::string name;
  Location at;
  std::shared_ptr<const Analysis> analysis;
  std::vector<std::pair<std::string, GiNaC::ex>> carried;  // name -> its closed form in the phase's parameters
};

struct Analysis {
  Model model;
  EquationSystem system;
  Solution solution;
  PowerCheck power;                         // the power balance checked against the solution (src/energy/)
  std::optional<Motion> motion;             // motion in time, when the description asks for it (src/motion/)
  std::optional<IntervalEnd> interval_end;  // the rates at the end of the interval (src/motion/phases)
  std::optional<ImpactResult> impact;       // an impact, instead of the balances (src/motion/phases)
  std::vector<RegimeChoice> regimes;        // connections decided at the numbers (analysis/regimes)
  // A phased description: the phases in order (the fields above are then empty but for the
  // model's title and file); every command but derive and solve works on one of them.
  std::vector<Phase> phases;
};

/// The phase named `name` of a phased analysis; a usage problem (`message`) when there is no
/// such phase, or when the analysis has phases and no name was given.
[[nodiscard]] const Analysis* pick_phase(const Analysis& a, const std::string& name, std::string& message);

[[nodiscard]] std::unique_ptr<const Analysis> analyze(const Description& d, const RuleSet& rules);
/// Reads and analyzes text; problems of the description and of the model are reported
/// together, in file order.
[[nodiscard]] std::unique_ptr<const Analysis> analyze_text(const std::string& text, const std::string& file,
                                                           const RuleSet& rules);
[[nodiscard]] std::unique_ptr<const Analysis> analyze_file(const std::string& path, const RuleSet& rules);
}  // namespace tackle

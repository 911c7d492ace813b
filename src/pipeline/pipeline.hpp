// The whole chain for one description file: read, build, balance, solve. Each stage's
// result is kept (immutable) so that reports, tests and benchmarks can look at any of them.
#pragma once

#include <memory>
#include <string>

#include "description/description.hpp"
#include "equations/equations.hpp"
#include "model/model.hpp"
#include "energy/power.hpp"
#include "motion/motion.hpp"
#include "motion/phases.hpp"
#include "pipeline/regimes.hpp"
#include "report/derivation.hpp"
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
  PowerCheck power;  // the power balance checked against the solution (src/energy/)
  std::optional<Motion> motion;  // motion in time, when the description asks for it (src/motion/)
  std::optional<IntervalEnd> interval_end;  // the rates at the end of the interval (src/motion/phases)
  std::optional<ImpactResult> impact;       // an impact, instead of the balances (src/motion/phases)
  std::vector<RegimeChoice> regimes;        // connections decided at the numbers (pipeline/regimes)
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
/// The derivation, with the described sweep's figure when there is one. A phased analysis
/// gives one derivation per phase (`explain_phases`); `explain` takes a single one.
[[nodiscard]] Derivation explain(const Analysis& a, const ReportOptions& options = {});
[[nodiscard]] std::vector<Derivation> explain_phases(const Analysis& a, const ReportOptions& options = {});

struct SweepSpec;
/// A described sweep as a spec to run.
[[nodiscard]] SweepSpec sweep_spec(const SweepDesc& s);

}  // namespace tackle

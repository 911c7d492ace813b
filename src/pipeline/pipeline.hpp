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
#include "report/derivation.hpp"
#include "ruleset/ruleset.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct Analysis {
  Model model;
  EquationSystem system;
  Solution solution;
  PowerCheck power;  // the power balance checked against the solution (src/energy/)
  std::optional<Motion> motion;  // motion in time, when the description asks for it (src/motion/)
};

[[nodiscard]] std::unique_ptr<const Analysis> analyze(const Description& d, const RuleSet& rules);
/// Reads and analyzes text; problems of the description and of the model are reported
/// together, in file order.
[[nodiscard]] std::unique_ptr<const Analysis> analyze_text(const std::string& text, const std::string& file,
                                                           const RuleSet& rules);
[[nodiscard]] std::unique_ptr<const Analysis> analyze_file(const std::string& path, const RuleSet& rules);
/// The derivation, with the described sweep's figure when there is one.
[[nodiscard]] Derivation explain(const Analysis& a, const ReportOptions& options = {});

struct SweepSpec;
/// A described sweep as a spec to run.
[[nodiscard]] SweepSpec sweep_spec(const SweepDesc& s);

}  // namespace tackle

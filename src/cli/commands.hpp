// The command line's commands, each run from the options it was given: 0, 1 for bad input
// (or an output that cannot be written), 2 for a usage problem; input errors are thrown.
#pragma once

#include "cli/options.hpp"
#include "pipeline/pipeline.hpp"
#include "ruleset/ruleset.hpp"

namespace tackle::cli {

/// The analysis of one phase (or of the whole description when it has none); nullptr, with
/// the usage problem said, when the phase named is not there.
[[nodiscard]] const tackle::Analysis* the_phase(const tackle::Analysis& whole, const Options& o);

/// derive (`full`) and solve: every phase of a phased description, unless --phase names one.
int run_report(const Options& o, const tackle::RuleSet& rules, bool full);
int run_key(const Options& o, const tackle::RuleSet& rules);
int run_sheet(const Options& o, const tackle::RuleSet& rules);
/// A page to try the step checker: the problem and a worked-solution form posting to a checker.
int run_page(const Options& o, const tackle::RuleSet& rules);
int run_isolate(const Options& o, const tackle::RuleSet& rules);
int run_sweep(const Options& o, const tackle::RuleSet& rules);
int run_simulate(const Options& o, const tackle::RuleSet& rules);
/// check (check_command.cpp).
int run_check(const Options& o, const tackle::RuleSet& rules);

}  // namespace tackle::cli

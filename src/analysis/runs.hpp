// The numeric runs of an analysis, stages after the answers: a sweep (the closed forms
// evaluated over a range of one parameter, with others fixed, each point marked valid or not:
// every validity condition holds there) and the described motion integrated in time. The
// report plots and narrates them (report/sweep.hpp writes a sweep as CSV, SVG, pgfplots);
// nothing here includes report/. Made in src/analysis/analysis.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"
#include "motion/simulate.hpp"
#include "numeric/plot.hpp"
#include "solve/answers.hpp"

namespace tackle {

struct SweepSpec {
  std::string vary;               // "h=0:2:41": name=start:end:count, in the parameter's unit
  std::vector<std::string> fix;   // "l=1", in the parameter's unit
  std::vector<std::string> plot;  // expressions in the answers and parameters: "N_A - N_B"
  std::string against;            // "h/l": the horizontal axis, an expression in the parameters
                                  // (empty: the varied parameter, in its unit)
};

/// A described sweep as a spec to run.
[[nodiscard]] SweepSpec sweep_spec(const SweepDesc& s);

/// Evaluates the sweep over the answers' closed forms, each point marked valid where every
/// one of `conditions` holds; titled with the model's title. Problems with the spec are
/// located InputErrors (`where` names the command-line option or the description key).
[[nodiscard]] SweepResult evaluate_sweep(const Model& m, const std::vector<Answer>& answers,
                                         const std::vector<ConditionReport>& conditions, const SweepSpec& spec,
                                         const Location& where);

/// The runs a description asks for, computed for the report to plot and narrate.
struct DescribedRuns {
  std::optional<Simulation> motion;  // the motion to its 'until' (a second of computing at most)
  std::optional<SweepResult> sweep;  // the description's 'sweep'
};

/// The description's runs: its motion when 'motion' has 'until', then its sweep (over
/// `answers`, the answers to the analysis' questions). An unphased analysis.
[[nodiscard]] DescribedRuns run_described(const Analysis& a, const Answers& answers);

}  // namespace tackle

// Sweeps written: the closed forms evaluated over a range of one parameter, with others fixed,
// each point marked valid or not (evaluated in analysis/runs.hpp), as CSV, as an SVG plot and
// as a pgfplots figure for the LaTeX report.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/runs.hpp"
#include "model/model.hpp"
#include "report/derivation.hpp"
#include "motion/simulate.hpp"
#include "numeric/plot.hpp"

namespace tackle {

/// Evaluates the sweep over the derivation's answers and conditions (analysis/runs.hpp's
/// evaluate_sweep), titled with its title; problems with the spec are located InputErrors
/// (`where` names the command-line option or the description key).
[[nodiscard]] SweepResult run_sweep(const Model& m, const Derivation& d, const SweepSpec& spec, const Location& where);

[[nodiscard]] std::string sweep_csv(const SweepResult& r);
[[nodiscard]] std::string sweep_svg(const SweepResult& r);
[[nodiscard]] std::string sweep_pgfplots(const SweepResult& r);

/// A numeric run (motion/simulate.hpp) as text: the events, then the table as CSV.
[[nodiscard]] std::string simulation_text(const Simulation& s);

}  // namespace tackle

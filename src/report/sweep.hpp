// Sweeps: the closed forms evaluated over a range of one parameter, with others fixed, each
// point marked valid or not (every validity condition holds there), written as CSV, as an SVG
// plot and as a pgfplots figure for the LaTeX report.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "report/derivation.hpp"
#include "motion/simulate.hpp"
#include "numeric/plot.hpp"

namespace tackle {

struct SweepSpec {
  std::string vary;               // "h=0:2:41": name=start:end:count, in the parameter's unit
  std::vector<std::string> fix;   // "l=1", in the parameter's unit
  std::vector<std::string> plot;  // expressions in the answers and parameters: "N_A - N_B"
  std::string against;            // "h/l": the horizontal axis, an expression in the parameters
                                  // (empty: the varied parameter, in its unit)
};

/// Evaluates the sweep; problems with the spec are located InputErrors (`where` names the
/// command-line option or the description key).
[[nodiscard]] SweepResult run_sweep(const Model& m, const Derivation& d, const SweepSpec& spec, const Location& where);

[[nodiscard]] std::string sweep_csv(const SweepResult& r);
[[nodiscard]] std::string sweep_svg(const SweepResult& r);
[[nodiscard]] std::string sweep_pgfplots(const SweepResult& r);

/// A numeric run (motion/simulate.hpp) as text: the events, then the table as CSV.
[[nodiscard]] std::string simulation_text(const Simulation& s);

}  // namespace tackle

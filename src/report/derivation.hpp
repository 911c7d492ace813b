// The Derivation: what is said about a solved problem, in the book's order, independent of
// how it is encoded. Writers (text, latex, json) only format it.
#pragma once

#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "energy/power.hpp"
#include "figure/figure.hpp"
#include "numeric/plot.hpp"
#include "equations/equations.hpp"
#include "model/model.hpp"
#include "motion/motion.hpp"
#include "motion/phases.hpp"
#include "numeric/evaluate.hpp"
#include "solve/answers.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct Step {
  // given: a parameter's value (lhs = rhs, unit in note), listed like a bullet.
  // figure: a drawn free body diagram (text and JSON leave it out).
  enum class Kind { section, text, bullet, equation, given, figure } kind = Kind::text;
  std::string text;  // section title, paragraph, bullet, or an equation's label
  GiNaC::ex lhs, rhs;
  std::string relation = "=";
  bool equals_constant = false;          // "lhs = const" (a length sum held constant)
  bool boxed = false;                    // a final closed form
  std::string note;                      // a number with its unit ("20 N"); for `given`, the unit only
  bool note_squared = false;             // the note is the square of that number: (19.1206 m/s)^2
  std::string number;                    // given: the value as a decimal ("0.3")
  std::vector<GiNaC::ex> math;           // text and bullets: each "{}" in `text` is the next of these
  std::shared_ptr<const Figure> figure;  // figure
};

/// A parameter (or a quantity given with its value) as the JSON reports it: enough for a
/// program to evaluate every closed form.
struct ParameterReport {
  std::string name, tex;
  std::string kind;                     // parameter | defined | length (a turning strand's) | given
  std::optional<NumericValue> si;       // the value in SI
  std::optional<NumericValue> stated;   // the value in the unit the description states
  std::optional<GiNaC::ex> definition;  // defined and length: the expression
};

struct Derivation {
  std::string title;
  std::string file;
  std::string phase;     // a phase of a phased description: its name
  int phase_number = 0;  // and its place (1, 2, ...); 0 for a description without phases
  std::vector<Step> steps;
  std::vector<Answer> answers;
  std::vector<CombinationReport> combinations;
  std::vector<ConditionReport> conditions;
  std::vector<ParameterRange> ranges;  // each parameter the conditions are solved for, alone, in numbers
  std::vector<std::string> free;
  std::vector<std::string> conflicts;
  std::string status;  // determined | underdetermined | inconsistent
  std::size_t rank = 0;
  std::size_t n_equations = 0;
  std::vector<GiNaC::ex> unknowns;
  std::vector<Equation> equations;  // what was solved, for the JSON
  std::vector<ConstraintSteps> constraint_steps;
  std::vector<Equation> impact_equations;      // an impact's, for the JSON
  std::shared_ptr<const SymbolTable> symbols;  // what the names are (LaTeX writes m a, mu N_A)
  std::optional<SweepResult> sweep_plot;       // the described sweep, when there is one
  std::optional<SweepResult> motion_plot;      // the simulated motion, when 'motion' has 'until'
  std::vector<std::string> motion_events;      // what happened in that run, in words
  // Indeterminate with numbers: the member of the family with the least norm (Eigen), for
  // the unknowns that are not determined alone.
  std::vector<std::pair<std::string, std::optional<NumericValue>>> minimum_norm;
  PowerCheck power;                   // the power balance, checked against the solution
  std::vector<RegimeChoice> regimes;  // connections decided at the numbers (stick or slip)
  std::vector<ParameterReport> parameters;
  // Motion in time, for the JSON (narrated in the steps): a copy without the simulation's
  // state functions, so that nothing in it points into the analysis.
  std::optional<Motion> motion;
};

struct ReportOptions {
  int digits = 6;  // significant digits of the numbers
  /// The steps' figures, the motion's narration and the plots (a simulation, a sweep). Off
  /// for what prints the answers only (`tackle solve`, `tackle sweep`): the answers, the
  /// conditions, the power check and the motion are the same either way.
  bool narrate = true;
  /// The free body diagrams and sketches drawn (with `narrate`). Off where the format shows
  /// no figure (text and JSON): drawing them is a tenth of a small problem's run.
  bool figures = true;
};

/// The derivation of a solved problem, in the book's order; `power_check` is the power-balance
/// check made in the analysis (narrated here, not computed).
/// `end`: the interval's end rates, told after the results.
[[nodiscard]] Derivation explain(const Model& m, const EquationSystem& s, const Solution& sol, const Answers& answers,
                                 const PowerCheck& power_check, const ReportOptions& options = {},
                                 const IntervalEnd* end = nullptr);

/// The motion in time appended to a derivation (report/motion_narration.cpp).
void narrate_motion(Derivation& d, const Model& m, const Motion& motion, const ReportOptions& options = {});

/// What was decided at the numbers for each connection with regimes (report/phase_narration.cpp).
void narrate_regimes(Derivation& d, const std::vector<RegimeChoice>& choices, const SymbolTable& table);

/// The end of an interval whose end rates were found, and an impact (report/phase_narration.cpp).
void narrate_interval_end(Derivation& d, const Model& m, const IntervalEnd& end, const ReportOptions& options = {});
void narrate_impact(Derivation& d, const Model& m, const ImpactResult& r, const ReportOptions& options = {});

enum class Format { text, latex, json, markdown, html };
/// `full`: the whole derivation; otherwise the answers only (`tackle solve`).
[[nodiscard]] std::string write(const Derivation& d, Format f, bool full);
/// The derivations of a phased description's phases, one after the other (one LaTeX document,
/// one JSON object with a `phases` array); a single unphased derivation as above.
[[nodiscard]] std::string write(const std::vector<Derivation>& phases, Format f, bool full);
/// The same written to `out` as it is made (the text format writes each answer as it goes):
/// the whole document is never held in memory.
void write_to(std::ostream& out, const Derivation& d, Format f, bool full);
void write_to(std::ostream& out, const std::vector<Derivation>& phases, Format f, bool full);

}  // namespace tackle

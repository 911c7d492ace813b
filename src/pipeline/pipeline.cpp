#include "pipeline/pipeline.hpp"

#include "analysis/runs.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "report/narrator.hpp"
#include "solve/bounds.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

std::vector<Derivation> explain_phases(const Analysis& a, const ReportOptions& options) {
  std::vector<Derivation> out;
  if (a.phases.empty()) {
    out.push_back(explain(a, options));
    return out;
  }
  for (std::size_t i = 0; i < a.phases.size(); ++i) {
    const Phase& p = a.phases[i];
    Derivation d = explain(*p.analysis, options);
    d.title = a.model.title;
    d.phase = p.name;
    d.phase_number = static_cast<int>(i + 1);
    if (!p.carried.empty()) {
      Narrator n{d, *p.analysis->model.symbols};
      n.section("Carried into the next phase");
      n.text("The state at the end of this phase, named for the phases that follow (a defined parameter there):");
      const SymbolTable& table = *p.analysis->model.symbols;
      for (const auto& [name, value] : p.carried) {
        Step* st = n.equation("carried", symbol(name), value);
        std::string problem;
        st->note = with_unit(evaluate(value, table, dimension_of(value, table, problem), options.digits));
      }
    }
    out.push_back(std::move(d));
  }
  return out;
}

namespace {

// The motion in time, for the JSON (a copy without the simulation's state functions, which
// point into the analysis' solution), its conditions for all t with their bounds' numbers to
// the report's digits, and narrated.
void tell_motion(Derivation& d, const Analysis& a, const ReportOptions& options) {
  d.motion = *a.motion;
  d.motion->in_state.clear();
  d.motion->conditions_in_state.clear();
  for (auto& c : d.motion->conditions) number_bounds(c.solved, *a.model.symbols, options.digits, a.motion->definitions);
  if (options.narrate) narrate_motion(d, a.model, *d.motion, options);
}

// The simulated motion's figure, and what happened in the run, in words.
void tell_run(Derivation& d, const Simulation& run) {
  d.motion_plot = run.table;
  d.motion_events.push_back("Integrated to t = " + decimal_string(GiNaC::numeric(run.reached), 6) + " s (" +
                            std::to_string(run.steps) + " steps, Dormand-Prince 5(4)).");
  for (const auto& e : run.events)
    d.motion_events.push_back("At t = " + decimal_string(GiNaC::numeric(e.t), 6) + " s: " + e.what +
                              (e.ends ? "; the run ends." : "."));
  if (!run.stopped.empty() && run.events.empty()) d.motion_events.push_back("Stopped: " + run.stopped + ".");
}

}  // namespace

Derivation explain(const Analysis& a, const ReportOptions& options) {
  if (!a.phases.empty()) throw InternalError("explain: a phased analysis is explained phase by phase (explain_phases)");
  // The answers with the report's digits, and the runs the description asks for (with the
  // narration only: their figures): stages of their own (solve/answers, analysis/runs),
  // narrated here.
  const Answers answers = answer(a.model, a.system, a.solution, options.digits);
  const DescribedRuns runs = options.narrate ? run_described(a, answers) : DescribedRuns{};
  Derivation d =
      explain(a.model, a.system, a.solution, answers, a.power, options, a.interval_end ? &*a.interval_end : nullptr);
  if (!a.regimes.empty()) narrate_regimes(d, a.regimes, *a.model.symbols);
  if (a.impact) {
    narrate_impact(d, a.model, *a.impact, options);
    d.impact_equations = a.impact->equations;
  }
  if (a.motion) tell_motion(d, a, options);
  if (runs.motion) tell_run(d, *runs.motion);
  if (runs.sweep) d.sweep_plot = *runs.sweep;
  return d;
}

}  // namespace tackle

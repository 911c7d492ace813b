#include "pipeline/pipeline.hpp"

#include "report/sweep.hpp"
#include "motion/simulate.hpp"

#include <algorithm>

namespace tackle {

namespace {

// Motion in time, after the instant; a motion that cannot be followed is an input error at
// the description's 'motion'.
void follow_motion(Analysis& a) {
  a.motion = analyze_motion(a.model, a.system, a.solution);
  if (a.motion && !a.motion->problem.empty()) throw InputError({{a.model.motion->at, a.motion->problem}});
}

}  // namespace

std::unique_ptr<const Analysis> analyze(const Description& d, const RuleSet& rules) {
  auto a = std::make_unique<Analysis>();
  a->model = build_model(d, rules);
  a->system = build_equations(a->model);
  a->solution = solve(a->model, a->system);
  a->power = check_power(a->model, a->system, a->solution);
  follow_motion(*a);
  return a;
}

std::unique_ptr<const Analysis> analyze_text(const std::string& text, const std::string& file, const RuleSet& rules) {
  DescriptionRead read = read_description_text(text, file);
  if (!read.usable) throw InputError(read.problems);
  std::vector<Diagnostic> all = read.problems;
  auto a = std::make_unique<Analysis>();
  try {
    a->model = build_model(read.description, rules);
  } catch (const InputError& e) {
    all.insert(all.end(), e.diagnostics().begin(), e.diagnostics().end());
  }
  if (!all.empty()) {
    std::stable_sort(all.begin(), all.end(), [](const Diagnostic& x, const Diagnostic& y) {
      return std::pair(x.where.line, x.where.column) < std::pair(y.where.line, y.where.column);
    });
    throw InputError(all);
  }
  a->system = build_equations(a->model);
  if (auto problems = check_dimensions(a->model, a->system); !problems.empty()) throw InputError(problems);
  a->solution = solve(a->model, a->system);
  a->power = check_power(a->model, a->system, a->solution);
  follow_motion(*a);
  return a;
}

std::unique_ptr<const Analysis> analyze_file(const std::string& path, const RuleSet& rules) {
  return analyze_text(read_text_file(path), path, rules);
}

Derivation explain(const Analysis& a, const ReportOptions& options) {
  Derivation d = explain(a.model, a.system, a.solution, a.power, options);
  if (a.motion) {
    narrate_motion(d, a.model, *a.motion, options);
    d.motion = &*a.motion;
    if (a.model.motion->until) {
      // A figure, not a command: a second of computing at most (a hostile 'until' must not
      // hold a report up; `tackle simulate` allows 10 s).
      SimulationSpec spec;
      spec.time_limit = 1;
      const Simulation run = simulate(a, spec, a.model.motion->at);
      d.motion_pgfplots = sweep_pgfplots(run.table);
      d.motion_events.push_back("Integrated to t = " + decimal_string(GiNaC::numeric(run.reached), 6) + " s (" +
                                std::to_string(run.steps) + " steps, Dormand-Prince 5(4)).");
      for (const auto& e : run.events)
        d.motion_events.push_back("At t = " + decimal_string(GiNaC::numeric(e.t), 6) + " s: " + e.what + (e.ends ? "; the run ends." : "."));
      if (!run.stopped.empty() && run.events.empty()) d.motion_events.push_back("Stopped: " + run.stopped + ".");
    }
  }
  if (a.model.sweep) d.figure_pgfplots = sweep_pgfplots(run_sweep(a, d, sweep_spec(*a.model.sweep), a.model.sweep->at));
  return d;
}

SweepSpec sweep_spec(const SweepDesc& s) {
  SweepSpec spec;
  spec.vary = s.vary.text;
  for (const auto& f : s.fix) spec.fix.push_back(f.text);
  for (const auto& p : s.plot) spec.plot.push_back(p.text);
  return spec;
}

}  // namespace tackle

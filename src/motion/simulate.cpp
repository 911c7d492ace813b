#include "motion/simulate.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <functional>

#include <Eigen/Dense>
#include <boost/numeric/odeint.hpp>

#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "numeric/compiled.hpp"
#include "numeric/evaluate.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

using State = std::vector<double>;
namespace odeint = boost::numeric::odeint;
// Dormand-Prince 5(4) with dense output, as make_dense_output makes it.
using Stepper = decltype(odeint::make_dense_output(1.0, 1.0, odeint::runge_kutta_dopri5<State>()));

// An expression in the state, the parameters put in (definitions, geometric lengths and
// values), ready to compile. A turning length's definition may bring in a dependent
// coordinate (the massless ring's y_R in l_RG): `dependent` gives it in the state.
ex in_numbers(const ex& e, const SymbolTable& table, const exmap& values, const exmap& dependent = {}) {
  ex out = e;
  const exmap defs = table.definitions(true);
  for (int depth = 0; depth < 8; ++depth) out = substituted(out, defs);
  if (!dependent.empty()) out = substituted(out, dependent);
  return substituted(out, values);
}

bool holds(double v, const std::string& op) {
  if (op == ">=") return v >= 0;
  if (op == ">") return v > 0;
  if (op == "<=") return v <= 0;
  if (op == "<") return v < 0;
  return std::abs(v) <= 1e-12;
}

// The end time: --until, else the description's 'until' (a located InputError when there is
// none, or it is not a positive number of seconds).
double end_time(const SimulationSpec& spec, const MotionSpec& ms, const Location& where) {
  double until = 0;
  if (spec.until)
    until = *spec.until;
  else if (ms.until)
    until = ex_to<numeric>(evalf(*ms.until)).to_double();
  else
    throw InputError({{where, "no end time (expected --until SECONDS, or 'until' in the description's 'motion')"}});
  if (!(until > 0) || !std::isfinite(until))
    throw InputError({{where, "the end time must be a positive number of seconds"}});
  return until;
}

// A sign watched along the run (`g op 0`): a validity condition, a strand's length, a slip
// speed; `what` says what its change means.
struct Watched {
  Compiled g;
  std::string op, what;
  bool slip = false;  // a slip speed (positive while the contact slips the way it assumes)
};

// The run compiled for doubles: the right-hand side, the watched signs, and the table's
// columns with the table's header; the problems found on the way.
struct CompiledRun {
  const SymbolTable& table;
  const Location& where;
  // The inputs of every compiled expression: t, then the coordinates, then the rates.
  std::vector<ex> inputs{};
  exmap values{};
  exmap state_of{};   // quantities asked for, dependent coordinates and rates -> their expressions in the state
  exmap dependent{};  // the dependent coordinates and rates alone
  std::vector<Diagnostic> problems{};
  std::vector<Compiled> accel{};
  // The mass-matrix form: M(q) and F compiled, M q'' = F solved at every evaluation.
  std::vector<std::pair<Eigen::Index, Compiled>> mass{};  // row * n + column, for the entries that are not 0
  std::vector<Watched> conditions{};
  std::vector<Compiled> columns{};
  SweepResult table_out{};

  // `e` compiled in the inputs, its parameters put in (a problem said, with `what`, where it cannot be).
  std::optional<Compiled> compile(const ex& e, const std::string& what) {
    std::string problem;
    auto c = Compiled::compile(in_numbers(e, table, values, dependent), inputs, problem);
    if (!c) problems.push_back({where, what + ": " + problem});
    return c;
  }
};

// The inputs (t, the coordinates, the rates), the parameters' values, and what the motion
// gives in the state: the quantities asked for and the dependent coordinates and rates.
void state_inputs(CompiledRun& run, const Model& m, const Motion& mo) {
  const EquationsOfMotion& eom = mo.eom;
  std::vector<ex>& inputs = run.inputs;
  inputs.push_back(m.time);
  inputs.insert(inputs.end(), eom.q.begin(), eom.q.end());
  inputs.insert(inputs.end(), eom.dq.begin(), eom.dq.end());
  run.values = run.table.values();
  for (const auto& x : inputs) run.values.erase(x);  // a coordinate given a value at the instant varies now
  for (const auto& [sym, e] : mo.in_state) {
    run.state_of[sym] = e;
    const SymbolInfo* info = run.table.find(sym);
    if (info && (info->role == SymbolRole::coordinate || info->role == SymbolRole::rate)) run.dependent[sym] = e;
  }
}

// The right-hand side compiled: each acceleration, or in the mass-matrix form each forcing
// and the mass matrix's entries that are not 0.
void compile_equations(CompiledRun& run, const EquationsOfMotion& eom) {
  const std::size_t n = eom.dof;
  for (std::size_t i = 0; i < n && !eom.mass_form; ++i)
    if (auto c = run.compile(eom.acceleration[i], "the acceleration " + to_text(eom.ddq[i]))) run.accel.push_back(*c);
  for (std::size_t i = 0; i < n && eom.mass_form; ++i) {
    if (auto c = run.compile(eom.forcing[i], "the forcing of " + to_text(eom.q[i]))) run.accel.push_back(*c);
    for (std::size_t j = 0; j < n; ++j)
      if (const ex& e = eom.M(static_cast<unsigned>(i), static_cast<unsigned>(j)); !e.is_zero())
        if (auto c = run.compile(e, "the mass matrix")) run.mass.emplace_back(static_cast<Eigen::Index>(i * n + j), *c);
  }
}

// The signs watched, compiled: each validity condition, each strand's length, each slip speed.
void compile_watched(CompiledRun& run, const Motion& mo) {
  std::vector<Watched>& conditions = run.conditions;
  for (const auto& [c, e] : mo.conditions_in_state)
    if (auto g = run.compile(e, c->condition->source))
      conditions.push_back({*g, c->condition->op, c->condition->source + ": " + c->condition->otherwise});
  for (const auto& [what, e] : mo.strands_in_state)
    if (auto g = run.compile(e, what))
      conditions.push_back({*g, ">", what + ": its length reaches zero (a body reaches the point at its end)"});
  for (const auto& [what, e] : mo.slips_in_state)
    if (auto g = run.compile(e, what))
      conditions.push_back(
          {*g, ">", what + ": the contact stops slipping (its friction would change; the body may roll from here)",
           true});
}

// What to tabulate: as asked, else the description's plot, else the coordinates; each column
// compiled, with the table's header (names, LaTeX, units). The columns' one dimension, where
// they share one.
std::optional<Dimension> compile_columns(CompiledRun& run, const Model& m, const EquationsOfMotion& eom,
                                         const SimulationSpec& spec) {
  const SymbolTable& table = run.table;
  SweepResult& table_out = run.table_out;
  std::vector<std::string> plot = spec.plot;
  if (plot.empty())
    for (const auto& p : m.motion->plot) plot.push_back(p.text);
  if (plot.empty())
    for (const auto& q : eom.q) plot.push_back(to_text(q));
  table_out.title = m.title;
  table_out.x_name = "t";
  table_out.x_unit = "s";
  table_out.x_latex = "t";
  std::optional<Dimension> common;
  bool same_dimension = true;
  for (const auto& p : plot) {
    auto r = parse_expression(p, table);
    if (!r.value) {
      for (const auto& pr : r.problems) run.problems.push_back({run.where, "plot '" + p + "': " + pr.message});
      continue;
    }
    const ex e = r.value->subs(run.state_of);
    if (auto c = run.compile(e, "plot '" + p + "'")) {
      run.columns.push_back(*c);
      table_out.names.push_back(p);
      table_out.latex.push_back(to_latex(*r.value));
      std::string dim_problem;
      const auto dim = dimension_of(e, table, dim_problem);
      table_out.units.push_back(dim ? si_unit_name(*dim) : "");
      if (!dim || (common && !(*common == *dim)))
        same_dimension = false;
      else
        common = dim;
    }
  }
  return same_dimension ? common : std::nullopt;
}

// The run compiled: its inputs, right-hand side, watched signs and columns (a located
// InputError with every problem found).
CompiledRun compile_run(const Model& m, const Motion& mo, const SimulationSpec& spec, const Location& where) {
  CompiledRun run{*m.symbols, where};
  state_inputs(run, m, mo);
  compile_equations(run, mo.eom);
  compile_watched(run, mo);
  const auto unit = compile_columns(run, m, mo.eom, spec);
  if (!run.problems.empty()) throw InputError(run.problems);
  if (unit) run.table_out.y_unit = si_unit_name(*unit);
  return run;
}

// The initial state in numbers, the coordinates then the rates (a located InputError for a
// value with no number).
State initial_state(const EquationsOfMotion& eom, const MotionSpec& ms, const CompiledRun& run) {
  const std::size_t n = eom.dof;
  State x(2 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (const bool rate : {false, true}) {
      const ex& s = rate ? eom.dq[i] : eom.q[i];
      const ex v = evalf(in_numbers(ms.initial.at(s), run.table, run.values));
      if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real())
        throw InputError(
            {{ms.at, "the initial value of " + to_text(s) + " has no number (a parameter without a value?)"}});
      x[rate ? n + i : i] = ex_to<numeric>(v).to_double();
    }
  return x;
}

// The compiled run evaluated in a state: the right-hand side, the table's rows, the watched signs.
struct Run {
  CompiledRun& c;
  const EquationsOfMotion& eom;
  std::size_t n;
  std::vector<double> in;  // the inputs of the compiled expressions
  Eigen::MatrixXd Mq;
  Eigen::VectorXd Fq;

  // The inputs at time t in state s.
  void load(double t, const State& s) {
    in[0] = t;
    for (std::size_t i = 0; i < 2 * n; ++i) in[1 + i] = s[i];
  }
  // ds/dt: the rates, and the accelerations (M q'' = F solved in the mass-matrix form).
  void rhs(const State& s, State& dsdt, double t) {
    load(t, s);
    for (std::size_t i = 0; i < n; ++i) {
      dsdt[i] = s[n + i];
      dsdt[n + i] = c.accel[i](in.data());
    }
    if (!eom.mass_form) return;
    const auto size = static_cast<Eigen::Index>(n);
    for (const auto& [at, g] : c.mass) Mq(at / size, at % size) = g(in.data());
    for (Eigen::Index i = 0; i < size; ++i) Fq(i) = dsdt[n + static_cast<std::size_t>(i)];
    const Eigen::VectorXd a = Mq.ldlt().solve(Fq);
    for (Eigen::Index i = 0; i < size; ++i) dsdt[n + static_cast<std::size_t>(i)] = a(i);
  }
  // The table's row at time t.
  void record(double t, const State& s) {
    SweepResult& table_out = c.table_out;
    load(t, s);
    table_out.x.push_back(t);
    if (table_out.y.empty()) table_out.y.resize(c.columns.size());
    for (std::size_t k = 0; k < c.columns.size(); ++k) {
      const double v = c.columns[k](in.data());
      table_out.y[k].push_back(std::isfinite(v) ? std::optional<double>(v) : std::nullopt);
    }
    table_out.valid.push_back(true);
  }
  // Whether watched sign k holds at time t in state s.
  bool truth(std::size_t k, double t, const State& s) {
    load(t, s);
    return holds(c.conditions[k].g(in.data()), c.conditions[k].op);
  }
};

// A slip from rest (two blocks that start at one speed) is no end: it starts, the way it
// assumes, where a short step from t = 0 makes it positive.
bool starts_slipping(Run& run, std::size_t k, const State& x, double until) {
  const std::size_t n = run.n;
  const Watched& w = run.c.conditions[k];
  run.load(0, x);
  double scale = 1;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::fabs(x[n + i]));
  if (!w.slip || std::fabs(w.g(run.in.data())) > 1e-12 * scale) return false;
  State dx(2 * n), y(2 * n);
  run.rhs(x, dx, 0);
  const double h = 1e-6 * until;
  for (std::size_t i = 0; i < 2 * n; ++i) y[i] = x[i] + h * dx[i];
  run.load(h, y);
  return w.g(run.in.data()) > 0;
}

// A model wrong from the start: a condition that fails at t = 0, or a start against the
// direction a rule assumes; what, in words.
std::optional<std::string> wrong_at_start(Run& run, const State& x, double until, const Motion& mo) {
  std::optional<std::string> wrong;
  for (std::size_t k = 0; k < run.c.conditions.size() && !wrong; ++k)
    if (!run.truth(k, 0, x) && !starts_slipping(run, k, x, until)) wrong = run.c.conditions[k].what;
  if (!wrong && !mo.direction_against.empty()) wrong = mo.direction_against;
  return wrong;
}

// The coordinates of turning bodies when a slip speed is watched: their rates turning is no event.
// (Or of a body whose every assumed sliding is a slip on another body, watched: its own
// rate turning is no event either.)
std::vector<bool> slip_watched(const Model& m, const EquationsOfMotion& eom) {
  const std::size_t n = eom.dof;
  std::vector<bool> slip_watched(n, false);
  auto watched = [&](int body) {
    bool any = false;
    for (const auto& l : m.loads) {
      if (l.body != body || std::find(m.direction_assumed_by.begin(), m.direction_assumed_by.end(), l.source()) ==
                                m.direction_assumed_by.end())
        continue;
      const bool slip = std::any_of(m.slips.begin(), m.slips.end(), [&](const Model::Slip& s) {
        return s.source == l.source() && std::find(s.bodies.begin(), s.bodies.end(), body) != s.bodies.end();
      });
      if (!slip) return false;
      any = true;
    }
    return any;
  };
  if (!m.slips.empty())
    for (std::size_t i = 0; i < n; ++i)
      for (const auto& c : m.coordinates)
        if (c.q.is_equal(eom.q[i]) && c.body >= 0 &&
            (!m.bodies[static_cast<std::size_t>(c.body)].angle.is_zero() || watched(c.body)))
          slip_watched[i] = true;
  return slip_watched;
}

// The integration under way: the stepper, the rows taken, the rates' signs, where it ended.
struct Integration {
  Run& run;
  const Model& m;
  const SimulationSpec& spec;
  double until;
  std::vector<bool> slip_watched;
  Stepper stepper;
  double dt;  // between rows
  int next_sample = 0;
  std::vector<int> rate_sign{};
  State xm{}, x1{};  // a state on the dense output; the state at the step's end
  double end = 0;
};

// An event within a step: when (past the step where there is none), what, and whether it
// ends the run.
struct Event {
  double t;
  std::string what;
  bool ends = false;
};

// The first event in (t0, t1], located by bisection on the dense output: a watched sign that
// stops holding, or a rate that turns where a rule assumed the direction of motion.
Event first_event(Integration& it, double t0, double t1) {
  Run& run = it.run;
  const std::size_t n = run.n;
  const EquationsOfMotion& eom = run.eom;
  const State& x1 = it.x1;
  const bool direction_assumed = !it.m.direction_assumed_by.empty();
  Event e{t1 + 1, {}};
  auto locate = [&](const std::function<bool(double, const State&)>& changed) {
    double lo = t0, hi = t1;
    for (int k = 0; k < 60 && hi - lo > 1e-13 * std::max(1.0, hi); ++k) {
      const double mid = (lo + hi) / 2;
      it.stepper.calc_state(mid, it.xm);
      (changed(mid, it.xm) ? hi : lo) = mid;
    }
    return hi;
  };
  for (std::size_t k = 0; k < run.c.conditions.size(); ++k)
    if (!run.truth(k, t1, x1)) {
      const double te = locate([&](double t, const State& s) { return !run.truth(k, t, s); });
      if (te < e.t) e.t = te, e.what = run.c.conditions[k].what, e.ends = true;
    }
  for (std::size_t i = 0; i < n; ++i) {
    const int now = x1[n + i] > 0 ? 1 : (x1[n + i] < 0 ? -1 : 0);
    // A turn matters where a rule assumed the direction of motion (sliding friction); an
    // oscillation's turns are not events, nor are those of a body whose contact slips at
    // a speed of its own (watched above).
    if (direction_assumed && !it.slip_watched[i] && it.rate_sign[i] != 0 && now != it.rate_sign[i]) {
      const int before = it.rate_sign[i];
      const double te = locate([&](double, const State& s) { return (s[n + i] > 0 ? 1 : -1) != before; });
      if (te < e.t || (te == e.t && !e.ends)) {
        e.t = te;
        e.what = to_text(eom.dq[i]) + " = 0: " + to_text(eom.q[i]) + " turns (the friction of " +
                 it.m.direction_assumed_by.front() + " would change direction)";
        e.ends = true;
      }
    }
    if (now != 0) it.rate_sign[i] = now;
  }
  return e;
}

// The table's rows due up to stop_at, from the dense output.
void sample_until(Integration& it, double stop_at) {
  while (it.next_sample * it.dt <= stop_at + 1e-12 * it.until && it.next_sample < it.spec.samples) {
    const double ts = std::min(it.next_sample * it.dt, it.until);
    it.stepper.calc_state(ts, it.xm);
    it.run.record(ts, it.xm);
    ++it.next_sample;
  }
}

// The integration loop: a step at a time, its first event and the rows due, until the end
// time, an event that ends the run, a step that cannot be made, a state no longer finite, or
// the time limit.
void integrate(Integration& it, Simulation& out) {
  const double until = it.until;
  const auto started = std::chrono::steady_clock::now();
  while (true) {
    // (Not a structured binding: the lambdas below capture the two times.) Odeint gives up
    // on a step after 500 failed size adjustments (a stiff or singular right-hand side): the
    // run is undecided from there. Its exception is odeint's own, never GiNaC's.
    std::pair<double, double> span;
    try {
      span = it.stepper.do_step([&](const State& s, State& dsdt, double t) { it.run.rhs(s, dsdt, t); });
    } catch (const odeint::step_adjustment_error&) {
      it.end = it.stepper.current_time();
      out.stopped = "the integration could not make a step after t = " + decimal_string(numeric(it.end), 6) +
                    " s (the equations are too stiff or singular there): undecided beyond";
      break;
    }
    const double t0 = span.first, t1 = span.second;
    ++out.steps;
    it.x1 = it.stepper.current_state();
    bool finite = true;
    for (double v : it.x1) finite = finite && std::isfinite(v);
    if (!finite) {
      it.end = t0;
      out.stopped = "the state stopped being finite after t = " + decimal_string(numeric(t0), 6) + " s";
      break;
    }
    const Event e = first_event(it, t0, t1);
    sample_until(it, std::min({e.t, until, t1}));
    if (e.t <= t1 && e.t <= until) {
      out.events.push_back({e.t, e.what, e.ends});
      if (e.ends) {
        it.end = e.t;
        it.stepper.calc_state(e.t, it.xm);
        if (it.run.c.table_out.x.empty() || it.run.c.table_out.x.back() < e.t) it.run.record(e.t, it.xm);
        out.stopped = "the model no longer holds after t = " + decimal_string(numeric(e.t), 6) + " s (" + e.what + ")";
        break;
      }
    }
    if (t1 >= until) {
      out.complete = true;
      break;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (elapsed > it.spec.time_limit || out.steps > 10000000) {
      it.end = t1;
      out.stopped = "the integration reached only t = " + decimal_string(numeric(t1), 6) + " s in its time limit (" +
                    std::to_string(out.steps) + " steps): undecided beyond";
      break;
    }
  }
}

}  // namespace

Simulation simulate(const Analysis& a, const SimulationSpec& spec, const Location& where) {
  const Model& m = a.model;
  if (!a.motion)
    throw InputError(
        {{where, "the description has no 'motion' (expected, e.g., motion: {initial: {x: 0, dot(x): 0}})"}});
  const Motion& mo = *a.motion;
  const MotionSpec& ms = *m.motion;
  const EquationsOfMotion& eom = mo.eom;
  const double until = end_time(spec, ms, where);
  CompiledRun compiled = compile_run(m, mo, spec, where);
  const State x = initial_state(eom, ms, compiled);
  const std::size_t n = eom.dof;
  const auto size = static_cast<Eigen::Index>(n);
  Run run{compiled, eom, n, std::vector<double>(1 + 2 * n), Eigen::MatrixXd::Zero(size, size), Eigen::VectorXd(size)};

  Simulation out;
  if (const auto wrong = wrong_at_start(run, x, until, mo)) {
    out.events.push_back({0, *wrong, true});
    out.stopped = "the model does not hold at t = 0 (" + *wrong + ")";
    run.record(0, x);
    out.table = std::move(compiled.table_out);
    return out;
  }
  Integration it{run,
                 m,
                 spec,
                 until,
                 slip_watched(m, eom),
                 odeint::make_dense_output(spec.tolerance, spec.tolerance, odeint::runge_kutta_dopri5<State>()),
                 until / std::max(1, spec.samples - 1)};
  it.stepper.initialize(x, 0.0, until / 1000);
  it.rate_sign.resize(n);
  for (std::size_t i = 0; i < n; ++i) it.rate_sign[i] = x[n + i] > 0 ? 1 : (x[n + i] < 0 ? -1 : 0);
  it.xm.resize(2 * n);
  it.x1.resize(2 * n);
  it.end = until;
  integrate(it, out);
  out.reached = out.complete ? until : it.end;
  out.not_followed = mo.not_followed;
  out.table = std::move(compiled.table_out);
  return out;
}

}  // namespace tackle

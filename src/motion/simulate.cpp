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

}  // namespace

Simulation simulate(const Analysis& a, const SimulationSpec& spec, const Location& where) {
  const Model& m = a.model;
  const SymbolTable& table = *m.symbols;
  if (!a.motion) throw InputError({{where, "the description has no 'motion' (expected, e.g., motion: {initial: {x: 0, dot(x): 0}})"}});
  const Motion& mo = *a.motion;
  const MotionSpec& ms = *m.motion;
  const EquationsOfMotion& eom = mo.eom;
  double until = 0;
  if (spec.until) until = *spec.until;
  else if (ms.until) until = ex_to<numeric>(evalf(*ms.until)).to_double();
  else throw InputError({{where, "no end time (expected --until SECONDS, or 'until' in the description's 'motion')"}});
  if (!(until > 0) || !std::isfinite(until)) throw InputError({{where, "the end time must be a positive number of seconds"}});

  // The inputs of every compiled expression: t, then the coordinates, then the rates.
  std::vector<ex> inputs{m.time};
  inputs.insert(inputs.end(), eom.q.begin(), eom.q.end());
  inputs.insert(inputs.end(), eom.dq.begin(), eom.dq.end());
  exmap values = table.values();
  for (const auto& x : inputs) values.erase(x);  // a coordinate given a value at the instant varies now
  exmap state_of;  // quantities asked for, dependent coordinates and rates -> their expressions in the state
  exmap dependent;  // the dependent coordinates and rates alone
  for (const auto& [sym, e] : mo.in_state) {
    state_of[sym] = e;
    const SymbolInfo* info = table.find(sym);
    if (info && (info->role == SymbolRole::coordinate || info->role == SymbolRole::rate)) dependent[sym] = e;
  }

  std::vector<Diagnostic> problems;
  auto compile = [&](const ex& e, const std::string& what) -> std::optional<Compiled> {
    std::string problem;
    auto c = Compiled::compile(in_numbers(e, table, values, dependent), inputs, problem);
    if (!c) problems.push_back({where, what + ": " + problem});
    return c;
  };
  const std::size_t n = eom.dof;
  std::vector<Compiled> accel;
  for (std::size_t i = 0; i < n && !eom.mass_form; ++i)
    if (auto c = compile(eom.acceleration[i], "the acceleration " + to_text(eom.ddq[i]))) accel.push_back(*c);
  // The mass-matrix form: M(q) and F compiled, M q'' = F solved at every evaluation.
  std::vector<std::pair<Eigen::Index, Compiled>> mass;  // row * n + column, for the entries that are not 0
  for (std::size_t i = 0; i < n && eom.mass_form; ++i) {
    if (auto c = compile(eom.forcing[i], "the forcing of " + to_text(eom.q[i]))) accel.push_back(*c);
    for (std::size_t j = 0; j < n; ++j)
      if (const ex& e = eom.M(static_cast<unsigned>(i), static_cast<unsigned>(j)); !e.is_zero())
        if (auto c = compile(e, "the mass matrix")) mass.emplace_back(static_cast<Eigen::Index>(i * n + j), *c);
  }
  struct Watched {
    Compiled g;
    std::string op, what;
    bool slip = false;  // a slip speed (positive while the contact slips the way it assumes)
  };
  std::vector<Watched> conditions;
  for (const auto& [c, e] : mo.conditions_in_state)
    if (auto g = compile(e, c->condition->source))
      conditions.push_back({*g, c->condition->op, c->condition->source + ": " + c->condition->otherwise});
  for (const auto& [what, e] : mo.strands_in_state)
    if (auto g = compile(e, what))
      conditions.push_back({*g, ">", what + ": its length reaches zero (a body reaches the point at its end)"});
  for (const auto& [what, e] : mo.slips_in_state)
    if (auto g = compile(e, what))
      conditions.push_back({*g, ">", what + ": the contact stops slipping (its friction would change; the body may roll from here)", true});
  // What to tabulate: as asked, else the description's plot, else the coordinates.
  std::vector<std::string> plot = spec.plot;
  if (plot.empty())
    for (const auto& p : ms.plot) plot.push_back(p.text);
  if (plot.empty())
    for (const auto& q : eom.q) plot.push_back(to_text(q));
  SweepResult table_out;
  table_out.title = m.title;
  table_out.x_name = "t";
  table_out.x_unit = "s";
  table_out.x_latex = "t";
  std::vector<Compiled> columns;
  std::optional<Dimension> common;
  bool same_dimension = true;
  for (const auto& p : plot) {
    auto r = parse_expression(p, table);
    if (!r.value) {
      for (const auto& pr : r.problems) problems.push_back({where, "plot '" + p + "': " + pr.message});
      continue;
    }
    const ex e = r.value->subs(state_of);
    if (auto c = compile(e, "plot '" + p + "'")) {
      columns.push_back(*c);
      table_out.names.push_back(p);
      table_out.latex.push_back(to_latex(*r.value));
      std::string dim_problem;
      const auto dim = dimension_of(e, table, dim_problem);
      table_out.units.push_back(dim ? si_unit_name(*dim) : "");
      if (!dim || (common && !(*common == *dim))) same_dimension = false;
      else common = dim;
    }
  }
  if (!problems.empty()) throw InputError(problems);
  if (same_dimension && common) table_out.y_unit = si_unit_name(*common);

  // The initial state.
  State x(2 * n);
  for (std::size_t i = 0; i < n; ++i)
    for (const bool rate : {false, true}) {
      const ex& s = rate ? eom.dq[i] : eom.q[i];
      const ex v = evalf(in_numbers(ms.initial.at(s), table, values));
      if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real())
        throw InputError({{ms.at, "the initial value of " + to_text(s) + " has no number (a parameter without a value?)"}});
      x[rate ? n + i : i] = ex_to<numeric>(v).to_double();
    }
  std::vector<double> in(1 + 2 * n);
  auto load = [&](double t, const State& s) {
    in[0] = t;
    for (std::size_t i = 0; i < 2 * n; ++i) in[1 + i] = s[i];
  };
  const auto size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd Mq = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd Fq(size);
  auto rhs = [&](const State& s, State& dsdt, double t) {
    load(t, s);
    for (std::size_t i = 0; i < n; ++i) {
      dsdt[i] = s[n + i];
      dsdt[n + i] = accel[i](in.data());
    }
    if (!eom.mass_form) return;
    for (const auto& [at, c] : mass) Mq(at / size, at % size) = c(in.data());
    for (Eigen::Index i = 0; i < size; ++i) Fq(i) = dsdt[n + static_cast<std::size_t>(i)];
    const Eigen::VectorXd a = Mq.ldlt().solve(Fq);
    for (Eigen::Index i = 0; i < size; ++i) dsdt[n + static_cast<std::size_t>(i)] = a(i);
  };

  Simulation out;
  auto record = [&](double t, const State& s) {
    load(t, s);
    table_out.x.push_back(t);
    if (table_out.y.empty()) table_out.y.resize(columns.size());
    for (std::size_t k = 0; k < columns.size(); ++k) {
      const double v = columns[k](in.data());
      table_out.y[k].push_back(std::isfinite(v) ? std::optional<double>(v) : std::nullopt);
    }
    table_out.valid.push_back(true);
  };
  // Watched signs: each condition's truth, each rate's sign.
  auto truth = [&](std::size_t k, double t, const State& s) {
    load(t, s);
    return holds(conditions[k].g(in.data()), conditions[k].op);
  };
  // A model wrong from the start: a condition that fails at t = 0, or a start against the
  // direction a rule assumes.
  // A slip from rest (two blocks that start at one speed) is no end: it starts, the way it
  // assumes, where a short step from t = 0 makes it positive.
  auto starts_slipping = [&](std::size_t k) {
    load(0, x);
    double scale = 1;
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, std::fabs(x[n + i]));
    if (!conditions[k].slip || std::fabs(conditions[k].g(in.data())) > 1e-12 * scale) return false;
    State dx(2 * n), y(2 * n);
    rhs(x, dx, 0);
    const double h = 1e-6 * until;
    for (std::size_t i = 0; i < 2 * n; ++i) y[i] = x[i] + h * dx[i];
    load(h, y);
    return conditions[k].g(in.data()) > 0;
  };
  std::optional<std::string> wrong_at_start;
  for (std::size_t k = 0; k < conditions.size() && !wrong_at_start; ++k)
    if (!truth(k, 0, x) && !starts_slipping(k)) wrong_at_start = conditions[k].what;
  if (!wrong_at_start && !mo.direction_against.empty()) wrong_at_start = mo.direction_against;
  if (wrong_at_start) {
    out.events.push_back({0, *wrong_at_start, true});
    out.stopped = "the model does not hold at t = 0 (" + *wrong_at_start + ")";
    record(0, x);
    out.table = std::move(table_out);
    return out;
  }
  const bool direction_assumed = !m.direction_assumed_by.empty();
  // The coordinates of turning bodies when a slip speed is watched: their rates turning is no event.
  // (Or of a body whose every assumed sliding is a slip on another body, watched: its own
  // rate turning is no event either.)
  std::vector<bool> slip_watched(n, false);
  auto watched = [&](int body) {
    bool any = false;
    for (const auto& l : m.loads) {
      if (l.body != body || std::find(m.direction_assumed_by.begin(), m.direction_assumed_by.end(), l.source) == m.direction_assumed_by.end())
        continue;
      const bool slip = std::any_of(m.slips.begin(), m.slips.end(), [&](const Model::Slip& s) {
        return s.source == l.source && std::find(s.bodies.begin(), s.bodies.end(), body) != s.bodies.end();
      });
      if (!slip) return false;
      any = true;
    }
    return any;
  };
  if (!m.slips.empty())
    for (std::size_t i = 0; i < n; ++i)
      for (const auto& c : m.coordinates)
        if (c.q.is_equal(eom.q[i]) && c.body >= 0 && (!m.bodies[static_cast<std::size_t>(c.body)].angle.is_zero() || watched(c.body)))
          slip_watched[i] = true;

  namespace odeint = boost::numeric::odeint;
  auto stepper = odeint::make_dense_output(spec.tolerance, spec.tolerance, odeint::runge_kutta_dopri5<State>());
  stepper.initialize(x, 0.0, until / 1000);
  const double dt = until / std::max(1, spec.samples - 1);
  int next_sample = 0;
  std::vector<int> rate_sign(n);
  for (std::size_t i = 0; i < n; ++i) rate_sign[i] = x[n + i] > 0 ? 1 : (x[n + i] < 0 ? -1 : 0);
  const auto started = std::chrono::steady_clock::now();
  State xm(2 * n), x1(2 * n);
  double end = until;
  while (true) {
    // (Not a structured binding: the lambdas below capture the two times.) Odeint gives up
    // on a step after 500 failed size adjustments (a stiff or singular right-hand side): the
    // run is undecided from there. Its exception is odeint's own, never GiNaC's.
    std::pair<double, double> span;
    try {
      span = stepper.do_step(rhs);
    } catch (const odeint::step_adjustment_error&) {
      end = stepper.current_time();
      out.stopped = "the integration could not make a step after t = " + decimal_string(numeric(end), 6) +
                    " s (the equations are too stiff or singular there): undecided beyond";
      break;
    }
    const double t0 = span.first, t1 = span.second;
    ++out.steps;
    x1 = stepper.current_state();
    bool finite = true;
    for (double v : x1) finite = finite && std::isfinite(v);
    if (!finite) {
      end = t0;
      out.stopped = "the state stopped being finite after t = " + decimal_string(numeric(t0), 6) + " s";
      break;
    }
    // The first event in (t0, t1], located by bisection on the dense output.
    double event_t = t1 + 1;
    std::string event_what;
    bool event_ends = false;
    auto locate = [&](const std::function<bool(double, const State&)>& changed) {
      double lo = t0, hi = t1;
      for (int it = 0; it < 60 && hi - lo > 1e-13 * std::max(1.0, hi); ++it) {
        const double mid = (lo + hi) / 2;
        stepper.calc_state(mid, xm);
        (changed(mid, xm) ? hi : lo) = mid;
      }
      return hi;
    };
    for (std::size_t k = 0; k < conditions.size(); ++k)
      if (!truth(k, t1, x1)) {
        const double te = locate([&](double t, const State& s) { return !truth(k, t, s); });
        if (te < event_t) event_t = te, event_what = conditions[k].what, event_ends = true;
      }
    for (std::size_t i = 0; i < n; ++i) {
      const int now = x1[n + i] > 0 ? 1 : (x1[n + i] < 0 ? -1 : 0);
      // A turn matters where a rule assumed the direction of motion (sliding friction); an
      // oscillation's turns are not events, nor are those of a body whose contact slips at
      // a speed of its own (watched above).
      if (direction_assumed && !slip_watched[i] && rate_sign[i] != 0 && now != rate_sign[i]) {
        const int before = rate_sign[i];
        const double te = locate([&](double, const State& s) { return (s[n + i] > 0 ? 1 : -1) != before; });
        if (te < event_t || (te == event_t && !event_ends)) {
          event_t = te;
          event_what = to_text(eom.dq[i]) + " = 0: " + to_text(eom.q[i]) + " turns (the friction of " +
                       m.direction_assumed_by.front() + " would change direction)";
          event_ends = true;
        }
      }
      if (now != 0) rate_sign[i] = now;
    }
    const double stop_at = std::min({event_t, until, t1});
    while (next_sample * dt <= stop_at + 1e-12 * until && next_sample < spec.samples) {
      const double ts = std::min(next_sample * dt, until);
      stepper.calc_state(ts, xm);
      record(ts, xm);
      ++next_sample;
    }
    if (event_t <= t1 && event_t <= until) {
      out.events.push_back({event_t, event_what, event_ends});
      if (event_ends) {
        end = event_t;
        stepper.calc_state(event_t, xm);
        if (table_out.x.empty() || table_out.x.back() < event_t) record(event_t, xm);
        out.stopped = "the model no longer holds after t = " + decimal_string(numeric(event_t), 6) + " s (" + event_what + ")";
        break;
      }
    }
    if (t1 >= until) {
      out.complete = true;
      break;
    }
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (elapsed > spec.time_limit || out.steps > 10000000) {
      end = t1;
      out.stopped = "the integration reached only t = " + decimal_string(numeric(t1), 6) + " s in its time limit (" +
                    std::to_string(out.steps) + " steps): undecided beyond";
      break;
    }
  }
  out.reached = out.complete ? until : end;
  out.not_followed = mo.not_followed;
  out.table = std::move(table_out);
  return out;
}

}  // namespace tackle

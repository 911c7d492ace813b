// The motion: the model's accelerations integrated over [0, 1 s] (or to where tackle's run
// ends) from the description's initial values, against `tackle simulate` at 11 times.
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

#include "crosscheck/compare.hpp"
#include "crosscheck/model.hpp"
#include "motion/simulate.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

namespace {

// The model's first event along its motion (Model::watched): a requirement that is not met
// (at the start: at t = 0; one that starts at 0 and falls: where it falls; else where it
// stops being met: a string goes slack, a contact stops pushing, a grip slips), a slip against
// the sliding direction the description assumes at the start (or, from rest, first growing
// against it), or a slip that turns.
class Events {
 public:
  Events(const Model& m, const State& start)
      : m_(m), tol_(1e-7 * std::max(1.0, m.largest_mass() * m.gravity_magnitude())) {
    const auto w = m.watched(start);
    for (std::size_t k = 0; k < w.size(); ++k) {
      const double v = w[k].second;
      // (a requirement, or a slip, is watched as a quantity that must stay positive; a slip
      // that starts at 0 takes the sign it first has)
      slip_.push_back(k >= m.requirements().size());
      sign_.push_back(std::isnan(v) || std::abs(v) <= tol_ ? (slip_[k] ? 0 : 1) : v > 0 ? 1 : -1);
      if (sign_[k] < 0 && !first)
        first = {0.0, w[k].first + (slip_[k] ? ": against the assumed sliding direction" : "")};
    }
  }
  // A step from t0 to t1, `at` the state at any time in it.
  void step(double t0, double t1, const std::function<State(double)>& at) {
    if (first) return;
    const auto w = m_.watched(at(t1));
    for (std::size_t k = 0; k < w.size(); ++k) {
      const double v = w[k].second;
      if (std::isnan(v) || std::abs(v) <= tol_) continue;
      const int now = v > 0 ? 1 : -1;
      if (sign_[k] != 0 && now != sign_[k]) {
        const double te = locate(k, t0, t1, at);
        if (!first || te < first->first) first = {te, w[k].first};
      } else if (sign_[k] == 0) {
        // a slip from rest that first grows against the assumed sliding direction: the
        // friction assumed would push the body along, from the start
        if (slip_[k] && now < 0 && !first) first = {0.0, w[k].first + ": against the assumed sliding direction"};
        sign_[k] = now;
      }
    }
  }
  std::optional<std::pair<double, std::string>> first;

 private:
  const Model& m_;
  double tol_;
  std::vector<int> sign_;
  std::vector<bool> slip_;
  double locate(std::size_t k, double lo, double hi, const std::function<State(double)>& at) const {
    for (int i = 0; i < 50 && hi - lo > 1e-12 * (1 + hi); ++i) {
      const double mid = (lo + hi) / 2;
      const double v = m_.watched(at(mid))[k].second;
      (v * sign_[k] > 0 ? lo : hi) = mid;
    }
    return hi;
  }
};

// tackle's first event that ends its run against the model's first event.
void compare_events(const tackle::Simulation& sim, const Events& ev, double horizon, Outcome& out) {
  std::optional<tackle::SimulationEvent> end;
  for (const auto& e : sim.events)
    if (e.ends) {
      end = e;
      break;
    }
  const auto close = [](double a, double b) { return std::abs(a - b) <= 1e-6 * std::max(1.0, std::abs(a)); };
  if (ev.first && ev.first->first <= horizon && (!end || !close(end->t, ev.first->first)))
    out.disagreements.push_back(
        {fmt::format("motion: the model's first event: {} at t = {:.9g} s; tackle's: {}", ev.first->second,
                     ev.first->first, end ? fmt::format("{} at t = {:.9g} s", end->what, end->t) : "none"),
         end ? end->t : -1, ev.first->first, "from the initial values"});
  else if (end && ev.first)
    out.motion_event = fmt::format("{} at t = {:.6g} s (tackle: {})", ev.first->second, ev.first->first, end->what);
  else if (end && !ev.first && end->t <= horizon)
    out.disagreements.push_back(
        {fmt::format("motion: tackle's run ends at t = {:.9g} s ({}); the model has no event there", end->t, end->what),
         end->t, -1, "from the initial values"});
}

}  // namespace

Outcome compare_motion(const tackle::Analysis& a, const Model& m, const tackle::Description& d, const Options& o) {
  Outcome out;
  if (!d.motion) return out;
  // Initial values, read from the description with the model's parameters (SI).
  std::map<std::string, double> coords, rates;
  {
    std::vector<std::string> names;
    std::map<std::string, int> slots;
    std::vector<double> vars;
    for (const auto& [k, v] : m.parameters()) {
      slots[k] = static_cast<int>(vars.size());
      vars.push_back(v);
    }
    for (const auto& [name, value] : d.motion->initial) {
      const Expr e = Expr::compile(value.text, [&](const std::string& n) {
        auto it = slots.find(n);
        return it == slots.end() ? -1 : it->second;
      });
      (name.text.rfind("dot(", 0) == 0 ? rates : coords)[name.text] = e.eval(vars);
    }
  }
  auto start = m.state_from(coords, rates, 0.0);
  if (!start) {
    out.motion_note = "the initial values do not keep the constraints in the model";
    return out;
  }
  tackle::SimulationSpec spec;
  spec.until = 1.0;
  spec.samples = 11;
  // (simulate tabulates the motion's own coordinates)
  for (const auto& q : a.model.motion->coordinates)
    if (const auto* info = a.model.symbols->find(q)) spec.plot.push_back(info->name);
  tackle::Simulation sim;
  try {
    sim = tackle::simulate(a, spec, tackle::Location{});
  } catch (const std::exception& e) {
    // tackle solved the instant but cannot follow it in time, where the model can
    out.disagreements.push_back(
        {std::string("motion: tackle's simulate refuses it: ") + e.what(), 0, 0, "from the initial values"});
    return out;
  }
  // The model's motion: positions and rates of every coordinate, Dormand-Prince 5(4) at a
  // tight tolerance; the translations' accelerations from the model at each state.
  using Vec = std::vector<double>;
  const int n = m.dofs();
  Vec x(static_cast<std::size_t>(2 * n));
  for (int i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = start->q(i);
    x[static_cast<std::size_t>(n + i)] = start->v(i);
  }
  bool failed = false;
  auto rhs = [&](const Vec& y, Vec& dy, double t) {
    State s;
    s.q = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
    s.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
    s.t = t;
    auto acc = m.accelerations(s);
    for (int i = 0; i < n; ++i) {
      dy[static_cast<std::size_t>(i)] = y[static_cast<std::size_t>(n + i)];
      dy[static_cast<std::size_t>(n + i)] = acc && std::isfinite((*acc)(i)) ? (*acc)(i) : 0.0;
    }
    if (!acc || !acc->allFinite()) failed = true;
  };
  namespace ode = boost::numeric::odeint;
  auto stepper = ode::make_dense_output(1e-11, 1e-11, ode::runge_kutta_dopri5<Vec>());
  double crossed = -1;
  long steps = 0;
  const auto began = std::chrono::steady_clock::now();
  std::size_t row = 0;
  const auto& table = sim.table;
  stepper.initialize(x, 0.0, 1e-3);
  auto state_at = [&](double t) {
    Vec y = x;
    stepper.calc_state(t, y);
    State s;
    s.q = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
    s.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
    s.t = t;
    return s;
  };
  Events events(m, *start);
  // Steps to `target` watching the strands and the events; false when the model cannot get
  // there (a point it cannot get past, where a strand's length reaches 0 and its direction is
  // lost, would take steps without end: the run stops there).
  auto advance = [&](double target) {
    while (target > 0 && stepper.current_time() < target && !failed && crossed < 0) {
      if (++steps > 200000 || std::chrono::steady_clock::now() - began > std::chrono::seconds(10)) {
        out.motion_note = fmt::format("the model's integration does not get past t = {:.4g} s (compared up to there)",
                                      stepper.current_time());
        return false;
      }
      stepper.do_step(rhs);
      const State s = state_at(stepper.current_time());
      if (!m.strands_keep_direction(s, *start))
        crossed = stepper.previous_time();
      else
        events.step(stepper.previous_time(), stepper.current_time(), state_at);
    }
    return true;
  };
  while (row < table.x.size()) {
    const double target = table.x[row];
    if (!advance(target)) return out;
    if (crossed >= 0 && target > crossed) {
      out.motion_note = fmt::format(
          "a strand goes through zero length at t = {:.4g} s (a block through its pulley or anchor): "
          "compared up to there",
          crossed);
      return out;
    }
    if (failed) {
      out.motion_note = "the model's accelerations are not determined along the motion";
      return out;
    }
    Vec y = x;
    if (target > 0) stepper.calc_state(target, y);
    State s;
    s.q = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
    s.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
    s.t = target;
    const auto cm = m.coordinates_at(s);
    for (std::size_t k = 0; k < table.names.size(); ++k) {
      const auto& cell = table.y[k][row];
      if (!cell) continue;
      const double mine = cm.at(table.names[k]);
      const double err = std::abs(mine - *cell);
      out.motion_error = std::max(out.motion_error, err);
      ++out.motion_points;
      if (err > o.motion_tolerance * std::max(1.0, std::abs(*cell)))
        out.disagreements.push_back(
            {fmt::format("motion: {} at t = {:g} s", table.names[k], target), *cell, mine, "from the initial values"});
    }
    ++row;
  }
  // (past the last row, to where tackle's run ends: an event there is the model's too)
  const double horizon =
      table.x.empty() ? 0.0 : std::max(table.x.back(), sim.complete ? 0.0 : sim.reached * (1 + 1e-5) + 1e-7);
  if (!advance(horizon)) return out;
  if (crossed < 0 && !failed) compare_events(sim, events, horizon, out);
  if (!sim.complete && out.motion_note.empty())
    out.motion_note = fmt::format("tackle's run ends at t = {:g} s ({})", sim.reached, sim.stopped);
  return out;
}

}  // namespace crosscheck

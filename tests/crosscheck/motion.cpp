// The motion: the model's accelerations integrated over [0, 1 s] (or to where tackle's run
// ends) from the description's initial values, against `tackle simulate` at 11 times.
#include <chrono>
#include <cmath>

#include <boost/numeric/odeint.hpp>
#include <fmt/format.h>

#include "crosscheck/compare.hpp"
#include "crosscheck/model.hpp"
#include "motion/simulate.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

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
    out.disagreements.push_back({std::string("motion: tackle's simulate refuses it: ") + e.what(), 0, 0, "from the initial values"});
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
  while (row < table.x.size()) {
    const double target = table.x[row];
    while (target > 0 && stepper.current_time() < target && !failed && crossed < 0) {
      // (a point the model cannot get past, where a strand's length reaches 0 and its
      // direction is lost, would take steps without end: the run stops there)
      if (++steps > 200000 || std::chrono::steady_clock::now() - began > std::chrono::seconds(10)) {
        out.motion_note = fmt::format("the model's integration does not get past t = {:.4g} s (compared up to there)",
                                      stepper.current_time());
        return out;
      }
      stepper.do_step(rhs);
      const Vec& y = stepper.current_state();
      State s;
      s.q = Eigen::Map<const Eigen::VectorXd>(y.data(), n);
      s.v = Eigen::Map<const Eigen::VectorXd>(y.data() + n, n);
      s.t = stepper.current_time();
      if (!m.strands_keep_direction(s, *start)) crossed = stepper.previous_time();
    }
    if (crossed >= 0 && target > crossed) {
      out.motion_note = fmt::format(
          "a strand goes through zero length at t = {:.4g} s (a block through its pulley or anchor): "
          "compared up to there", crossed);
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
        out.disagreements.push_back({fmt::format("motion: {} at t = {:g} s", table.names[k], target), *cell, mine,
                                     "from the initial values"});
    }
    ++row;
  }
  if (!sim.complete && out.motion_note.empty()) out.motion_note = fmt::format("tackle's run ends at t = {:g} s ({})", sim.reached, sim.stopped);
  return out;
}

}  // namespace crosscheck

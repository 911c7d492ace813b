// The dependent coordinates and rates of the motion (those the constraints or a massless
// body's balance give from the motion's own), and how an expression gets them put in.
#include "motion/motion_detail.hpp"

#include <algorithm>

#include "expr/print.hpp"
#include "model/kinematics.hpp"

namespace tackle::motion_detail {

using namespace GiNaC;

bool zero(const ex& e) { return normal(e).is_zero(); }

// Everything that varies with the state: the coordinates, the rates and the turning lengths.
bool depends_on_state(const ex& e, const std::vector<ex>& state, const Model& m) {
  for (const auto& s : state)
    if (e.has(s)) return true;
  for (const auto& l : m.lengths)
    if (e.has(l.symbol)) return true;
  return false;
}

namespace {

// A massless body's coordinate that its balance fixes: its value from the solve, in the
// state, and its rate by the chain rule.
void add_balance_coordinates(Dependents& d, const Model& m, const Solution& sol) {
  for (const auto& q : balance_coordinates(m)) {
    const auto v = sol.value_of(q);
    if (!v) continue;  // the solve did not give it: what needs it says so
    const ex value = d.coords.empty() ? *v : substituted(*v, d.coords);
    d.coords[q] = value;
    const auto coordinate =
        std::find_if(m.coordinates.begin(), m.coordinates.end(), [&](const Coordinate& c) { return c.q.is_equal(q); });
    ex rate = time_derivative(value, m);
    if (!d.rates.empty()) rate = substituted(rate, d.rates);
    d.rates[coordinate->rate] = rate;
  }
}

}  // namespace

Dependents dependents(const Model& m, const EquationSystem& s, const Solution& sol, const MotionSpec& spec,
                      const ex& needed) {
  Dependents d;
  d.definitions = m.symbols->definitions();
  const std::vector<ex> by_balance = balance_coordinates(m);
  std::vector<ex> dep_rates, dep_coords;
  for (const auto& c : m.coordinates) {
    if (contains(by_balance, c.q) || contains(spec.coordinates, c.q)) continue;
    dep_rates.push_back(c.rate);
    dep_coords.push_back(c.q);
  }
  if (!dep_rates.empty() && !s.rate_equations.empty()) {
    const Solution r = solve_equations(m.file, s.rate_equations, dep_rates);
    for (const auto& v : r.values) d.rates[v.unknown] = v.value;
  }
  // A dependent coordinate is needed where it appears, also inside a strand's length that
  // turns with it (l_RG = sqrt(L^2 + (H + y_R)^2) in a force on a massless ring).
  bool coords_needed = false;
  for (const auto& c : dep_coords) {
    coords_needed = coords_needed || needed.has(c);
    for (const auto& l : m.lengths) coords_needed = coords_needed || (needed.has(l.symbol) && l.squared.has(c));
  }
  if (!coords_needed) {
    add_balance_coordinates(d, m, sol);
    return d;
  }
  // quantity(q) = quantity(q at t = 0) for each constraint. An initial value 'initial' does
  // not give stands as a symbol of its own: it often cancels (a fixed pulley's height in the
  // length of the string over it), and where it does not, that value is what is missing.
  exmap at_start = spec.initial;
  std::vector<std::pair<ex, ex>> not_given;  // (symbol standing for q(0), q)
  for (const auto& c : m.coordinates)
    if (!spec.initial.count(c.q)) {
      const symbol q0(to_text(c.q) + "(0)");
      at_start[c.q] = q0;
      not_given.emplace_back(q0, c.q);
    }
  std::vector<Equation> eqs;
  for (const auto& c : m.constraints) {
    Equation e;
    e.kind = Equation::Kind::constraint_position;
    e.label = c.label;
    e.lhs = c.quantity;
    e.rhs = substituted(c.quantity, at_start);
    eqs.push_back(e);
  }
  const Solution r = solve_equations(m.file, eqs, dep_coords);
  for (const auto& v : r.values) d.coords[v.unknown] = v.value;
  // The dependent coordinates that are needed, and the starting values they still contain.
  std::vector<std::string> missing;
  for (const auto& c : dep_coords) {
    bool used = needed.has(c);
    for (const auto& l : m.lengths) used = used || (needed.has(l.symbol) && l.squared.has(c));
    if (!used) continue;
    const auto it = d.coords.find(c);
    if (it == d.coords.end()) {  // not solved for: reported where it is used, unless it is missing
      if (!spec.initial.count(c) && std::find(missing.begin(), missing.end(), to_text(c)) == missing.end())
        missing.push_back(to_text(c));
      continue;
    }
    for (const auto& [q0, q] : not_given)
      if (it->second.has(q0) && std::find(missing.begin(), missing.end(), to_text(q)) == missing.end())
        missing.push_back(to_text(q));
  }
  if (!missing.empty()) {
    d.problem = "the motion needs the initial value of " + join(missing, " and ") + " (the constraints fix " +
                (missing.size() == 1 ? "it" : "them") + " only up to a constant; expected " +
                (missing.size() == 1 ? "it" : "them") + " in 'initial')";
    return d;
  }
  // A coordinate that is not needed and whose place depends on a starting value not given
  // is not placed (what uses it later says that it cannot be followed).
  for (auto it = d.coords.begin(); it != d.coords.end();)
    if (std::any_of(not_given.begin(), not_given.end(), [&](const auto& p) { return it->second.has(p.first); }))
      it = d.coords.erase(it);
    else
      ++it;
  add_balance_coordinates(d, m, sol);
  return d;
}

ex put_in(const ex& e, const Dependents& d) {
  ex out = e;
  for (int depth = 0; depth < 8; ++depth) out = substituted(out, d.definitions);
  if (!d.coords.empty()) out = substituted(out, d.coords);
  if (!d.rates.empty()) out = substituted(out, d.rates);
  return out;
}

}  // namespace tackle::motion_detail

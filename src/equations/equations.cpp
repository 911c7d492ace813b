#include "equations/equations.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

ex time_derivative(const ex& e, const Model& m) {
  ex d = 0;
  for (const auto& b : m.bodies) {
    if (b.coord.is_zero()) continue;
    d += e.diff(ex_to<symbol>(b.coord)) * b.rate + e.diff(ex_to<symbol>(b.rate)) * b.accel;
  }
  return d.expand();
}

namespace {

Equation lmb(const Model& m, const std::vector<int>& bodies, bool system) {
  Equation eq;
  eq.kind = Equation::Kind::lmb;
  std::string names;
  for (int b : bodies) names += (names.empty() ? "" : ", ") + m.bodies[b].name;
  eq.label = std::string(system ? "LMB of the system {" + names + "}" : "LMB " + names) + " (" + m.axis + ")";
  ex sum = 0;
  ex rhs = 0;
  for (const auto& l : m.loads) {
    if (std::find(bodies.begin(), bodies.end(), l.body) == bodies.end()) continue;
    eq.terms.push_back(l.force);
    eq.sources.push_back(l.source);
    sum += l.force;
  }
  for (int b : bodies) rhs += m.bodies[b].mass * m.bodies[b].accel;
  eq.lhs = sum;  // forces internal to a system cancel here
  eq.rhs = rhs;
  return eq;
}

}  // namespace

EquationSystem build_equations(const Model& m) {
  EquationSystem s;
  exmap still_coordinates;
  for (const auto& b : m.bodies)
    if (!b.coord.is_zero()) still_coordinates[b.coord] = 0;
  auto add_constraint = [&](const Constraint& c) {
    // Constant parts (fixed points, offsets, wrap around pulleys) drop out of the derivatives;
    // the book leaves them out of the length sum too.
    const ex q = c.quantity.expand();
    const ex varying = (q - q.subs(still_coordinates)).expand();
    ConstraintSteps steps{c.label, c.meaning, varying, time_derivative(varying, m), 0};
    steps.acceleration = time_derivative(steps.rate, m);
    s.constraints.push_back(steps);
    Equation eq;
    eq.kind = Equation::Kind::constraint_acceleration;
    eq.label = c.label + ": acceleration";
    eq.lhs = steps.acceleration;
    eq.rhs = 0;
    eq.terms = {steps.acceleration};
    eq.sources = {"second time derivative of the " + c.meaning};
    s.equations.push_back(eq);
  };
  if (m.derive.empty()) {
    // A complete set: LMB for every body that has a mass (0 for a pulley block), and every
    // constraint.
    for (std::size_t i = 0; i < m.bodies.size(); ++i)
      if (m.bodies[i].has_mass) s.equations.push_back(lmb(m, {static_cast<int>(i)}, false));
    for (const auto& c : m.constraints) add_constraint(c);
  } else {
    for (const auto& sel : m.derive) {
      if (sel.kind == Selection::Kind::lmb) {
        s.equations.push_back(lmb(m, sel.bodies, sel.system));
      } else {
        for (const auto& c : m.constraints)
          if (c.connection == sel.constraint) add_constraint(c);
      }
    }
  }
  for (const auto& u : m.candidates) {
    for (const auto& eq : s.equations)
      if ((eq.lhs - eq.rhs).has(u)) {
        s.unknowns.push_back(u);
        break;
      }
  }
  return s;
}

}  // namespace tackle

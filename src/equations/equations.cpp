#include "equations/equations.hpp"

#include <algorithm>
#include <set>

#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

std::string body_list(const Model& m, const std::vector<int>& bodies, bool system) {
  std::string names;
  for (int b : bodies) names += (names.empty() ? "" : ", ") + m.bodies[b].name;
  return system ? "the system {" + names + "}" : names;
}

bool in(const std::vector<int>& bodies, int b) { return std::find(bodies.begin(), bodies.end(), b) != bodies.end(); }

Vec axis_vec(int i) {
  Vec v = zero_vec();
  v[i] = 1;
  return v;
}

}  // namespace

Equation lmb_along(const Model& m, const std::vector<int>& bodies, bool system, const Vec& direction,
                   const std::string& direction_label) {
  Equation eq;
  eq.kind = Equation::Kind::lmb;
  eq.bodies = bodies;
  eq.system = system;
  eq.label = "LMB " + std::string(system ? "of " : "") + body_list(m, bodies, system) + " (" + direction_label + ")";
  ex sum = 0, rhs = 0;
  for (const auto& l : m.loads) {
    if (!in(bodies, l.body)) continue;
    const ex built = inner(l.force, direction);
    const ex f = built.expand();
    if (f.is_zero()) continue;
    eq.terms.push_back(f);
    eq.built.push_back(built);
    eq.sources.push_back(l.source());
    eq.origins.push_back(l.origin);
    sum += f;
  }
  for (int b : bodies) rhs += inner(kinematics::momentum_rate(m, m.bodies[b]), direction);
  eq.lhs = sum;  // forces internal to a system cancel here
  eq.rhs = rhs.expand();
  return eq;
}

Equation amb_along(const Model& m, const std::vector<int>& bodies, bool system, const Vec& about,
                   const std::string& about_label, const Vec& direction, const std::string& direction_label) {
  Equation eq;
  eq.kind = Equation::Kind::amb;
  eq.bodies = bodies;
  eq.system = system;
  eq.label = "AMB " + std::string(system ? "of " : "") + body_list(m, bodies, system) + " about " + about_label + " (" +
             direction_label + ")";
  ex sum = 0, rhs = 0;
  std::vector<std::string> eliminated;
  for (const auto& l : m.loads) {
    if (!in(bodies, l.body)) continue;
    Vec moment = l.couple;
    if (l.at) moment = moment + cross(*l.at - about, l.force);
    const ex mz = fewer_trig_terms(normal(inner(moment, direction)));
    if (mz.is_zero()) {
      if (!is_zero_vec(l.force)) eliminated.push_back(l.source());
      continue;
    }
    eq.terms.push_back(mz);
    eq.sources.push_back(l.source());
    eq.origins.push_back(l.origin);
    sum += mz;
  }
  // The rate of change of angular momentum about C: r_cm/C x m a (+ I alpha).
  for (int b : bodies) rhs += inner(kinematics::angular_momentum_rate(m, m.bodies[b], about), direction);
  if (!eliminated.empty()) eq.why = "no moment from: " + join(eliminated, "; ");
  eq.lhs = sum;
  eq.rhs = normal(rhs);
  return eq;
}

// A particle: no angle, no moment of inertia (a shape to draw, `draw:`, is drawing only), and no load on it
// away from its center of mass, nor a couple. It does not turn, and no balance of its moments
// is written (it would read 0 = 0, or ask a single contact to balance a moment it cannot). A
// force from another particle, at that particle's center (a block pressing on the block
// under it, both points), gives it no size: two particles touch where they are. A body
// without inertia whose own points take forces (a suitcase on its two feet), or that is
// joined to another at a point of that one away from its center (a block pinned to the
// block in front, a distance behind that one's center), keeps its balance of moments: it
// says how the forces share.
bool particle(const Model& m, int body) {
  const auto bare = [&](const Body& b) {
    // (A body with an angle turns, inertia or not: a bob on a light rod has its angle's balance.)
    return b.angle.is_zero() && b.inertia.is_zero() && b.has_cm;
  };
  const Body& b = m.bodies[static_cast<std::size_t>(body)];
  if (!bare(b)) return false;
  return std::all_of(m.loads.begin(), m.loads.end(), [&](const Load& l) {
    if (l.body != body) return true;
    if (!is_zero_vec(l.couple)) return false;
    if (!l.at || is_zero_vec(*l.at - b.cm)) return true;
    const auto p = std::find_if(m.points.begin(), m.points.end(), [&](const Point& x) { return x.name == l.at_name; });
    if (p == m.points.end() || p->body < 0 || p->body == body) return false;
    const Body& other = m.bodies[static_cast<std::size_t>(p->body)];
    return bare(other) && is_zero_vec(*l.at - other.cm);
  });
}

namespace {

// The steps of building a model's equations and what they share: the model, the system being
// filled, each coordinate mapped to 0 (to tell a constraint's terms that vary), and, once the
// equations are made, their residuals and the symbols in them.
struct EquationBuilder {
  const Model& m;
  EquationSystem s;
  exmap still_coordinates;
  std::vector<ex> residuals;
  std::set<ex, ex_is_less> present;

  explicit EquationBuilder(const Model& model) : m(model) {
    for (const auto& c : m.coordinates) still_coordinates[c.q] = 0;
  }

  // A term varies when it has a coordinate, or a turning strand's length (whose square does).
  bool varies(const ex& t) const {
    if (!(t - substituted(t, still_coordinates)).expand().is_zero()) return true;
    return std::any_of(m.lengths.begin(), m.lengths.end(), [&](const TurningLength& l) {
      return t.has(l.symbol) && !(l.squared - substituted(l.squared, still_coordinates)).expand().is_zero();
    });
  }

  // The terms of a constraint's quantity that vary. Constant parts (fixed points, offsets,
  // wrap around pulleys) drop out of the derivatives; the book leaves them out of the length
  // sum too.
  ex varying_part(const Constraint& c) const {
    const ex q = c.quantity.expand();
    ex varying = 0;
    if (is_a<add>(q)) {
      for (const auto& t : q)
        if (varies(t)) varying += t;
    } else if (varies(q)) {
      varying = q;
    }
    return varying;
  }

  // A constraint's steps, its acceleration and rate equations, and its position equation when
  // it has a constant.
  void add_constraint(const Constraint& c) {
    const ex varying = varying_part(c);
    // Nothing varies: the coordinates themselves keep it (a pendulum's string, its bob written
    // in the string's angle), and its derivatives would read 0 = 0.
    if (varying.is_zero()) return;
    ConstraintSteps steps{c.label, c.meaning, varying, time_derivative(varying, m), 0};
    steps.acceleration = time_derivative(steps.rate, m);
    steps.constant = c.constant;
    s.constraints.push_back(steps);
    Equation eq;
    eq.kind = Equation::Kind::constraint_acceleration;
    eq.label = c.label + ": acceleration";
    eq.lhs = steps.acceleration;
    eq.rhs = 0;
    eq.terms = {steps.acceleration};
    eq.sources = {"second time derivative of the " + c.meaning};
    s.equations.push_back(eq);
    Equation rate{Equation::Kind::constraint_rate,
                  c.label + ": rate",
                  steps.rate,
                  0,
                  {"first time derivative of the " + c.meaning},
                  {steps.rate},
                  "",
                  {},
                  false,
                  {}};
    s.rate_equations.push_back(rate);
    if (!c.constant.is_zero())
      s.position_equations.push_back({Equation::Kind::constraint_position,
                                      c.label + ": position",
                                      varying,
                                      c.constant,
                                      {"the " + c.meaning + " is constant"},
                                      {varying},
                                      "",
                                      {},
                                      false,
                                      {}});
  }

  // One equation per axis.
  void add_lmb(const std::vector<int>& bodies, bool system) {
    for (int i = 0; i < m.dims(); ++i) s.equations.push_back(lmb_along(m, bodies, system, axis_vec(i), m.axes[i]));
  }

  // About the axis given, else one equation per axis; a 2-D moment has only a z component.
  void add_amb(const std::vector<int>& bodies, bool system, const Vec& about, const std::string& about_label,
               const std::optional<Vec>& axis, const std::string& axis_label) {
    if (axis) {
      s.equations.push_back(amb_along(m, bodies, system, about, about_label, *axis, "axis " + axis_label));
    } else if (m.dims() == 2) {
      s.equations.push_back(amb_along(m, bodies, system, about, about_label, axis_vec(2), "z"));
    } else {
      for (int i = 0; i < 3; ++i)
        s.equations.push_back(amb_along(m, bodies, system, about, about_label, axis_vec(i), m.axes[i]));
    }
  }

  // A complete set: LMB for every body that has a mass (0 for a pulley block), AMB about
  // its center of mass in 2-D and 3-D, and every constraint.
  void complete_set() {
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const Body& b = m.bodies[i];
      if (!b.has_mass) continue;
      add_lmb({static_cast<int>(i)}, false);
      // A massless body has no center of mass to speak of: take moments about the origin.
      if (m.dims() > 1 && !particle(m, static_cast<int>(i)))
        add_amb({static_cast<int>(i)}, false, b.has_cm ? b.cm : zero_vec(),
                b.has_cm ? "its center of mass" : "the origin", std::nullopt, "");
    }
    for (const auto& c : m.constraints) add_constraint(c);
  }

  // The balances and constraints `derive` asks for, in its order.
  void selected() {
    for (const auto& sel : m.derive) {
      if (sel.kind == Selection::Kind::lmb) {
        add_lmb(sel.bodies, sel.system);
      } else if (sel.kind == Selection::Kind::amb) {
        add_amb(sel.bodies, sel.system, sel.about_position, sel.about, sel.axis, sel.axis_label);
      } else {
        for (const auto& c : m.constraints)
          if (c.connection == sel.constraint) add_constraint(c);
      }
    }
  }

  // Constant acceleration over an interval: the change of each rate given at both ends.
  void interval_changes() {
    if (m.interval)
      for (const auto& c : m.interval->changes) {
        if (!c.to) continue;  // its end is found after the solve (motion/interval)
        const Coordinate& b = *kinematics::translation(m, m.bodies[c.body]);  // (a body whose rate is given has one)
        Equation eq;
        eq.kind = Equation::Kind::interval;
        eq.label = "interval: " + to_text(b.q);
        if (m.interval->duration) {
          eq.lhs = b.accel * *m.interval->duration;
          eq.rhs = *c.to - c.from;
          eq.sources = {"impulse and momentum: the constant acceleration times the duration is the change of " +
                        to_text(b.rate)};
        } else {
          eq.lhs = 2 * b.accel * *m.interval->distance;
          eq.rhs = pow(*c.to, 2) - pow(c.from, 2);
          eq.sources = {"constant acceleration over the distance: " + to_text(b.rate) + "^2 changes by 2 " +
                        to_text(b.accel) + " times the distance"};
        }
        eq.terms = {eq.lhs};
        s.equations.push_back(eq);
      }
  }

  // The candidates the equations hold, in the candidates' order. The equations' symbols are
  // gathered once: has() of each candidate in each equation is quadratic in a chain.
  void held_candidates() {
    for (const auto& eq : s.equations) {
      residuals.push_back(eq.lhs - eq.rhs);
      for (const ex& x : symbols_in(residuals.back())) present.insert(x);
    }
    for (const auto& u : m.candidates) {
      const bool held = is_a<symbol>(u)
                            ? present.count(u) != 0
                            : std::any_of(residuals.begin(), residuals.end(), [&](const ex& r) { return r.has(u); });
      if (held) s.unknowns.push_back(u);
    }
  }

  // A massless body that no constraint ties: its balance fixes its coordinate (linearly, or
  // the problem is refused: a balance through a turning strand is not solved for it).
  void balance_coordinates_held() {
    for (const auto& q : balance_coordinates(m)) {
      const auto coordinate = std::find_if(m.coordinates.begin(), m.coordinates.end(),
                                           [&](const Coordinate& c) { return c.q.is_equal(q); });
      const Body* body = &m.bodies[coordinate->body];
      for (const auto& r : residuals)
        if (m.symbols->hidden_in_lengths(r, q))
          throw InputError(
              {{body->at, "body '" + body->name + "' has no mass and no constraint ties " + to_text(q) +
                              " to the other coordinates, so its balance fixes it; but a strand that turns with it "
                              "makes that balance nonlinear in " +
                              to_text(q) + " (expected a string or a joint that ties it, or a mass)"}});
      if (present.count(q) != 0) s.unknowns.push_back(q);
    }
  }
};

}  // namespace

EquationSystem build_equations(const Model& m) {
  EquationBuilder b(m);
  if (m.derive.empty())
    b.complete_set();
  else
    b.selected();
  b.interval_changes();
  b.held_candidates();
  b.balance_coordinates_held();
  return std::move(b.s);
}

}  // namespace tackle

namespace tackle {

namespace {

// e with every plain number that is added to something else left out (x + 3 -> x; 3 alone
// stays): such a number is read in SI, in the unit of what it is added to.
ex without_plain_summands(const ex& e) {
  if (is_exactly<numeric>(e) || is_exactly<symbol>(e)) return e;
  if (is_exactly<add>(e)) {
    ex kept = 0;
    bool any = false;
    for (const auto& part : e)
      if (!is_exactly<numeric>(part)) kept += without_plain_summands(part), any = true;
    return any ? kept : e;
  }
  return e.map(without_plain_summands);
}

}  // namespace

std::vector<Diagnostic> check_dimensions(const Model& m, const EquationSystem& s) {
  // Each term of a linear momentum balance is a force. (The other sides and the moment arms
  // may be written as plain numbers, which are read in SI and carry no dimension of their
  // own, so they are not compared: a term is looked at as built, before it is expanded, and
  // a plain number added to a quantity is taken to be in that quantity's unit, as a point
  // at 3 on a spring's path is 3 m.)
  std::vector<Diagnostic> out;
  const SymbolTable& table = *m.symbols;
  for (const auto& eq : s.equations) {
    if (eq.kind != Equation::Kind::lmb) continue;
    for (std::size_t i = 0; i < eq.terms.size(); ++i) {
      std::string problem;
      const auto dim =
          dimension_of(without_plain_summands(i < eq.built.size() ? eq.built[i] : eq.terms[i]), table, problem);
      if (!dim) {
        if (!problem.empty())
          out.push_back(
              {{m.file, 0, 0}, "equation '" + eq.label + "': the term from " + eq.sources[i] + " " + problem});
        continue;
      }
      if (!(*dim == Dimension::force()) && !(*dim == Dimension::none()))
        out.push_back({{m.file, 0, 0},
                       "equation '" + eq.label + "' is not dimensionally consistent: the term from " + eq.sources[i] +
                           " is " + with_article(dim->describe()) + " (expected a force)"});
    }
  }
  return out;
}

}  // namespace tackle

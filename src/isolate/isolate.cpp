#include "isolate/isolate.hpp"

#include <algorithm>

#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "solve/eliminate.hpp"
#include "solve/solve.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

Vec axis_vec(int i) {
  Vec v = zero_vec();
  v[i] = 1;
  return v;
}

}  // namespace

std::vector<ex> model_unknowns(const Model& m) {
  std::vector<ex> out;
  for (const auto& u : m.candidates)
    if (!contains(m.given, u)) out.push_back(u);
  return out;
}

std::vector<Equation> candidate_equations(const Model& m) {
  std::vector<Equation> out;
  std::vector<int> bodies;
  for (std::size_t i = 0; i < m.bodies.size(); ++i)
    if (m.bodies[i].has_mass) bodies.push_back(static_cast<int>(i));
  // Points that are not bodies' own (the places forces act), then the bodies' centers of mass.
  std::vector<const Point*> points;
  for (const auto& p : m.points)
    if (std::none_of(m.bodies.begin(), m.bodies.end(), [&](const Body& b) { return b.name == p.name; }))
      points.push_back(&p);
  for (const auto& p : m.points)
    if (std::any_of(m.bodies.begin(), m.bodies.end(), [&](const Body& b) { return b.name == p.name && b.has_cm; }))
      points.push_back(&p);
  for (int b : bodies) {
    for (int i = 0; i < m.dims(); ++i) out.push_back(lmb_along(m, {b}, false, axis_vec(i), m.axes[i]));
    if (m.dims() == 1) continue;
    for (const Point* p : points)
      for (const Point* q : points) {
        if (p >= q) continue;
        const Vec along = q->position - p->position;
        if (is_zero_vec(along)) continue;
        out.push_back(lmb_along(m, {b}, false, unit(along), "along " + p->name + q->name));
        if (m.dims() == 2)
          out.push_back(lmb_along(m, {b}, false, unit(Vec{-along[1], along[0], 0}), "across " + p->name + q->name));
      }
    // A particle's moments are not balanced (its contacts are idealized points): the
    // derivation writes none, and one written here could contradict its forces.
    if (particle(m, b)) continue;
    for (const Point* c : points) {
      if (m.dims() == 2) {
        out.push_back(amb_along(m, {b}, false, c->position, c->name, axis_vec(2), "z"));
        continue;
      }
      for (int i = 0; i < 3; ++i) {
        // A coordinate axis through C that also passes through a point Q is the line QC.
        std::string label = m.axes[i];
        for (const Point* q : points)
          if (q != c && !is_zero_vec(q->position - c->position) &&
              is_zero_vec(cross(q->position - c->position, axis_vec(i)))) {
            label = "axis " + q->name + c->name + ", along " + m.axes[i];
            break;
          }
        out.push_back(amb_along(m, {b}, false, c->position, c->name, axis_vec(i), label));
      }
      for (const Point* q : points) {
        if (q == c) continue;
        const Vec along = c->position - q->position;
        if (is_zero_vec(along)) continue;
        out.push_back(amb_along(m, {b}, false, c->position, c->name, unit(along), "axis " + q->name + c->name));
      }
    }
  }
  if (m.dims() == 1) {
    const EquationSystem all = build_equations(m);
    for (const auto& eq : all.equations)
      if (eq.kind == Equation::Kind::constraint_acceleration) out.push_back(eq);
  }
  return out;
}

namespace {

// Basis of the null space of `rows` (each of length k): the vectors y with row . y = 0 for
// every row, from the solver's elimination in column order (so the free columns are those a
// person reading the columns in order would choose): one vector per free column, 1 there and
// 0 at the other free columns.
std::vector<std::vector<ex>> null_space(const std::vector<std::vector<ex>>& rows, std::size_t k) {
  SparseSystem sys;
  sys.columns = k;
  for (const auto& row : rows) {
    std::map<std::size_t, ex> entries;
    for (std::size_t c = 0; c < k; ++c)
      if (!normal(row[c]).is_zero()) entries.emplace(c, row[c]);
    sys.a.push_back(std::move(entries));
    sys.b.push_back(0);
  }
  std::vector<ex> free_symbols;
  for (std::size_t c = 0; c < k; ++c) free_symbols.push_back(symbol("y_" + std::to_string(c)));
  const Elimination e = eliminate(sys, free_symbols, Pivoting::in_column_order, false);
  std::vector<std::vector<ex>> basis;
  for (std::size_t f = 0; f < k; ++f) {
    if (e.pivot[f]) continue;
    exmap at;
    for (std::size_t c = 0; c < k; ++c)
      if (!e.pivot[c]) at[free_symbols[c]] = c == f ? 1 : 0;
    std::vector<ex> y(k, 0);
    y[f] = 1;
    for (std::size_t j = 0; j < k; ++j)
      if (e.pivot[j]) y[j] = normal(substituted(e.value[j], at));
    basis.push_back(y);
  }
  return basis;
}

std::string vec_text(const Vec& v, int dims) {
  std::vector<std::string> parts;
  for (int i = 0; i < dims; ++i) parts.push_back(to_text(simplest(v[i])));
  return "[" + join(parts) + "]";
}

// Clears denominators and common factors of a direction (its length does not matter).
Vec tidy(const Vec& given) {
  // cos(theta) and the like stand in as symbols (lcm and gcd take polynomials only).
  exmap repl;
  Vec v;
  for (int i = 0; i < 3; ++i) v[i] = normal(given[i]).to_rational(repl);
  ex l = 1;
  for (const auto& x : v) l = lcm(l, normal(x).denom());
  Vec w = {normal(v[0] * l), normal(v[1] * l), normal(v[2] * l)};
  ex g = 0;
  for (const auto& x : w) g = x.is_zero() ? g : (g.is_zero() ? x : gcd(g, x));
  if (!g.is_zero()) w = {normal(w[0] / g), normal(w[1] / g), normal(w[2] / g)};
  for (auto& x : w) x = normal(substituted(x, repl));
  // gcd() chooses the sign by GiNaC's term order: orient the direction canonically (its
  // first nonzero component's canonical factorization has a positive coefficient).
  for (const auto& x : w) {
    if (x.is_zero()) continue;
    const ex lead = canonical_factors(x.numer())[0];
    if (is_a<numeric>(lead) && ex_to<numeric>(lead).is_negative()) w = {-w[0], -w[1], -w[2]};
    break;
  }
  return w;
}

// The exact test for one body; fills `r` when a combination is found.
bool isolate_in_body(const Model& m, int b, const std::vector<ex>& unknowns, const ex& unknown, Isolation& r) {
  const int dims = m.dims();
  // Balance components, from the equations stage's own balances: LMB along each axis, AMB
  // about the origin along each axis (z only in 2-D) for a body that is not a particle.
  std::vector<ex> components;
  auto axis = [](int i) {
    Vec e = zero_vec();
    e[i] = 1;
    return e;
  };
  for (int i = 0; i < dims; ++i) {
    const Equation eq = lmb_along(m, {b}, false, axis(i), m.axes[i]);
    components.push_back((eq.lhs - eq.rhs).expand());
  }
  // (None for a particle: its moments are not balanced, see candidate_equations.)
  const int first_moment = particle(m, b) ? 3 : dims == 2 ? 2 : 0;
  for (int i = first_moment; i < 3; ++i) {
    const Equation eq = amb_along(m, {b}, false, zero_vec(), "the origin", axis(i), "axis " + std::to_string(i));
    components.push_back((eq.lhs - eq.rhs).expand());
  }
  const std::size_t k = components.size();
  auto column = [&](const ex& u) {
    std::vector<ex> c;
    for (const auto& comp : components) c.push_back(comp.diff(ex_to<symbol>(u)));
    return c;
  };
  const std::vector<ex> target = column(unknown);
  if (std::all_of(target.begin(), target.end(), [](const ex& x) { return normal(x).is_zero(); })) return false;
  std::vector<std::vector<ex>> others;
  for (const auto& u : unknowns)
    if (!u.is_equal(unknown)) others.push_back(column(u));
  for (const auto& y : null_space(others, k)) {
    ex dot = 0;
    for (std::size_t i = 0; i < k; ++i) dot += y[i] * target[i];
    if (normal(dot).is_zero()) continue;
    // y = (lambda, mu): lambda . LMB + mu . AMB_origin.
    Vec lambda = zero_vec(), mu = zero_vec();
    for (int i = 0; i < dims; ++i) lambda[i] = y[i];
    for (int i = first_moment; i < 3; ++i) mu[i] = y[dims + i - first_moment];
    Equation eq;
    if (is_zero_vec(mu)) {
      const Vec dir = tidy(lambda);
      eq = lmb_along(m, {b}, false, dir, "along " + vec_text(dir, dims));
    } else if (normal(inner(lambda, mu)).is_zero()) {
      // lambda . F + mu . M_O = mu . M_C with C x mu = lambda: C = (mu x lambda)/|mu|^2.
      const Vec c = (1 / inner(mu, mu)) * cross(mu, lambda);
      const Vec point = {simplest(c[0]), simplest(c[1]), simplest(c[2])};
      const Vec axis = tidy(mu);
      std::string point_label = "the point " + vec_text(point, dims);
      for (const auto& p : m.points)
        if (is_zero_vec(p.position - point)) {
          point_label = p.name;
          break;
        }
      eq = amb_along(m, {b}, false, point, point_label, axis, dims == 2 ? "z" : "along " + vec_text(axis, 3));
    } else {
      continue;  // a screw combination, not one LMB or AMB: try another null-space vector
    }
    const ex residual = normal(eq.lhs - eq.rhs);
    const ex expanded = residual.numer().expand();
    if (expanded.degree(unknown) != 1) continue;
    r.equation = eq;
    r.value = simplest(-expanded.coeff(unknown, 0) / expanded.coeff(unknown, 1));
    return true;
  }
  return false;
}

}  // namespace

Isolation isolate(const Model& m, const std::vector<Equation>& candidates, const ex& unknown) {
  Isolation r;
  r.unknown = unknown;
  const std::vector<ex> unknowns = model_unknowns(m);
  for (const auto& eq : candidates) {
    ++r.tried;
    const ex residual = normal(eq.lhs - eq.rhs);
    if (!residual.has(unknown)) continue;
    const bool alone = std::none_of(unknowns.begin(), unknowns.end(),
                                    [&](const ex& u) { return !u.is_equal(unknown) && residual.has(u); });
    if (!alone) continue;
    const ex expanded = residual.numer().expand();
    if (expanded.degree(unknown) != 1) continue;  // not linear in it: keep looking
    const ex a = expanded.coeff(unknown, 1), b = expanded.coeff(unknown, 0);
    r.equation = eq;
    r.value = simplest(-b / a);
    return r;
  }
  if (m.dims() == 1) return r;
  for (std::size_t b = 0; b < m.bodies.size(); ++b)
    if (m.bodies[b].has_mass && isolate_in_body(m, static_cast<int>(b), unknowns, unknown, r)) return r;
  r.impossible = true;
  return r;
}

}  // namespace tackle

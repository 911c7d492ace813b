// The model's two entry points: time_derivative, and build_model, which runs the stages of
// src/model/builder/ (stages.hpp) in order on one BuildContext.
#include "model/model.hpp"

#include <algorithm>

#include "expr/rational.hpp"

#include "model/builder/context.hpp"
#include "model/builder/stages.hpp"

namespace tackle {

using namespace GiNaC;

std::unordered_set<ex, ExHash, ex_is_equal> symbols_asked(const std::vector<Wanted>& wanted) {
  std::unordered_set<ex, ExHash, ex_is_equal> out;
  for (const auto& w : wanted)
    for (const ex& x : distinct_symbols(w.expr)) out.insert(x);
  return out;
}

std::vector<ex> balance_coordinates(const Model& m, const SymbolTable& table) {
  std::vector<ex> out;
  for (const auto& q : m.coordinates) {  // (in body order)
    const Body& b = m.bodies[q.body];
    if (q.kind != Coordinate::Kind::translation || !b.has_mass || !b.mass.is_zero() || contains(m.given, q.q)) continue;
    const bool tied = std::any_of(m.constraints.begin(), m.constraints.end(), [&](const Constraint& c) {
      return c.quantity.has(q.q) || table.hidden_in_lengths(c.quantity, q.q);
    });
    if (!tied) out.push_back(q.q);
  }
  return out;
}

ex time_derivative(const ex& e, const Model& m) { return time_derivative(e, m.coordinates, m.lengths, m.time); }

ex time_derivative(const ex& e, const std::vector<Coordinate>& coordinates, const std::vector<TurningLength>& lengths,
                   const ex& time) {
  ex d = is_a<symbol>(time) ? e.diff(ex_to<symbol>(time)) : ex(0);
  // Only the coordinates and rates `e` holds (a string of two bodies among 256: two, not 512
  // derivatives).
  const auto present = symbols_in(e);
  // A few symbols are told apart by their hashes first (a set lookup for each of a chain's
  // 512 coordinates and rates, in each of its 1500 derivatives, was a twentieth of its run).
  std::vector<unsigned> hashes;
  if (present.size() <= 8)
    for (const ex& x : present) hashes.push_back(x.gethash());
  auto in_e = [&](const ex& x) {
    if (present.size() <= 8 && std::find(hashes.begin(), hashes.end(), x.gethash()) == hashes.end()) return false;
    return present.count(x) != 0;
  };
  for (const auto& c : coordinates) {
    if (in_e(c.q)) d += e.diff(ex_to<symbol>(c.q)) * c.rate;
    if (in_e(c.rate)) d += e.diff(ex_to<symbol>(c.rate)) * c.accel;
  }
  // d l/dt = d(l^2)/dt / (2 l), with l^2 a polynomial in the coordinates.
  for (const auto& l : lengths)
    if (in_e(l.symbol))
      d += e.diff(ex_to<symbol>(l.symbol)) * time_derivative(l.squared, coordinates, {}, time) / (2 * l.symbol);
  return d.expand();
}

ex reduced_on_lengths(const ex& e, const Model& m) {
  if (m.lengths.empty()) return e;
  ex n = numer_denom_remembered(e).op(0).expand();
  // rem() takes polynomials over the rationals: the parts that are not (sin(theta) of a
  // turning body, roots) stand as symbols of their own meanwhile, the same in both.
  exmap stand_ins;
  for (const auto& l : m.lengths) {
    const ex divisor = (pow(l.symbol, 2) - l.squared).to_polynomial(stand_ins);
    n = rem(n.to_polynomial(stand_ins), divisor, ex_to<symbol>(l.symbol)).expand();
  }
  return stand_ins.empty() ? n : n.subs(stand_ins).expand();
}

Model build_model(const Description& d, const RuleSet& rules) {
  build::BuildContext ctx(d, rules);
  Model& m = ctx.m;
  m.file = d.file;
  m.title = d.title.text;
  build::axes(ctx);
  build::parameters(ctx);
  build::steady(ctx);
  build::bodies(ctx);
  build::points(ctx);
  build::read_layout(ctx);
  build::connections(ctx);
  build::gravity(ctx);
  build::given_and_find(ctx);
  build::constraint_constants(ctx);
  build::derive(ctx);
  build::motion(ctx);
  build::interval(ctx);
  build::impact(ctx);
  build::statement(ctx);
  m.sweep = d.sweep;
  ctx.diags.throw_if_any();
  m.symbols = ctx.table;
  return m;
}

}  // namespace tackle

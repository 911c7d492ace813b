#include "motion/phases.hpp"

#include "expr/print.hpp"
#include "model/kinematics.hpp"
#include "numeric/evaluate.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// Whether `e` is known to be > 0 (>= 0 when `or_zero`), from its symbols' domains or else
// from the given numbers; nothing when neither tells.
std::optional<bool> positive(const ex& e, bool or_zero, const SymbolTable& table) {
  if (auto s = sign_of(e)) return *s > 0 || (or_zero && *s == 0);
  if (auto v = NormalForm(e).approx_at(table.values())) return *v > 0 || (or_zero && *v == 0);
  return std::nullopt;
}

// Something other than the parameters (a coordinate, a rate, time) in `e`, or nothing.
std::optional<ex> not_a_parameter(const ex& e, const SymbolTable& table) {
  for (const auto& s : table.all())
    if (s->role != SymbolRole::parameter && e.has(s->sym)) return s->sym;
  return std::nullopt;
}

}  // namespace

IntervalEnd interval_end(const Model& m, const Solution& sol) {
  IntervalEnd out;
  if (!m.interval) return out;
  const IntervalSpec& iv = *m.interval;
  const SymbolTable& table = *m.symbols;
  for (const auto& c : iv.changes) {
    const Body& b = m.bodies[c.body];
    const Coordinate& q = *kinematics::translation(m, b);  // (a body whose rate is given has one)
    IntervalEnd::Rate r;
    r.body = c.body;
    r.rate = q.rate;
    r.from = c.from;
    if (c.to) {
      r.value = *c.to;
      r.given = true;
      out.rates.push_back(r);
      continue;
    }
    const auto a = sol.value_of(q.accel);
    if (!a) {
      out.problem =
          "the end of " + to_text(q.rate) + " needs " + to_text(q.accel) + ", which the equations do not determine";
      return out;
    }
    if (auto other = not_a_parameter(*a, table)) {
      out.problem = "the end of " + to_text(q.rate) + " needs a constant " + to_text(q.accel) + ", and it is " +
                    to_text(*a) + " (it depends on " + to_text(*other) + ")";
      return out;
    }
    r.accel = *a;
    if (iv.duration) {
      const ex T = *iv.duration;
      r.value = simplest(c.from + *a * T);
      r.displacement = simplest(c.from * T + *a * T * T / 2);
    } else {
      const ex s = *iv.distance;
      const auto s_positive = positive(s, false, table), s_negative = positive(-s, false, table);
      if (!s_positive.value_or(false) && !s_negative.value_or(false)) {
        out.problem = "the end of " + to_text(q.rate) + " takes the sign of the distance " + to_text(s) +
                      ", which is not known (expected a distance of known sign)";
        return out;
      }
      const ex squared = simplest(pow(c.from, 2) + 2 * *a * s);
      r.value = (*s_positive ? 1 : -1) * sqrt(squared);
      r.reaches = {{squared, ">="}};
      const ex towards_start = normal(c.from * s), towards_accel = normal(*a * s);
      const auto moving = positive(towards_start, false, table), pushed = positive(towards_accel, false, table);
      const auto reached = positive(squared, true, table);
      if (moving.value_or(false))
        r.reaches.push_back({towards_start, ">"});
      else if (pushed.value_or(false))
        r.reaches.push_back({towards_accel, ">"});
      else
        r.reaches.push_back({towards_start, ">"});
      if (reached && (moving || pushed))
        r.reaches_holds = *reached && (moving.value_or(false) || pushed.value_or(false));
      if (r.reaches_holds && !*r.reaches_holds) {
        out.problem = "body '" + b.name + "' never moves by " + to_text(s) + " (it starts with " + to_text(q.rate) +
                      " = " + to_text(c.from) + " and has " + to_text(q.accel) + " = " + to_text(*a) +
                      "; expected it to reach the end of the interval)";
        return out;
      }
    }
    out.rates.push_back(r);
  }
  return out;
}

ImpactResult analyze_impact(const Model& m) {
  ImpactResult out;
  if (!m.impact) return out;
  const ImpactSpec& im = *m.impact;
  Equation momentum;
  momentum.kind = Equation::Kind::impact;
  momentum.label = "momentum over the impact";
  momentum.lhs = 0;
  momentum.rhs = 0;
  std::vector<ex> unknowns;
  for (const auto& bf : im.before) {
    const Body& b = m.bodies[bf.body];
    const ex& rate = kinematics::translation(m, b)->rate;  // (each body of an impact has one)
    momentum.lhs += b.mass * rate;
    momentum.rhs += b.mass * bf.rate;
    momentum.sources.push_back(b.name + " after");
    momentum.terms.push_back(b.mass * rate);
    out.energy_before += b.mass * pow(bf.rate, 2) / 2;
    unknowns.push_back(rate);
  }
  out.equations.push_back(momentum);
  const Body& first = m.bodies[im.before.front().body];
  const ex& first_rate = kinematics::translation(m, first)->rate;
  for (std::size_t i = 1; i < im.before.size(); ++i) {
    const Body& b = m.bodies[im.before[i].body];
    const ex& rate = kinematics::translation(m, b)->rate;
    Equation e;
    e.kind = Equation::Kind::impact;
    if (im.restitution) {
      e.label = "restitution";
      e.lhs = rate - first_rate;
      e.rhs = -*im.restitution * (im.before[i].rate - im.before.front().rate);
      e.sources = {"the rate of separation after is -e times the rate of separation before"};
    } else {
      e.label = "plastic: " + b.name + " moves with " + first.name;
      e.lhs = rate;
      e.rhs = first_rate;
      e.sources = {"the bodies stick together"};
    }
    e.terms = {e.lhs};
    out.equations.push_back(e);
  }
  const Solution sol = solve_equations(m.file, out.equations, unknowns);
  for (const auto& bf : im.before) {
    const Body& b = m.bodies[bf.body];
    const ex& rate = kinematics::translation(m, b)->rate;  // (each body of an impact has one)
    const auto v = sol.value_of(rate);
    if (!v) throw InternalError("the impact's rate " + to_text(rate) + " after it is not determined");
    ImpactResult::After a;
    a.body = bf.body;
    a.rate = rate;
    a.before = bf.rate;
    a.after = simplest(*v);
    a.impulse_symbol = bf.impulse;
    a.impulse = simplest(b.mass * (*v - bf.rate));
    out.energy_after += b.mass * pow(*v, 2) / 2;
    out.after.push_back(a);
  }
  out.energy_lost = simplest(out.energy_before - out.energy_after);
  out.energy_before = simplest(out.energy_before);
  out.energy_after = simplest(out.energy_after);
  out.energy_lost_symbol = im.energy_lost;
  return out;
}

exmap end_state(const Model& m, const Solution& sol, const std::optional<IntervalEnd>& end,
                const std::optional<ImpactResult>& impact) {
  exmap state;
  for (const auto& d : sol.values) state[d.unknown] = d.value;
  for (const auto& w : m.wanted)
    if (w.defined) {
      const SymbolInfo* s = m.symbols->find(w.name);
      if (s) state[s->sym] = normal(substituted(w.expr, state));
    }
  if (end)
    for (const auto& r : end->rates) state[r.rate] = r.value;
  if (impact) {
    for (const auto& a : impact->after) {
      state[a.rate] = a.after;
      state[a.impulse_symbol] = a.impulse;
    }
    state[impact->energy_lost_symbol] = impact->energy_lost;
  }
  return state;
}

}  // namespace tackle

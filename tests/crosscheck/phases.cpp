// Impacts, intervals and phases, where the model can follow them (issue 41, item 3). The
// model's own physics: an impact conserves the colliding bodies' momentum; a plastic one
// leaves them one velocity, one with a coefficient of restitution e (two bodies) parts them at
// e times their speed of approach; the impulse on each is its change of momentum and the
// energy lost the change of kinetic energy. An interval of constant forces: the model's
// acceleration at its start (its own balances, the start's rates given) carries each rate to
// its end (v0 + a T over a duration, v^2 = v0^2 + 2 a s over a distance, the body moving
// towards s). Phases: each followed in turn, what one carries into the next computed by the
// model from its own end state. What the model cannot follow (a force no constraint
// determines, an impact in more than one axis) is noted, and the phases after it are not
// compared.
#include <cmath>

#include <fmt/format.h>

#include "crosscheck/compare.hpp"
#include "crosscheck/model.hpp"
#include "expr/print.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

namespace {

using Values = std::map<std::string, double>;

// A tackle expression at the model's numbers: its defined names written out, every symbol by
// name; nothing when a symbol has no number.
std::optional<double> tackle_at(const GiNaC::ex& e, const tackle::SymbolTable& table, const Values& numbers) {
  GiNaC::ex x = e;
  const GiNaC::exmap defs = table.definitions(true);
  for (int i = 0; i < 12; ++i) x = x.subs(defs);
  GiNaC::exmap at;
  for (const auto& s : table.all())
    if (auto it = numbers.find(s->name); it != numbers.end()) at[s->sym] = GiNaC::numeric(it->second);
  const GiNaC::ex v = x.subs(at).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

void expect(Outcome& out, const std::string& what, std::optional<double> tackle, double model,
            const std::string& phase) {
  ++out.compared;
  if (!tackle || std::abs(*tackle - model) > 1e-9 * std::max({std::abs(*tackle), std::abs(model), 1.0}))
    out.disagreements.push_back({what + (tackle ? "" : " (tackle gives no number)"), tackle.value_or(0), model, phase});
}

// The body whose coordinate's rate is `rate` (dot(y)), and its mass.
struct Moving {
  std::string rate;
  double mass = 0, before = 0, after = 0;
};

std::optional<Moving> moving(const tackle::Description& d, const std::string& rate, const Values& numbers) {
  for (const auto& b : d.bodies)
    if (b.position && "dot(" + b.position->text + ")" == rate && b.mass)
      if (const auto m = evaluate_text(b.mass->text, numbers)) return Moving{rate, *m, 0, 0};
  return std::nullopt;
}

// The impact as the model has it; the rates after, by name, or a note why not.
std::optional<Values> follow_impact(const tackle::Description& d, const tackle::Analysis& a, const Values& numbers,
                                    const std::string& phase, Outcome& out) {
  if (d.axes.size() > 1) {
    out.not_compared.insert(phase + ": an impact in more than one axis");
    return std::nullopt;
  }
  std::vector<Moving> bodies;
  for (const auto& [rate, value] : d.impact->from) {
    auto b = moving(d, rate.text, numbers);
    const auto v = evaluate_text(value.text, numbers);
    if (!b || !v) return std::nullopt;
    b->before = *v;
    bodies.push_back(*b);
  }
  double mass = 0, momentum = 0;
  for (const auto& b : bodies) mass += b.mass, momentum += b.mass * b.before;
  const auto e =
      d.impact->restitution ? evaluate_text(d.impact->restitution->text, numbers) : std::optional<double>(0.0);
  if (!e || (d.impact->restitution && bodies.size() != 2)) return std::nullopt;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    // common velocity, less e times the approach shared out by the other's mass
    const double approach = bodies.size() == 2 ? bodies[i].before - bodies[1 - i].before : 0;
    const double other = bodies.size() == 2 ? bodies[1 - i].mass : 0;
    bodies[i].after = momentum / mass - *e * other * approach / mass;
  }
  const auto& table = *a.model.symbols;
  Values after = numbers;
  double lost = 0;
  for (const auto& r : a.impact->after) {
    const std::string rate = tackle::to_text(r.rate);
    for (const auto& b : bodies) {
      if (b.rate != rate) continue;
      expect(out, phase + ": " + rate + " after the impact", tackle_at(r.after, table, numbers), b.after, phase);
      expect(out, phase + ": the impulse " + tackle::to_text(r.impulse_symbol), tackle_at(r.impulse, table, numbers),
             b.mass * (b.after - b.before), phase);
      after[rate] = b.after;
    }
  }
  for (const auto& b : bodies) lost += b.mass * (b.before * b.before - b.after * b.after) / 2;
  expect(out, phase + ": the kinetic energy lost", tackle_at(a.impact->energy_lost, table, numbers), lost, phase);
  return after;
}

// The interval as the model has it (its forces known): the rates at its end, by name.
std::optional<Values> follow_interval(const tackle::Description& d, const tackle::Analysis& a, const Values& numbers,
                                      const std::string& phase, Outcome& out) {
  tackle::Description start = d;
  start.interval.reset();
  for (const auto& [rate, value] : d.interval->from) start.given.push_back({rate, value, std::nullopt});
  std::mt19937_64 rng(1);
  const Model m(start, rng);  // (throws Unsupported: a force no constraint determines)
  const Instant inst = m.solve(m.base_state());
  const auto T = d.interval->duration ? evaluate_text(d.interval->duration->text, m.parameters()) : std::nullopt;
  const auto s = d.interval->distance ? evaluate_text(d.interval->distance->text, m.parameters()) : std::nullopt;
  Values after = numbers;
  const auto& table = *a.model.symbols;
  for (const auto& r : a.interval_end->rates) {
    const std::string rate = tackle::to_text(r.rate);
    const Quantity* acc = inst.find("d" + rate);  // ddot(y) for dot(y)
    const auto v0 = evaluate_text(tackle::to_text(r.from), m.parameters());
    if (!acc || !acc->determined || !v0 || (!T && !s)) return std::nullopt;
    const double v =
        T ? *v0 + acc->value * *T : std::copysign(std::sqrt(std::max(0.0, *v0 * *v0 + 2 * acc->value * *s)), *s);
    expect(out, phase + ": " + rate + " at the end of the interval", tackle_at(r.value, table, numbers), v, phase);
    after[rate] = v;
  }
  return after;
}

}  // namespace

Outcome compare_phases(const tackle::Description& d, const tackle::Analysis& a) {
  Outcome out;
  std::vector<std::pair<const tackle::Description*, const tackle::Analysis*>> steps;
  if (d.phases.empty()) steps.emplace_back(&d, &a);
  for (std::size_t i = 0; i < d.phases.size() && i < a.phases.size(); ++i)
    steps.emplace_back(&d.phases[i].d, a.phases[i].analysis.get());
  Values carried;  // what the previous phase carries, the model's own numbers
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string phase = d.phases.empty() ? "the description" : "phase " + d.phases[i].name.text;
    tackle::Description pd = *steps[i].first;
    for (const auto& [name, v] : carried)
      pd.parameters.push_back({{name, {}}, tackle::Text{fmt::format("{:.17g}", v), {}}, {}, {}, {}, false, {}, {}, {}});
    std::optional<Values> end;
    try {
      tackle::Description bare = pd;
      bare.impact.reset();
      bare.interval.reset();
      std::mt19937_64 rng(1);
      Values numbers = Model(bare, rng).parameters();
      if (pd.impact && steps[i].second->impact)
        end = follow_impact(pd, *steps[i].second, numbers, phase, out);
      else if (pd.interval && steps[i].second->interval_end)
        end = follow_interval(pd, *steps[i].second, numbers, phase, out);
    } catch (const Unsupported& e) {
      out.not_compared.insert(phase + ": " + e.what());
    }
    if (!end) {
      out.not_compared.insert(phase + (d.phases.empty() ? "" : " and the phases after it") +
                              " (the model does not follow it)");
      break;
    }
    carried.clear();
    if (i < d.phases.size())
      for (const auto& [name, expr] : d.phases[i].carry)
        if (const auto v = evaluate_text(expr.text, *end)) carried[name.text] = *v;
  }
  out.kind = !out.disagreements.empty() ? Outcome::Kind::disagree
             : out.compared             ? Outcome::Kind::agree
                                        : Outcome::Kind::skipped;
  if (out.kind == Outcome::Kind::skipped) out.reason = "phases, an impact or an interval the model does not follow";
  return out;
}

}  // namespace crosscheck

// The ends of phases as the derivation tells them: the rates at the end of an interval, and an
// impact (momentum, sticking or restitution, the rates after, the impulses, the energy lost).
// Narration only: everything is computed in src/motion/phases.cpp.
#include "report/derivation.hpp"

#include <cmath>

#include "expr/print.hpp"
#include "model/kinematics.hpp"
#include "report/narrator.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// An answer for a quantity of a phase's end (a rate, an impulse, the energy lost), boxed.
void answer(Derivation& d, Narrator& n, const SymbolTable& table, const ex& symbol, const ex& value,
            const Dimension& dim, const ReportOptions& options, const std::string& label,
            const std::optional<Unit>& unit = std::nullopt) {
  Answer a;
  const SymbolInfo* info = table.find(symbol);
  a.name = info ? info->name : to_text(symbol);
  a.tex = info ? info->tex : a.name;
  a.symbol = symbol;
  a.closed_form = fold_definitions(value, table);
  a.unit = unit;
  a.value = evaluate(value, table, dim, options.digits, unit);
  Step* st = n.equation(label, symbol, *a.closed_form);
  st->boxed = true;
  st->note = with_unit(a.value);
  d.answers.push_back(std::move(a));
}

}  // namespace

void narrate_interval_end(Derivation& d, const Model& m, const IntervalEnd& end, const ReportOptions& options) {
  const SymbolTable& table = *m.symbols;
  Narrator n{d, table};
  bool open = false;
  for (const auto& r : end.rates) open = open || !r.given;
  if (!open) return;
  n.section("End of the interval");
  for (const auto& r : end.rates) {
    if (r.given) continue;
    const Coordinate& b = *kinematics::translation(m, m.bodies[r.body]);  // (a body whose rate is given has one)
    if (m.interval->duration) {
      n.text_with(
          "With {} constant, the rate at the end is the rate at the start plus the acceleration times the duration:",
          {b.accel});
      n.equation("end of the interval: {}", r.rate, r.from + r.accel * *m.interval->duration)->math = {b.rate};
      answer(d, n, table, r.rate, r.value, Dimension::velocity(), options, "at the end of the interval");
      if (r.displacement) {
        n.text("Over the duration the body moves by");
        Step* st = n.equation("displacement over the interval",
                              symbol("Delta " + to_text(b.q), "\\Delta " + table.find(b.q)->tex), *r.displacement);
        st->note = with_unit(evaluate(*r.displacement, table, Dimension::length(), options.digits));
      }
    } else {
      n.text_with("With {} constant, the square of the rate changes by twice the acceleration times the distance:",
                  {b.accel});
      n.equation("end of the interval: {}", pow(r.rate, 2), pow(r.from, 2) + 2 * r.accel * *m.interval->distance)
          ->math = {pow(b.rate, 2)};
      n.text(
          "The body gets to the end of the interval when {} and {}; the rate there takes the sign of the distance "
          "(the first time the body has moved by it).");
      d.steps.back().math = {r.reaches[0].first >= 0, r.reaches[1].first > 0};
      if (r.reaches_holds && *r.reaches_holds) d.steps.back().text += " Both hold with the given numbers.";
      answer(d, n, table, r.rate, r.value, Dimension::velocity(), options, "at the end of the interval");
    }
  }
}

void narrate_impact(Derivation& d, const Model& m, const ImpactResult& r, const ReportOptions& options) {
  const SymbolTable& table = *m.symbols;
  Narrator n{d, table};
  d.status = "determined";
  n.section("The impact: momentum is conserved");
  n.text(
      "While the impact lasts, the force between the bodies is far larger than gravity or any other finite force, "
      "which give no impulse: the total momentum is the same just before and just after it. The rates below are "
      "those just after; the rates just before are given.");
  std::string rates_before;
  std::vector<ex> math;
  for (const auto& b : m.impact->before) {
    rates_before += std::string(rates_before.empty() ? "" : ", ") + "{} = {}";
    math.push_back(kinematics::translation(m, m.bodies[b.body])->rate);
    math.push_back(b.rate);
  }
  n.text_with("Just before: " + rates_before + ".", math);
  for (const auto& eq : r.equations) n.equation(eq.label, eq.lhs, eq.rhs);
  d.n_equations = r.equations.size();
  d.rank = r.equations.size();
  for (const auto& a : r.after) d.unknowns.push_back(a.rate);
  n.section("Results");
  for (const auto& a : r.after) answer(d, n, table, a.rate, a.after, Dimension::velocity(), options, "just after");
  n.text("The impulse on each body is its change of momentum:");
  for (const auto& a : r.after)
    answer(d, n, table, a.impulse_symbol, a.impulse, Dimension::force() * Dimension::time(), options,
           "impulse on " + m.bodies[a.body].name);
  n.text("The kinetic energy before and after the impact, and what the impact takes:");
  Step* before = n.equation("kinetic energy just before", symbol("E_before", "E_{\\mathrm{before}}"), r.energy_before);
  before->note =
      with_unit(evaluate(r.energy_before, table, Dimension::force() * Dimension::length(), options.digits, joule()));
  Step* after = n.equation("kinetic energy just after", symbol("E_after", "E_{\\mathrm{after}}"), r.energy_after);
  after->note =
      with_unit(evaluate(r.energy_after, table, Dimension::force() * Dimension::length(), options.digits, joule()));
  answer(d, n, table, r.energy_lost_symbol, r.energy_lost, Dimension::force() * Dimension::length(), options,
         "energy lost", joule());
  n.section("Check: energy");
  const auto sign = sign_of(r.energy_lost);
  const auto number = evaluate(r.energy_lost, table, Dimension::force() * Dimension::length(), options.digits);
  if (sign && *sign >= 0)
    n.text("The energy lost is never negative for positive parameters: the impact does not make energy.");
  else if (number && number->approx >= -1e-12 * (1 + std::abs(number->approx)))
    n.text("With the given numbers the energy lost is not negative: the impact does not make energy.");
  else if (number)
    n.text(
        "With the given numbers the energy lost is NEGATIVE: the impact would make energy (a restitution above 1?).");
  else
    n.text("Whether the energy lost is positive depends on the parameters (it is for a restitution of at most 1).");
  n.section("Check: power balance");
  n.text("The power balance is not checked: " + d.power.reason + ".");
}

void narrate_regimes(Derivation& d, const std::vector<RegimeChoice>& choices, const SymbolTable& table) {
  d.regimes = choices;
  Narrator n{d, table};
  for (const auto& c : choices) {
    n.section("Sticking or slipping: " + c.connection);
    const bool slips = c.chosen != c.first;
    // Sticking holds while these do; slipping: the ones that fail say why.
    auto shown = [&](const RegimeChoice::Bound& b, bool coefficient) {
      return b.coefficient == coefficient && (slips ? b.failed : b.tightest);
    };
    auto bounds = [&](bool coefficient, const std::string& lead) {
      bool any = false;
      for (const auto& b : c.holds_while) {
        if (!shown(b, coefficient)) continue;
        if (!any) n.text(lead);
        any = true;
        const std::string name = to_text(b.parameter);
        const bool lower = b.op[0] == '>';
        const std::string what = coefficient
                                     ? (lower ? "the least " : "the largest ") + name +
                                           (slips ? " that would hold them together" : " that holds them together")
                                     : (lower ? "the least " : "the largest ") + name + " for which they move together";
        Step* st = n.equation(what, b.parameter, b.bound);
        st->relation = b.op;
        st->note = b.value;
      }
    };
    bounds(false, slips ? "Solved sticking (" + c.first + "), the bodies would move together only while:"
                        : "Solved sticking (" + c.first + "), the bodies move together while:");
    if (c.friction) {
      const auto& f = *c.friction;
      n.text(slips ? "The friction on " + f.body + " that moving together needs, and the most the contact can give:"
                   : "The friction on " + f.body + " while they do, and the most the contact can give:");
      n.equation("the friction on " + f.body, f.unknown, f.value)->note = f.value_number;
      if (!f.limit.is_zero())
        n.equation("the most friction at the contact", f.limit, f.limit_value)->note = f.limit_number;
    }
    bounds(true, slips ? "The friction coefficient that would hold them together:"
                       : "The friction coefficient that holds them together:");
    if (c.undecided) {
      n.text(
          "At the given numbers these have no number (they depend on the time or on a coordinate): the contact is "
          "derived "
          "sticking, and the model holds while they do (a simulation stops where they fail).");
    } else if (!slips) {
      n.text("At the given numbers they do: the bodies move together, as derived here.");
    } else {
      n.text("At the given numbers they do not (" + join(c.failed, "; ") +
             " fails): the bodies slip on each other, and the contact is " + "derived here sliding (" + c.chosen +
             "), with kinetic friction against the slip.");
    }
  }
}

}  // namespace tackle

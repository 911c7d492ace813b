#include "crosscheck/compare.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "crosscheck/claims.hpp"
#include "crosscheck/model.hpp"
#include "description/description.hpp"
#include "pipeline/pipeline.hpp"  // tackle's side: its closed forms (and, for motion, simulate)

namespace crosscheck {

namespace {

/// tackle's closed forms with every defined name (defined parameters, turning strands'
/// lengths) written out, ready for numbers.
struct ClosedForms {
  std::vector<std::pair<std::string, GiNaC::ex>> values;
  std::vector<std::pair<std::string, GiNaC::ex>> symbols;  // every symbol of the table, by name
};

// `e` with every defined name written out (to 12 levels).
GiNaC::ex written_out(GiNaC::ex e, const GiNaC::exmap& defs) {
  for (int i = 0; i < 12; ++i) {
    const GiNaC::ex next = e.subs(defs);
    if (next.is_equal(e)) break;
    e = next;
  }
  return e;
}

ClosedForms closed_forms(const tackle::Analysis& a) {
  ClosedForms out;
  const auto& table = *a.model.symbols;
  const GiNaC::exmap defs = table.definitions(true);
  std::vector<tackle::Determined> all = a.solution.values;
  if (a.solution.rates)  // velocity questions: the constraints' rates solved for the rates
    all.insert(all.end(), a.solution.rates->values.begin(), a.solution.rates->values.end());
  for (const auto& d : all) {
    const tackle::SymbolInfo* s = table.find(d.unknown);
    if (!s) continue;
    out.values.emplace_back(s->name, written_out(d.value, defs));
  }
  for (const auto& s : table.all()) out.symbols.emplace_back(s->name, s->sym);
  return out;
}

std::optional<double> evaluate(const GiNaC::ex& e, const GiNaC::exmap& at) {
  const GiNaC::ex x = e.subs(at).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(x)) return std::nullopt;
  const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(x);
  if (!n.is_real()) {
    const double im = GiNaC::imag(n).to_double(), re = GiNaC::real(n).to_double();
    if (std::abs(im) > 1e-12 * (1 + std::abs(re))) return std::nullopt;
    return re;
  }
  return n.to_double();
}

std::string describe_state(const std::map<std::string, double>& vals, const tackle::Description& d) {
  std::set<std::string> params;
  for (const auto& p : d.parameters) params.insert(p.name.text);
  std::string out;
  for (const auto& [k, v] : vals) {
    if (params.count(k)) continue;
    if (!out.empty()) out += ", ";
    out += fmt::format("{} = {:.17g}", k, v);
  }
  return out;
}

}  // namespace

Outcome compare_motion(const tackle::Analysis& a, const Model& m, const tackle::Description& d, const Options& o);
Outcome compare_phases(const tackle::Description& d, const tackle::Analysis& a);  // phases.cpp

Outcome compare(const std::string& text, const std::string& file, const tackle::RuleSet& rules, const Options& o) {
  Outcome out;
  tackle::Description d;
  try {
    d = tackle::parse_description(text, file);
  } catch (const std::exception& e) {
    out.kind = Outcome::Kind::tackle_refused;
    out.reason = std::string("the description does not read: ") + e.what();
    return out;
  }
  if (!d.phases.empty() || d.impact || d.interval) {
    // (impacts, intervals and phases: what the model follows of them)
    try {
      return compare_phases(d, *tackle::analyze_text(text, file, rules));
    } catch (const std::exception& e) {
      out.kind = Outcome::Kind::tackle_refused;
      out.reason = e.what();
      return out;
    }
  }
  std::mt19937_64 rng(o.seed);
  std::optional<Model> model;
  try {
    Perturbation p;
    p.masses = o.perturb;
    p.inertia = o.perturb_inertia;
    p.winding = o.perturb_winding;
    model.emplace(d, rng, p);
  } catch (const Unsupported& e) {
    out.kind = Outcome::Kind::skipped;
    out.reason = e.what();
    return out;
  }
  std::unique_ptr<const tackle::Analysis> a;
  try {
    a = tackle::analyze_text(text, file, rules);
  } catch (const tackle::InputError& e) {
    // A description whose balances cannot all hold is refused (exit 1, "the balances cannot
    // all hold: ..."): the model must agree that no state satisfies them, as below. Any other
    // refusal is one.
    out.kind = Outcome::Kind::tackle_refused;
    out.reason = e.what();
    const auto& all = e.diagnostics();
    if (all.size() != 1 || all.front().message.rfind("the balances cannot all hold", 0) != 0) return out;
    out.reason = "tackle finds the equations inconsistent (refused: the balances cannot all hold)";
  } catch (const std::exception& e) {
    out.kind = Outcome::Kind::tackle_refused;
    out.reason = e.what();
    return out;
  }
  if (a && a->solution.status == tackle::Solution::Status::inconsistent) {
    out.kind = Outcome::Kind::tackle_refused;
    out.reason = "tackle finds the equations inconsistent";
    // The model must agree that no state satisfies them: checked below at the base state.
  }
  // (Refused as inconsistent: nothing of tackle's to compare but that.)
  const ClosedForms forms = a ? closed_forms(*a) : ClosedForms{};
  Claims claims = a ? claims_of(*a, d) : Claims{};
  plant(claims, o);
  const GiNaC::exmap defs = a ? a->model.symbols->definitions(true) : GiNaC::exmap{};

  std::vector<State> states;
  states.push_back(model->base_state());
  for (int tries = 0; static_cast<int>(states.size()) < o.states && tries < 10 * o.states; ++tries)
    if (auto s = model->random_state(rng, 0.1)) states.push_back(*s);
  if (model->has_massless()) {
    // a massless body's place and rate at the layout follow from its balance too
    State& b = states.front();
    if (auto s = model->random_state(rng, 0.0)) b = *s;
  }

  std::optional<std::string> model_balanced;  // tackle: inconsistent; the model: balanced at every state
  for (const State& s : states) {
    const auto vals = model->values_at(s);
    GiNaC::exmap at;
    for (const auto& [name, sym] : forms.symbols) {
      auto it = vals.find(name);
      if (it != vals.end()) at[sym] = GiNaC::numeric(it->second);
    }
    // a length sum's named constant (C_s in a position answer, x_A = C_s - x_B): its value here
    if (a)
      for (const auto& c : a->system.constraints)
        if (!c.constant.is_zero() && GiNaC::is_a<GiNaC::symbol>(c.constant))
          if (auto v = evaluate(written_out(c.quantity, defs), at)) at[c.constant] = GiNaC::numeric(*v);
    std::map<std::string, double> tk;
    for (const auto& [name, e] : forms.values) {
      if (auto v = evaluate(e, at)) tk[name] = *v;
    }
    Instant inst = model->solve(s);
    // a rate tackle gives from the constraints is the state's own (the state keeps them)
    for (const auto& [name, value] : vals)
      if (name.rfind("dot(", 0) == 0 && tk.count(name)) inst.quantities.push_back({name, value, true, false, {}});
    ++out.states;
    if (std::getenv("CROSSCHECK_DEBUG")) {
      std::fprintf(stderr, "state (residual %g, rank deficiency %d):\n", inst.residual, inst.rank_deficiency);
      for (const auto& q : inst.quantities)
        std::fprintf(stderr, "  %s = %.17g%s (tackle: %s)\n", q.name.c_str(), q.value, q.determined ? "" : " (free)",
                     tk.count(q.name) ? fmt::format("{:.17g}", tk[q.name]).c_str() : "-");
    }
    // Scales for values near 0: the largest acceleration (at least g, or 1 m/s^2) and the
    // largest force (at least the largest mass times that acceleration).
    double force_scale = 0, accel_scale = std::max(1.0, model->gravity_magnitude());
    for (const auto& q : inst.quantities) {
      double& sc = q.force ? force_scale : accel_scale;
      sc = std::max(sc, std::abs(q.value));
      if (tk.count(q.name)) sc = std::max(sc, std::abs(tk[q.name]));
    }
    force_scale = std::max({force_scale, model->largest_mass() * accel_scale, 1e-3});
    const std::string where = describe_state(vals, d);
    if (out.kind == Outcome::Kind::tackle_refused) {
      // tackle's balances have no force across a body's motion: they are consistent exactly
      // when the model solves its own with every guide force 0
      bool guides_zero = true;
      for (const auto& q : inst.quantities)
        if (q.name.rfind("guide", 0) == 0 && q.determined &&
            std::abs(q.value) > 1e-8 * (q.force ? force_scale : accel_scale))
          guides_zero = false;
      // (tackle decides for every state at once: one state where the model finds no balance
      // either is agreement)
      // (a system the balances leave underdetermined still balances)
      if (inst.residual < 1e-8 && guides_zero) {
        if (!model_balanced) model_balanced = where;
      } else {
        model_balanced.reset();
        out.reason +=
            " (so does the model: at a state where the balances cannot hold without a force the description does not "
            "have)";
        break;
      }
      continue;
    }
    if (inst.residual > 1e-8) {
      out.disagreements.push_back(
          {"consistency (the model's balances cannot hold at this state)", 0, inst.residual, where});
      continue;
    }
    for (const auto& q : inst.quantities) {
      const bool guide = q.name.rfind("guide", 0) == 0;
      auto it = tk.find(q.name);
      if (!guide && it == tk.end()) continue;
      if (!q.determined) {
        ++out.not_determined;
        continue;
      }
      const double expect = guide ? 0.0 : it->second;
      const double scale = q.force ? force_scale : accel_scale;
      const double diff = std::abs(expect - q.value);
      ++out.compared;
      if (diff > o.tolerance * std::max(std::abs(expect), std::abs(q.value)) + 1e-10 * scale)
        out.disagreements.push_back({q.name, expect, q.value, where});
    }
    // what tackle says beyond its closed forms: every answer asked for, the conditions
    ClaimState cs{&s,
                  &inst,
                  vals,
                  [&](const GiNaC::ex& e) { return evaluate(written_out(e, defs), at); },
                  force_scale,
                  accel_scale,
                  &s == &states.front(),
                  where};
    for (const auto& q : inst.quantities) cs.values[q.name] = q.value;
    compare_claims(claims, *model, cs, out, out.not_compared);
  }
  if (model_balanced)
    out.disagreements.push_back(
        {"consistency (tackle: inconsistent; the model solves the balances at every state)", 1, 0, *model_balanced});
  if (out.kind != Outcome::Kind::tackle_refused) {
    out.kind = out.disagreements.empty() ? Outcome::Kind::agree : Outcome::Kind::disagree;
    if (o.motion && a && a->motion && out.kind == Outcome::Kind::agree) {
      const Outcome mo = compare_motion(*a, *model, d, o);
      out.motion_points = mo.motion_points;
      out.motion_error = mo.motion_error;
      out.motion_note = mo.motion_note;
      out.motion_event = mo.motion_event;
      for (const auto& x : mo.disagreements) out.disagreements.push_back(x);
      if (!mo.disagreements.empty()) out.kind = Outcome::Kind::disagree;
    }
  } else if (!out.disagreements.empty()) {
    out.kind = Outcome::Kind::disagree;
  } else if (out.reason.find("so does the model") != std::string::npos) {
    out.kind = Outcome::Kind::agree;  // both find no solution
  }
  return out;
}

}  // namespace crosscheck

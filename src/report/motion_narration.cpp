// The motion in time as the derivation tells it: degrees of freedom, equations of motion,
// equilibrium, the closed-form response, the quantities asked for and the validity
// conditions along it. Narration only: everything is computed in src/motion/.
#include "report/derivation.hpp"

#include <cmath>

#include "expr/print.hpp"
#include "report/narrator.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// A display symbol for a coordinate as a function of time: y(t).
ex of_time(const ex& q, const SymbolTable& table) {
  const SymbolInfo* s = table.find(q);
  const std::string name = s ? s->name : to_text(q), tex = s ? s->tex : name;
  return symbol(name + "(t)", tex + "(t)");
}

std::string regime_text(Response::Regime r) {
  switch (r) {
    case Response::Regime::undamped: return "an undamped oscillation";
    case Response::Regime::underdamped: return "an underdamped oscillation (it decays while it oscillates)";
    case Response::Regime::critically_damped: return "critically damped (the fastest return without oscillating)";
    case Response::Regime::overdamped: return "overdamped (a return without oscillating)";
    case Response::Regime::free_particle: return "unresisted (no stiffness and no damping): the forcing alone moves it";
    case Response::Regime::damped_particle: return "damped, with no stiffness: the velocity relaxes";
  }
  return {};
}

// The motion's narration under way: the narrator, what it tells of, and its steps, one part of
// the story each.
struct Telling {
  Narrator& n;
  const Model& m;
  const Motion& mo;
  const ReportOptions& options;
  const SymbolTable& table;
  const EquationsOfMotion& eom;

  Step* step(Step::Kind kind, std::string t) { return n.step(kind, std::move(t)); }
  void text(std::string t) { n.text(std::move(t)); }
  void text_with(std::string t, std::vector<ex> math) { n.text_with(std::move(t), std::move(math)); }
  Step* equation(std::string label, ex lhs, ex rhs) { return n.equation(std::move(label), lhs, rhs); }
  // A number for an expression in the parameters and the motion's quantities.
  std::optional<NumericValue> number(const ex& e, std::optional<Dimension> dim) {
    ex x = e;
    for (int depth = 0; depth < 4; ++depth) x = substituted(x, mo.definitions);
    return evaluate(x, table, dim, options.digits);
  }

  void freedom();
  void equations();
  void energy();
  void no_response();
  void response();
  void direction();
  void steady_state(const ConditionInTime& c);
  void extreme(const ConditionInTime& c);
};

// The section's head: the degrees of freedom, how many coordinates the constraints tie, and
// the coordinates that describe the motion.
void Telling::freedom() {
  step(Step::Kind::section, "Motion in time");
  std::string coords;
  for (std::size_t i = 0; i < eom.q.size(); ++i) coords += (i ? ", " : "") + std::string("{}");
  const std::size_t tied = eom.moving - eom.dof;
  text_with("The motion has " + std::to_string(eom.dof) + (eom.dof == 1 ? " degree" : " degrees") + " of freedom (" +
                std::to_string(eom.moving) + (eom.moving == 1 ? " coordinate" : " coordinates") +
                (tied ? ", " + std::to_string(tied) + " tied by the constraints" : std::string()) + "), described by " +
                coords + ".",
            eom.q);
}

// The equations of motion: M q'' + C q' + K q = F (linear) with the equilibrium, the
// mass-matrix form, or the solved accelerations (nonlinear); and the natural frequencies.
void Telling::equations() {
  if (eom.linear) {
    text(
        "Equations of motion, the constraint forces eliminated (M from the kinetic energy, C from the dampers, K from "
        "the springs):");
    for (std::size_t i = 0; i < eom.dof; ++i) {
      ex lhs = 0;
      for (std::size_t j = 0; j < eom.dof; ++j)
        lhs += eom.M(i, j) * eom.ddq[j] + eom.C(i, j) * eom.dq[j] + eom.K(i, j) * eom.q[j];
      Step* st = equation("equation of motion ({})", lhs, eom.forcing[i]);
      st->math = {eom.q[i]};
      st->boxed = true;
    }
    if (eom.equilibrium)
      for (std::size_t i = 0; i < eom.dof; ++i) {
        Step* st = equation("equilibrium", eom.q[i], (*eom.equilibrium)[i]);
        st->note = with_unit(number((*eom.equilibrium)[i], Dimension::length()));
      }
  } else if (eom.mass_form) {
    text(
        "Equations of motion, the balances projected on each coordinate (the joint forces do no work on the motion the "
        "coordinates allow, so they drop out), M(q) q'' = F (nonlinear: " +
        eom.nonlinear + "):");
    for (std::size_t i = 0; i < eom.dof; ++i) {
      ex lhs = 0;
      for (std::size_t j = 0; j < eom.dof; ++j) lhs += eom.M(i, j) * eom.ddq[j];
      equation("equation of motion ({})", lhs, eom.forcing[i])->math = {eom.q[i]};
    }
  } else {
    text("Equations of motion, the constraint forces eliminated (nonlinear: " + eom.nonlinear + "):");
    for (std::size_t i = 0; i < eom.dof; ++i)
      equation("equation of motion ({})", eom.ddq[i], eom.acceleration[i])->math = {eom.q[i]};
  }
  if (!eom.natural_frequencies.empty()) {
    std::string f;
    for (std::size_t i = 0; i < eom.natural_frequencies.size(); ++i)
      f += (i ? ", " : "") + decimal_string(GiNaC::numeric(eom.natural_frequencies[i]), options.digits);
    text("Natural frequencies (numeric, from the eigenvalues of M^-1 K with the given values; undamped): " + f +
         " rad/s.");
  }
}

// The work-energy balance: the work of the forces from the start to the position asked
// about, and the speed there (or why there is none).
void Telling::energy() {
  const EnergyAnswer& e = *mo.energy;
  const ex q = eom.q[0], v = eom.dq[0];
  const std::string qn = to_text(q), vn = to_text(v);
  const SymbolInfo* qi = table.find(q);
  const SymbolInfo* vi = table.find(v);
  const ex v_there = symbol(vn + "|" + qn + "=" + to_text(e.position),
                            vi->tex + "\\big|_{" + qi->tex + " = " + to_latex(e.position) + "}");
  text_with(
      "Work and energy: from {} = {} to {} = {}, the change of the kinetic energy is the work of the forces (the "
      "constraint forces do none).",
      {q, m.motion->initial.at(q), q, e.position});
  if (!e.not_possible.empty()) {
    text("No work-energy answer: " + e.not_possible + ".");
  } else {
    if (!e.numeric_only) {
      Step* w = equation("work of the forces", symbol("W", "W"), e.work);
      w->note = with_unit(evaluate(e.work, table, Dimension::force() * Dimension::length(), options.digits, joule()));
      Step* st = equation("work-energy", pow(v_there, 2), *e.rate_squared);
      st->boxed = true;
    } else {
      text(
          "The work has no closed form here; it is integrated numerically (Gauss-Legendre, 64 panels) with the given "
          "values.");
    }
    if (e.rate_squared_number) {
      const double v2 = *e.rate_squared_number;
      if (v2 < 0) {
        text("The kinetic energy there would be negative: the body does not reach " + qn + " = " + to_text(e.position) +
             ".");
      } else {
        Step* sp = equation(e.numeric_only ? "speed there (numeric)" : "speed there", abs(v_there),
                            e.numeric_only ? ex(numeric(decimal_string(numeric(std::sqrt(v2)), options.digits).c_str()))
                                           : sqrt(*e.rate_squared));
        sp->note = decimal_string(numeric(std::sqrt(v2)), options.digits) + " m/s";
        sp->boxed = true;
      }
    }
  }
}

// No closed-form response: why, and the small oscillations about a rest (the linearised
// equations, their frequencies) where there is one.
void Telling::no_response() {
  text("No closed-form response: " + mo.no_response + ". `tackle simulate` integrates the motion numerically.");
  if (const auto& lin = eom.linearised; lin && eom.dof > 1) {
    std::string where;
    for (std::size_t i = 0; i < eom.dof; ++i) where += to_text(eom.q[i]) + " = ";
    text("Small oscillations about " + where + to_text(lin->about) +
         ", where it can rest (the equations of motion "
         "linearised there):");
    for (std::size_t i = 0; i < eom.dof; ++i) {
      ex rhs = 0;
      for (std::size_t j = 0; j < eom.dof; ++j)
        rhs -= lin->stiffness_matrix(static_cast<unsigned>(i), static_cast<unsigned>(j)) * (eom.q[j] - lin->about);
      equation("linearised ({})", eom.ddq[i], rhs)->math = {eom.q[i]};
    }
    if (!lin->frequencies.empty()) {
      std::string f;
      for (std::size_t i = 0; i < lin->frequencies.size(); ++i)
        f += (i ? ", " : "") + decimal_string(GiNaC::numeric(lin->frequencies[i]), options.digits);
      text(
          "Natural frequencies of small oscillations (numeric, from the eigenvalues of the linearised stiffness with "
          "the "
          "given values): " +
          f + " rad/s.");
    }
    text(
        "At larger amplitudes the motion is not a sum of these modes: `tackle simulate` follows the nonlinear "
        "equations.");
  } else if (const auto& lin = eom.linearised) {
    const ex q = eom.q[0];
    const symbol lambda("lambda", "\\lambda");
    text("Small oscillations about " + to_text(q) + " = " + to_text(lin->about) +
         ", where it can rest (the equation of "
         "motion linearised there):");
    equation("linearised", eom.ddq[0], -pow(lambda, 2) * (q - lin->about));
    Step* st = equation("small-oscillation frequency", lambda, sqrt(lin->stiffness));
    if (lin->lambda) {
      st->note = decimal_string(numeric(*lin->lambda), options.digits) + " rad/s";
      Step* p = equation("small-oscillation period", symbol("tau", "\\tau"), 2 * Pi / lambda);
      p->note = decimal_string(numeric(2 * M_PI / *lin->lambda), options.digits) + " s";
    }
    text("The period at a larger amplitude is longer: `tackle simulate` follows the nonlinear equation.");
  }
}

// The closed-form response: the quantities it is written in, its regime, the initial
// conditions, the response itself, what its form assumes, and its check.
void Telling::response() {
  const Response& r = *mo.response;
  for (const auto& [sym, def] : r.definitions) {
    const SymbolInfo* s = table.find(sym);
    const std::string what = s && s->name.rfind("zeta", 0) == 0      ? "damping ratio"
                             : s && s->name.rfind("omega_d", 0) == 0 ? "damped frequency"
                                                                     : "natural frequency";
    Step* st = equation(what, sym, def);
    st->note =
        with_unit(number(sym, what == "damping ratio" ? Dimension::none() : Dimension::none() / Dimension::time()));
    if (what != "damping ratio" && !st->note.empty()) st->note = st->note.substr(0, st->note.rfind(' ')) + " rad/s";
  }
  text("The motion is " + regime_text(r.regime) + ".");
  std::string init = "From ";
  std::vector<ex> init_math;
  for (std::size_t i = 0; i < eom.q.size(); ++i) {
    init += (i ? " and " : "") + std::string("{} = {}, {} = {}");
    init_math.push_back(symbol(to_text(eom.q[i]) + "(0)", table.find(eom.q[i])->tex + "(0)"));
    init_math.push_back(m.motion->initial.at(eom.q[i]));
    init_math.push_back(symbol(to_text(eom.dq[i]) + "(0)", table.find(eom.dq[i])->tex + "(0)"));
    init_math.push_back(m.motion->initial.at(eom.dq[i]));
  }
  text_with(init + ":", init_math);
  Step* resp = equation("response", of_time(eom.q[0], table), r.q);
  resp->boxed = true;
  for (const auto& a : r.assumptions) {
    text("This form assumes (" + a.why + "):");
    Step* st = equation("assumed", a.lhs, a.rhs);
    st->relation = a.op;
  }
  text(r.verified
           ? "Checked: put back into the equation of motion, at random parameter values and times, it holds."
           : "WARNING: put back into the equation of motion it does NOT hold (an error in tackle; please report it).");
}

// Where a rule assumes the direction of motion: how long the response holds (until the rate
// first vanishes), or that the start is against it.
void Telling::direction() {
  const std::string rate = to_text(eom.dq[0]);
  const std::string who = join(mo.direction_assumed_by);
  text(who + " assumes the direction of motion (friction opposes it): this response holds only while " + rate +
       " keeps its sign.");
  if (!mo.direction_against.empty()) {
    text("But " + mo.direction_against +
         ": the closed form describes no part of this motion (reverse the "
         "sliding direction in the description for this start).");
  } else if (mo.direction_until) {
    Step* st = equation("end of the interval", symbol("t_1", "t_{1}"), *mo.direction_until);
    if (mo.direction_until_s) st->note = decimal_string(numeric(*mo.direction_until_s), options.digits) + " s";
    text(
        "At t_1 the body stops and friction would reverse: past it the closed form no longer describes the motion "
        "(simulate it, or write the next phase).");
  } else if (mo.direction_until_s) {
    text(rate + " first vanishes at t_1 = " + decimal_string(numeric(*mo.direction_until_s), options.digits) +
         " s (with the given numbers): past it the closed form no longer describes the motion.");
  } else if (mo.direction_kept) {
    text("With the given numbers " + rate + " keeps its sign" +
         (m.motion && m.motion->until ? std::string(" until the end of the run") : std::string(" for 100 s")) + ".");
  } else {
    text("Without numbers the end of that interval is not found: it is where " + rate + " first vanishes.");
  }
}

// A condition in the steady state (the forced part alone): where it holds for all t, the
// amplitude condition, the band of driving frequencies, and the verdict with the numbers.
void Telling::steady_state(const ConditionInTime& c) {
  const Condition& cond = c.condition;
  text("In the steady state (the forced part of the response alone):");
  Step* ss = equation("steady state", *c.steady_of_t, 0);
  ss->relation = cond.op;
  const bool low = cond.op == ">=" || cond.op == ">";
  text_with(std::string("It holds for all t exactly when the part that does not oscillate, {}, is ") +
                (low ? "non-negative" : "non-positive") + " and outweighs the amplitude:",
            {*c.steady_offset});
  if (c.steady_amplitude_condition) {
    if (const auto always = holds_always(*c.steady_amplitude_condition, ">=")) {
      narrate_always(n, "The amplitude condition's left side, {}, is ", *c.steady_amplitude_condition,
                     *c.steady_amplitude_condition, ">=", *always, cond.otherwise);
    } else {
      Step* amp = equation("amplitude condition", *c.steady_amplitude_condition, 0);
      amp->relation = ">=";
    }
  }
  if (c.band) {
    const auto& b = *c.band;
    text_with(
        std::string("A quadratic in {}: it ") +
            (b.fails_between ? "fails between its roots" : "holds only between its roots") + ", so " +
            (b.fails_between ? "the model fails in a band of driving frequencies:" : "the model holds only in a band:"),
        {b.variable});
    Step* lo = equation(b.fails_between ? "fails above" : "holds above", b.variable, b.low);
    lo->relation = ">";
    if (auto v = number(b.low, std::nullopt)) lo->note = v->decimal + " rad^2/s^2";
    Step* hi = equation(b.fails_between ? "and below" : "and below", b.variable, b.high);
    hi->relation = "<";
    if (auto v = number(b.high, std::nullopt)) hi->note = v->decimal + " rad^2/s^2";
  }
  if (c.steady_holds)
    text(*c.steady_holds ? "With the given numbers it holds for all t in the steady state."
                         : "With the given numbers it does NOT hold in the steady state: " + cond.otherwise + ".");
}

// A condition's extreme over time: the condition for all t (solved for the parameters), where
// the extreme is reached, and the verdict with the numbers and the first failure.
void Telling::extreme(const ConditionInTime& c) {
  const Condition& cond = c.condition;
  const ex& t = m.time;
  const bool lower = cond.op == ">=" || cond.op == ">";
  const auto always = holds_always(*c.extreme, cond.op);
  if (always) {
    narrate_always(n, std::string(lower ? "Its least" : "Its greatest") + " value over time, {}, is ", *c.extreme,
                   *c.extreme, cond.op, *always, cond.otherwise);
  } else {
    Step* ex_st = equation(lower ? "least value over time" : "greatest value over time", *c.extreme, 0);
    ex_st->relation = cond.op;
  }
  if (c.extreme_at) {
    Step* at = equation(lower ? "least at" : "greatest at", t, *c.extreme_at);
    if (auto v = number(*c.extreme_at, Dimension::time())) at->note = with_unit(v);
  }
  if (!always)
    text(std::string("So the model holds for all t exactly when this holds") + (c.solved.empty() ? "." : ", that is:"));
  if (!always)
    for (const auto& sv : c.solved) narrate_solved(n, sv, "for all {}, solved for {}", {t, sv.parameter});
  if (c.holds_for_all_t) {
    if (*c.holds_for_all_t) {
      text("With the given numbers it holds for all t.");
    } else {
      text("With the given numbers it does NOT hold for all t: " + cond.otherwise + ".");
      if (c.first_failure) {
        Step* f = equation("first fails at", t, *c.first_failure);
        if (c.first_failure_s) f->note = decimal_string(numeric(*c.first_failure_s), options.digits) + " s";
        text("After that the model no longer holds; the equations above describe the motion only until then.");
      }
    }
  }
}

}  // namespace

void narrate_motion(Derivation& d, const Model& m, const Motion& mo, const ReportOptions& options) {
  const SymbolTable& table = *m.symbols;
  Narrator n{d, table};
  Telling tell{n, m, mo, options, table, mo.eom};
  tell.freedom();
  tell.equations();
  if (mo.energy) tell.energy();
  // Conditions the motion cannot follow are said whether or not there is a response.
  for (const auto& [source, why] : mo.not_followed)
    tell.text(source + " is not followed in time: " + why + "; `tackle simulate` does not watch it.");
  if (!mo.response) {
    tell.no_response();
    return;
  }
  tell.response();
  if (!mo.direction_assumed_by.empty()) tell.direction();
  for (const auto& q : mo.quantities) {
    Step* st = tell.equation("{} in time", symbol(q.name + "(t)", q.tex + "(t)"), q.of_t);
    st->math = {symbol(q.name, q.tex)};
    st->boxed = true;
  }
  for (const auto& c : mo.conditions) {
    const Condition& cond = c.condition;
    tell.text(cond.source + " along the motion (" + cond.meaning + "):");
    Step* st = tell.equation("in time", c.of_t, 0);
    st->relation = cond.op;
    if (c.steady_of_t) tell.steady_state(c);
    if (!c.extreme) {
      tell.text(
          "Its extremes over time (the whole response) are not found in closed form; `tackle simulate` follows it "
          "numerically.");
      continue;
    }
    tell.extreme(c);
  }
}

}  // namespace tackle

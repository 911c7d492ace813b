#include "report/derivation.hpp"
#include "report/narrator.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

#include "expr/pairs.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// The longest sum of five or more terms, each a number times a parameter or its reciprocal,
// found in at least two closed forms (as a whole subexpression), with a name for it that the
// problem does not use: M for masses, else S. Chosen by size, then by its text: never by GiNaC's order of terms.
std::optional<std::pair<ex, ex>> shared_sum(const std::vector<Answer>& answers, const SymbolTable& table) {
  // Each sum is judged once (by hash), and the closed forms are walked by structure: a
  // chain's closed forms hold the same sum over 256 masses 511 times.
  std::unordered_map<ex, bool, ExHash, ex_is_equal> of_parameters;
  std::unordered_map<ex, int, ExHash, ex_is_equal> count;
  std::unordered_set<ex, ExHash, ex_is_equal> seen;
  auto is_sum_of_parameters = [&](const ex& s) {
    if (auto it = of_parameters.find(s); it != of_parameters.end()) return it->second;
    // Each term a number times a parameter, or its reciprocal (a compound Atwood machine's
    // 16384/m_1 + ... + 1/m_9), and no number alone.
    bool parameters = Pairs::overall(s).is_zero();
    for (const auto& p : Pairs::of(s)) {
      if (!parameters) break;
      ex term = p.rest;
      if (is_exactly<power>(term) && term.op(1).is_equal(-1)) term = term.op(0);
      const SymbolInfo* info = is_exactly<symbol>(term) ? table.find(term) : nullptr;
      parameters = info && info->role == SymbolRole::parameter;
    }
    of_parameters.emplace(s, parameters);
    return parameters;
  };
  std::function<void(const ex&)> walk = [&](const ex& e) {
    if (is_a<symbol>(e) || is_a<numeric>(e)) return;
    if (is_a<add>(e) && e.nops() >= 5 && is_sum_of_parameters(e)) {
      if (seen.insert(e).second) ++count[e];
      return;  // its terms are names (times numbers): no sum inside
    }
    // A sum's and a product's stored pairs: op() would make each power of a sum anew.
    if (is_exactly<add>(e) || is_exactly<mul>(e)) {
      for (const auto& p : Pairs::of(e)) walk(p.rest);
      return;
    }
    for (std::size_t i = 0; i < e.nops(); ++i) walk(e.op(i));
  };
  for (const auto& a : answers) {
    if (!a.closed_form) continue;
    seen.clear();
    walk(*a.closed_form);
  }
  std::optional<ex> best;
  for (const auto& [sum, n] : count)
    if (n >= 2 && (!best || sum.nops() > best->nops() || (sum.nops() == best->nops() && to_text(sum) < to_text(*best))))
      best = sum;
  if (!best) return std::nullopt;
  std::string problem;
  const auto dim = dimension_of(*best, table, problem);
  const bool mass = dim && *dim == Dimension::mass();
  for (const std::string name : {mass ? "M" : "S", mass ? "M_sum" : "S_sum", "Sigma_sum"})
    if (!table.find(name)) return std::make_pair(ex(symbol(name, default_tex(name))), *best);
  return std::nullopt;
}

}  // namespace

Derivation explain(const Model& m, const EquationSystem& s, const Solution& sol, const Answers& ans,
                   const PowerCheck& power_check, const ReportOptions& options, const IntervalEnd* end) {
  Derivation d;
  d.title = m.title;
  d.file = m.file;
  d.rank = sol.rank;
  d.n_equations = s.equations.size();
  d.unknowns = s.unknowns;
  d.equations = s.equations;
  d.constraint_steps = s.constraints;
  d.symbols = m.symbols;
  const SymbolTable& table = *m.symbols;
  Narrator n{d, table};
  auto step = [&](Step::Kind kind, std::string t) { return n.step(kind, std::move(t)); };
  auto section = [&](std::string t) { n.section(std::move(t)); };
  auto text = [&](std::string t) { n.text(std::move(t)); };
  auto text_with = [&](std::string t, std::vector<ex> math) { n.text_with(std::move(t), std::move(math)); };
  auto listed = [](const std::vector<ex>& xs) { return listed_names(xs); };
  auto bullet = [&](std::string t) { n.bullet(std::move(t)); };
  auto equation = [&](std::string label, ex lhs, ex rhs) { return n.equation(std::move(label), lhs, rhs); };

  section("Model");
  std::optional<FigureMaker> figures;  // made once, for the sketch and every balance
  const bool draw = options.narrate && options.figures;
  if (m.dims() <= 2 && draw) {
    figures.emplace(m);
    if (auto fig = figures->sketch()) {
      Step* st = step(Step::Kind::figure, fig->caption);
      st->figure = std::make_shared<const Figure>(std::move(*fig));
    }
  }
  for (const auto& a : m.assumptions) bullet("Assumed: " + a + ".");
  // Connections of one kind said once: "sliding at A and sliding at B: a Coulomb sliding ...".
  {
    // (Said once when the text is the same, its symbols too: three springs of stiffness k.)
    struct Kind {
      std::vector<std::string> labels;
      const Model::ConnectionNote* note;
    };
    std::vector<Kind> kinds;
    auto same = [](const Model::ConnectionNote& a, const Model::ConnectionNote& b) {
      if (a.summary.empty() || a.summary != b.summary || a.terms.size() != b.terms.size()) return false;
      for (std::size_t i = 0; i < a.terms.size(); ++i)
        if (!a.terms[i].is_equal(b.terms[i])) return false;
      return true;
    };
    for (const auto& c : m.connections) {
      auto it = std::find_if(kinds.begin(), kinds.end(), [&](const Kind& k) { return same(*k.note, c); });
      if (it == kinds.end())
        kinds.push_back({{c.label}, &c});
      else
        it->labels.push_back(c.label);
    }
    for (const auto& [labels, note] : kinds) {
      std::string who;
      for (std::size_t i = 0; i < labels.size(); ++i)
        who += (i == 0 ? "" : i + 1 == labels.size() ? " and " : ", ") + labels[i];
      Step* st = step(Step::Kind::bullet, who + (note->summary.empty() ? "" : ": " + note->summary) + ".");
      st->math = note->terms;
    }
  }
  std::vector<std::string> symbolic;
  for (const auto& sym : table.all()) {
    // Parameters, and quantities given with their value at the instant (z = 3 m).
    if (sym->role != SymbolRole::parameter && !sym->value && !sym->definition) continue;
    {
      ParameterReport pr;
      pr.name = sym->name;
      pr.tex = sym->tex;
      pr.kind = sym->role != SymbolRole::parameter ? "given"
                : sym->geometric                   ? "length"
                : sym->definition                  ? "defined"
                                                   : "parameter";
      pr.si = evaluate(sym->sym, table, sym->dimension, options.digits);
      if (!sym->unit.empty() && sym->dimension && !sym->unit_to_si.is_equal(1))
        pr.stated = evaluate(sym->sym, table, sym->dimension, options.digits,
                             Unit{sym->unit_to_si, *sym->dimension, sym->unit});
      pr.definition = sym->definition;
      d.parameters.push_back(std::move(pr));
    }
    if (sym->definition) {
      // A defined parameter: its definition, and its value when the others have one.
      // not folded: it is the definition (a quantity given in the parameters: dot(theta) = v/l)
      Step* st = step(Step::Kind::equation, sym->role == SymbolRole::parameter ? "definition" : "given");
      st->lhs = sym->sym;
      st->rhs = *sym->definition;
      if (auto v = evaluate(sym->sym, table, sym->dimension))
        st->note = v->decimal + (v->unit.empty() ? "" : " " + v->unit);
      continue;
    }
    // A parameter is shown in the unit it was stated in (30 deg, 3000 lbm).
    std::optional<Unit> stated;
    if (!sym->unit.empty() && sym->dimension) stated = Unit{sym->unit_to_si, *sym->dimension, sym->unit};
    if (auto v = sym->value ? evaluate(sym->sym, table, sym->dimension, options.digits, stated) : std::nullopt) {
      Step* st = step(Step::Kind::given, sym->name);
      st->lhs = sym->sym;
      st->rhs = v->exact;
      st->number = v->decimal;
      st->note = v->unit;
    } else {
      symbolic.push_back(sym->name);
    }
  }
  if (!symbolic.empty()) {
    std::vector<ex> syms;
    for (const auto& n : symbolic) syms.push_back(table.find(n)->sym);
    const auto [names, shown] = listed(syms);
    Step* st = step(Step::Kind::bullet, "Symbolic parameters (no value given): " + names + ".");
    st->math = shown;
  }

  if (m.steady) {
    const SteadySpec& sp = *m.steady;
    const ex rate = table.find(sp.rate)->sym, period = table.find(sp.period)->sym;
    step(Step::Kind::bullet,
         "Steady motion at an unknown rate {}: the balances are linear in {}, an unknown solved for "
         "with the others; the rate is its root (the balances fix its size, not its sense), and the "
         "period follows from it:")
        ->math = {rate, sp.squared};
    equation("steady rate", rate, sqrt(sp.squared));
    equation("period", period, 2 * Pi / rate);
  }

  // An impact has no balances of forces: it is told by narrate_impact.
  if (m.impact) {
    d.power = power_check;
    return d;
  }

  const bool has_amb = std::any_of(s.equations.begin(), s.equations.end(),
                                   [](const Equation& e) { return e.kind == Equation::Kind::amb; });
  section(has_amb ? "Free body diagrams: linear and angular momentum balance"
                  : "Free body diagrams: linear momentum balance");
  std::pair<std::vector<int>, bool> drawn{{}, false};  // the body or system last drawn
  for (const auto& eq : s.equations) {
    if (eq.kind == Equation::Kind::constraint_acceleration || eq.kind == Equation::Kind::interval) continue;
    if (draw && !eq.bodies.empty() && std::pair{eq.bodies, eq.system} != drawn) {
      drawn = {eq.bodies, eq.system};
      if (!figures) figures.emplace(m);
      if (auto fig = figures->draw(eq.bodies, eq.system)) {
        Step* st = n.step(Step::Kind::figure, fig->caption);
        st->figure = std::make_shared<const Figure>(std::move(*fig));
      }
    }
    std::vector<std::string> parts;
    std::vector<ex> terms;
    for (std::size_t i = 0; i < eq.terms.size(); ++i) {
      parts.push_back(eq.sources[i] + ": {}");
      terms.push_back(fold_definitions(eq.terms[i], table));
    }
    const std::string what = eq.kind == Equation::Kind::lmb ? "Forces" : "Moments";
    text_with(eq.label + ". " + what + ": " + (parts.empty() ? "none" : join(parts, "; ")) + ".", terms);
    if (!eq.why.empty()) text("About this point and axis there is " + eq.why + ".");
    equation(eq.label, eq.lhs, eq.rhs);
  }

  if (!s.constraints.empty()) {
    section("Constraints: constant lengths, differentiated twice");
    for (const auto& c : s.constraints) {
      text("The " + c.meaning + " is constant in time.");
      // "length of string s", not "string s: length of string s".
      const bool named = c.meaning.size() >= c.label.size() &&
                         c.meaning.compare(c.meaning.size() - c.label.size(), c.label.size(), c.label) == 0;
      Step* st = equation(named ? c.meaning : c.label + ": " + c.meaning, c.quantity, c.constant);
      st->equals_constant = c.constant.is_zero();
      equation(c.label + ": rate", 0, c.rate);
      equation(c.label + ": acceleration", 0, c.acceleration);
    }
  }

  if (m.interval) {
    section(m.interval->duration ? "Over the interval: impulse and momentum"
                                 : "Over the interval: constant acceleration");
    const bool any = std::any_of(s.equations.begin(), s.equations.end(),
                                 [](const Equation& e) { return e.kind == Equation::Kind::interval; });
    text(
        "The forces are taken constant over the interval (their averages), so each acceleration is constant and each "
        "rate changes linearly" +
        std::string(any ? ":" : "; the rates at its end follow from the solved accelerations (below)."));
    for (const auto& eq : s.equations)
      if (eq.kind == Equation::Kind::interval) {
        text(eq.sources.front() + ".");
        equation(eq.label, eq.lhs, eq.rhs);
      }
  }

  section("Solving");
  auto count = [](std::size_t n, const std::string& word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
  };
  {
    const auto [names, shown] = listed(s.unknowns);
    text_with(count(s.equations.size(), "equation") + " in " + count(s.unknowns.size(), "unknown") + " (" + names +
                  ")" + (sol.unsolved.empty() ? "; rank " + std::to_string(sol.rank) : std::string()) + ".",
              shown);
  }
  {
    // The balances that read 0 = 0 (a translating body's AMB about its center, a direction
    // with no force) are said once, their axes together: "AMB A about its center of mass (x,
    // y, z)"; the dependent groups one by one.
    std::vector<std::pair<std::string, std::vector<std::string>>> identical;  // label without its axis, axes
    for (const auto& group : sol.redundant) {
      if (group.size() != 1) continue;
      std::string base = group[0], axis;
      if (const auto open = base.rfind(" ("); open != std::string::npos && base.back() == ')') {
        axis = base.substr(open + 2, base.size() - open - 3);
        base = base.substr(0, open);
      }
      auto it = std::find_if(identical.begin(), identical.end(), [&](const auto& x) { return x.first == base; });
      if (it == identical.end()) identical.push_back({base, {}}), it = identical.end() - 1;
      if (!axis.empty()) it->second.push_back(axis);
    }
    if (!identical.empty()) {
      std::vector<std::string> items;
      for (const auto& [base, axes] : identical)
        items.push_back(axes.empty() ? base : base + " (" + join(axes, ", ") + ")");
      text(items.size() == 1 && identical[0].second.size() <= 1
               ? "Redundant: " + items[0] + " holds identically (it reads 0 = 0)."
               : "Redundant, each holds identically (it reads 0 = 0): " + join(items, "; ") + ".");
    }
    for (const auto& group : sol.redundant)
      if (group.size() > 1)
        text("Redundant: " + join(group, ", ") + " are linearly dependent (one follows from the others).");
  }
  if (!sol.unsolved.empty()) {
    d.status = "not_solved";
    text("They are not solved here: " + sol.unsolved + ".");
  } else
    switch (sol.status) {
      case Solution::Status::determined: {
        d.status = "determined";
        // The status of each quantity is said once: where an answer asked for still needs a
        // quantity no equation gives, the line does not claim more than the solve found.
        const bool every_answer = std::none_of(ans.answers.begin(), ans.answers.end(), [](const Answer& a) {
          return a.status == Answer::Status::undetermined || a.status == Answer::Status::not_in_equations;
        });
        text(every_answer
                 ? "Every unknown is determined."
                 : "Every unknown of these equations is determined; an answer below that needs a quantity they do not "
                   "give says which.");
        break;
      }
      case Solution::Status::underdetermined:
        d.status = "underdetermined";
        {
          const auto [names, shown] = listed(sol.free);
          text_with("Not every unknown is determined; free: " + names + ".", shown);
        }
        break;
      case Solution::Status::inconsistent:
        d.status = "inconsistent";
        text("The equations are inconsistent: " + join(sol.conflicts, ", ") +
             (sol.conflicts.size() == 1 ? " cannot hold (the other equations give its terms values that contradict it)."
                                        : " contradict each other."));
        break;
    }
  // Velocity and position questions: the rate (length) equations solved on their own.
  for (const auto& [level, equations, what] :
       {std::tuple{sol.rates.get(), &s.rate_equations, "Velocities: the constraints differentiated once, "},
        std::tuple{sol.positions.get(), &s.position_equations, "Positions: the constraints themselves, "}}) {
    if (!level) continue;
    std::vector<ex> solved;
    for (const auto& [q, v] : level->general) solved.push_back(q);
    std::sort(solved.begin(), solved.end(), [&](const ex& a, const ex& b) { return to_text(a) < to_text(b); });
    const auto [names, shown] = listed(solved);
    text_with(std::string(what) + count(equations->size(), "equation") + " in " + count(solved.size(), "unknown") +
                  " (" + names + "); rank " + std::to_string(level->rank) + ".",
              shown);
  }
  d.conflicts = sol.conflicts;
  for (const auto& f : sol.free) d.free.push_back(to_text(f));

  d.answers = ans.answers;
  d.combinations = ans.combinations;
  d.minimum_norm = ans.minimum_norm;
  // A long sum that several closed forms share (a chain's m_1 + ... + m_n) is named once,
  // as a person would write it, and the closed forms and conditions below use the name.
  // Only the steps show it: without them (`tackle solve`) nothing is named.
  const auto shared = options.narrate ? shared_sum(d.answers, table) : std::nullopt;
  // By structure, not as a pattern: a pattern is matched at every node (a chain's 511 closed
  // forms over 256 masses spent 0.7 G instructions so).
  exmap naming;
  if (shared) naming[shared->second] = shared->first;
  auto named = [&](const ex& e) { return shared ? e.subs(naming, subs_options::no_pattern) : e; };
  if (sol.status != Solution::Status::inconsistent && sol.unsolved.empty()) {
    section("Results");
    if (shared) equation("a name for the sum the closed forms share", shared->first, shared->second);
    for (const auto& a : d.answers) {
      if (a.closed_form) {
        Step* st = equation("", table.find(a.name)->sym, named(*a.closed_form));
        st->boxed = true;
        if (a.value) st->note = a.value->decimal + (a.value->unit.empty() ? "" : " " + a.value->unit);
      } else if (a.status == Answer::Status::not_in_equations) {
        text_with("{} does not appear in the chosen equations.", {a.symbol});
      } else if (a.status == Answer::Status::undetermined && a.missing.empty()) {
        // A defined quantity that divides by zero (the reason's names as math).
        std::vector<ex> math{a.symbol};
        std::string zeros;
        for (const auto& z : a.zero_divisors) {
          zeros += (zeros.empty() ? "" : ", ") + std::string("{} = 0");
          math.push_back(z);
        }
        text_with("{} is not determined: its definition divides by zero" +
                      (zeros.empty() ? "" : " (" + zeros + " here)") + ".",
                  math);
      } else if (a.status == Answer::Status::undetermined) {
        std::vector<ex> math{a.symbol};
        math.insert(math.end(), a.missing.begin(), a.missing.end());
        text_with("{} is not determined: " + undetermined_reason(a, table, sol, true) + ".", math);
      } else if (a.general) {
        text_with("{} is determined only together with the free unknowns:", {a.symbol});
        equation("", a.symbol, *a.general);
      } else {
        text_with("{} is not determined by the equations (free).", {a.symbol});
      }
    }
    if (!d.minimum_norm.empty()) {
      std::vector<std::string> parts;
      std::vector<ex> names;
      for (const auto& [name, v] : d.minimum_norm) {
        parts.push_back("{} = " + v->decimal + (v->unit.empty() ? "" : " " + v->unit));
        names.push_back(table.find(name)->sym);
      }
      text_with("The member of the family with the least norm (as a computer's least-squares solution would pick): " +
                    join(parts) + ".",
                names);
    }
    for (const auto& c : d.combinations) {
      Step* st = equation("determined in combination", c.combination, c.value);
      st->boxed = true;
      if (c.number) st->note = c.number->decimal + (c.number->unit.empty() ? "" : " " + c.number->unit);
    }
  }

  if (end) narrate_interval_end(d, m, *end, options);

  d.conditions = ans.conditions;
  d.ranges = ans.ranges;
  narrate_validity(n, ans.conditions, ans.ranges, named);
  // The power balance: an independent check, made in the analysis from the model's velocities
  // and loads; narrated here.
  d.power = power_check;
  if (d.power.status == PowerCheck::Status::not_applicable) {
    section("Check: power balance");
    text(d.power.reason == "every body is at rest"
             ? "Every body is at rest, so no force does work: the power balance has nothing to check."
             : "The power balance is not checked: " + d.power.reason + ".");
  } else {
    section("Check: power balance");
    text(
        "The rate of change of the kinetic energy equals the power of the forces; the constraint forces do no "
        "work.");
    const symbol kinetic("dot(E_k)", "\\dot{E}_{k}"), power("P", "P");
    equation("kinetic energy: rate of change", kinetic, d.power.kinetic_rate);
    equation("power of the forces", power, d.power.power);
    if (!d.power.speeds.empty()) {
      std::string names;
      for (std::size_t k = 0; k < d.power.speeds.size(); ++k) names += (k ? ", " : "") + std::string("{}");
      text_with(
          "(" + names + (d.power.speeds.size() == 1 ? " is a speed" : " are speeds") + " along the line of motion.)",
          d.power.speeds);
    }
    if (d.power.status == PowerCheck::Status::holds)
      text(
          "With the solved accelerations and forces, and the velocities the constraints allow, the two are equal: "
          "the power balance holds.");
    else
      text_with(
          "With the solved accelerations and forces the two DIFFER by {}: the power balance FAILS (an error in "
          "tackle; please report it).",
          {d.power.residual});
  }
  return d;
}

}  // namespace tackle

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

// A count of things in words: "1 equation", "3 unknowns".
std::string counted(std::size_t n, const std::string& word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

// Connections of one kind said once: "sliding at A and sliding at B: a Coulomb sliding ...".
// (Said once when the text is the same, its symbols too: three springs of stiffness k.)
struct ConnectionKind {
  std::vector<std::string> labels;
  const Model::ConnectionNote* note;
};

// Whether two connections are told alike: the same summary, with the same symbols.
bool told_alike(const Model::ConnectionNote& a, const Model::ConnectionNote& b) {
  if (a.summary.empty() || a.summary != b.summary || a.terms.size() != b.terms.size()) return false;
  for (std::size_t i = 0; i < a.terms.size(); ++i)
    if (!a.terms[i].is_equal(b.terms[i])) return false;
  return true;
}

// The model's connections grouped by how they are told, in the order each kind first appears.
std::vector<ConnectionKind> connection_kinds(const Model& m) {
  std::vector<ConnectionKind> kinds;
  for (const auto& c : m.connections) {
    auto it = std::find_if(kinds.begin(), kinds.end(), [&](const ConnectionKind& k) { return told_alike(*k.note, c); });
    if (it == kinds.end())
      kinds.push_back({{c.label}, &c});
    else
      it->labels.push_back(c.label);
  }
  return kinds;
}

// The balances that read 0 = 0 (a translating body's AMB about its center, a direction with
// no force), their axes together: each label without its axis, with its axes.
std::vector<std::pair<std::string, std::vector<std::string>>> identical_balances(const Solution& sol) {
  std::vector<std::pair<std::string, std::vector<std::string>>> identical;
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
  return identical;
}

// The steps of a derivation's story, in the book's order, and what they share: the solved
// problem, the narrator writing into the derivation, the figures (made once, for the sketch
// and every balance) and the name for a sum the closed forms share.
struct Story {
  const Model& m;
  const EquationSystem& s;
  const Solution& sol;
  const Answers& ans;
  const ReportOptions& options;
  Derivation& d;
  const SymbolTable& table;
  Narrator n;
  bool draw;                                // the figures are drawn
  std::optional<FigureMaker> figures;       // made when first needed
  std::optional<std::pair<ex, ex>> shared;  // a name for a shared sum, and the sum
  exmap naming;                             // the sum to its name

  Story(const Model& model, const EquationSystem& system, const Solution& solution, const Answers& answers,
        const ReportOptions& opts, Derivation& derivation)
      : m(model),
        s(system),
        sol(solution),
        ans(answers),
        options(opts),
        d(derivation),
        table(*model.symbols),
        n{derivation, *model.symbols},
        draw(opts.narrate && opts.figures) {}

  // What the derivation carries of the problem and its equations.
  void header() {
    d.title = m.title;
    d.file = m.file;
    d.rank = sol.rank;
    d.n_equations = s.equations.size();
    d.unknowns = s.unknowns;
    d.equations = s.equations;
    d.constraint_steps = s.constraints;
    d.symbols = m.symbols;
  }

  // A figure as a step.
  void figure(std::optional<Figure> fig) {
    if (!fig) return;
    Step* st = n.step(Step::Kind::figure, fig->caption);
    st->figure = std::make_shared<const Figure>(std::move(*fig));
  }

  // The model: its sketch, the assumptions, the connections, the parameters, a steady motion.
  void model() {
    n.section("Model");
    if (m.dims() <= 2 && draw) {
      figures.emplace(m);
      figure(figures->sketch());
    }
    for (const auto& a : m.assumptions) n.bullet("Assumed: " + a + ".");
    connections();
    parameters();
    steady();
  }

  // Each kind of connection once, with the labels of the connections of that kind.
  void connections() {
    for (const auto& [labels, note] : connection_kinds(m)) {
      std::string who;
      for (std::size_t i = 0; i < labels.size(); ++i)
        who += (i == 0 ? "" : i + 1 == labels.size() ? " and " : ", ") + labels[i];
      Step* st = n.step(Step::Kind::bullet, who + (note->summary.empty() ? "" : ": " + note->summary) + ".");
      st->math = note->terms;
    }
  }

  // Parameters, and quantities given with their value at the instant (z = 3 m): each reported,
  // and told with its value or definition; those without a value named together.
  void parameters() {
    std::vector<std::string> symbolic;
    for (const auto& sym : table.all()) {
      if (sym->role != SymbolRole::parameter && !sym->value && !sym->definition) continue;
      d.parameters.push_back(parameter_report(*sym));
      if (sym->definition)
        definition(*sym);
      else if (!given(*sym))
        symbolic.push_back(sym->name);
    }
    if (symbolic.empty()) return;
    std::vector<ex> syms;
    for (const auto& name : symbolic) syms.push_back(table.find(name)->sym);
    const auto [names, shown] = listed_names(syms);
    Step* st = n.step(Step::Kind::bullet, "Symbolic parameters (no value given): " + names + ".");
    st->math = shown;
  }

  // A parameter (or a quantity given with its value) as the JSON reports it.
  ParameterReport parameter_report(const SymbolInfo& sym) const {
    ParameterReport pr;
    pr.name = sym.name;
    pr.tex = sym.tex;
    pr.kind = sym.role != SymbolRole::parameter ? "given"
              : sym.geometric                   ? "length"
              : sym.definition                  ? "defined"
                                                : "parameter";
    pr.si = evaluate(sym.sym, table, sym.dimension, options.digits);
    if (!sym.unit.empty() && sym.dimension && !sym.unit_to_si.is_equal(1))
      pr.stated =
          evaluate(sym.sym, table, sym.dimension, options.digits, Unit{sym.unit_to_si, *sym.dimension, sym.unit});
    pr.definition = sym.definition;
    return pr;
  }

  // A defined parameter: its definition, and its value when the others have one.
  // not folded: it is the definition (a quantity given in the parameters: dot(theta) = v/l)
  void definition(const SymbolInfo& sym) {
    Step* st = n.step(Step::Kind::equation, sym.role == SymbolRole::parameter ? "definition" : "given");
    st->lhs = sym.sym;
    st->rhs = *sym.definition;
    if (auto v = evaluate(sym.sym, table, sym.dimension))
      st->note = v->decimal + (v->unit.empty() ? "" : " " + v->unit);
  }

  // A parameter's value, in the unit it was stated in (30 deg, 3000 lbm); false when it has none.
  bool given(const SymbolInfo& sym) {
    std::optional<Unit> stated;
    if (!sym.unit.empty() && sym.dimension) stated = Unit{sym.unit_to_si, *sym.dimension, sym.unit};
    auto v = sym.value ? evaluate(sym.sym, table, sym.dimension, options.digits, stated) : std::nullopt;
    if (!v) return false;
    Step* st = n.step(Step::Kind::given, sym.name);
    st->lhs = sym.sym;
    st->rhs = v->exact;
    st->number = v->decimal;
    st->note = v->unit;
    return true;
  }

  // Steady motion at an unknown rate: the rate as the root of its square, and the period.
  void steady() {
    if (!m.steady) return;
    const SteadySpec& sp = *m.steady;
    const ex rate = table.find(sp.rate)->sym, period = table.find(sp.period)->sym;
    n.step(Step::Kind::bullet,
           "Steady motion at an unknown rate {}: the balances are linear in {}, an unknown solved for "
           "with the others; the rate is its root (the balances fix its size, not its sense), and the "
           "period follows from it:")
        ->math = {rate, sp.squared};
    n.equation("steady rate", rate, sqrt(sp.squared));
    n.equation("period", period, 2 * Pi / rate);
  }

  // The free body diagrams and the balances, each with its forces or moments.
  void balances() {
    const bool has_amb = std::any_of(s.equations.begin(), s.equations.end(),
                                     [](const Equation& e) { return e.kind == Equation::Kind::amb; });
    n.section(has_amb ? "Free body diagrams: linear and angular momentum balance"
                      : "Free body diagrams: linear momentum balance");
    std::pair<std::vector<int>, bool> drawn{{}, false};  // the body or system last drawn
    for (const auto& eq : s.equations) {
      if (eq.kind == Equation::Kind::constraint_acceleration || eq.kind == Equation::Kind::interval) continue;
      if (draw && !eq.bodies.empty() && std::pair{eq.bodies, eq.system} != drawn) {
        drawn = {eq.bodies, eq.system};
        if (!figures) figures.emplace(m);
        figure(figures->draw(eq.bodies, eq.system));
      }
      balance(eq);
    }
  }

  // A balance: its terms with their sources, the point and axis it is about, the equation.
  void balance(const Equation& eq) {
    std::vector<std::string> parts;
    std::vector<ex> terms;
    for (std::size_t i = 0; i < eq.terms.size(); ++i) {
      parts.push_back(eq.sources[i] + ": {}");
      terms.push_back(fold_definitions(eq.terms[i], table));
    }
    const std::string what = eq.kind == Equation::Kind::lmb ? "Forces" : "Moments";
    n.text_with(eq.label + ". " + what + ": " + (parts.empty() ? "none" : join(parts, "; ")) + ".", terms);
    if (!eq.why.empty()) n.text("About this point and axis there is " + eq.why + ".");
    n.equation(eq.label, eq.lhs, eq.rhs);
  }

  // The constraints: each length constant, and its rate and acceleration.
  void constraints() {
    if (s.constraints.empty()) return;
    n.section("Constraints: constant lengths, differentiated twice");
    for (const auto& c : s.constraints) {
      n.text("The " + c.meaning + " is constant in time.");
      // "length of string s", not "string s: length of string s".
      const bool named = c.meaning.size() >= c.label.size() &&
                         c.meaning.compare(c.meaning.size() - c.label.size(), c.label.size(), c.label) == 0;
      Step* st = n.equation(named ? c.meaning : c.label + ": " + c.meaning, c.quantity, c.constant);
      st->equals_constant = c.constant.is_zero();
      n.equation(c.label + ": rate", 0, c.rate);
      n.equation(c.label + ": acceleration", 0, c.acceleration);
    }
  }

  // Over an interval: the forces taken constant, and the interval's equations.
  void interval() {
    if (!m.interval) return;
    n.section(m.interval->duration ? "Over the interval: impulse and momentum"
                                   : "Over the interval: constant acceleration");
    const bool any = std::any_of(s.equations.begin(), s.equations.end(),
                                 [](const Equation& e) { return e.kind == Equation::Kind::interval; });
    n.text(
        "The forces are taken constant over the interval (their averages), so each acceleration is constant and each "
        "rate changes linearly" +
        std::string(any ? ":" : "; the rates at its end follow from the solved accelerations (below)."));
    for (const auto& eq : s.equations)
      if (eq.kind == Equation::Kind::interval) {
        n.text(eq.sources.front() + ".");
        n.equation(eq.label, eq.lhs, eq.rhs);
      }
  }

  // Solving: how many equations in how many unknowns, the redundant ones, what the solve
  // found, the velocity and position questions.
  void solving() {
    n.section("Solving");
    const auto [names, shown] = listed_names(s.unknowns);
    n.text_with(counted(s.equations.size(), "equation") + " in " + counted(s.unknowns.size(), "unknown") + " (" +
                    names + ")" + (sol.unsolved.empty() ? "; rank " + std::to_string(sol.rank) : std::string()) + ".",
                shown);
    redundant();
    status();
    levels();
    d.conflicts = sol.conflicts;
    for (const auto& f : sol.free) d.free.push_back(to_text(f));
  }

  // The balances that read 0 = 0 said once, their axes together: "AMB A about its center of
  // mass (x, y, z)"; the dependent groups one by one.
  void redundant() {
    const auto identical = identical_balances(sol);
    if (!identical.empty()) {
      std::vector<std::string> items;
      for (const auto& [base, axes] : identical)
        items.push_back(axes.empty() ? base : base + " (" + join(axes, ", ") + ")");
      n.text(items.size() == 1 && identical[0].second.size() <= 1
                 ? "Redundant: " + items[0] + " holds identically (it reads 0 = 0)."
                 : "Redundant, each holds identically (it reads 0 = 0): " + join(items, "; ") + ".");
    }
    for (const auto& group : sol.redundant)
      if (group.size() > 1)
        n.text("Redundant: " + join(group, ", ") + " are linearly dependent (one follows from the others).");
  }

  // What the solve found: not solved, determined, underdetermined or inconsistent.
  void status() {
    if (!sol.unsolved.empty()) {
      d.status = "not_solved";
      n.text("They are not solved here: " + sol.unsolved + ".");
      return;
    }
    switch (sol.status) {
      case Solution::Status::determined:
        d.status = "determined";
        determined();
        break;
      case Solution::Status::underdetermined: {
        d.status = "underdetermined";
        const auto [names, shown] = listed_names(sol.free);
        n.text_with("Not every unknown is determined; free: " + names + ".", shown);
        break;
      }
      case Solution::Status::inconsistent:
        d.status = "inconsistent";
        n.text("The equations are inconsistent: " + join(sol.conflicts, ", ") +
               (sol.conflicts.size() == 1
                    ? " cannot hold (the other equations give its terms values that contradict it)."
                    : " contradict each other."));
        break;
    }
  }

  // Every unknown determined. The status of each quantity is said once: where an answer asked
  // for still needs a quantity no equation gives, the line does not claim more than the solve found.
  void determined() {
    const bool every_answer = std::none_of(ans.answers.begin(), ans.answers.end(), [](const Answer& a) {
      return a.status == Answer::Status::undetermined || a.status == Answer::Status::not_in_equations;
    });
    n.text(every_answer ? "Every unknown is determined."
                        : "Every unknown of these equations is determined; an answer below that needs a quantity "
                          "they do not give says which.");
  }

  // Velocity and position questions: the rate (length) equations solved on their own.
  void levels() {
    for (const auto& [level, equations, what] :
         {std::tuple{sol.rates.get(), &s.rate_equations, "Velocities: the constraints differentiated once, "},
          std::tuple{sol.positions.get(), &s.position_equations, "Positions: the constraints themselves, "}}) {
      if (!level) continue;
      std::vector<ex> solved;
      for (const auto& [q, v] : level->general) solved.push_back(q);
      std::sort(solved.begin(), solved.end(), [&](const ex& a, const ex& b) { return to_text(a) < to_text(b); });
      const auto [names, shown] = listed_names(solved);
      n.text_with(std::string(what) + counted(equations->size(), "equation") + " in " +
                      counted(solved.size(), "unknown") + " (" + names + "); rank " + std::to_string(level->rank) + ".",
                  shown);
    }
  }

  // The answers into the derivation, and a name for the long sum several closed forms share
  // (a chain's m_1 + ... + m_n), as a person would write it: the closed forms and conditions
  // below use the name. Only the steps show it: without them (`tackle solve`) nothing is named.
  void answers() {
    d.answers = ans.answers;
    d.combinations = ans.combinations;
    d.minimum_norm = ans.minimum_norm;
    shared = options.narrate ? shared_sum(d.answers, table) : std::nullopt;
    // By structure, not as a pattern: a pattern is matched at every node (a chain's 511 closed
    // forms over 256 masses spent 0.7 G instructions so).
    if (shared) naming[shared->second] = shared->first;
  }

  // An expression with the shared sum named.
  ex named(const ex& e) const { return shared ? e.subs(naming, subs_options::no_pattern) : e; }

  // The results, when the equations were solved and are consistent: each answer, the
  // least-norm member of a family, the determined combinations.
  void results() {
    if (sol.status == Solution::Status::inconsistent || !sol.unsolved.empty()) return;
    n.section("Results");
    if (shared) n.equation("a name for the sum the closed forms share", shared->first, shared->second);
    for (const auto& a : d.answers) result(a);
    minimum_norm();
    for (const auto& c : d.combinations) {
      Step* st = n.equation("determined in combination", c.combination, c.value);
      st->boxed = true;
      if (c.number) st->note = c.number->decimal + (c.number->unit.empty() ? "" : " " + c.number->unit);
    }
  }

  // One answer: its closed form boxed, or why it has none.
  void result(const Answer& a) {
    if (a.closed_form) {
      Step* st = n.equation("", table.find(a.name)->sym, named(*a.closed_form));
      st->boxed = true;
      if (a.value) st->note = a.value->decimal + (a.value->unit.empty() ? "" : " " + a.value->unit);
    } else if (a.status == Answer::Status::not_in_equations) {
      n.text_with("{} does not appear in the chosen equations.", {a.symbol});
    } else if (a.status == Answer::Status::undetermined && a.missing.empty()) {
      divides_by_zero(a);
    } else if (a.status == Answer::Status::undetermined) {
      std::vector<ex> math{a.symbol};
      math.insert(math.end(), a.missing.begin(), a.missing.end());
      n.text_with("{} is not determined: " + undetermined_reason(a, table, sol, true) + ".", math);
    } else if (a.general) {
      n.text_with("{} is determined only together with the free unknowns:", {a.symbol});
      n.equation("", a.symbol, *a.general);
    } else {
      n.text_with("{} is not determined by the equations (free).", {a.symbol});
    }
  }

  // A defined quantity that divides by zero (the reason's names as math).
  void divides_by_zero(const Answer& a) {
    std::vector<ex> math{a.symbol};
    std::string zeros;
    for (const auto& z : a.zero_divisors) {
      zeros += (zeros.empty() ? "" : ", ") + std::string("{} = 0");
      math.push_back(z);
    }
    n.text_with(
        "{} is not determined: its definition divides by zero" + (zeros.empty() ? "" : " (" + zeros + " here)") + ".",
        math);
  }

  // The member of the family with the least norm, when there is one.
  void minimum_norm() {
    if (d.minimum_norm.empty()) return;
    std::vector<std::string> parts;
    std::vector<ex> names;
    for (const auto& [name, v] : d.minimum_norm) {
      parts.push_back("{} = " + v->decimal + (v->unit.empty() ? "" : " " + v->unit));
      names.push_back(table.find(name)->sym);
    }
    n.text_with("The member of the family with the least norm (as a computer's least-squares solution would pick): " +
                    join(parts) + ".",
                names);
  }

  // The validity conditions and the parameters' ranges, with the shared sum named.
  void validity() {
    d.conditions = ans.conditions;
    d.ranges = ans.ranges;
    narrate_validity(n, ans.conditions, ans.ranges, [this](const ex& e) { return named(e); });
  }

  // The power balance: an independent check, made in the analysis from the model's velocities
  // and loads; narrated here.
  void power(const PowerCheck& power_check) {
    d.power = power_check;
    n.section("Check: power balance");
    if (d.power.status == PowerCheck::Status::not_applicable) {
      n.text(d.power.reason == "every body is at rest"
                 ? "Every body is at rest, so no force does work: the power balance has nothing to check."
                 : "The power balance is not checked: " + d.power.reason + ".");
      return;
    }
    n.text(
        "The rate of change of the kinetic energy equals the power of the forces; the constraint forces do no "
        "work.");
    const symbol kinetic("dot(E_k)", "\\dot{E}_{k}"), power("P", "P");
    n.equation("kinetic energy: rate of change", kinetic, d.power.kinetic_rate);
    n.equation("power of the forces", power, d.power.power);
    speeds();
    if (d.power.status == PowerCheck::Status::holds)
      n.text(
          "With the solved accelerations and forces, and the velocities the constraints allow, the two are equal: "
          "the power balance holds.");
    else
      n.text_with(
          "With the solved accelerations and forces the two DIFFER by {}: the power balance FAILS (an error in "
          "tackle; please report it).",
          {d.power.residual});
  }

  // The speeds the power balance uses, said to be along the line of motion.
  void speeds() {
    if (d.power.speeds.empty()) return;
    std::string names;
    for (std::size_t k = 0; k < d.power.speeds.size(); ++k) names += (k ? ", " : "") + std::string("{}");
    n.text_with(
        "(" + names + (d.power.speeds.size() == 1 ? " is a speed" : " are speeds") + " along the line of motion.)",
        d.power.speeds);
  }
};

}  // namespace

Derivation explain(const Model& m, const EquationSystem& s, const Solution& sol, const Answers& ans,
                   const PowerCheck& power_check, const ReportOptions& options, const IntervalEnd* end) {
  Derivation d;
  Story story(m, s, sol, ans, options, d);
  story.header();
  story.model();
  // An impact has no balances of forces: it is told by narrate_impact.
  if (m.impact) {
    d.power = power_check;
    return d;
  }
  story.balances();
  story.constraints();
  story.interval();
  story.solving();
  story.answers();
  story.results();
  if (end) narrate_interval_end(d, m, *end, options);
  story.validity();
  story.power(power_check);
  return d;
}

}  // namespace tackle

#include "solve/answers.hpp"

#include <algorithm>
#include <set>
#include <unordered_set>

#include <Eigen/Dense>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "solve/bounds.hpp"

namespace tackle {

using namespace GiNaC;

std::string undetermined_reason(const Answer& a, const SymbolTable& table, const Solution& sol, bool placeholders) {
  std::vector<std::string> names;
  bool kinematic = false;
  for (const auto& x : a.missing) {
    const SymbolInfo* info = table.find(x);
    names.push_back(placeholders ? "{}" : info->name);
    kinematic = kinematic || info->role == SymbolRole::rate || info->role == SymbolRole::coordinate;
  }
  if (kinematic && (sol.rates || sol.positions))
    return "it depends on " + join(names, ", ") + ", which the constraints leave free (give it in 'given')";
  // A position or velocity other than the one asked for, in a force (a spring at x): the
  // answer holds at any instant once it is given.
  const bool other =
      std::none_of(a.missing.begin(), a.missing.end(), [&](const ex& x) { return x.is_equal(a.symbol); });
  if (kinematic && other)
    return "it depends on " + join(names, ", ") + " (give " + (names.size() == 1 ? "it" : "them") +
           " in 'given' for the answer at any instant)";
  return "no solved equation gives " + join(names, ", ") +
         (kinematic
              ? "; the equations solved are at the acceleration level (balances and constraints differentiated twice)"
              : " in terms of the parameters and given quantities");
}

bool has_definition(const ex& e, const SymbolTable& table) {
  for (const SymbolInfo* sym : table.defined())
    if (!sym->geometric && e.has(sym->sym)) return true;
  return false;
}

ex fold_definitions(const ex& e, const SymbolTable& table) {
  ex best = e;
  for (const SymbolInfo* sym : table.defined()) {  // in the table's order (an exmap's is the hash order)
    const ex& name_sym = sym->sym;
    const ex& definition = *sym->definition;
    // l = sqrt(A): put l^2 for A, so that sqrt(A) and 1/sqrt(A) become l and 1/l (l > 0).
    const bool root = is_a<power>(definition) && definition.op(1).is_equal(numeric(1, 2));
    const ex folded = root ? best.subs(definition.op(0) == pow(name_sym, 2)) : best.subs(definition == name_sym);
    if (folded.is_equal(best)) continue;
    const ex tidy = simplest(folded);
    if (to_text(tidy).size() < to_text(best).size()) best = tidy;
  }
  return best;
}

namespace {

// What `find` asks for, or every unknown; and a steady motion's rate and period, unless
// `find` placed them.
std::vector<Wanted> wanted_answers(const Model& m, const EquationSystem& s) {
  const SymbolTable& table = *m.symbols;
  std::vector<Wanted> wanted = m.wanted;
  if (wanted.empty())
    for (const auto& u : s.unknowns) {
      const SymbolInfo* info = table.find(u);
      wanted.push_back({info->name, info->tex, u, false, info->dimension, std::nullopt});
    }
  if (m.steady)
    for (const auto& w : m.steady->reported)
      if (std::none_of(wanted.begin(), wanted.end(), [&](const Wanted& x) { return x.name == w.name; }))
        wanted.push_back(w);
  return wanted;
}

// What a closed form may not contain: anything but parameters, defined quantities, time
// and what is given. At one instant the positions and velocities are the state the balances
// are written in: known symbols, as a person keeps x in `k (D - x - l_0)/m`. They are
// unknowns only where a question asks for one of their kind (then the constraints, solved
// at that level, give them or leave them free, and an answer never is itself).
// (A massless body's coordinate that its balance fixes is an unknown of the instant.)
std::unordered_set<ex, ExHash, ex_is_equal> not_known_symbols(const Model& m, const Solution& sol) {
  const SymbolTable& table = *m.symbols;
  bool positions_asked = static_cast<bool>(sol.positions), rates_asked = static_cast<bool>(sol.rates);
  const std::vector<ex> by_balance = balance_coordinates(m);
  for (const auto& w : m.wanted)
    if (const SymbolInfo* info = w.defined || contains(by_balance, w.expr) ? nullptr : table.find(w.expr)) {
      positions_asked = positions_asked || info->role == SymbolRole::coordinate;
      rates_asked = rates_asked || info->role == SymbolRole::rate;
    }
  std::unordered_set<ex, ExHash, ex_is_equal> not_known;
  for (const auto& sym : table.all()) {
    const bool state =
        (sym->role == SymbolRole::coordinate && !positions_asked) || (sym->role == SymbolRole::rate && !rates_asked);
    if (!(sym->role == SymbolRole::parameter || sym->role == SymbolRole::defined || sym->role == SymbolRole::time ||
          state || contains(m.given, sym->sym)))
      not_known.insert(sym->sym);
  }
  return not_known;
}

// The answers to what is wanted, one step per way an answer can end.
struct Answering {
  const Model& m;
  const EquationSystem& s;
  const Solution& sol;
  int digits;
  const SymbolTable& table = *m.symbols;
  const std::unordered_set<ex, ExHash, ex_is_equal> not_known = not_known_symbols(m, sol);

  // An expression in the solution: the general solution put in, then the rates' and positions'.
  ex solved_in(const ex& e) const {
    ex g = substituted(e, sol.general);
    for (const auto* level : {sol.rates.get(), sol.positions.get()})
      if (level) g = substituted(g, level->general);
    return g;
  }

  Answer answer(const Wanted& w) const {
    Answer a;
    a.name = w.name;
    a.tex = w.tex;
    a.symbol = table.find(w.name)->sym;
    a.unit = w.unit;
    const bool is_unknown = contains(s.unknowns, w.expr);
    const bool is_candidate = contains(m.candidates, w.expr);
    if (sol.status == Solution::Status::inconsistent || (!w.defined && is_candidate && !is_unknown)) {
      a.status = Answer::Status::not_in_equations;
      return a;
    }
    if (divides_by_zero(w, a)) return a;
    const ex general = solved_in(w.expr);
    bool free = false;
    for (const auto& f : sol.free) free = free || general.has(f);
    if (free)
      with_free_unknowns(w, general, a);
    else
      in_closed_form(w, general, a);
    return a;
  }

  // A defined quantity that divides by something the equations make zero (F/ddot(x_B)
  // where ddot(x_B) = 0) is undefined. Denominators are tried first, innermost first:
  // GiNaC would throw from inside a node it is making, and that node would leak.
  bool divides_by_zero(const Wanted& w, Answer& a) const {
    for (const_postorder_iterator it = w.expr.postorder_begin(); it != w.expr.postorder_end(); ++it) {
      if (!is_a<power>(*it) || !is_a<numeric>(it->op(1)) || !ex_to<numeric>(it->op(1)).is_negative()) continue;
      if (!normal(solved_in(it->op(0))).is_zero()) continue;
      a.zero_divisors.push_back(it->op(0));
      break;
    }
    if (a.zero_divisors.empty()) return false;
    a.status = Answer::Status::undetermined;
    a.reason = "its definition " + to_text(w.expr) + " divides by zero (" + to_text(a.zero_divisors[0]) + " = 0 here)";
    return true;
  }

  // Free itself, or in combination: affine in the free unknowns, each free unknown with its
  // coefficient, then the rest.
  void with_free_unknowns(const Wanted& w, const ex& general, Answer& a) const {
    const bool is_free = contains(sol.free, w.expr);
    a.status = is_free ? Answer::Status::free : Answer::Status::in_combination;
    if (is_free) return;
    exmap none;
    for (const auto& f : sol.free) none[f] = 0;
    const ex g = general.expand();
    ex shown = simplest(substituted(g, none));
    for (const auto& f : sol.free) shown += simplest(g.coeff(f, 1)) * f;
    a.general = shown;
  }

  // A closed form may contain parameters and given quantities only: anything else (a
  // velocity asked for while only accelerations are solved) is what is missing.
  // (Only the symbols that are not known are looked for, each met once: asking has()
  // of every symbol of a chain of 256 bodies would make this cubic.) In the table's order.
  void in_closed_form(const Wanted& w, const ex& general, Answer& a) const {
    const std::vector<ex> found = distinct_symbols_among(general, not_known);
    if (!found.empty()) {
      const std::unordered_set<ex, ExHash, ex_is_equal> present(found.begin(), found.end());
      for (const auto& sym : table.all())
        if (present.count(sym->sym) > 0) a.missing.push_back(sym->sym);
    }
    if (!a.missing.empty()) {
      a.status = Answer::Status::undetermined;
      a.reason = undetermined_reason(a, table, sol, false);
      return;
    }
    a.closed_form = closed_form(general);
    a.value = evaluate(*a.closed_form, table, w.dimension, digits, w.unit);
    // For programs: the same closed form in the parameters alone (l put in).
    if (has_definition(*a.closed_form, table)) a.in_parameters = simplest(definitions_put_in(*a.closed_form));
  }

  // `e` with the defined quantities' definitions put in (to a depth of 8).
  ex definitions_put_in(ex e) const {
    for (int depth = 0; depth < 8 && has_definition(e, table); ++depth) e = substituted(e, table.definitions());
    return e;
  }

  // With the definitions put in, terms may cancel (y_s = (m + M) g/k in sample 12.4):
  // the shorter of the two, definitions folded back.
  ex closed_form(const ex& general) const {
    const ex plain = simplest(general);
    // Nothing to put in: the same form twice would cost a second simplification.
    if (!has_definition(general, table)) return fold_definitions(plain, table);
    const ex expanded = fold_definitions(simplest(definitions_put_in(general)), table);
    return to_text(expanded).size() < to_text(plain).size() ? expanded : fold_definitions(plain, table);
  }

  // Indeterminate, with numbers: x = p + N f over the free unknowns f; the member of least
  // norm is the least-squares solution of N f = -p (Eigen, complete orthogonal decomposition).
  decltype(Answers::minimum_norm) minimum_norm() const;

  // The model's conditions, each with whether it holds at the numbers (when it does not
  // depend on a free unknown) and its bounds in numbers.
  std::vector<ConditionReport> conditions() const;
};

decltype(Answers::minimum_norm) Answering::minimum_norm() const {
  decltype(Answers::minimum_norm) out;
  std::vector<ex> family;
  for (const auto& u : s.unknowns) {
    const ex g = substituted(u, sol.general);
    if (std::any_of(sol.free.begin(), sol.free.end(), [&](const ex& f) { return g.has(f); })) family.push_back(u);
  }
  const exmap values = table.values();
  exmap zero_free;
  for (const auto& f : sol.free) zero_free[f] = 0;
  Eigen::MatrixXd N(family.size(), sol.free.size());
  Eigen::VectorXd p(family.size());
  bool numeric_family = true;
  // A family undefined at the given numbers (a denominator that vanishes there) has no
  // least-norm member (found by fuzzing, where it was an internal error). Each number is
  // taken from the normal form's numerator and denominator, the denominator checked first:
  // GiNaC would throw from inside a node it is making, and that node would leak.
  auto number = [&](const ex& x) { return NormalForm(x).approx_at(values); };
  for (std::size_t i = 0; i < family.size() && numeric_family; ++i) {
    const ex g = substituted(family[i], sol.general).expand();
    const auto base = number(substituted(g, zero_free));
    numeric_family = base.has_value();
    if (numeric_family) p(static_cast<Eigen::Index>(i)) = *base;
    for (std::size_t j = 0; j < sol.free.size() && numeric_family; ++j) {
      const auto c = number(g.coeff(sol.free[j], 1));
      numeric_family = c.has_value();
      if (numeric_family) N(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = *c;
    }
  }
  if (!numeric_family || family.empty()) return out;
  const Eigen::VectorXd f = N.completeOrthogonalDecomposition().solve(-p);
  const Eigen::VectorXd x = p + N * f;
  for (std::size_t i = 0; i < family.size(); ++i) {
    const SymbolInfo* info = table.find(family[i]);
    // A double from Eigen, shown to the report's digits (not exact).
    NumericValue v;
    v.exact = v.si = numeric(x(static_cast<Eigen::Index>(i)));
    v.approx = x(static_cast<Eigen::Index>(i));
    v.decimal = decimal_string(numeric(std::abs(v.approx) < 1e-12 ? 0.0 : v.approx), std::min(digits, 12));
    v.unit = info->dimension ? si_unit_name(*info->dimension) : "";
    out.emplace_back(info->name, v);
  }
  return out;
}

std::vector<ConditionReport> Answering::conditions() const {
  std::vector<ConditionReport> out;
  for (const auto& cc : sol.conditions) {
    ConditionReport r{cc.condition->source, cc.condition->lhs,     cc.condition->rhs,       cc.condition->op, cc.expr,
                      std::nullopt,         cc.condition->meaning, cc.condition->otherwise, cc.solved,        cc.always,
                      cc.depends_on_free};
    if (!cc.depends_on_free) {
      if (auto v = evaluate(cc.expr, table, std::nullopt)) {
        // Exactly when the value is rational, else on its high-precision float.
        const numeric x = is_a<numeric>(v->exact) ? ex_to<numeric>(v->exact) : ex_to<numeric>(evalf(v->exact));
        r.holds = relation_holds(x, r.op);
      }
    }
    number_bounds(r.solved, table, digits);
    out.push_back(r);
  }
  return out;
}

}  // namespace

Answers answer(const Model& m, const EquationSystem& s, const Solution& sol, int digits) {
  Answers out;
  if (!sol.unsolved.empty()) return out;  // nothing is asked, and nothing solved
  const Answering answering{m, s, sol, digits};
  for (const auto& w : wanted_answers(m, s)) out.answers.push_back(answering.answer(w));
  for (const auto& c : sol.combinations) {
    std::string problem;
    auto dim = dimension_of(c.combination, *m.symbols, problem);
    out.combinations.push_back({c.combination, c.value, evaluate(c.value, *m.symbols, dim, digits)});
  }
  if (sol.status == Solution::Status::underdetermined) out.minimum_norm = answering.minimum_norm();
  out.conditions = answering.conditions();
  out.ranges = ranges_at_numbers(out.conditions, *m.symbols, digits);
  return out;
}

}  // namespace tackle

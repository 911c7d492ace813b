#include "solve/solve.hpp"
#include "expr/memory.hpp"

#include "expr/trig.hpp"

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <set>
#include <map>
#include <random>

#include "core/diagnostics.hpp"
#include "expr/pairs.hpp"
#include "expr/print.hpp"
#include "motion/mass_form.hpp"
#include "solve/eliminate.hpp"

namespace tackle {

using namespace GiNaC;

std::optional<ex> Solution::value_of(const ex& unknown) const {
  for (const auto& d : values)
    if (d.unknown.is_equal(unknown)) return d.value;
  return std::nullopt;
}

namespace {

// Zero, also by sin^2 + cos^2 = 1 (closed forms are simplified with it).
bool zero(const ex& e) { return is_zero_exactly(e); }

// True when a denominator of `e` (innermost first) vanishes at `point`.
bool pole_at(const ex& e, const exmap& point) {
  for (const_postorder_iterator it = e.postorder_begin(); it != e.postorder_end(); ++it)
    if (is_a<power>(*it) && is_a<numeric>(it->op(1)) && ex_to<numeric>(it->op(1)).is_negative() &&
        normal(substituted(it->op(0), point)).is_zero())
      return true;
  return false;
}

}  // namespace

namespace {

std::string flipped(const std::string& op) {
  if (op == ">=") return "<=";
  if (op == "<=") return ">=";
  if (op == ">") return "<";
  if (op == "<") return ">";
  return op;
}

int known_sign(const ex& e) { return sign_of(e).value_or(0); }

// `e op 0` with the factors of known sign divided out, given e's numerator and denominator:
// returns the factors left (their product), and flips `op` for each negative factor.
ex strip_signed_factors_of(const ex& nd, std::string& op) {
  ex rest = 1;
  for (int side = 0; side < 2; ++side) {
    const bool denominator = side == 1;
    const std::vector<ex> factors = canonical_factors(nd.op(side));
    for (const ex& x : factors) {
      const int sign = known_sign(x);
      if (sign > 0) continue;
      if (sign < 0) {
        op = flipped(op);
        continue;
      }
      rest = denominator ? rest / x : rest * x;
    }
  }
  return rest;
}

// The same for `e` itself.
ex strip_signed_factors(const ex& e, std::string& op) { return strip_signed_factors_of(numer_denom_remembered(e), op); }

// Whether `rest op 0` holds (or fails) whatever the values, for what strip_signed_factors left:
// a number, or even powers only (k^2 x_S^2 with k^2 divided out: never negative, and zero
// where x_S is).
std::optional<bool> always_of_rest(const ex& rest, const std::string& op) {
  if (is_a<numeric>(rest)) return relation_holds(ex_to<numeric>(rest), op);
  const ex nd = numer_denom_remembered(rest);
  for (int side = 0; side < 2; ++side)
    for (const ex& x : canonical_factors(nd.op(side)))
      if (!(is_a<numeric>(x) && ex_to<numeric>(x).is_positive()) && !(is_a<power>(x) && x.op(1).info(info_flags::even)))
        return std::nullopt;
  if (op == ">=") return true;
  if (op == "<") return false;
  return std::nullopt;
}

}  // namespace

bool relation_holds(const numeric& x, const std::string& op) {
  if (op == ">=") return x >= 0;
  if (op == ">") return x > 0;
  if (op == "<=") return x <= 0;
  if (op == "<") return x < 0;
  return x.is_zero();
}

namespace {

// `rest reduced_op 0` (factors of known sign divided out) solved for each parameter.
std::vector<SolvedFor> solve_reduced(const ex& rest, const std::string& reduced_op, const std::vector<ex>& parameters,
                                     const exmap* values = nullptr) {
  std::vector<SolvedFor> out;
  const ex nd = numer_denom_remembered(rest);
  if (!nd.op(1).is_equal(1)) return out;  // a denominator of unknown sign remains
  const ex poly = nd.op(0).expand();
  for (const ex& p : parameters) {
    // (Not in p where p is inside a root, a function or a power of a non-integer exponent:
    // a normal written in a parameter, [a, 0, 1], has it in sqrt(a^2 + 1).)
    if (!poly.has(p) || !poly.is_polynomial(p)) continue;
    const int degree = poly.degree(p);
    // a p + b, or a p^2 + b for a positive p (a speed v: v^2 <= r g tan(beta) gives v <=
    // sqrt(r g tan(beta)) where that root is real).
    const bool square = degree == 2 && poly.coeff(p, 1).is_zero() && p.info(info_flags::positive);
    if (degree != 1 && !square) continue;
    const ex a = normal(poly.coeff(p, degree)), b = normal(poly.coeff(p, 0));
    int sign = known_sign(factored(a));
    ex provided = 0;
    if (sign == 0 && values && square) {
      // Of a sign the parameters leave open: solved where it has the sign it has at the given
      // numbers, and said so (the top speed on a banked curve exists while cos - mu sin > 0).
      const ex at = evalf(a.subs(*values).subs(*values));
      if (is_a<numeric>(at) && ex_to<numeric>(at).is_real() && !ex_to<numeric>(at).is_zero()) {
        sign = ex_to<numeric>(at).is_positive() ? 1 : -1;
        provided = simplest(sign > 0 ? a : -a);
      }
    }
    if (sign == 0) continue;
    const ex bound = simplest(-b / a);
    const std::string op = sign > 0 ? reduced_op : flipped(reduced_op);
    if (!square) {
      out.push_back({p, op, bound, 0, std::nullopt});
      continue;
    }
    if (op != "<=" && op != "<" && op != ">=" && op != ">") continue;
    // v op sqrt(bound) where the bound is positive, else the square itself (v^2 >= a negative
    // number always holds, and the parameters may make it so).
    if (known_sign(factored(bound)) > 0) {
      out.push_back({p, op, simplest(sqrt(bound)), provided, std::nullopt});
      continue;
    }
    // (A lower bound on the square that is negative at the given numbers asks nothing of p
    // there: the report says so, with the number.)
    out.push_back({pow(p, 2), op, bound, provided, std::nullopt});
  }
  return out;
}

}  // namespace

std::optional<bool> holds_always(const ex& expr, const std::string& op) {
  std::string reduced_op = op;
  const ex rest = strip_signed_factors(expr, reduced_op);
  return always_of_rest(rest, reduced_op);
}

std::vector<SolvedFor> solve_condition(const ex& expr, const std::string& op, const std::vector<ex>& parameters) {
  if (op == "=") return {};
  std::string reduced_op = op;
  const ex rest = strip_signed_factors(expr, reduced_op);
  return solve_reduced(rest, reduced_op, parameters);
}

namespace {

// The equations as a sparse linear system in `unknowns` (the coefficients in normal form);
// an input error for an equation not linear in them.
SparseSystem linear_system(const std::string& file, const std::vector<Equation>& equations,
                           const std::vector<ex>& unknowns) {
  const std::size_t n_eq = equations.size(), n_unk = unknowns.size();
  std::unordered_map<ex, std::size_t, ExHash, ex_is_equal> column_of;
  for (std::size_t j = 0; j < n_unk; ++j) column_of.emplace(unknowns[j], j);
  SparseSystem system;
  system.columns = n_unk;
  system.a.resize(n_eq);
  system.b.resize(n_eq);
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < n_eq; ++i) {
    const ex residual = (equations[i].lhs - equations[i].rhs).expand();
    // The unknowns this equation holds, in the unknowns' order.
    std::set<std::size_t> present;
    for (const_preorder_iterator it = residual.preorder_begin(); it != residual.preorder_end(); ++it)
      if (is_a<symbol>(*it))
        if (const auto c = column_of.find(*it); c != column_of.end()) present.insert(c->second);
    exmap zero_unknowns;
    for (const std::size_t j : present) zero_unknowns[unknowns[j]] = 0;
    for (const std::size_t j : present) {
      const ex a = residual.diff(ex_to<symbol>(unknowns[j]));
      if (std::any_of(present.begin(), present.end(), [&](std::size_t k) { return a.has(unknowns[k]); }))
        problems.push_back("equation '" + equations[i].label + "' is not linear in " + to_text(unknowns[j]) +
                           " (tackle solves linear systems)");
      if (!zero(a)) system.a[i][j] = normal_remembered(a);
    }
    system.b[i] = normal(-substituted(residual, zero_unknowns));
  }
  if (!problems.empty()) {
    std::vector<Diagnostic> ds;
    for (auto& p : problems) ds.push_back({{file, 0, 0}, p});
    throw InputError(ds);
  }
  return system;
}

// Sparse elimination, Markowitz pivots first. When some unknown has no pivot, again with
// the columns in order, so that the free unknowns are the ones a person reading the
// unknowns in order would leave free; when some equation is left over, again with the
// rows tracked, to say which equations it combines.
// (With more equations than unknowns some are left over for certain: tracked at once.)
Elimination eliminated(const SparseSystem& system, const std::vector<ex>& unknowns, std::size_t n_eq) {
  const std::size_t n_unk = unknowns.size();
  Elimination e = eliminate(system, unknowns, Pivoting::markowitz, n_eq > n_unk);
  Pivoting pivoting = Pivoting::markowitz;
  if (e.rank < n_unk) {
    pivoting = Pivoting::in_column_order;
    e = eliminate(system, unknowns, pivoting, !e.leftover.empty());
  } else if (!e.leftover.empty() && n_eq <= n_unk) {
    e = eliminate(system, unknowns, pivoting, true);
  }
  return e;
}

// Rows without a pivot: 0 = b. Nonzero b: the equations that combine to it conflict (the
// solution inconsistent); zero b: they are redundant.
void read_leftovers(Solution& sol, const Elimination& e, const std::vector<Equation>& equations) {
  auto involved = [&](const Elimination::Leftover& l) {
    std::vector<std::string> labels;
    for (const std::size_t row : l.combination) labels.push_back(equations[row].label);
    return labels;
  };
  for (const auto& l : e.leftover) {
    if (!zero(l.rhs)) {
      sol.status = Solution::Status::inconsistent;
      for (const auto& label : involved(l))
        if (std::find(sol.conflicts.begin(), sol.conflicts.end(), label) == sol.conflicts.end())
          sol.conflicts.push_back(label);
    } else {
      sol.redundant.push_back(involved(l));
    }
  }
}

// The free unknowns (no pivot), then each pivot's value: alone when its row holds no free
// unknown, else a combination (u + rest = value); the general solution in every case.
void read_values(Solution& sol, const Elimination& e, const std::vector<ex>& unknowns) {
  for (std::size_t j = 0; j < unknowns.size(); ++j)
    if (!e.pivot[j]) sol.free.push_back(unknowns[j]);
  if (!sol.free.empty()) sol.status = Solution::Status::underdetermined;
  exmap no_free;
  for (const auto& f : sol.free) no_free[f] = 0;
  for (std::size_t j = 0; j < unknowns.size(); ++j) {
    if (!e.pivot[j]) continue;
    const ex& u = unknowns[j];
    const ex& general = e.value[j];
    ex rest = 0;  // the free unknowns in this unknown's row: u + rest = value
    for (const auto& f : sol.free)
      if (general.has(f)) rest -= normal(general.diff(ex_to<symbol>(f))) * f;
    const ex value = simplest(sol.free.empty() ? general : substituted(general, no_free));
    sol.general[u] = value - rest;
    if (rest.is_zero())
      sol.values.push_back({u, value});
    else
      sol.combinations.push_back({u + rest, value});
  }
}

// Rational functions evaluated modulo the prime 2^61 - 1, in machine words (exact rationals
// grew with every product: a chain's check was a tenth of its run); a residual that is not 0
// there is not 0. The points the general solution holds at (up to two), or nothing when some
// value is not a rational function (checked at exact points instead).
std::optional<int> verified_modular(const Solution& sol, const std::vector<Equation>& equations) {
  int trial = 0;
  bool modular = true;
  for (std::uint64_t draw = 0; modular && trial < 2 && draw < 30; ++draw) {
    ModularPoint point(20261121 + draw);
    bool pole = false;
    for (const auto& [u, g] : sol.general) {
      const ModularAt r = modular_at(g, point);
      modular = r.kind != RationalAt::Kind::other;
      pole = r.kind == RationalAt::Kind::pole;
      if (!modular || pole) break;
      point.assign(u, r.value);
    }
    for (std::size_t i = 0; modular && !pole && i < equations.size(); ++i) {
      const ModularAt r = modular_at(equations[i].lhs - equations[i].rhs, point);
      modular = r.kind != RationalAt::Kind::other;
      pole = r.kind == RationalAt::Kind::pole;
      if (r.kind == RationalAt::Kind::value && r.value != 0)
        throw InternalError("solution fails equation '" + equations[i].label + "' at a random point");
    }
    if (modular && !pole) ++trial;
  }
  if (!modular) return std::nullopt;
  return trial;
}

// At exact random points (anything else: sin(theta), a turning strand's square root). A point
// where some denominator vanishes is drawn again (GiNaC would throw there, from inside a node
// it is making; found by fuzzing). Rational functions are evaluated as numbers; anything else
// by substitution. The points the general solution holds at (up to two).
int verified_exact(const Solution& sol, const std::vector<Equation>& equations) {
  lst everything;  // the equations' symbols
  for (const auto& eq : equations) everything.append(eq.lhs - eq.rhs);
  std::mt19937 rng(20261121);
  int trial = 0;
  for (int draws = 0; trial < 2 && draws < 30; ++draws) {
    const exmap point = random_point(everything, rng);
    RationalPoint numbers;
    for (const auto& [sym, v] : point) numbers.emplace(sym, ex_to<numeric>(v));
    exmap at = point;
    bool pole = false, rational = true;
    for (const auto& [u, g] : sol.general) {
      const RationalAt r = rational_at(g, numbers);
      if (r.kind == RationalAt::Kind::pole || (r.kind == RationalAt::Kind::other && pole_at(g, point))) {
        pole = true;
        break;
      }
      if (r.kind == RationalAt::Kind::value) {
        numbers.insert_or_assign(u, r.value);
        at[u] = r.value;
      } else {
        rational = false;
        at[u] = substituted(g, point);
      }
    }
    if (pole) continue;
    for (std::size_t i = 0; !pole && i < equations.size(); ++i) {
      const ex residual = equations[i].lhs - equations[i].rhs;
      const RationalAt r = rational ? rational_at(residual, numbers) : RationalAt{};
      if (r.kind == RationalAt::Kind::pole || (r.kind == RationalAt::Kind::other && pole_at(residual, at)))
        pole = true;
      else if (r.kind == RationalAt::Kind::value && !r.value.is_zero())
        throw InternalError("solution fails equation '" + equations[i].label + "' at a random point");
      else if (r.kind == RationalAt::Kind::other && !zero(substituted(residual, at)))
        throw InternalError("solution fails equation '" + equations[i].label + "' at a random point");
    }
    if (pole) continue;
    ++trial;
  }
  return trial;
}

// Verify: the general solution satisfies every equation at two random points of the
// parameters and free unknowns (integers drawn from 2^40 values each, so a residual that
// is not zero vanishes at one by chance with a probability of its degree over 2^40).
// At a point, each unknown's value is evaluated once and put into every equation. Only when
// no point can be used (a denominator vanishes at every one drawn) is every residual put in
// normal form, which for a large solution is what would make this the slowest step.
// The values hold no symbol the equations do not: the points are drawn for theirs.
// Throws InternalError when an equation fails.
void verify(const Solution& sol, const std::vector<Equation>& equations) {
  const std::optional<int> modular = verified_modular(sol, equations);
  const int trial = modular ? *modular : verified_exact(sol, equations);
  if (trial == 0)
    for (const auto& eq : equations) {
      const ex residual = substituted(eq.lhs - eq.rhs, sol.general);
      if (!zero(residual))
        throw InternalError("solution fails equation '" + eq.label + "': residual " + to_text(normal(residual)));
    }
}

}  // namespace

Solution solve_equations(const std::string& file, const std::vector<Equation>& equations,
                         const std::vector<ex>& unknowns) {
  Solution sol;
  const SparseSystem system = linear_system(file, equations, unknowns);
  const Elimination e = eliminated(system, unknowns, equations.size());
  sol.rank = e.rank;
  read_leftovers(sol, e, equations);
  if (sol.status == Solution::Status::inconsistent) return sol;
  read_values(sol, e, unknowns);
  verify(sol, equations);
  return sol;
}

namespace {

// The rate or position level: the constraints' equations at that level, solved for the
// rates (coordinates) of the bodies that are not given. Only when a question needs it.
std::optional<Solution> solve_level(const Model& model, const std::vector<Equation>& equations, SymbolRole role) {
  const auto in_questions = symbols_asked(model.wanted);
  bool asked = false;
  for (const auto& sym : model.symbols->all())
    if (sym->role == role && in_questions.count(sym->sym) != 0) asked = true;
  if (!asked || equations.empty()) return std::nullopt;
  std::vector<ex> unknowns;
  for (const auto& c : model.coordinates) {
    const ex& q = role == SymbolRole::rate ? c.rate : c.q;
    if (contains(model.given, q)) continue;
    // A coordinate inside a turning strand's length (x in l_CP = sqrt(h^2 + x^2)): the length
    // sum only looks linear in it, so it is not solved for (it stays what it depends on).
    if (std::any_of(equations.begin(), equations.end(),
                    [&](const Equation& e) { return model.symbols->hidden_in_lengths(e.lhs - e.rhs, q); }))
      continue;
    if (std::any_of(equations.begin(), equations.end(),
                    [&](const Equation& e) { return e.lhs.has(q) || e.rhs.has(q); }))
      unknowns.push_back(q);
  }
  if (unknowns.empty()) return std::nullopt;
  return solve_equations(model.file, equations, unknowns);
}

}  // namespace

namespace {

// The parameters that are acute angles: a range (the variants') inside (0, pi/2) in SI.
// Their sin, cos and tan stand as positive symbols while a condition is solved.
struct AcuteAngles {
  exmap stand_ins, back;
};

AcuteAngles acute_angles(const Model& model) {
  AcuteAngles out;
  for (const auto& sym : model.symbols->all()) {
    if (sym->role != SymbolRole::parameter || !sym->range) continue;
    const ex low = evalf(sym->range->first * sym->unit_to_si), high = evalf(sym->range->second * sym->unit_to_si);
    if (!is_a<numeric>(low) || !is_a<numeric>(high)) continue;
    if (!(ex_to<numeric>(low) > 0) || !(ex_to<numeric>(high) < ex_to<numeric>(evalf(Pi / 2)))) continue;
    const ex x = sym->sym;
    for (const ex& f : {sin(x), cos(x), tan(x)}) {
      const possymbol stand_in(to_text(f));
      out.stand_ins[f] = stand_in;
      out.back[stand_in] = f;
    }
  }
  return out;
}

// Square roots with the factors of known positive sign taken out of them: sqrt(m^2 r^2
// (omega^4 + alpha^2)) is m r sqrt(omega^4 + alpha^2) for positive m and r (the size of a
// friction in the tangent plane, sqrt(F_1^2 + F_2^2)), and so are the fourth powers of real
// factors (sqrt(omega^4) = omega^2). A root whose radicand has no such factor is left as it is.
struct RootsPulledOut : map_function {
  ex operator()(const ex& e) override {
    if (!is_exactly<power>(e)) return e.map(*this);
    const ex expo = e.op(1);
    if (!is_exactly<numeric>(expo) || !(2 * ex_to<numeric>(expo)).is_odd()) return e.map(*this);
    const ex base = (*this)(e.op(0));
    const ex nd = normal(base).numer_denom();
    ex out = 1, in = 1;
    bool pulled = false;
    for (int side = 0; side < 2; ++side) {
      const ex factored = factor(nd.op(side));
      const exvector factors =
          is_exactly<mul>(factored) ? exvector(factored.begin(), factored.end()) : exvector{factored};
      ex side_out = 1, side_in = 1;
      for (const ex& f : factors) {
        ex b = f, k = 1;
        if (is_exactly<power>(f) && f.op(1).info(info_flags::posint)) b = f.op(0), k = f.op(1);
        const int kk = static_cast<int>(ex_to<numeric>(k).to_int());
        if (kk >= 2 && !is_exactly<numeric>(b) && sign_of(b).value_or(0) > 0) {
          side_out *= pow(b, kk / 2);
          side_in *= pow(b, kk % 2);
          pulled = true;
        } else if (kk >= 4 && !is_exactly<numeric>(b) && b.info(info_flags::real)) {
          // A real base of unknown sign: sqrt(omega^4) = omega^2 (an even power under the root).
          side_out *= pow(b, 2 * (kk / 4));
          side_in *= pow(b, kk % 4);
          pulled = true;
        } else {
          side_in *= f;
        }
      }
      out = side == 0 ? side_out : out / side_out;
      in = side == 0 ? side_in : in / side_in;
    }
    if (!pulled) return pow(base, expo);
    // (out^2 in)^(k/2) = out^k in^(k/2), out being positive.
    return pow(out, 2 * expo) * pow(in, expo);
  }
};

ex roots_pulled_out(const ex& e) {
  bool root = false;
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end() && !root; ++it)
    root = is_exactly<power>(*it) && is_exactly<numeric>(it->op(1)) && !it->op(1).info(info_flags::integer);
  if (!root) return e;
  RootsPulledOut pull;
  return pull(e);
}

}  // namespace

Solution solve(const Model& model, const EquationSystem& s) {
  if (LeftToMotion left = instant_left_to_motion(model); !left.why.empty()) {
    Solution unsolved;
    unsolved.unsolved = std::move(left.why);
    unsolved.mass_form = std::move(left.form);
    return unsolved;
  }
  Solution sol = solve_equations(model.file, s.equations, s.unknowns);
  if (sol.status == Solution::Status::inconsistent) return sol;
  if (auto r = solve_level(model, s.rate_equations, SymbolRole::rate))
    sol.rates = std::make_shared<const Solution>(std::move(*r));
  if (auto r = solve_level(model, s.position_equations, SymbolRole::coordinate))
    sol.positions = std::make_shared<const Solution>(std::move(*r));
  const AcuteAngles acute = acute_angles(model);
  // The given numbers (and the acute angles' stand-ins at them), made once for every condition.
  exmap values = model.symbols->values();
  for (const auto& [stand_in, f] : acute.back) values[stand_in] = f.subs(values);
  // Quantities given in the parameters (dot(theta) = v/L) are put in: the conditions are then
  // in the parameters, and solved for them (v^2 >= -g L cos(theta), not dot(theta)^2 >= ...).
  exmap given_in_parameters;
  for (const auto& g : model.given)
    if (const SymbolInfo* info = model.symbols->find(g); info && info->definition)
      given_in_parameters[g] = *info->definition;
  auto given_put_in = [&](const ex& e) {
    return given_in_parameters.empty() ? e : substituted(e, given_in_parameters);
  };
  for (const auto& c : model.conditions) {
    CheckedCondition cc;
    cc.condition = &c;
    const ex normal_form = normal_remembered(roots_pulled_out(given_put_in(substituted(c.lhs - c.rhs, sol.general))));
    cc.expr = simplest(normal_form);
    // The symbols are gathered once (has() of each symbol would be quadratic per condition),
    // by hash: they are only looked up.
    const std::vector<ex> symbols = distinct_symbols(normal_form);
    const std::unordered_set<ex, ExHash, ex_is_equal> present(symbols.begin(), symbols.end());
    for (const auto& f : sol.free) cc.depends_on_free = cc.depends_on_free || present.count(f) != 0;
    // Conditions on unknowns that the chosen equations do not contain are left out.
    bool relevant = true;
    for (const auto& u : model.candidates)
      if (present.count(u) != 0 && !contains(s.unknowns, u)) relevant = false;
    if (!relevant) continue;
    if (!cc.depends_on_free) {
      std::vector<ex> parameters;
      for (const auto& sym : model.symbols->all())
        if (sym->role == SymbolRole::parameter && present.count(sym->sym) != 0) parameters.push_back(sym->sym);
      // A given coordinate or velocity is a parameter of the instant: solve for it too (the
      // blocks of sample 12.4 stay together while y >= -y_s).
      for (const auto& g : model.given)
        if (present.count(g) != 0) parameters.push_back(g);
      // Not for a name a defined quantity in the condition depends on (a turning strand's
      // length, a given rate v/R, y_s = (m + M) g/k): solved with that quantity held, the form
      // would be wrong; nor for a turning strand's length itself: the condition only looks
      // linear in it. (The defined names in the condition are found once, not per parameter.)
      std::vector<const SymbolInfo*> defined_in;
      for (const SymbolInfo* sym : model.symbols->defined())
        if (present.count(sym->sym) != 0) defined_in.push_back(sym);
      if (!defined_in.empty())
        parameters.erase(std::remove_if(parameters.begin(), parameters.end(),
                                        [&](const ex& p) {
                                          return std::any_of(
                                              defined_in.begin(), defined_in.end(), [&](const SymbolInfo* l) {
                                                return (l->geometric && l->sym.is_equal(p)) || l->definition->has(p);
                                              });
                                        }),
                         parameters.end());
      if (c.op != "=") {
        // Factors of known sign divided out once: what is left is solved for a parameter, or
        // is a number, and then the condition always or never holds. The sine, cosine and
        // tangent of an acute angle (a parameter whose range lies in (0, 90 deg)) are positive:
        // they stand as positive symbols meanwhile.
        std::string op = c.op;
        ex for_solving = normal_form;
        if (!acute.stand_ins.empty()) {
          const ex put = normal_form.subs(acute.stand_ins);
          if (!put.is_equal(normal_form)) for_solving = normal(put);
        }
        const ex rest = strip_signed_factors_of(numer_denom_of_normal(for_solving), op);
        cc.solved = solve_reduced(rest, op, parameters, &values);
        for (auto& sv : cc.solved)
          if (!acute.back.empty()) {
            sv.bound = simplest(sv.bound.subs(acute.back));
            sv.provided = simplest(sv.provided.subs(acute.back));
          }
        cc.always = always_of_rest(rest, op);
      }
    }
    sol.conditions.push_back(cc);
  }
  return sol;
}

}  // namespace tackle

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

// The sign of base^expo from the base's: a power of a positive base is positive, an even power
// of a negative one too, an odd one negative.
std::optional<int> sign_of_power(std::optional<int> b, const ex& expo) {
  if (!b || *b == 0 || !expo.info(info_flags::real)) return std::nullopt;
  if (*b > 0) return 1;
  if (expo.info(info_flags::even)) return 1;
  if (expo.info(info_flags::odd)) return -1;
  return std::nullopt;
}

// The sign of a sum: the common sign of its nonzero terms.
std::optional<int> sign_of_sum(const ex& e) {
  int s = 0;  // the common sign of the nonzero terms so far
  auto take = [&](std::optional<int> t) {
    if (!t) return false;
    if (*t == 0) return true;
    if (s != 0 && *t != s) return false;
    s = *t;
    return true;
  };
  for (const auto& p : Pairs::of(e)) {
    const auto r = sign_of(p.rest), c = sign_of(p.coeff);
    if (!take(r && c ? std::optional<int>(*r * *c) : std::nullopt)) return std::nullopt;
  }
  if (!take(sign_of(Pairs::overall(e)))) return std::nullopt;
  return s == 0 ? std::nullopt : std::optional<int>(s);  // an all-zero sum is not left unevaluated
}

}  // namespace

// The sign of an expression when the domains of its symbols decide it: +1, -1, 0 (zero) or
// nullopt (unknown). Decided structurally (not by GiNaC's info flags, which say nothing of a
// sum of negative terms), so the answer never depends on the order GiNaC keeps terms in.
std::optional<int> sign_of(const ex& e) {
  if (is_exactly<numeric>(e)) {
    const numeric& n = ex_to<numeric>(e);
    if (!n.is_real()) return std::nullopt;
    return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
  }
  if (is_exactly<symbol>(e)) {
    if (e.info(info_flags::positive)) return 1;
    return std::nullopt;
  }
  // Sums and products by their stored pairs: a term is rest times a number, a factor rest to
  // a number. A long sum's sign is remembered per thread (a chain's 255 conditions share the
  // sum of its 256 masses).
  if (is_exactly<add>(e)) {
    if (Pairs::of(e).size() <= long_sum_terms) return sign_of_sum(e);
    auto& memory = thread_memory<struct sum_sign_memory, ExMemory<std::optional<int>>>();
    return remembered(memory, e, 1024, [&] { return sign_of_sum(e); });
  }
  if (is_exactly<mul>(e)) {
    int s = 1;
    for (const auto& p : Pairs::of(e)) {
      const auto r = sign_of(p.rest);
      const auto t = ex_to<numeric>(p.coeff) == 1 ? r : sign_of_power(r, p.coeff);
      if (!t) return std::nullopt;
      s *= *t;
    }
    const auto c = sign_of(Pairs::overall(e));
    if (!c) return std::nullopt;
    return s * *c;
  }
  if (is_exactly<power>(e)) return sign_of_power(sign_of(e.op(0)), e.op(1));
  return std::nullopt;
}

namespace {

// A sum's orientation: +1 if the sum is kept as it is, -1 if it is to be negated. A sum of
// known sign is made positive; any other sum gets a positive coefficient on the term that
// prints first in tackle's fixed order, so the choice never depends on GiNaC's hash order.
int orientation(const ex& sum) {
  if (const auto s = sign_of(sum); s && *s != 0) return *s;
  std::string first;
  int sign = 1;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    const ex t = sum.op(i);
    ex coeff = 1, rest = t;
    if (is_a<numeric>(t)) {
      coeff = t;
      rest = 1;
    } else if (is_a<mul>(t)) {
      coeff = t.op(t.nops() - 1);
      rest = is_a<numeric>(coeff) ? t / coeff : t;
      if (!is_a<numeric>(coeff)) coeff = 1;
    }
    const std::string key = to_text(rest);
    if (i == 0 || key < first) {
      first = key;
      sign = ex_to<numeric>(coeff).is_negative() ? -1 : 1;
    }
  }
  return sign;
}

}  // namespace

namespace {

// The monomial and integer content of a large expanded polynomial times what is left: GiNaC's
// factor() takes seconds on sums of some dozens of terms in ten symbols (a collar hoisted by
// two cables: 2 s for one problem), and factoring such a sum rarely shortens it.
ex content_only(const ex& expanded) {
  const Content c = content_of(expanded);
  return c.content * c.rest;
}

// Not factored either (besides a sum of more than factor_term_limit terms, rational.hpp): a
// sum of more than 8 terms in more than 8 symbols (functions standing in as symbols
// count): one such sum of 12 terms in 11 symbols took factor() 70 ms of a 95 ms run (a
// damped, driven block's response), for no shorter form.
constexpr std::size_t factor_wide_terms = 8, factor_wide_symbols = 8;

// A sum that, its monomial content taken out, is of degree 1 in some symbol x with
// coefficients of x^1 and x^0 that have no common factor: it cannot be factored further (a
// factor would be free of x and divide both), so factor() has nothing to do. Most sums met
// are such (k*y_0 - g*m, m*w^2 - k); gcd() is far cheaper than factor().
bool linear_and_primitive(const ex& expanded) {
  if (!is_a<add>(expanded)) return false;
  ex monomial = 1;
  for (const auto& [x, low] : degrees_of(expanded).low) monomial *= pow(x, low);
  return linear_and_coprime((expanded / monomial).expand());
}

bool too_wide(const ex& expanded) {
  if (!is_a<add>(expanded) || expanded.nops() <= factor_wide_terms) return false;
  return symbols_in(expanded).size() > factor_wide_symbols;
}

}  // namespace

namespace {

// The factors of a polynomial: a number, powers of symbols and sums, as factor() or (for
// long or wide sums) content_only() finds them.
ex factors_found(const ex& polynomial) {
  // A long primitive sum times a monomial (the back substitution's numerators): the content
  // content_only() finds in its expansion, without expanding it.
  if (const auto c = content_of_product(polynomial, factor_term_limit)) return times(c->content, c->rest);
  // sin(theta) and the like stand in as symbols while factoring (factor() leaves a sum with
  // them unfactored), and are put back in each factor.
  exmap repl;
  const ex p = is_polynomial_in_symbols(polynomial) ? polynomial : polynomial.to_polynomial(repl);
  const ex expanded = p.expand();
  const bool plain = (is_a<add>(expanded) && expanded.nops() > factor_term_limit) || too_wide(expanded) ||
                     linear_and_primitive(expanded);
  return substituted(plain ? content_only(expanded) : factor(p), repl);
}

std::vector<ex> canonical_factors_uncached(const ex& polynomial) {
  const ex f = factors_found(polynomial);
  std::vector<ex> raw;
  if (is_a<mul>(f))
    for (std::size_t i = 0; i < f.nops(); ++i) raw.push_back(f.op(i));
  else
    raw.push_back(f);
  // GiNaC's factor() can leave a sum partly factored (d*g - a*(e - c)), and which part it
  // factors can vary between runs: each factor is expanded, so that only the factorization
  // into whole factors is kept. Each sum is oriented (see `orientation`) and the signs taken
  // out are gathered in the numeric coefficient, which comes first.
  numeric coefficient = 1;
  std::vector<ex> out;
  for (const ex& x : raw) {
    ex base = x, exponent = 1;
    if (is_a<power>(x)) {
      base = x.op(0);
      exponent = x.op(1);
    }
    base = base.expand();
    if (const ex p = pow(base, exponent); is_a<numeric>(p)) {
      coefficient *= ex_to<numeric>(p);
      continue;
    }
    // Only integer powers of a sum are oriented: a fractional power of the negated sum is
    // another expression.
    if (is_a<add>(base) && exponent.info(info_flags::integer) && orientation(base) < 0) {
      base = (-base).expand();
      if (exponent.info(info_flags::odd)) coefficient = -coefficient;
    }
    out.push_back(exponent.is_equal(1) ? base : pow(base, exponent));
  }
  if (!coefficient.is_equal(1) || out.empty()) out.insert(out.begin(), coefficient);
  return out;
}

}  // namespace

// Remembered per thread (the last 4096 polynomials): a condition's numerator and
// denominator are factored again after simplest() factored them, and a chain's 255 tensions
// share one denominator. Equal polynomials give equal factors, so nothing printed changes.
std::vector<ex> canonical_factors(const ex& polynomial) {
  auto& memory = thread_memory<struct canonical_factors_memory, ExMemory<std::vector<ex>>>();
  return remembered(memory, polynomial, 4096, [&] { return canonical_factors_uncached(polynomial); });
}

namespace {

// The product of the canonical factors (see canonical_factors), remembered: one run factors
// the same numerators and denominators many times (a motion's quantities share m + M). The
// memory is per thread and forgets everything past 4096 polynomials; an equal polynomial
// always gives an equal product, so what is remembered changes no output.
ex factored(const ex& polynomial) {
  auto& memory = thread_memory<struct polynomial_memory, ExMemory<ex>>();
  return remembered(memory, polynomial, 4096, [&] {
    ex out = 1;
    for (const ex& x : canonical_factors(polynomial)) out = times(out, x);
    return out;
  });
}

}  // namespace

namespace {

// Which form is shorter is judged by its printed length; past some hundreds of nodes (a
// chain's closed forms over 256 masses), by its node count: printing both forms of every
// closed form was a quarter of the time of a large problem.
bool shorter(const ex& a, const ex& b, bool large) {
  return large ? node_count(a) < node_count(b) : to_text(a).size() < to_text(b).size();
}

// The factored form f of the normal form n, or n, whichever is shorter; f is remembered as
// having the normal form n.
ex shorter_form(const ex& f, const ex& n, bool large) {
  remember_normal(f, n);
  if (f.is_equal(n)) return n;  // one form (a chain's F*(m_2 + ... + m_256)/M): nothing to count
  return shorter(f, n, large) ? f : n;
}

ex simplest_uncached(const ex& e);

// A compound Atwood machine's accelerations are sums over the masses of the product of all
// but one, over another such sum (11 terms of 10 masses for 10 levels): divided through by
// the product, each term is a number over one mass, and the closed form grows like the
// number of levels instead of its square. Tried only for that shape (three or more symbols
// of degree 1 in the denominator, each of its terms holding all of them but one at most),
// made by expand() alone (no gcd), and kept only when it takes a third of the nodes of
// `best` off: textbook problems keep their forms.
// The product of the symbols of degree 1 in the expanded denominator d when d has the shape
// reciprocal_form() looks for; nothing otherwise. Remembered per thread: a chain's 255
// tensions share one denominator of 256 terms, and telling that it has not the shape was a
// set of 256 symbols made for each.
std::optional<ex> reciprocal_denominator(const ex& d) {
  auto& memory = thread_memory<struct denominator_memory, ExMemory<std::optional<ex>>>();
  return remembered(memory, d, 1024, [&]() -> std::optional<ex> {
    if (!is_exactly<add>(d) || !is_polynomial_in_symbols(d)) return std::nullopt;
    std::set<ex, ex_is_less> inverted;
    for (const auto& [x, high] : degrees_of(d).high)
      if (high == 1) inverted.insert(x);
    if (inverted.size() < 3) return std::nullopt;
    for (std::size_t i = 0; i < d.nops(); ++i) {
      const ex term = d.op(i);
      std::size_t held = 0;
      for (const ex& x : inverted) held += term.has(x) ? 1 : 0;
      if (held + 1 < inverted.size()) return std::nullopt;
    }
    ex product = 1;
    for (const ex& x : inverted) product *= x;
    return product;
  });
}

std::optional<ex> reciprocal_form(const ex& n, const ex& nd, const ex& best) {
  constexpr std::size_t min_nodes = 80;
  if (node_count(best, min_nodes) < min_nodes) return std::nullopt;
  const ex d = nd.op(1).expand();
  const std::optional<ex> product = reciprocal_denominator(d);
  if (!product || !is_polynomial_in_symbols(nd.op(0))) return std::nullopt;
  const ex over = pow(*product, -1);
  const ex num = (nd.op(0) * over).expand(), den = (d * over).expand();
  // The numerator's common monomial and integer content taken out (g, 524288 g).
  const ex r = content_only(num) / den;
  if (3 * node_count(r) >= 2 * node_count(best)) return std::nullopt;
  remember_normal(r, n);
  return r;
}

// The shortest form of n without rewriting by sin^2 + cos^2 = 1.
ex simplest_as_written(const ex& n, bool large) {
  const ex nd = numer_denom_of_normal(n);
  const ex num = factored(nd.op(0)), den = factored(nd.op(1));
  const auto held = evaluated_quotient(num, den);  // (see pairs.hpp)
  const ex best = shorter_form(held ? *held : num / den, n, large);
  if (const auto r = reciprocal_form(n, nd, best)) return *r;
  return best;
}

// sin^2 + cos^2 = 1: the shortest of the forms of n, of n with every power of a sine written
// in cosines, and the other way (and each of those back), each made as short as it goes; of
// two equally short, the first in text order. The forms are compared as they are printed, so
// that the choice does not depend on which of them the caller's n was, nor on the signs
// GiNaC's hash order gives a normal form (a double pendulum's acceleration reached as its
// sine form or its cosine form).
ex shortest_rewriting(const ex& n, bool large) {
  std::vector<ex> starts{n};
  auto add = [&](const ex& e) {
    if (std::none_of(starts.begin(), starts.end(), [&](const ex& s) { return s.is_equal(e); })) starts.push_back(e);
  };
  const ex c = normal(pythagoras(n, true)), s = normal(pythagoras(n, false));
  add(c);
  add(s);
  add(normal(pythagoras(c, false)));
  add(normal(pythagoras(s, true)));
  ex best;
  std::string best_text;
  for (const ex& start : starts) {
    const ex f = simplest_as_written(start, large);
    const std::string text = to_text(f);
    if (best_text.empty() || text.size() < best_text.size() || (text.size() == best_text.size() && text < best_text)) {
      best = f;
      best_text = text;
    }
  }
  return best;
}

ex simplest_uncached(const ex& e) {
  const ex n = normal_remembered(e);
  const bool large = node_count(n, 301) > 300;
  // (Only a power of a sin or a cos can be rewritten: a long response in cos(omega_d t) has none.)
  if (has_trig_power(n)) return shortest_rewriting(n, large);
  return simplest_as_written(n, large);
}

}  // namespace

// Remembered per thread like factored(): the solver, the conditions and the report ask for
// the same closed forms.
ex simplest(const ex& e) {
  auto& memory = thread_memory<struct simplest_memory, std::unordered_map<ex, ex, ExHash, ex_is_equal>>();
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  // Keyed by the normal form too: simplest(e) and simplest(normal(e)) are one form, made once.
  const ex n = normal_remembered(e);
  ex out;
  if (auto it = memory.find(n); it != memory.end())
    out = it->second;
  else
    out = simplest_uncached(n);
  if (memory.size() >= 4096) memory.clear();
  memory.emplace(e, out);
  memory.emplace(n, out);
  return out;
}

ex simplest_of_product(const ex& polynomial, const std::vector<ex>& parts) {
  const ex n = normal_remembered(polynomial);
  const ex nd = numer_denom_of_normal(n);
  if (!nd.op(1).is_equal(1) || has_trig_power(n)) return simplest(polynomial);
  // The number c with polynomial = c * (the parts' product), from one exact random point,
  // then checked exactly.
  ex product = 1;
  for (const ex& p : parts) product *= p;
  const ex expanded = product.expand();
  std::mt19937 rng(20261124);
  RationalPoint at;
  for (const auto& [sym, v] : random_point(lst{nd.op(0), expanded}, rng)) at.emplace(sym, ex_to<numeric>(v));
  const RationalAt whole = rational_at(nd.op(0), at), of_parts = rational_at(expanded, at);
  if (whole.kind != RationalAt::Kind::value || of_parts.kind != RationalAt::Kind::value || of_parts.value.is_zero())
    return simplest(polynomial);
  const numeric c = whole.value / of_parts.value;
  if (!(nd.op(0) - c * expanded).expand().is_zero()) return simplest(polynomial);
  ex f = c;
  for (const ex& p : parts) f *= factored(p);
  return shorter_form(f, n, node_count(n, 301) > 300);
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

Solution solve_equations(const std::string& file, const std::vector<Equation>& equations,
                         const std::vector<ex>& unknowns) {
  Solution sol;
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

  // Sparse elimination, Markowitz pivots first. When some unknown has no pivot, again with
  // the columns in order, so that the free unknowns are the ones a person reading the
  // unknowns in order would leave free; when some equation is left over, again with the
  // rows tracked, to say which equations it combines.
  // (With more equations than unknowns some are left over for certain: tracked at once.)
  Elimination e = eliminate(system, unknowns, Pivoting::markowitz, n_eq > n_unk);
  Pivoting pivoting = Pivoting::markowitz;
  if (e.rank < n_unk) {
    pivoting = Pivoting::in_column_order;
    e = eliminate(system, unknowns, pivoting, !e.leftover.empty());
  } else if (!e.leftover.empty() && n_eq <= n_unk) {
    e = eliminate(system, unknowns, pivoting, true);
  }
  sol.rank = e.rank;

  auto involved = [&](const Elimination::Leftover& l) {
    std::vector<std::string> labels;
    for (const std::size_t row : l.combination) labels.push_back(equations[row].label);
    return labels;
  };
  // Rows without a pivot: 0 = b. Nonzero b: the equations that combine to it conflict.
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
  if (sol.status == Solution::Status::inconsistent) return sol;

  for (std::size_t j = 0; j < n_unk; ++j)
    if (!e.pivot[j]) sol.free.push_back(unknowns[j]);
  if (!sol.free.empty()) sol.status = Solution::Status::underdetermined;

  exmap no_free;
  for (const auto& f : sol.free) no_free[f] = 0;
  for (std::size_t j = 0; j < n_unk; ++j) {
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

  // Verify: the general solution satisfies every equation at two random points of the
  // parameters and free unknowns (integers drawn from 2^40 values each, so a residual that
  // is not zero vanishes at one by chance with a probability of its degree over 2^40).
  // At a point, each unknown's value is evaluated once and put into every equation. Only when
  // no point can be used (a denominator vanishes at every one drawn) is every residual put in
  // normal form, which for a large solution is what would make this the slowest step.
  // The values hold no symbol the equations do not: the points are drawn for theirs.
  // Rational functions are first evaluated modulo the prime 2^61 - 1, in machine words (exact
  // rationals grew with every product: a chain's check was a tenth of its run); a residual
  // that is not 0 there is not 0. Anything else (sin(theta), a turning strand's square root)
  // is checked at exact points below.
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
  if (!modular) trial = 0;
  lst everything;  // the equations' symbols, for the exact points (only when not modular)
  if (!modular)
    for (const auto& eq : equations) everything.append(eq.lhs - eq.rhs);
  std::mt19937 rng(20261121);
  // A point where some denominator vanishes is drawn again (GiNaC would throw there, from
  // inside a node it is making; found by fuzzing). Rational functions are evaluated as
  // numbers; anything else (sin(theta), a turning strand's square root) by substitution.
  for (int draws = 0; !modular && trial < 2 && draws < 30; ++draws) {
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
    std::vector<ex> residuals;  // those that are not plain numbers, put in by substitution
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
  if (trial == 0)
    for (const auto& eq : equations) {
      const ex residual = substituted(eq.lhs - eq.rhs, sol.general);
      if (!zero(residual))
        throw InternalError("solution fails equation '" + eq.label + "': residual " + to_text(normal(residual)));
    }

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

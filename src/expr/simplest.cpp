// Signs, canonical factors and the simplest form of an expression (see simplest.hpp).
#include "expr/simplest.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "expr/memory.hpp"
#include "expr/pairs.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;

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

ex factored(const ex& polynomial) {
  auto& memory = thread_memory<struct polynomial_memory, ExMemory<ex>>();
  return remembered(memory, polynomial, 4096, [&] {
    ex out = 1;
    for (const ex& x : canonical_factors(polynomial)) out = times(out, x);
    return out;
  });
}

namespace {}  // namespace

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

}  // namespace tackle

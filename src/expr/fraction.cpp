#include "expr/fraction.hpp"
#include "expr/memory.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "expr/pairs.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// GiNaC's own object for a small integer (ex(int) hands it out for -12 ... 12), or `c`.
ex shared(const ex& c) {
  const numeric& n = ex_to<numeric>(c);
  // (Compared as a machine integer: n < -12 would make a number of -12 first.)
  if (!n.is_integer() || n.int_length() > 4) return c;
  const long v = n.to_long();
  if (v < -12 || v > 12) return c;
  const ex s(static_cast<int>(v));
  return are_ex_trivially_equal(s, c) ? c : s;
}

}  // namespace

namespace {

// Shares the numbers of the sums and products of e in place. A coefficient is replaced by a
// number of equal value, so nothing anyone holding the node can see changes: not its value,
// its order of pairs, its hash or its flags. (GiNaC's reference counts are not atomic: no
// expression is shared between threads, and tackle runs one.) A node met before is not walked
// again (a chain's closed forms share their denominator).
void share_in_place(const ex& e, std::unordered_set<const basic*>& seen) {
  if (!is_exactly<add>(e) && !is_exactly<mul>(e)) return;
  if (ex_to<basic>(e).get_refcount() > 1 && !seen.insert(&ex_to<basic>(e)).second) return;
  auto& seq = const_cast<epvector&>(Pairs::of(e));
  for (auto& p : seq) {
    share_in_place(p.rest, seen);
    const ex c = shared(p.coeff);
    if (!are_ex_trivially_equal(c, p.coeff)) p.coeff = c;
  }
}

}  // namespace

ex with_shared_numbers(const ex& e) {
  std::unordered_set<const basic*> seen;
  share_in_place(e, seen);
  return e;
}

bool linear_irreducible(const ex& p) {
  auto& memory = thread_memory<struct coprime_memory, ExMemory<bool>>();
  return remembered(memory, p, 1024, [&] { return linear_and_coprime(p); });
}

namespace {

// The total degree of an expanded polynomial (the highest of its terms' degrees), or -1 when
// it is not one (or an exponent is past a million: no decision from degrees then).
long total_degree(const ex& p) {
  auto of_monomial = [](const ex& t) -> long {
    if (is_exactly<numeric>(t)) return 0;
    if (is_exactly<symbol>(t)) return 1;
    auto power_of = [](const ex& base, const ex& expo) -> long {
      const numeric& k = ex_to<numeric>(expo);
      return is_exactly<symbol>(base) && k.is_pos_integer() && k <= 1000000 ? k.to_long() : -1;
    };
    if (is_exactly<power>(t)) return is_exactly<numeric>(t.op(1)) ? power_of(t.op(0), t.op(1)) : -1;
    if (!is_exactly<mul>(t)) return -1;
    long d = 0;
    for (const auto& f : Pairs::of(t)) {
      const long k = power_of(f.rest, f.coeff);
      if (k < 0) return -1;
      d += k;
    }
    return d;
  };
  if (!is_exactly<add>(p)) return of_monomial(p);
  long d = 0;
  for (const auto& t : Pairs::of(p)) {
    const long k = of_monomial(t.rest);
    if (k < 0) return -1;
    d = std::max(d, k);
  }
  return d;
}

}  // namespace

// At integers drawn from the other symbols' names, p is not zero at g's root in x: then g
// does not divide p. (divide() takes long to say no for a sum over 256 masses.) The symbol
// and the root are found once per g (a chain's values share one denominator); the values
// drawn by name are the same for g's coefficients and for p.
bool may_divide(const ex& p, const ex& g) {
  if (is_a<symbol>(g)) return p.ldegree(g) > 0 || p.is_zero();
  // By degree first: g (a sum) divides p only if p's total degree is at least g's, and when
  // the two are equal, only if p is a number times g, term for term (a chain's partial sums
  // of masses against the sum of all of them).
  auto& degrees = thread_memory<struct total_degree_memory, ExMemory<long>>();
  const long dg = remembered(degrees, g, 1024, [&] { return total_degree(g); });
  if (const long dp = total_degree(p); dp >= 0 && dg >= 0 && !p.is_zero()) {
    if (dp < dg) return false;
    if (dp == dg && is_exactly<add>(g) && (!is_exactly<add>(p) || p.nops() != g.nops())) return false;
  }
  constexpr std::uint64_t seed = 20261123;
  struct Root {
    ex x;
    std::uint64_t value;
  };
  auto& roots = thread_memory<struct root_memory, ExMemory<std::optional<Root>>>();
  const std::optional<Root> root = remembered(roots, g, 1024, [&]() -> std::optional<Root> {
    for (const ex& x : symbols_in(g)) {
      if (g.degree(x) != 1) continue;
      ModularPoint point(seed);
      const ModularAt a = modular_at(g.coeff(x, 1), point), b = modular_at(g.coeff(x, 0), point);
      if (a.kind == RationalAt::Kind::value && b.kind == RationalAt::Kind::value && a.value != 0)
        return Root{x, modular_quotient(modular_negated(b.value), a.value)};
      break;
    }
    return std::nullopt;
  });
  if (!root) return true;
  ModularPoint point(seed);
  point.values.emplace(root->x, root->value);
  const ModularAt at = modular_at(p, point);
  return at.kind != RationalAt::Kind::value || at.value == 0;
}

namespace {

using Factors = std::map<ex, int, ex_is_less>;  // irreducible factor -> positive exponent

// numerator / (product of factors^exponents), the numerator an expanded polynomial.
struct Fraction {
  ex num;
  Factors den;
};

// A factor GiNaC keeps as it is in a product, known to be irreducible: a symbol, or an
// expanded sum with integer coefficients without a common factor, the first one positive
// (how evaluation leaves a sum under the line), of degree 1 in a symbol with coprime
// coefficients.
bool irreducible_factor(const ex& b) {
  if (is_exactly<symbol>(b)) return true;
  return is_exactly<add>(b) && primitive_sum(b) && expanded_polynomial(b) && linear_irreducible(b);
}

ex expanded(const ex& p) { return expanded_polynomial(p) ? p : p.expand(); }

ex power_of(const Factors& f, int times) {
  exvector v;
  v.reserve(f.size());
  for (const auto& [g, k] : f) v.push_back(pow(g, k * times));
  return v.empty() ? ex(1) : ex(dynallocate<mul>(v));
}

std::optional<Fraction> as_fraction(const ex& e);

// 1 / (polynomial p): its factors read off GiNaC's evaluation of p^-1, which takes a sum's
// integer content out (and a monomial's factors apart); each must be an irreducible factor.
std::optional<Fraction> inverse_of_polynomial(const ex& p, int k) {
  if (p.is_zero()) return std::nullopt;
  const ex inv = pow(p, -k);
  Fraction out{1, {}};
  auto take = [&](const ex& base, const ex& expo) {
    if (is_exactly<numeric>(base)) {
      out.num = out.num * pow(base, expo);
      return true;
    }
    if (!is_exactly<numeric>(expo) || !ex_to<numeric>(expo).is_integer()) return false;
    const int n = ex_to<numeric>(expo).to_int();
    if (n > 0) return false;  // p was not expanded
    if (!irreducible_factor(base)) return false;
    out.den[base] += -n;
    return true;
  };
  if (is_exactly<numeric>(inv)) return Fraction{inv, {}};
  if (is_exactly<mul>(inv)) {
    for (const auto& f : Pairs::of(inv))
      if (!take(f.rest, f.coeff)) return std::nullopt;
    out.num = out.num * Pairs::overall(inv);
  } else if (is_exactly<power>(inv)) {
    if (!take(inv.op(0), inv.op(1))) return std::nullopt;
  } else {
    return std::nullopt;
  }
  if (!is_exactly<numeric>(out.num) || !ex_to<numeric>(out.num).is_rational()) return std::nullopt;
  return out;
}

std::optional<Fraction> sum_of(const std::vector<Fraction>& parts) {
  Factors lcm;
  for (const auto& f : parts)
    for (const auto& [g, k] : f.den) {
      auto [it, inserted] = lcm.emplace(g, k);
      if (!inserted) it->second = std::max(it->second, k);
    }
  exvector terms;
  terms.reserve(parts.size());
  for (const auto& f : parts) {
    if (f.num.is_zero()) continue;
    Factors missing;
    for (const auto& [g, k] : lcm) {
      const auto it = f.den.find(g);
      const int have = it == f.den.end() ? 0 : it->second;
      if (k > have) missing.emplace(g, k - have);
    }
    terms.push_back(missing.empty() ? f.num : f.num * power_of(missing, 1));
  }
  if (terms.empty()) return Fraction{0, {}};
  return Fraction{expanded(dynallocate<add>(terms)), std::move(lcm)};
}

std::optional<Fraction> product_of(const std::vector<Fraction>& parts) {
  Fraction out{1, {}};
  exvector nums;
  for (const auto& f : parts) {
    if (f.num.is_zero()) return Fraction{0, {}};
    nums.push_back(f.num);
    for (const auto& [g, k] : f.den) out.den[g] += k;
  }
  out.num = expanded(dynallocate<mul>(nums));
  return out;
}

std::optional<Fraction> as_fraction(const ex& e) {
  if (rational_polynomial(e)) return Fraction{expanded(e), {}};
  if (is_exactly<add>(e)) {
    std::vector<Fraction> parts;
    for (const auto& p : Pairs::of(e)) {
      auto f = as_fraction(p.rest);
      if (!f) return std::nullopt;
      f->num = expanded(f->num * p.coeff);
      parts.push_back(std::move(*f));
    }
    if (!Pairs::overall(e).is_zero()) parts.push_back({Pairs::overall(e), {}});
    return sum_of(parts);
  }
  auto power_part = [](const ex& base, const ex& expo) -> std::optional<Fraction> {
    if (!is_exactly<numeric>(expo) || !ex_to<numeric>(expo).is_integer()) return std::nullopt;
    const numeric& n = ex_to<numeric>(expo);
    if (n.int_length() > 20) return std::nullopt;
    const int k = n.to_int();
    auto b = as_fraction(base);
    if (!b) return std::nullopt;
    if (k >= 0) {
      Fraction out{expanded(pow(b->num, k)), {}};
      for (const auto& [g, j] : b->den) out.den.emplace(g, j * k);
      return out;
    }
    // (num/den)^-k = den^k / num^k: num^k's factors must be known.
    auto inv = inverse_of_polynomial(b->num, -k);
    if (!inv) return std::nullopt;
    inv->num = expanded(inv->num * power_of(b->den, -k));
    return inv;
  };
  if (is_exactly<mul>(e)) {
    std::vector<Fraction> parts;
    for (const auto& p : Pairs::of(e)) {
      auto f = power_part(p.rest, p.coeff);
      if (!f) return std::nullopt;
      parts.push_back(std::move(*f));
    }
    parts.push_back({Pairs::overall(e), {}});
    return product_of(parts);
  }
  if (is_exactly<power>(e)) return power_part(e.op(0), e.op(1));
  return std::nullopt;
}

// The least common multiple of the denominators of an expanded polynomial's coefficients.
numeric coefficient_denominators(const ex& p) {
  numeric l = 1;
  auto take = [&](const numeric& c) {
    if (!c.is_integer()) l = lcm(l, c.denom());
  };
  if (is_exactly<numeric>(p)) {
    take(ex_to<numeric>(p));
  } else if (is_exactly<add>(p)) {
    for (const auto& t : Pairs::of(p)) take(ex_to<numeric>(t.coeff));
    take(Pairs::overall(p));
  } else if (is_exactly<mul>(p)) {
    take(Pairs::overall(p));
  }
  return l;
}

}  // namespace

std::optional<ex> normal_by_factors(const ex& e) {
  auto f = as_fraction(e);
  if (!f) return std::nullopt;
  if (f->num.is_zero()) return ex(0);
  // Symbols under the line: each cancels as far as its lowest power in the numerator.
  bool symbols = false;
  for (const auto& [g, k] : f->den) symbols = symbols || is_exactly<symbol>(g);
  if (symbols) {
    const auto low = low_degrees(f->num);
    exvector out;
    for (auto& [g, k] : f->den) {
      if (!is_exactly<symbol>(g)) continue;
      const auto it = low.find(g);
      if (it == low.end()) continue;
      const int c = std::min(k, it->second);
      out.push_back(pow(g, -c));
      k -= c;
    }
    if (!out.empty()) {
      out.push_back(f->num);
      f->num = ex(dynallocate<mul>(out)).expand();
    }
  }
  // Sums under the line: divided out while they divide.
  for (auto& [g, k] : f->den) {
    if (is_exactly<symbol>(g)) continue;
    ex q;
    while (k > 0 && may_divide(f->num, g) && divide(f->num, g, q)) {
      f->num = expanded(q);
      --k;
    }
  }
  // As normal() leaves it: the numerator with integer coefficients, their least common
  // denominator under the line.
  const numeric l = coefficient_denominators(f->num);
  exvector den;
  for (const auto& [g, k] : f->den)
    if (k > 0) den.push_back(pow(g, k));
  den.push_back(l);
  const ex num = l == 1 ? f->num : (f->num * l).expand();
  return num / ex(dynallocate<mul>(den));
}

}  // namespace tackle

#include "expr/rational.hpp"
#include "expr/memory.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <cln/integer.h>
#include <cln/rational.h>

#include "core/kind.hpp"
#include "expr/pairs.hpp"
#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

using Memory = std::unordered_map<ex, ex, ExHash, ex_is_equal>;

}  // namespace

ex numer_denom_remembered(const ex& e) {
  auto& memory = thread_memory<struct normal_memory, Memory>();
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  // From the remembered normal form: the same numerator and denominator as numer_denom()
  // makes, and the closed forms' normal forms are usually made already.
  const ex nd = numer_denom_of_normal(normal_remembered(e));
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, nd);
  return nd;
}

Memory& normal_memory() { return thread_memory<struct fraction_memory, Memory>(); }

void remember_normal(const ex& e, const ex& n) {
  Memory& memory = normal_memory();
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, n);
  memory.emplace(n, n);
}

namespace {

// A product with sums over and under the line (a m (c - e)/2 over d (c - e)/l, sample 12.8's
// rod) with each sum written as its monomial content times what is left: GiNaC's evaluation
// then cancels a sum left over and under the line by itself (it keeps every sum in a product
// primitive, its first coefficient positive), and normal() has no gcd of sums to find (2 M
// instructions of the 16 M of that whole run). The same product when nothing cancels.
ex with_common_sums_cancelled(const ex& e) {
  if (!is_exactly<mul>(e)) return e;
  bool over = false, under = false;
  for (const auto& p : Pairs::of(e))
    if (is_exactly<add>(p.rest) && ex_to<numeric>(p.coeff).is_integer())
      (ex_to<numeric>(p.coeff).is_positive() ? over : under) = true;
  if (!over || !under) return e;
  std::size_t sums = 0;
  ex out = Pairs::overall(e);
  for (const auto& p : Pairs::of(e)) {
    const numeric& k = ex_to<numeric>(p.coeff);
    if (is_exactly<add>(p.rest) && k.is_integer()) {
      ++sums;
      if (expanded_polynomial(p.rest)) {
        const Content c = content_of(p.rest);
        out *= pow(c.content, k) * pow(c.rest, k);
        continue;
      }
    }
    out *= pow(p.rest, k);
  }
  std::size_t left = 0;
  if (is_exactly<mul>(out))
    for (const auto& p : Pairs::of(out)) left += is_exactly<add>(p.rest) ? 1 : 0;
  else if (is_exactly<add>(out) || is_exactly<power>(out))
    left = 1;
  return left < sums ? out : e;
}

}  // namespace

ex normal_remembered(const ex& e) {
  Memory& memory = normal_memory();
  if (is_a<numeric>(e) || is_a<symbol>(e)) return e;
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  const ex n = normal(with_common_sums_cancelled(e));
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, n);
  memory.emplace(n, n);
  return n;
}

ex numer_denom_of_normal(const ex& n) {
  ex num = 1, den = 1;
  auto take = [&](const ex& f) {
    if (is_a<numeric>(f)) {
      const numeric& c = ex_to<numeric>(f);
      if (c.is_rational()) {
        num = times(num, c.numer());
        den = times(den, c.denom());
        return;
      }
    } else if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_negative()) {
      den = times(den, pow(f.op(0), -f.op(1)));
      return;
    }
    num = times(num, f);
  };
  if (is_exactly<mul>(n)) {
    // By its pairs: op(i) would make each power of a sum again (see pairs.hpp).
    take(Pairs::overall(n));
    for (const auto& p : Pairs::of(n)) {
      const numeric& k = ex_to<numeric>(p.coeff);
      if (k.is_negative())
        den = times(den, pow(p.rest, -k));
      else
        num = times(num, k.is_equal(1) ? p.rest : pow(p.rest, k));
    }
  } else {
    take(n);
  }
  return lst{num, den};
}

namespace {

// rational_at in CLN's rationals: one number object per node instead of a GiNaC numeric
// (each a new heap object with its own hash), and classes told apart by their class-info
// address (is_a<> is a dynamic_cast that compares type names across libraries).
// `value_of(symbol)` is the symbol's number, or null.
template <class ValueOf, class Sums>
RationalAt::Kind rational_in(const ex& e, const ValueOf& value_of, cln::cl_RA& out, const Sums& sums);

// b^x for an integer x; a pole for 0 to a negative power.
RationalAt::Kind power_in(const cln::cl_RA& b, const numeric& exponent, cln::cl_RA& out) {
  const cln::cl_I x = cln::the<cln::cl_I>(exponent.to_cl_N());
  if (cln::zerop(b) && cln::minusp(x)) return RationalAt::Kind::pole;
  out = cln::expt(b, x);
  return RationalAt::Kind::value;
}

// No memory of sums' values (see SumValues).
struct NoSums {
  const numeric* find(const ex&) const { return nullptr; }
  void remember(const ex&, const cln::cl_RA&) const {}
};

// Long sums' values looked up in and added to a SumValues (its mutex held by the caller).
struct SumMemory {
  SumValues& sums;
  static bool long_sum(const ex& e) { return Pairs::of(e).size() > long_sum_terms; }
  const numeric* find(const ex& e) const {
    if (!long_sum(e)) return nullptr;
    const auto it = sums.values.find(e);
    return it == sums.values.end() ? nullptr : &it->second;
  }
  void remember(const ex& e, const cln::cl_RA& v) const {
    if (!long_sum(e)) return;
    if (sums.values.size() >= 16384) sums.values.clear();  // forgets everything past its limit
    sums.values.emplace(e, numeric(v));
  }
};

template <class ValueOf, class Sums>
RationalAt::Kind rational_in(const ex& e, const ValueOf& value_of, cln::cl_RA& out, const Sums& sums) {
  using Kind = RationalAt::Kind;
  if (is_exactly<numeric>(e) || is_exactly<symbol>(e)) {
    const numeric* c = is_exactly<numeric>(e) ? &ex_to<numeric>(e) : value_of(e);
    if (!c || !c->is_rational()) return Kind::other;
    out = cln::the<cln::cl_RA>(c->to_cl_N());
    return Kind::value;
  }
  const bool sum = is_exactly<add>(e);
  if (sum)
    if (const numeric* known = sums.find(e)) {
      out = cln::the<cln::cl_RA>(known->to_cl_N());
      return Kind::value;
    }
  if (sum || is_exactly<mul>(e)) {
    // By the stored pairs (see pairs.hpp): a term rest*coeff, a factor rest^coeff.
    const numeric& overall = Pairs::overall(e);
    if (!overall.is_rational()) return Kind::other;
    cln::cl_RA acc = cln::the<cln::cl_RA>(overall.to_cl_N()), t, f;
    for (const auto& p : Pairs::of(e)) {
      const numeric& k = ex_to<numeric>(p.coeff);
      if (sum ? !k.is_rational() : !k.is_integer()) return Kind::other;
      if (const Kind r = rational_in(p.rest, value_of, t, sums); r != Kind::value) return r;
      if (sum) {
        acc = acc + t * cln::the<cln::cl_RA>(k.to_cl_N());
      } else {
        if (const Kind r = power_in(t, k, f); r != Kind::value) return r;
        acc = acc * f;
      }
    }
    out = acc;
    if (sum) sums.remember(e, acc);
    return Kind::value;
  }
  if (is_exactly<power>(e) && is_exactly<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    cln::cl_RA b;
    if (const Kind k = rational_in(e.op(0), value_of, b, sums); k != Kind::value) return k;
    return power_in(b, ex_to<numeric>(e.op(1)), out);
  }
  return Kind::other;
}

}  // namespace

namespace {

template <class ValueOf, class Sums = NoSums>
RationalAt rational_at_with(const ex& e, const ValueOf& value_of, const Sums& sums = {}) {
  cln::cl_RA v;
  const RationalAt::Kind k = rational_in(e, value_of, v, sums);
  if (k == RationalAt::Kind::value) return {k, numeric(v)};
  return {k, 0};
}

}  // namespace

// A symbol's number in a point, or null.
struct InPoint {
  const RationalPoint& point;
  const numeric* operator()(const ex& x) const {
    const auto it = point.find(x);
    return it == point.end() ? nullptr : &it->second;
  }
};

RationalAt rational_at(const ex& e, const RationalPoint& point) { return rational_at_with(e, InPoint{point}); }

RationalAt rational_at(const ex& e, const RationalPoint& point, SumValues& sums) {
  const std::lock_guard<std::mutex> lock(sums.mutex);
  return rational_at_with(e, InPoint{point}, SumMemory{sums});
}

// A symbol's number in a substitution map, or null (also when its value is not a number).
struct InMap {
  const exmap& values;
  const numeric* operator()(const ex& x) const {
    const auto it = values.find(x);
    return it == values.end() || !is_exactly<numeric>(it->second) ? nullptr : &ex_to<numeric>(it->second);
  }
};

RationalAt rational_at(const ex& e, const exmap& values) { return rational_at_with(e, InMap{values}); }

numeric drawn_value(const std::string& name, std::uint64_t seed) {
  // FNV-1a of the name, mixed with the seed by splitmix64's finalizer.
  std::uint64_t h = 14695981039346656037ULL;
  for (const unsigned char c : name) h = (h ^ c) * 1099511628211ULL;
  h ^= seed + 0x9e3779b97f4a7c15ULL;
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
  h ^= h >> 31;
  return numeric(static_cast<long>(1 + (h & ((std::uint64_t{1} << 40) - 1))));
}

namespace {

using u64 = std::uint64_t;
constexpr u64 P = ModularPoint::prime;

u64 mod_mul(u64 a, u64 b) {
  const unsigned __int128 x = static_cast<unsigned __int128>(a) * b;
  u64 r = static_cast<u64>(x & P) + static_cast<u64>(x >> 61);
  return r >= P ? r - P : r;
}
u64 mod_add(u64 a, u64 b) {
  const u64 r = a + b;
  return r >= P ? r - P : r;
}
u64 mod_pow(u64 b, u64 k) {
  u64 r = 1;
  for (; k; k >>= 1, b = mod_mul(b, b))
    if (k & 1) r = mod_mul(r, b);
  return r;
}
u64 mod_inverse(u64 a) { return mod_pow(a, P - 2); }

// An integer modulo the prime: in machine integers when it fits in 64 bits (the prime itself
// is past CLN's fixnums, so each cln::mod made it on the heap: a tenth of a chain's run went
// to the modular checks).
u64 mod_of(const cln::cl_I& x) {
  if (cln::integer_length(x) < 63) {
    const std::int64_t r = cln::cl_I_to_Q(x) % static_cast<std::int64_t>(P);
    return static_cast<u64>(r < 0 ? r + static_cast<std::int64_t>(P) : r);
  }
  return cln::cl_I_to_UQ(cln::mod(x, cln::cl_I(P)));
}

// A rational number modulo the prime.
ModularAt number_mod(const numeric& c) {
  using Kind = RationalAt::Kind;
  if (c.is_integer()) return {Kind::value, mod_of(cln::the<cln::cl_I>(c.to_cl_N()))};
  if (!c.is_rational()) return {};
  const cln::cl_RA r = cln::the<cln::cl_RA>(c.to_cl_N());
  const u64 d = mod_of(cln::denominator(r));
  if (d == 0) return {Kind::pole, 0};
  return {Kind::value, mod_mul(mod_of(cln::numerator(r)), mod_inverse(d))};
}

// b^x for an integer x modulo the prime; a pole for 0 to a negative power.
ModularAt power_mod(u64 b, const numeric& exponent) {
  using Kind = RationalAt::Kind;
  const cln::cl_I x = cln::the<cln::cl_I>(exponent.to_cl_N());
  if (b == 0) {
    if (cln::minusp(x)) return {Kind::pole, 0};
    return {Kind::value, cln::zerop(x) ? u64{1} : u64{0}};
  }
  // b^(p-1) = 1 for b != 0: the exponent counts modulo p - 1 (in machine integers when it
  // fits, as in mod_of).
  const u64 k = cln::integer_length(x) < 63 ? static_cast<u64>(std::llabs(cln::cl_I_to_Q(x))) % (P - 1)
                                            : cln::cl_I_to_UQ(cln::mod(cln::abs(x), cln::cl_I(P - 1)));
  const u64 v = mod_pow(b, k);
  return {Kind::value, cln::minusp(x) ? mod_inverse(v) : v};
}

ModularAt modular_in(const ex& e, ModularPoint& point) {
  using Kind = RationalAt::Kind;
  if (is_exactly<numeric>(e)) return number_mod(ex_to<numeric>(e));
  if (is_exactly<symbol>(e)) {
    auto it = point.values.find(e);
    if (it == point.values.end()) {
      const numeric v = drawn_value(ex_to<symbol>(e).get_name(), point.seed);
      it = point.values.emplace(e, static_cast<u64>(v.to_long())).first;
    }
    return {Kind::value, it->second};
  }
  const bool sum = is_exactly<add>(e);
  if (sum || is_exactly<mul>(e)) {
    const auto& pairs = Pairs::of(e);
    const bool long_sum = sum && pairs.size() >= 8;
    const basic* node = &ex_to<basic>(e);
    if (long_sum)
      if (const auto it = point.sums.find(node); it != point.sums.end()) return {Kind::value, it->second.second};
    // By the stored pairs (see pairs.hpp): a term rest*coeff, a factor rest^coeff.
    ModularAt acc = number_mod(Pairs::overall(e));
    if (acc.kind != Kind::value) return acc;
    for (const auto& p : pairs) {
      const ModularAt t = modular_in(p.rest, point);
      if (t.kind != Kind::value) return t;
      const numeric& k = ex_to<numeric>(p.coeff);
      if (sum) {
        const ModularAt c = number_mod(k);
        if (c.kind != Kind::value) return c;
        acc.value = mod_add(acc.value, mod_mul(c.value, t.value));
      } else {
        if (!k.is_integer()) return {};
        const ModularAt f = power_mod(t.value, k);
        if (f.kind != Kind::value) return f;
        acc.value = mod_mul(acc.value, f.value);
      }
    }
    if (long_sum) point.sums.emplace(node, std::make_pair(e, acc.value));
    return acc;
  }
  if (is_exactly<power>(e) && is_exactly<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    const ModularAt b = modular_in(e.op(0), point);
    if (b.kind != Kind::value) return b;
    return power_mod(b.value, ex_to<numeric>(e.op(1)));
  }
  return {};
}

}  // namespace

ModularAt modular_at(const ex& e, ModularPoint& point) { return modular_in(e, point); }
std::uint64_t modular_negated(std::uint64_t a) { return a == 0 ? 0 : P - a; }
std::uint64_t modular_quotient(std::uint64_t a, std::uint64_t b) { return mod_mul(a, mod_inverse(b)); }

namespace {

// The distinct symbols of `e` in the order first met, walked by op() (GiNaC's preorder
// iterator keeps a stack of copies and was a tenth of a chain's run); each symbol is
// remembered by its hash, so a sum over 256 masses met again costs no comparisons of names.
// Only the symbols `keep` says yes to are gathered.
template <class Keep>
void gather_symbols(const ex& e, std::unordered_set<ex, ExHash, ex_is_equal>& seen, std::vector<ex>& out,
                    const Keep& keep) {
  if (is_exactly<symbol>(e)) {
    if (keep(e) && seen.insert(e).second) out.push_back(e);
    return;
  }
  if (is_exactly<numeric>(e)) return;
  if (is_exactly<add>(e) || is_exactly<mul>(e)) {
    for (const auto& p : Pairs::of(e)) gather_symbols(p.rest, seen, out, keep);  // the coefficients are numbers
    return;
  }
  const std::size_t n = e.nops();
  for (std::size_t i = 0; i < n; ++i) gather_symbols(e.op(i), seen, out, keep);
}

// The nodes as op() would make them, counted from the pairs (see pairs.hpp): a term
// rest*c (c != 1) is a product of rest's factors and c, or of rest and c; a factor rest^c
// (c != 1) a power of rest and c; the numeric term or coefficient one node more.
void count_nodes(const ex& e, std::size_t limit, std::size_t& n) {
  if (++n >= limit) return;
  const bool sum = is_exactly<add>(e);
  if (sum || is_exactly<mul>(e)) {
    for (const auto& p : Pairs::of(e)) {
      if (n >= limit) return;
      if (ex_to<numeric>(p.coeff).is_equal(1)) {
        count_nodes(p.rest, limit, n);
      } else if (sum && is_exactly<mul>(p.rest)) {
        count_nodes(p.rest, limit, n);
        n = std::min(limit, n + 1);
      } else {
        n = std::min(limit, n + 1);
        if (n < limit) count_nodes(p.rest, limit, n);
        n = std::min(limit, n + 1);
      }
    }
    if (!Pairs::overall(e).is_equal(sum ? 0 : 1)) n = std::min(limit, n + 1);
    return;
  }
  const std::size_t k = e.nops();
  for (std::size_t i = 0; i < k && n < limit; ++i) count_nodes(e.op(i), limit, n);
}

}  // namespace

std::vector<ex> distinct_symbols(const ex& e) {
  std::unordered_set<ex, ExHash, ex_is_equal> seen;
  std::vector<ex> out;
  gather_symbols(e, seen, out, [](const ex&) { return true; });
  return out;
}

std::vector<ex> distinct_symbols_among(const ex& e, const std::unordered_set<ex, ExHash, ex_is_equal>& among) {
  std::unordered_set<ex, ExHash, ex_is_equal> seen;
  std::vector<ex> out;
  if (!among.empty()) gather_symbols(e, seen, out, [&](const ex& x) { return among.count(x) > 0; });
  return out;
}

// Values are drawn for the symbols in the order of their names, not in the order GiNaC
// keeps them, so the points are the same in every run.
exmap random_point(const ex& e, std::mt19937& rng) {
  std::map<std::string, ex> by_name;
  for (const ex& s : distinct_symbols(e)) by_name.emplace(ex_to<symbol>(s).get_name(), s);
  // Integers up to 2^40: as good as rationals for telling a nonzero rational function from
  // zero (the chance of a root is its degree over 2^40), and sums of them need no gcd.
  exmap m;
  std::uniform_int_distribution<long> value(1, 1L << 40);
  for (const auto& [name, sym] : by_name) m[sym] = numeric(value(rng));
  return m;
}

std::set<ex, ex_is_less> symbols_in(const ex& e) {
  const std::vector<ex> v = distinct_symbols(e);
  return std::set<ex, ex_is_less>(v.begin(), v.end());
}

ex substituted(const ex& e, const exmap& m) {
  if (m.empty()) return e;
  // What GiNaC's subschildren() would find by looking through the map at every sum and
  // product: whether a key is a product or a power (then pairs are recombined to find it).
  bool product = false;
  for (const auto& [k, v] : m) product = product || is_exactly<mul>(k) || is_exactly<power>(k);
  return e.subs(m, subs_options::no_pattern |
                       (product ? subs_options::pattern_is_product : subs_options::pattern_is_not_product));
}

bool is_polynomial_in_symbols(const ex& e) {
  if (is_exactly<symbol>(e) || is_exactly<numeric>(e)) return true;
  if (is_exactly<power>(e)) return e.op(1).info(info_flags::nonnegint) && is_polynomial_in_symbols(e.op(0));
  if (!is_exactly<add>(e) && !is_exactly<mul>(e)) return false;
  const std::size_t n = e.nops();
  for (std::size_t i = 0; i < n; ++i)
    if (!is_polynomial_in_symbols(e.op(i))) return false;
  return true;
}

bool contains(const std::vector<ex>& v, const ex& x) {
  return std::any_of(v.begin(), v.end(), [&](const ex& y) { return y.is_equal(x); });
}

std::size_t node_count(const ex& e, std::size_t limit) {
  std::size_t n = 0;
  if (limit > 0) count_nodes(e, limit, n);
  return n;
}

namespace {

// The whole powers of the symbols in one term of an expanded polynomial, added to `p`; a
// product by its stored pairs (a term's number has no symbol in it).
template <class Powers>
void add_symbol_powers(const ex& term, Powers& p) {
  auto one = [&](const ex& base, const ex& expo) {
    if (is_exactly<symbol>(base) && expo.info(info_flags::nonnegint)) p[base] += ex_to<numeric>(expo).to_int();
  };
  if (is_exactly<mul>(term))
    for (const auto& f : Pairs::of(term)) one(f.rest, f.coeff);
  else if (is_exactly<power>(term))
    one(term.op(0), term.op(1));
  else
    one(term, 1);
}

// `low` keeps only the symbols also in `p`, each at the lesser of its two powers.
template <class Low, class Powers>
void keep_least(Low& low, const Powers& p) {
  for (auto it = low.begin(); it != low.end();) {
    const auto q = p.find(it->first);
    if (q == p.end()) {
      it = low.erase(it);
    } else {
      it->second = std::min(it->second, q->second);
      ++it;
    }
  }
}

Degrees degrees_of_uncached(const ex& expanded) {
  // One pass over the terms with the symbols kept by hash (a map per term, ordered by
  // ex_is_less, was most of the time of factoring a chain's closed forms); ordered at the end.
  using Powers = std::unordered_map<ex, int, ExHash, ex_is_equal>;
  auto powers = [&](const ex& term, Powers& p) {
    p.clear();
    add_symbol_powers(term, p);
  };
  Powers high, low, p;
  bool first = true;
  auto take = [&](const ex& term) {
    powers(term, p);
    for (const auto& [x, k] : p) {
      auto [it, inserted] = high.emplace(x, k);
      if (!inserted) it->second = std::max(it->second, k);
    }
    if (first) {
      low = p;
      first = false;
      return;
    }
    keep_least(low, p);
  };
  if (is_exactly<add>(expanded)) {
    for (const auto& t : Pairs::of(expanded)) take(t.rest);
    if (!Pairs::overall(expanded).is_zero()) take(Pairs::overall(expanded));  // a term without symbols
  } else {
    take(expanded);
  }
  Degrees d;
  d.high.insert(high.begin(), high.end());
  d.low.insert(low.begin(), low.end());
  return d;
}

}  // namespace

std::map<ex, int, ex_is_less> low_degrees(const ex& expanded) {
  std::map<ex, int, ex_is_less> low;
  // The power of a symbol in a term (0 when it is not there or not to a whole power).
  auto degree_in = [](const ex& term, const ex& x) -> int {
    auto one = [&](const ex& base, const ex& expo) {
      return is_exactly<symbol>(base) && base.is_equal(x) && expo.info(info_flags::nonnegint)
                 ? ex_to<numeric>(expo).to_int()
                 : 0;
    };
    if (is_exactly<mul>(term)) {
      for (const auto& f : Pairs::of(term))
        if (const int k = one(f.rest, f.coeff); k != 0) return k;
      return 0;
    }
    if (is_exactly<power>(term)) return one(term.op(0), term.op(1));
    return one(term, 1);
  };
  if (!is_exactly<add>(expanded)) {
    add_symbol_powers(expanded, low);
    return low;
  }
  if (!Pairs::overall(expanded).is_zero()) return low;  // a term without symbols
  bool first = true;
  for (const auto& t : Pairs::of(expanded)) {
    if (first) {
      add_symbol_powers(t.rest, low);
      first = false;
      continue;
    }
    for (auto it = low.begin(); it != low.end();) {
      const int k = degree_in(t.rest, it->first);
      if (k == 0) {
        it = low.erase(it);
      } else {
        it->second = std::min(it->second, k);
        ++it;
      }
    }
    if (low.empty()) break;
  }
  return low;
}

Content content_of(const ex& expanded) {
  const numeric c = expanded.integer_content();
  const auto low = low_degrees(expanded);
  ex monomial = c;
  for (const auto& [x, k] : low) monomial *= pow(x, k);
  // Nothing to take out: the polynomial itself (the term-by-term walk below would make it
  // again).
  if (c.is_equal(1) && low.empty() && expanded_polynomial(expanded)) return {monomial, expanded};
  if (!is_exactly<add>(expanded) || !expanded_polynomial(expanded) || c.is_zero())
    return {monomial, (expanded / monomial).expand()};
  // A term rest*coeff over the content: rest with each common symbol's power lowered (a
  // term that is one symbol or one power holds the one common symbol there can be), coeff/c.
  auto lowered = [&](const ex& rest) -> ex {
    if (low.empty()) return rest;
    if (!is_exactly<mul>(rest)) return rest * pow(low.begin()->first, -low.begin()->second);
    epvector factors;
    factors.reserve(Pairs::of(rest).size());
    for (const auto& f : Pairs::of(rest)) {
      const auto it = low.find(f.rest);
      if (it == low.end()) {
        factors.push_back(f);
        continue;
      }
      const numeric left = ex_to<numeric>(f.coeff) - it->second;
      if (!left.is_zero()) factors.emplace_back(f.rest, left);
    }
    return dynallocate<mul>(std::move(factors), Pairs::overall(rest));
  };
  epvector terms;
  terms.reserve(Pairs::of(expanded).size());
  numeric overall = Pairs::overall(expanded) / c;
  for (const auto& t : Pairs::of(expanded)) {
    const ex r = lowered(t.rest);
    const numeric coeff = ex_to<numeric>(t.coeff) / c;
    if (is_exactly<numeric>(r))
      overall += coeff * ex_to<numeric>(r);
    else
      terms.emplace_back(r, coeff);
  }
  return {monomial, dynallocate<add>(std::move(terms), overall)};
}

std::optional<Content> content_of_product(const ex& p, std::size_t min_terms) {
  if (!is_exactly<mul>(p)) return std::nullopt;
  const numeric& k = Pairs::overall(p);
  if (!k.is_integer()) return std::nullopt;
  ex sum;
  ex monomial = abs(k);
  for (const auto& f : Pairs::of(p)) {
    const numeric& e = ex_to<numeric>(f.coeff);
    if (is_exactly<add>(f.rest) && e.is_equal(1) && sum.is_zero()) {
      sum = f.rest;
    } else if (is_exactly<symbol>(f.rest) && e.is_pos_integer()) {
      monomial *= pow(f.rest, e);
    } else {
      return std::nullopt;
    }
  }
  if (sum.is_zero() || sum.nops() <= min_terms || !expanded_polynomial(sum) || !primitive_sum(sum) ||
      !low_degrees(sum).empty())
    return std::nullopt;
  return Content{monomial, k.is_negative() ? ex(-sum) : sum};
}

ex common_monomial(const std::vector<ex>& terms) {
  std::map<ex, int, ex_is_less> low;
  bool first = true;
  for (const ex& t : terms) {
    if (t.is_zero()) continue;
    std::map<ex, int, ex_is_less> p;
    add_symbol_powers(t, p);
    if (first) {
      low = std::move(p);
      first = false;
    } else {
      keep_least(low, p);
    }
    std::erase_if(low, [](const auto& x) { return x.second == 0; });
    if (low.empty()) return 1;
  }
  ex out = 1;
  for (const auto& [x, k] : low) out *= pow(x, k);
  return out;
}

// Remembered per thread (the last 1024 polynomials): a chain's closed forms share one
// denominator, and a numerator's degrees are asked for by each step of its factoring.
Degrees degrees_of(const ex& expanded) {
  auto& memory = thread_memory<struct degrees_memory, ExMemory<Degrees>>();
  return remembered(memory, expanded, 1024, [&] { return degrees_of_uncached(expanded); });
}

bool linear_and_coprime(const ex& expanded) {
  if (!is_a<add>(expanded)) return false;
  const Degrees d = degrees_of(expanded);
  for (const auto& [x, high] : d.high) {
    if (high != 1 || d.low.count(x) != 0) continue;
    const ex a = expanded.coeff(x, 1), b = expanded.coeff(x, 0);
    if (!b.is_zero() && is_a<numeric>(gcd(a, b))) return true;
  }
  return false;
}

std::optional<bool> zero_at_random_points(const ex& e, const std::vector<const exmap*>& substitutions) {
  int done = 0;
  for (std::uint64_t draw = 0; done < 2 && draw < 30; ++draw) {
    ModularPoint point(20261123 + draw);
    bool pole = false;
    // Later substitutions are made in the result of earlier ones: evaluate the last first.
    for (auto s = substitutions.rbegin(); !pole && s != substitutions.rend(); ++s)
      for (const auto& [u, v] : **s) {
        const ModularAt r = modular_at(v, point);
        if (r.kind == RationalAt::Kind::other) return std::nullopt;
        if (r.kind == RationalAt::Kind::pole) {
          pole = true;
          break;
        }
        point.assign(u, r.value);
      }
    if (pole) continue;
    const ModularAt r = modular_at(e, point);
    if (r.kind == RationalAt::Kind::other) return std::nullopt;
    if (r.kind == RationalAt::Kind::pole) continue;
    if (r.value != 0) return false;
    ++done;
  }
  if (done < 2) return std::nullopt;
  return true;
}

bool is_zero_exactly(const ex& e) {
  const ex n = normal_remembered(e);
  return n.is_zero() || (has_trig(n) && normal(pythagoras(n, true)).is_zero());
}

}  // namespace tackle

#include "expr/rational.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <cln/integer.h>
#include <cln/rational.h>

#include "expr/kind.hpp"
#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

using Memory = std::unordered_map<ex, ex, ExHash, ex_is_equal>;

}  // namespace

ex numer_denom_remembered(const ex& e) {
  thread_local Memory memory;
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  // From the remembered normal form: the same numerator and denominator as numer_denom()
  // makes, and the closed forms' normal forms are usually made already.
  const ex nd = numer_denom_of_normal(normal_remembered(e));
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, nd);
  return nd;
}

Memory& normal_memory() {
  thread_local Memory memory;
  return memory;
}

void remember_normal(const ex& e, const ex& n) {
  Memory& memory = normal_memory();
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, n);
  memory.emplace(n, n);
}

ex normal_remembered(const ex& e) {
  Memory& memory = normal_memory();
  if (is_a<numeric>(e) || is_a<symbol>(e)) return e;
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  const ex n = normal(e);
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
        num *= c.numer();
        den *= c.denom();
        return;
      }
    } else if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_negative()) {
      den *= pow(f.op(0), -f.op(1));
      return;
    }
    num *= f;
  };
  if (is_a<mul>(n))
    for (std::size_t i = 0; i < n.nops(); ++i) take(n.op(i));
  else
    take(n);
  return lst{num, den};
}

namespace {

// rational_at in CLN's rationals: one number object per node instead of a GiNaC numeric
// (each a new heap object with its own hash), and classes told apart by their class-info
// address (is_a<> is a dynamic_cast that compares type names across libraries).
RationalAt::Kind rational_in(const ex& e, const RationalPoint& point, cln::cl_RA& out) {
  using Kind = RationalAt::Kind;
  if (is_exactly<numeric>(e)) {
    const numeric& c = ex_to<numeric>(e);
    if (!c.is_rational()) return Kind::other;
    out = cln::the<cln::cl_RA>(c.to_cl_N());
    return Kind::value;
  }
  if (is_exactly<symbol>(e)) {
    const auto it = point.find(e);
    if (it == point.end() || !it->second.is_rational()) return Kind::other;
    out = cln::the<cln::cl_RA>(it->second.to_cl_N());
    return Kind::value;
  }
  const bool sum = is_exactly<add>(e);
  if (sum || is_exactly<mul>(e)) {
    cln::cl_RA acc = sum ? 0 : 1, t;
    const std::size_t n = e.nops();
    for (std::size_t i = 0; i < n; ++i) {
      const Kind k = rational_in(e.op(i), point, t);
      if (k != Kind::value) return k;
      acc = sum ? acc + t : acc * t;
    }
    out = acc;
    return Kind::value;
  }
  if (is_exactly<power>(e) && is_exactly<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    cln::cl_RA b;
    const Kind k = rational_in(e.op(0), point, b);
    if (k != Kind::value) return k;
    const cln::cl_I x = cln::the<cln::cl_I>(ex_to<numeric>(e.op(1)).to_cl_N());
    if (cln::zerop(b) && cln::minusp(x)) return Kind::pole;
    out = cln::expt(b, x);
    return Kind::value;
  }
  return Kind::other;
}

}  // namespace

RationalAt rational_at(const ex& e, const RationalPoint& point) {
  cln::cl_RA v;
  const RationalAt::Kind k = rational_in(e, point, v);
  if (k == RationalAt::Kind::value) return {k, numeric(v)};
  return {k, 0};
}

namespace {

// The distinct symbols of `e` in the order first met, walked by op() (GiNaC's preorder
// iterator keeps a stack of copies and was a tenth of a chain's run); each symbol is
// remembered by its hash, so a sum over 256 masses met again costs no comparisons of names.
void gather_symbols(const ex& e, std::unordered_set<ex, ExHash, ex_is_equal>& seen, std::vector<ex>& out) {
  if (is_exactly<symbol>(e)) {
    if (seen.insert(e).second) out.push_back(e);
    return;
  }
  if (is_exactly<numeric>(e)) return;
  const std::size_t n = e.nops();
  for (std::size_t i = 0; i < n; ++i) gather_symbols(e.op(i), seen, out);
}

std::vector<ex> distinct_symbols(const ex& e) {
  std::unordered_set<ex, ExHash, ex_is_equal> seen;
  std::vector<ex> out;
  gather_symbols(e, seen, out);
  return out;
}

void count_nodes(const ex& e, std::size_t limit, std::size_t& n) {
  if (++n >= limit) return;
  const std::size_t k = e.nops();
  for (std::size_t i = 0; i < k && n < limit; ++i) count_nodes(e.op(i), limit, n);
}

}  // namespace

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

bool contains(const std::vector<ex>& v, const ex& x) {
  return std::any_of(v.begin(), v.end(), [&](const ex& y) { return y.is_equal(x); });
}

std::size_t node_count(const ex& e, std::size_t limit) {
  std::size_t n = 0;
  if (limit > 0) count_nodes(e, limit, n);
  return n;
}

Degrees degrees_of(const ex& expanded) {
  Degrees d;
  auto powers = [](const ex& term) {
    std::map<ex, int, ex_is_less> p;
    auto one = [&](const ex& f) {
      if (is_a<symbol>(f)) p[f] += 1;
      else if (is_a<power>(f) && is_a<symbol>(f.op(0)) && f.op(1).info(info_flags::nonnegint))
        p[f.op(0)] += ex_to<numeric>(f.op(1)).to_int();
    };
    if (is_a<mul>(term))
      for (std::size_t i = 0; i < term.nops(); ++i) one(term.op(i));
    else
      one(term);
    return p;
  };
  const bool sum = is_a<add>(expanded);
  const std::size_t n = sum ? expanded.nops() : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const auto p = powers(sum ? expanded.op(i) : expanded);
    for (const auto& [s, k] : p) d.high[s] = std::max(d.high[s], k);
    if (i == 0) {
      d.low = p;
    } else {
      for (auto it = d.low.begin(); it != d.low.end();) {
        const auto q = p.find(it->first);
        if (q == p.end()) {
          it = d.low.erase(it);
        } else {
          it->second = std::min(it->second, q->second);
          ++it;
        }
      }
    }
  }
  return d;
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
  lst everything{e};
  for (const exmap* s : substitutions)
    for (const auto& [u, v] : *s) everything.append(v);
  std::mt19937 rng(20261123);
  int done = 0;
  for (int draws = 0; done < 2 && draws < 30; ++draws) {
    RationalPoint numbers;
    for (const auto& [sym, v] : random_point(everything, rng)) numbers.emplace(sym, ex_to<numeric>(v));
    bool pole = false;
    // Later substitutions are made in the result of earlier ones: evaluate the last first.
    for (auto s = substitutions.rbegin(); !pole && s != substitutions.rend(); ++s)
      for (const auto& [u, v] : **s) {
        const RationalAt r = rational_at(v, numbers);
        if (r.kind == RationalAt::Kind::other) return std::nullopt;
        if (r.kind == RationalAt::Kind::pole) {
          pole = true;
          break;
        }
        numbers.insert_or_assign(u, r.value);
      }
    if (pole) continue;
    const RationalAt r = rational_at(e, numbers);
    if (r.kind == RationalAt::Kind::other) return std::nullopt;
    if (r.kind == RationalAt::Kind::pole) continue;
    if (!r.value.is_zero()) return false;
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

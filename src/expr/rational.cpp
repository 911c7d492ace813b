#include "expr/rational.hpp"

#include <map>
#include <string>
#include <unordered_map>

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

RationalAt rational_at(const ex& e, const RationalPoint& point) {
  using Kind = RationalAt::Kind;
  if (is_a<numeric>(e)) {
    const numeric& c = ex_to<numeric>(e);
    return c.is_rational() ? RationalAt{Kind::value, c} : RationalAt{};
  }
  if (is_a<symbol>(e)) {
    const auto it = point.find(e);
    return it == point.end() ? RationalAt{} : RationalAt{Kind::value, it->second};
  }
  if (is_a<add>(e) || is_a<mul>(e)) {
    const bool sum = is_a<add>(e);
    numeric acc = sum ? 0 : 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const RationalAt t = rational_at(e.op(i), point);
      if (t.kind != Kind::value) return t;
      acc = sum ? acc + t.value : acc * t.value;
    }
    return {Kind::value, acc};
  }
  if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    const RationalAt b = rational_at(e.op(0), point);
    if (b.kind != Kind::value) return b;
    const numeric& x = ex_to<numeric>(e.op(1));
    if (b.value.is_zero() && x.is_negative()) return {Kind::pole, 0};
    return {Kind::value, pow(b.value, x)};
  }
  return {};
}

// Values are drawn for the symbols in the order of their names, not in the order GiNaC
// keeps them, so the points are the same in every run.
exmap random_point(const ex& e, std::mt19937& rng) {
  std::map<std::string, ex> by_name;
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_a<symbol>(*it)) by_name.emplace(ex_to<symbol>(*it).get_name(), *it);
  // Integers up to 2^40: as good as rationals for telling a nonzero rational function from
  // zero (the chance of a root is its degree over 2^40), and sums of them need no gcd.
  exmap m;
  std::uniform_int_distribution<long> value(1, 1L << 40);
  for (const auto& [name, sym] : by_name) m[sym] = numeric(value(rng));
  return m;
}

std::set<ex, ex_is_less> symbols_in(const ex& e) {
  std::set<ex, ex_is_less> out;
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_a<symbol>(*it)) out.insert(*it);
  return out;
}

std::size_t node_count(const ex& e, std::size_t limit) {
  std::size_t n = 0;
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end() && n < limit; ++it) ++n;
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

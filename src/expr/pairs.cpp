#include "expr/pairs.hpp"
#include "expr/memory.hpp"

#include <numeric>
#include <unordered_map>

#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

bool primitive_sum_uncached(const ex& s) {
  const epvector& seq = Pairs::of(s);
  if (seq.empty() || !ex_to<numeric>(seq.front().coeff).is_pos_integer()) return false;
  long g = 0;
  bool big = false;  // a coefficient past a long: its gcd is left to CLN below
  auto take = [&](const numeric& c) {
    if (!c.is_integer()) return false;
    if (g == 1) return true;
    if (c.is_zero()) return true;
    if (!big && c.numer().int_length() < 62)
      g = std::gcd(g, std::labs(c.to_long()));
    else
      big = true;
    return true;
  };
  for (const auto& p : seq)
    if (!take(ex_to<numeric>(p.coeff))) return false;
  if (!take(Pairs::overall(s))) return false;
  if (g == 1) return true;
  if (!big) return false;
  return s.integer_content() == 1;
}

// One factor of a product: its base and integer exponent when evaluation leaves it so.
bool plain_factor(const ex& base, const ex& expo) {
  if (!is_exactly<numeric>(expo) || !ex_to<numeric>(expo).is_integer() || expo.is_zero()) return false;
  if (is_exactly<symbol>(base)) return true;
  return is_exactly<add>(base) && primitive_sum(base);
}

// The factors of `e` (a number, a symbol, a sum, a power or a product) as pairs with their
// exponents times `sign`, and its number into `c`; false when some factor is not plain.
bool gather(const ex& e, int sign, epvector& pairs, numeric& c) {
  if (is_exactly<numeric>(e)) {
    if (e.is_zero()) return false;
    c = c.mul(sign > 0 ? ex_to<numeric>(e) : ex_to<numeric>(e).inverse());
    return true;
  }
  if (is_exactly<mul>(e)) {
    for (const auto& p : Pairs::of(e)) {
      if (!plain_factor(p.rest, p.coeff)) return false;
      pairs.emplace_back(p.rest, sign > 0 ? p.coeff : ex(-ex_to<numeric>(p.coeff)));
    }
    const numeric& k = Pairs::overall(e);
    c = c.mul(sign > 0 ? k : k.inverse());
    return true;
  }
  const bool is_power = is_exactly<power>(e);
  const ex base = is_power ? e.op(0) : e, expo = is_power ? e.op(1) : ex(1);
  if (!plain_factor(base, expo)) return false;
  pairs.emplace_back(base, sign > 0 ? expo : ex(-ex_to<numeric>(expo)));
  return true;
}

}  // namespace

bool primitive_sum(const ex& s) {
  if (!is_exactly<add>(s)) return false;
  // Remembered: a chain's closed forms share one denominator. The memory keeps the sums it
  // holds alive, so it forgets everything past 2^16 terms as well as past 1024 sums: the
  // partial sums met once each while a chain of 2048 blocks is solved (a million terms,
  // each with a number of its own) were 120 MB kept for nothing. Deciding again costs one
  // pass over the terms.
  auto& memory = thread_memory<struct pairs_memory, ExMemory<bool>>();
  auto& terms = thread_memory<struct pairs_memory_terms, std::size_t>();  // in the sums remembered
  if (auto it = memory.find(s); it != memory.end()) return it->second;
  const bool v = primitive_sum_uncached(s);
  const std::size_t k = Pairs::of(s).size();
  if (memory.size() >= 1024 || terms + k > (std::size_t{1} << 16)) {
    memory.clear();
    terms = 0;
  }
  memory.emplace(s, v);
  terms += k;
  return v;
}

bool rational_polynomial(const ex& e) {
  if (is_exactly<numeric>(e)) return ex_to<numeric>(e).is_rational();
  if (is_exactly<symbol>(e)) return true;
  if (is_exactly<add>(e)) {
    for (const auto& p : Pairs::of(e))
      if (!ex_to<numeric>(p.coeff).is_rational() || !rational_polynomial(p.rest)) return false;
    return Pairs::overall(e).is_rational();
  }
  if (is_exactly<mul>(e)) {
    for (const auto& p : Pairs::of(e))
      if (!ex_to<numeric>(p.coeff).is_nonneg_integer() || !rational_polynomial(p.rest)) return false;
    return Pairs::overall(e).is_rational();
  }
  if (is_exactly<power>(e)) return e.op(1).info(info_flags::nonnegint) && rational_polynomial(e.op(0));
  return e.info(info_flags::rational_polynomial);
}

bool expanded_polynomial(const ex& e) {
  const auto monomial = [](const ex& t) {
    if (is_exactly<symbol>(t) || is_exactly<numeric>(t)) return true;
    if (is_exactly<power>(t)) return is_exactly<symbol>(t.op(0)) && t.op(1).info(info_flags::posint);
    if (!is_exactly<mul>(t)) return false;
    for (const auto& p : Pairs::of(t))
      if (!is_exactly<symbol>(p.rest) || !ex_to<numeric>(p.coeff).is_pos_integer()) return false;
    return true;
  };
  if (!is_exactly<add>(e)) return monomial(e);
  for (const auto& p : Pairs::of(e))
    if (!monomial(p.rest)) return false;
  return true;
}

namespace {

// a^sign_a * b^sign_b made without evaluating it, when evaluation would leave it as it is.
std::optional<ex> evaluated_product(const ex& a, int sign_a, const ex& b, int sign_b) {
  epvector pairs;
  numeric c = 1;
  if (!gather(a, sign_a, pairs, c) || !gather(b, sign_b, pairs, c)) return std::nullopt;
  // Every base once (GiNaC would combine two), and at least two of them: a product of one
  // factor is evaluated to the factor, and a number times a sum to a sum.
  if (pairs.size() < 2) return std::nullopt;
  for (std::size_t i = 0; i < pairs.size(); ++i)
    for (std::size_t j = i + 1; j < pairs.size(); ++j)
      if (pairs[i].rest.is_equal(pairs[j].rest)) return std::nullopt;
  // The constructor puts the pairs in GiNaC's order; evaluation would change nothing more.
  return dynallocate<mul>(std::move(pairs), c).setflag(status_flags::evaluated);
}

}  // namespace

std::optional<ex> evaluated_quotient(const ex& num, const ex& den) { return evaluated_product(num, 1, den, -1); }

ex times(const ex& a, const ex& b) {
  if (auto p = evaluated_product(a, 1, b, 1)) return *p;
  return a * b;
}

}  // namespace tackle

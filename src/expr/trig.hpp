// sin^2 + cos^2 = 1: the one trigonometric identity closed forms of inclined problems need.
// GiNaC treats sin(x) and cos(x) as unrelated, so (L - s)^2 (cos^2 + sin^2) is not a square
// and m (cos^2 + sin^2) is not m until one of the squares is rewritten.
#pragma once

#include <string>

#include <ginac/ginac.h>

#include "core/kind.hpp"
#include "expr/pairs.hpp"

namespace tackle {

/// `e` with every sin(x)^2 written as 1 - cos(x)^2 (`to_cos`), or every cos(x)^2 as
/// 1 - sin(x)^2, expanded.
[[nodiscard]] inline GiNaC::ex pythagoras(const GiNaC::ex& e, bool to_cos) {
  using namespace GiNaC;
  const ex from = to_cos ? pow(sin(wild()), 2) : pow(cos(wild()), 2);
  const ex to = to_cos ? 1 - pow(cos(wild()), 2) : 1 - pow(sin(wild()), 2);
  return e.subs(from == to, subs_options::algebraic).expand();
}

namespace detail {

inline bool is_sin_or_cos(const GiNaC::ex& e) {
  using namespace GiNaC;
  if (!is_exactly<function>(e)) return false;
  const unsigned s = ex_to<function>(e).get_serial();
  return s == sin_SERIAL::serial || s == cos_SERIAL::serial;
}

// Walked by structure, the class told by its class-info address: has() with a pattern tries
// a match at every node, which for a sum over 256 masses was most of simplest()'s time. Sums
// and products by their stored pairs (op() would make each power of a sum anew).
inline bool has_trig_node(const GiNaC::ex& e, bool power_only) {
  using namespace GiNaC;
  if (is_exactly<symbol>(e) || is_exactly<numeric>(e)) return false;
  if (power_only ? (is_exactly<power>(e) && is_sin_or_cos(e.op(0))) : is_sin_or_cos(e)) return true;
  if (is_exactly<add>(e) || is_exactly<mul>(e)) {
    const bool product = is_exactly<mul>(e);
    for (const auto& p : Pairs::of(e)) {
      // A factor sin(x)^2 is kept as the pair (sin(x), 2).
      if (product && power_only && ex_to<numeric>(p.coeff) != 1 && is_sin_or_cos(p.rest)) return true;
      if (has_trig_node(p.rest, power_only)) return true;
    }
    return false;
  }
  const std::size_t n = e.nops();
  for (std::size_t i = 0; i < n; ++i)
    if (has_trig_node(e.op(i), power_only)) return true;
  return false;
}

}  // namespace detail

/// True when `e` has a sin or cos in it.
[[nodiscard]] inline bool has_trig(const GiNaC::ex& e) { return detail::has_trig_node(e, false); }

/// True when `e` has a power of a sin or a cos in it: only such a power can be rewritten by
/// sin^2 + cos^2 = 1 (pythagoras()).
[[nodiscard]] inline bool has_trig_power(const GiNaC::ex& e) { return detail::has_trig_node(e, true); }

/// The sum of squares `e` (expanded) with sin^2 + cos^2 = 1 used where that leaves fewer terms
/// (a number when it can): what goes under the root of a length or a norm.
[[nodiscard]] inline GiNaC::ex fewer_trig_terms(GiNaC::ex e) {
  if (!has_trig(e)) return e;
  // Counted in terms (a sum's), not operands: m (cos^2 + sin^2) L^2 becomes one product.
  const auto terms = [](const GiNaC::ex& x) { return tackle::is_exactly<GiNaC::add>(x) ? x.nops() : std::size_t{1}; };
  for (const bool to_cos : {true, false})
    if (const GiNaC::ex t = pythagoras(e, to_cos); terms(t) < terms(e) || GiNaC::is_a<GiNaC::numeric>(t)) e = t;
  return e;
}

}  // namespace tackle

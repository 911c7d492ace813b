// A sum's and a product's stored pairs, read without op(). GiNaC keeps a + 3 b as pairs
// (a, 1), (b, 3) and m M^-1 as (m, 1), (M, -1); op(i) rebuilds each term or factor as a new
// node, and a power of a sum made so is evaluated again, which takes the integer content of
// the sum (a gcd per term): a walk over a chain's closed forms, each over the sum of 256
// masses, spent a third of the run there. The pairs are GiNaC's own protected members,
// reached through a pointer to member formed in a derived class (which the language allows).
#pragma once

#include <optional>

#include <ginac/ginac.h>

#include "core/kind.hpp"

namespace tackle {

struct Pairs : GiNaC::expairseq {
  /// The pairs (rest, numeric coeff) of a sum or product: a term rest*coeff, a factor
  /// rest^coeff.
  static const GiNaC::epvector& of(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::expairseq>(e).*(&Pairs::seq); }
  /// The numeric term of a sum (0 if none) or coefficient of a product (1 if none).
  static const GiNaC::numeric& overall(const GiNaC::ex& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::ex_to<GiNaC::expairseq>(e).*(&Pairs::overall_coeff));
  }
};

/// num/den made as GiNaC's evaluation would leave it, without evaluating it: evaluating a
/// product takes, for each sum in it, the sum's integer content (a gcd and an lcm per term),
/// and GiNaC evaluates a product again each time one is made from it; a chain's 511 closed
/// forms over m_1 + ... + m_256 spent a tenth of a run there. Made only when num and den are
/// numbers, symbols, sums and products of them whose evaluation is known to leave them as they
/// are: each sum with integer coefficients without a common factor, the first one positive
/// (see primitive_sum), to a whole power, every base once. Nothing otherwise (the caller
/// divides as usual).
[[nodiscard]] std::optional<GiNaC::ex> evaluated_quotient(const GiNaC::ex& num, const GiNaC::ex& den);
/// a*b, made as evaluated_quotient() makes a quotient when it can (F times m_1 + ... + m_256:
/// evaluating the product takes the sum's integer content, a gcd and an lcm per term); a*b
/// as GiNaC makes it otherwise. Equal to a*b either way.
[[nodiscard]] GiNaC::ex times(const GiNaC::ex& a, const GiNaC::ex& b);

/// e.info(info_flags::rational_polynomial), read from the stored pairs: GiNaC decides it by
/// making every term and factor anew (a tenth of a chain's elimination went there).
[[nodiscard]] bool rational_polynomial(const GiNaC::ex& e);

/// True when `e` is a symbol, a number, a product of powers of symbols, or a sum of such
/// terms: expand() would give it back (walking every term, and making each product anew).
[[nodiscard]] bool expanded_polynomial(const GiNaC::ex& e);

/// True when `s` is a sum with integer coefficients whose greatest common divisor is 1 and
/// whose first coefficient (GiNaC's order) is positive: the form GiNaC's evaluation leaves a
/// sum in, as a factor of a product or the base of a whole power. Decided in machine integers
/// where the coefficients fit.
[[nodiscard]] bool primitive_sum(const GiNaC::ex& s);

}  // namespace tackle

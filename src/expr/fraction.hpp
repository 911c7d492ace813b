// Rational functions put in normal form without a polynomial gcd, when every denominator is
// a product of factors known to be irreducible: symbols, and sums of degree 1 in some symbol
// whose coefficients of that symbol's first and zeroth power are coprime (m_1 + m_2, or a
// compound Atwood machine's sum over the products of all masses but one). A sum of such
// fractions is put over the least common multiple of the denominators, read off their
// factors; what is left cancels only by those factors, each tried by division (a symbol by
// its lowest power in the numerator). normal() finds the same fraction by a gcd of numerator
// and denominator, computed from their values at large integers: during a cascade's
// elimination that was nine tenths of the run (numerators of dozens of terms of degree 32
// against products of 32 masses).
#pragma once

#include <optional>

#include <ginac/ginac.h>

namespace tackle {

/// e in normal form (numerator and denominator coprime, the numerator expanded, the number
/// over the line the least common denominator of the numerator's coefficients, as normal()
/// leaves it), made without a gcd; nothing when some denominator in `e` is not a product of
/// whole powers of symbols and of expanded primitive sums known to be irreducible (see
/// above), or `e` is not a rational function of symbols with rational coefficients. The
/// fraction's value is exactly e's; when the denominator is a monomial, its form is
/// normal()'s too. An expression equal to 0 gives exactly 0.
[[nodiscard]] std::optional<GiNaC::ex> normal_by_factors(const GiNaC::ex& e);

/// e with each coefficient that is an integer from -12 to 12 made of the one object GiNaC
/// keeps for it, changed in place (a number of equal value: whoever else holds a node sees
/// the same expression): a number made by arithmetic is an object of its own (some 48 bytes),
/// and negating a sum makes one per term. A chain of 2048 blocks' closed forms hold 2 million
/// terms; their coefficients were 100 MB of separate ones. Returns `e`.
[[nodiscard]] GiNaC::ex with_shared_numbers(const GiNaC::ex& e);

/// Whether an expanded polynomial is irreducible because it is of degree 1 in some symbol
/// with coprime coefficients (linear_and_coprime), remembered per thread.
[[nodiscard]] bool linear_irreducible(const GiNaC::ex& p);

/// False when the polynomial g (a symbol, or of degree 1 in some symbol) certainly does not
/// divide the expanded polynomial p: by degrees, or because p is not zero at g's root at a
/// point modulo a prime. True when that does not decide it (divide() then decides).
[[nodiscard]] bool may_divide(const GiNaC::ex& p, const GiNaC::ex& g);

}  // namespace tackle

// The simplest form of an expression, and what it rests on: the sign an expression's symbols'
// domains decide, and a polynomial's factors in a canonical form. Every room that prints or
// compares closed forms uses these (the solve, the checker, the reports).
#pragma once

#include <optional>
#include <vector>

#include <ginac/ginac.h>

namespace tackle {

/// The sign of an expression when its symbols' domains decide it (+1, -1, 0), decided from
/// its structure in both directions (a sum of negative terms is negative), never from the
/// order GiNaC keeps terms in.
[[nodiscard]] std::optional<int> sign_of(const GiNaC::ex& e);

/// The factors of a polynomial in a canonical form: a numeric coefficient first (when it is
/// not 1), then each factor expanded, every integer power of a sum oriented (positive when its
/// sign is known, else a positive coefficient on the term that prints first), the signs taken
/// out gathered in the coefficient. The same for every hash order.
[[nodiscard]] std::vector<GiNaC::ex> canonical_factors(const GiNaC::ex& polynomial);

/// The product of the canonical factors (see canonical_factors), remembered: one run factors
/// the same numerators and denominators many times (a motion's quantities share m + M). The
/// memory is per thread and forgets everything past 4096 polynomials; an equal polynomial
/// always gives an equal product, so what is remembered changes no output.
[[nodiscard]] GiNaC::ex factored(const GiNaC::ex& polynomial);

/// Shortest of the normal form and its factored form (the normal form made here: there is no
/// need to call normal() first). Remembered per thread, by `e` and by its normal form.
[[nodiscard]] GiNaC::ex simplest(const GiNaC::ex& e);
/// simplest(polynomial) for a polynomial known to be a number times the product of `parts`
/// (polynomials; checked, else simplest() of the whole): its factors are the parts', each
/// factored alone, which is far cheaper than factor() of the whole. The same form.
[[nodiscard]] GiNaC::ex simplest_of_product(const GiNaC::ex& polynomial, const std::vector<GiNaC::ex>& parts);

}  // namespace tackle

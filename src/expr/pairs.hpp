// A sum's and a product's stored pairs, read without op(). GiNaC keeps a + 3 b as pairs
// (a, 1), (b, 3) and m M^-1 as (m, 1), (M, -1); op(i) rebuilds each term or factor as a new
// node, and a power of a sum made so is evaluated again, which takes the integer content of
// the sum (a gcd per term): a walk over a chain's closed forms, each over the sum of 256
// masses, spent a third of the run there. The pairs are GiNaC's own protected members,
// reached through a pointer to member formed in a derived class (which the language allows).
#pragma once

#include <ginac/ginac.h>

#include "core/kind.hpp"

namespace tackle {

struct Pairs : GiNaC::expairseq {
  /// The pairs (rest, numeric coeff) of a sum or product: a term rest*coeff, a factor
  /// rest^coeff.
  static const GiNaC::epvector& of(const GiNaC::ex& e) {
    return GiNaC::ex_to<GiNaC::expairseq>(e).*(&Pairs::seq);
  }
  /// The numeric term of a sum (0 if none) or coefficient of a product (1 if none).
  static const GiNaC::numeric& overall(const GiNaC::ex& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::ex_to<GiNaC::expairseq>(e).*(&Pairs::overall_coeff));
  }
};

}  // namespace tackle

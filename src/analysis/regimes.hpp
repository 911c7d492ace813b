// Connections decided at the given numbers (a rule with `regimes:`, such as friction between
// two moving bodies): each becomes its first regime's rule (sticking); where that regime's
// validity fails at the given numbers, its next (sliding, the way the friction it needed could
// not hold). What was decided, and the first regime's conditions solved (the largest load for
// which the bodies move together), is kept for the derivation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "description/description.hpp"
#include "ruleset/ruleset.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct Analysis;

/// The places of the connections of `d` that are decided at the numbers.
[[nodiscard]] std::vector<std::size_t> decided_connections(const Description& d, const RuleSet& rules);

/// `d` with each decided connection (`which`) as its regime `regime[k]`, a turned vector
/// turned where `turn[k]`.
[[nodiscard]] Description with_regimes(const Description& d, const RuleSet& rules,
                                       const std::vector<std::size_t>& which, const std::vector<std::size_t>& regime,
                                       const std::vector<bool>& turn);

/// For connection `i` of `d`, analysed in its first regime as `a`: what was decided (chosen is
/// the first regime's rule when its validity holds at the numbers), and whether the next
/// regime's vector is turned (the unknown it is against is positive at the numbers).
[[nodiscard]] RegimeChoice decide_regime(const Analysis& a, const Description& d, const RuleSet& rules, std::size_t i,
                                         bool& turn);

}  // namespace tackle

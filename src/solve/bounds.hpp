// Conditions as numbers: each solved form's bound at the given numbers, in its parameter's
// unit (`mu >= tan(theta)/3 = 0.19245`), a square's bound on the parameter itself (`v^2 <= ...
// = (19.1206 m/s)^2`), what a bound at or below 0 means for a positive parameter; and each
// parameter's range with the others at their given values (`5.3187 m/s <= v <= 19.1206 m/s`).
#pragma once

#include <vector>

#include <ginac/ginac.h>

#include "model/symbols.hpp"
#include "solve/answers.hpp"
#include "solve/solve.hpp"

namespace tackle {

/// The bound of `form` at the given numbers (`definitions` put in first: a motion's lambda),
/// or nothing when some symbol in it has no value or it is not real there.
[[nodiscard]] std::optional<BoundNumber> bound_number(const SolvedFor& form, const SymbolTable& table, int digits,
                                                      const GiNaC::exmap& definitions = {});
/// Fills each form's `number`.
void number_bounds(std::vector<SolvedFor>& forms, const SymbolTable& table, int digits,
                   const GiNaC::exmap& definitions = {});

/// For each parameter some condition is solved for (in the order first met): the values for
/// which every condition holds, the others at their given values. Only where that is known:
/// every condition that has the parameter is solved for it with a number, and every other
/// holds at the given numbers.
[[nodiscard]] std::vector<ParameterRange> ranges_at_numbers(const std::vector<ConditionReport>& conditions,
                                                            const SymbolTable& table, int digits);

}  // namespace tackle

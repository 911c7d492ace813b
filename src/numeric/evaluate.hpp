// Numbers from closed forms: substitute the parameters' SI values (exact rationals) and
// report exactly when the result is rational, else to a stated number of digits.
#pragma once

#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "core/units.hpp"
#include "model/symbols.hpp"

namespace tackle {

struct NumericValue {
  GiNaC::ex exact;      // a rational number, or an exact irrational form (sqrt(2)*3)
  double approx = 0.0;
  std::string decimal;  // "-2.25", "6.78233"
  std::string unit;     // SI unit of the quantity's dimension ("" if dimensionless or unknown)
};

/// The value of `e` with every parameter's value substituted, or nullopt when some symbol
/// has no value.
[[nodiscard]] std::optional<NumericValue> evaluate(const GiNaC::ex& e, const SymbolTable& symbols,
                                                   std::optional<Dimension> dimension, int digits = 6);

/// A decimal string for a real number: exact when it terminates within `digits` significant
/// digits, else rounded to `digits` significant digits.
[[nodiscard]] std::string decimal_string(const GiNaC::numeric& v, int digits = 6);

}  // namespace tackle

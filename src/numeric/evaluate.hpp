// Numbers from closed forms: substitute the parameters' SI values (exact rationals, or exact
// expressions for defined parameters) and report exactly when the result is rational, else
// to a stated number of significant digits (CLN arithmetic at any precision).
#pragma once

#include <optional>
#include <string>

#include <ginac/ginac.h>

#include "expr/normal_form.hpp"

#include "core/units.hpp"
#include "model/symbols.hpp"

namespace tackle {

struct NumericValue {
  GiNaC::ex exact;      // in `unit`: a rational number, or an exact irrational form (2*sqrt(23/2))
  GiNaC::ex si;         // the same in SI
  double approx = 0.0;  // in `unit`
  std::string decimal;  // in `unit`: "-2.25", "6.78233"
  std::string unit;     // SI unit of the quantity's dimension, or the unit asked for
};

/// The value of `e` with every parameter's value substituted, or nullopt when some symbol
/// has no value. With `unit`, the number is given in it (its dimension must match).
[[nodiscard]] std::optional<NumericValue> evaluate(const GiNaC::ex& e, const SymbolTable& symbols,
                                                   std::optional<Dimension> dimension, int digits = 6,
                                                   const std::optional<Unit>& unit = std::nullopt);
/// The same with the values given explicitly (variants and sweeps).
[[nodiscard]] std::optional<NumericValue> evaluate_with(const GiNaC::ex& e, const GiNaC::exmap& values,
                                                        std::optional<Dimension> dimension, int digits = 6,
                                                        const std::optional<Unit>& unit = std::nullopt);

/// A decimal string for a real number: exact when it terminates within 15 significant
/// digits (or `digits`, if more), else rounded to `digits` significant digits (any number of
/// them: CLN floats at that precision).
/// `e` at `values`, exactly (the normal form's numerator over its denominator, the
/// denominator checked first), or nothing where it is undefined (a denominator that vanishes
/// there) or still has a symbol. Never lets GiNaC throw from inside a new node (which leaks).
[[nodiscard]] std::optional<GiNaC::ex> value_at(const GiNaC::ex& e, const GiNaC::exmap& values);

[[nodiscard]] std::string decimal_string(const GiNaC::numeric& v, int digits = 6);

}  // namespace tackle

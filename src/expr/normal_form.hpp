// An expression's normal form as numerator and denominator, for evaluating it where a
// denominator may vanish. The denominator is always checked first: substituting into a pole
// makes GiNaC throw from inside a node it is making, and that node leaks (found by fuzzing
// and the sanitizers). Made once, a form is evaluated at many points (a sweep, key variants):
// normal() is the costly part.
#pragma once

#include <optional>

#include <ginac/ginac.h>

namespace tackle {

/// True when `e` is a rational number written with +, *, and integer powers only (no roots,
/// no functions, no symbols): exact arithmetic decides everything about it.
[[nodiscard]] bool is_rational_number(const GiNaC::ex& e);

/// The same with symbols allowed: a rational function (no roots, no functions).
[[nodiscard]] bool is_rational_function(const GiNaC::ex& e);

/// True when `e` at `values` has a pole that exact arithmetic does not see (a denominator
/// such as sqrt(20) - 2*sqrt(5), which is zero); evaluating it numerically would throw.
[[nodiscard]] bool has_pole_at(const GiNaC::ex& e, const GiNaC::exmap& values);

struct NormalForm {
  GiNaC::ex num, den;
  explicit NormalForm(const GiNaC::ex& e);
  /// True when the denominator vanishes at `values` (the expression is undefined there),
  /// exactly or hidden in radicals.
  [[nodiscard]] bool undefined_at(const GiNaC::exmap& values) const;
  /// The denominator at `values`, or nothing where it vanishes (exactly or hidden in
  /// radicals) or the numerator has a hidden pole of its own.
  [[nodiscard]] std::optional<GiNaC::ex> denominator_at(const GiNaC::exmap& values) const;
  /// The exact value at `values`; nothing where undefined or where a symbol is left.
  [[nodiscard]] std::optional<GiNaC::ex> at(const GiNaC::exmap& values) const;
  /// The same as a double (the denominator still checked exactly; the rest in floating point).
  [[nodiscard]] std::optional<double> approx_at(const GiNaC::exmap& values) const;
};

}  // namespace tackle

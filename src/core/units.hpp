// Physical dimensions and SI units. Values are stored in SI; a unit is an exact factor to SI
// (a rational, or pi/180 for degrees) and a dimension. (US customary units are a later issue.)
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <ginac/ginac.h>

namespace tackle {

/// Exponents of mass, length and time.
struct Dimension {
  std::array<int, 3> exp{0, 0, 0};  // M, L, T

  static Dimension mass() { return {{1, 0, 0}}; }
  static Dimension length() { return {{0, 1, 0}}; }
  static Dimension time() { return {{0, 0, 1}}; }
  static Dimension force() { return {{1, 1, -2}}; }
  static Dimension acceleration() { return {{0, 1, -2}}; }
  static Dimension velocity() { return {{0, 1, -1}}; }
  static Dimension none() { return {}; }

  friend Dimension operator*(Dimension a, Dimension b) {
    for (int i = 0; i < 3; ++i) a.exp[i] += b.exp[i];
    return a;
  }
  friend Dimension operator/(Dimension a, Dimension b) {
    for (int i = 0; i < 3; ++i) a.exp[i] -= b.exp[i];
    return a;
  }
  [[nodiscard]] Dimension pow(int n) const {
    Dimension d = *this;
    for (int& e : d.exp) e *= n;
    return d;
  }
  friend bool operator==(const Dimension&, const Dimension&) = default;

  /// "force", "mass", "length per time squared" or "mass^a length^b time^c".
  [[nodiscard]] std::string describe() const;
  /// Named dimensions accepted by a `dimension:` key: force, mass, length, ...
  static std::optional<Dimension> from_name(std::string_view name);
};

struct Unit {
  GiNaC::ex to_si;  // value in SI = value in this unit * to_si (exact; pi/180 for deg)
  Dimension dimension;
  std::string text;  // as the user wrote it, or the canonical SI name
};

/// Parses "kg", "m/s^2", "kN", "N*m", "kg*m/s^2". Returns nullopt with `error` set when it
/// cannot (unknown unit, bad syntax); `error_column` is 0-based within `text`.
std::optional<Unit> parse_unit(std::string_view text, std::string& error, int& error_column);

/// The SI unit tackle prints for a dimension: N, kg, m, s, m/s, m/s^2, N/m, J, ... or a
/// product of base units.
[[nodiscard]] std::string si_unit_name(const Dimension& d);

/// Joules, for a quantity that is an energy or a work (a moment has the same dimension and
/// is printed in N*m).
[[nodiscard]] const Unit& joule();

/// The same unit as LaTeX (`\mathrm{m/s^{2}}`).
[[nodiscard]] std::string unit_latex(std::string_view unit_text);

/// "a force", "an acceleration".
[[nodiscard]] std::string with_article(const std::string& noun);

/// Dimension of an expression whose symbols have the given dimensions. Returns nullopt and
/// sets `problem` when terms of a sum disagree or a symbol's dimension is unknown
/// (`unknown_symbol` is then set and `problem` is empty).
struct DimensionLookup {
  virtual ~DimensionLookup() = default;
  virtual std::optional<Dimension> dimension_of(const GiNaC::symbol& s) const = 0;
};
std::optional<Dimension> dimension_of(const GiNaC::ex& e, const DimensionLookup& lookup, std::string& problem);

}  // namespace tackle

// The SymbolTable: every symbol of a problem is made here, once, with its name as typed
// (`m_A`, `ddot(x_A)`, `T_s`), its TeX name, its role, its dimension and (for parameters)
// its value in SI. Everything else looks symbols up here.
#pragma once

#include <map>
#include <set>
#include <mutex>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/diagnostics.hpp"
#include "core/units.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle {

// time: t. motion: a quantity of the motion in time that the motion stage defines (the
// natural frequency lambda, the damping ratio zeta, the damped frequency omega_d).
enum class SymbolRole { parameter, coordinate, rate, acceleration, unknown, defined, time, motion };

struct SymbolInfo {
  std::string name;
  std::string tex;
  GiNaC::ex sym;  // an ex, so that possymbol / realsymbol keep their domain (no slicing)
  SymbolRole role = SymbolRole::parameter;
  std::optional<Dimension> dimension;
  std::optional<GiNaC::ex> value;  // parameters: value in SI, exact (pi/6 for 30 deg)
  std::string unit;                // parameters: the unit they are stated in
  bool positive = false;
  std::optional<GiNaC::ex> definition;  // a defined parameter: its expression in the others
  // A strand's length that turns as the bodies move, `l_CP = sqrt(a^2 + (h - z)^2)`: kept as
  // a positive symbol in every closed form (so no root of the coordinates ever meets
  // normal()), its definition substituted for numbers only.
  bool geometric = false;
  GiNaC::ex unit_to_si = 1;  // parameters: `unit`'s factor to SI (pi/180 for deg)
  // Variants: the range values are drawn from and the step they are rounded to, in `unit`.
  std::optional<std::pair<GiNaC::numeric, GiNaC::numeric>> range;
  std::optional<GiNaC::numeric> step;
  Location where;

  [[nodiscard]] const GiNaC::symbol& symbol() const { return GiNaC::ex_to<GiNaC::symbol>(sym); }
};

/// TeX for a name as typed: `m_A` -> `m_{A}`, `mu` -> `\mu`, `mu_k` -> `\mu_{k}`,
/// `ddot(x_A)` -> `\ddot{x}_{A}`, `T_HI` -> `T_{HI}`.
[[nodiscard]] std::string default_tex(std::string_view name);

class SymbolTable;
/// The order a person writes a product's factors in, from what the names are: dimensionless
/// coefficients (mu), masses, other parameters (g, lengths), coordinates, then unknowns,
/// rates and accelerations; anything not a name last. For PersonOrder (expr/print.hpp).
/// Several tables (the problems of a key, the phases of a description): each name is looked
/// up in the table that made it.
[[nodiscard]] FactorRank factor_rank(std::vector<std::shared_ptr<const SymbolTable>> tables);

class SymbolTable : public NameResolver, public DimensionLookup {
 public:
  /// Makes a symbol; the caller has checked that the name is free (InternalError if not).
  const SymbolInfo& add(const std::string& name, std::optional<std::string> tex, SymbolRole role,
                        std::optional<Dimension> dimension, bool positive, Location where);
  [[nodiscard]] const SymbolInfo* find(std::string_view name) const;
  [[nodiscard]] const SymbolInfo* find(const GiNaC::ex& sym) const;
  [[nodiscard]] const std::vector<std::unique_ptr<SymbolInfo>>& all() const { return items_; }
  /// The unit a parameter is stated in (its text and factor to SI).
  void set_unit(const std::string& name, std::string unit, GiNaC::ex to_si);
  void set_value(const std::string& name, GiNaC::ex value);

  // NameResolver
  [[nodiscard]] std::optional<GiNaC::ex> resolve(std::string_view name) const override;
  [[nodiscard]] std::vector<std::string> known_names() const override;
  // DimensionLookup
  [[nodiscard]] std::optional<Dimension> dimension_of(const GiNaC::symbol& s) const override;

  /// Substitution map of every parameter that has a value (SI).
  [[nodiscard]] GiNaC::exmap values() const;
  /// The same values, and the rational ones as a point for rational_at(), made once (every
  /// closed form of a chain is evaluated at them: a copy of each for each was a tenth of it).
  struct ValueSet {
    GiNaC::exmap map;
    RationalPoint rational;
    mutable SumValues sums;  // long sums' values at `rational`, remembered by evaluate()
  };
  [[nodiscard]] std::shared_ptr<const ValueSet> value_set() const;
  /// Substitution map of every defined parameter to its expression; the geometric lengths
  /// too when asked (for numbers only: their roots are not for normal()).
  [[nodiscard]] GiNaC::exmap definitions(bool geometric = false) const;
  void set_definition(const std::string& name, GiNaC::ex definition, bool geometric = false);
  /// A name that reads as an expression wherever a description or an answer names it: a
  /// steady motion's unknown rate omega reads as sqrt(omega^2), its square being the unknown.
  void set_alias(const std::string& name, GiNaC::ex expression);
  /// The symbols with a definition, in the table's order (a chain's thousand symbols have
  /// none: each closed form and each term of the derivation asked every symbol).
  [[nodiscard]] std::vector<const SymbolInfo*> defined() const;
  /// True when a geometric length in `e` depends on `s` (e is then not linear in s where it
  /// looks so).
  [[nodiscard]] bool hidden_in_lengths(const GiNaC::ex& e, const GiNaC::ex& s) const;
  void set_range(const std::string& name, GiNaC::numeric low, GiNaC::numeric high, std::optional<GiNaC::numeric> step);

 private:
  std::vector<std::unique_ptr<SymbolInfo>> items_;
  std::map<std::string, std::size_t, std::less<>> by_name_;
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> by_symbol_;
  std::set<std::size_t> defined_;  // the indices of the symbols with a definition
  std::map<std::string, GiNaC::ex, std::less<>> aliases_;
  // values(), made once after the last change (every change forgets it); a run asks for it
  // some thirty times.
  mutable std::shared_ptr<const ValueSet> values_;
  mutable std::mutex values_mutex_;
  void changed() { values_.reset(); }
};

}  // namespace tackle

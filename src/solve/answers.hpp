// The answers: what each quantity asked for comes to (a closed form with its number, free,
// only in combination, or undetermined and why), the combinations the equations determine,
// the least-norm member of an indeterminate family, and each validity condition with the
// given numbers. A stage after the solve; the report narrates what it finds.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ginac/ginac.h>

#include "core/units.hpp"
#include "equations/equations.hpp"
#include "model/model.hpp"
#include "numeric/evaluate.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct Answer {
  std::string name;
  std::string tex;
  GiNaC::ex symbol;  // the name as a symbol (from the symbol table)
  // undetermined: what it comes to still contains quantities no solved equation gives
  // (`missing`): never reported as a closed form, least of all as itself.
  enum class Status { determined, free, in_combination, not_in_equations, undetermined } status = Status::determined;
  std::vector<GiNaC::ex> missing;
  std::string reason;  // undetermined: why, in words ("no solved equation gives dot(x_A) ...")
  // undetermined because a defined quantity divides by zero: the unknowns that are 0 there
  // (F/ddot(x_B) with ddot(x_B) = 0)
  std::vector<GiNaC::ex> zero_divisors;
  std::optional<GiNaC::ex> closed_form;
  std::optional<GiNaC::ex> in_parameters;  // the closed form with the defined parameters put in, when it has any
  std::optional<NumericValue> value;
  std::optional<GiNaC::ex> general;  // free or in combination: in terms of the free unknowns
  std::optional<Unit> unit;          // the unit the numbers are given in (SI when absent)
};

struct ConditionReport {
  std::string source;
  GiNaC::ex lhs, rhs;  // as the rule states it (T_s >= 0)
  std::string op;
  GiNaC::ex simplified;       // closed form, `simplified op 0`
  std::optional<bool> holds;  // with the given numbers
  std::string meaning, otherwise;
  std::vector<SolvedFor> solved;  // the condition solved for a parameter, when it can be
  std::optional<bool> always;     // for every positive value of the parameters
  bool depends_on_free = false;   // on an unknown the equations leave free
};

/// One parameter's values for which every condition holds, the others at their given values
/// (from the solved forms' numbers): `5.3187 m/s <= v <= 19.1206 m/s`.
struct ParameterRange {
  GiNaC::ex parameter;
  std::optional<NumericValue> low, high;  // absent: nothing asked on that side
  bool low_strict = false, high_strict = false;
  std::optional<NumericValue> given;  // the parameter's own value, in the same unit
  bool empty = false;                 // the bounds exclude each other: no value will do
};

struct CombinationReport {
  GiNaC::ex combination, value;
  std::optional<NumericValue> number;
};

struct Answers {
  std::vector<Answer> answers;
  std::vector<CombinationReport> combinations;
  // Indeterminate with numbers: the member of the family with the least norm (Eigen), for
  // the unknowns that are not determined alone.
  std::vector<std::pair<std::string, std::optional<NumericValue>>> minimum_norm;
  std::vector<ConditionReport> conditions;
  std::vector<ParameterRange> ranges;  // each parameter the conditions are solved for, alone
};

/// The answers to the model's questions (every unknown when it asks none), numbers to
/// `digits` significant digits.
[[nodiscard]] Answers answer(const Model& m, const EquationSystem& s, const Solution& sol, int digits);

/// Why an undetermined answer is not determined, with each missing quantity as "{}" when
/// `placeholders` (for typeset prose).
[[nodiscard]] std::string undetermined_reason(const Answer& a, const SymbolTable& table, const Solution& sol,
                                              bool placeholders);

[[nodiscard]] bool has_definition(const GiNaC::ex& e, const SymbolTable& table);
/// An expression with each defined parameter folded back in where that is shorter
/// (a*l*m/(2*d) rather than a*m*sqrt(b^2 + d^2 + e^2)/(2*d)).
[[nodiscard]] GiNaC::ex fold_definitions(const GiNaC::ex& e, const SymbolTable& table);

}  // namespace tackle

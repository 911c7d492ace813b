// Solving the linear system for the unknowns with explicit rank and consistency checks
// (Gauss-Jordan over rational functions, pivots decided by `normal(.).is_zero()`, so the
// rank is the generic rank: parameters are treated as independent symbols). Every reported
// solution has been substituted back into every equation, symbolically and at random exact
// rational parameter values.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"
#include "expr/simplest.hpp"
#include "numeric/evaluate.hpp"

namespace tackle {

struct MassForm;  // motion/mass_form.hpp

struct Determined {
  GiNaC::ex unknown;
  GiNaC::ex value;  // closed form in the parameters
};

/// A combination of unknowns that the equations determine although its parts are free
/// (`O_y + G_y = -3 N`).
struct Combination {
  GiNaC::ex combination;
  GiNaC::ex value;
};

/// A solved form's bound at the given numbers, as the report says it (filled by the answers
/// stage, which knows the digits: solve_condition leaves it empty).
struct BoundNumber {
  NumericValue value;                // the bound, in the parameter's stated unit (a square's: in SI)
  std::optional<NumericValue> root;  // `p^2 op B` with B >= 0: sqrt(B), the bound on p, in p's unit
  // For a positive parameter: a lower bound at or below 0 asks nothing of it (every value
  // down to 0 satisfies it); an upper bound at or below 0 leaves it no value.
  bool every_value = false;
  bool no_value = false;
};

/// A condition solved for one parameter: `parameter op bound`, equivalent to the condition
/// (found when the condition is linear in that parameter with a coefficient of known sign,
/// once factors of known sign are divided out).
struct SolvedFor {
  GiNaC::ex parameter;  // a parameter, or its square (v^2 <= ...) where the root's sign is open
  std::string op;
  GiNaC::ex bound;
  // 0, or an expression of unknown sign that the solving divided by, positive at the given
  // numbers: the form holds while it stays positive (`v^2 <= g r .../(cos(beta) - mu sin(beta))`
  // while cos(beta) - mu sin(beta) > 0).
  GiNaC::ex provided = 0;
  std::optional<BoundNumber> number;  // at the given numbers (see BoundNumber)
};

struct CheckedCondition {
  const Condition* condition = nullptr;
  GiNaC::ex expr;  // lhs - rhs with the solution substituted, simplified; the condition is `expr op 0`
  bool depends_on_free = false;
  std::optional<bool> always;     // true: holds for every positive value of the parameters; false: never
  std::vector<SolvedFor> solved;  // one per parameter it could be solved for, in parameter order
};

/// Whether `x op 0` holds, for op one of >=, >, <=, <, =.
[[nodiscard]] bool relation_holds(const GiNaC::numeric& x, const std::string& op);

/// Whether `expr op 0` holds for every value of its symbols (true), for none (false), or
/// depends on them (nothing): from the signs of its factors, the known ones and even powers
/// (`k^2*x_S^2 >= 0` always holds).
[[nodiscard]] std::optional<bool> holds_always(const GiNaC::ex& expr, const std::string& op);

/// Solves `expr op 0` for each parameter it is linear in (see SolvedFor).
[[nodiscard]] std::vector<SolvedFor> solve_condition(const GiNaC::ex& expr, const std::string& op,
                                                     const std::vector<GiNaC::ex>& parameters);

/// A connection decided at the given numbers (analysis/regimes): the rule tried first and the
/// one chosen, with what failed and the first one's conditions solved (for the derivation).
struct RegimeChoice {
  std::string connection;     // the connection's label in the chosen model ("sliding between at A")
  std::string first, chosen;  // the rules tried first and chosen (sticking_between, sliding_between)
  // The first regime's conditions that fail at the given numbers (their meanings) ...
  std::vector<std::string> failed;
  // (... or none, and some have no number there: they depend on the time or on a coordinate
  // without a value. The first regime is taken; it holds while they do.)
  bool undecided = false;
  // ... and each of its conditions solved for a parameter, with the bound's number (when the
  // parameters have values): `F <= g*mu_s*(m_A + m_B) = 14.715 N`.
  struct Bound {
    std::string meaning;
    GiNaC::ex parameter, bound;
    std::string op;
    std::string value;    // the bound's number with its unit, or empty
    bool failed = false;  // its condition fails at the given numbers
    // The tightest of the bounds on its parameter the same way at the given numbers (the
    // largest lower bound, the smallest upper bound; every bound without a number).
    bool tightest = true;
    bool coefficient = false;      // on a dimensionless parameter (a friction coefficient)
    std::optional<double> number;  // the bound at the given numbers (SI)
  };
  std::vector<Bound> holds_while;
  // The first regime's friction (the unknown the next regime's vector is turned against) on
  // the connection's first body: its closed form, and the most the contact can give (the other
  // side of its condition), each with its number.
  struct Friction {
    std::string body;
    GiNaC::ex unknown, value, limit, limit_value;
    std::string value_number, limit_number;
  };
  std::optional<Friction> friction;
};

struct Solution {
  enum class Status { determined, underdetermined, inconsistent } status = Status::determined;
  std::size_t rank = 0;
  std::vector<Determined> values;
  std::vector<GiNaC::ex> free;
  std::vector<Combination> combinations;
  std::vector<std::string> conflicts;               // inconsistent: the equations that conflict
  std::vector<std::vector<std::string>> redundant;  // groups of equations that depend on each other
  std::vector<CheckedCondition> conditions;
  GiNaC::exmap general;  // every unknown in terms of the parameters and the free unknowns
  // Velocity and position questions: the constraints' rate (position) equations solved for
  // the rates (coordinates) of the bodies that are not given; only when one is asked for.
  std::shared_ptr<const Solution> rates, positions;
  // Not solved, and why (instant_left_to_motion): nothing is asked at the instant and the
  // motion has its equations without it. Empty when solved.
  std::string unsolved;
  std::shared_ptr<const MassForm> mass_form;  // unsolved: the motion's equations, made once

  [[nodiscard]] std::optional<GiNaC::ex> value_of(const GiNaC::ex& unknown) const;
};

[[nodiscard]] Solution solve(const Model& m, const EquationSystem& s);

/// The linear solve alone (no conditions): rank, values, free unknowns, combinations,
/// conflicts, redundant groups, every solution verified. `file` names input errors.
[[nodiscard]] Solution solve_equations(const std::string& file, const std::vector<Equation>& equations,
                                       const std::vector<GiNaC::ex>& unknowns);

}  // namespace tackle

// Checking an equation a student wrote (a balance, a constraint, or one derived from them)
// against the model: correct when it holds in every state the model allows (decided by the
// verdict algebra, algebra/truth.hpp, over every balance and constraint of the model, not only
// those its `derive:` prints), named when it is one of the model's equations up to a factor,
// and otherwise diagnosed in the words of the free body diagram (a force missing, a force with
// the wrong sign, the inertial term missing, a force that acts on another body), never
// showing the correct equation.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <ginac/ginac.h>

#include "algebra/truth.hpp"
#include "check/check.hpp"

namespace tackle {

class EquationChecker {
 public:
  EquationChecker(const Analysis& analysis, const CheckOptions& options);
  /// The verdict on `text` ("2*T - F = m_A*ddot(x_A)"); invalid when it cannot be read.
  [[nodiscard]] CheckResult check(std::string_view text) const;
  /// The fewest of the model's equations that give `unknown = closed_form` (their labels, the
  /// derivation's own first); empty when none do.
  [[nodiscard]] std::vector<std::string> needed_for(const GiNaC::ex& unknown, const GiNaC::ex& closed_form) const;
  /// The model's equation with this label (the rates' and the length sums' too), or null.
  [[nodiscard]] const Equation* equation(const std::string& label) const;
  /// A length sum's (a constraint at the level of positions) equation at the level of
  /// accelerations: "string s: acceleration" for "length of string s"; empty for other labels.
  [[nodiscard]] std::string differentiated(const std::string& label) const;

 private:
  // One level of equations (accelerations, rates, positions): the model's equations there and
  // the algebra that decides with them, and what the diagnosis needs of each equation at the
  // fixed points (made when first wanted).
  struct Level {
    std::string name;  // "balances and constraints", "constraints in rates", "length sums"
    std::vector<const Equation*> equations;
    std::vector<GiNaC::ex> unknowns;
    std::optional<Truth> truth;  // made when first wanted (none past the bound on equations)
    struct Terms {
      std::vector<std::optional<std::vector<Row>>> terms;  // each term's values
      std::optional<std::vector<Row>> lhs;
      // A body's own balance with another body's mass, or acceleration, in its m a: by the
      // other body's place.
      std::vector<std::pair<std::size_t, std::vector<Row>>> other_mass, other_acceleration;
    };
    mutable std::once_flag made;
    mutable std::vector<Terms> terms;
  };
  using Rows = std::vector<Row>;

  /// The equation read as `side[0] = side[1]` checked (see check()); `constants`: the names read
  /// as a length sum's constants.
  CheckResult settle(const GiNaC::ex (&side)[2], const std::vector<GiNaC::ex>& constants, CheckResult r) const;
  CheckResult decide(const Level& level, const GiNaC::ex& residual, CheckResult r) const;
  CheckResult decide_linear(const Level& level, const std::vector<GiNaC::ex>& parts, CheckResult r) const;
  CheckResult incorrect(const Level& level, const Rows& values, CheckResult r) const;
  void name_it(const Level& level, const Rows& values, CheckResult& r) const;
  [[nodiscard]] std::optional<Rows> values_of(const Level& level, const GiNaC::ex& e, bool fixed_only) const;
  [[nodiscard]] const std::vector<Level::Terms>& terms_of(const Level& level) const;
  void diagnose(const Level& level, const Rows& v, CheckResult& r) const;
  void diagnose_balance(const Level& level, std::size_t ei, const Rows& v, CheckResult& r) const;
  void other_bodies(const Level& level, const Equation& e, Level::Terms& t) const;
  void diagnose_other_forces(const Level& level, std::size_t ei, const Rows& v, CheckResult& r) const;
  [[nodiscard]] CheckResult position_verdict(const Level& level, const GiNaC::ex& residual, CheckResult r) const;
  void build_levels(const Analysis& analysis);
  void prepare() const;

  CheckOptions options_;
  std::shared_ptr<const SymbolTable> symbols_;
  GiNaC::exmap definitions_;  // the defined parameters, and the turning strands' lengths
  std::map<std::string, GiNaC::ex, std::less<>> defined_names_;  // the defined quantities' names
  GiNaC::exmap defined_;                                         // and their definitions
  // The model's equations (copies: a checker may outlive its analysis): the derivation's, then
  // those of the complete set of balances that the derivation's `derive:` left out.
  std::vector<Equation> equations_, rate_equations_, position_equations_;
  std::vector<std::string> position_differentiated_;
  struct BodyTerms {
    std::string name;
    GiNaC::ex mass, accel;  // its mass (0 for a massless one) and its acceleration's symbol
  };
  std::vector<BodyTerms> bodies_;
  // Each level's equations and unknowns; its algebra made by prepare(), once.
  mutable Level acceleration_, rate_, position_;
  std::size_t derivation_size_ = 0;  // the derivation's own equations, first among the acceleration level's
  std::vector<StateInput> inputs_;
  std::vector<Truth::Condition> conditions_;  // the model's stated conditions: the states it allows
  mutable std::once_flag prepared_;
  std::shared_ptr<SettledAnswers> settled_ = std::make_shared<SettledAnswers>();  // by the two sides as read
};

}  // namespace tackle

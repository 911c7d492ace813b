// Checking an equation a student wrote (a balance, a constraint, or one derived from them)
// against the derivation's own equations: correct when it holds for every motion the model
// allows (it is a combination of the derivation's equations, with coefficients in the
// parameters), named when it is one of them up to a factor, and otherwise diagnosed in the
// words of the free body diagram (a force missing, a force with the wrong sign, the inertial
// term missing, a force that acts on another body), never showing the correct equation.
#pragma once

#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <ginac/ginac.h>

#include "check/check.hpp"

namespace tackle {

/// The source of a force as a student reads it: "a strand of string s at pA", "the weight of
/// A", "the force on A", "the force of the sliding contact at A".
[[nodiscard]] std::string force_phrase(const std::string& source);

class EquationChecker {
 public:
  EquationChecker(const Analysis& analysis, const CheckOptions& options);
  /// The verdict on `text` ("2*T - F = m_A*ddot(x_A)"); invalid when it cannot be read.
  [[nodiscard]] CheckResult check(std::string_view text) const;
  /// The fewest of the derivation's equations that give `unknown = closed_form` (their
  /// labels, in the derivation's order); empty when none do or there are too many to decide.
  [[nodiscard]] std::vector<std::string> needed_for(const GiNaC::ex& unknown, const GiNaC::ex& closed_form) const;
  /// The derivation's equation with this label (the rates' and the length sums' too), or null.
  [[nodiscard]] const Equation* equation(const std::string& label) const;
  /// A length sum's (a constraint at the level of positions) equation at the level of
  /// accelerations: "string s: acceleration" for "length of string s"; empty for other labels.
  [[nodiscard]] std::string differentiated(const std::string& label) const;

 private:
  // One family of equations the student's may follow from: those at the acceleration level
  // (balances and constraints differentiated twice) or at the rate level (differentiated once),
  // with the unknowns they are linear in.
  struct Family {
    std::vector<const Equation*> equations;
    std::vector<GiNaC::ex> unknowns;
    std::vector<std::vector<GiNaC::ex>> vectors;  // each equation's coefficients: unknowns, then the rest
    mutable std::optional<std::size_t> rank;      // of those columns (made with the rest, below)
    // A basis of the vectors orthogonal to every column (made once, when it can be): a vector
    // is a combination of the columns exactly when its product with each of these is zero, a
    // sum to normalise instead of a rank to eliminate. With each at the point (when defined).
    // Made when an equation is first checked (prepared()), not with the checker: a checker
    // made for answers alone never pays for them.
    mutable std::once_flag made;
    mutable std::optional<std::vector<std::vector<GiNaC::ex>>> orthogonal;
    mutable std::vector<std::optional<std::vector<GiNaC::numeric>>> orthogonal_at;
    // Each equation's terms' vectors and its left side's (none where not linear), for the
    // diagnosis: a balance with a term left out is its vector less the term's.
    mutable std::vector<std::vector<std::optional<std::vector<GiNaC::ex>>>> term_vectors;
    mutable std::vector<std::optional<std::vector<GiNaC::ex>>> lhs_vectors;
    // The same at the point (none where not linear or not defined there).
    mutable std::vector<std::optional<std::vector<GiNaC::numeric>>> vectors_at, lhs_vectors_at;
    mutable std::vector<std::vector<std::optional<std::vector<GiNaC::numeric>>>> term_vectors_at;
  };
  [[nodiscard]] std::optional<std::vector<GiNaC::ex>> vector_of(const GiNaC::ex& residual, const Family& f) const;
  /// Whether `v` is a combination of `columns` (`rank`: theirs, when known).
  [[nodiscard]] bool in_span(const std::vector<std::vector<GiNaC::ex>>& columns, const std::vector<GiNaC::ex>& v,
                             std::optional<std::size_t> rank = std::nullopt) const;
  /// Whether `v` is a combination of the family's equations (exact; see Family::orthogonal).
  [[nodiscard]] bool in_family(const Family& f, const std::vector<GiNaC::ex>& v) const;
  /// `ap`, `bp`: the vectors at the point, when known (else made here).
  [[nodiscard]] bool proportional(const std::vector<GiNaC::ex>& a, const std::vector<GiNaC::ex>& b,
                                  const std::optional<std::vector<GiNaC::numeric>>* ap = nullptr,
                                  const std::optional<std::vector<GiNaC::numeric>>* bp = nullptr) const;
  /// `v` at the point (exact rationals), or none where an entry is not a rational number there.
  [[nodiscard]] std::optional<std::vector<GiNaC::numeric>> at_point(const std::vector<GiNaC::ex>& v) const;
  /// `f` with its orthogonal basis and vectors made (once, thread-safely).
  const Family& prepared(const Family& f) const;
  void prepare(const Family& f) const;
  [[nodiscard]] std::vector<std::string> fewest(const Family& f, const std::vector<GiNaC::ex>& v) const;
  void diagnose(const Family& f, const std::vector<GiNaC::ex>& v, CheckResult& r) const;
  /// An equation in the positions alone: one of the length sums (up to its constant)?
  [[nodiscard]] CheckResult check_position(const GiNaC::ex& residual, CheckResult r) const;

  CheckOptions options_;
  std::shared_ptr<const SymbolTable> symbols_;
  // A point of the parameters (fixed rationals): a value there that is not zero proves an
  // expression is not zero; a zero there proves nothing, and is decided exactly.
  GiNaC::exmap point_;
  GiNaC::exmap definitions_;
  std::vector<Equation> equations_, rate_equations_;  // copies: a checker may outlive its analysis
  // Each constraint's constant quantity (the length sum 3 x_B - 2 x_A), labelled as the
  // derivation prints it, and the label of its second derivative.
  std::vector<Equation> position_equations_;
  std::vector<std::string> position_differentiated_;
  struct BodyTerms {
    std::string name;
    GiNaC::ex mass, accel;  // its mass (0 for a massless one) and its acceleration's symbol
  };
  std::vector<BodyTerms> bodies_;
  Family acceleration_, rate_, position_;
};

}  // namespace tackle

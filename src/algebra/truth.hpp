// The verdict algebra: whether an equation holds in every state a model allows.
//
// A family is a model's equations at one level (its balances and constraints at the level of
// accelerations; its constraints in rates; its length sums in positions), each linear in the
// family's unknowns (forces and accelerations; rates; positions) with coefficients in
// everything else (parameters, coordinates, rates, time, with sines, cosines and roots). At a
// state (a point: algebra/states.hpp) the family is a matrix [A | e], its solutions the u with
// A u + e = 0. An equation r(u) = 0 holds at the state when it holds for every solution: for
// r = c . u + d, when (c, d) is a combination of the rows of [A | e], i.e. orthogonal to
// every vector of its null space; for any other r, at random solutions. It holds in the model
// when it holds at every state drawn. Each state's numbers are exact rationals where they can
// be (angles through rational points on the circle), so that a verdict at a state is certain;
// a root makes them CLN floats, compared within a relative tolerance.
//
// sin^2 + cos^2 = 1, tan = sin/cos, 2 sin cos = sin 2x, sqrt(x^2) = |x|: every identity the
// numbers obey holds here without being known as a rule, and every balance of the model (any
// body or system, any direction, moments about any point) is a combination of the family's.
#pragma once

#include <optional>
#include <random>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/kind.hpp"

#include "algebra/linear.hpp"
#include "algebra/program.hpp"
#include "algebra/states.hpp"

namespace tackle {

/// `e`'s coefficients of each unknown, then the rest (free of them); none when `e` is not a
/// polynomial of degree at most one in them.
[[nodiscard]] std::optional<std::vector<GiNaC::ex>> linear_parts(const GiNaC::ex& e,
                                                                 const std::vector<GiNaC::ex>& unknowns);

struct Family {
  std::vector<std::string> labels;
  std::vector<GiNaC::ex> residuals;  // lhs - rhs of each equation, definitions put in
  std::vector<GiNaC::ex> unknowns;
  // Position level: each equation keeps a constant of its own (a string's length), so the rest
  // (the last part) of an equation says nothing and is dropped.
  bool free_constants = false;
};

class Truth {
 public:
  enum class Answer { holds, fails, unknown };
  struct Decision {
    Answer answer = Answer::unknown;
    bool exact = false;  // every number it rests on exact
  };
  /// Values of a vector of parts (as linear_parts gives) at each point, or none where one is
  /// not defined.
  using Values = std::optional<std::vector<Row>>;

  Truth() = default;
  /// `points`: the states, the first `fixed` of them the fixed ones (the diagnoses use those
  /// alone, so that what a student is told does not change from run to run).
  Truth(Family family, const States& states, std::vector<Sample> points, std::size_t fixed,
        const GiNaC::exmap& definitions, Tolerance tolerance);

  [[nodiscard]] const Family& family() const { return family_; }
  /// Every equation linear in the unknowns, defined and consistent at every point: the family
  /// can decide.
  [[nodiscard]] bool usable() const { return usable_; }
  [[nodiscard]] std::size_t points() const { return points_.size(); }
  [[nodiscard]] std::size_t fixed() const { return fixed_; }

  /// The parts' values at the points from `first` (all of them, or the fixed ones only).
  [[nodiscard]] Values values(const std::vector<GiNaC::ex>& parts, bool fixed_only = false,
                              std::size_t first = 0) const;
  /// The equation `i`'s parts' values at every point.
  [[nodiscard]] const std::vector<Row>& equation_values(std::size_t i) const { return at_rows_[i]; }
  /// Whether the linear equation with these values (at the first points, or all) holds at
  /// those points: it fails at one, or holds at all of them; unknown when it holds there and
  /// they are not past the fixed ones.
  [[nodiscard]] Decision holds(const std::vector<Row>& values) const;
  /// The model's stated conditions (`lhs op rhs`, op one of >=, <=, >, <), so that a random
  /// solution where one fails (a suitcase that tips: N_A < 0) is not a state the model
  /// allows; an equality or a condition that cannot be evaluated there restricts nothing.
  struct Condition {
    GiNaC::ex lhs, rhs;
    std::string op;
  };
  void restrict_to(const std::vector<Condition>& conditions);
  /// Which sign of lhs - rhs a condition's `op` asks for: +1 for >= and >, -1 for <= and <, 0
  /// for an equality (which restricts no state).
  [[nodiscard]] static int sign_asked(const std::string& op);
  /// Whether `residual` (any expression in the unknowns and the inputs) vanishes at random
  /// solutions at every point, those where a stated condition fails left out.
  [[nodiscard]] Decision holds_anyhow(const GiNaC::ex& residual) const;
  /// Whether `residual` vanishes whatever the unknowns are (random values, not solutions).
  [[nodiscard]] Decision vanishes(const GiNaC::ex& residual) const;
  /// Whether two vectors of values are multiples of each other at every point given.
  [[nodiscard]] bool proportional(const std::vector<Row>& a, const std::vector<Row>& b) const;
  /// The fewest equations a holding equation is a combination of (their places, the family's
  /// earlier equations kept first), with whether each coefficient is a plain number (the same
  /// at the points, relative to the first's; the first is plain when all the others are).
  struct Part {
    std::size_t equation;
    bool plain;
  };
  [[nodiscard]] std::vector<Part> combination(const std::vector<Row>& values) const;
  /// A random solution at point k (the unknowns' values), none when the family has none there.
  [[nodiscard]] std::optional<Row> solution(std::size_t k, std::mt19937& rng) const;
  [[nodiscard]] const Sample& point(std::size_t k) const { return points_[k]; }

 private:
  Family family_;
  Sample layout_;  // the states' inputs, then the unknowns that are not inputs
  std::vector<bool> angles_;
  std::vector<std::size_t> unknown_at_;  // each unknown's place in layout_
  GiNaC::exmap definitions_;
  Tolerance tolerance_;
  std::vector<Sample> points_;  // over the states' inputs
  std::size_t fixed_ = 0;
  std::vector<std::vector<Row>> at_rows_;  // [equation][point]: its parts' values
  std::vector<std::vector<Row>> null_;     // [point]: the null space of [A | e]
  // The equations a combination is written in (independent at the first point, the earlier
  // kept first), and at each point their left inverse (none where they are not independent).
  std::vector<std::size_t> basis_;
  std::vector<std::optional<LeftInverse>> inverses_;
  struct Stated {
    Program difference;  // lhs - rhs
    int sign;            // +1: >= or > (the difference must not be negative), -1: <= or <
  };
  std::vector<Stated> conditions_;
  // Whether each point is a state the model allows (its one solution meets the stated
  // conditions); empty: every point (no conditions, or none of the points meets them).
  std::vector<bool> allowed_points_;
  bool usable_ = false;
  [[nodiscard]] bool allowed_point(std::size_t k) const { return allowed_points_.empty() || allowed_points_[k]; }
  // Whether the stated conditions hold (within the tolerance) at point k with these unknowns.
  [[nodiscard]] bool allowed(std::size_t k, const Row& unknowns) const;
  void prepare_basis();

  [[nodiscard]] std::size_t width() const { return family_.unknowns.size() + 1; }
  // Some points past the fixed ones: anyone can find the fixed points, so that an equation
  // built to hold at them alone must not be found to hold.
  [[nodiscard]] bool fresh() const { return points_.size() > fixed_; }
  [[nodiscard]] Sample extended(std::size_t k, const Row& unknowns) const;
};

}  // namespace tackle

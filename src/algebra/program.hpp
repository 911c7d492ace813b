// A Program: an expression made once into code over a point's inputs and evaluated at any
// number of points, exactly (rationals) as long as the operations allow and in CLN floats
// after that. The verdict algebra (algebra/truth.hpp) and the answer checker evaluate every
// expression they compare this way: walking an expression node by node at each point (GiNaC
// makes the products' factors anew for each visit) was half the time of a check.
//
// Angles are exact too. An input marked as an angle holds t = tan(angle/2) in a point, a
// rational, so that its cosine (1 - t^2)/(1 + t^2) and sine 2t/(1 + t^2) are rationals: a
// point on the circle, where sin^2 + cos^2 = 1 holds exactly. sin, cos and tan of a whole
// multiple of angles (2 theta, theta - phi) plus a multiple of pi/2 are then exact rationals;
// an angle anywhere else (theta alone, theta/2) is a float, 2 atan(t).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <cln/real.h>
#include <ginac/ginac.h>

#include "core/kind.hpp"

namespace tackle {

/// One point: each input symbol and its value (for an angle input: tan(angle/2)).
using Sample = std::vector<std::pair<GiNaC::ex, GiNaC::numeric>>;

class Program {
 public:
  Program() = default;  // evaluates to nothing
  /// `e` over the inputs of `layout` (their values there do not matter); a symbol that is not
  /// an input is replaced by its entry in `definitions` (to 8 levels), else the program gives
  /// nothing. `angles`: the inputs (by their place in `layout`) that are angles.
  Program(const GiNaC::ex& e, const Sample& layout, const GiNaC::exmap& definitions,
          const std::vector<bool>& angles = {});
  /// The value at `point` (same inputs as the layout), or nothing: a symbol without a value, a
  /// division by zero, a complex value, a number past the bounds.
  [[nodiscard]] std::optional<GiNaC::numeric> operator()(const Sample& point) const;
  /// The value at `point` in doubles (each input's value as a double, in the layout's order),
  /// NaN for nothing: a screen, never a verdict (an exact evaluation confirms what it passes).
  /// With `sin_cos_swapped`, the value of `e` with sin written for cos and cos for sin
  /// everywhere (a diagnosis's screen, without making that expression).
  [[nodiscard]] double approx(const std::vector<double>& point, bool sin_cos_swapped = false) const;
  [[nodiscard]] bool empty() const { return nodes_.empty(); }

 private:
  enum class Op { number, input, angle, nothing, add, mul, power, function, trig };
  struct Node {
    Op op;
    cln::cl_R number;       // number
    std::size_t index = 0;  // input, angle: the input's place in a point
    unsigned serial = 0;    // function, trig
    std::size_t n = 0;      // add, mul: how many operands follow; trig: how many (index, multiple) pairs follow
    long multiple = 0;      // trig: pi/2 added this many times; a pair: the angle's multiple
    double approx = 0;      // number: as a double
  };
  struct Value;              // a fraction kept unreduced, or a float
  std::vector<Node> nodes_;  // in preorder
  void emit(const GiNaC::ex& e, const Sample& layout, const GiNaC::exmap& definitions, const std::vector<bool>& angles,
            int depth);
  bool emit_trig(const GiNaC::ex& e, const Sample& layout, const std::vector<bool>& angles);
  bool run(std::size_t& at, const Sample& point, Value& out) const;
  bool run_power(std::size_t& at, const Sample& point, Value& out) const;
  bool run_function(const Node& node, std::size_t& at, const Sample& point, Value& out) const;
  bool run_trig(const Node& node, std::size_t& at, const Sample& point, Value& out) const;
  double run_double(std::size_t& at, const std::vector<double>& point, bool swapped) const;
};

/// A point's values as doubles, in its order (for Program::approx).
[[nodiscard]] std::vector<double> doubles_of(const Sample& point);

/// The angle's value at a point from its t = tan(angle/2): 2 atan(t), a float.
[[nodiscard]] GiNaC::numeric angle_of(const GiNaC::numeric& t);
/// t = tan(angle/2) for an angle, a rational within about 10^-12 of it.
[[nodiscard]] GiNaC::numeric half_tangent(double angle);

}  // namespace tackle

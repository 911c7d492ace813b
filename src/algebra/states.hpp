// The states a verdict is decided at: a value for each input of a problem (its parameters,
// and for equations its coordinates, rates and time), exact positive or negative rationals
// near the value the problem gives (between half and twice it), or between 1 and 10 where it
// gives none. An angle's input is t = tan(angle/2) (algebra/program.hpp), near the given
// angle's, or between 1/10 and 1 (6 to 90 degrees) where none is given.
//
// Fixed points come from a fixed seed, the same in every run: they settle quickly what differs
// and feed the diagnoses. Since anyone can find them, a verdict of `correct` never rests on
// them alone but on fresh points, drawn from std::random_device (a seed makes them
// reproducible, for tests only).
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include <ginac/ginac.h>

#include "core/kind.hpp"

#include "algebra/program.hpp"

namespace tackle {

struct StateInput {
  GiNaC::ex symbol;
  std::optional<GiNaC::numeric> base;  // drawn near this (an angle's: its t), else from a range
  bool angle = false;
};

class States {
 public:
  States() = default;
  explicit States(std::vector<StateInput> inputs);
  /// The inputs as a point's layout (their values: the bases, or 1).
  [[nodiscard]] const Sample& layout() const { return layout_; }
  [[nodiscard]] const std::vector<bool>& angles() const { return angles_; }
  [[nodiscard]] const std::vector<StateInput>& inputs() const { return inputs_; }
  /// The k-th fixed point (coarse: values to 3 digits, the same in every run).
  [[nodiscard]] Sample fixed(int k) const;
  /// A point drawn from `rng`, finer (values to 7 digits).
  [[nodiscard]] Sample draw(std::mt19937& rng) const;
  /// A random generator for fresh points: from `seed` when given, else std::random_device
  /// (the clock where there is none).
  [[nodiscard]] static std::mt19937 generator(const std::optional<std::uint64_t>& seed);

 private:
  std::vector<StateInput> inputs_;
  Sample layout_;
  std::vector<bool> angles_;
  [[nodiscard]] GiNaC::numeric value(const StateInput& in, std::mt19937& rng, long fine) const;
};

/// An input drawn near `value` (an exact value, or any expression that evaluates to a real
/// number: a rational within 10^-6 of it); none, zero or no number: drawn from a range.
[[nodiscard]] StateInput input_near(const GiNaC::ex& symbol, const std::optional<GiNaC::ex>& value, bool angle);

/// The symbols that are angles in `e`: those inside the argument of a sin, cos or tan.
void angles_in(const GiNaC::ex& e, GiNaC::exset& out);

}  // namespace tackle

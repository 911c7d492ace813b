// The oracle's numbers (issue 41, item 2): the cross-check's model solved at several draws of
// the parameters and several states, and the truth of a student's equation or answer decided
// from those numbers alone, with the cross-check's own parser (expr.hpp), never from tackle's
// verdicts. What the oracle takes from tackle is said in model.hpp and docs/crosscheck.md.
#pragma once

#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "crosscheck/model.hpp"

namespace crosscheck {

/// One state of the model at one draw of the parameters: every number an expression can name.
struct World {
  int draw = 0;                                 // 0: the description's own values
  std::map<std::string, double> values;         // parameters, coordinates, rates, t, solved quantities
  std::map<std::string, Eigen::VectorXd> free;  // a solved quantity's parts the model leaves free
  int free_directions = 0;
  double scale = 1;  // the largest force (at least the largest m g): "near 0"
  double accel_scale = 1;
  State state;
  Instant instant;
  std::vector<std::string> parameters;  // the names of values that no state changes
};

struct WorldOptions {
  int draws = 3;         // draws of the parameters: the first the description's values
  int states = 3;        // per draw: the layout, then random states near it
  double spread = 1.25;  // a later draw multiplies each value by a factor from 1/spread to spread
};

/// A named quantity tackle makes that the description does not (a turning strand's length
/// l_CP), as text in the description's names: evaluated in each world.
using Definitions = std::vector<std::pair<std::string, std::string>>;

/// The description with each parameter's value times a random factor (defined ones follow).
[[nodiscard]] tackle::Description redrawn(const tackle::Description& d, std::mt19937_64& rng, double spread);
/// The worlds of a description (throws Unsupported where the model cannot express it).
[[nodiscard]] std::vector<World> make_worlds(const tackle::Description& d, std::mt19937_64& rng, const WorldOptions& o,
                                             const Definitions& definitions);

enum class Truth { holds, fails, unknown };
struct Judgement {
  Truth truth = Truth::unknown;
  std::string why;   // unknown: why the model cannot decide; fails: where it fails
  double worst = 0;  // the largest relative residual found
  // holds whatever the forces, accelerations, rates and coordinates are (`T = T`, `0 = 0`):
  // true, and says nothing about the problem
  bool tautology = false;
};

/// Whether `equation` ("lhs = rhs") holds in every world. An equation in coordinates and
/// parameters alone (no force, rate or acceleration) with a constant (`const`, or a number)
/// is a length sum: it holds when lhs - rhs is the same at every state of a draw.
[[nodiscard]] Judgement judge_equation(const std::string& equation, const std::vector<World>& worlds);
/// Whether `answer` is the model's value of `unknown` in every world.
[[nodiscard]] Judgement judge_answer(const std::string& unknown, const std::string& answer,
                                     const std::vector<World>& worlds);

}  // namespace crosscheck

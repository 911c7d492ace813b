// Free body diagrams for the oracle (issue 41, item 2): a body's diagram drawn from the model's
// own forces on it at the sketch's position (Model::forces_on), right (each force at its
// point along its line, the sense where it is known; a force of unknown sense either way, one
// of unknown direction as `any`), or with an arrow dropped, turned, moved, tilted or added;
// judged against the model's forces by a matching of arrows to forces (a force of unknown
// direction may take its components, drawn at one point, as docs/checking.md allows), and
// checked by tackle's check_fbd.
#pragma once

#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "check/check.hpp"
#include "crosscheck/model.hpp"
#include "crosscheck/variants.hpp"
#include "crosscheck/worlds.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

struct Arrow {
  std::string name, at;
  std::optional<Eigen::VectorXd> direction;  // none: `any`
  bool couple = false;
  int sense = 0;   // a couple's: +1 counterclockwise, -1 clockwise, 0 any
  int force = -1;  // the model's force it was drawn for (-1: one added)
};

struct Diagram {
  std::string body;
  std::vector<Arrow> arrows;
  std::vector<BodyForce> forces;                     // the model's, at the sketch
  std::map<std::string, Eigen::VectorXd> positions;  // every named point's and body's there
};

/// A diagram of a body of the description, of a family drawn at random; nothing where the
/// model cannot draw the body's forces (a damper's, a couple in space).
[[nodiscard]] std::optional<Variant> make_diagram(const tackle::Description& d, std::mt19937_64& rng);
/// Whether its arrows are the model's forces on its body, one for one.
[[nodiscard]] Judgement judge_diagram(const Diagram& g);
/// tackle's verdict on the diagram (its YAML read by tackle's reader, checked by check_fbd).
[[nodiscard]] tackle::CheckResult check_diagram(const tackle::Analysis& a, const std::string& yaml);

}  // namespace crosscheck

// Free body diagrams for the oracle (issue 41, item 2): diagrams made from the model's own
// forces on a body at the sketch's position, right or with an arrow dropped, turned or added,
// judged against the model's forces and checked by tackle's check_fbd.
#pragma once

#include <optional>
#include <random>
#include <string>

#include "crosscheck/variants.hpp"
#include "crosscheck/worlds.hpp"
#include "check/check.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

/// A diagram (YAML text) of a body of the description, of a family drawn at random.
[[nodiscard]] std::optional<Variant> make_diagram(const tackle::Description& d, const tackle::Analysis& a, std::mt19937_64& rng);
/// Whether the diagram draws the model's forces on its body.
[[nodiscard]] Judgement judge_diagram(const tackle::Description& d, const std::string& diagram);
/// tackle's verdict on the diagram.
[[nodiscard]] tackle::CheckResult check_diagram(const tackle::Analysis& a, const std::string& diagram);

}  // namespace crosscheck

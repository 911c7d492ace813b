// The forces on a body as a free body diagram shows them: each load split into one arrow per
// unknown it carries (a contact's N apart from its mu N) and what is known. The figures draw
// these parts; the checker of a student's free body diagram compares arrows with them.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace tackle {

/// The forces internal to a system of bodies: the keys (force_key of a load's origin) whose
/// loads on the system's bodies add up to nothing. Empty for one body.
[[nodiscard]] std::set<std::string> internal_forces(const Model& m, const std::vector<int>& bodies);

/// A part of a force vector.
struct ForcePart {
  /// The unknown the part carries (its direction: `coefficients`, in the model's axes, for a
  /// positive unknown); 0 for the known remainder, which is then `coefficients` itself.
  GiNaC::ex unknown = 0;
  GiNaC::ex key = 1;  // a dimensionless factor that makes a term its own force (mu in mu N)
  Vec coefficients = zero_vec();
  std::array<double, 3> numbers{0, 0, 0};  // the coefficients at the numbers (an unknown's part)
};

using NumberAt = std::function<std::optional<double>(const GiNaC::ex&)>;

/// `force` split into parts: for each unknown (in the model's order of candidates) that it is
/// linear in, one part per dimensionless factor (sorted by its text), kept only where the
/// direction can be evaluated by `number` and is not zero; then the rest, when it is not zero
/// (as written when no unknown was split off, expanded otherwise).
[[nodiscard]] std::vector<ForcePart> split_force(const Model& m, const Vec& force,
                                                 const std::set<GiNaC::ex, GiNaC::ex_is_less>& unknowns,
                                                 const NumberAt& number);

}  // namespace tackle

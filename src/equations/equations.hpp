// The EquationSystem: labelled equations with provenance. Linear momentum balance for each
// body (or a chosen system of bodies), and for each constraint its quantity, differentiated
// once and twice in time. Only the acceleration-level equations enter the solve; the
// quantity and its rate are kept for the derivation.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace tackle {

struct Equation {
  enum class Kind { lmb, amb, constraint_acceleration, constraint_rate, constraint_position, interval, impact } kind;
  std::string label;  // "LMB A (x)", "AMB board about G (axis OG)", "string s: acceleration"
  GiNaC::ex lhs, rhs;
  std::vector<std::string> sources;  // where each term of the lhs comes from
  std::vector<GiNaC::ex> terms;      // the lhs terms, one per source
  std::string why;                   // amb: what the choice of point or axis eliminates
  std::vector<int> bodies;           // lmb, amb: the body or the system balanced
  bool system = false;
  std::vector<GiNaC::ex> built;  // lmb: the same terms as built, not expanded (for units)
  // lmb, amb: the load each term comes from, one per source (empty: no term is a load's). Its
  // initializer keeps the aggregates written without it free of missing-initializer warnings.
  std::vector<LoadOrigin> origins = {};
};

/// A constraint as the derivation shows it: the constant quantity, its rate, its acceleration.
struct ConstraintSteps {
  std::string label;
  std::string meaning;
  GiNaC::ex quantity;
  GiNaC::ex rate;          // d/dt of the quantity (= 0)
  GiNaC::ex acceleration;  // d2/dt2 of the quantity (= 0)
  GiNaC::ex constant = 0;  // the named constant the quantity keeps (C_s), when one was made
};

struct EquationSystem {
  std::vector<Equation> equations;  // what is solved
  std::vector<ConstraintSteps> constraints;
  std::vector<GiNaC::ex> unknowns;  // candidates that appear in the equations, in order
  // The same constraints once differentiated (rates) and undifferentiated (positions, equal
  // to their constant), for velocity and position questions.
  std::vector<Equation> rate_equations;
  std::vector<Equation> position_equations;
};

[[nodiscard]] EquationSystem build_equations(const Model& m);

/// Every force in a linear momentum balance must be a force: one problem per term that is
/// not, naming where it comes from (empty when all are).
[[nodiscard]] std::vector<Diagnostic> check_dimensions(const Model& m, const EquationSystem& s);

/// Linear momentum balance of a body or a system, along a unit direction.
[[nodiscard]] Equation lmb_along(const Model& m, const std::vector<int>& bodies, bool system, const Vec& direction,
                                 const std::string& direction_label);
/// Angular momentum balance about a point, along a unit direction (the axis, or a coordinate
/// direction for one component of the vector balance).
[[nodiscard]] Equation amb_along(const Model& m, const std::vector<int>& bodies, bool system, const Vec& about,
                                 const std::string& about_label, const Vec& direction,
                                 const std::string& direction_label);

/// Whether body `body` is a particle: no angle, inertia or drawn size, and every load at its
/// center of mass (or at another particle's, touching it); no balance of its moments is
/// written for it (the idealized points of its contacts could not carry one).
[[nodiscard]] bool particle(const Model& m, int body);

}  // namespace tackle

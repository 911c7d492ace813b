// The ends of phases: where an interval of constant acceleration ends (the rates its
// description leaves open, found from the solved acceleration), and what an impact leaves
// (momentum conserved, the bodies stuck together or parted by a restitution). Phases chain
// these: the state at the end of one is carried into the next (pipeline/).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"
#include "solve/solve.hpp"

namespace tackle {

/// The rates at the end of an interval: given in `to`, or found from the constant
/// acceleration: v = v0 + a T over a duration T (the distance covered is v0 T + a T^2/2);
/// over a distance s, v^2 = v0^2 + 2 a s with v taking the sign of s, which is the rate the
/// first time the body has moved by s, when it gets there (the conditions in `reaches`).
struct IntervalEnd {
  struct Rate {
    int body = -1;
    GiNaC::ex rate;                         // the body's rate symbol, dot(y)
    GiNaC::ex from;                         // at the start
    GiNaC::ex accel;                        // the constant acceleration (closed form), when found
    GiNaC::ex value;                        // at the end (closed form)
    bool given = false;                     // from `to`
    std::optional<GiNaC::ex> displacement;  // over a duration: v0 T + a T^2/2
    // Over a distance s, the body gets there: v0^2 + 2 a s >= 0, and it moves towards s at the
    // start or accelerates towards it (v0 s > 0 or a s > 0); each `expr >= 0` or `expr > 0`.
    std::vector<std::pair<GiNaC::ex, std::string>> reaches;
    std::optional<bool> reaches_holds;  // with the given numbers
  };
  std::vector<Rate> rates;
  std::string problem;  // why an end rate could not be found ("" when all were)
};

/// The interval's end state; needs the solved accelerations of the bodies whose end is open.
[[nodiscard]] IntervalEnd interval_end(const Model& m, const Solution& sol);

/// An impact: momentum balance of the colliding bodies (no external impulse: the finite forces
/// give none while it lasts), plus the bodies sticking together or the restitution, solved for
/// the rates just after; the impulse on each body and the kinetic energy lost.
struct ImpactResult {
  std::vector<Equation> equations;  // momentum, then sticking (or restitution)
  struct After {
    int body = -1;
    GiNaC::ex rate;                     // dot(y_P): the rate just after
    GiNaC::ex before;                   // the rate just before
    GiNaC::ex after;                    // closed form
    GiNaC::ex impulse_symbol, impulse;  // J_P = m_P (after - before)
  };
  std::vector<After> after;
  GiNaC::ex energy_before, energy_after, energy_lost;  // energy_lost = before - after, closed form
  GiNaC::ex energy_lost_symbol;
};

[[nodiscard]] ImpactResult analyze_impact(const Model& m);

/// The state at a phase's end, for `carry`: each body rate -> its value there (the interval's
/// end, or the impact's rates after), plus what the phase's answers came to.
[[nodiscard]] GiNaC::exmap end_state(const Model& m, const Solution& sol, const std::optional<IntervalEnd>& end,
                                     const std::optional<ImpactResult>& impact);

}  // namespace tackle

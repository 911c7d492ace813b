// The power balance, an independent check of every derivation: the rate of change of the
// bodies' kinetic energy equals the power of the forces on them,
//   d/dt(E_k) = sum over bodies of m v.a = sum over loads of F.v = P,
// with the constraint forces doing no work. It is written from the model (velocities from
// the coordinates, forces from the loads), apart from the momentum balances, and holds once
// the solved accelerations and forces are put in and the velocities obey the constraints.
#pragma once

#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct PowerCheck {
  enum class Status { holds, fails, not_applicable } status = Status::not_applicable;
  std::string reason;             // not_applicable: why, in words
  GiNaC::ex kinetic_rate = 0;     // sum of m v.a, in the rates and accelerations
  GiNaC::ex power = 0;            // sum of F.v, in the forces and rates
  std::vector<GiNaC::ex> speeds;  // speed symbols made for bodies moving without a coordinate
  GiNaC::ex residual = 0;         // fails: d/dt(E_k) - P with everything solved put in
};

[[nodiscard]] PowerCheck check_power(const Model& m, const EquationSystem& s, const Solution& sol);

}  // namespace tackle

// What the motion's steps share across src/motion/motion*.cpp (not an interface of the
// stage; see motion.hpp): the dependent coordinates and rates and how they are put in, and
// the state analyze_motion's steps work on, one step a function.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"
#include "motion/motion.hpp"
#include "solve/solve.hpp"

namespace tackle::motion_detail {

/// Whether `e` is zero once normal() has put it over one denominator.
[[nodiscard]] bool zero(const GiNaC::ex& e);

/// Whether `e` varies with the state: the coordinates, the rates and the turning lengths.
[[nodiscard]] bool depends_on_state(const GiNaC::ex& e, const std::vector<GiNaC::ex>& state, const Model& m);

// The dependent coordinates and rates in terms of the independent ones: rates from the
// constraints' rate equations, coordinates from the constraint quantities keeping their
// values at t = 0 (which needs those coordinates' initial values).
struct Dependents {
  GiNaC::exmap rates, coords;
  GiNaC::exmap definitions;  // the defined parameters (y_s = (m + M) g/k), put in so that terms cancel
  std::string problem;
};

/// The dependent coordinates and rates that `needed` asks for (a problem when a starting
/// value they need is not given).
[[nodiscard]] Dependents dependents(const Model& m, const EquationSystem& s, const Solution& sol,
                                    const MotionSpec& spec, const GiNaC::ex& needed);

/// `e` with the defined parameters, the dependent coordinates and the dependent rates put in.
[[nodiscard]] GiNaC::ex put_in(const GiNaC::ex& e, const Dependents& d);

/// What analyze_motion's steps share: its inputs, the motion being made, and the dependent
/// coordinates and rates that the steps put in.
struct MotionStory {
  const Model& m;
  const EquationSystem& s;
  const Solution& sol;
  const MotionSpec& spec;
  const SymbolTable& table;
  Motion& out;
  EquationsOfMotion& eom;
  std::vector<GiNaC::ex> state{};  // the motion's coordinates, then its rates
  // What needs the dependents: the accelerations, then also the quantities asked for and the
  // validity conditions.
  GiNaC::ex all = 0;
  Dependents for_accelerations{}, for_all{};
  const Dependents* dep = nullptr;  // for_all, or for_accelerations where for_all has a problem
  bool mass_constant = true;        // the mass matrix is constant (and invertible)

  /// A coordinate (or rate) of a body that is neither the motion's nor given by it.
  [[nodiscard]] std::optional<GiNaC::ex> unplaced(const GiNaC::ex& e) const;
};

/// One degree of freedom, linear: the response in closed form (or why there is none).
void closed_form_response(MotionStory& st);

/// The quantities asked for and the validity conditions along the closed-form response.
void along_response(MotionStory& st);

}  // namespace tackle::motion_detail

// Equations of motion in the mass-matrix form, M(q) q'' = F(q, q', t), without solving the
// instant: each body's balances projected on the partial velocities of the motion's
// coordinates (Kane's method, d'Alembert's principle in the form of virtual power). For each
// coordinate q_i,
//   sum over bodies of (m a . dv/dq'_i + I alpha dw/dq'_i)
//     = sum over loads of (F . dv_P/dq'_i + M dw/dq'_i),
// v_P the velocity of the body's material point where the load acts. When the coordinates
// describe every body (no constraint is left between them: a chain of links whose centers
// are written in the angles of the links above), every joint force does no work on any
// motion the coordinates allow, so the forces the rules leave unknown drop out. A chain of
// n links so gets its n equations in O(n^3) terms, where the closed-form accelerations are
// ratios of n x n determinants in sines and cosines.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace tackle {

struct MassForm {
  GiNaC::matrix M{0, 0};     // M_ij, symmetric, in the coordinates and parameters
  std::vector<GiNaC::ex> F;  // F_i, in the coordinates, rates, parameters and t
  bool mass_varies = false;  // M depends on the coordinates
};

/// The motion's equations in the mass-matrix form; nothing (with `why_not` said) when the
/// motion's coordinates do not describe every body or an unknown force does not drop out.
[[nodiscard]] std::optional<MassForm> mass_form(const Model& m, std::string& why_not);

/// Why the instant is left to the motion (empty: it is solved): the description asks nothing
/// of it (no 'find', no given value) and its closed forms would be
/// ratios of determinants of a mass matrix that turns with the coordinates (two degrees of
/// freedom or more), while the motion has its equations in the mass-matrix form.
/// The mass-matrix form comes with it, made once.
struct LeftToMotion {
  std::string why;
  std::shared_ptr<const MassForm> form;
};
[[nodiscard]] LeftToMotion instant_left_to_motion(const Model& m);

/// The small oscillations of the mass-matrix form about q = 0, q' = 0 where it rests
/// (F(0, 0) = 0, no time): M0 q'' + C0 q' + K0 q = 0 with M0 = M(0), K0 = -dF/dq and C0 =
/// -dF/dq' there. Nothing when it does not rest there.
struct MassFormAtRest {
  GiNaC::matrix M0{0, 0}, C0{0, 0}, K0{0, 0};
};
[[nodiscard]] std::optional<MassFormAtRest> at_rest(const Model& m, const MassForm& f);

/// The frequencies of small oscillations ddot(q) = -K q (K per unit of inertia), with the
/// given values: the square roots of K's eigenvalues, ascending (0 for a free mode). Nothing
/// when q = 0 is not a stable rest; empty when there are no numbers to tell.
[[nodiscard]] std::optional<std::vector<double>> small_oscillations(const Model& m, const GiNaC::matrix& K);

struct EquationsOfMotion;
struct Motion;
/// The mass-matrix form into `eom` (M, forcing, mass_form), when the mass matrix turns with
/// the coordinates: `made`, or made here. False when there is none.
bool take_mass_form(const Model& m, EquationsOfMotion& eom, std::shared_ptr<const MassForm> made = nullptr);
/// The motion of an instant left unsolved (instant_left_to_motion): its equations in the
/// mass-matrix form `f` and their small oscillations about rest, in `out.eom`; the validity
/// conditions are not followed (their forces are not solved for).
void follow_mass_form(const Model& m, const std::shared_ptr<const MassForm>& f, Motion& out);

}  // namespace tackle

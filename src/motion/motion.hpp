// Motion in time, the stage after the instant: from the solved accelerations, the equations
// of motion of the independent coordinates (constraint forces eliminated), in the form
//   M q'' + C q' + K q = F(t)
// when they are linear with constant coefficients (M from the kinetic energy, so the form is
// the one a person writes: (m + M) y'' + k y = 0); for one degree of freedom their solution
// in closed form from the initial conditions (natural frequency, damping ratio, free and
// forced response); then every quantity asked for and every validity condition as functions
// of time, with their extremes and the conditions that keep the model valid for all t.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "equations/equations.hpp"
#include "model/model.hpp"
#include "numeric/evaluate.hpp"
#include "solve/solve.hpp"

namespace tackle {

struct EquationsOfMotion {
  std::size_t dof = 0;     // degrees of freedom
  std::size_t moving = 0;  // coordinates of moving bodies, before the constraints
  std::vector<GiNaC::ex> q, dq, ddq;
  // ddot(q_i) = f_i(q, dot(q), t), the constraint forces eliminated and the dependent
  // coordinates and rates put in.
  std::vector<GiNaC::ex> acceleration;
  // Linear with constant coefficients: M q'' + C q' + K q = F(t); else `nonlinear` says why.
  bool linear = false;
  std::string nonlinear;
  GiNaC::matrix M, C, K;  // M is made whenever it is constant (also for nonlinear motion)
  // The instant left unsolved (instant_left_to_motion): the equations in the mass-matrix
  // form M(q) q'' = F(q, q', t), M in the coordinates and `forcing` F; no `acceleration`.
  bool mass_form = false;
  std::vector<GiNaC::ex> forcing;
  std::optional<std::vector<GiNaC::ex>> equilibrium;  // K q = F, when F is constant and K invertible
  // More than one degree of freedom, linear, with numbers: the undamped natural frequencies
  // (rad/s, ascending), numeric: square roots of the eigenvalues of M^-1 K (Eigen).
  std::vector<double> natural_frequencies;
  // One nonlinear degree of freedom with no damping or forcing in time, at rest at q = q0
  // (ddot(q) = 0 there): the small oscillations about it, ddot(q) = -lambda^2 (q - q0), with
  // lambda^2 = -d f/d q at q0 (the pendulum's g/l), when that is positive with the numbers.
  struct Linearised {
    GiNaC::ex about;               // q0
    GiNaC::ex stiffness;           // lambda^2 = -df/dq at q0 (per unit of the coordinate's inertia)
    std::optional<double> lambda;  // rad/s, with the numbers
    // More than one degree of freedom: ddot(q) = -K q about q = 0, K_ij = -df_i/dq_j there,
    // and the natural frequencies of small oscillations, sqrt of K's eigenvalues (numbers).
    GiNaC::matrix stiffness_matrix{0, 0};
    std::vector<double> frequencies;
  };
  std::optional<Linearised> linearised;
};

/// The closed-form response of one linear degree of freedom from its initial conditions.
struct Response {
  enum class Regime { undamped, underdamped, critically_damped, overdamped, free_particle, damped_particle } regime;
  GiNaC::ex q;                      // q(t), in lambda, zeta, omega_d where they appear
  GiNaC::ex rate;                   // dot(q)(t)
  GiNaC::ex particular;             // the forced part (0 for free motion)
  GiNaC::ex forcing_frequency = 0;  // w of a harmonic forcing (0 when there is none)
  GiNaC::ex homogeneous;            // the free part, its constants fixed by the initial conditions
  // Quantities the response is written in, with their definitions (lambda = sqrt(k/(m + M))).
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> definitions;
  // Conditions the form assumes (zeta < 1, omega != lambda), in words and as expressions.
  struct Assumption {
    GiNaC::ex lhs, rhs;
    std::string op;   // <, !=, ...
    std::string why;  // "underdamped", "no resonance"
  };
  std::vector<Assumption> assumptions;
  bool verified = false;  // put back into the equation of motion at random parameter values and times
};

/// A validity condition of the instant, followed in time along the response.
struct ConditionInTime {
  Condition condition;  // the model's (a copy: a report keeps it after the analysis is gone)
  GiNaC::ex of_t;       // the condition's expression along the response: the condition is `of_t op 0`
  // The least (for >=, >) or greatest (for <=, <) value over all t, in closed form, and the
  // condition for all t (`extreme op 0`) solved for the parameters where it can be.
  std::optional<GiNaC::ex> extreme;
  std::optional<GiNaC::ex> extreme_at;  // the first t >= 0 at which it is reached
  std::vector<SolvedFor> solved;
  std::optional<bool> holds_for_all_t;     // with the given numbers
  std::optional<GiNaC::ex> first_failure;  // the first t at which it fails, in closed form
  std::optional<double> first_failure_s;   // the same in seconds (numeric)
  // Under a harmonic forcing: the condition in the steady state (the forced part alone),
  // alpha + beta cos(w t) + gamma sin(w t) op 0. It holds for all t exactly when alpha >= 0
  // and alpha^2 - beta^2 - gamma^2 >= 0 (for >=); the second, a quadratic in w^2 with two
  // roots, fails in a band of driving frequencies (or outside it).
  std::optional<GiNaC::ex> steady_of_t;
  std::optional<GiNaC::ex> steady_offset;               // alpha: must keep its sign
  std::optional<GiNaC::ex> steady_amplitude_condition;  // alpha^2 - beta^2 - gamma^2, its numerator (>= 0)
  struct Band {
    GiNaC::ex variable;   // w^2
    GiNaC::ex low, high;  // the roots, low < high with the given numbers
    bool fails_between = true;
  };
  std::optional<Band> band;
  std::optional<bool> steady_holds;  // with the given numbers
};

struct QuantityInTime {
  std::string name, tex;
  GiNaC::ex symbol;
  GiNaC::ex of_t;
  std::optional<Dimension> dimension;
};

/// The speed where a coordinate reaches a value, from the work-energy balance
/// (1/2 M v^2 - 1/2 M v0^2 = the work of the forces from q0 to q), one degree of freedom,
/// forces that depend on the position only.
struct EnergyAnswer {
  GiNaC::ex position;                         // q's value there
  GiNaC::ex work;                             // the work of the forces from q0 to there (closed form, when found)
  std::optional<GiNaC::ex> rate_squared;      // dot(q)^2 there, in closed form
  std::optional<double> rate_squared_number;  // the same with the given values (numeric quadrature when no closed form)
  bool numeric_only = false;                  // the work was integrated numerically
  std::string not_possible;                   // why there is no work-energy answer
};

struct Motion {
  EquationsOfMotion eom;
  std::optional<Response> response;
  std::optional<EnergyAnswer> energy;
  std::string no_response;  // why there is no closed-form response
  std::vector<QuantityInTime> quantities;
  std::vector<ConditionInTime> conditions;
  GiNaC::exmap definitions;  // lambda, zeta, omega_d -> their expressions (for numbers)
  // For a simulated motion: each quantity asked for, each dependent coordinate and rate, and
  // each validity condition (`expr op 0`), as expressions in q, dot(q), t and the parameters.
  std::vector<std::pair<GiNaC::ex, GiNaC::ex>> in_state;  // symbol -> expression
  std::vector<std::pair<const CheckedCondition*, GiNaC::ex>> conditions_in_state;
  // Validity conditions that cannot be followed in time (source, why): a dependent coordinate
  // whose starting value is not given. Said in the report; simulate does not watch them.
  std::vector<std::pair<std::string, std::string>> not_followed;
  // Each strand's length in the state (it must stay positive), with the strand's name.
  std::vector<std::pair<std::string, GiNaC::ex>> strands_in_state;
  // Each sliding contact's slip speed on a turning body (Model::slips) in the state (it must
  // stay positive), with its source.
  std::vector<std::pair<std::string, GiNaC::ex>> slips_in_state;
  std::string problem;                 // the motion could not be followed at all: why (an input error)
  std::optional<Location> problem_at;  // where in the description, when not at 'motion'
  // A rule assumes the direction of motion (sliding friction opposes it): the closed-form
  // response holds only while the rate keeps the sign it starts with, up to the first t > 0
  // where it vanishes (the body stops; friction would reverse). Said for every response of
  // such a model: `direction_until` when the rate vanishes (in closed form where it can be,
  // `direction_until_s` with the numbers), neither when it keeps its sign.
  std::vector<std::string> direction_assumed_by;
  std::optional<GiNaC::ex> direction_until;
  std::optional<double> direction_until_s;
  bool direction_kept = false;     // the rate keeps its sign for every t > 0 (with the numbers)
  bool direction_unknown = false;  // no numbers to tell
  // The motion starts against the assumed direction (with the numbers): why, in words. The
  // closed form then describes no part of the motion, and `simulate` stops at t = 0.
  std::string direction_against;
};

/// The equations of motion and, where possible, their closed-form solution and the validity
/// over time. Nothing when the description asks for no motion.
[[nodiscard]] std::optional<Motion> analyze_motion(const Model& m, const EquationSystem& s, const Solution& sol);

}  // namespace tackle

// The Model: a problem with its symbols made, its rules instantiated and every load and
// constraint expressed in GiNaC. Built from a Description and a RuleSet; immutable after.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include <ginac/ginac.h>

#include "description/description.hpp"
#include "model/load_origin.hpp"
#include "model/symbols.hpp"
#include "model/vec.hpp"
#include "ruleset/ruleset.hpp"

namespace tackle {

/// A generalized coordinate: its symbol, rate and acceleration, the body it moves and how
/// (along a line, or turning). Time derivatives walk the model's coordinates.
struct Coordinate {
  enum class Kind { translation, rotation };
  GiNaC::ex q, rate, accel;  // x_A, dot(x_A), ddot(x_A)
  int body = -1;
  Kind kind = Kind::translation;
};

/// A body: its pose (the center of mass, and an angle: 0 for a body that only translates),
/// its mass and its moment of inertia about its center (about the plane's normal). Its
/// coordinates are the model's (`Model::coordinates`, with their body); what follows from
/// them (its translation coordinate, accelerations, velocities, momenta, kinetic energy,
/// power) is in model/kinematics.hpp.
struct Body {
  std::string name;
  GiNaC::ex mass;  // 0 for an ideal pulley block
  bool has_mass = false;
  Vec cm = zero_vec();  // center of mass, written in the model's coordinates (1-D: the coordinate)
  bool has_cm = false;
  GiNaC::ex angle = 0;    // 0: the body only translates
  GiNaC::ex inertia = 0;  // about the center of mass
  // The acceleration as the description gives it, for a body with no coordinate: a vector
  // (`acceleration:`), or `along` times an unknown magnitude `along_unknown` (a_B). Zero for a
  // body with coordinates: theirs is kinematics::acceleration, from the model's coordinates.
  Vec given_acceleration = zero_vec();
  GiNaC::ex along_unknown = 0;
  // How the free body diagram draws it (`draw:`, else its `shape`): "" (from its points),
  // "rectangle" (size: width, height), "circle" (size: diameter), "spool" (size: diameter,
  // its hub's diameter), "rod" (size: length) or "wedge" (size: base, height; a right
  // triangle on its base, its sloping face to the right, or to the left where
  // `drawn_face_left`), centred on its center of mass (a wedge's centroid) and turned by its
  // angle. Drawing only: the mechanics never read it.
  std::string drawn_shape;
  std::vector<GiNaC::ex> drawn_size;
  bool drawn_face_left = false;
  Location at;
};

struct Point {
  std::string name;
  Vec position = zero_vec();
  int body = -1;  // 1-D: the body the point moves with; -1: fixed to the ground
  // A point of a turning body that keeps the ground's directions (`turns: false`): it moves
  // with the center of mass, at `offset` from it, but does not turn (where a string leaves a
  // drum, where a wheel touches the ground).
  bool turns = true;
  Vec offset = zero_vec();
  Location at;
};

/// A force (and couple) on a body, with where it acts and where it comes from.
struct Load {
  int body = -1;
  Vec force = zero_vec();
  std::optional<Vec> at;  // point of application (needed for angular momentum balance)
  std::string at_name;    // the point's name, for reports
  Vec couple = zero_vec();
  LoadOrigin origin;  // where it comes from: gravity, a connection, a strand of one
  /// The sentence the reports print: "force on A", "string s: strand pB-C at pB", "gravity on A".
  [[nodiscard]] std::string source() const { return sentence(origin); }
};

/// A quantity held constant in time (a string's length sum, a still body's coordinate); its
/// first and second time derivatives vanish.
struct Constraint {
  std::string label;       // "string s", "support of C"
  std::string connection;  // the connection's name, for `derive: [{constraint: ...}]`
  GiNaC::ex quantity;      // e.g. 3*x_B - 2*x_A
  std::string meaning;     // "length of string s", "position of C"
  // For position questions: the constant the quantity's varying part keeps (`C_s`, made
  // only when a coordinate is asked for); 0 when not made.
  GiNaC::ex constant = 0;
};

/// A condition under which the model holds, from a rule's `validity`.
struct Condition {
  GiNaC::ex lhs, rhs;
  std::string op;  // >=, <=, >, <, =
  std::string meaning, otherwise, source;
};

/// A quantity to report: an unknown, a given, or an expression defined from them.
struct Wanted {
  std::string name;
  std::string tex;
  GiNaC::ex expr;  // the symbol itself, or the defining expression
  bool defined = false;
  std::optional<Dimension> dimension;
  std::optional<Unit> unit;  // the unit to report it in (SI when absent)
};

/// A balance or constraint the user asked for (`derive`).
struct Selection {
  enum class Kind { lmb, amb, constraint } kind;
  std::vector<int> bodies;  // lmb, amb: one body, or a system
  bool system = false;
  std::string constraint;  // constraint: the connection name
  std::string about;       // amb: the point's name
  Vec about_position = zero_vec();
  std::optional<Vec> axis;  // amb: unit vector of the axis (all components when absent)
  std::string axis_label;   // "OG", "[0, 1, 0]"
};

/// A strand's length that turns as the bodies move: a positive symbol whose square is a
/// polynomial in the coordinates and parameters (`l_CP^2 = a^2 + (h - z)^2`). Its time
/// derivative is d(squared)/dt / (2 l): no root ever appears in a closed form.
struct TurningLength {
  GiNaC::ex symbol;
  GiNaC::ex squared;
};

/// Motion in time, as asked for by `motion:`: the independent coordinates (as many as the
/// degrees of freedom), their values and rates at t = 0, and simulate's defaults.
struct MotionSpec {
  std::vector<GiNaC::ex> coordinates;    // q: independent, listed or chosen (given ones first)
  std::vector<GiNaC::ex> rates;          // dot(q)
  std::vector<GiNaC::ex> accelerations;  // ddot(q)
  std::vector<int> bodies;               // the body each coordinate belongs to
  std::size_t moving = 0;                // coordinates of moving bodies in all
  // Values at t = 0 (SI expressions in the parameters), of the independent coordinates and
  // rates, and of any dependent coordinate the description gives.
  GiNaC::exmap initial;
  std::vector<std::pair<GiNaC::ex, Location>> initial_at;  // where each was written
  std::optional<GiNaC::ex> until;                          // seconds
  std::vector<Text> plot;
  std::optional<std::pair<GiNaC::ex, GiNaC::ex>> speed_at;  // coordinate -> its value there
  Location at;
  GiNaC::ex lambda, zeta, omega_d;  // symbols: natural frequency, damping ratio, damped frequency
};

/// Constant acceleration over an interval (`interval:`): for each body whose rate is given at
/// its start and end, one equation ties its acceleration to the change (impulse and momentum
/// over a duration, v^2 = v0^2 + 2 a s over a distance along its coordinate).
struct IntervalSpec {
  std::optional<GiNaC::ex> duration, distance;
  struct Change {
    int body = -1;
    GiNaC::ex from;
    std::optional<GiNaC::ex> to;  // none: found from the solved (constant) acceleration
  };
  std::vector<Change> changes;
  Location at;
};

/// An impact: the rates just before (the bodies' rate symbols stand for the rates just after),
/// plastic (all stick together) or with a coefficient of restitution (two bodies), and the
/// names of the impulses and of the kinetic energy lost.
struct ImpactSpec {
  struct Before {
    int body = -1;
    GiNaC::ex rate;
    GiNaC::ex impulse;  // the symbol J_<body>
  };
  std::vector<Before> before;
  std::optional<GiNaC::ex> restitution;  // none: plastic
  GiNaC::ex energy_lost;                 // the symbol E_lost
  Location at;
};

/// A steady motion whose rate is unknown (`steady:`): the balances are linear in the rate's
/// square, an unknown of the solve; the rate (its root: the balances fix its size, not its
/// sense) and its period 2 pi/rate are reported as well as what `find` asks for.
struct SteadySpec {
  std::string rate, period;      // their names
  GiNaC::ex squared;             // the unknown, rate^2
  std::vector<Wanted> reported;  // the rate and its period
};

struct Model {
  std::string file;
  std::string title;
  std::optional<Text> statement;       // for sheets; its {placeholders} checked to be parameters
  std::string axis = "x";              // the first axis' name
  std::vector<std::string> axes{"x"};  // one name per axis (1 to 3)
  [[nodiscard]] int dims() const { return static_cast<int>(axes.size()); }
  std::shared_ptr<const SymbolTable> symbols;
  std::vector<Body> bodies;
  std::vector<Coordinate> coordinates;  // every body's, in body order
  std::vector<Point> points;
  std::vector<Load> loads;
  std::vector<Constraint> constraints;
  std::vector<Condition> conditions;
  std::vector<TurningLength> lengths;
  std::vector<std::string> assumptions;
  std::vector<std::string> direction_assumed_by;  // connections whose rule assumes the direction of motion
  // Of those, each one at a point of a turning body: its slip speed, the velocity of the
  // body's material point at the contact along the assumed sliding direction (v + omega x r);
  // each one between two bodies: the first's velocity there relative to the other's.
  // The friction opposes the slip while it is positive; at zero the contact stops slipping
  // (a ball thrown without spin starts to roll), and the model no longer holds.
  struct Slip {
    std::string source;
    GiNaC::ex speed;
    std::vector<int> bodies;  // whose own rates may turn without an event (the slip is watched instead)
  };
  std::vector<Slip> slips;
  // Each strand of a path that changes length and does not turn, with its name ("strand A-P
  // of string s"): its length must stay positive, or a body has reached the point at its end
  // (a block pulled into its pulley) and the model no longer holds. Followed in time.
  std::vector<std::pair<GiNaC::ex, std::string>> strand_lengths;
  struct ConnectionNote {
    std::string label;             // "sliding at A", "string s"
    std::string summary;           // the rule's, for the problem's number of axes, with a {} per term
    std::vector<GiNaC::ex> terms;  // the rule's {N}, {mu*N} in this connection's symbols
  };
  std::vector<ConnectionNote> connections;  // one per connection, in the description's order
  /// What a mechanism's sketch draws of a connection (its rule's `sketch:`).
  struct Drawing {
    std::string as;           // line, spring, damper, pulley, support, arrow, contact, surface, wheel, pin, joint, rod,
                              // couple
    std::string label;        // the connection's label ("force on A": its loads' source)
    std::vector<int> path;    // its path's points (line, spring, damper; contact: between)
    int point = -1;           // its first point (pulley, surface, wheel, pin, joint, arrow)
    std::vector<int> points;  // all its points, in the rule's order (a rod's or a cable's from and to)
    int body = -1;            // its first body (support, arrow, surface, wheel, pin, joint, rod, couple)
    Vec vector = zero_vec();  // its first vector (a surface's normal)
  };
  std::vector<Drawing> drawings;  // in the description's order
  std::optional<Vec> gravity;
  std::vector<GiNaC::ex> candidates;  // possible unknowns: accelerations, then rule unknowns
  std::vector<GiNaC::ex> given;       // kinematic quantities given as known
  std::vector<Wanted> wanted;
  std::vector<Selection> derive;   // empty: a complete set
  std::optional<SweepDesc> sweep;  // as described (checked when it is run)
  GiNaC::ex time = 0;              // t (0 when the description uses the name t itself)
  std::optional<MotionSpec> motion;
  std::optional<IntervalSpec> interval;
  std::optional<ImpactSpec> impact;
  std::optional<SteadySpec> steady;
  // Numbers for drawing: every parameter's value (SI) and the layout's coordinates.
  GiNaC::exmap layout;
};

/// The symbols the questions (`wanted`) hold, gathered once: asking has() of each symbol in
/// each question is quadratic (a chain of 256 asks 511 questions about 768 symbols).
[[nodiscard]] std::unordered_set<GiNaC::ex, ExHash, GiNaC::ex_is_equal> symbols_asked(
    const std::vector<Wanted>& wanted);

/// d/dt of an expression in the coordinates and their rates, the turning lengths and time
/// itself (the chain rule; `time` is t, or 0 when nothing depends on time explicitly).
[[nodiscard]] GiNaC::ex time_derivative(const GiNaC::ex& e, const std::vector<Coordinate>& coordinates,
                                        const std::vector<TurningLength>& lengths, const GiNaC::ex& time = 0);
/// The same in the model's coordinates, lengths and time.
[[nodiscard]] GiNaC::ex time_derivative(const GiNaC::ex& e, const Model& m);

/// The numerator of `e` reduced modulo l^2 - squared for each turning length (monic in l, so
/// the remainder is unique): zero exactly when `e` vanishes wherever every length is what it
/// stands for. Zero tests of closed forms through turning strands go through this.
[[nodiscard]] GiNaC::ex reduced_on_lengths(const GiNaC::ex& e, const Model& m);

/// The coordinates of massless bodies that no constraint ties to the others (the joint of two
/// springs in series): nothing moves them but the forces, which sum to zero, so the body's
/// balance fixes each one at every instant. They are unknowns of the instant and not degrees
/// of freedom of the motion. (A massless ring on a string is tied by the string's length: its
/// balance gives the tension instead.) Given coordinates are left out. `table` is the model's
/// symbol table (while the model is built, the builder's).
[[nodiscard]] std::vector<GiNaC::ex> balance_coordinates(const Model& m, const SymbolTable& table);
[[nodiscard]] inline std::vector<GiNaC::ex> balance_coordinates(const Model& m) {
  return balance_coordinates(m, *m.symbols);
}

/// Builds the model; every problem in the description is reported at once (InputError).
[[nodiscard]] Model build_model(const Description& d, const RuleSet& rules);

}  // namespace tackle

// The cross-check's numeric model of a description: every body's center free in the
// problem's axes (and, for a body with mass in 2-D or 3-D or an `angle` in 2-D, a rotation),
// every point's position from the description's geometry (center + Rot(rotation) offset, or
// center + offset for a point that keeps the ground's directions), each connection a
// constraint on those coordinates or a force law. A body with an `angle` (2-D) turns: its
// rotation is that angle, its inertia about the center from `inertia`/`shape`, and the
// model's own physics (pins as constraints on a material point, strings wound on drums,
// rolling without slip) must reproduce the center tackle writes in the angle; a body without
// one is held at rotation 0 by a guide couple, which must come out 0. At a state (q, dq/dt, t) it solves
//   M q'' = f + G lambda,   J q'' = -gamma
// (J the constraints' Jacobian, gamma their second time derivative at q'' = 0, both exact by
// dual numbers; G the generalized directions of the constraint forces, J^T for ideal ones).
// It reads the description (tackle's plain Description structs) and takes the SI factor of
// each parameter's unit from tackle's unit table (src/core/units: input reading); nothing of
// tackle's model, equations, solver, energy or motion is used. Its requirements (strings pull,
// contacts push, grips stay within mu N, cords stay taut, a steady rate is real) and its
// forces on a body (forces.cpp) are its own, not read from tackle's rules. A steady motion at
// an unknown rate (`steady:`, a body's given acceleration a0 + omega^2 w) is solved with the
// body guided only across w: omega^2 is where the force of a guide along w would vanish.
//
// What the rest of the cross-check takes from tackle, beyond what it checks:
// - compare.cpp, claims.cpp, motion.cpp: tackle's answers (closed forms, the asked quantities,
//   the conditions with `holds` and `always`, the slip speeds, simulate) are what is compared;
//   tackle's definitions of the names it makes (defined parameters, turning strands' lengths,
//   a length sum's constant as its quantity) are put in before they are evaluated.
// - the oracle of verdicts (oracle.cpp, variants.cpp, worlds.cpp, diagram.cpp): the students'
//   items are made from tackle's equations (the derivation's, its rate and position equations,
//   lmb_along and amb_along for other bodies and systems), closed forms and symbol table
//   (which symbols are parameters and masses, their dimensions: to write equations of one
//   dimension), printed with tackle's to_text and kept within tackle's documented input bounds
//   (answer_limits); a diagram names the description's points and bodies. Their truth comes
//   from this model alone (worlds.cpp: the text read by expr.hpp's parser, evaluated at the
//   model's states), except the turning strands' lengths, which tackle names and defines and
//   the oracle evaluates from tackle's definition, as text.
#pragma once

#include <algorithm>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "crosscheck/expr.hpp"
#include "description/description.hpp"

namespace crosscheck {

/// A description the model cannot express, with the reason.
struct Unsupported : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One state of the mechanism: the coordinates and rates (translations of every body, then
/// rotations: a turning body's is its angle, any other body's stays 0), and the time.
struct State {
  Eigen::VectorXd q, v;
  double t = 0;
};

/// What the model gives at a state: the named quantities (tackle's names: ddot(x_A), T_s, N_A,
/// and `guide ...` for the forces that keep a body on the motion tackle gives it, which must
/// be 0), each with whether the equations determine it.
struct Quantity {
  std::string name;
  double value = 0;
  bool determined = true;
  bool force = false;  // a constraint force (else an acceleration)
  // Its parts along the directions the equations leave free (the null space of the system,
  // each column of unit length): empty or zero when determined. An expression in several
  // quantities is determined where these parts cancel (O_y + G_y in an indeterminate support).
  Eigen::VectorXd free;
};

struct Instant {
  std::vector<Quantity> quantities;
  /// The quantity of that name, or null.
  [[nodiscard]] const Quantity* find(const std::string& name) const {
    for (const auto& q : quantities)
      if (q.name == name) return &q;
    return nullptr;
  }
  int free_directions = 0;  // columns of each Quantity::free
  double residual = 0;      // of the KKT system at its least-squares solution, relative
  int rank_deficiency = 0;
};

/// What the model's own physics requires of a solution, connection by connection: a string
/// or a cable pulls (its tension is not negative), a contact, a roller or a wheel pushes (its
/// normal force is not negative), a sticking contact's or a gripping wheel's friction stays
/// within its cone (|F| <= mu N; in 3-D F has two components in the tangent plane), an elastic
/// cord is taut (its length at least its rest length); a steady motion's unknown rate is real (its
/// square is not negative). Nothing here
/// is read from tackle's rules.
struct Requirement {
  enum Kind { pulls, pushes, cone, taut, real } kind = pulls;
  std::string force;        // the constraint force (tackle's name for it): T, N_A; cone: the friction F_A
                            // (3-D: its first component F_A1); real: the rate squared (omega^2)
  std::string normal;       // cone: the normal force N_A
  double mu = 0;            // cone
  int element = -1;         // taut: the cord (an element of the model)
  std::string what;         // in words: "string s pulls"
  std::string force_too{};  // cone in 3-D: the friction's second component in the tangent plane (F_A2);
                            // its size is then sqrt(F_A1^2 + F_A2^2)
};

/// How far a requirement is met at a state: a force (N), not negative when it is met.
struct Margin {
  const Requirement* requirement = nullptr;
  double value = 0;
  bool determined = true;  // the model determines the forces it is made of
};

/// A force on a body as the model has it at a state, for free body diagrams: where it acts (a
/// point's name, or the body's for its center), along which line, and whether its sense is
/// known before solving (gravity, a given force, a string that pulls, a contact that pushes, a
/// spring's pull or push at the state) or not (a reaction of either sign). A force of unknown
/// direction (a pin's, a joint's: two or three reactions of either sign at one point) has the
/// lines its direction spans. A 2-D couple has no line and its sense in `turn` (0: unknown).
struct BodyForce {
  std::string what;  // "string s", "gravity", "roller at A", "spring k_s"
  std::string at;
  std::vector<Eigen::VectorXd> lines;  // unit; the first is the force's own direction when `sense`
  bool sense = true;
  bool zero = false;  // nothing at this state (a spring at its rest length)
  bool couple = false;
  int turn = 0;
};

/// A deliberately wrong model (the test that the comparison catches one).
struct Perturbation {
  double masses = 0;     // every mass times 1 + masses
  double inertia = 0;    // every turning body's moment of inertia times 1 + inertia
  bool winding = false;  // a string wound on a drum winds the other way
};

/// Whether every strand that kept its direction between `then` and `now` (strand_vectors)
/// still points the same way: none went through zero length.
[[nodiscard]] bool same_directions(const std::vector<Eigen::VectorXd>& now, const std::vector<Eigen::VectorXd>& then);

class Model {
 public:
  /// Builds the model from a description (throws Unsupported, with the reason, for what it
  /// cannot express). `rng` draws values for parameters that have none. `perturb` makes the
  /// model wrong on purpose (the test that the comparison catches a wrong model).
  Model(const tackle::Description& d, std::mt19937_64& rng, const Perturbation& perturb = {});

  [[nodiscard]] int dims() const { return dims_; }
  [[nodiscard]] int dofs() const { return ndof_; }
  /// The state at the layout (given values, then layout, then 0), projected onto the
  /// constraints.
  [[nodiscard]] State base_state() const;
  /// A random state near the layout, consistent with the constraints (positions and rates);
  /// a coordinate or rate given in the parameters keeps its value.
  [[nodiscard]] std::optional<State> random_state(std::mt19937_64& rng, double spread) const;
  /// The accelerations and constraint forces at a state.
  [[nodiscard]] Instant solve(const State& s) const;
  /// The values tackle's closed forms are evaluated at: every parameter (SI), every coordinate
  /// and rate (by tackle's names) and t.
  [[nodiscard]] std::map<std::string, double> values_at(const State& s) const;
  /// The accelerations (all of q) at a state, for integration; nullopt when not determined.
  [[nodiscard]] std::optional<Eigen::VectorXd> accelerations(const State& s) const;
  /// Each coordinate of tackle's (a body's `position`) at a state.
  [[nodiscard]] std::map<std::string, double> coordinates_at(const State& s) const;
  /// The state whose tackle coordinates and rates are the given ones (other coordinates
  /// projected onto the constraints); for initial values of a motion.
  [[nodiscard]] std::optional<State> state_from(const std::map<std::string, double>& coords,
                                                const std::map<std::string, double>& rates, double t) const;
  /// Whether every strand that keeps its direction (of strings, springs, dampers, contacts) points the way it
  /// points in `ref` (a strand through zero length, a block through its pulley, is where
  /// neither this model nor tackle's describes the mechanism any more).
  [[nodiscard]] bool strands_keep_direction(const State& s, const State& ref) const;
  /// Each strand (of strings, springs, dampers, contacts, in the model's order) from its
  /// first point to its second: the same list for every model of one description.
  [[nodiscard]] std::vector<Eigen::VectorXd> strand_vectors(const State& s) const;
  /// Its requirements (Requirement) in the description's order, and how far each is met at a
  /// state whose instant (solve()) is `inst`.
  [[nodiscard]] const std::vector<Requirement>& requirements() const { return requirements_; }
  [[nodiscard]] std::vector<Margin> margins(const State& s, const Instant& inst) const;
  /// A sliding contact's slip speed (its material point's velocity along its sliding
  /// direction) by its normal force's name (N_A); nothing for another name.
  [[nodiscard]] std::optional<double> slip_speed(const std::string& normal, const State& s) const;
  /// What a motion watches, at a state (projected onto the constraints first): each
  /// requirement's margin (NaN where not determined), then each sliding contact's slip speed.
  /// A margin that turns negative, or a slip that turns, ends the motion the model describes.
  [[nodiscard]] std::vector<std::pair<std::string, double>> watched(const State& s) const;
  /// The forces on a body at a state (throws Unsupported for what a sketch cannot show: a
  /// damper's force or a load that depends on the speed, a couple in space).
  [[nodiscard]] std::vector<BodyForce> forces_on(const std::string& body, const State& s) const;
  /// A named point's (or a body's center's) position at a state; nothing for another name.
  [[nodiscard]] std::optional<Eigen::VectorXd> named_position(const std::string& name, const State& s) const;
  [[nodiscard]] std::vector<std::string> body_names() const;
  /// Whether any expression depends on time.
  [[nodiscard]] bool uses_time() const { return uses_time_; }
  [[nodiscard]] const std::map<std::string, double>& parameters() const { return params_; }
  /// Whether a massless body's position had to be solved for from its force balance.
  [[nodiscard]] bool has_massless() const { return has_massless_; }
  /// Scales for "near 0": the largest mass and the magnitude of gravity.
  [[nodiscard]] double largest_mass() const {
    double m = 0;
    for (const auto& b : bodies_) m = std::max(m, b.mass);
    return m;
  }
  [[nodiscard]] double gravity_magnitude() const { return gravity_.norm(); }

  struct Body {
    std::string name;
    double mass = 0;
    bool massive = false;
    enum Kind { line, still, driven, along, turning } kind = line;
    std::string coord;            // line: tackle's coordinate (position), along: the acceleration's name
    Eigen::VectorXd a, b;         // line: cm(s) = a + s b; along: b is the unit direction
    Eigen::VectorXd cm0;          // at the layout
    Eigen::VectorXd frame_accel;  // driven: the given acceleration (constant)
    int q0 = 0, r0 = -1, nr = 0;  // index of its translations; of its rotations (-1: none)
    std::string angle;            // 2-D: tackle's angle coordinate, which is the rotation q[r0] ("" : none)
    double angle0 = 0;            // the rotation at the layout
    double inertia = 0;           // about the center (a body with an angle)
    std::vector<Expr> cm_expr;    // turning: the center in tackle's coordinates (its angle, others')
  };
  struct PointRef {
    std::string name;             // the description's point (or body, for its center); "" for one made here
    int body = -1;                // -1: the ground
    Eigen::VectorXd offset;       // from the body's center, in the body's frame (material point)
    bool turns = true;            // false: the offset keeps the ground's directions (a point where a
                                  // strand leaves a drum, where a wheel touches the ground)
    std::vector<Expr> ground;     // a ground point's position (parameters, t)
    Eigen::VectorXd frame_accel;  // a ground point that moves with a driven body's frame
    int frame_body = -1;          // that body (-1: none)
  };
  struct Constraint {
    std::string name;  // tackle's unknown, "" when it has none, "guide ..." for guides
    bool guide = false;
    enum Kind { path, length_expr, project, relative, slide, rotation, guide_line, roll, guide_curve } kind = path;
    std::vector<PointRef> points;  // path: in order; project: one; relative: two; slide: the point on `body`
    Expr length;                   // length_expr
    Eigen::VectorXd dir;           // project/relative/guide: the unit direction (rotation: axis index in dir[0])
    int body = -1, other = -1;     // rotation: the bodies (other -1: the ground); guide: the body;
                                   // slide: `other` carries the slide (dir turns with it)
    double g_sign = 1;             // G = g_sign J^T, unless friction is set
    double mu = 0;                 // sliding: friction -mu N along `sliding`
    Eigen::VectorXd sliding;
    double constant = 0;              // its value at the layout
    double arm = 0;                   // roll: the rotation's coefficient, (z x (C - cm)) . dir
    struct Winding {                  // a path's end wound on a turning body: the length gains s * rotation,
      std::size_t end = 0, next = 0;  // s = d . (z x offset), d the unit vector from point `next` into `end`
      int body = -1;
      double sign = 1;  // -1 only in a deliberately wrong model
    };
    std::vector<Winding> winds;  // path
    std::string label;           // the connection's type and name ("string s"), for diagrams
  };
  struct Element {  // a spring, elastic cord or damper on a path
    enum Kind { spring, damper } kind = spring;
    std::vector<PointRef> points;
    std::vector<Constraint::Winding> winds;
    double k = 0, rest = 0, c = 0;
    bool stretch = false;  // rest = origin length - stretch
    double stretch_value = 0;
    std::string label;
  };
  struct Load {
    int body = -1;
    PointRef at;
    std::vector<Expr> force;   // one per axis; may use coordinates, rates, t
    std::vector<Expr> couple;  // 2-D: one, 3-D: three
    std::string label;
  };

 private:
  int dims_ = 1;
  int ndof_ = 0;
  bool uses_time_ = false;
  bool has_massless_ = false;
  std::map<std::string, double> params_;
  std::vector<std::string> slot_names_;
  std::map<std::string, int> slots_;
  int first_coord_slot_ = 0;
  std::vector<Body> bodies_;
  std::map<std::string, PointRef> points_;
  std::vector<Constraint> cons_;
  std::vector<Element> elements_;
  std::vector<Load> loads_;
  std::vector<Requirement> requirements_;
  [[nodiscard]] double element_tension(const Element& e, const State& s) const;
  [[nodiscard]] Eigen::VectorXd point_position(const PointRef& p, const State& s) const;
  [[nodiscard]] std::vector<double> numbers_at(const State& s) const;  // every slot's value
  // forces.cpp: the parts of forces_on
  struct ForcePart {
    std::string what, group;  // parts of one group of unknown sense make one force of unknown direction
    std::string at;
    Eigen::VectorXd direction;
    bool sense = false, zero = false;
  };
  void strand_parts(int body, const std::vector<PointRef>& pts, double sign, const std::string& what, bool sense,
                    const State& s, std::vector<ForcePart>& out) const;
  void constraint_parts(int body, const Constraint& c, const State& s, std::vector<ForcePart>& out,
                        std::vector<BodyForce>& couples) const;
  void load_forces(int body, const State& s, std::vector<BodyForce>& out) const;
  [[nodiscard]] bool sense_known(const std::string& force) const;
  [[nodiscard]] Eigen::VectorXd velocity(const PointRef& p, const State& s) const;
  Eigen::VectorXd gravity_;
  Eigen::VectorXd origin_q_;  // every coordinate of tackle's at 0 (a spring's `stretch`)
  std::map<std::string, double> base_coord_, base_rate_;
  std::map<std::string, double> given_accel_;  // kinematics: ddot(q) -> its value
  std::map<std::string, double> pinned_;       // coordinates and rates given in the parameters: every state keeps them
  bool kinematic_ = false;                     // no body has a mass: the constraints alone
  [[nodiscard]] Instant solve_kinematics(const State& s) const;
  // A steady motion at an unknown rate: the body whose given acceleration is a0 + s w in the
  // rate squared s, and the guide along w (whose force solve_steady makes 0).
  struct Steady {
    int body = -1, guide = -1;
    Eigen::VectorXd a0, w;
    std::string squared, rate, period;  // tackle's names: omega^2, omega, tau
  };
  std::optional<Steady> steady_;
  int steady_slot_ = -1;  // the rate's slot (no value: only a body's acceleration uses it)
  [[nodiscard]] Instant solve_steady(const State& s) const;
  [[nodiscard]] Instant solve_fixed(const State& s) const;  // with every given acceleration as it is
  void set_steady(double squared);  // the body's (and its frame's) acceleration at this rate squared
  [[nodiscard]] Eigen::VectorXd along_line(const Body& b, const Eigen::MatrixXd& nulls) const;

  int slot(const std::string& name) const;
  Expr compile(const tackle::Text& t) const;      // (not the steady rate)
  Expr compile_any(const tackle::Text& t) const;  // (the steady rate too)
  double number(const tackle::Text& t) const;
  PointRef point(const std::string& name, int body_hint) const;
  PointRef material(const std::string& name, int body) const;

  template <class S>
  std::vector<S> variables(const std::vector<S>& q, const Eigen::VectorXd& v, const S& t) const;
  template <class S>
  std::vector<S> position(const PointRef& p, const std::vector<S>& q, const std::vector<S>& vars, const S& t) const;
  template <class S>
  S value(const Constraint& c, const std::vector<S>& q, const S& t) const;
  template <class S>
  S path_length(const std::vector<PointRef>& pts, const std::vector<S>& q, const S& t) const;
  template <class S>
  S winding_arm(const Constraint::Winding& w, const std::vector<PointRef>& pts, const std::vector<S>& q,
                const S& t) const;
  Eigen::VectorXd layout_position(const PointRef& p) const;
  std::vector<Constraint::Winding> windings(const std::vector<PointRef>& pts, double sign) const;
  void place_turning(State& s) const;

  /// Value, gradient in q, time derivative and second derivative along (v, 1) of a function
  /// of (q, t) given in D2.
  struct Derivs {
    double value = 0, dt = 0, dd = 0;
    Eigen::VectorXd grad;
  };
  template <class F>
  Derivs derivs(const F& f, const State& s) const;
  Eigen::VectorXd generalized(const PointRef& p, const Eigen::VectorXd& force, const State& s) const;
  // A constraint's derivatives (a wound path's in its rate form: J = grad L + s e_rot).
  Derivs cons_derivs(const Constraint& c, const State& s) const;
  Derivs length_derivs(const std::vector<PointRef>& pts, const std::vector<Constraint::Winding>& winds,
                       const State& s) const;
  // Onto the constraints (positions, then rates), moving only the coordinates not frozen.
  void project(State& s, bool rates_only, const std::vector<bool>* frozen_q = nullptr,
               const std::vector<bool>* frozen_v = nullptr) const;
  bool settle_massless(State& s) const;
  struct Kkt {
    Eigen::MatrixXd K;
    Eigen::VectorXd rhs;
    std::vector<int> kept;  // the constraints in the system
  };
  // (`only`: these constraints, else the rules' and the guides they leave free at s)
  Kkt system(const State& s, const std::vector<int>* only = nullptr) const;
};

}  // namespace crosscheck

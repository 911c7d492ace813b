// The description of a problem as the user wrote it: plain data with locations, no GiNaC.
// Expressions stay text here; the model stage parses them against the problem's names.
#pragma once

#include "core/files.hpp"  // read_text_file

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostics.hpp"

namespace tackle {

/// A scalar as written, with where it was written.
struct Text {
  std::string text;
  Location at;
};

struct ParameterDesc {
  Text name;
  std::optional<Text> value;      // an expression in numbers (exact: 9.81 is 981/100)
  std::optional<Text> unit;       // unit of value, e.g. "m/s^2"
  std::optional<Text> dimension;  // "force", "mass", ... when there is no unit
  std::optional<Text> tex;        // TeX name, e.g. "\mu_{k}"
  std::optional<bool> positive;   // default: true for masses, lengths and g
  std::optional<Text> define;     // a name for an expression in earlier parameters (l = sqrt(b^2 + d^2))
  std::vector<Text> range;        // variants: [low, high], in the parameter's unit
  std::optional<Text> round;      // variants: values are multiples of this step
};

/// A vector as written: one expression per axis (one item for a 1-D scalar).
struct VectorDesc {
  std::vector<Text> items;
  Location at;
};

struct BodyDesc {
  Text name;
  std::optional<Text> mass;                  // expression; 0 for an ideal pulley block
  std::optional<Text> position;              // the body's coordinate (a new name): in 1-D along the axis,
                                             // in 2-D and 3-D the variable its center_of_mass is written in
  std::optional<VectorDesc> center_of_mass;  // 2-D and 3-D
  // 2-D and 3-D straight-line motion: a given acceleration vector, or an unknown scalar
  // acceleration `accel_name` along `accel_along`; neither means at rest.
  std::optional<VectorDesc> acceleration;
  std::optional<VectorDesc> accel_along;
  std::optional<Text> accel_name;
  // Rotation (2-D): the angle coordinate (a new name; the center of mass and the body's points
  // turn with it), and the moment of inertia about the center of mass, given (`inertia:`) or
  // from a shape (`shape: {disk: R}`, ring, rod, sphere, box: [a, b], point).
  std::optional<Text> angle;
  std::optional<Text> inertia;
  std::optional<Text> shape_kind;
  std::optional<VectorDesc> shape_size;
  // How the figures draw it: `draw: {shape: rectangle | circle | spool | wedge, size: [w, h] |
  // [d] | [D, hub d] | [base, height], face: left | right}` (a wedge's sloping face)
  std::optional<Text> draw_shape;
  std::optional<VectorDesc> draw_size;
  std::optional<Text> draw_face;
  Location at;
};

struct PointDesc {
  Text name;
  std::optional<VectorDesc> at;      // fixed point: position (an expression in 1-D, a list else)
  std::optional<Text> on;            // a point on a body
  std::optional<VectorDesc> offset;  // with `on`: constant offset from the body's coordinate
                                     // (1-D) or center of mass (2-D, 3-D)
  bool turns = true;                 // with `on`: the offset turns with the body (false: it
                                     // keeps the ground's directions - where a string leaves a
                                     // drum, where a wheel touches the ground)
  std::optional<Location> turns_at;  // where `turns` was written
};

/// An argument of a connection: a scalar or a list of scalars.
struct ArgDesc {
  Text key;
  std::vector<Text> items;  // one item for a scalar
  bool is_list = false;
};

struct ConnectionDesc {
  Text type;
  std::optional<Text> name;
  std::vector<ArgDesc> args;  // everything but type and name
  Location at;
  [[nodiscard]] const ArgDesc* arg(const std::string& key) const;
};

/// A quantity taken as known: a coordinate, a velocity, an acceleration or an unknown, with
/// an optional value at the instant considered (`given: {z: {value: 3, unit: m}, dot(z): 0}`).
struct GivenDesc {
  Text name;
  std::optional<Text> value;
  std::optional<Text> unit;
};

struct FindDesc {
  Text name;                 // unknown name, e.g. ddot(x_A), or a new name for `expr`
  std::optional<Text> expr;  // a quantity defined from the unknowns, e.g. F/ddot(x_B)
  std::optional<Text> tex;
  std::optional<Text> unit;  // report the number in this unit (lbf, ft/s^2, km/h, ...)
};

struct DeriveDesc {
  Text kind;                       // lmb | amb | constraint
  std::vector<Text> items;         // bodies (lmb, amb), or a connection name (constraint)
  bool is_list = false;            // a list of bodies: one balance for the system of those bodies
  std::optional<Text> about;       // amb: the point
  std::optional<VectorDesc> axis;  // amb: a direction, or two point names
};

struct SweepDesc {
  Text vary;                    // "h=0:2:41"
  std::vector<Text> fix;        // "l=1"
  std::vector<Text> plot;       // "N_A - N_B"
  std::optional<Text> against;  // "h/l": the horizontal axis, when not the varied parameter
  Location at;
};

/// Motion in time (`motion:`): the coordinates the motion is described by, their values and
/// rates at t = 0, and the defaults of `tackle simulate`.
struct MotionDesc {
  std::vector<Text> coordinates;                   // empty: the given coordinates
  std::vector<std::pair<Text, Text>> initial;      // coordinate or rate -> expression in the parameters (SI)
  std::vector<std::optional<Text>> initial_units;  // one per entry of `initial`: {value, unit} gave one
  std::optional<Text> until;                       // simulate: the end time (a number in s, or value + unit)
  std::optional<Text> until_unit;
  std::vector<Text> plot;                         // simulate: quantities to tabulate and plot
  std::optional<std::pair<Text, Text>> speed_at;  // work-energy: the speed where a coordinate has this value
  Location at;
};

/// An interval of constant acceleration (`interval:`): the forces are taken constant over it
/// (their averages), so each rate changes linearly: impulse and momentum over a duration, or
/// v^2 = v0^2 + 2 a s over a distance.
struct IntervalDesc {
  std::optional<Text> duration, distance;
  std::vector<std::pair<Text, Text>> from, to;  // rate -> expression in the parameters; a rate
                                                // in `from` only has its end value found
  Location at;
};

/// A steady motion whose rate is unknown (`steady:`): `rate` names it (a new name, used in
/// the description's expressions: an acceleration omega^2*r), `unit` is the unit it is
/// reported in (rad/s unless said), `period` names its period (tau unless said).
struct SteadyDesc {
  Text rate;
  std::optional<Text> unit, period;
  Location at;
};

/// An impact (`impact:`): the bodies' rates just before (`from`); the finite forces give no
/// impulse while it lasts, so momentum is conserved, and the bodies stick together
/// (`plastic: true`) or, two of them, part with a coefficient of restitution.
struct ImpactDesc {
  std::vector<std::pair<Text, Text>> from;  // rate -> expression in the parameters
  std::optional<Text> plastic;              // "true"
  std::optional<Text> restitution;          // e, an expression in the parameters
  Location at;
};

struct PhaseDesc;

struct Description {
  std::string file;
  Text title;
  // The problem as a student reads it, for sheets: text (math between $...$) where {F} is
  // the value of parameter F with its unit.
  std::optional<Text> statement;
  std::vector<Text> axes;
  std::vector<ParameterDesc> parameters;
  std::optional<VectorDesc> gravity;
  // Or, for axes tilted with a slope: the magnitude of gravity and the angle the first axis
  // rises above the horizontal (the second axis is across the slope, upwards).
  std::optional<Text> gravity_magnitude, gravity_tilt;
  std::vector<BodyDesc> bodies;
  std::vector<PointDesc> points;
  std::vector<ConnectionDesc> connections;  // `loads` and `strings` entries land here too
  std::vector<std::pair<Text, Text>> layout;
  std::vector<GivenDesc> given;
  std::vector<FindDesc> find;
  std::vector<DeriveDesc> derive;        // empty: tackle chooses a complete set
  std::optional<SweepDesc> sweep;        // a default for `tackle sweep`, and a figure in LaTeX reports
  std::optional<MotionDesc> motion;      // motion in time (equations of motion, response, simulate)
  std::optional<IntervalDesc> interval;  // constant acceleration over an interval
  std::optional<ImpactDesc> impact;      // an impact: momentum conserved, rates before -> after
  std::optional<SteadyDesc> steady;      // a steady motion whose rate is solved from the balances
  // Phases (`phases:`): each a description of its own sharing the top-level parameters; the
  // state at the end of one is carried into the next as defined parameters.
  std::vector<PhaseDesc> phases;
};

struct PhaseDesc {
  Text name;
  Description d;  // the phase's own description (its parameters: the shared ones, then its own)
  std::vector<std::pair<Text, Text>> carry;  // new parameter -> expression in the state at the phase's end
  Location at;
};

/// A description and the problems found while reading it; what could be read is kept so that
/// the model stage can report its own problems in the same run.
struct DescriptionRead {
  Description description;
  std::vector<Diagnostic> problems;
  bool usable = true;  // false when the file is not YAML or not a mapping
};
[[nodiscard]] DescriptionRead read_description_text(const std::string& text, const std::string& file);

/// Reads a description; every problem in the file is reported at once (InputError).
[[nodiscard]] Description read_description(const std::string& path);
/// The same from text already in memory; `file` names it in messages.
[[nodiscard]] Description parse_description(const std::string& text, const std::string& file);

}  // namespace tackle

// Rule instantiation: each connection's arguments checked and bound, its unknowns made, its
// loads, constraints and conditions added to the Model; then the checks that need every
// connection. The arguments and unknowns are connection_arguments.cpp's, the constraints
// connection_constraints.cpp's.
#include "model/builder/connection_steps.hpp"
#include "model/builder/stages.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "core/placeholders.hpp"
#include "expr/print.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

// The origin of a connection's own loads: an applied force (rule force), a sliding contact
// labelled by its point ("sliding at P"), else the connection.
LoadOrigin own_origin(const Instance& in) {
  LoadOrigin o = connection_origin(in.label, in.rule.type);
  if (in.rule.type == "force") o.kind = LoadOrigin::Kind::applied;
  if (in.rule.type == "sliding" && !in.c.name && in.c.arg("at")) {
    o.kind = LoadOrigin::Kind::sliding;
    o.point = in.c.arg("at")->items[0].text;
  }
  return o;
}

// A rule expression in the instance's scope; problems are the rule's.
std::optional<ex> rule_expr(BuildContext& ctx, Instance& in, const std::string& text, const Location& at) {
  auto r = parse_expression(text, in.scope);
  for (const auto& p : r.problems) ctx.diags.error(at, "rule '" + in.rule.type + "': in '" + text + "': " + p.message);
  return r.value;
}

// A rule expression as a vector: a number is along the axis in 1-D (a force) or about z
// in 2-D (a couple).
std::optional<Vec> as_vec(BuildContext& ctx, const Instance& in, const ex& e, bool couple, const Location& at) {
  if (is_vector(e)) return Vec{e.op(0), e.op(1), e.op(2)};
  if (!couple && ctx.m.dims() == 1) return Vec{e, 0, 0};
  if (couple && ctx.m.dims() == 2) return Vec{0, 0, e};
  ctx.diags.error(at, "rule '" + in.rule.type + "': a " + std::string(couple ? "couple" : "force") + " in a " +
                          std::to_string(ctx.m.dims()) + "-D problem must be a vector");
  return std::nullopt;
}

// A load `on` a body (or a point on one): its force and couple from the rule, at its point
// of application (needed for a force in 2-D and 3-D).
void load_on(BuildContext& ctx, Instance& in, const LoadSpec& l) {
  const ConnectionDesc& c = in.c;
  const std::string& what = in.what;
  auto& point_args = in.point_args;
  auto& body_args = in.body_args;
  auto it = point_args.find(l.arg);
  if (it == point_args.end()) return;  // optional argument not given
  int body = -1;
  if (auto bt = body_args.find(l.arg); bt != body_args.end())
    body = bt->second;
  else
    body = ctx.m.points[it->second].body;
  if (body < 0) {
    ctx.diags.error(c.at, "a " + what + " acts on fixed point '" + ctx.m.points[it->second].name +
                              "' (expected a body or a point on one)");
    return;
  }
  Load load;
  load.body = body;
  load.origin = own_origin(in);
  if (!l.at_arg.empty()) {
    if (auto at = point_args.find(l.at_arg); at != point_args.end()) {
      load.at = ctx.m.points[at->second].position;
      load.at_name = ctx.m.points[at->second].name;
    }
  } else if (!body_args.count(l.arg)) {
    load.at = ctx.m.points[it->second].position;
    load.at_name = ctx.m.points[it->second].name;
  }
  bool good = true;
  if (!l.expr.empty()) {
    auto f = rule_expr(ctx, in, l.expr, l.at);
    auto v = f ? as_vec(ctx, in, *f, false, l.at) : std::nullopt;
    if (v)
      load.force = *v;
    else
      good = false;
  }
  if (!l.couple.empty()) {
    auto f = rule_expr(ctx, in, l.couple, l.at);
    auto v = f ? as_vec(ctx, in, *f, true, l.at) : std::nullopt;
    if (v)
      load.couple = *v;
    else
      good = false;
  }
  if (!good) return;
  if (ctx.m.dims() > 1 && !load.at && !is_zero_vec(load.force)) {
    ctx.diags.error(c.at, "a " + what + " needs a point of application in a " + std::to_string(ctx.m.dims()) +
                              "-D problem (give '" + (l.at_arg.empty() ? std::string("at") : l.at_arg) + "')");
    return;
  }
  ctx.m.loads.push_back(load);
}

// Loads `along` a path: its tension pulling each point the path runs over.
void loads_along(BuildContext& ctx, Instance& in, const LoadSpec& l) {
  const Path* path = path_of(ctx, in, l.arg);
  if (!path) return;
  // A force element's tension may use its path's length and lengthening rate.
  in.scope.bind("length", path->length);
  in.scope.bind("lengthening", time_derivative(path->length, ctx.m));
  // ... and its length where every coordinate is 0 (a spring's stretch is stated there).
  const exmap& coordinates = ctx.coordinates_at_zero();
  exmap lengths;  // the turning strands' lengths there
  for (const auto& t : ctx.m.lengths)
    if (path->length.has(t.symbol)) lengths[t.symbol] = sqrt(substituted(t.squared, coordinates));
  ex origin_length = substituted(path->length, coordinates);
  if (!lengths.empty()) origin_length = substituted(origin_length, lengths);
  in.scope.bind("origin_length", origin_length);
  auto tension = rule_expr(ctx, in, l.expr, l.at);
  if (!tension) return;
  for (auto& load : tension_loads(*path, ctx.m.points, *tension, own_origin(in)))
    ctx.m.loads.push_back(std::move(load));
}

// The generalized force of a length sum on coordinate q, `generalized` = -T dL/dq, as a load:
// in 1-D a force along the axis; on an angle, a couple; in 2-D and 3-D, a force at the center
// of mass along the line the coordinate moves it on (a length sum says how long the string
// is, not which way it pulls, so that line must be straight).
void length_sum_load(BuildContext& ctx, const Instance& in, const Coordinate& q, const ex& generalized) {
  const ConnectionDesc& c = in.c;
  const std::string& label = in.label;
  const Body& b = ctx.m.bodies[q.body];
  Load load;
  load.body = q.body;
  if (q.kind == Coordinate::Kind::rotation) {
    load.couple = {0, 0, generalized};
  } else if (ctx.m.dims() == 1) {
    load.force = {generalized, 0, 0};
  } else {
    Vec along = zero_vec();
    for (int i = 0; i < 3; ++i) along[i] = b.cm[i].diff(ex_to<symbol>(q.q));
    bool straight = !is_zero_vec(along);
    for (const Coordinate& other : ctx.m.coordinates)
      for (int i = 0; i < 3; ++i)
        straight = straight && !along[i].has(other.q) &&
                   (other.body != q.body || other.q.is_equal(q.q) || !b.cm[i].has(other.q));
    if (!straight) {
      ctx.diags.error(c.at, "the length sum of " + label + " is written in " + to_text(q.q) +
                                ", which does not move body '" + b.name +
                                "' along one straight line (expected a coordinate along a line, or the string's "
                                "'path')");
      return;
    }
    load.force = (generalized / inner(along, along).expand()) * along;
    load.at = b.cm;
    load.at_name = b.name;
  }
  load.origin = length_sum_origin(own_origin(in), b.name);
  ctx.m.loads.push_back(load);
}

// Loads `from_length` of a length sum: its generalized force on each coordinate it is
// written in, -T dL/dq (virtual work).
void loads_from_length(BuildContext& ctx, Instance& in, const LoadSpec& l) {
  auto it = in.expr_args.find(l.arg);
  if (it == in.expr_args.end()) return;
  auto tension = rule_expr(ctx, in, l.expr, l.at);
  if (!tension) return;
  for (const Coordinate& q : ctx.m.coordinates) {
    const ex dl = it->second.first.diff(ex_to<symbol>(q.q));
    if (dl.is_zero()) continue;
    const ex generalized = -*tension * dl;
    length_sum_load(ctx, in, q, generalized);
  }
}

// The rule's loads that apply to the connection, into m.loads.
void add_loads(BuildContext& ctx, Instance& in) {
  for (const auto& l : in.rule.loads) {
    if (!applies(ctx, in.c, l.when)) continue;  // for an optional argument not given, or another number of axes
    if (l.kind == LoadSpec::Kind::on)
      load_on(ctx, in, l);
    else if (l.kind == LoadSpec::Kind::along)
      loads_along(ctx, in, l);
    else
      loads_from_length(ctx, in, l);
  }
}

// A rule that assumes the direction of sliding with no friction at the given numbers (mu = 0):
// its forces along the sliding direction are zero, so a turn changes nothing.
bool frictionless(BuildContext& ctx, const Instance& in) {
  const auto along = in.vector_args.find("sliding");
  if (along == in.vector_args.end()) return false;
  const exmap values = ctx.table->values();
  bool any = false;
  for (const auto& l : ctx.m.loads) {
    if (l.source() != in.label) continue;
    any = true;
    const ex f = evalf(substituted(inner(l.force, unit(along->second)), values));
    if (!f.is_zero()) return false;
  }
  return any;
}

// The rule's validity conditions in the connection's symbols, and its assumptions (each once).
void add_validity_and_assumptions(BuildContext& ctx, Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  const std::string& label = in.label;
  for (const auto& v : rule->validity) {
    if (!applies(ctx, c, v.when)) continue;
    auto r = parse_relation(v.holds, in.scope);
    for (const auto& p : r.problems) ctx.diags.error(v.at, "rule '" + rule->type + "': " + p.message);
    if (r.value) ctx.m.conditions.push_back({r.value->lhs, r.value->rhs, r.value->op, v.meaning, v.otherwise, label});
  }
  for (const auto& a : rule->assumptions) {
    if (!applies(ctx, c, a.when)) continue;
    if (std::find(ctx.m.assumptions.begin(), ctx.m.assumptions.end(), a.text) == ctx.m.assumptions.end())
      ctx.m.assumptions.push_back(a.text);
  }
}

// The model's note of the connection: the rule's text with its {N}, {mu*N} in this
// connection's own symbols (N_A, mu N_A).
void add_note(BuildContext& ctx, Instance& in) {
  const std::string& tmpl = in.rule.summary_for(ctx.m.dims());
  Model::ConnectionNote note{in.label, "", {}};
  std::size_t from = 0;
  for (const auto& ph : placeholders(tmpl)) {
    note.summary += tmpl.substr(from, ph.open - from);
    auto r = parse_expression(ph.name, in.scope);
    if (r.value && !is_vector(*r.value)) {
      note.summary += "{}";
      note.terms.push_back(*r.value);
    } else {
      note.summary += std::string(ph.name);  // an optional argument not given: as written
    }
    from = ph.close + 1;
  }
  note.summary += tmpl.substr(from);
  ctx.m.connections.push_back(std::move(note));
}

// What the figure draws for the connection, when its rule says how: the first argument of
// each kind, in the rule's order.
void add_drawing(BuildContext& ctx, const Instance& in) {
  const Rule* rule = &in.rule;
  if (rule->sketch.empty()) return;
  Model::Drawing d;
  d.as = rule->sketch;
  d.label = in.label;
  bool vector = false;
  for (const auto& spec : rule->args) {  // the first argument of each kind, in the rule's order
    if (spec.kind == ArgKind::points && d.path.empty() && in.path_args.count(spec.key))
      d.path = in.path_args.at(spec.key);
    if (spec.kind == ArgKind::body && d.body < 0 && in.body_args.count(spec.key)) d.body = in.body_args.at(spec.key);
    if (spec.kind == ArgKind::point && in.point_args.count(spec.key)) {
      if (d.point < 0) d.point = in.point_args.at(spec.key);
      d.points.push_back(in.point_args.at(spec.key));
    }
    if (spec.kind == ArgKind::vector && !vector && in.vector_args.count(spec.key)) {
      d.vector = in.vector_args.at(spec.key);
      vector = true;
    }
  }
  ctx.m.drawings.push_back(std::move(d));
}

// A rule that assumes the direction of sliding (unless frictionless): noted, with the
// velocity the contact slips at.
void add_assumed_direction(BuildContext& ctx, const Instance& in) {
  const std::string& label = in.label;
  if (!in.rule.assumes_direction || frictionless(ctx, in)) return;
  ctx.m.direction_assumed_by.push_back(label);
  // At a point of a turning body the contact slips at the material point's velocity, not
  // the center's (a ball that slides and spins).
  const auto body = in.body_args.find("body");
  const auto other = in.body_args.find("other");
  const auto at = in.point_args.find("at");
  const auto along = in.vector_args.find("sliding");
  if (body != in.body_args.end() && at != in.point_args.end() && along != in.vector_args.end()) {
    const Body& b = ctx.m.bodies[body->second];
    const Vec& p = ctx.m.points[at->second].position;
    if (other != in.body_args.end()) {
      // Two bodies: the contact slips at the first's velocity relative to the other's.
      const Body& o = ctx.m.bodies[other->second];
      const auto v = kinematics::point_velocity(ctx.m, b, p - b.cm), w = kinematics::point_velocity(ctx.m, o, p - o.cm);
      if (v && w)
        ctx.m.slips.push_back(
            {label, fewer_trig_terms(inner(unit(along->second), *v - *w).expand()), {body->second, other->second}});
    } else if (!b.angle.is_zero()) {
      if (const auto v = kinematics::point_velocity(ctx.m, b, p - b.cm))
        ctx.m.slips.push_back({label, fewer_trig_terms(inner(unit(along->second), *v).expand()), {body->second}});
    }
  }
}

// A `positive` check: a stiffness or damping coefficient, positive where its value is known.
void check_positive(BuildContext& ctx, const Instance& in, const CheckSpec& chk) {
  auto it = in.expr_args.find(chk.arg);
  if (it == in.expr_args.end()) return;
  const ex v = evalf(substituted(it->second.first, ctx.table->values()));
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real() && !ex_to<numeric>(v).is_positive()) {
    const ArgSpec* spec = in.rule.arg(chk.arg);
    const std::string unit = spec && spec->dimension ? si_unit_name(*spec->dimension) : "";
    ctx.diags.error(it->second.second, "'" + chk.arg + "' of a " + in.what + " is " +
                                           (is_a<numeric>(it->second.first) ? "" : to_text(it->second.first) + " = ") +
                                           fmt::format("{:g}", ex_to<numeric>(v).to_double()) +
                                           (unit.empty() ? "" : " " + unit) + " (expected a positive value)");
  }
}

// The rule's checks: a positive value now, the others (that need every connection) pending.
void add_checks(BuildContext& ctx, Instance& in) {
  for (const auto& chk : in.rule.checks) {
    if (!applies(ctx, in.c, chk.when) || chk.kind == CheckSpec::Kind::across) continue;  // (across: vectors_fit)
    if (chk.kind == CheckSpec::Kind::positive) {
      check_positive(ctx, in, chk);
      continue;
    }
    ctx.pending_checks.push_back({&chk, in.point_args.count(chk.arg) ? in.point_args[chk.arg] : -1, in.c.at, in.what});
  }
}

// Validity conditions, assumptions, the model's list of connections, and checks that need
// every connection (run after all of them).
void add_conditions(BuildContext& ctx, Instance& in) {
  add_validity_and_assumptions(ctx, in);
  add_note(ctx, in);
  add_drawing(ctx, in);
  add_assumed_direction(ctx, in);
  add_checks(ctx, in);
}

// One connection: its rule found, then instantiated step by step (connection_steps.hpp).
void connection(BuildContext& ctx, const ConnectionDesc& c, std::set<std::string>& connection_names) {
  const Rule* found = ctx.rules.find(c.type.text);
  if (!found) {
    std::string msg = "unknown connection type '" + c.type.text + "'";
    if (auto near = nearest(c.type.text, ctx.rules.names()); !near.empty())
      msg += " (did you mean '" + near + "'?)";
    else
      msg += " (known: " + join(ctx.rules.names()) + ")";
    ctx.diags.error(c.type.at, msg);
    return;
  }
  if (!found->regimes.empty())  // (the pipeline makes it one of its regimes before the model is built)
    throw InternalError("a '" + found->type + "' connection reached the model builder undecided");
  Instance in{c,
              *found,
              "'" + found->type + "' connection" + (c.name ? " '" + c.name->text + "'" : ""),
              {},
              Scope(*ctx.table),
              {},
              {},
              {},
              {},
              {}};
  if (c.name && !connection_names.insert(c.name->text).second)
    ctx.diags.error(c.name->at, "duplicate connection name '" + c.name->text + "'");
  if (!arguments_fit(ctx, in) || !bind_arguments(ctx, in)) {
    ctx.connection_failed = true;  // its paths are unknown: points it would run over too
    return;
  }
  if (at_point_of_another_body(ctx, in)) return;
  in.label = label_of(in);
  if (!vectors_fit(ctx, in)) return;
  if (!make_unknowns(ctx, in)) return;
  add_loads(ctx, in);
  add_constraints(ctx, in);
  add_conditions(ctx, in);
}

}  // namespace

void connections(BuildContext& ctx) {
  std::set<std::string> names;
  for (const auto& c : ctx.d.connections) connection(ctx, c, names);
  // A path bends at a fixed point only where something holds it (a pulley: a rule whose
  // check says a path passes over its point); a point on a body is held by the body.
  std::set<int> held;
  for (const auto& pc : ctx.pending_checks)
    if (pc.check->kind == CheckSpec::Kind::passes_over && pc.point >= 0) held.insert(pc.point);
  for (const auto& [point, by] : ctx.interior_points)
    if (ctx.m.points[point].body < 0 && !held.count(point))
      ctx.diags.error(by.second, "the path of a " + by.first + " runs over point '" + ctx.m.points[point].name +
                                     "', which nothing holds (expected a pulley there: {type: pulley, at: " +
                                     ctx.m.points[point].name + "})");
  for (const auto& pc : ctx.pending_checks) {
    // (Not when a connection could not be read: its path may be the one that runs there.)
    if (pc.check->kind == CheckSpec::Kind::passes_over && pc.point >= 0 && !ctx.interior_points.count(pc.point) &&
        !ctx.connection_failed)
      ctx.diags.error(pc.at, "no string runs over point '" + ctx.m.points[pc.point].name + "' of a " + pc.what +
                                 " (expected it inside some string's path)");
    if (pc.check->kind == CheckSpec::Kind::steady_at && pc.point >= 0) {
      if (auto it = ctx.turning_at.find(pc.point); it != ctx.turning_at.end())
        ctx.diags.error(pc.at,
                        "strand " + it->second + " at point '" + ctx.m.points[pc.point].name + "' of a " + pc.what +
                            " turns as the bodies move, so the length wrapped on it would change (expected strands "
                            "that keep their directions there, or the pulley as a point: no '" +
                            pc.check->when + "')");
    }
  }
}

}  // namespace tackle::build

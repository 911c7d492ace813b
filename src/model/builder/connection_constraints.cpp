// A connection's constraints: a path's length, a length sum, a point held still, two bodies
// together (or pinned together, one turning), keeping along a direction, a body rolling.
#include "model/builder/connection_steps.hpp"
#include "model/builder/stages.hpp"

#include "expr/print.hpp"
#include "expr/trig.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

// Rolling without slipping on a straight surface along `along`: the body's material point at
// the contact has no velocity along the surface, v . t + omega (z x r) . t = 0 (r from the
// center to the contact). With r fixed in the ground's directions (the contact point keeps
// them: 'turns: false') this integrates: cm . t + angle (z x r) . t is constant (x + r phi
// for a wheel on level ground).
void roll(BuildContext& ctx, Instance& in, const ConstraintSpec& k) {
  const auto b = in.body_args.find(k.arg);
  const auto p = in.point_args.find(k.point);
  const auto t = in.vector_args.find(k.with);
  if (b == in.body_args.end() || p == in.point_args.end() || t == in.vector_args.end()) return;
  const Body& body = ctx.m.bodies[b->second];
  const Point& contact = ctx.m.points[p->second];
  if (body.angle.is_zero()) {
    ctx.diags.error(in.c.at, "body '" + body.name + "' of a " + in.what +
                                 " does not turn (expected a body with an 'angle': a wheel rolls by turning)");
    return;
  }
  if (contact.body != b->second || contact.turns) {
    ctx.diags.error(in.c.at, "the contact point '" + contact.name + "' of a " + in.what + " is not a point of body '" +
                                 body.name + "' that keeps the ground's directions (expected a point written {on: " +
                                 body.name + ", offset: ..., turns: false}, where the wheel touches the surface)");
    return;
  }
  const Vec along = unit(t->second);
  const Vec r = contact.offset;
  if (!normal(inner(r, along)).is_zero()) {
    ctx.diags.error(in.c.at, "the contact point '" + contact.name + "' of a " + in.what +
                                 " is not straight across the surface from the center of body '" + body.name +
                                 "' (expected its offset " + to_text(r[0]) + ", " + to_text(r[1]) +
                                 " at right angles to the rolling direction)");
    return;
  }
  const ex lever = fewer_trig_terms(normal(inner(cross(Vec{0, 0, 1}, r), along)));
  const ex q = (fewer_trig_terms(inner(body.cm, along).expand()) + lever * body.angle).expand();
  ctx.m.constraints.push_back(
      {in.label, in.c.name ? in.c.name->text : "", q,
       "travel of " + body.name + " along the surface plus the arc it turns through (it rolls without slipping)"});
}

// One body's position relative to another along a direction, constant: two bodies that stay
// in contact (along the normal), or do not slip on each other (along the tangent). For bodies
// that only translate (a turning one's contact point moves on it: refused). Nothing to keep
// where the coordinates already keep it (a block's height on a cart written as a constant).
void keep(BuildContext& ctx, Instance& in, const ConstraintSpec& k) {
  const auto a = in.body_args.find(k.arg), b = in.body_args.find(k.with);
  const auto v = in.vector_args.find(k.along);
  if (a == in.body_args.end() || b == in.body_args.end() || v == in.vector_args.end()) return;
  const Body& first = ctx.m.bodies[a->second];
  const Body& second = ctx.m.bodies[b->second];
  if (a->second == b->second) {
    ctx.diags.error(in.c.at,
                    "a " + in.what + " joins body '" + first.name + "' to itself (expected two different bodies)");
    return;
  }
  for (const Body* body : {&first, &second})
    if (!body->angle.is_zero()) {
      ctx.diags.error(in.c.at,
                      "body '" + body->name + "' of a " + in.what +
                          " turns, and its point of contact moves on it (expected two bodies that only translate)");
      return;
    }
  const ex q = fewer_trig_terms(normal(inner(first.cm - second.cm, unit(v->second))).expand());
  bool moves = false;
  for (const auto& coordinate : ctx.m.coordinates) moves = moves || q.has(coordinate.q);
  if (!moves) return;
  const std::string direction = to_text(v->second[0]) + ", " + to_text(v->second[1]);
  ctx.m.constraints.push_back(
      {in.label + " (along [" + direction + "])", in.c.name ? in.c.name->text : "", q,
       "position of " + first.name + " relative to " + second.name + " along [" + direction + "]"});
}

// Two bodies joined at a point P, one of them (or both) turning: for each body, P stays its
// own point. A body that only translates carries P at a fixed offset from its center; a
// turning one at a fixed offset in its frame, Rot(angle) r0, with r0 where P sits in the
// layout. What the coordinates do not already keep so (a pendulum's bob written in the
// cart's x and its angle keeps its pin) is a constraint, one per axis.
void pinned_together(BuildContext& ctx, Instance& in, const Body& first, const Body& second, const Point& p) {
  const std::string cname = in.c.name ? in.c.name->text : "";
  exmap layout_coordinates;
  for (const auto& c : ctx.m.coordinates)
    if (auto it = ctx.layout.find(c.q); it != ctx.layout.end())
      layout_coordinates[c.q] = it->second;
    else
      layout_coordinates[c.q] = 0;
  for (const Body* b : {&first, &second}) {
    const Vec d = p.position - b->cm;
    Vec q = d;  // must stay constant
    if (!b->angle.is_zero()) {
      const ex& a = b->angle;
      // P's offset in the body's frame, Rot(-a) d; where it sits in the layout, r0.
      const ex rx = fewer_trig_terms(normal((cos(a) * d[0] + sin(a) * d[1]).expand()));
      const ex ry = fewer_trig_terms(normal((-sin(a) * d[0] + cos(a) * d[1]).expand()));
      bool fixed = true;
      for (const auto& c : ctx.m.coordinates) fixed = fixed && !rx.has(c.q) && !ry.has(c.q);
      if (fixed) continue;  // the coordinates keep P on this body
      const ex r0x = rx.subs(layout_coordinates), r0y = ry.subs(layout_coordinates);
      q = {d[0] - (cos(a) * r0x - sin(a) * r0y), d[1] - (sin(a) * r0x + cos(a) * r0y), 0};
    }
    for (int i = 0; i < 2; ++i) {
      const ex qi = fewer_trig_terms(q[i].expand());
      bool moves = false;
      for (const auto& coordinate : ctx.m.coordinates) moves = moves || qi.has(coordinate.q);
      if (!moves) continue;
      ctx.m.constraints.push_back({in.label + " (" + ctx.m.axes[i] + ", " + b->name + ")", cname, qi,
                                   "position of the joint " + p.name + " on " + b->name + " along " + ctx.m.axes[i]});
    }
  }
}

// Two bodies `together`, joined (see pinned_together when one turns).
void together(BuildContext& ctx, Instance& in, const ConstraintSpec& k) {
  const ConnectionDesc& c = in.c;
  const std::string& label = in.label;
  const std::string cname = c.name ? c.name->text : "";
  // One body's position relative to the other, along each axis, is constant.
  auto a = in.body_args.find(k.arg), b = in.body_args.find(k.with);
  if (a == in.body_args.end() || b == in.body_args.end()) return;
  const Body& first = ctx.m.bodies[a->second];
  const Body& second = ctx.m.bodies[b->second];
  if (a->second == b->second) {
    ctx.diags.error(c.at,
                    "a " + in.what + " joins body '" + first.name + "' to itself (expected two different bodies)");
    return;
  }
  // With a body that turns, the bodies do not share their translation: each one's own
  // point at the joint stays at the joint (a pendulum pinned to a cart).
  const auto at = in.point_args.find("at");
  if ((!first.angle.is_zero() || !second.angle.is_zero()) && at != in.point_args.end()) {
    pinned_together(ctx, in, first, second, ctx.m.points[at->second]);
    return;
  }
  for (int i = 0; i < ctx.m.dims(); ++i) {
    const ex q = (second.cm[i] - first.cm[i]).expand();
    bool moves = false;
    for (const auto& coordinate : ctx.m.coordinates) moves = moves || q.has(coordinate.q);
    if (!moves) continue;
    ctx.m.constraints.push_back({label + (ctx.m.dims() > 1 ? " (" + ctx.m.axes[i] + ")" : ""), cname, q,
                                 "position of " + second.name + " relative to " + first.name +
                                     (ctx.m.dims() > 1 ? " along " + ctx.m.axes[i] : "")});
  }
}

}  // namespace

// The rule's constraints, into m.constraints.
void add_constraints(BuildContext& ctx, Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  const std::string& label = in.label;
  const std::string cname = c.name ? c.name->text : "";
  for (const auto& k : rule->constraints) {
    if (k.kind == ConstraintSpec::Kind::length) {
      if (const Path* path = path_of(ctx, in, k.arg))
        ctx.m.constraints.push_back({label, cname, path->varying_length, "length of " + label});
    } else if (k.kind == ConstraintSpec::Kind::together) {
      together(ctx, in, k);
    } else if (k.kind == ConstraintSpec::Kind::rolls) {
      roll(ctx, in, k);
    } else if (k.kind == ConstraintSpec::Kind::keeps) {
      keep(ctx, in, k);
    } else if (k.kind == ConstraintSpec::Kind::length_sum) {
      auto it = in.expr_args.find(k.arg);
      if (it == in.expr_args.end()) continue;
      ctx.m.constraints.push_back({label, cname, it->second.first, "length of " + label});
    } else {
      auto it = in.point_args.find(k.arg);
      if (it == in.point_args.end()) continue;
      const Point& p = ctx.m.points[it->second];
      ctx.m.constraints.push_back({label, cname, p.position[0], "position of " + p.name});
    }
  }
}

}  // namespace tackle::build

// Rule instantiation: each connection's arguments checked and bound, its unknowns made, its
// loads, constraints and conditions added to the Model; then the checks that need every
// connection.
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

// Whether a rule entry with this `when` applies to the connection: always, when it gives the
// optional argument named, or in a problem with the number of axes named ("3-D").
bool applies(const BuildContext& ctx, const ConnectionDesc& c, const std::string& when) {
  if (when.empty()) return true;
  if (const auto axes = when_axes(when)) return *axes == ctx.m.dims();
  return c.arg(when) != nullptr;
}

std::string substitute(BuildContext& ctx, std::string tmpl, const ConnectionDesc& c, bool& ok) {
  std::size_t pos;
  while ((pos = tmpl.find('{')) != std::string::npos) {
    const auto end = tmpl.find('}', pos);
    if (end == std::string::npos) break;
    const std::string key = tmpl.substr(pos + 1, end - pos - 1);
    std::string value;
    if (key == "name") {
      if (!c.name) {
        ctx.diags.error(c.at, "a '" + c.type.text + "' connection needs a 'name' (its unknowns are named after it)");
        ok = false;
        return {};
      }
      value = c.name->text;
    } else if (const ArgDesc* a = c.arg(key); a && a->items.size() == 1) {
      value = a->items[0].text;
    } else {
      ok = false;
      return {};
    }
    tmpl.replace(pos, end - pos + 1, value);
  }
  return tmpl;
}

// The connection gives what its rule needs, and the rule is for this many axes.
bool arguments_fit(BuildContext& ctx, const Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  const std::string& what = in.what;
  bool ok = true;
  // Arguments: known keys, required ones present, exactly one of each group.
  std::vector<std::string> arg_keys;
  for (const auto& a : rule->args) arg_keys.push_back(a.key);
  for (const auto& a : c.args) {
    if (!rule->arg(a.key.text)) {
      std::string msg = "unknown key '" + a.key.text + "' for a " + what;
      if (auto near = nearest(a.key.text, arg_keys); !near.empty())
        msg += " (did you mean '" + near + "'?)";
      else
        msg += " (expected one of: " + join(arg_keys) + ")";
      ctx.diags.error(a.key.at, msg);
      ok = false;
    }
  }
  for (const auto& spec : rule->args)
    if (spec.required && !c.arg(spec.key)) {
      ctx.diags.error(c.at, "a " + what + " needs '" + spec.key + "'");
      ok = false;
    }
  for (const auto& group : rule->one_of) {
    std::vector<std::string> present;
    for (const auto& k : group)
      if (c.arg(k)) present.push_back(k);
    if (present.size() != 1) {
      ctx.diags.error(c.at, "a " + what +
                                (present.empty() ? " needs one of: " + join(group)
                                                 : " has " + join(present, " and ") + " (expected one of them)"));
      ok = false;
    }
  }
  if (!ok) return false;

  if (std::find(rule->dimensions.begin(), rule->dimensions.end(), ctx.m.dims()) == rule->dimensions.end()) {
    std::vector<std::string> dims;
    for (int n : rule->dimensions) dims.push_back(std::to_string(n) + "-D");
    ctx.diags.error(c.type.at, "a " + what + " is for " + join(dims, " and ") + " problems (this one has " +
                                   std::to_string(ctx.m.dims()) + (ctx.m.dims() == 1 ? " axis)" : " axes)"));
    return false;
  }
  return true;
}

// Resolves every argument: bodies and points by name (bound as position vectors in the
// rule's scope), paths, expressions, vectors and moments.
bool bind_arguments(BuildContext& ctx, Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  const std::string& what = in.what;
  Scope& scope = in.scope;
  auto& point_args = in.point_args;
  auto& body_args = in.body_args;
  auto& path_args = in.path_args;
  auto& expr_args = in.expr_args;
  bool ok = true;
  for (const auto& spec : rule->args) {
    const ArgDesc* a = c.arg(spec.key);
    if (!a) continue;
    const bool list = spec.kind == ArgKind::points;
    if (spec.kind != ArgKind::vector && spec.kind != ArgKind::moment && list != a->is_list) {
      ctx.diags.error(a->key.at, "'" + spec.key + "' of a " + what +
                                     (list ? " is a single name (expected a list of points)"
                                           : " is a list (expected a single value)"));
      ok = false;
      continue;
    }
    if (a->items.empty()) {  // it was not a name or a list of names: reported when it was read
      ok = false;
      continue;
    }
    switch (spec.kind) {
      case ArgKind::body: {
        auto it = ctx.body_index.find(a->items[0].text);
        if (it == ctx.body_index.end()) {
          ctx.unknown_name(a->items[0], "body", ctx.body_names());
          ok = false;
        } else {
          point_args[spec.key] = ctx.point_index.at(a->items[0].text);
          body_args[spec.key] = it->second;
          const Vec& cm = ctx.m.bodies[it->second].cm;
          scope.bind(spec.key, make_vector(cm[0], cm[1], cm[2]));
        }
        break;
      }
      case ArgKind::point: {
        auto it = ctx.point_index.find(a->items[0].text);
        if (it == ctx.point_index.end()) {
          ctx.unknown_name(a->items[0], "point", ctx.point_names());
          ok = false;
        } else {
          point_args[spec.key] = it->second;
          const Vec& p = ctx.m.points[it->second].position;
          scope.bind(spec.key, make_vector(p[0], p[1], p[2]));
        }
        break;
      }
      case ArgKind::points: {
        std::vector<int> path;
        for (const auto& item : a->items) {
          auto it = ctx.point_index.find(item.text);
          if (it == ctx.point_index.end()) {
            ctx.unknown_name(item, "point", ctx.point_names());
            ok = false;
          } else
            path.push_back(it->second);
        }
        if (a->items.size() < 2) {
          ctx.diags.error(a->key.at, "'" + spec.key + "' of a " + what + " has " + std::to_string(a->items.size()) +
                                         " point (expected at least two)");
          ok = false;
        }
        path_args[spec.key] = path;
        break;
      }
      case ArgKind::expr: {
        if (auto e = ctx.parse(a->items[0], *ctx.table, "'" + spec.key + "' of a " + what)) {
          if (spec.dimension && !e->is_zero())
            ctx.check_dimension(*e, *spec.dimension, a->items[0].at, "'" + spec.key + "' of a " + what);
          scope.bind(spec.key, *e);
          expr_args[spec.key] = {*e, a->items[0].at};
        } else {
          ok = false;
        }
        break;
      }
      case ArgKind::vector: {
        const VectorDesc vd{a->items, a->items.empty() ? a->key.at : a->items[0].at};
        if (auto v = ctx.vector(vd, *ctx.table, "'" + spec.key + "' of a " + what, spec.dimension)) {
          scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
          in.vector_args[spec.key] = *v;
        } else
          ok = false;
        break;
      }
      case ArgKind::moment: {
        // 2-D: one number, about z; 3-D: a vector.
        const Location at = a->items.empty() ? a->key.at : a->items[0].at;
        if (ctx.m.dims() == 2) {
          if (a->items.size() != 1) {
            ctx.diags.error(at, "'" + spec.key + "' of a " + what + " has " + std::to_string(a->items.size()) +
                                    " entries (expected one number, the moment about z)");
            ok = false;
          } else if (auto e = ctx.parse(a->items[0], *ctx.table, "'" + spec.key + "' of a " + what)) {
            if (spec.dimension && !is_a<numeric>(*e))
              ctx.check_dimension(*e, *spec.dimension, at, "'" + spec.key + "' of a " + what);
            scope.bind(spec.key, make_vector(0, 0, *e));
          } else {
            ok = false;
          }
        } else if (auto v = ctx.vector(VectorDesc{a->items, at}, *ctx.table, "'" + spec.key + "' of a " + what,
                                       spec.dimension)) {
          scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
        } else {
          ok = false;
        }
        break;
      }
      case ArgKind::name:
        if (!is_identifier(a->items[0].text)) {
          ctx.diags.error(a->items[0].at, "'" + a->items[0].text + "' is not a valid name");
          ok = false;
        }
        break;
    }
  }

  for (const auto& [key, path] : path_args)
    for (std::size_t i = 1; i + 1 < path.size(); ++i)
      ctx.interior_points.emplace(path[i], std::make_pair(in.what, c.at));
  return ok;
}

std::string label_of(const Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  // "string s", or after the first point argument ("pulley at C", "rod from H"), else the
  // first body argument ("force on A").
  std::string label = rule->type;
  std::replace(label.begin(), label.end(), '_', ' ');  // "ball and socket at O", as a person writes it
  if (c.name) {
    label += " " + c.name->text;
  } else {
    for (const ArgKind kind : {ArgKind::point, ArgKind::body}) {
      const auto spec = std::find_if(rule->args.begin(), rule->args.end(),
                                     [&](const ArgSpec& a) { return a.kind == kind && c.arg(a.key); });
      if (spec != rule->args.end()) {
        label += " " + spec->key + " " + c.arg(spec->key)->items[0].text;
        break;
      }
    }
  }
  return label;
}

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

// `across` checks, before the loads are made of the vectors: a direction that is not zero, at
// right angles to another (a contact's tangent to its normal), whatever the parameters it is
// written in, or at least at their given numbers.
bool vectors_fit(BuildContext& ctx, const Instance& in) {
  bool ok = true;
  const exmap values = ctx.table->values();
  auto where = [&](const std::string& key) {
    const ArgDesc* a = in.c.arg(key);
    return a && !a->items.empty() ? a->items[0].at : a ? a->key.at : in.c.at;
  };
  // "" when not zero, else how: zero, or zero at the given numbers.
  auto zero = [&](const Vec& v) -> std::string {
    bool symbolic = true, numeric_zero = true;
    for (const ex& x : v) {
      const ex n = fewer_trig_terms(normal(x.expand()));
      symbolic = symbolic && n.is_zero();
      const ex at = evalf(substituted(n, values));
      numeric_zero = numeric_zero && is_a<numeric>(at) && std::abs(ex_to<numeric>(at).to_double()) < 1e-12;
    }
    return symbolic ? "the zero vector" : numeric_zero ? "the zero vector at the given numbers" : "";
  };
  for (const auto& chk : in.rule.checks) {
    if (chk.kind != CheckSpec::Kind::across || !applies(ctx, in.c, chk.when)) continue;
    const auto v = in.vector_args.find(chk.arg), w = in.vector_args.find(chk.to);
    if (v == in.vector_args.end() || w == in.vector_args.end()) continue;
    bool nonzero = true;
    for (const auto& [key, vec] : {std::pair{chk.to, w->second}, std::pair{chk.arg, v->second}})
      if (const std::string how = zero(vec); !how.empty()) {
        ctx.diags.error(where(key),
                        "'" + key + "' of a " + in.what + " is " + how +
                            (key == chk.to ? std::string(" (expected a direction)")
                                           : " (expected a direction at right angles to '" + chk.to + "')"));
        ok = nonzero = false;
      }
    if (!nonzero) continue;
    const ex dot = fewer_trig_terms(normal(inner(v->second, w->second).expand()));
    if (dot.is_zero()) continue;
    const ex at = evalf(substituted(dot, values));
    const bool number = is_a<numeric>(at) && ex_to<numeric>(at).is_real();
    if (number && std::abs(ex_to<numeric>(at).to_double()) < 1e-12) continue;  // at right angles at the given numbers
    std::string vs;
    for (int i = 0; i < ctx.m.dims(); ++i) vs += (i ? ", " : "") + to_text(v->second[i]);
    std::string ws;
    for (int i = 0; i < ctx.m.dims(); ++i) ws += (i ? ", " : "") + to_text(w->second[i]);
    ctx.diags.error(
        where(chk.arg),
        "'" + chk.arg + "' of a " + in.what + ", [" + vs + "], is not at right angles to its '" + chk.to + "', [" + ws +
            "]: their dot product is " + to_text(dot) +
            (number && !is_a<numeric>(dot) ? fmt::format(" = {:g} at the given numbers", ex_to<numeric>(at).to_double())
                                           : std::string()) +
            " (expected a direction at right angles to '" + chk.to + "')");
    ok = false;
  }
  return ok;
}

bool make_unknowns(BuildContext& ctx, Instance& in) {
  const ConnectionDesc& c = in.c;
  for (const auto& u : in.rule.unknowns) {
    if (!applies(ctx, c, u.when)) continue;
    std::string name;
    Location at = c.at;
    if (u.rename_arg && c.arg(*u.rename_arg)) {
      name = c.arg(*u.rename_arg)->items[0].text;
      at = c.arg(*u.rename_arg)->items[0].at;
    } else {
      bool named = true;
      name = substitute(ctx, u.name_template, c, named);
      if (!named) return false;
    }
    if (!ctx.claim(Text{name, at}, "unknown")) return false;
    const SymbolInfo& s = ctx.table->add(name, std::nullopt, SymbolRole::unknown, u.dimension, false, at);
    in.scope.bind(u.local, s.sym);
    ctx.m.candidates.push_back(s.sym);
  }
  return true;
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

void add_loads(BuildContext& ctx, Instance& in) {
  const ConnectionDesc& c = in.c;
  const Rule* rule = &in.rule;
  const std::string& what = in.what;
  const std::string& label = in.label;
  auto& point_args = in.point_args;
  auto& body_args = in.body_args;
  auto& expr_args = in.expr_args;
  for (const auto& l : rule->loads) {
    if (!applies(ctx, c, l.when)) continue;  // for an optional argument not given, or another number of axes
    if (l.kind == LoadSpec::Kind::on) {
      auto it = point_args.find(l.arg);
      if (it == point_args.end()) continue;  // optional argument not given
      int body = -1;
      if (auto bt = body_args.find(l.arg); bt != body_args.end())
        body = bt->second;
      else
        body = ctx.m.points[it->second].body;
      if (body < 0) {
        ctx.diags.error(c.at, "a " + what + " acts on fixed point '" + ctx.m.points[it->second].name +
                                  "' (expected a body or a point on one)");
        continue;
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
      if (!good) continue;
      if (ctx.m.dims() > 1 && !load.at && !is_zero_vec(load.force)) {
        ctx.diags.error(c.at, "a " + what + " needs a point of application in a " + std::to_string(ctx.m.dims()) +
                                  "-D problem (give '" + (l.at_arg.empty() ? std::string("at") : l.at_arg) + "')");
        continue;
      }
      ctx.m.loads.push_back(load);
    } else if (l.kind == LoadSpec::Kind::along) {
      const Path* path = path_of(ctx, in, l.arg);
      if (!path) continue;
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
      if (!tension) continue;
      for (auto& load : tension_loads(*path, ctx.m.points, *tension, own_origin(in)))
        ctx.m.loads.push_back(std::move(load));
    } else {
      auto it = expr_args.find(l.arg);
      if (it == expr_args.end()) continue;
      auto tension = rule_expr(ctx, in, l.expr, l.at);
      if (!tension) continue;
      // Generalized force of a length sum L on coordinate q: -T dL/dq (virtual work). In
      // 1-D it is a force along the axis; on an angle, a couple; in 2-D and 3-D, a force at
      // the center of mass along the line the coordinate moves it on (a length sum says how
      // long the string is, not which way it pulls, so that line must be straight).
      for (const Coordinate& q : ctx.m.coordinates) {
        const Body& b = ctx.m.bodies[q.body];
        const ex dl = it->second.first.diff(ex_to<symbol>(q.q));
        if (dl.is_zero()) continue;
        const ex generalized = -*tension * dl;
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
            ctx.diags.error(
                c.at, "the length sum of " + label + " is written in " + to_text(q.q) + ", which does not move body '" +
                          b.name +
                          "' along one straight line (expected a coordinate along a line, or the string's 'path')");
            continue;
          }
          load.force = (generalized / inner(along, along).expand()) * along;
          load.at = b.cm;
          load.at_name = b.name;
        }
        load.origin = length_sum_origin(own_origin(in), b.name);
        ctx.m.loads.push_back(load);
      }
    }
  }
}

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

// A one-body contact (a body against the ground) placed at a point of another body that
// moves: the contact's force on the other body would be missing. Refused, naming the rule for
// two bodies.
bool at_point_of_another_body(BuildContext& ctx, const Instance& in) {
  const auto body = in.body_args.find("body");
  if (body == in.body_args.end() || in.body_args.size() != 1) return false;
  for (const auto& spec : in.rule.args) {
    if (spec.kind != ArgKind::point) continue;
    const auto p = in.point_args.find(spec.key);
    const ArgDesc* a = in.c.arg(spec.key);
    if (p == in.point_args.end() || !a || a->items.empty()) continue;
    const Point& point = ctx.m.points[static_cast<std::size_t>(p->second)];
    if (point.body < 0 || point.body == body->second) continue;
    const Body& other = ctx.m.bodies[static_cast<std::size_t>(point.body)];
    if (other.coord.is_zero() && other.angle.is_zero() && !other.has_mass) continue;  // a body that does not move
    const std::string& held = ctx.m.bodies[static_cast<std::size_t>(body->second)].name;
    const std::string instead = in.rule.two_bodies.empty() ? "a connection between two bodies"
                                                           : "{type: " + in.rule.two_bodies + ", body: " + held +
                                                                 ", other: " + other.name + ", ...}";
    ctx.diags.error(a->items[0].at, "'" + spec.key + "' of a " + in.what + " is point '" + point.name + "' of body '" +
                                        other.name + "', which moves: this connection holds '" + held +
                                        "' against the ground, and the force on '" + other.name +
                                        "' would be missing (expected a fixed point or a point of '" + held +
                                        "'; for two bodies: " + instead + ")");
    return true;
  }
  return false;
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
      // One body's position relative to the other, along each axis, is constant.
      auto a = in.body_args.find(k.arg), b = in.body_args.find(k.with);
      if (a == in.body_args.end() || b == in.body_args.end()) continue;
      const Body& first = ctx.m.bodies[a->second];
      const Body& second = ctx.m.bodies[b->second];
      if (a->second == b->second) {
        ctx.diags.error(c.at,
                        "a " + in.what + " joins body '" + first.name + "' to itself (expected two different bodies)");
        continue;
      }
      // With a body that turns, the bodies do not share their translation: each one's own
      // point at the joint stays at the joint (a pendulum pinned to a cart).
      const auto at = in.point_args.find("at");
      if ((!first.angle.is_zero() || !second.angle.is_zero()) && at != in.point_args.end()) {
        pinned_together(ctx, in, first, second, ctx.m.points[at->second]);
        continue;
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

// Validity conditions, assumptions, the model's list of connections, and checks that need
// every connection (run after all of them).
void add_conditions(BuildContext& ctx, Instance& in) {
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
  {
    // The rule's text with its {N}, {mu*N} in this connection's own symbols (N_A, mu N_A).
    const std::string& tmpl = rule->summary_for(ctx.m.dims());
    Model::ConnectionNote note{label, "", {}};
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
  if (!rule->sketch.empty()) {
    Model::Drawing d;
    d.as = rule->sketch;
    d.label = label;
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
  if (rule->assumes_direction && !frictionless(ctx, in)) {
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
        const auto v = kinematics::point_velocity(ctx.m, b, p - b.cm),
                   w = kinematics::point_velocity(ctx.m, o, p - o.cm);
        if (v && w)
          ctx.m.slips.push_back(
              {label, fewer_trig_terms(inner(unit(along->second), *v - *w).expand()), {body->second, other->second}});
      } else if (!b.angle.is_zero()) {
        if (const auto v = kinematics::point_velocity(ctx.m, b, p - b.cm))
          ctx.m.slips.push_back({label, fewer_trig_terms(inner(unit(along->second), *v).expand()), {body->second}});
      }
    }
  }
  for (const auto& chk : rule->checks) {
    if (!applies(ctx, c, chk.when) || chk.kind == CheckSpec::Kind::across) continue;  // (across: vectors_fit)
    if (chk.kind == CheckSpec::Kind::positive) {
      // A stiffness or damping coefficient: positive where its value is known.
      auto it = in.expr_args.find(chk.arg);
      if (it == in.expr_args.end()) continue;
      const ex v = evalf(substituted(it->second.first, ctx.table->values()));
      if (is_a<numeric>(v) && ex_to<numeric>(v).is_real() && !ex_to<numeric>(v).is_positive()) {
        const ArgSpec* spec = in.rule.arg(chk.arg);
        const std::string unit = spec && spec->dimension ? si_unit_name(*spec->dimension) : "";
        ctx.diags.error(it->second.second,
                        "'" + chk.arg + "' of a " + in.what + " is " +
                            (is_a<numeric>(it->second.first) ? "" : to_text(it->second.first) + " = ") +
                            fmt::format("{:g}", ex_to<numeric>(v).to_double()) + (unit.empty() ? "" : " " + unit) +
                            " (expected a positive value)");
      }
      continue;
    }
    ctx.pending_checks.push_back({&chk, in.point_args.count(chk.arg) ? in.point_args[chk.arg] : -1, c.at, in.what});
  }
}

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

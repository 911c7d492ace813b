// A connection's arguments: checked against its rule, bound in its scope (bodies, points,
// paths, expressions, vectors, moments), its label, the `across` checks of its vectors, its
// unknowns.
#include "model/builder/connection_steps.hpp"
#include "model/builder/stages.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "expr/print.hpp"
#include "expr/trig.hpp"
#include "model/kinematics.hpp"

namespace tackle::build {

using namespace GiNaC;

// Whether a rule entry with this `when` applies to the connection: always, when it gives the
// optional argument named, or in a problem with the number of axes named ("3-D").
bool applies(const BuildContext& ctx, const ConnectionDesc& c, const std::string& when) {
  if (when.empty()) return true;
  if (const auto axes = when_axes(when)) return *axes == ctx.m.dims();
  return c.arg(when) != nullptr;
}

namespace {

// The rule's name template with {name} and {ARG} replaced by the connection's; `ok` false (and
// "" returned) when one is missing.
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

// A body argument: the body, and its center of mass bound as a position vector.
bool bind_body(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  auto it = ctx.body_index.find(a->items[0].text);
  if (it == ctx.body_index.end()) {
    ctx.unknown_name(a->items[0], "body", ctx.body_names());
    return false;
  }
  in.point_args[spec.key] = ctx.point_index.at(a->items[0].text);
  in.body_args[spec.key] = it->second;
  const Vec& cm = ctx.m.bodies[it->second].cm;
  in.scope.bind(spec.key, make_vector(cm[0], cm[1], cm[2]));
  return true;
}

// A point argument: the point, bound as a position vector.
bool bind_point(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  auto it = ctx.point_index.find(a->items[0].text);
  if (it == ctx.point_index.end()) {
    ctx.unknown_name(a->items[0], "point", ctx.point_names());
    return false;
  }
  in.point_args[spec.key] = it->second;
  const Vec& p = ctx.m.points[it->second].position;
  in.scope.bind(spec.key, make_vector(p[0], p[1], p[2]));
  return true;
}

// A points argument: the points of a path, at least two.
bool bind_points(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  bool ok = true;
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
    ctx.diags.error(a->key.at, "'" + spec.key + "' of a " + in.what + " has " + std::to_string(a->items.size()) +
                                   " point (expected at least two)");
    ok = false;
  }
  in.path_args[spec.key] = path;
  return ok;
}

// An expression argument, of the dimension the rule gives (0 has any).
bool bind_expr(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  if (auto e = ctx.parse(a->items[0], *ctx.table, "'" + spec.key + "' of a " + in.what)) {
    if (spec.dimension && !e->is_zero())
      ctx.check_dimension(*e, *spec.dimension, a->items[0].at, "'" + spec.key + "' of a " + in.what);
    in.scope.bind(spec.key, *e);
    in.expr_args[spec.key] = {*e, a->items[0].at};
    return true;
  }
  return false;
}

// A vector argument.
bool bind_vector(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  const VectorDesc vd{a->items, a->items.empty() ? a->key.at : a->items[0].at};
  if (auto v = ctx.vector(vd, *ctx.table, "'" + spec.key + "' of a " + in.what, spec.dimension)) {
    in.scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
    in.vector_args[spec.key] = *v;
    return true;
  }
  return false;
}

// A moment argument. 2-D: one number, about z; 3-D: a vector.
bool bind_moment(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  const Location at = a->items.empty() ? a->key.at : a->items[0].at;
  if (ctx.m.dims() == 2) {
    if (a->items.size() != 1) {
      ctx.diags.error(at, "'" + spec.key + "' of a " + in.what + " has " + std::to_string(a->items.size()) +
                              " entries (expected one number, the moment about z)");
      return false;
    }
    if (auto e = ctx.parse(a->items[0], *ctx.table, "'" + spec.key + "' of a " + in.what)) {
      if (spec.dimension && !is_a<numeric>(*e))
        ctx.check_dimension(*e, *spec.dimension, at, "'" + spec.key + "' of a " + in.what);
      in.scope.bind(spec.key, make_vector(0, 0, *e));
      return true;
    }
    return false;
  }
  if (auto v = ctx.vector(VectorDesc{a->items, at}, *ctx.table, "'" + spec.key + "' of a " + in.what, spec.dimension)) {
    in.scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
    return true;
  }
  return false;
}

// One argument the connection gives, read as its kind; false when it is reported (or was,
// when it was read).
bool bind_argument(BuildContext& ctx, Instance& in, const ArgSpec& spec, const ArgDesc* a) {
  const bool list = spec.kind == ArgKind::points;
  if (spec.kind != ArgKind::vector && spec.kind != ArgKind::moment && list != a->is_list) {
    ctx.diags.error(a->key.at, "'" + spec.key + "' of a " + in.what +
                                   (list ? " is a single name (expected a list of points)"
                                         : " is a list (expected a single value)"));
    return false;
  }
  if (a->items.empty()) return false;  // it was not a name or a list of names: reported when it was read
  switch (spec.kind) {
    case ArgKind::body: return bind_body(ctx, in, spec, a);
    case ArgKind::point: return bind_point(ctx, in, spec, a);
    case ArgKind::points: return bind_points(ctx, in, spec, a);
    case ArgKind::expr: return bind_expr(ctx, in, spec, a);
    case ArgKind::vector: return bind_vector(ctx, in, spec, a);
    case ArgKind::moment: return bind_moment(ctx, in, spec, a);
    case ArgKind::name:
      if (!is_identifier(a->items[0].text)) {
        ctx.diags.error(a->items[0].at, "'" + a->items[0].text + "' is not a valid name");
        return false;
      }
      break;
  }
  return true;
}

}  // namespace

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
  bool ok = true;
  for (const auto& spec : in.rule.args) {
    const ArgDesc* a = in.c.arg(spec.key);
    if (!a) continue;
    if (!bind_argument(ctx, in, spec, a)) ok = false;
  }

  for (const auto& [key, path] : in.path_args)
    for (std::size_t i = 1; i + 1 < path.size(); ++i)
      ctx.interior_points.emplace(path[i], std::make_pair(in.what, in.c.at));
  return ok;
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
    if (!kinematics::translation(ctx.m, other) && other.angle.is_zero() && !other.has_mass)
      continue;  // a body that does not move
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

// "string s", "pulley at C", "force on A": how reports name the connection.
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

// The rule's unknowns, named for the connection (after an argument, or by the name template)
// and bound in its scope; false when a name cannot be made or is taken.
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

}  // namespace tackle::build

#include "description/description.hpp"

#include "core/files.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include "description/latex_safety.hpp"
#include "description/yaml_reader.hpp"

namespace tackle {

const ArgDesc* ConnectionDesc::arg(const std::string& key) const {
  for (const auto& a : args)
    if (a.key.text == key) return &a;
  return nullptr;
}

namespace {

using yaml::check_map;
using yaml::scalar;
using yaml::scalar_list;
using yaml::where;

struct Reader {
  const std::string& file;
  Diagnostics& diags;
  Description& d;

  std::optional<Text> opt_scalar(const yaml::Node& map, const char* key, const std::string& what) {
    const yaml::Node n = map[key];
    if (!n) return std::nullopt;
    return scalar(n, "'" + std::string(key) + "' of " + what, file, diags);
  }

  Text key_text(const yaml::Node& key) { return {key.text(), where(key, file)}; }

  // A scalar (one item) or a list of scalars.
  std::optional<VectorDesc> vector(const yaml::Node& n, const std::string& what) {
    VectorDesc v;
    v.at = where(n, file);
    if (n.is_scalar()) {
      v.items.push_back({n.text(), where(n, file)});
      return v;
    }
    if (!n.is_sequence()) {
      diags.error(where(n, file), what + " is " + yaml::kind_name(n) + " (expected an expression or a list of them)");
      return std::nullopt;
    }
    for (const auto& item : n) {
      if (auto t = scalar(item, "an entry of " + what, file, diags))
        v.items.push_back(*t);
      else
        return std::nullopt;
    }
    if (v.items.empty()) {
      diags.error(v.at, what + " is an empty list (expected one entry per axis)");
      return std::nullopt;
    }
    return v;
  }
  std::optional<VectorDesc> opt_vector(const yaml::Node& map, const char* key, const std::string& what) {
    const yaml::Node n = map[key];
    if (!n) return std::nullopt;
    return vector(n, "'" + std::string(key) + "' of " + what);
  }

  // A section that maps names to entries (parameters, bodies, points).
  bool name_map(const yaml::Node& n, const std::string& section) {
    if (!n.is_map()) {
      diags.error(where(n, file), "'" + section + "' is " + yaml::kind_name(n) + " (expected a mapping of names)");
      return false;
    }
    yaml::check_unique_keys(n, "'" + section + "'", file, diags);
    return true;
  }

  void read_parameters(const yaml::Node& n) {
    if (!name_map(n, "parameters")) return;
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!seen.insert(kv.first.text()).second) continue;  // reported as a duplicate key
      ParameterDesc p;
      p.name = key_text(kv.first);
      const std::string what = "parameter '" + p.name.text + "'";
      const yaml::Node v = kv.second;
      if (v.is_null()) {
        // symbolic only
      } else if (v.is_scalar()) {
        p.value = Text{v.text(), where(v, file)};
      } else if (check_map(v,
                           {"value", "unit", "dimension", "tex", "positive", "description", "define", "range", "round"},
                           what, file, diags)) {
        if (const yaml::Node r = v["range"]) {
          if (auto items = scalar_list(r, "'range' of " + what, file, diags)) {
            if (items->size() != 2 || !r.is_sequence())
              diags.error(where(r, file), "'range' of " + what + " has " + std::to_string(items->size()) +
                                              " entries (expected [low, high])");
            else
              p.range = *items;
          }
        }
        p.round = opt_scalar(v, "round", what);
        p.value = opt_scalar(v, "value", what);
        p.define = opt_scalar(v, "define", what);
        if (p.define && (p.value || p.unit || p.dimension))
          diags.error(p.define->at, what +
                                        " has 'define' with 'value', 'unit' or 'dimension' (a defined name takes all "
                                        "of them from its expression)");
        p.unit = opt_scalar(v, "unit", what);
        p.dimension = opt_scalar(v, "dimension", what);
        p.tex = opt_scalar(v, "tex", what);
        if (auto pos = opt_scalar(v, "positive", what)) {
          if (pos->text == "true")
            p.positive = true;
          else if (pos->text == "false")
            p.positive = false;
          else
            diags.error(pos->at, "'positive' of " + what + " is '" + pos->text + "' (expected true or false)");
        }
      }
      d.parameters.push_back(std::move(p));
    }
  }

  // `given`: a list of names, or a mapping from names to their values at the instant
  // (null, a number, or {value, unit}).
  void read_given(const yaml::Node& n) {
    if (!n.is_map()) {
      if (auto items = scalar_list(n, "'given'", file, diags))
        for (const auto& t : *items) d.given.push_back({t, std::nullopt, std::nullopt});
      return;
    }
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!seen.insert(kv.first.text()).second) continue;  // reported as a duplicate key
      GivenDesc g{key_text(kv.first), std::nullopt, std::nullopt};
      const std::string what = "'given' value of '" + g.name.text + "'";
      const yaml::Node v = kv.second;
      if (v.is_null()) {
        // known, without a value
      } else if (v.is_scalar()) {
        g.value = Text{v.text(), where(v, file)};
      } else if (check_map(v, {"value", "unit"}, what, file, diags)) {
        g.value = opt_scalar(v, "value", what);
        g.unit = opt_scalar(v, "unit", what);
        if (g.unit && !g.value) diags.error(g.unit->at, what + " has a 'unit' but no 'value'");
      }
      d.given.push_back(std::move(g));
    }
  }

  void read_bodies(const yaml::Node& n) {
    if (!name_map(n, "bodies")) return;
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!seen.insert(kv.first.text()).second) continue;
      BodyDesc b;
      b.name = key_text(kv.first);
      b.at = where(kv.second, file);
      const std::string what = "body '" + b.name.text + "'";
      if (check_map(kv.second,
                    {"mass", "position", "angle", "center_of_mass", "acceleration", "inertia", "shape", "draw"}, what,
                    file, diags)) {
        b.mass = opt_scalar(kv.second, "mass", what);
        b.position = opt_scalar(kv.second, "position", what);
        b.angle = opt_scalar(kv.second, "angle", what);
        b.inertia = opt_scalar(kv.second, "inertia", what);
        if (const yaml::Node sh = kv.second["shape"]) {
          const std::string expected =
              " (expected one of {disk: R}, {ring: R}, {rod: L}, {sphere: R}, {box: [a, b]}, point)";
          if (sh.is_scalar()) {
            b.shape_kind = opt_scalar(kv.second, "shape", what);
          } else if (!sh.is_map() || sh.size() != 1) {
            diags.error(where(sh, file), "'shape' of " + what + " is not a shape" + expected);
          } else {
            for (const auto& skv : sh) {
              b.shape_kind = key_text(skv.first);
              b.shape_size = vector(skv.second, "'shape' of " + what);
            }
          }
        }
        b.center_of_mass = opt_vector(kv.second, "center_of_mass", what);
        if (const yaml::Node acc = kv.second["acceleration"]) {
          if (acc.is_map()) {
            if (check_map(acc, {"along", "name"}, "'acceleration' of " + what, file, diags)) {
              b.accel_along = opt_vector(acc, "along", "'acceleration' of " + what);
              b.accel_name = opt_scalar(acc, "name", "'acceleration' of " + what);
              if (!b.accel_along)
                diags.error(where(acc, file),
                            "'acceleration' of " + what + " has no 'along' (expected the direction of motion)");
            }
          } else {
            b.acceleration = vector(acc, "'acceleration' of " + what);
          }
        }
        if (const yaml::Node dr = kv.second["draw"]) {
          if (!dr.is_map())
            diags.error(
                where(dr, file),
                "'draw' of " + what +
                    " is not a mapping (expected {shape: rectangle, size: [w, h]}, {shape: circle, size: [d]} or "
                    "{shape: wedge, size: [base, height]})");
          else if (check_map(dr, {"shape", "size", "face"}, "'draw' of " + what, file, diags)) {
            b.draw_shape = opt_scalar(dr, "shape", "'draw' of " + what);
            b.draw_size = opt_vector(dr, "size", "'draw' of " + what);
            b.draw_face = opt_scalar(dr, "face", "'draw' of " + what);
            if (!b.draw_shape)
              diags.error(where(dr, file),
                          "'draw' of " + what + " has no 'shape' (expected rectangle, circle, spool or wedge)");
          }
        }
      }
      d.bodies.push_back(std::move(b));
    }
  }

  void read_points(const yaml::Node& n) {
    if (!name_map(n, "points")) return;
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!seen.insert(kv.first.text()).second) continue;
      PointDesc p;
      p.name = key_text(kv.first);
      const std::string what = "point '" + p.name.text + "'";
      if (kv.second.is_scalar() || kv.second.is_sequence()) {
        p.at = vector(kv.second, what);
      } else if (check_map(kv.second, {"at", "on", "offset", "turns"}, what, file, diags)) {
        p.at = opt_vector(kv.second, "at", what);
        p.on = opt_scalar(kv.second, "on", what);
        p.offset = opt_vector(kv.second, "offset", what);
        if (auto turns = opt_scalar(kv.second, "turns", what)) {
          p.turns_at = turns->at;
          if (turns->text == "false")
            p.turns = false;
          else if (turns->text != "true")
            diags.error(turns->at, "'turns' of " + what + " is '" + turns->text + "' (expected true or false)");
          if (!p.on)
            diags.error(turns->at, "'turns' of " + what + " needs 'on' (only a point on a body turns with it)");
        }
        if (p.at && p.on)
          diags.error(where(kv.second, file),
                      what + " has both 'at' and 'on' (expected a fixed point or a point on a body)");
        else if (!p.at && !p.on)
          diags.error(where(kv.second, file),
                      what + " has neither 'at' nor 'on' (expected a fixed position or a body)");
        if (p.offset && !p.on)
          diags.error(p.offset->at, "'offset' of " + what + " needs 'on' (an offset is measured from a body)");
      }
      d.points.push_back(std::move(p));
    }
  }

  // A connection entry: `type` (given, or implied by the section), optional `name`, and
  // arguments the rule checks later.
  void read_connection(const yaml::Node& n, const std::optional<std::string>& implied_type,
                       const std::string& section) {
    if (!n.is_map()) {
      diags.error(where(n, file), "an entry of '" + section + "' is " + yaml::kind_name(n) + " (expected a mapping)");
      return;
    }
    ConnectionDesc c;
    c.at = where(n, file);
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!kv.first.is_scalar()) {
        diags.error(where(kv.first, file), "a key in an entry of '" + section + "' is not a name");
        continue;
      }
      const std::string key = kv.first.text();
      if (!seen.insert(key).second) {
        diags.error(where(kv.first, file), "duplicate key '" + key + "' in an entry of '" + section + "'");
        continue;
      }
      if (key == "type" && !implied_type) {
        if (auto t = scalar(kv.second, "'type'", file, diags)) c.type = *t;
      } else if (key == "name") {
        c.name = scalar(kv.second, "'name'", file, diags);
      } else {
        ArgDesc a;
        a.key = key_text(kv.first);
        a.is_list = kv.second.is_sequence();
        if (auto items = scalar_list(kv.second, "'" + key + "'", file, diags)) a.items = *items;
        c.args.push_back(std::move(a));
      }
    }
    if (implied_type) {
      c.type = Text{*implied_type, c.at};
    } else if (c.type.text.empty()) {
      diags.error(c.at, "a connection has no 'type' (expected a rule name from rules/)");
      return;
    }
    d.connections.push_back(std::move(c));
  }

  void read_list(const yaml::Node& n, const std::string& section, const std::optional<std::string>& implied) {
    if (!n.is_sequence()) {
      diags.error(where(n, file), "'" + section + "' is " + yaml::kind_name(n) + " (expected a list)");
      return;
    }
    for (const auto& item : n) read_connection(item, implied, section);
  }

  void read_layout(const yaml::Node& n) {
    if (!n.is_map()) {
      diags.error(where(n, file),
                  "'layout' is " + yaml::kind_name(n) + " (expected a mapping of coordinates to numbers)");
      return;
    }
    yaml::check_unique_keys(n, "'layout'", file, diags);
    for (const auto& kv : n)
      if (auto v = scalar(kv.second, "layout value of '" + kv.first.text() + "'", file, diags))
        d.layout.emplace_back(key_text(kv.first), *v);
  }

  void read_find(const yaml::Node& n) {
    if (!n.is_sequence()) {
      diags.error(where(n, file), "'find' is " + yaml::kind_name(n) + " (expected a list of unknowns)");
      return;
    }
    for (const auto& item : n) {
      FindDesc f;
      if (item.is_scalar()) {
        f.name = Text{item.text(), where(item, file)};
      } else if (check_map(item, {"name", "expr", "tex", "unit"}, "an entry of 'find'", file, diags)) {
        if (auto nm = opt_scalar(item, "name", "an entry of 'find'"))
          f.name = *nm;
        else {
          diags.error(where(item, file), "an entry of 'find' has no 'name'");
          continue;
        }
        f.expr = opt_scalar(item, "expr", "'" + f.name.text + "' in 'find'");
        f.tex = opt_scalar(item, "tex", "'" + f.name.text + "' in 'find'");
        f.unit = opt_scalar(item, "unit", "'" + f.name.text + "' in 'find'");
      } else {
        continue;
      }
      d.find.push_back(std::move(f));
    }
  }

  void read_motion(const yaml::Node& n) {
    if (!check_map(n, {"coordinates", "initial", "until", "plot", "speed_at"}, "'motion'", file, diags)) return;
    MotionDesc mo;
    mo.at = where(n, file);
    if (auto c = n["coordinates"])
      if (auto items = scalar_list(c, "'coordinates' of 'motion'", file, diags)) mo.coordinates = *items;
    if (auto init = n["initial"]) {
      if (!init.is_map()) {
        diags.error(where(init, file),
                    "'initial' of 'motion' is " + yaml::kind_name(init) +
                        " (expected a mapping of coordinates and rates to values, e.g. {y: y_0, dot(y): 0})");
      } else {
        yaml::check_unique_keys(init, "'initial' of 'motion'", file, diags);
        std::set<std::string> seen;
        for (const auto& kv : init) {
          if (!seen.insert(kv.first.text()).second) continue;
          const std::string what = "initial value of '" + kv.first.text() + "'";
          if (kv.second.is_map()) {  // {value: 60, unit: deg}
            if (check_map(kv.second, {"value", "unit"}, what, file, diags)) {
              auto v = opt_scalar(kv.second, "value", what);
              if (!v)
                diags.error(where(kv.second, file), what + " has no 'value' (expected, e.g., {value: 60, unit: deg})");
              else
                mo.initial.emplace_back(key_text(kv.first), *v),
                    mo.initial_units.push_back(opt_scalar(kv.second, "unit", what));
            }
          } else if (auto v = scalar(kv.second, what, file, diags)) {
            mo.initial.emplace_back(key_text(kv.first), *v);
            mo.initial_units.emplace_back();
          }
        }
      }
    } else {
      diags.error(
          mo.at,
          "'motion' has no 'initial' (expected the coordinates' values and rates at t = 0, e.g. {y: y_0, dot(y): 0})");
    }
    if (auto u = n["until"]) {
      if (u.is_map()) {
        if (check_map(u, {"value", "unit"}, "'until' of 'motion'", file, diags)) {
          mo.until = opt_scalar(u, "value", "'until' of 'motion'");
          mo.until_unit = opt_scalar(u, "unit", "'until' of 'motion'");
          if (!mo.until)
            diags.error(where(u, file), "'until' of 'motion' has no 'value' (expected, e.g., {value: 2, unit: s})");
        }
      } else {
        mo.until = scalar(u, "'until' of 'motion'", file, diags);
      }
    }
    if (auto p = n["plot"])
      if (auto items = scalar_list(p, "'plot' of 'motion'", file, diags)) mo.plot = *items;
    if (auto sa = n["speed_at"]) {
      std::vector<std::pair<Text, Text>> values;
      read_values(sa, "'speed_at' of 'motion'", values);
      if (values.size() == 1)
        mo.speed_at = values.front();
      else if (sa.is_map())
        diags.error(where(sa, file), "'speed_at' of 'motion' names " + std::to_string(values.size()) +
                                         " coordinates (expected one, e.g. {x: 0})");
    }
    d.motion = std::move(mo);
  }

  // A mapping of names to expressions (`{dot(x): v_1}`), into `out`.
  void read_values(const yaml::Node& n, const std::string& what, std::vector<std::pair<Text, Text>>& out,
                   const std::string& expected = "a mapping of rates to values, e.g. {dot(x): v_1}") {
    if (!n.is_map()) {
      diags.error(where(n, file), what + " is " + yaml::kind_name(n) + " (expected " + expected + ")");
      return;
    }
    yaml::check_unique_keys(n, what, file, diags);
    std::set<std::string> seen;
    for (const auto& kv : n) {
      if (!seen.insert(kv.first.text()).second) continue;
      if (auto v = scalar(kv.second, "value of '" + kv.first.text() + "' in " + what, file, diags))
        out.emplace_back(key_text(kv.first), *v);
    }
  }

  void read_interval(const yaml::Node& n) {
    if (!check_map(n, {"duration", "distance", "from", "to"}, "'interval'", file, diags)) return;
    IntervalDesc iv;
    iv.at = where(n, file);
    iv.duration = opt_scalar(n, "duration", "'interval'");
    iv.distance = opt_scalar(n, "distance", "'interval'");
    if (iv.duration.has_value() == iv.distance.has_value())
      diags.error(iv.at,
                  "'interval' needs exactly one of 'duration' and 'distance' (expected, e.g., duration: Delta_t)");
    if (auto f = n["from"])
      read_values(f, "'from' of 'interval'", iv.from);
    else
      diags.error(iv.at, "'interval' has no 'from' (expected the rates at its start, e.g. {dot(x): v_1})");
    if (auto t = n["to"]) read_values(t, "'to' of 'interval'", iv.to);
    d.interval = std::move(iv);
  }

  void read_steady(const yaml::Node& n) {
    if (!check_map(n, {"rate", "unit", "period"}, "'steady'", file, diags)) return;
    SteadyDesc st;
    st.at = where(n, file);
    if (auto r = opt_scalar(n, "rate", "'steady'"))
      st.rate = *r;
    else
      diags.error(st.at, "'steady' has no 'rate' (expected the name of the unknown rate, e.g. rate: omega)");
    st.unit = opt_scalar(n, "unit", "'steady'");
    st.period = opt_scalar(n, "period", "'steady'");
    d.steady = std::move(st);
  }

  void read_impact(const yaml::Node& n) {
    if (!check_map(n, {"from", "plastic", "restitution"}, "'impact'", file, diags)) return;
    ImpactDesc im;
    im.at = where(n, file);
    if (auto f = n["from"])
      read_values(f, "'from' of 'impact'", im.from);
    else
      diags.error(im.at, "'impact' has no 'from' (expected the rates just before it, e.g. {dot(x_A): v, dot(x_B): 0})");
    im.plastic = opt_scalar(n, "plastic", "'impact'");
    im.restitution = opt_scalar(n, "restitution", "'impact'");
    if (im.plastic && im.plastic->text != "true")
      diags.error(im.plastic->at,
                  "'plastic' of 'impact' is '" + im.plastic->text + "' (expected true, or 'restitution: e' instead)");
    if (im.plastic.has_value() == im.restitution.has_value())
      diags.error(im.at,
                  "'impact' needs exactly one of 'plastic: true' (the bodies stick together) and 'restitution' "
                  "(a coefficient, two bodies)");
    d.impact = std::move(im);
  }

  // The phases, each read as a description of its own from the same document (locations
  // stay those of the file); the shared parameters come first in each.
  void read_phases(const yaml::Node& n) {
    if (!n.is_sequence() || n.size() == 0) {
      diags.error(where(n, file), "'phases' is " +
                                      (n.is_sequence() ? std::string("an empty list") : yaml::kind_name(n)) +
                                      " (expected a list of phases, each a mapping with a name, its bodies, ...)");
      return;
    }
    std::set<std::string> names;
    for (const auto& item : n) {
      if (!item.is_map()) {
        diags.error(where(item, file),
                    "a phase is " + yaml::kind_name(item) + " (expected a mapping with a name, its bodies, ...)");
        continue;
      }
      PhaseDesc ph;
      ph.at = where(item, file);
      ph.d.file = file;
      ph.d.parameters = d.parameters;
      if (auto nm = item["name"]) {
        if (auto t = scalar(nm, "'name' of a phase", file, diags)) {
          ph.name = *t;
          if (!names.insert(t->text).second)
            diags.error(t->at, "a second phase named '" + t->text + "' (expected phase names to differ)");
        }
      } else {
        diags.error(ph.at, "a phase has no 'name' (expected, e.g., name: fall)");
      }
      ph.d.title = {d.title.text + ": " + (ph.name.text.empty() ? std::string("phase") : ph.name.text), ph.at};
      if (d.phases.empty()) ph.d.statement = d.statement;  // the problem's statement goes with its first phase
      Reader inner{file, diags, ph.d};
      inner.read_root(item, true);
      if (auto c = item["carry"])
        read_values(c, "'carry' of phase '" + ph.name.text + "'", ph.carry,
                    "a mapping of new names to quantities at the phase's end, e.g. {v: dot(y)}");
      d.phases.push_back(std::move(ph));
    }
  }

  void read_root(const yaml::Node& root, bool phase) {
    std::vector<std::string> keys{"axes",
                                  "parameters",
                                  "gravity",
                                  "bodies",
                                  "points",
                                  "connections",
                                  "loads",
                                  "strings",
                                  "layout",
                                  "given",
                                  "find",
                                  "derive",
                                  "expected",
                                  "expected_combinations",
                                  "expected_conditions",
                                  "expected_ranges",
                                  "expected_free",
                                  "expected_power",
                                  "notes",
                                  "sweep",
                                  "motion",
                                  "expected_motion",
                                  "interval",
                                  "impact",
                                  "steady"};
    if (phase) {
      keys.insert(keys.begin(), {"name", "carry"});
    } else {
      keys.insert(keys.begin(), {"title", "source", "statement"});
    }
    check_map(root, keys, phase ? "a phase" : "the description", file, diags);
    if (!phase) {
      if (auto st = root["statement"]) d.statement = scalar(st, "'statement'", file, diags);
      if (auto t = root["title"]) {
        if (auto s = scalar(t, "'title'", file, diags)) d.title = *s;
      } else {
        diags.error({file, 1, 1}, "the description has no 'title' (expected a one-line title)");
      }
    }
    if (auto a = root["axes"]) {
      if (auto items = scalar_list(a, "'axes'", file, diags)) d.axes = *items;
    }
    if (auto p = root["parameters"]) read_parameters(p);
    if (auto g = root["gravity"]) {
      if (g.is_map()) {
        if (check_map(g, {"magnitude", "tilt"}, "'gravity'", file, diags)) {
          d.gravity_magnitude = opt_scalar(g, "magnitude", "'gravity'");
          d.gravity_tilt = opt_scalar(g, "tilt", "'gravity'");
          if (!d.gravity_magnitude || !d.gravity_tilt)
            diags.error(where(g, file),
                        "'gravity' as a mapping needs 'magnitude' and 'tilt' (the angle the first axis rises above the "
                        "horizontal)");
        }
      } else {
        d.gravity = vector(g, "'gravity'");
      }
    }
    if (auto b = root["bodies"])
      read_bodies(b);
    else
      diags.error(
          phase ? where(root, file) : Location{file, 1, 1},
          std::string(phase ? "the phase" : "the description") + " has no 'bodies' (expected at least one body)");
    if (auto p = root["points"]) read_points(p);
    if (auto c = root["connections"]) read_list(c, "connections", std::nullopt);
    if (auto l = root["loads"]) read_list(l, "loads", std::string("force"));
    if (auto s = root["strings"]) read_list(s, "strings", std::string("string"));
    if (auto l = root["layout"]) read_layout(l);
    if (auto g = root["given"]) read_given(g);
    if (auto f = root["find"]) read_find(f);
    if (auto dv = root["derive"]) read_derive(dv);
    if (auto sw = root["sweep"]) {
      if (check_map(sw, {"vary", "fix", "plot", "against"}, "'sweep'", file, diags)) {
        SweepDesc sd;
        sd.at = where(sw, file);
        if (auto v = sw["vary"]) {
          if (auto t = scalar(v, "'vary' of 'sweep'", file, diags)) sd.vary = *t;
        } else {
          diags.error(sd.at, "'sweep' has no 'vary' (expected name=start:end:count, e.g. h=0:2:41)");
        }
        if (auto f = sw["fix"])
          if (auto items = scalar_list(f, "'fix' of 'sweep'", file, diags)) sd.fix = *items;
        if (auto p = sw["plot"])
          if (auto items = scalar_list(p, "'plot' of 'sweep'", file, diags)) sd.plot = *items;
        if (auto a = sw["against"]) sd.against = scalar(a, "'against' of 'sweep'", file, diags);
        d.sweep = sd;
      }
    }
    if (auto mo = root["motion"]) read_motion(mo);
    if (auto iv = root["interval"]) read_interval(iv);
    if (auto im = root["impact"]) read_impact(im);
    if (auto st = root["steady"]) read_steady(st);
  }

  void read_derive(const yaml::Node& n) {
    if (!n.is_sequence()) {
      diags.error(where(n, file), "'derive' is " + yaml::kind_name(n) + " (expected a list of balances)");
      return;
    }
    for (const auto& item : n) {
      if (!check_map(item, {"lmb", "amb", "constraint", "about", "axis"}, "an entry of 'derive'", file, diags))
        continue;
      DeriveDesc dd;
      int kinds = 0;
      yaml::Node value;
      for (const char* k : {"lmb", "amb", "constraint"})
        if (item[k]) {
          ++kinds;
          value = item[k];
          for (const auto& kv : item)
            if (kv.first.text() == k) dd.kind = key_text(kv.first);
        }
      if (kinds != 1) {
        diags.error(where(item, file), "an entry of 'derive' names " + std::to_string(kinds) +
                                           " balances (expected one of: lmb, amb, constraint)");
        continue;
      }
      dd.is_list = value.is_sequence();
      if (auto items = scalar_list(value, "'" + dd.kind.text + "'", file, diags)) dd.items = *items;
      dd.about = opt_scalar(item, "about", "an entry of 'derive'");
      dd.axis = opt_vector(item, "axis", "an entry of 'derive'");
      if (dd.kind.text == "amb" && !dd.about)
        diags.error(where(item, file),
                    "an 'amb' entry of 'derive' has no 'about' (expected the point the moments are taken about)");
      if (dd.kind.text != "amb" && (dd.about || dd.axis))
        diags.error(where(item, file), "'about' and 'axis' belong to an 'amb' entry of 'derive'");
      if (dd.is_list && dd.items.empty()) {
        diags.error(where(value, file), "'" + dd.kind.text + "' lists no bodies (expected at least one)");
        continue;
      }
      d.derive.push_back(std::move(dd));
    }
  }
};

}  // namespace

DescriptionRead read_description_text(const std::string& text, const std::string& file) {
  Diagnostics diags;
  DescriptionRead out;
  Description& d = out.description;
  d.file = file;
  const yaml::Document doc = yaml::load(text, file, diags);
  const yaml::Node root = doc.root();
  if (diags.empty() && !root.is_map())
    diags.error({file, 1, 1},
                "the description is " + yaml::kind_name(root) + " (expected a mapping with title, bodies, ...)");
  if (!diags.empty()) {
    out.problems = diags.items();
    out.usable = false;
    return out;
  }
  Reader r{file, diags, d};
  if (root["phases"]) {
    check_map(root, {"title", "source", "notes", "statement", "parameters", "phases"}, "a description with 'phases'",
              file, diags);
    if (auto st = root["statement"]) d.statement = scalar(st, "'statement'", file, diags);
    if (auto t = root["title"]) {
      if (auto s = scalar(t, "'title'", file, diags)) d.title = *s;
    } else {
      diags.error({file, 1, 1}, "the description has no 'title' (expected a one-line title)");
    }
    if (auto p = root["parameters"]) r.read_parameters(p);
    r.read_phases(root["phases"]);
  } else {
    r.read_root(root, false);
  }
  check_texts(text, d, diags);
  // A phase's parameters are the shared ones, already checked; its own come after them.
  for (const auto& ph : d.phases) {
    if (ph.name.text.find_first_of("\r\n") != std::string::npos)
      diags.error(ph.name.at,
                  "'name' of a phase has a line break (expected one line: it is part of the phase's title)");
    Description own = ph.d;
    own.title = {};
    own.statement.reset();
    own.parameters.erase(
        own.parameters.begin(),
        own.parameters.begin() + static_cast<std::ptrdiff_t>(std::min(d.parameters.size(), own.parameters.size())));
    check_texts(text, own, diags);
  }
  out.problems = diags.items();
  return out;
}

Description parse_description(const std::string& text, const std::string& file) {
  DescriptionRead r = read_description_text(text, file);
  if (!r.problems.empty()) throw InputError(r.problems);
  return std::move(r.description);
}

Description read_description(const std::string& path) { return parse_description(read_text_file(path), path); }

}  // namespace tackle

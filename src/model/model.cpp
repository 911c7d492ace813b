#include "model/model.hpp"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "expr/print.hpp"
#include "model/path.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// Local names of a rule instance (its expression arguments and unknowns) in front of the
// problem's symbol table.
class Scope : public NameResolver {
 public:
  explicit Scope(const SymbolTable& table) : table_(table) {}
  void bind(const std::string& name, ex value) { locals_[name] = std::move(value); }
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto it = locals_.find(std::string(name)); it != locals_.end()) return it->second;
    return table_.resolve(name);
  }
  std::vector<std::string> known_names() const override {
    auto n = table_.known_names();
    for (const auto& [k, v] : locals_) n.push_back(k);
    return n;
  }

 private:
  const SymbolTable& table_;
  std::map<std::string, ex> locals_;
};

// Numbers only: parameter values and layout values may not use names.
const NameResolver& none = numbers_only();

struct Builder {
  Builder(const Description& desc, const RuleSet& rs) : d(desc), rules(rs) {}
  const Description& d;
  const RuleSet& rules;
  Diagnostics diags;
  std::shared_ptr<SymbolTable> table = std::make_shared<SymbolTable>();
  Model m;
  std::map<std::string, Location> names_in_use;   // symbol names: parameters, coordinates, unknowns
  std::map<std::string, Location> places_in_use;  // body and point names
  std::map<std::string, int> body_index;
  std::map<std::string, int> point_index;  // bodies are points too
  exmap layout;                            // values for telling strand directions

  bool claim(const Text& name, const std::string& what) { return claim_in(names_in_use, name, what); }
  bool claim_place(const Text& name, const std::string& what) { return claim_in(places_in_use, name, what); }

  bool claim_in(std::map<std::string, Location>& names_in_use, const Text& name, const std::string& what) {
    if (!is_identifier(name.text)) {
      diags.error(name.at, what + " name '" + name.text +
                               "' is not a valid name (expected a letter, then letters, digits or _)");
      return false;
    }
    if (auto it = names_in_use.find(name.text); it != names_in_use.end()) {
      diags.error(name.at, "duplicate name '" + name.text + "' (first defined at line " +
                               std::to_string(it->second.line) + ")");
      return false;
    }
    names_in_use[name.text] = name.at;
    return true;
  }

  std::optional<ex> parse(const Text& t, const NameResolver& names, const std::string& what) {
    auto r = parse_expression(t.text, names);
    for (const auto& p : r.problems) diags.error(t.at.shifted(p.column), what + ": " + p.message);
    return r.value;
  }

  // Reports when `e` does not have dimension `expected`; silent when it cannot tell.
  void check_dimension(const ex& e, const Dimension& expected, const Location& at, const std::string& what) {
    std::string problem;
    auto dim = dimension_of(e, *table, problem);
    if (!dim) {
      if (!problem.empty()) diags.error(at, what + " " + problem + " (expected a " + expected.describe() + ")");
      return;
    }
    if (!(*dim == expected))
      diags.error(at, what + " is " + with_article(dim->describe()) + " (expected " + with_article(expected.describe()) + ")");
  }

  void parameters() {
    for (const auto& p : d.parameters) {
      if (!claim(p.name, "parameter")) continue;
      std::optional<Unit> unit;
      if (p.unit) {
        std::string err;
        int col = 0;
        unit = parse_unit(p.unit->text, err, col);
        if (!unit) diags.error(p.unit->at.shifted(col), "unit of parameter '" + p.name.text + "': " + err +
                                                           " (expected SI units such as kg, m, s, N, m/s^2, kN)");
      }
      std::optional<Dimension> dim;
      if (unit) dim = unit->dimension;
      // A value with neither unit nor dimension is a pure number (a friction coefficient).
      if (!p.unit && !p.dimension && p.value && !p.define) dim = Dimension::none();
      if (p.dimension) {
        auto named = Dimension::from_name(p.dimension->text);
        if (!named)
          diags.error(p.dimension->at, "unknown dimension '" + p.dimension->text +
                                           "' (expected force, mass, length, time, velocity, acceleration, ...)");
        else if (dim && !(*dim == *named))
          diags.error(p.dimension->at, "parameter '" + p.name.text + "' has dimension " + named->describe() + " but its unit " +
                                           p.unit->text + " is " +
                                           (*dim == Dimension::none() ? std::string("dimensionless (an angle or a pure number)")
                                                                      : with_article(dim->describe())));
        else
          dim = named;
      }
      // A defined parameter: its dimension, sign and value come from its expression.
      std::optional<ex> definition;
      if (p.define) {
        definition = parse(*p.define, *table, "'define' of parameter '" + p.name.text + "'");
        if (!definition) continue;
        std::string problem;
        dim = dimension_of(*definition, *table, problem);
        if (!problem.empty()) diags.error(p.define->at, "'define' of parameter '" + p.name.text + "' " + problem);
      }
      const bool positive = p.positive.value_or(
          p.name.text == "g" ||
          (dim && (*dim == Dimension::mass() || *dim == Dimension::length() || *dim == Dimension::force() / Dimension::length() ||
                   *dim == Dimension::force() / Dimension::velocity())) ||
          (definition && definition->info(info_flags::positive)));
      table->add(p.name.text, p.tex ? std::optional<std::string>(p.tex->text) : std::nullopt, SymbolRole::parameter,
                 dim, positive, p.name.at);
      if (definition) table->set_definition(p.name.text, *definition);
      table->set_unit(p.name.text, p.unit && unit ? p.unit->text : si_unit_name(dim.value_or(Dimension{})),
                      unit ? unit->to_si : numeric(1));
      if (!p.range.empty()) {
        std::optional<numeric> bounds[2], step;
        for (int i = 0; i < 2; ++i) {
          auto v = parse(p.range[i], none, "'range' of parameter '" + p.name.text + "'");
          if (v && is_a<numeric>(*v)) bounds[i] = ex_to<numeric>(*v);
        }
        if (p.round) {
          auto v = parse(*p.round, none, "'round' of parameter '" + p.name.text + "'");
          if (v && is_a<numeric>(*v) && ex_to<numeric>(*v).is_positive())
            step = ex_to<numeric>(*v);
          else if (v)
            diags.error(p.round->at, "'round' of parameter '" + p.name.text + "' is not a positive number");
        }
        if (bounds[0] && bounds[1]) {
          if (!(*bounds[0] < *bounds[1]))
            diags.error(p.range[0].at, "'range' of parameter '" + p.name.text + "' is empty (expected low < high)");
          else if (positive && !bounds[0]->is_positive())
            diags.error(p.range[0].at, "'range' of parameter '" + p.name.text + "' reaches " + to_text(*bounds[0]) +
                                           ", but the parameter is positive");
          else
            table->set_range(p.name.text, *bounds[0], *bounds[1], step);
        }
      }
      if (p.value) {
        auto v = parse(*p.value, none, "value of parameter '" + p.name.text + "'");
        // A number, or an exact real constant such as pi/6 or sqrt(2).
        const ex approx = v ? evalf(*v) : ex(0);
        if (v && !(is_a<numeric>(approx) && ex_to<numeric>(approx).is_real()))
          diags.error(p.value->at, "value of parameter '" + p.name.text + "' is not a number");
        else if (v) {
          const ex value = unit ? *v * unit->to_si : *v;
          if (positive && !ex_to<numeric>(approx).is_positive())
            diags.error(p.value->at, "parameter '" + p.name.text + "' is assumed positive but its value is " +
                                         to_text(*v) + " (set 'positive: false' to allow it)");
          table->set_value(p.name.text, value);
        }
      }
    }
  }

  // A vector as written: one expression per axis (a bare expression in 1-D). Each entry is
  // checked against `expected` when given (plain numbers are taken in SI).
  std::optional<Vec> vector(const VectorDesc& v, const NameResolver& names, const std::string& what,
                            std::optional<Dimension> expected) {
    if (static_cast<int>(v.items.size()) != m.dims()) {
      diags.error(v.at, what + " has " + std::to_string(v.items.size()) + (v.items.size() == 1 ? " entry" : " entries") +
                            " (expected " + std::to_string(m.dims()) + ", one per axis: " + join(m.axes) + ")");
      return std::nullopt;
    }
    Vec out = zero_vec();
    bool ok = true;
    for (std::size_t i = 0; i < v.items.size(); ++i) {
      auto e = parse(v.items[i], names, what);
      if (!e) {
        ok = false;
        continue;
      }
      if (is_vector(*e)) {
        diags.error(v.items[i].at, what + ": an entry is a vector (expected a number)");
        ok = false;
        continue;
      }
      if (expected && !is_a<numeric>(*e)) check_dimension(*e, *expected, v.items[i].at, what);
      out[i] = *e;
    }
    if (!ok) return std::nullopt;
    return out;
  }

  void bodies() {
    const bool one_d = m.dims() == 1;
    std::vector<ex> accelerations;  // unknown accelerations come first among the unknowns
    for (const auto& b : d.bodies) {
      if (!claim_place(b.name, "body")) continue;
      Body body;
      body.name = b.name.text;
      body.at = b.name.at;
      if (one_d) {
        if (!b.position)
          diags.error(b.at, "body '" + body.name + "' has no 'position' (expected the name of its coordinate, e.g. x_" +
                                body.name + ")");
        for (const auto* v : {&b.center_of_mass, &b.acceleration})
          if (*v) diags.error((*v)->at, "body '" + body.name + "': 'center_of_mass' and 'acceleration' are for 2-D and 3-D problems (in 1-D, 'position' names the coordinate)");
        if (b.accel_along) diags.error(b.accel_along->at, "body '" + body.name + "': 'acceleration' is for 2-D and 3-D problems");
        if (b.position && claim(*b.position, "coordinate")) {
          const std::string q = b.position->text;
          body.coord = table->add(q, std::nullopt, SymbolRole::coordinate, Dimension::length(), false, b.position->at).sym;
          body.rate = table->add("dot(" + q + ")", std::nullopt, SymbolRole::rate, Dimension::velocity(), false,
                                 b.position->at).sym;
          body.accel = table->add("ddot(" + q + ")", std::nullopt, SymbolRole::acceleration,
                                  Dimension::acceleration(), false, b.position->at).sym;
          body.cm = {body.coord, 0, 0};
          body.has_cm = true;
          body.acceleration = {body.accel, 0, 0};
          accelerations.push_back(body.accel);
        }
      } else {
        // A coordinate: the center of mass is written in it, and the acceleration follows
        // (twice differentiated in time).
        if (b.position) {
          if (!b.center_of_mass)
            diags.error(b.position->at, "body '" + body.name + "' has a 'position' but no 'center_of_mass' (expected its center of mass written in " + b.position->text + ")");
          if (b.acceleration || b.accel_along)
            diags.error(b.position->at, "body '" + body.name + "' has both 'position' and 'acceleration' (its acceleration follows from its position; give one)");
          if (claim(*b.position, "coordinate")) {
            const std::string q = b.position->text;
            body.coord = table->add(q, std::nullopt, SymbolRole::coordinate, Dimension::length(), false, b.position->at).sym;
            body.rate = table->add("dot(" + q + ")", std::nullopt, SymbolRole::rate, Dimension::velocity(), false, b.position->at).sym;
            body.accel = table->add("ddot(" + q + ")", std::nullopt, SymbolRole::acceleration, Dimension::acceleration(), false, b.position->at).sym;
          }
        }
        if (b.center_of_mass) {
          if (auto cm = vector(*b.center_of_mass, *table, "'center_of_mass' of body '" + body.name + "'", Dimension::length())) {
            body.cm = *cm;
            body.has_cm = true;
          }
        }
        if (!body.coord.is_zero() && body.has_cm) {
          bool depends = false;
          for (const auto& c : body.cm) depends = depends || c.has(body.coord);
          if (!depends) {
            diags.error(b.center_of_mass->at, "'center_of_mass' of body '" + body.name + "' does not depend on its coordinate '" +
                                                  b.position->text + "' (expected it written in " + b.position->text + ")");
          } else {
            // a = d2(cm)/dt2 = cm'' dot(q)^2 + cm' ddot(q) (no velocity term on a straight line).
            const symbol& q = ex_to<symbol>(body.coord);
            for (int i = 0; i < 3; ++i)
              body.acceleration[i] = (body.cm[i].diff(q) * body.accel + body.cm[i].diff(q, 2) * pow(body.rate, 2)).expand();
            accelerations.push_back(body.accel);
          }
        }
        // (a position with an acceleration too is reported above; the position wins)
        if (b.acceleration && !b.position) {
          if (auto a = vector(*b.acceleration, *table, "'acceleration' of body '" + body.name + "'", Dimension::acceleration()))
            body.acceleration = *a;
        } else if (b.accel_along && !b.position) {
          auto dir = vector(*b.accel_along, *table, "'along' of the acceleration of body '" + body.name + "'", std::nullopt);
          const Text name = b.accel_name ? *b.accel_name : Text{"a_" + body.name, b.accel_along->at};
          if (dir && is_zero_vec(*dir)) {
            diags.error(b.accel_along->at, "the direction of motion of body '" + body.name + "' is a zero vector");
          } else if (dir && claim(name, "acceleration")) {
            const SymbolInfo& a = table->add(name.text, std::nullopt, SymbolRole::unknown, Dimension::acceleration(), false, name.at);
            body.accel = a.sym;
            body.acceleration = a.sym * unit(*dir);
            accelerations.push_back(a.sym);
          }
        }
      }
      body_index[body.name] = static_cast<int>(m.bodies.size());
      point_index[body.name] = static_cast<int>(m.points.size());
      Point self;
      self.name = body.name;
      self.position = body.cm;
      self.body = static_cast<int>(m.bodies.size());
      self.at = body.at;
      m.points.push_back(self);
      m.bodies.push_back(body);
    }
    m.candidates.insert(m.candidates.begin(), accelerations.begin(), accelerations.end());
    // Masses after every coordinate exists (a mass may not depend on them, but the message
    // for a misused name is clearer this way).
    for (std::size_t i = 0; i < d.bodies.size(); ++i) {
      const auto& b = d.bodies[i];
      auto it = body_index.find(b.name.text);
      if (it == body_index.end() || !b.mass) continue;
      Body& body = m.bodies[it->second];
      if (auto mass = parse(*b.mass, *table, "mass of body '" + body.name + "'")) {
        body.mass = *mass;
        body.has_mass = true;
        if (!mass->is_zero()) check_dimension(*mass, Dimension::mass(), b.mass->at, "mass of body '" + body.name + "'");
        if (!one_d && !mass->is_zero() && !body.has_cm)
          diags.error(b.at, "body '" + body.name + "' has no 'center_of_mass' (needed for its weight and its angular momentum balance)");
      }
    }
  }

  void points() {
    for (const auto& p : d.points) {
      if (!claim_place(p.name, "point")) continue;
      Point pt;
      pt.name = p.name.text;
      pt.at = p.name.at;
      if (p.at) {
        if (auto pos = vector(*p.at, *table, "position of point '" + pt.name + "'", Dimension::length())) pt.position = *pos;
      } else if (p.on) {
        auto it = body_index.find(p.on->text);
        if (it == body_index.end()) {
          unknown_name(*p.on, "body", body_names());
          continue;
        }
        pt.body = it->second;
        pt.position = m.bodies[pt.body].cm;
        if (p.offset) {
          if (auto off = vector(*p.offset, *table, "offset of point '" + pt.name + "'", Dimension::length()))
            for (int i = 0; i < 3; ++i) pt.position[i] += (*off)[i];
        }
      }
      point_index[pt.name] = static_cast<int>(m.points.size());
      m.points.push_back(pt);
    }
  }

  std::vector<std::string> body_names() const {
    std::vector<std::string> n;
    for (const auto& b : m.bodies) n.push_back(b.name);
    return n;
  }
  std::vector<std::string> point_names() const {
    std::vector<std::string> n;
    for (const auto& p : m.points) n.push_back(p.name);
    return n;
  }

  void unknown_name(const Text& t, const std::string& kind, const std::vector<std::string>& known) {
    std::string msg = "unknown " + kind + " '" + t.text + "'";
    if (auto near = nearest(t.text, known); !near.empty())
      msg += " (did you mean '" + near + "'?)";
    else if (!known.empty())
      msg += " (known: " + join(known) + ")";
    diags.error(t.at, msg);
  }

  void read_layout() {
    layout = table->values();
    for (const auto& [name, value] : d.layout) {
      const SymbolInfo* s = table->find(name.text);
      if (!s || (s->role != SymbolRole::coordinate && s->role != SymbolRole::parameter)) {
        std::vector<std::string> known;
        for (const auto& sym : table->all())
          if (sym->role == SymbolRole::coordinate || sym->role == SymbolRole::parameter) known.push_back(sym->name);
        std::string msg = "'layout' names '" + name.text + "', which is not a coordinate or a parameter";
        if (auto near = nearest(name.text, known); !near.empty()) msg += " (did you mean '" + near + "'?)";
        diags.error(name.at, msg);
        continue;
      }
      auto v = parse(value, none, "layout value of '" + name.text + "'");
      if (v && is_a<numeric>(*v)) layout[s->sym] = *v;
    }
    // A coordinate given with a value is at that value in the layout, unless the layout says
    // otherwise (its problems are reported with the other given quantities).
    for (const auto& g : d.given) {
      const SymbolInfo* s = g.value ? table->find(g.name.text) : nullptr;
      if (!s || s->role != SymbolRole::coordinate || layout.count(s->sym)) continue;
      Diagnostics later;
      if (auto v = given_value(g, *s, later)) layout[s->sym] = *v;
    }
  }

  std::string substitute(std::string tmpl, const ConnectionDesc& c, bool& ok) {
    std::size_t pos;
    while ((pos = tmpl.find('{')) != std::string::npos) {
      const auto end = tmpl.find('}', pos);
      if (end == std::string::npos) break;
      const std::string key = tmpl.substr(pos + 1, end - pos - 1);
      std::string value;
      if (key == "name") {
        if (!c.name) {
          diags.error(c.at, "a '" + c.type.text + "' connection needs a 'name' (its unknowns are named after it)");
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

  // One connection being instantiated from its rule: its arguments resolved, its local
  // names bound, its label. The stages below fill the model from it.
  struct Instance {
    const ConnectionDesc& c;
    const Rule& rule;
    std::string what;   // "'string' connection 's'" for messages
    std::string label;  // "string s", "pulley at C", "force on A" for reports
    Scope scope;
    std::map<std::string, int> point_args;              // point / body arguments: the point
    std::map<std::string, int> body_args;               // body arguments: the body
    std::map<std::string, std::vector<int>> path_args;  // points arguments
    std::map<std::string, std::pair<ex, Location>> expr_args;
    std::map<std::string, std::optional<Path>> paths;  // points arguments as paths, made once
  };

  // The symbol for the length of a strand that turns (one per pair of points, whichever way
  // round): l_CP, or l_C_P1 when a name is longer than one letter, with l^2 = `squared`.
  std::map<std::pair<std::string, std::string>, ex> turning_lengths;
  std::map<int, std::string> turning_at;  // a point at an end of a turning strand: the strand
  ex turning_length(const Point& a, const Point& b, const ex& squared) {
    const auto key = std::minmax(a.name, b.name);
    if (auto it = turning_lengths.find(key); it != turning_lengths.end()) return it->second;
    const bool short_names = a.name.size() == 1 && b.name.size() == 1;
    const std::string base = "l_" + a.name + (short_names ? "" : "_") + b.name;
    std::string name = base;
    for (int k = 2; table->find(name); ++k) name = base + "_" + std::to_string(k);
    const std::string tex = "\\ell" + default_tex(name).substr(1);
    const SymbolInfo& s = table->add(name, tex, SymbolRole::parameter, Dimension::length(), true, Location{});
    table->set_definition(name, sqrt(squared), true);
    table->set_unit(name, "m", 1);
    m.lengths.push_back({s.sym, squared});
    turning_lengths.emplace(key, s.sym);
    for (const Point* p : {&a, &b}) turning_at.emplace(point_index.at(p->name), a.name + "-" + b.name);
    return s.sym;
  }

  // The path of a points argument, made on first use; nothing when it cannot be made (its
  // problems are reported then).
  const Path* path_of(Instance& in, const std::string& key) {
    auto it = in.path_args.find(key);
    if (it == in.path_args.end()) return nullptr;
    // A body whose coordinate could not be made has been reported already.
    for (int p : it->second)
      if (m.dims() == 1 && m.points[p].body >= 0 && m.bodies[m.points[p].body].coord.is_zero()) return nullptr;
    auto [cached, fresh] = in.paths.try_emplace(key);
    if (fresh) {
      cached->second = make_path(it->second, m.points, m.dims(), layout, diags, in.c.at, in.label,
                                 [this](const Point& a, const Point& b, const ex& squared) { return turning_length(a, b, squared); });
      if (cached->second && cached->second->varying_length.is_zero()) {
        diags.error(in.c.at, "the path of a " + in.what +
                                 " never changes length (its ends are on one body, or fixed; expected a path between "
                                 "points that move apart)");
        cached->second.reset();
      }
    }
    return cached->second ? &*cached->second : nullptr;
  }

  void connection(const ConnectionDesc& c, std::set<std::string>& connection_names) {
    const Rule* found = rules.find(c.type.text);
    if (!found) {
      std::string msg = "unknown connection type '" + c.type.text + "'";
      if (auto near = nearest(c.type.text, rules.names()); !near.empty())
        msg += " (did you mean '" + near + "'?)";
      else
        msg += " (known: " + join(rules.names()) + ")";
      diags.error(c.type.at, msg);
      return;
    }
    Instance in{c, *found, "'" + found->type + "' connection" + (c.name ? " '" + c.name->text + "'" : ""), {}, Scope(*table),
                {}, {}, {}, {}, {}};
    if (c.name && !connection_names.insert(c.name->text).second)
      diags.error(c.name->at, "duplicate connection name '" + c.name->text + "'");
    if (!arguments_fit(in) || !bind_arguments(in)) return;
    in.label = label_of(in);
    if (!make_unknowns(in)) return;
    add_loads(in);
    add_constraints(in);
    add_conditions(in);
  }

  // The connection gives what its rule needs, and the rule is for this many axes.
  bool arguments_fit(const Instance& in) {
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
        if (auto near = nearest(a.key.text, arg_keys); !near.empty()) msg += " (did you mean '" + near + "'?)";
        else msg += " (expected one of: " + join(arg_keys) + ")";
        diags.error(a.key.at, msg);
        ok = false;
      }
    }
    for (const auto& spec : rule->args)
      if (spec.required && !c.arg(spec.key)) {
        diags.error(c.at, "a " + what + " needs '" + spec.key + "'");
        ok = false;
      }
    for (const auto& group : rule->one_of) {
      std::vector<std::string> present;
      for (const auto& k : group)
        if (c.arg(k)) present.push_back(k);
      if (present.size() != 1) {
        diags.error(c.at, "a " + what + (present.empty() ? " needs one of: " + join(group)
                                                          : " has " + join(present, " and ") + " (expected one of them)"));
        ok = false;
      }
    }
    if (!ok) return false;

    if (std::find(rule->dimensions.begin(), rule->dimensions.end(), m.dims()) == rule->dimensions.end()) {
      std::vector<std::string> dims;
      for (int n : rule->dimensions) dims.push_back(std::to_string(n) + "-D");
      diags.error(c.type.at, "a " + what + " is for " + join(dims, " and ") + " problems (this one has " +
                                 std::to_string(m.dims()) + (m.dims() == 1 ? " axis)" : " axes)"));
      return false;
    }
    return true;
  }

  // Resolves every argument: bodies and points by name (bound as position vectors in the
  // rule's scope), paths, expressions, vectors and moments.
  bool bind_arguments(Instance& in) {
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
        diags.error(a->key.at, "'" + spec.key + "' of a " + what + (list ? " is a single name (expected a list of points)"
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
          auto it = body_index.find(a->items[0].text);
          if (it == body_index.end()) {
            unknown_name(a->items[0], "body", body_names());
            ok = false;
          } else {
            point_args[spec.key] = point_index.at(a->items[0].text);
            body_args[spec.key] = it->second;
            const Vec& cm = m.bodies[it->second].cm;
            scope.bind(spec.key, make_vector(cm[0], cm[1], cm[2]));
          }
          break;
        }
        case ArgKind::point: {
          auto it = point_index.find(a->items[0].text);
          if (it == point_index.end()) {
            unknown_name(a->items[0], "point", point_names());
            ok = false;
          } else {
            point_args[spec.key] = it->second;
            const Vec& p = m.points[it->second].position;
            scope.bind(spec.key, make_vector(p[0], p[1], p[2]));
          }
          break;
        }
        case ArgKind::points: {
          std::vector<int> path;
          for (const auto& item : a->items) {
            auto it = point_index.find(item.text);
            if (it == point_index.end()) { unknown_name(item, "point", point_names()); ok = false; }
            else path.push_back(it->second);
          }
          if (a->items.size() < 2) {
            diags.error(a->key.at, "'" + spec.key + "' of a " + what + " has " + std::to_string(a->items.size()) +
                                       " point (expected at least two)");
            ok = false;
          }
          path_args[spec.key] = path;
          break;
        }
        case ArgKind::expr: {
          if (auto e = parse(a->items[0], *table, "'" + spec.key + "' of a " + what)) {
            if (spec.dimension && !e->is_zero())
              check_dimension(*e, *spec.dimension, a->items[0].at, "'" + spec.key + "' of a " + what);
            scope.bind(spec.key, *e);
            expr_args[spec.key] = {*e, a->items[0].at};
          } else {
            ok = false;
          }
          break;
        }
        case ArgKind::vector: {
          const VectorDesc vd{a->items, a->items.empty() ? a->key.at : a->items[0].at};
          if (auto v = vector(vd, *table, "'" + spec.key + "' of a " + what, spec.dimension))
            scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
          else
            ok = false;
          break;
        }
        case ArgKind::moment: {
          // 2-D: one number, about z; 3-D: a vector.
          const Location at = a->items.empty() ? a->key.at : a->items[0].at;
          if (m.dims() == 2) {
            if (a->items.size() != 1) {
              diags.error(at, "'" + spec.key + "' of a " + what + " has " + std::to_string(a->items.size()) +
                                  " entries (expected one number, the moment about z)");
              ok = false;
            } else if (auto e = parse(a->items[0], *table, "'" + spec.key + "' of a " + what)) {
              if (spec.dimension && !is_a<numeric>(*e)) check_dimension(*e, *spec.dimension, at, "'" + spec.key + "' of a " + what);
              scope.bind(spec.key, make_vector(0, 0, *e));
            } else {
              ok = false;
            }
          } else if (auto v = vector(VectorDesc{a->items, at}, *table, "'" + spec.key + "' of a " + what, spec.dimension)) {
            scope.bind(spec.key, make_vector((*v)[0], (*v)[1], (*v)[2]));
          } else {
            ok = false;
          }
          break;
        }
        case ArgKind::name:
          if (!is_identifier(a->items[0].text)) {
            diags.error(a->items[0].at, "'" + a->items[0].text + "' is not a valid name");
            ok = false;
          }
          break;
      }
    }

    for (const auto& [key, path] : path_args)
      for (std::size_t i = 1; i + 1 < path.size(); ++i) interior_points.insert(path[i]);
    return ok;
  }

  static std::string label_of(const Instance& in) {
    const ConnectionDesc& c = in.c;
    const Rule* rule = &in.rule;
    // "string s", or after the first point argument ("pulley at C", "rod from H"), else the
    // first body argument ("force on A").
    std::string label = rule->type;
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

  bool make_unknowns(Instance& in) {
    const ConnectionDesc& c = in.c;
    for (const auto& u : in.rule.unknowns) {
      std::string name;
      Location at = c.at;
      if (u.rename_arg && c.arg(*u.rename_arg)) {
        name = c.arg(*u.rename_arg)->items[0].text;
        at = c.arg(*u.rename_arg)->items[0].at;
      } else {
        bool named = true;
        name = substitute(u.name_template, c, named);
        if (!named) return false;
      }
      if (!claim(Text{name, at}, "unknown")) return false;
      const SymbolInfo& s = table->add(name, std::nullopt, SymbolRole::unknown, u.dimension, false, at);
      in.scope.bind(u.local, s.sym);
      m.candidates.push_back(s.sym);
    }
    return true;
  }

  // A rule expression in the instance's scope; problems are the rule's.
  std::optional<ex> rule_expr(Instance& in, const std::string& text, const Location& at) {
    auto r = parse_expression(text, in.scope);
    for (const auto& p : r.problems) diags.error(at, "rule '" + in.rule.type + "': in '" + text + "': " + p.message);
    return r.value;
  }

  // A rule expression as a vector: a number is along the axis in 1-D (a force) or about z
  // in 2-D (a couple).
  std::optional<Vec> as_vec(const Instance& in, const ex& e, bool couple, const Location& at) {
    if (is_vector(e)) return Vec{e.op(0), e.op(1), e.op(2)};
    if (!couple && m.dims() == 1) return Vec{e, 0, 0};
    if (couple && m.dims() == 2) return Vec{0, 0, e};
    diags.error(at, "rule '" + in.rule.type + "': a " + std::string(couple ? "couple" : "force") + " in a " +
                        std::to_string(m.dims()) + "-D problem must be a vector");
    return std::nullopt;
  }

  void add_loads(Instance& in) {
    const ConnectionDesc& c = in.c;
    const Rule* rule = &in.rule;
    const std::string& what = in.what;
    const std::string& label = in.label;
    auto& point_args = in.point_args;
    auto& body_args = in.body_args;
    auto& expr_args = in.expr_args;
    for (const auto& l : rule->loads) {
      if (l.kind == LoadSpec::Kind::on) {
        auto it = point_args.find(l.arg);
        if (it == point_args.end()) continue;  // optional argument not given
        int body = -1;
        if (auto bt = body_args.find(l.arg); bt != body_args.end()) body = bt->second;
        else body = m.points[it->second].body;
        if (body < 0) {
          diags.error(c.at, "a " + what + " acts on fixed point '" + m.points[it->second].name +
                                "' (expected a body or a point on one)");
          continue;
        }
        Load load;
        load.body = body;
        load.source = label;
        if (!l.at_arg.empty()) {
          if (auto at = point_args.find(l.at_arg); at != point_args.end()) {
            load.at = m.points[at->second].position;
            load.at_name = m.points[at->second].name;
          }
        } else if (!body_args.count(l.arg)) {
          load.at = m.points[it->second].position;
          load.at_name = m.points[it->second].name;
        }
        bool good = true;
        if (!l.expr.empty()) {
          auto f = rule_expr(in, l.expr, l.at);
          auto v = f ? as_vec(in, *f, false, l.at) : std::nullopt;
          if (v) load.force = *v;
          else good = false;
        }
        if (!l.couple.empty()) {
          auto f = rule_expr(in, l.couple, l.at);
          auto v = f ? as_vec(in, *f, true, l.at) : std::nullopt;
          if (v) load.couple = *v;
          else good = false;
        }
        if (!good) continue;
        if (m.dims() > 1 && !load.at && !is_zero_vec(load.force)) {
          diags.error(c.at, "a " + what + " needs a point of application in a " + std::to_string(m.dims()) +
                                "-D problem (give '" + (l.at_arg.empty() ? std::string("at") : l.at_arg) + "')");
          continue;
        }
        m.loads.push_back(load);
      } else if (l.kind == LoadSpec::Kind::along) {
        const Path* path = path_of(in, l.arg);
        if (!path) continue;
        // A force element's tension may use its path's length and lengthening rate.
        in.scope.bind("length", path->length);
        in.scope.bind("lengthening", time_derivative(path->length, m.bodies, m.lengths));
        auto tension = rule_expr(in, l.expr, l.at);
        if (!tension) continue;
        for (auto& load : tension_loads(*path, m.points, *tension, label)) m.loads.push_back(std::move(load));
      } else {
        auto it = expr_args.find(l.arg);
        if (it == expr_args.end()) continue;
        auto tension = rule_expr(in, l.expr, l.at);
        if (!tension) continue;
        // Generalized force of a length sum L on coordinate q: -T dL/dq (virtual work).
        for (std::size_t bi = 0; bi < m.bodies.size(); ++bi) {
          const Body& b = m.bodies[bi];
          if (b.coord.is_zero()) continue;
          const ex dl = it->second.first.diff(ex_to<symbol>(b.coord));
          if (dl.is_zero()) continue;
          Load load;
          load.body = static_cast<int>(bi);
          load.force = {-*tension * dl, 0, 0};
          load.source = label + " (from its length sum) on " + b.name;
          m.loads.push_back(load);
        }
      }
    }
  }

  void add_constraints(Instance& in) {
    const ConnectionDesc& c = in.c;
    const Rule* rule = &in.rule;
    const std::string& label = in.label;
    const std::string cname = c.name ? c.name->text : "";
    for (const auto& k : rule->constraints) {
      if (k.kind == ConstraintSpec::Kind::length) {
        if (const Path* path = path_of(in, k.arg)) m.constraints.push_back({label, cname, path->varying_length, "length of " + label});
      } else if (k.kind == ConstraintSpec::Kind::together) {
        // One body's position relative to the other, along each axis, is constant.
        auto a = in.body_args.find(k.arg), b = in.body_args.find(k.with);
        if (a == in.body_args.end() || b == in.body_args.end()) continue;
        const Body& first = m.bodies[a->second];
        const Body& second = m.bodies[b->second];
        if (a->second == b->second) {
          diags.error(c.at, "a " + in.what + " joins body '" + first.name + "' to itself (expected two different bodies)");
          continue;
        }
        for (int i = 0; i < m.dims(); ++i) {
          const ex q = (second.cm[i] - first.cm[i]).expand();
          bool moves = false;
          for (const auto& body : m.bodies) moves = moves || (!body.coord.is_zero() && q.has(body.coord));
          if (!moves) continue;
          m.constraints.push_back({label + (m.dims() > 1 ? " (" + m.axes[i] + ")" : ""), cname, q,
                                   "position of " + second.name + " relative to " + first.name +
                                       (m.dims() > 1 ? " along " + m.axes[i] : "")});
        }
      } else if (k.kind == ConstraintSpec::Kind::length_sum) {
        auto it = in.expr_args.find(k.arg);
        if (it == in.expr_args.end()) continue;
        m.constraints.push_back({label, cname, it->second.first, "length of " + label});
      } else {
        auto it = in.point_args.find(k.arg);
        if (it == in.point_args.end()) continue;
        const Point& p = m.points[it->second];
        m.constraints.push_back({label, cname, p.position[0], "position of " + p.name});
      }
    }
  }

  // Validity conditions, assumptions, the model's list of connections, and checks that need
  // every connection (run after all of them).
  void add_conditions(Instance& in) {
    const ConnectionDesc& c = in.c;
    const Rule* rule = &in.rule;
    const std::string& label = in.label;
    for (const auto& v : rule->validity) {
      if (!v.when.empty() && !c.arg(v.when)) continue;
      auto r = parse_relation(v.holds, in.scope);
      for (const auto& p : r.problems) diags.error(v.at, "rule '" + rule->type + "': " + p.message);
      if (r.value) m.conditions.push_back({r.value->lhs, r.value->rhs, r.value->op, v.meaning, v.otherwise, label});
    }
    for (const auto& a : rule->assumptions) {
      if (!a.when.empty() && !c.arg(a.when)) continue;
      if (std::find(m.assumptions.begin(), m.assumptions.end(), a.text) == m.assumptions.end()) m.assumptions.push_back(a.text);
    }
    m.connections.push_back(label + ": " + rule->summary);
    for (const auto& chk : rule->checks) {
      if (!chk.when.empty() && !c.arg(chk.when)) continue;
      if (chk.kind == CheckSpec::Kind::positive) {
        // A stiffness or damping coefficient: positive where its value is known.
        auto it = in.expr_args.find(chk.arg);
        if (it == in.expr_args.end()) continue;
        const ex v = evalf(it->second.first.subs(table->values()));
        if (is_a<numeric>(v) && ex_to<numeric>(v).is_real() && !ex_to<numeric>(v).is_positive())
        {
          const ArgSpec* spec = in.rule.arg(chk.arg);
          const std::string unit = spec && spec->dimension ? si_unit_name(*spec->dimension) : "";
          diags.error(it->second.second, "'" + chk.arg + "' of a " + in.what + " is " +
                                             (is_a<numeric>(it->second.first) ? "" : to_text(it->second.first) + " = ") +
                                             fmt::format("{:g}", ex_to<numeric>(v).to_double()) + (unit.empty() ? "" : " " + unit) +
                                             " (expected a positive value)");
        }
        continue;
      }
      pending_checks.push_back({&chk, in.point_args.count(chk.arg) ? in.point_args[chk.arg] : -1, c.at, in.what});
    }
  }

  struct PendingCheck {
    const CheckSpec* check;
    int point;
    Location at;
    std::string what;
  };
  std::vector<PendingCheck> pending_checks;
  std::set<int> interior_points;  // points some string runs over

  void connections() {
    std::set<std::string> names;
    for (const auto& c : d.connections) connection(c, names);
    for (const auto& pc : pending_checks) {
      if (pc.check->kind == CheckSpec::Kind::passes_over && pc.point >= 0 && !interior_points.count(pc.point))
        diags.error(pc.at, "no string runs over point '" + m.points[pc.point].name + "' of a " + pc.what +
                               " (expected it inside some string's path)");
      if (pc.check->kind == CheckSpec::Kind::steady_at && pc.point >= 0) {
        if (auto it = turning_at.find(pc.point); it != turning_at.end())
          diags.error(pc.at, "strand " + it->second + " at point '" + m.points[pc.point].name + "' of a " + pc.what +
                                 " turns as the bodies move, so the length wrapped on it would change (expected strands "
                                 "that keep their directions there, or the pulley as a point: no '" + pc.check->when + "')");
      }
    }
  }

  void gravity() {
    std::optional<Vec> g;
    if (d.gravity) {
      g = vector(*d.gravity, *table, "'gravity'", Dimension::acceleration());
    } else if (d.gravity_magnitude && d.gravity_tilt) {
      // Axes tilted by `tilt`: gravity is -g sin(tilt) along the first axis (up the slope) and
      // -g cos(tilt) along the second (across it, upwards).
      auto magnitude = parse(*d.gravity_magnitude, *table, "'magnitude' of 'gravity'");
      auto tilt = parse(*d.gravity_tilt, *table, "'tilt' of 'gravity'");
      if (magnitude && !is_a<numeric>(*magnitude))
        check_dimension(*magnitude, Dimension::acceleration(), d.gravity_magnitude->at, "'magnitude' of 'gravity'");
      if (tilt && !is_a<numeric>(*tilt)) check_dimension(*tilt, Dimension::none(), d.gravity_tilt->at, "'tilt' of 'gravity'");
      if (magnitude && tilt) g = Vec{-*magnitude * sin(*tilt), m.dims() > 1 ? ex(-*magnitude * cos(*tilt)) : ex(0), 0};
    }
    if (!g) return;
    m.gravity = *g;
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const Body& b = m.bodies[i];
      if (!b.has_mass || b.mass.is_zero()) continue;
      Load weight;
      weight.body = static_cast<int>(i);
      weight.force = b.mass * *g;
      if (b.has_cm) {
        weight.at = b.cm;
        weight.at_name = "the center of mass of " + b.name;
      }
      weight.source = "gravity on " + b.name;
      m.loads.push_back(weight);
    }
  }

  // The unit a `find` entry asks for, checked against the quantity's dimension.
  std::optional<Unit> output_unit(const FindDesc& f, std::optional<Dimension> dim) {
    if (!f.unit) return std::nullopt;
    std::string err;
    int col = 0;
    auto unit = parse_unit(f.unit->text, err, col);
    if (!unit) {
      diags.error(f.unit->at.shifted(col), "unit of '" + f.name.text + "' in 'find': " + err);
      return std::nullopt;
    }
    if (dim && !(unit->dimension == *dim)) {
      diags.error(f.unit->at, "'" + f.name.text + "' is " + with_article(dim->describe()) + ", but " + f.unit->text +
                                  " is " + with_article(unit->dimension.describe()));
      return std::nullopt;
    }
    return unit;
  }

  // The value of a `given` entry in SI, checked against the quantity's dimension; nothing
  // (with the problem reported to `to`) when it is not a number in a fitting unit.
  std::optional<ex> given_value(const GivenDesc& g, const SymbolInfo& s, Diagnostics& to, std::string* unit_text = nullptr,
                                ex* to_si = nullptr) {
    const std::string what = "'given' value of '" + g.name.text + "'";
    std::optional<Unit> unit;
    if (g.unit) {
      std::string err;
      int col = 0;
      unit = parse_unit(g.unit->text, err, col);
      if (!unit) {
        to.error(g.unit->at.shifted(col), "unit of " + what + ": " + err);
        return std::nullopt;
      }
      if (s.dimension && !(unit->dimension == *s.dimension)) {
        to.error(g.unit->at, "'" + g.name.text + "' is " + with_article(s.dimension->describe()) + ", but " + g.unit->text +
                                 " is " + with_article(unit->dimension.describe()));
        return std::nullopt;
      }
    }
    auto r = parse_expression(g.value->text, none);
    if (!r.value) {
      for (const auto& p : r.problems) to.error(g.value->at.shifted(p.column), what + ": " + p.message);
      return std::nullopt;
    }
    const ex approx = evalf(*r.value);
    if (!is_a<numeric>(approx) || !ex_to<numeric>(approx).is_real()) {
      to.error(g.value->at, what + " is not a number");
      return std::nullopt;
    }
    if (unit_text) *unit_text = unit ? g.unit->text : si_unit_name(s.dimension.value_or(Dimension{}));
    if (to_si) *to_si = unit ? ex(unit->to_si) : ex(1);
    return unit ? *r.value * unit->to_si : *r.value;
  }

  void given_and_find() {
    for (const auto& gd : d.given) {
      const Text& g = gd.name;
      auto r = parse_expression(g.text, *table);
      if (!r.value) {
        for (const auto& p : r.problems) diags.error(g.at.shifted(p.column), "'given': " + p.message);
        continue;
      }
      const SymbolInfo* s = table->find(*r.value);
      if (!s || (s->role != SymbolRole::acceleration && s->role != SymbolRole::rate && s->role != SymbolRole::unknown &&
                 s->role != SymbolRole::coordinate)) {
        diags.error(g.at, "'" + g.text + "' cannot be given (expected a coordinate, a velocity or an acceleration such as ddot(x_B), or an unknown)");
        continue;
      }
      if (gd.value) {
        std::string unit_text;
        ex to_si = 1;
        if (auto v = given_value(gd, *s, diags, &unit_text, &to_si)) {
          table->set_value(s->name, *v);
          table->set_unit(s->name, unit_text, to_si);
        }
      }
      m.given.push_back(s->sym);
      m.candidates.erase(std::remove(m.candidates.begin(), m.candidates.end(), s->sym), m.candidates.end());
    }
    for (const auto& f : d.find) {
      if (f.expr) {
        if (!claim(f.name, "quantity")) continue;
        auto e = parse(*f.expr, *table, "'" + f.name.text + "' in 'find'");
        if (!e) continue;
        std::string problem;
        auto dim = dimension_of(*e, *table, problem);
        if (!dim && !problem.empty()) diags.error(f.expr->at, "'" + f.name.text + "' in 'find' " + problem);
        const SymbolInfo& s = table->add(f.name.text, f.tex ? std::optional<std::string>(f.tex->text) : std::nullopt,
                                         SymbolRole::defined, dim, false, f.name.at);
        m.wanted.push_back({s.name, s.tex, *e, true, dim, output_unit(f, dim)});
      } else {
        auto r = parse_expression(f.name.text, *table);
        if (!r.value) {
          for (const auto& p : r.problems) diags.error(f.name.at.shifted(p.column), "'find': " + p.message);
          continue;
        }
        const SymbolInfo* s = table->find(*r.value);
        if (!s) {
          diags.error(f.name.at, "'find' lists '" + f.name.text + "', which is not a single name (use {name: ..., expr: ...})");
          continue;
        }
        m.wanted.push_back({s->name, s->tex, s->sym, false, s->dimension, output_unit(f, s->dimension)});
      }
    }
  }

  // Position questions: each constraint's constant (the varying part of its quantity keeps
  // the value it has; the layout only tells directions, so the constant is a symbol,
  // `C_s` for string s, as a person writes "x_S = 2 x + const").
  void constraint_constants() {
    bool asked = false;
    for (const auto& w : m.wanted)
      for (const auto& b : m.bodies)
        if (!b.coord.is_zero() && w.expr.has(b.coord)) asked = true;
    if (!asked) return;
    for (auto& c : m.constraints) {
      const std::string base = c.connection.empty() ? c.label : c.connection;
      std::string name = "C_" + base;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') ch = '_';
      if (table->find(name)) continue;  // a parameter of that name: no constant for this one
      std::string problem;
      const auto dim = dimension_of(c.quantity, *table, problem);
      c.constant = table->add(name, std::nullopt, SymbolRole::parameter, dim, false, Location{}).sym;
    }
  }

  // Bodies named by an lmb or amb entry; all need a mass.
  std::optional<std::vector<int>> selected_bodies(const DeriveDesc& dd) {
    std::vector<int> out;
    bool ok = true;
    for (const auto& item : dd.items) {
      auto it = body_index.find(item.text);
      if (it == body_index.end()) {
        unknown_name(item, "body", body_names());
        ok = false;
      } else if (!m.bodies[it->second].has_mass) {
        diags.error(item.at, "body '" + item.text + "' has no 'mass' (needed for its momentum balance; 0 for a pulley block)");
        ok = false;
      } else {
        out.push_back(it->second);
      }
    }
    if (!ok) return std::nullopt;
    return out;
  }

  void derive() {
    std::set<std::string> constraint_names;
    for (const auto& c : m.constraints) constraint_names.insert(c.connection);
    for (const auto& dd : d.derive) {
      if (dd.kind.text == "lmb") {
        Selection s{Selection::Kind::lmb, {}, dd.is_list, {}, {}, zero_vec(), std::nullopt, {}};
        if (auto bodies = selected_bodies(dd)) {
          s.bodies = *bodies;
          m.derive.push_back(s);
        }
      } else if (dd.kind.text == "amb") {
        if (m.dims() == 1) {
          diags.error(dd.kind.at, "angular momentum balance needs a 2-D or 3-D problem (this one has one axis)");
          continue;
        }
        Selection s{Selection::Kind::amb, {}, dd.is_list, {}, {}, zero_vec(), std::nullopt, {}};
        auto bodies = selected_bodies(dd);
        if (!bodies || !dd.about) continue;
        s.bodies = *bodies;
        auto p = point_index.find(dd.about->text);
        if (p == point_index.end()) {
          unknown_name(*dd.about, "point", point_names());
          continue;
        }
        s.about = dd.about->text;
        s.about_position = m.points[p->second].position;
        if (dd.axis) {
          // Two point names: the line through them; else a direction vector.
          const auto& items = dd.axis->items;
          if (items.size() == 2 && point_index.count(items[0].text) && point_index.count(items[1].text)) {
            const Vec from = m.points[point_index[items[0].text]].position;
            const Vec to = m.points[point_index[items[1].text]].position;
            if (is_zero_vec(to - from)) {
              diags.error(dd.axis->at, "the axis " + items[0].text + items[1].text + " has zero length (expected two different points)");
              continue;
            }
            s.axis = unit(to - from);
            s.axis_label = items[0].text + items[1].text;
          } else if (auto v = vector(*dd.axis, *table, "'axis' of an 'amb' entry", std::nullopt)) {
            if (is_zero_vec(*v)) {
              diags.error(dd.axis->at, "the axis of an 'amb' entry is a zero vector");
              continue;
            }
            s.axis = unit(*v);
            std::vector<std::string> parts;
            for (const auto& t : items) parts.push_back(t.text);
            s.axis_label = "[" + join(parts) + "]";
          } else {
            continue;
          }
        }
        m.derive.push_back(s);
      } else {
        for (const auto& item : dd.items) {
          if (!constraint_names.count(item.text)) {
            std::vector<std::string> known(constraint_names.begin(), constraint_names.end());
            known.erase(std::remove(known.begin(), known.end(), std::string{}), known.end());
            unknown_name(item, "constraint (a named connection with a constraint)", known);
            continue;
          }
          m.derive.push_back({Selection::Kind::constraint, {}, false, item.text, {}, zero_vec(), std::nullopt, {}});
        }
      }
    }
  }

  void axes() {
    if (d.axes.empty()) return;  // default: one axis named x
    if (d.axes.size() > 3) {
      diags.error(d.axes[3].at, "'axes' lists " + std::to_string(d.axes.size()) + " axes (expected one to three)");
      return;
    }
    std::set<std::string> seen;
    m.axes.clear();
    for (const auto& a : d.axes) {
      if (!is_identifier(a.text)) diags.error(a.at, "axis name '" + a.text + "' is not a valid name");
      if (!seen.insert(a.text).second) diags.error(a.at, "duplicate axis '" + a.text + "'");
      m.axes.push_back(a.text);
    }
    m.axis = m.axes[0];
  }

  Model build() {
    m.file = d.file;
    m.title = d.title.text;
    axes();
    parameters();
    bodies();
    points();
    read_layout();
    connections();
    gravity();
    given_and_find();
    constraint_constants();
    derive();
    m.sweep = d.sweep;
    diags.throw_if_any();
    m.symbols = table;
    return m;
  }
};

}  // namespace

ex time_derivative(const ex& e, const std::vector<Body>& bodies, const std::vector<TurningLength>& lengths) {
  ex d = 0;
  for (const auto& b : bodies) {
    if (b.coord.is_zero()) continue;
    d += e.diff(ex_to<symbol>(b.coord)) * b.rate + e.diff(ex_to<symbol>(b.rate)) * b.accel;
  }
  // d l/dt = d(l^2)/dt / (2 l), with l^2 a polynomial in the coordinates.
  for (const auto& l : lengths)
    if (e.has(l.symbol))
      d += e.diff(ex_to<symbol>(l.symbol)) * time_derivative(l.squared, bodies, {}) / (2 * l.symbol);
  return d.expand();
}

Model build_model(const Description& d, const RuleSet& rules) {
  Builder b(d, rules);
  return b.build();
}

}  // namespace tackle

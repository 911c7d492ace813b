#include "model/model.hpp"

#include <algorithm>
#include <map>
#include <set>

#include "expr/print.hpp"

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
struct NoNames : NameResolver {
  std::optional<ex> resolve(std::string_view) const override { return std::nullopt; }
  std::vector<std::string> known_names() const override { return {}; }
};
const NoNames none;

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
      diags.error(at, what + " is a " + dim->describe() + " (expected a " + expected.describe() + ")");
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
      if (p.dimension) {
        auto named = Dimension::from_name(p.dimension->text);
        if (!named)
          diags.error(p.dimension->at, "unknown dimension '" + p.dimension->text +
                                           "' (expected force, mass, length, time, velocity, acceleration, ...)");
        else if (dim && !(*dim == *named))
          diags.error(p.dimension->at, "parameter '" + p.name.text + "' has dimension " + named->describe() +
                                           " but its unit is a " + dim->describe());
        else
          dim = named;
      }
      const bool positive = p.positive.value_or(
          p.name.text == "g" || (dim && (*dim == Dimension::mass() || *dim == Dimension::length())));
      table->add(p.name.text, p.tex ? std::optional<std::string>(p.tex->text) : std::nullopt, SymbolRole::parameter,
                 dim, positive, p.name.at);
      if (p.value) {
        auto v = parse(*p.value, none, "value of parameter '" + p.name.text + "'");
        if (v && !is_a<numeric>(*v))
          diags.error(p.value->at, "value of parameter '" + p.name.text + "' is not a number");
        else if (v) {
          numeric value = ex_to<numeric>(*v);
          if (unit) value *= unit->to_si;
          if (positive && !value.is_positive())
            diags.error(p.value->at, "parameter '" + p.name.text + "' is assumed positive but its value is " +
                                         to_text(*v) + " (set 'positive: false' to allow it)");
          table->set_value(p.name.text, value, p.unit ? p.unit->text : si_unit_name(dim.value_or(Dimension{})));
        }
      }
    }
  }

  void bodies() {
    for (const auto& b : d.bodies) {
      if (!claim_place(b.name, "body")) continue;
      Body body;
      body.name = b.name.text;
      body.at = b.name.at;
      if (b.position && claim(*b.position, "coordinate")) {
        const std::string q = b.position->text;
        body.coord = table->add(q, std::nullopt, SymbolRole::coordinate, Dimension::length(), false, b.position->at).sym;
        body.rate = table->add("dot(" + q + ")", std::nullopt, SymbolRole::rate, Dimension::velocity(), false,
                               b.position->at).sym;
        body.accel = table->add("ddot(" + q + ")", std::nullopt, SymbolRole::acceleration,
                                Dimension::acceleration(), false, b.position->at).sym;
      }
      body_index[body.name] = static_cast<int>(m.bodies.size());
      point_index[body.name] = static_cast<int>(m.points.size());
      m.points.push_back({body.name, body.coord, static_cast<int>(m.bodies.size()), body.at});
      m.bodies.push_back(body);
    }
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
        if (auto pos = parse(*p.at, *table, "position of point '" + pt.name + "'")) {
          pt.position = *pos;
          // A plain number is a position in metres.
          if (!is_a<numeric>(*pos)) check_dimension(*pos, Dimension::length(), p.at->at, "position of point '" + pt.name + "'");
        }
      } else if (p.on) {
        auto it = body_index.find(p.on->text);
        if (it == body_index.end()) {
          unknown_name(*p.on, "body", body_names());
          continue;
        }
        pt.body = it->second;
        pt.position = m.bodies[pt.body].coord;
        if (p.offset) {
          if (auto off = parse(*p.offset, *table, "offset of point '" + pt.name + "'")) {
            pt.position += *off;
            if (!off->is_zero()) check_dimension(*off, Dimension::length(), p.offset->at, "offset of point '" + pt.name + "'");
          }
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
  }

  // Direction (+1 or -1) of the strand from point a to point b in the layout, or 0 when the
  // strand's length is constant (both ends on one body, or both fixed).
  std::optional<int> strand_sign(const Point& a, const Point& b, const Location& at, const std::string& label) {
    if (a.body == b.body) return 0;
    // A body whose coordinate could not be made has been reported already.
    for (const Point* p : {&a, &b})
      if (p->body >= 0 && m.bodies[p->body].coord.is_zero()) return std::nullopt;
    const ex diff = (b.position - a.position).subs(layout);
    if (!is_a<numeric>(diff)) {
      std::set<std::string> missing;
      for (const_preorder_iterator it = diff.preorder_begin(); it != diff.preorder_end(); ++it)
        if (is_a<symbol>(*it)) missing.insert(to_text(*it));
      diags.error(at, "cannot tell the direction of strand " + label + " (give 'layout' values for " +
                          join(std::vector<std::string>(missing.begin(), missing.end())) + ")");
      return std::nullopt;
    }
    const numeric n = ex_to<numeric>(diff);
    if (n.is_zero()) {
      diags.error(at, "strand " + label + " has zero length in the layout (expected its ends apart)");
      return std::nullopt;
    }
    return n.is_positive() ? 1 : -1;
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

  void connection(const ConnectionDesc& c, std::set<std::string>& connection_names) {
    const Rule* rule = rules.find(c.type.text);
    if (!rule) {
      std::string msg = "unknown connection type '" + c.type.text + "'";
      if (auto near = nearest(c.type.text, rules.names()); !near.empty()) msg += " (did you mean '" + near + "'?";
      else msg += " (";
      msg += (msg.back() == '(' ? "" : "; ") + std::string("known: ") + join(rules.names()) + ")";
      diags.error(c.type.at, msg);
      return;
    }
    const std::string what = "'" + rule->type + "' connection" + (c.name ? " '" + c.name->text + "'" : "");
    if (c.name) {
      if (!connection_names.insert(c.name->text).second)
        diags.error(c.name->at, "duplicate connection name '" + c.name->text + "'");
    }
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
    if (!ok) return;

    Scope scope(*table);
    std::map<std::string, int> point_args;                 // point / body arguments
    std::map<std::string, std::vector<int>> path_args;     // points arguments
    std::map<std::string, std::pair<ex, Location>> expr_args;
    for (const auto& spec : rule->args) {
      const ArgDesc* a = c.arg(spec.key);
      if (!a) continue;
      const bool list = spec.kind == ArgKind::points;
      if (list != a->is_list) {
        diags.error(a->key.at, "'" + spec.key + "' of a " + what + (list ? " is a single name (expected a list of points)"
                                                                         : " is a list (expected a single value)"));
        ok = false;
        continue;
      }
      switch (spec.kind) {
        case ArgKind::body: {
          auto it = body_index.find(a->items[0].text);
          if (it == body_index.end()) { unknown_name(a->items[0], "body", body_names()); ok = false; }
          else point_args[spec.key] = point_index.at(a->items[0].text);
          break;
        }
        case ArgKind::point: {
          auto it = point_index.find(a->items[0].text);
          if (it == point_index.end()) { unknown_name(a->items[0], "point", point_names()); ok = false; }
          else point_args[spec.key] = it->second;
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
        case ArgKind::name:
          if (!is_identifier(a->items[0].text)) {
            diags.error(a->items[0].at, "'" + a->items[0].text + "' is not a valid name");
            ok = false;
          }
          break;
      }
    }
    if (!ok) return;

    // "string s", or after the first body or point argument: "pulley at C", "force on A".
    std::string label = rule->type;
    if (c.name) {
      label += " " + c.name->text;
    } else {
      for (const auto& spec : rule->args)
        if ((spec.kind == ArgKind::body || spec.kind == ArgKind::point) && c.arg(spec.key)) {
          label += " " + spec.key + " " + c.arg(spec.key)->items[0].text;
          break;
        }
    }
    // Unknowns.
    for (const auto& u : rule->unknowns) {
      std::string name;
      Location at = c.at;
      if (u.rename_arg && c.arg(*u.rename_arg)) {
        name = c.arg(*u.rename_arg)->items[0].text;
        at = c.arg(*u.rename_arg)->items[0].at;
      } else {
        bool named = true;
        name = substitute(u.name_template, c, named);
        if (!named) return;
      }
      if (!claim(Text{name, at}, "unknown")) return;
      const SymbolInfo& s = table->add(name, std::nullopt, SymbolRole::unknown, u.dimension, false, at);
      scope.bind(u.local, s.sym);
      m.candidates.push_back(s.sym);
    }
    auto rule_expr = [&](const std::string& text, const Location& at) -> std::optional<ex> {
      auto r = parse_expression(text, scope);
      for (const auto& p : r.problems) diags.error(at, "rule '" + rule->type + "': in '" + text + "': " + p.message);
      return r.value;
    };
    // Loads.
    for (const auto& l : rule->loads) {
      if (l.kind == LoadSpec::Kind::on) {
        auto it = point_args.find(l.arg);
        if (it == point_args.end()) continue;  // optional argument not given
        const Point& p = m.points[it->second];
        auto f = rule_expr(l.expr, l.at);
        if (!f) continue;
        if (p.body < 0) {
          diags.error(c.at, "a " + what + " acts on fixed point '" + p.name + "' (expected a body or a point on one)");
          continue;
        }
        m.loads.push_back({p.body, *f, label});
      } else if (l.kind == LoadSpec::Kind::along) {
        auto it = path_args.find(l.arg);
        if (it == path_args.end()) continue;
        auto tension = rule_expr(l.expr, l.at);
        if (!tension) continue;
        const auto& path = it->second;
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
          const Point& a = m.points[path[i]];
          const Point& b = m.points[path[i + 1]];
          const std::string strand = a.name + "-" + b.name;
          auto sign = strand_sign(a, b, c.at, strand + " of " + label);
          if (!sign || *sign == 0) continue;
          // The strand pulls each end towards the other.
          if (a.body >= 0) m.loads.push_back({a.body, *sign * *tension, label + ": strand " + strand + " at " + a.name});
          if (b.body >= 0) m.loads.push_back({b.body, -*sign * *tension, label + ": strand " + strand + " at " + b.name});
        }
      } else {
        auto it = expr_args.find(l.arg);
        if (it == expr_args.end()) continue;
        auto tension = rule_expr(l.expr, l.at);
        if (!tension) continue;
        // Generalized force of a length sum L on coordinate q: -T dL/dq (virtual work).
        for (std::size_t bi = 0; bi < m.bodies.size(); ++bi) {
          const Body& b = m.bodies[bi];
          if (b.coord.is_zero()) continue;
          const ex dl = it->second.first.diff(ex_to<symbol>(b.coord));
          if (!dl.is_zero())
            m.loads.push_back({static_cast<int>(bi), -*tension * dl, label + " (from its length sum) on " + b.name});
        }
      }
    }
    // Constraints.
    const std::string cname = c.name ? c.name->text : "";
    for (const auto& k : rule->constraints) {
      if (k.kind == ConstraintSpec::Kind::length) {
        auto it = path_args.find(k.arg);
        if (it == path_args.end()) continue;
        ex length = 0;
        bool complete = true;
        const auto& path = it->second;
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
          const Point& a = m.points[path[i]];
          const Point& b = m.points[path[i + 1]];
          if (a.body == b.body) continue;  // constant length
          const ex diff = (b.position - a.position).subs(layout);
          if (!is_a<numeric>(diff) || ex_to<numeric>(diff).is_zero()) {
            complete = false;  // reported with the loads
            continue;
          }
          length += (ex_to<numeric>(diff).is_positive() ? 1 : -1) * (b.position - a.position);
        }
        if (complete) m.constraints.push_back({label, cname, length, "length of " + label});
      } else if (k.kind == ConstraintSpec::Kind::length_sum) {
        auto it = expr_args.find(k.arg);
        if (it == expr_args.end()) continue;
        m.constraints.push_back({label, cname, it->second.first, "length of " + label});
      } else {
        auto it = point_args.find(k.arg);
        if (it == point_args.end()) continue;
        const Point& p = m.points[it->second];
        m.constraints.push_back({label, cname, p.position, "position of " + p.name});
      }
    }
    for (const auto& v : rule->validity) {
      auto r = parse_relation(v.holds, scope);
      for (const auto& p : r.problems) diags.error(v.at, "rule '" + rule->type + "': " + p.message);
      if (r.value) m.conditions.push_back({r.value->lhs, r.value->rhs, r.value->op, v.meaning, v.otherwise, label});
    }
    for (const auto& a : rule->assumptions)
      if (std::find(m.assumptions.begin(), m.assumptions.end(), a) == m.assumptions.end()) m.assumptions.push_back(a);
    m.connections.push_back(label + ": " + rule->summary);
    for (const auto& chk : rule->checks) pending_checks.push_back({&chk, point_args.count(chk.arg) ? point_args[chk.arg] : -1, c.at, what});
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
    for (const auto& c : d.connections) {
      connection(c, names);
      if (const ArgDesc* p = c.arg("path"); p && p->items.size() > 2)
        for (std::size_t i = 1; i + 1 < p->items.size(); ++i)
          if (auto it = point_index.find(p->items[i].text); it != point_index.end()) interior_points.insert(it->second);
    }
    for (const auto& pc : pending_checks)
      if (pc.check->kind == CheckSpec::Kind::passes_over && pc.point >= 0 && !interior_points.count(pc.point))
        diags.error(pc.at, "no string runs over point '" + m.points[pc.point].name + "' of a " + pc.what +
                               " (expected it inside some string's path)");
  }

  void gravity() {
    if (!d.gravity) return;
    auto g = parse(*d.gravity, *table, "'gravity'");
    if (!g) return;
    check_dimension(*g, Dimension::acceleration(), d.gravity->at, "'gravity'");
    m.gravity = *g;
    for (std::size_t i = 0; i < m.bodies.size(); ++i)
      if (m.bodies[i].has_mass && !m.bodies[i].mass.is_zero())
        m.loads.push_back({static_cast<int>(i), m.bodies[i].mass * *g, "gravity on " + m.bodies[i].name});
  }

  void given_and_find() {
    std::vector<ex> accelerations;
    for (const auto& b : m.bodies)
      if (!b.accel.is_zero()) accelerations.push_back(b.accel);
    m.candidates.insert(m.candidates.begin(), accelerations.begin(), accelerations.end());
    for (const auto& g : d.given) {
      auto r = parse_expression(g.text, *table);
      if (!r.value) {
        for (const auto& p : r.problems) diags.error(g.at.shifted(p.column), "'given': " + p.message);
        continue;
      }
      const SymbolInfo* s = table->find(*r.value);
      if (!s || (s->role != SymbolRole::acceleration && s->role != SymbolRole::rate && s->role != SymbolRole::unknown)) {
        diags.error(g.at, "'" + g.text + "' cannot be given (expected an acceleration such as ddot(x_B) or an unknown)");
        continue;
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
        m.wanted.push_back({s.name, s.tex, *e, true, dim});
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
        m.wanted.push_back({s->name, s->tex, s->sym, false, s->dimension});
      }
    }
  }

  void derive() {
    std::set<std::string> constraint_names;
    for (const auto& c : m.constraints) constraint_names.insert(c.connection);
    for (const auto& dd : d.derive) {
      if (dd.kind.text == "lmb") {
        Selection s{Selection::Kind::lmb, {}, dd.is_list, {}};
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
            s.bodies.push_back(it->second);
          }
        }
        if (ok) m.derive.push_back(s);
      } else {
        for (const auto& item : dd.items) {
          if (!constraint_names.count(item.text)) {
            std::vector<std::string> known(constraint_names.begin(), constraint_names.end());
            known.erase(std::remove(known.begin(), known.end(), std::string{}), known.end());
            unknown_name(item, "constraint (a named connection with a constraint)", known);
            continue;
          }
          m.derive.push_back({Selection::Kind::constraint, {}, false, item.text});
        }
      }
    }
  }

  Model build() {
    m.file = d.file;
    m.title = d.title.text;
    if (d.axes.size() > 1)
      diags.error(d.axes[1].at, "this version of tackle handles one axis (2-D and 3-D balances are not available yet)");
    if (!d.axes.empty()) m.axis = d.axes[0].text;
    parameters();
    bodies();
    points();
    read_layout();
    connections();
    gravity();
    given_and_find();
    derive();
    diags.throw_if_any();
    m.symbols = table;
    return m;
  }
};

}  // namespace

Model build_model(const Description& d, const RuleSet& rules) {
  Builder b(d, rules);
  return b.build();
}

}  // namespace tackle

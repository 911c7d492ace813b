#include "ruleset/ruleset.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "description/yaml_reader.hpp"
#include "core/files.hpp"
#include "core/placeholders.hpp"
#include "expr/parse.hpp"

namespace tackle {

std::optional<int> when_axes(const std::string& when) {
  if (when == "1-D") return 1;
  if (when == "2-D") return 2;
  if (when == "3-D") return 3;
  return std::nullopt;
}

const ArgSpec* Rule::arg(const std::string& key) const {
  for (const auto& a : args)
    if (a.key == key) return &a;
  return nullptr;
}

RuleSet::RuleSet(const RuleSet& other) {
  const std::lock_guard<std::mutex> lock(other.mutex_);
  rules_ = other.rules_;
  pending_ = other.pending_;
}

RuleSet& RuleSet::operator=(const RuleSet& other) {
  if (this == &other) return *this;
  std::scoped_lock lock(mutex_, other.mutex_);
  rules_ = other.rules_;
  pending_ = other.pending_;
  return *this;
}

void RuleSet::add(Rule r) {
  const std::lock_guard<std::mutex> lock(mutex_);
  pending_.erase(r.type);
  rules_[r.type] = std::move(r);
}

void RuleSet::add_pending(const std::string& type, std::string text, std::string file, const BuiltinRule* builtin) {
  const std::lock_guard<std::mutex> lock(mutex_);
  rules_.erase(type);
  pending_[type] = {std::move(text), std::move(file), builtin};
}

Rule made_from(const BuiltinRule& builtin, const std::string& file) {
  Rule r = builtin.make();
  r.at.file = file;
  for (auto& l : r.loads) l.at.file = file;
  for (auto& c : r.constraints) c.at.file = file;
  for (auto& v : r.validity) v.at.file = file;
  for (auto& c : r.checks) c.at.file = file;
  for (auto& g : r.regimes) g.at.file = file;
  return r;
}

namespace {

// A pending rule, read (or made by its builtin); its type must be the one its `type:` line
// gave.
Rule read_pending(const std::string& type, const std::string& text, const std::string& file,
                  const BuiltinRule* builtin) {
  Rule r = builtin ? made_from(*builtin, file) : parse_rule(text, file);
  if (r.type != type)
    throw InputError(
        {{r.at, "rule type '" + r.type + "' differs from its 'type: " + type + "' line (expected one 'type' key)"}});
  return r;
}

}  // namespace

const Rule* RuleSet::find(const std::string& type) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (auto p = pending_.find(type); p != pending_.end()) {
    Rule r = read_pending(type, p->second.text, p->second.file, p->second.builtin);  // throws the file's problems
    pending_.erase(p);
    rules_[type] = std::move(r);
  }
  auto it = rules_.find(type);
  return it == rules_.end() ? nullptr : &it->second;
}

std::vector<std::string> RuleSet::names() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<std::string> n;
  for (const auto& [k, v] : rules_) n.push_back(k);
  for (const auto& [k, v] : pending_) n.push_back(k);
  std::sort(n.begin(), n.end());
  return n;
}

void RuleSet::read_all() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Diagnostic> all;
  for (auto p = pending_.begin(); p != pending_.end();) {
    try {
      rules_[p->first] = read_pending(p->first, p->second.text, p->second.file, p->second.builtin);
      p = pending_.erase(p);
    } catch (const InputError& e) {
      all.insert(all.end(), e.diagnostics().begin(), e.diagnostics().end());
      ++p;
    }
  }
  if (!all.empty()) throw InputError(all);
}

std::string default_rules_dir() {
  if (const char* env = std::getenv("TACKLE_RULES"); env && *env) return env;
  // An installed program: PREFIX/bin/tackle finds PREFIX/share/tackle/rules.
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const std::filesystem::path installed = exe.parent_path().parent_path() / TACKLE_INSTALLED_RULES;
    if (std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return TACKLE_RULES_DIR;
}

namespace {

using yaml::check_map;
using yaml::is_list;
using yaml::scalar;
using yaml::where;

// Resolves a rule's local names to placeholder symbols, to check its expressions at load.
class LocalNames : public NameResolver {
 public:
  // `vectors`: names that stand for vectors (points, vector arguments).
  LocalNames(std::vector<std::string> names, const std::set<std::string>& vectors) : names_(std::move(names)) {
    for (const auto& n : names_) {
      if (vectors.count(n))
        values_.emplace(n, make_vector(GiNaC::symbol(n + "_1"), GiNaC::symbol(n + "_2"), GiNaC::symbol(n + "_3")));
      else
        values_.emplace(n, GiNaC::symbol(n));
    }
  }
  std::optional<GiNaC::ex> resolve(std::string_view name) const override {
    auto it = values_.find(std::string(name));
    if (it == values_.end()) return std::nullopt;
    return it->second;
  }
  std::vector<std::string> known_names() const override { return names_; }

 private:
  std::vector<std::string> names_;
  std::map<std::string, GiNaC::ex> values_;
};

struct RuleReader {
  const std::string& file;
  Diagnostics& diags;

  std::optional<ArgKind> kind_of(const Text& t) {
    static const std::map<std::string, ArgKind> kinds = {
        {"body", ArgKind::body}, {"point", ArgKind::point},   {"points", ArgKind::points}, {"expr", ArgKind::expr},
        {"name", ArgKind::name}, {"vector", ArgKind::vector}, {"moment", ArgKind::moment}};
    if (auto it = kinds.find(t.text); it != kinds.end()) return it->second;
    diags.error(t.at, "unknown argument kind '" + t.text +
                          "' (expected one of: body, point, points, expr, name, vector, moment)");
    return std::nullopt;
  }

  void read_args(const yaml::Node& n, bool required, Rule& r) {
    if (!n.is_map()) {
      diags.error(where(n, file), "'" + std::string(required ? "needs" : "optional") + "' is " + yaml::kind_name(n) +
                                      " (expected a mapping of argument names to kinds)");
      return;
    }
    for (const auto& kv : n) {
      ArgSpec a;
      a.key = kv.first.text();
      a.required = required;
      if (kv.second.is_scalar()) {
        if (auto k = kind_of({kv.second.text(), where(kv.second, file)}))
          a.kind = *k;
        else
          a.kind_known = false;
      } else if (check_map(kv.second, {"kind", "dimension"}, "argument '" + a.key + "'", file, diags)) {
        if (auto k = kv.second["kind"]) {
          if (auto t = scalar(k, "'kind'", file, diags)) {
            if (auto kk = kind_of(*t))
              a.kind = *kk;
            else
              a.kind_known = false;
          }
        }
        if (auto d = kv.second["dimension"]) {
          if (auto t = scalar(d, "'dimension'", file, diags)) {
            a.dimension = Dimension::from_name(t->text);
            if (!a.dimension)
              diags.error(t->at, "unknown dimension '" + t->text + "' (expected force, mass, length, ...)");
          }
        }
      }
      r.args.push_back(std::move(a));
    }
  }

  std::string need_scalar(const yaml::Node& map, const char* key, const std::string& what) {
    const yaml::Node n = map[key];
    if (!n) {
      diags.error(where(map, file), what + " has no '" + key + "'");
      return {};
    }
    auto t = scalar(n, "'" + std::string(key) + "' of " + what, file, diags);
    return t ? t->text : std::string{};
  }

  // Which single key of `kinds` the map uses, e.g. `on` or `along` for a load.
  std::optional<std::string> which(const yaml::Node& item, const std::vector<std::string>& kinds,
                                   const std::string& what) {
    std::optional<std::string> found;
    for (const auto& k : kinds)
      if (item[k]) {
        if (found) {
          diags.error(where(item, file), what + " has both '" + *found + "' and '" + k + "' (expected one)");
          return std::nullopt;
        }
        found = k;
      }
    if (!found) diags.error(where(item, file), what + " has none of: " + join(kinds));
    return found;
  }

  // `when: ARG` names an argument of the rule; `when: 3-D` a number of axes the rule is for.
  void check_when(const Rule& r, const std::string& when, const Location& at) {
    if (const auto axes = when_axes(when)) {
      if (std::find(r.dimensions.begin(), r.dimensions.end(), *axes) == r.dimensions.end())
        diags.error(at,
                    "'when' is '" + when + "', but the rule is not for " + when + " problems (see its 'dimensions')");
      return;
    }
    if (!r.arg(when)) diags.error(at, "'when' names argument '" + when + "', which the rule does not declare");
  }

  void check_arg_ref(const Rule& r, const std::string& key, ArgKind expected, const Location& at,
                     const std::string& what) {
    const ArgSpec* a = r.arg(key);
    if (!a) {
      diags.error(at, what + " names argument '" + key + "', which the rule does not declare");
      return;
    }
    static const char* names[] = {"body", "point", "points", "expr", "name", "vector", "moment"};
    if (a->kind_known && a->kind != expected && !(expected == ArgKind::body && a->kind == ArgKind::point))
      diags.error(at, what + " uses argument '" + key + "' as " + names[static_cast<int>(expected)] +
                          " but the rule declares it as " + names[static_cast<int>(a->kind)]);
  }

  // A regime: {type: RULE, ARG: THIS_RULES_ARG, ..., ARG: {against: UNKNOWN, of: THIS_RULES_VECTOR}}.
  void read_regime(Rule& r, const yaml::Node& g) {
    RegimeSpec s;
    s.at = where(g, file);
    if (!g.is_map()) {
      diags.error(s.at, "a regime is not a map (expected {type: RULE, ...})");
      return;
    }
    for (const auto& kv : g) {
      const std::string key = kv.first.text();
      if (key == "type") {
        s.type = kv.second.text();
      } else if (kv.second.is_map()) {
        if (!check_map(kv.second, {"against", "of"}, "regime argument '" + key + "'", file, diags)) continue;
        s.turned = key;
        s.against = kv.second["against"] ? kv.second["against"].text() : "";
        s.of = kv.second["of"] ? kv.second["of"].text() : "";
        if (s.against.empty() || s.of.empty())
          diags.error(s.at, "regime argument '" + key +
                                "' needs 'against' (an unknown of the regime before) and 'of' (a vector argument)");
        else
          check_arg_ref(r, s.of, ArgKind::vector, s.at, "a regime");
      } else {
        s.args.emplace_back(key, kv.second.text());
        check_arg_ref(r, kv.second.text(), r.arg(kv.second.text()) ? r.arg(kv.second.text())->kind : ArgKind::expr,
                      s.at, "a regime");
      }
    }
    if (s.type.empty()) diags.error(s.at, "a regime needs 'type' (the rule the connection becomes)");
    r.regimes.push_back(std::move(s));
  }

  // `summary`: one text, or one per number of axes.
  void read_summary(const yaml::Node& root, Rule& r) {
    if (auto s = root["summary"]) {
      if (s.is_map()) {
        // One text per number of axes.
        if (check_map(s, {"1-D", "2-D", "3-D"}, "'summary'", file, diags))
          for (int k = 1; k <= 3; ++k)
            if (auto t = s[std::to_string(k) + "-D"])
              r.summary_in[k - 1] =
                  scalar(t, "'summary' for " + std::to_string(k) + "-D", file, diags).value_or(Text{}).text;
        for (const auto& t : r.summary_in)
          if (r.summary.empty() && !t.empty()) r.summary = t;
      } else {
        r.summary = scalar(s, "'summary'", file, diags).value_or(Text{}).text;
      }
    }
  }

  // `two_bodies` (the rule for two bodies, named when refusing a one-body contact) and
  // `assumes_direction` (true or false).
  void read_two_bodies_and_direction(const yaml::Node& root, Rule& r) {
    if (auto s = root["two_bodies"])
      if (const auto t = scalar(s, "'two_bodies'", file, diags)) r.two_bodies = t->text;
    if (auto s = root["assumes_direction"]) {
      const auto t = scalar(s, "'assumes_direction'", file, diags);
      if (t && (t->text == "true" || t->text == "false"))
        r.assumes_direction = t->text == "true";
      else if (t)
        diags.error(t->at, "'assumes_direction' is '" + t->text + "' (expected true or false)");
    }
  }

  // `sketch`: how the figure draws the connection, one of the known kinds.
  void read_sketch(const yaml::Node& root, Rule& r) {
    if (auto s = root["sketch"]) {
      const auto t = scalar(s, "'sketch'", file, diags);
      static const std::vector<std::string> kinds{"line",  "spring",  "damper",  "pulley", "support",
                                                  "arrow", "contact", "surface", "wheel",  "pin",
                                                  "joint", "rod",     "couple"};
      if (t && std::find(kinds.begin(), kinds.end(), t->text) != kinds.end())
        r.sketch = t->text;
      else if (t)
        diags.error(t->at, "'sketch' is '" + t->text +
                               "' (expected line, spring, damper, pulley, support, arrow, contact, surface, wheel, "
                               "pin, joint, rod or couple)");
    }
  }

  // `one_of`: groups of arguments, exactly one of each given; each a declared argument.
  void read_one_of(const yaml::Node& root, Rule& r) {
    if (auto n = root["one_of"]; n && is_list(n, "'one_of'", file, diags)) {
      for (const auto& group : n) {
        if (!is_list(group, "a group of 'one_of'", file, diags)) continue;
        std::vector<std::string> g;
        for (const auto& k : group) {
          g.push_back(k.text());
          if (!r.arg(g.back()))
            diags.error(where(k, file), "'one_of' names argument '" + g.back() + "', which the rule does not declare");
        }
        r.one_of.push_back(g);
      }
    }
  }

  // `dimensions`: the numbers of axes the rule is for (1, 2 or 3).
  void read_dimensions(const yaml::Node& root, Rule& r) {
    if (auto n = root["dimensions"]; n && is_list(n, "'dimensions'", file, diags)) {
      r.dimensions.clear();
      for (const auto& k : n) {
        const std::string v = k.text();
        if (v == "1" || v == "2" || v == "3")
          r.dimensions.push_back(std::stoi(v));
        else
          diags.error(where(k, file), "'dimensions' lists '" + v + "' (expected 1, 2 or 3)");
      }
    }
  }

  // One of `unknowns`: its local name (added to `locals`), the name template, the argument
  // that renames it, its dimension, its `when`.
  void read_unknown(const yaml::Node& u, Rule& r, std::vector<std::string>& locals) {
    if (!check_map(u, {"local", "name", "rename", "dimension", "when"}, "an unknown of the rule", file, diags)) return;
    UnknownSpec s;
    if (u["when"]) {
      s.when = u["when"].text();
      check_when(r, s.when, where(u, file));
    }
    s.local = need_scalar(u, "local", "an unknown");
    s.name_template = need_scalar(u, "name", "an unknown");
    if (auto rn = u["rename"]) {
      s.rename_arg = rn.text();
      if (!r.arg(*s.rename_arg))
        diags.error(where(rn, file),
                    "'rename' names argument '" + *s.rename_arg + "', which the rule does not declare");
    }
    const std::string dim = need_scalar(u, "dimension", "an unknown");
    if (auto d = Dimension::from_name(dim))
      s.dimension = *d;
    else if (!dim.empty())
      diags.error(where(u["dimension"], file), "unknown dimension '" + dim + "' (expected force, mass, length, ...)");
    locals.push_back(s.local);
    r.unknowns.push_back(std::move(s));
  }

  // Names a rule's expressions may use: its expression, vector and point arguments (points
  // as position vectors) and its unknowns (read here).
  std::vector<std::string> read_unknowns(const yaml::Node& root, Rule& r) {
    std::vector<std::string> locals;
    for (const auto& a : r.args)
      if (a.kind == ArgKind::expr || a.kind == ArgKind::vector || a.kind == ArgKind::moment || a.kind == ArgKind::point)
        locals.push_back(a.key);
    if (auto n = root["unknowns"]; n && is_list(n, "'unknowns'", file, diags))
      for (const auto& u : n) read_unknown(u, r, locals);
    return locals;
  }

  // The problems of an expression in `names`, reported at `at`.
  void check_expr(const LocalNames& names, const std::string& text, const Location& at) {
    auto res = parse_expression(text, names);
    for (const auto& p : res.problems) diags.error(at, "in '" + text + "': " + p.message);
  }

  // The summary's {N}, {mu*N}: expressions in the rule's local names, typeset in the
  // derivation with the connection's own symbols.
  void check_summary(const yaml::Node& root, const Rule& r, const LocalNames& names) {
    if (auto s = root["summary"]) {
      std::vector<const std::string*> texts{&r.summary};
      for (const auto& t : r.summary_in) texts.push_back(&t);
      for (const std::string* t : texts)
        for (const auto& ph : placeholders(*t)) check_expr(names, std::string(ph.name), where(s, file));
    }
  }

  // A load `on` a body or point: its force or couple, its point of application.
  void read_load_on(const yaml::Node& l, Rule& r, LoadSpec& s, const LocalNames& names) {
    s.kind = LoadSpec::Kind::on;
    if (l["force"]) s.expr = need_scalar(l, "force", "a load");
    if (l["couple"]) {
      s.couple = need_scalar(l, "couple", "a load");
      if (!s.couple.empty()) check_expr(names, s.couple, s.at);
    }
    if (!l["force"] && !l["couple"]) diags.error(s.at, "a load has neither 'force' nor 'couple'");
    if (l["at"]) {
      s.at_arg = l["at"].text();
      check_arg_ref(r, s.at_arg, ArgKind::point, s.at, "a load");
    }
    check_arg_ref(r, s.arg, ArgKind::body, s.at, "a load");
  }

  // One of `loads`: on a body or point, along a path, or from a length sum; its expression
  // checked (a tension along a path may use the path's length and rate of lengthening).
  void read_load(const yaml::Node& l, Rule& r, const LocalNames& names, const LocalNames& along_names) {
    if (!check_map(l, {"on", "along", "from_length", "force", "tension", "at", "couple", "when"}, "a load of the rule",
                   file, diags))
      return;
    auto kind = which(l, {"on", "along", "from_length"}, "a load");
    if (!kind) return;
    LoadSpec s;
    s.at = where(l, file);
    s.arg = l[*kind].text();
    if (l["when"]) {
      s.when = l["when"].text();
      check_when(r, s.when, s.at);
    }
    if (*kind == "on") {
      read_load_on(l, r, s, names);
    } else {
      s.kind = *kind == "along" ? LoadSpec::Kind::along : LoadSpec::Kind::from_length;
      s.expr = need_scalar(l, "tension", "a load");
      check_arg_ref(r, s.arg, *kind == "along" ? ArgKind::points : ArgKind::expr, s.at, "a load");
    }
    if (!s.expr.empty()) {
      if (s.kind == LoadSpec::Kind::along) {
        for (const auto& p : parse_expression(s.expr, along_names).problems)
          diags.error(s.at, "in '" + s.expr + "': " + p.message);
      } else {
        check_expr(names, s.expr, s.at);
      }
    }
    r.loads.push_back(std::move(s));
  }

  // A constraint's kind and the arguments it names: a path's length, a length sum, a point
  // held still, two bodies together or keeping along a direction, a body rolling.
  void constraint_kind(const yaml::Node& c, const std::string& kind, Rule& r, ConstraintSpec& s) {
    if (kind == "length") {
      s.kind = ConstraintSpec::Kind::length;
      check_arg_ref(r, s.arg, ArgKind::points, s.at, "a constraint");
    } else if (kind == "length_sum") {
      s.kind = ConstraintSpec::Kind::length_sum;
      check_arg_ref(r, s.arg, ArgKind::expr, s.at, "a constraint");
    } else if (kind == "together") {
      s.kind = ConstraintSpec::Kind::together;
      s.with = c["with"] ? c["with"].text() : "";
      if (s.with.empty()) diags.error(s.at, "a 'together' constraint needs 'with' (the second body)");
      check_arg_ref(r, s.arg, ArgKind::body, s.at, "a constraint");
      if (!s.with.empty()) check_arg_ref(r, s.with, ArgKind::body, s.at, "a constraint");
    } else if (kind == "keeps") {
      s.kind = ConstraintSpec::Kind::keeps;
      s.with = c["with"] ? c["with"].text() : "";
      s.along = c["along"] ? c["along"].text() : "";
      if (s.with.empty() || s.along.empty())
        diags.error(s.at, "a 'keeps' constraint needs 'with' (the second body) and 'along' (the direction)");
      check_arg_ref(r, s.arg, ArgKind::body, s.at, "a constraint");
      if (!s.with.empty()) check_arg_ref(r, s.with, ArgKind::body, s.at, "a constraint");
      if (!s.along.empty()) check_arg_ref(r, s.along, ArgKind::vector, s.at, "a constraint");
    } else if (kind == "rolls") {
      s.kind = ConstraintSpec::Kind::rolls;
      s.point = c["at"] ? c["at"].text() : "";
      s.with = c["along"] ? c["along"].text() : "";
      if (s.point.empty() || s.with.empty())
        diags.error(s.at, "a 'rolls' constraint needs 'at' (the contact point) and 'along' (the rolling direction)");
      check_arg_ref(r, s.arg, ArgKind::body, s.at, "a constraint");
      if (!s.point.empty()) check_arg_ref(r, s.point, ArgKind::point, s.at, "a constraint");
      if (!s.with.empty()) check_arg_ref(r, s.with, ArgKind::vector, s.at, "a constraint");
    } else {
      s.kind = ConstraintSpec::Kind::still;
      check_arg_ref(r, s.arg, ArgKind::body, s.at, "a constraint");
    }
  }

  // `constraints`: each of one kind, naming the rule's arguments.
  void read_constraints(const yaml::Node& root, Rule& r) {
    if (auto n = root["constraints"]; n && is_list(n, "'constraints'", file, diags)) {
      for (const auto& c : n) {
        if (!check_map(c, {"length", "length_sum", "still", "together", "with", "rolls", "at", "along", "keeps"},
                       "a constraint of the rule", file, diags))
          continue;
        auto kind = which(c, {"length", "length_sum", "still", "together", "rolls", "keeps"}, "a constraint");
        if (!kind) continue;
        ConstraintSpec s;
        s.at = where(c, file);
        s.arg = c[*kind].text();
        constraint_kind(c, *kind, r, s);
        r.constraints.push_back(std::move(s));
      }
    }
  }

  // `validity`: conditions in the rule's local names (and a path's length, for a rule with a
  // force along a path), their meaning and what holds otherwise.
  void read_validity(const yaml::Node& root, Rule& r, const LocalNames& names, const LocalNames& along_names) {
    if (auto n = root["validity"]; n && is_list(n, "'validity'", file, diags)) {
      for (const auto& v : n) {
        if (!check_map(v, {"holds", "meaning", "otherwise", "when"}, "a validity condition", file, diags)) continue;
        ValiditySpec s;
        s.at = where(v, file);
        if (v["when"]) {
          s.when = v["when"].text();
          check_when(r, s.when, s.at);
        }
        s.holds = need_scalar(v, "holds", "a validity condition");
        s.meaning = need_scalar(v, "meaning", "a validity condition");
        s.otherwise = need_scalar(v, "otherwise", "a validity condition");
        // A rule with a force along a path may state its validity in the path's length too
        // (an elastic cord is taut while its length exceeds its rest length).
        const bool along = std::any_of(r.loads.begin(), r.loads.end(),
                                       [](const LoadSpec& l) { return l.kind == LoadSpec::Kind::along; });
        auto res = parse_relation(s.holds, along ? along_names : names);
        for (const auto& p : res.problems) diags.error(s.at, "in '" + s.holds + "': " + p.message);
        r.validity.push_back(std::move(s));
      }
    }
  }

  // One of `checks`: a path passing over a point, a positive value, a pulley kept steady, a
  // vector across another.
  void read_check(const yaml::Node& c, Rule& r) {
    if (!check_map(c, {"passes_over", "positive", "steady_at", "across", "to", "when"}, "a check of the rule", file,
                   diags))
      return;
    auto kind = which(c, {"passes_over", "positive", "steady_at", "across"}, "a check");
    if (!kind) return;
    const CheckSpec::Kind k = *kind == "passes_over" ? CheckSpec::Kind::passes_over
                              : *kind == "positive"  ? CheckSpec::Kind::positive
                              : *kind == "across"    ? CheckSpec::Kind::across
                                                     : CheckSpec::Kind::steady_at;
    CheckSpec s{k, c[*kind].text(), where(c, file), {}, {}};
    if (k == CheckSpec::Kind::across) {
      s.to = c["to"] ? c["to"].text() : "";
      if (s.to.empty())
        diags.error(s.at, "an 'across' check needs 'to' (the vector it is at right angles to)");
      else
        check_arg_ref(r, s.to, ArgKind::vector, s.at, "a check");
    }
    check_arg_ref(r, s.arg,
                  k == CheckSpec::Kind::positive ? ArgKind::expr
                  : k == CheckSpec::Kind::across ? ArgKind::vector
                                                 : ArgKind::point,
                  s.at, "a check");
    if (c["when"]) {
      s.when = c["when"].text();
      check_when(r, s.when, s.at);
    }
    r.checks.push_back(std::move(s));
  }

  // `assumptions`: each a sentence, or {text, when: ARG} for one that holds only when ARG is given.
  void read_assumptions(const yaml::Node& root, Rule& r) {
    if (auto n = root["assumptions"]; n && is_list(n, "'assumptions'", file, diags)) {
      for (const auto& a : n) {
        // A sentence, or {text, when: ARG} for one that holds only when ARG is given.
        if (a.is_map()) {
          if (!check_map(a, {"text", "when"}, "an assumption", file, diags)) continue;
          Assumption as{need_scalar(a, "text", "an assumption"), ""};
          if (a["when"]) {
            as.when = a["when"].text();
            check_when(r, as.when, where(a, file));
          }
          r.assumptions.push_back(std::move(as));
        } else if (auto t = scalar(a, "an assumption", file, diags)) {
          r.assumptions.push_back({t->text, ""});
        }
      }
    }
  }

  // The rule's expressions checked in its local names: the summary's, the loads', the
  // validity conditions'; the loads, constraints, regimes and validity read on the way.
  void read_expressions(const yaml::Node& root, Rule& r, const std::vector<std::string>& locals) {
    std::set<std::string> vectors;
    for (const auto& a : r.args)
      if (a.kind == ArgKind::vector || a.kind == ArgKind::moment || a.kind == ArgKind::point) vectors.insert(a.key);
    LocalNames names(locals, vectors);
    // A tension along a path may also use the path's length and its rate of lengthening.
    std::vector<std::string> path_locals = locals;
    path_locals.insert(path_locals.end(), {"length", "lengthening", "origin_length"});
    LocalNames along_names(path_locals, vectors);
    check_summary(root, r, names);
    if (auto n = root["loads"]; n && is_list(n, "'loads'", file, diags))
      for (const auto& l : n) read_load(l, r, names, along_names);
    read_constraints(root, r);
    // (After the arguments: a regime names them.)
    if (auto n = root["regimes"]; n && is_list(n, "'regimes'", file, diags))
      for (const auto& g : n) read_regime(r, g);
    read_validity(root, r, names, along_names);
  }

  Rule read(const yaml::Node& root) {
    Rule r;
    r.at = where(root, file);
    if (!check_map(root,
                   {"type", "summary", "needs", "optional", "one_of", "unknowns", "loads", "constraints", "validity",
                    "checks", "assumptions", "dimensions", "assumes_direction", "sketch", "two_bodies", "regimes"},
                   "the rule", file, diags))
      return r;
    r.type = need_scalar(root, "type", "the rule");
    read_summary(root, r);
    read_two_bodies_and_direction(root, r);
    read_sketch(root, r);
    if (auto n = root["needs"]) read_args(n, true, r);
    if (auto n = root["optional"]) read_args(n, false, r);
    read_one_of(root, r);
    read_dimensions(root, r);
    const std::vector<std::string> locals = read_unknowns(root, r);
    read_expressions(root, r, locals);
    if (auto n = root["checks"]; n && is_list(n, "'checks'", file, diags))
      for (const auto& c : n) read_check(c, r);
    read_assumptions(root, r);
    return r;
  }
};

}  // namespace

Rule parse_rule(const std::string& text, const std::string& file) {
  Diagnostics diags;
  const yaml::Document doc = yaml::load(text, file, diags);
  const yaml::Node root = doc.root();
  Rule r;
  if (diags.empty()) r = RuleReader{file, diags}.read(root);
  diags.throw_if_any();
  return r;
}

namespace {

// The type a rule file states on a top-level line of its own (`type: spring`, maybe with a
// comment), or "" when it is not that plain (flow style, quotes, no such line): such a file
// is read at once.
std::string plain_type(const std::string& text) {
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + at, end - at);
    if (line.substr(0, 5) == "type:") {
      std::size_t i = 5;
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
      const std::size_t start = i;
      while (i < line.size() && (std::isalnum(static_cast<unsigned char>(line[i])) || line[i] == '_')) ++i;
      const std::string name(line.substr(start, i - start));
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      const bool rest_ok = i == line.size() || line[i] == '#';
      if (name.empty() || !rest_ok || std::isdigit(static_cast<unsigned char>(name[0]))) return "";
      return name;
    }
    at = end + 1;
  }
  return "";
}

}  // namespace

RuleSet load_rules(const std::string& dir, RuleLoading how, std::span<const BuiltinRule> builtins) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError({{{dir, 0, 0}, "the rules directory does not exist (expected rules/*.yaml)"}});
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  RuleSet set;
  std::vector<Diagnostic> all;
  std::map<std::string, std::string> defined_in;
  for (const auto& f : files) {
    try {
      std::string text = read_text_file(f.string());
      const std::string type = how == RuleLoading::when_used ? plain_type(text) : "";
      if (!type.empty()) {
        if (auto it = defined_in.find(type); it != defined_in.end()) {
          all.push_back({{f.string(), 1, 1}, "rule type '" + type + "' is defined twice (also in " + it->second + ")"});
          continue;
        }
        defined_in[type] = f.string();
        const std::string name = f.filename().string();
        const auto builtin = std::find_if(builtins.begin(), builtins.end(),
                                          [&](const BuiltinRule& b) { return b.name == name && b.text == text; });
        set.add_pending(type, std::move(text), f.string(), builtin == builtins.end() ? nullptr : &*builtin);
        continue;
      }
      Rule r = parse_rule(text, f.string());
      if (auto it = defined_in.find(r.type); it != defined_in.end()) {
        all.push_back({r.at, "rule type '" + r.type + "' is defined twice (also in " + it->second + ")"});
        continue;
      }
      defined_in[r.type] = f.string();
      set.add(std::move(r));
    } catch (const InputError& e) {
      all.insert(all.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
  }
  if (!all.empty()) throw InputError(all);
  return set;
}

}  // namespace tackle

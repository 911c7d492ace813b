#include "analysis/regimes.hpp"

#include <algorithm>

#include "expr/rational.hpp"
#include "numeric/evaluate.hpp"
#include "analysis/analysis.hpp"

namespace tackle {

using namespace GiNaC;

std::vector<std::size_t> decided_connections(const Description& d, const RuleSet& rules) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < d.connections.size(); ++i) {
    const Rule* r = nullptr;
    try {
      r = rules.find(d.connections[i].type.text);
    } catch (const InputError&) {
      continue;  // reported when the model is built
    }
    if (r && !r->regimes.empty()) out.push_back(i);
  }
  return out;
}

namespace {

// An argument's items turned: each component negated (a vector the other way).
ArgDesc turned(ArgDesc a) {
  for (auto& item : a.items) item.text = "-(" + item.text + ")";
  return a;
}

// The connection as its regime's rule: each of that rule's arguments from the one of the same
// name, or as the regime maps it, or the turned vector.
ConnectionDesc as_regime(const ConnectionDesc& c, const RegimeSpec& g, const Rule& target, bool turn) {
  ConnectionDesc out;
  out.type = {g.type, c.type.at};
  out.name = c.name;
  out.at = c.at;
  for (const auto& spec : target.args) {
    std::string from = spec.key;
    for (const auto& [to, source] : g.args)
      if (to == spec.key) from = source;
    if (spec.key == g.turned) from = g.of;
    const ArgDesc* a = c.arg(from);
    if (!a) continue;
    ArgDesc copy = spec.key == g.turned && turn ? turned(*a) : *a;
    copy.key.text = spec.key;
    out.args.push_back(std::move(copy));
  }
  return out;
}

// An unknown's name as the rule makes it for this connection (`F_{at}` -> F_A).
std::string unknown_name(const Rule& rule, const ConnectionDesc& c, const std::string& local) {
  for (const auto& u : rule.unknowns) {
    if (u.local != local) continue;
    if (u.rename_arg)
      if (const ArgDesc* a = c.arg(*u.rename_arg); a && a->items.size() == 1) return a->items[0].text;
    std::string name = u.name_template;
    for (std::size_t open = name.find('{'); open != std::string::npos; open = name.find('{')) {
      const std::size_t close = name.find('}', open);
      if (close == std::string::npos) break;
      const std::string key = name.substr(open + 1, close - open - 1);
      const ArgDesc* a = key == "name" ? nullptr : c.arg(key);
      name.replace(open, close - open + 1,
                   key == "name" && c.name  ? c.name->text
                   : a && !a->items.empty() ? a->items[0].text
                                            : key);
    }
    return name;
  }
  return {};
}

// A number at the given values (none when a symbol has none).
std::optional<numeric> at_values(const ex& e, const SymbolTable& table) {
  const ex v = evalf(substituted(substituted(e, table.definitions(true)), table.values()));
  if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nullopt;
  return ex_to<numeric>(v);
}

}  // namespace

Description with_regimes(const Description& d, const RuleSet& rules, const std::vector<std::size_t>& which,
                         const std::vector<std::size_t>& regime, const std::vector<bool>& turn) {
  Description out = d;
  for (std::size_t k = 0; k < which.size(); ++k) {
    const ConnectionDesc& c = d.connections[which[k]];
    const Rule* rule = rules.find(c.type.text);
    const RegimeSpec& g = rule->regimes.at(regime[k]);
    const Rule* target = rules.find(g.type);
    if (!target) throw InternalError("regime '" + g.type + "' of rule '" + rule->type + "' is no rule");
    out.connections[which[k]] = as_regime(c, g, *target, turn[k]);
  }
  return out;
}

RegimeChoice decide_regime(const Analysis& a, const Description& d, const RuleSet& rules, std::size_t i, bool& turn) {
  const ConnectionDesc& c = d.connections[i];
  const Rule* rule = rules.find(c.type.text);
  const RegimeSpec& first = rule->regimes.front();
  const Rule* first_rule = rules.find(first.type);
  RegimeChoice out;
  out.connection = a.model.connections.at(i).label;
  out.first = out.chosen = first.type;
  const SymbolTable& table = *a.model.symbols;
  // The number of an expression of the parameters, with its unit (of `like`'s dimension).
  auto number_of = [&](const ex& e, const ex& like) -> std::string {
    std::string problem;
    const auto n = evaluate(e, table, dimension_of(like, table, problem));
    return n ? n->decimal + (n->unit.empty() ? "" : " " + n->unit) : "";
  };
  for (const auto& cc : a.solution.conditions) {
    if (!cc.condition || cc.condition->source != out.connection) continue;
    const auto v = at_values(cc.expr, table);
    const bool fails = v && !relation_holds(*v, cc.condition->op);
    if (fails) out.failed.push_back(cc.condition->meaning);
    if (!v) out.undecided = true;
    for (const auto& s : cc.solved) {
      RegimeChoice::Bound b;
      b.meaning = cc.condition->meaning;
      b.parameter = s.parameter;
      b.bound = s.bound;
      b.op = s.op;
      b.value = number_of(s.bound, s.parameter);
      b.failed = fails;
      std::string problem;
      const auto dim = dimension_of(s.parameter, table, problem);
      b.coefficient = dim && *dim == Dimension{};
      if (const auto n = at_values(s.bound, table)) b.number = n->to_double();
      out.holds_while.push_back(std::move(b));
    }
  }
  // Of the bounds on one parameter the same way, the tightest at the given numbers.
  for (auto& b : out.holds_while) {
    if (!b.number) continue;
    const bool lower = b.op[0] == '>';
    for (const auto& o : out.holds_while)
      if (&o != &b && o.number && o.parameter.is_equal(b.parameter) && (o.op[0] == '>') == lower && o.op[0] != '=' &&
          (lower ? *o.number > *b.number : *o.number < *b.number))
        b.tightest = false;
  }
  // The friction the first regime needs, on the first body, and the most it can be.
  const std::string friction = rule->regimes.size() > 1 ? rule->regimes[1].against : "";
  const SymbolInfo* f = friction.empty()
                            ? nullptr
                            : table.find(unknown_name(*first_rule, as_regime(c, first, *first_rule, false), friction));
  if (f) {
    exmap solved;
    for (const auto& v : a.solution.values) solved[v.unknown] = v.value;
    if (const auto value = a.solution.value_of(f->sym)) {
      RegimeChoice::Friction fr;
      const ArgDesc* body = c.arg("body");
      fr.body = body && !body->items.empty() ? body->items[0].text : "";
      fr.unknown = f->sym;
      fr.value = *value;
      fr.value_number = number_of(*value, f->sym);
      for (const auto& cc : a.solution.conditions)
        if (cc.condition && cc.condition->source == out.connection && cc.condition->lhs.is_equal(f->sym) &&
            cc.condition->op[0] == '<') {
          fr.limit = cc.condition->rhs;
          fr.limit_value = normal(substituted(cc.condition->rhs, solved));
          fr.limit_number = number_of(fr.limit_value, f->sym);
        }
      out.friction = std::move(fr);
    }
  }
  turn = false;
  if (!out.failed.empty()) out.undecided = false;
  if (out.failed.empty() || rule->regimes.size() < 2) return out;
  const RegimeSpec& next = rule->regimes[1];
  out.chosen = next.type;
  if (f)
    if (const auto value = a.solution.value_of(f->sym))
      if (const auto v = at_values(*value, table)) turn = v->is_positive();
  return out;
}

}  // namespace tackle

#include "model/symbols.hpp"

#include "expr/normal_form.hpp"

#include <set>

namespace tackle {

namespace {

std::string tex_atom(std::string_view s) {
  static const std::set<std::string, std::less<>> greek = {
      "alpha", "beta",  "gamma", "delta", "epsilon", "zeta",  "eta", "theta",   "iota", "kappa", "lambda",
      "mu",    "nu",    "xi",    "pi",    "rho",     "sigma", "tau", "upsilon", "phi",  "chi",   "psi",
      "omega", "Gamma", "Delta", "Theta", "Lambda",  "Xi",    "Pi",  "Sigma",   "Phi",  "Psi",   "Omega"};
  if (greek.count(s)) return "\\" + std::string(s);
  if (s.size() > 1) return "\\mathrm{" + std::string(s) + "}";
  return std::string(s);
}

}  // namespace

FactorRank factor_rank(std::vector<std::shared_ptr<const SymbolTable>> tables) {
  return [tables = std::move(tables)](const GiNaC::ex& x) {
    if (!GiNaC::is_a<GiNaC::symbol>(x)) return 5;
    const SymbolInfo* s = nullptr;
    for (const auto& t : tables)
      if (t && (s = t->find(x))) break;
    if (!s) return 2;
    switch (s->role) {
      case SymbolRole::parameter:
      case SymbolRole::defined:
        if (s->dimension ? s->dimension->exp == Dimension::none().exp : s->role == SymbolRole::parameter) return 0;
        if (s->dimension->exp == Dimension::mass().exp) return 1;
        return 2;
      case SymbolRole::time: return 3;  // omega t, as a person writes it
      case SymbolRole::coordinate: return 3;
      default: return 4;
    }
  };
}

std::string default_tex(std::string_view name) {
  for (const char* op : {"ddot", "dot"}) {
    const std::string prefix = std::string(op) + "(";
    if (name.substr(0, prefix.size()) == prefix && name.back() == ')') {
      const std::string inner(name.substr(prefix.size(), name.size() - prefix.size() - 1));
      const auto us = inner.find('_');
      const std::string base = inner.substr(0, us);
      std::string t = "\\" + std::string(op) + "{" + tex_atom(base) + "}";
      if (us != std::string::npos) t += "_{" + inner.substr(us + 1) + "}";
      return t;
    }
  }
  const auto us = name.find('_');
  if (us == std::string_view::npos) return tex_atom(name);
  std::string sub(name.substr(us + 1));
  for (auto& c : sub)
    if (c == '_') c = ',';
  return tex_atom(name.substr(0, us)) + "_{" + sub + "}";
}

const SymbolInfo& SymbolTable::add(const std::string& name, std::optional<std::string> tex, SymbolRole role,
                                   std::optional<Dimension> dimension, bool positive, Location where) {
  changed();
  if (by_name_.count(name)) throw InternalError("symbol '" + name + "' made twice");
  auto info = std::make_unique<SymbolInfo>();
  info->name = name;
  info->tex = tex ? *tex : default_tex(name);
  if (positive)
    info->sym = GiNaC::possymbol(name, info->tex);
  else
    info->sym = GiNaC::realsymbol(name, info->tex);
  info->role = role;
  info->dimension = dimension;
  info->positive = positive;
  info->where = std::move(where);
  by_name_[name] = items_.size();
  by_symbol_[info->sym] = items_.size();
  items_.push_back(std::move(info));
  return *items_.back();
}

const SymbolInfo* SymbolTable::find(std::string_view name) const {
  auto it = by_name_.find(name);
  return it == by_name_.end() ? nullptr : items_[it->second].get();
}

const SymbolInfo* SymbolTable::find(const GiNaC::ex& sym) const {
  auto it = by_symbol_.find(sym);
  return it == by_symbol_.end() ? nullptr : items_[it->second].get();
}

void SymbolTable::set_unit(const std::string& name, std::string unit, GiNaC::ex to_si) {
  changed();
  auto it = by_name_.find(name);
  if (it == by_name_.end()) throw InternalError("no symbol '" + name + "'");
  items_[it->second]->unit = std::move(unit);
  items_[it->second]->unit_to_si = to_si;
}

void SymbolTable::set_value(const std::string& name, GiNaC::ex value) {
  changed();
  auto it = by_name_.find(name);
  if (it == by_name_.end()) throw InternalError("no symbol '" + name + "'");
  items_[it->second]->value = value;
}

void SymbolTable::set_alias(const std::string& name, GiNaC::ex expression) { aliases_[name] = std::move(expression); }

std::optional<GiNaC::ex> SymbolTable::resolve(std::string_view name) const {
  if (const auto a = aliases_.find(name); a != aliases_.end()) return a->second;
  if (const SymbolInfo* s = find(name)) {
    if (s->role == SymbolRole::defined) return std::nullopt;
    return GiNaC::ex(s->sym);
  }
  return std::nullopt;
}

std::vector<std::string> SymbolTable::known_names() const {
  std::vector<std::string> n;
  for (const auto& s : items_)
    if (s->role != SymbolRole::defined && s->name.find('^') == std::string::npos) n.push_back(s->name);  // not omega^2
  for (const auto& [name, expression] : aliases_) n.push_back(name);
  return n;
}

std::optional<Dimension> SymbolTable::dimension_of(const GiNaC::symbol& s) const {
  if (const SymbolInfo* i = find(s)) return i->dimension;
  return std::nullopt;
}

void SymbolTable::set_range(const std::string& name, GiNaC::numeric low, GiNaC::numeric high,
                            std::optional<GiNaC::numeric> step) {
  changed();
  auto it = by_name_.find(name);
  if (it == by_name_.end()) throw InternalError("no symbol '" + name + "'");
  items_[it->second]->range = std::make_pair(low, high);
  items_[it->second]->step = step;
}

GiNaC::exmap SymbolTable::definitions(bool geometric) const {
  GiNaC::exmap m;
  for (const SymbolInfo* s : defined())
    if (geometric || !s->geometric) m[s->sym] = *s->definition;
  return m;
}

void SymbolTable::set_definition(const std::string& name, GiNaC::ex definition, bool geometric) {
  changed();
  auto it = by_name_.find(name);
  if (it == by_name_.end()) throw InternalError("no symbol '" + name + "'");
  items_[it->second]->definition = std::move(definition);
  items_[it->second]->geometric = geometric;
  defined_.insert(it->second);
}

std::vector<const SymbolInfo*> SymbolTable::defined() const {
  std::vector<const SymbolInfo*> out;
  out.reserve(defined_.size());
  for (const std::size_t i : defined_) out.push_back(items_[i].get());
  return out;
}

bool SymbolTable::hidden_in_lengths(const GiNaC::ex& e, const GiNaC::ex& s) const {
  for (const SymbolInfo* item : defined())
    if (item->geometric && e.has(item->sym) && (item->sym.is_equal(s) || item->definition->has(s))) return true;
  return false;
}

GiNaC::exmap SymbolTable::values() const { return value_set()->map; }

std::shared_ptr<const SymbolTable::ValueSet> SymbolTable::value_set() const {
  const std::lock_guard<std::mutex> lock(values_mutex_);
  if (values_) return values_;
  // Defined parameters get their exact expression in the values before them (sqrt(61)/2,
  // not a float whose last digits would depend on the order of operations).
  GiNaC::exmap m;
  for (const auto& s : items_) {
    if (s->value) {
      m[s->sym] = *s->value;
    } else if (s->definition) {
      // Undefined at these values (a denominator that vanishes): no value.
      const NormalForm form(*s->definition);
      if (form.undefined_at(m)) continue;
      const GiNaC::ex v = substituted(form.num, m) / substituted(form.den, m);
      bool complete = true;
      for (GiNaC::const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
        complete = complete && !GiNaC::is_a<GiNaC::symbol>(*it);
      if (complete) m[s->sym] = v;
    }
  }
  auto set = std::make_shared<ValueSet>();
  for (const auto& [sym, v] : m)
    if (GiNaC::is_a<GiNaC::numeric>(v) && GiNaC::ex_to<GiNaC::numeric>(v).is_rational())
      set->rational.emplace(sym, GiNaC::ex_to<GiNaC::numeric>(v));
  set->map = std::move(m);
  values_ = set;
  return values_;
}

}  // namespace tackle

#include "report/key.hpp"

#include <algorithm>
#include <map>
#include <random>

#include "expr/print.hpp"
#include "report/tex.hpp"

namespace tackle {

using namespace GiNaC;

std::vector<std::vector<Variant>> draw_variants(const std::vector<std::pair<const Model*, const Derivation*>>& parts,
                                                int count, unsigned long long seed, int digits) {
  // The ranged parameters of all parts, by name, in the order they first appear (a phase's
  // shared parameters come first in each, so the same draw serves every phase).
  std::vector<const SymbolInfo*> ranged;
  for (const auto& [a, d] : parts)
    for (const auto& s : a->symbols->all())
      if (s->role == SymbolRole::parameter && s->range &&
          std::none_of(ranged.begin(), ranged.end(), [&](const SymbolInfo* r) { return r->name == s->name; }))
        ranged.push_back(s.get());
  std::vector<std::vector<Variant>> out(parts.size());
  if (ranged.empty() || count <= 0 || parts.empty()) return out;
  std::mt19937_64 rng(seed);
  // Each condition's normal form once; each draw only substitutes into it.
  std::vector<std::vector<NormalForm>> condition_forms(parts.size());
  for (std::size_t p = 0; p < parts.size(); ++p)
    for (const auto& c : parts[p].second->conditions) condition_forms[p].emplace_back(c.simplified);
  int attempts = 0, drawn = 0;
  while (drawn < count) {
    if (++attempts > 1000 * count)
      throw InputError({{{parts[0].first->file, 0, 0},
                         "could not draw " + std::to_string(count) +
                             " variants that keep every validity condition (check the parameters' 'range')"}});
    std::map<std::string, ex> drawn_si;
    std::vector<Quantity> parameters;
    for (const SymbolInfo* s : ranged) {
      const auto [low, high] = *s->range;
      // A multiple of the step from `low`: k in [0, steps], steps = floor((high - low)/step).
      const numeric step = s->step ? *s->step : (high - low) / 100;
      const auto steps = static_cast<unsigned long long>(((high - low) / step).to_double() + 1e-9);
      const numeric value = low + numeric(static_cast<long>(rng() % (steps + 1))) * step;
      drawn_si[s->name] = value * s->unit_to_si;
      parameters.push_back({s->name, decimal_string(value, digits), s->unit, value.to_double()});
    }
    // Every condition of every part must hold and every answer must have a value (a draw
    // where one is undefined is drawn again).
    bool valid = true;
    std::vector<Variant> variants(parts.size());
    for (std::size_t p = 0; p < parts.size() && valid; ++p) {
      const SymbolTable& table = *parts[p].first->symbols;
      const Derivation& d = *parts[p].second;
      exmap values = table.values();
      Variant& v = variants[p];
      v.index = drawn + 1;
      for (const auto& s : table.all())
        if (auto it = drawn_si.find(s->name); it != drawn_si.end() && s->role == SymbolRole::parameter) {
          values[s->sym] = it->second;
          v.values[s->sym] = it->second;
        }
      for (const SymbolInfo* r : ranged)
        for (const auto& q : parameters)
          if (q.name == r->name && table.find(r->name)) v.parameters.push_back(q);
      for (const auto& s : table.all())
        if (s->definition)
          if (auto x = value_at(*s->definition, values)) values[s->sym] = *x;
      for (std::size_t k = 0; k < d.conditions.size(); ++k) {
        const auto& c = d.conditions[k];
        const auto exact = condition_forms[p][k].at(values);
        const ex x = exact ? evalf(*exact) : ex(0);
        valid = valid && exact && is_a<numeric>(x) && ex_to<numeric>(x).is_real() &&
                relation_holds(ex_to<numeric>(x), c.op);
      }
      for (const auto& ans : d.answers) {
        if (!valid || !ans.closed_form) continue;
        const SymbolInfo* info = table.find(ans.symbol);
        auto value = evaluate_with(*ans.closed_form, values, info ? info->dimension : std::nullopt, digits, ans.unit);
        if (!value) {
          valid = false;
          continue;
        }
        v.answers.push_back({ans.name, value->decimal, value->unit, value->approx});
      }
    }
    if (!valid) continue;
    ++drawn;
    for (std::size_t p = 0; p < parts.size(); ++p)
      if (!variants[p].parameters.empty()) out[p].push_back(std::move(variants[p]));
  }
  return out;
}

std::vector<Variant> draw_variants(const Model& m, const Derivation& d, int count, unsigned long long seed,
                                   int digits) {
  return draw_variants({{&m, &d}}, count, seed, digits).front();
}

}  // namespace tackle

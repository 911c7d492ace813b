#include "numeric/layout.hpp"

#include "numeric/evaluate.hpp"

#include <cmath>

namespace tackle {

using namespace GiNaC;

exmap layout_numbers(const Model& m, const exmap& values, std::set<ex, ex_is_less>* defaulted) {
  exmap out = m.layout;
  const SymbolTable& table = *m.symbols;
  if (!values.empty()) {
    for (const auto& [s, v] : values) out[s] = v;
    for (const auto& s : table.all())
      if (s->definition) out.erase(s->sym);  // made again from the new values below
  }
  for (const auto& s : table.all()) {
    if (out.count(s->sym) || s->definition) continue;
    if (s->role == SymbolRole::parameter) {
      out[s->sym] = 1;
      if (defaulted) defaulted->insert(s->sym);
    } else if (s->role == SymbolRole::coordinate || s->role == SymbolRole::time) {
      out[s->sym] = 0;
    }
  }
  for (const auto& s : table.all())
    if (s->definition && !out.count(s->sym))
      if (auto x = value_at(*s->definition, out)) out[s->sym] = *x;
  for (const auto& l : m.lengths)
    if (auto sq = value_at(l.squared, out); sq && is_a<numeric>(*sq) && ex_to<numeric>(*sq) >= 0)
      out[l.symbol] = sqrt(*sq);
  return out;
}

std::optional<double> real_at(const ex& e, const exmap& values) {
  const auto v = value_at(e, values);
  if (!v) return std::nullopt;
  const ex x = evalf(*v);
  if (!is_a<numeric>(x) || !ex_to<numeric>(x).is_real()) return std::nullopt;
  const double d = ex_to<numeric>(x).to_double();
  return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
}

std::optional<std::array<double, 3>> point_at(const Model& m,
                                              const std::function<std::optional<double>(const ex&)>& number,
                                              const Vec& v) {
  std::array<double, 3> p{0, 0, 0};
  for (int k = 0; k < m.dims(); ++k) {
    const auto x = number(v[k]);
    if (!x) return std::nullopt;
    p[static_cast<std::size_t>(k)] = *x;
  }
  return p;
}

}  // namespace tackle

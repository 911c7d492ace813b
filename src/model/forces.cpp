#include "model/forces.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "expr/print.hpp"

namespace tackle {

using namespace GiNaC;

std::set<std::string> internal_forces(const Model& m, const std::vector<int>& bodies) {
  std::set<std::string> internal;
  if (bodies.size() < 2) return internal;
  std::map<std::string, Vec> sums;
  for (const auto& l : m.loads)
    if (std::find(bodies.begin(), bodies.end(), l.body) != bodies.end()) {
      auto [it, fresh] = sums.emplace(force_key(l.origin), zero_vec());
      it->second = it->second + l.force;
    }
  for (const auto& [key, sum] : sums)
    if (is_zero_vec(sum)) internal.insert(key);
  return internal;
}

std::vector<ForcePart> split_force(const Model& m, const Vec& force, const std::set<ex, ex_is_less>& unknowns,
                                   const NumberAt& number) {
  std::vector<ForcePart> parts;
  Vec rest = zero_vec();
  for (int k = 0; k < m.dims(); ++k) rest[k] = force[k].expand();
  // In the model's order of unknowns, never GiNaC's (hash) order: the result must not change
  // from run to run.
  std::set<ex, ex_is_less> seen;
  for (int k = 0; k < m.dims(); ++k)
    for (const_preorder_iterator it = rest[k].preorder_begin(); it != rest[k].preorder_end(); ++it)
      if (is_a<symbol>(*it) && unknowns.count(*it)) seen.insert(*it);
  std::vector<ex> present;
  for (const ex& c : m.candidates)
    if (seen.count(c)) present.push_back(c);
  for (const ex& u : present) {
    Vec c = zero_vec();
    bool linear = true;
    for (int k = 0; k < m.dims(); ++k) {
      if (rest[k].degree(u) > 1 || rest[k].ldegree(u) < 0) linear = false;
      c[k] = rest[k].coeff(u, 1);
    }
    if (!linear) continue;  // left in the rest
    // One part per kind of term: a contact's mu N apart from its N (a dimensionless factor
    // such as mu makes a term its own force), the geometry (angles, lengths) kept in the
    // direction.
    std::vector<std::pair<ex, Vec>> groups;  // in the order the terms are met
    for (int k = 0; k < m.dims(); ++k) {
      const ex ck = c[k].expand();
      const std::size_t n = is_a<add>(ck) ? ck.nops() : 1;
      for (std::size_t t = 0; t < n; ++t) {
        const ex term = is_a<add>(ck) ? ck.op(t) : ck;
        if (term.is_zero()) continue;
        ex key = 1;
        const std::size_t nf = is_a<mul>(term) ? term.nops() : 1;
        for (std::size_t q = 0; q < nf; ++q) {
          const ex fac = is_a<mul>(term) ? term.op(q) : term;
          const ex base = is_a<power>(fac) ? fac.op(0) : fac;
          if (!is_a<symbol>(base)) continue;
          const SymbolInfo* info = m.symbols->find(base);
          if (info && info->role == SymbolRole::parameter &&
              (!info->dimension || info->dimension->exp == Dimension::none().exp) && !info->definition)
            key *= fac;
        }
        auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first.is_equal(key); });
        if (it == groups.end()) it = groups.insert(groups.end(), {key, zero_vec()});
        it->second[k] += term / key;
      }
    }
    std::sort(groups.begin(), groups.end(),
              [](const auto& a, const auto& b) { return to_text(a.first) < to_text(b.first); });
    bool kept = false;
    for (const auto& [key, cvec] : groups) {
      ForcePart p{u, key, cvec, {0, 0, 0}};
      bool ok = true, nonzero = false;
      for (int k = 0; k < m.dims(); ++k) {
        const auto v = number(cvec[k]);
        if (!v)
          ok = false;
        else
          p.numbers[k] = *v;
        if (v && std::fabs(*v) > 1e-12) nonzero = true;
      }
      if (!ok || !nonzero) continue;
      parts.push_back(std::move(p));
      kept = true;
    }
    if (kept)
      for (int k = 0; k < m.dims(); ++k) rest[k] = (rest[k] - c[k] * u).expand();
  }
  bool any = false;
  for (int k = 0; k < m.dims(); ++k) any = any || !rest[k].is_zero();
  if (any) {
    ForcePart p;
    // A force with no unknown split off keeps the form it was written in (k (x_B - x_A - L)).
    for (int k = 0; k < m.dims(); ++k)
      p.coefficients[k] = rest[k].is_zero() ? ex(0) : present.empty() ? force[k] : rest[k];
    for (int k = 0; k < m.dims(); ++k)
      if (const auto v = number(p.coefficients[k])) p.numbers[k] = *v;
    parts.push_back(std::move(p));
  }
  return parts;
}

}  // namespace tackle

#include "algebra/truth.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

std::optional<std::vector<ex>> linear_parts(const ex& residual, const std::vector<ex>& unknowns) {
  try {
    const ex e = residual.expand();
    std::vector<ex> v;
    exmap zero;
    for (const ex& u : unknowns) zero[u] = 0;
    for (const ex& u : unknowns) {
      if (!e.has(u)) {
        v.push_back(0);
        continue;
      }
      // (degree() throws for a power with a fractional exponent, sqrt(T^2): not linear.)
      if (e.degree(u) > 1 || e.ldegree(u) < 0) return std::nullopt;
      const ex c = e.coeff(u, 1);
      for (const ex& w : unknowns)
        if (c.has(w)) return std::nullopt;  // a product of two unknowns
      v.push_back(c);
    }
    const ex rest = e.subs(zero);
    // Every unknown must appear linearly: what is left must be free of them, and the parts
    // must make the whole (abs(T) has no part linear in T).
    for (const ex& w : unknowns)
      if (rest.has(w)) return std::nullopt;
    ex whole = rest;
    for (std::size_t i = 0; i < unknowns.size(); ++i) whole += v[i] * unknowns[i];
    if (!(e - whole).expand().is_zero()) return std::nullopt;
    v.push_back(rest);
    return v;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Truth::Truth(Family family, const States& states, std::vector<Sample> points, std::size_t fixed, const exmap& definitions,
             Tolerance tolerance)
    : family_(std::move(family)),
      layout_(states.layout()),
      angles_(states.angles()),
      definitions_(definitions),
      tolerance_(std::move(tolerance)),
      points_(std::move(points)),
      fixed_(fixed) {
  for (const ex& u : family_.unknowns) {
    std::size_t i = 0;
    while (i < layout_.size() && !layout_[i].first.is_equal(u)) ++i;
    if (i == layout_.size()) {
      layout_.emplace_back(u, 0);
      angles_.push_back(false);
    }
    unknown_at_.push_back(i);
  }
  at_rows_.resize(family_.residuals.size());
  for (std::size_t i = 0; i < family_.residuals.size(); ++i) {
    const auto parts = linear_parts(family_.residuals[i], family_.unknowns);
    if (!parts) return;
    const Values v = values(*parts);
    if (!v) return;
    at_rows_[i] = *v;
  }
  for (std::size_t k = 0; k < points_.size(); ++k) {
    std::vector<Row> rows;
    for (const auto& r : at_rows_) rows.push_back(r[k]);
    null_.push_back(null_space(rows, width(), tolerance_));
    // Consistent: some solution has the constant's place not zero (free constants: always).
    const bool consistent = family_.free_constants || std::any_of(null_.back().begin(), null_.back().end(), [&](const Row& x) {
                              return !tolerance_.negligible(x.back(), size_of(x));
                            });
    if (!consistent) return;
  }
  usable_ = !points_.empty();
}

Sample Truth::extended(std::size_t k, const Row& unknowns) const {
  Sample p = points_[k];
  p.resize(layout_.size());
  for (std::size_t i = points_[k].size(); i < layout_.size(); ++i) p[i] = {layout_[i].first, 0};
  for (std::size_t j = 0; j < unknowns.size() && j < unknown_at_.size(); ++j) p[unknown_at_[j]].second = unknowns[j];
  return p;
}

Truth::Values Truth::values(const std::vector<ex>& parts, bool fixed_only) const {
  std::vector<Program> programs;
  for (std::size_t j = 0; j < parts.size(); ++j) {
    const bool dropped = family_.free_constants && j + 1 == parts.size();
    programs.emplace_back(dropped ? ex(0) : parts[j], layout_, definitions_, angles_);
  }
  const std::size_t n = fixed_only ? std::min(fixed_, points_.size()) : points_.size();
  std::vector<Row> out;
  const Row none(family_.unknowns.size(), 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Sample p = extended(k, none);
    Row row;
    for (const Program& prog : programs) {
      const auto x = prog(p);
      if (!x) return std::nullopt;
      row.push_back(*x);
    }
    out.push_back(std::move(row));
  }
  return out;
}

Truth::Decision Truth::holds(const std::vector<Row>& values) const {
  bool exact = true;
  for (std::size_t k = 0; k < values.size() && k < null_.size(); ++k) {
    const bool rational = std::all_of(values[k].begin(), values[k].end(), [](const numeric& x) { return x.is_rational(); });
    for (const Row& x : null_[k])
      if (!orthogonal(values[k], x, tolerance_)) return {Answer::fails, rational && all_rational(null_[k])};
    exact = exact && rational && all_rational(null_[k]);
  }
  return {fresh() ? Answer::holds : Answer::unknown, exact};
}

std::optional<Row> Truth::solution(std::size_t k, std::mt19937& rng) const {
  if (k >= null_.size()) return std::nullopt;
  std::uniform_int_distribution<int> pick(1, 1000);
  for (int attempt = 0; attempt < 4; ++attempt) {
    Row x(width(), 0);
    for (const Row& b : null_[k]) {
      const numeric z(pick(rng), 97);
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = x[i] + z * b[i];
    }
    if (tolerance_.negligible(x.back(), size_of(x))) continue;
    Row u(x.begin(), x.end() - 1);
    for (numeric& v : u) v = v / x.back();
    return u;
  }
  return std::nullopt;
}

namespace {

// The value of `residual` at a point, and the scale it is compared with (the sum of its
// terms' sizes); none where it is not defined.
struct Evaluated {
  numeric value, scale;
};

std::optional<Evaluated> evaluate_terms(const std::vector<Program>& terms, const Sample& p) {
  Evaluated out{0, 0};
  for (const Program& t : terms) {
    const auto v = t(p);
    if (!v || !v->is_real()) return std::nullopt;
    out.value = out.value + *v;
    out.scale = out.scale + abs(*v);
  }
  return out;
}

std::vector<Program> term_programs(const ex& residual, const Sample& layout, const exmap& definitions, const std::vector<bool>& angles) {
  std::vector<Program> out;
  if (is_exactly<add>(residual)) {
    for (const auto& t : residual) out.emplace_back(t, layout, definitions, angles);
  } else {
    out.emplace_back(residual, layout, definitions, angles);
  }
  return out;
}

}  // namespace

Truth::Decision Truth::holds_anyhow(const ex& residual) const {
  const std::vector<Program> terms = term_programs(residual, layout_, definitions_, angles_);
  std::mt19937 rng(7);
  bool exact = true, any = false;
  for (std::size_t k = 0; k < points_.size(); ++k)
    for (int draw = 0; draw < 2; ++draw) {
      const auto u = solution(k, rng);
      if (!u) continue;
      const auto v = evaluate_terms(terms, extended(k, *u));
      if (!v) continue;
      any = true;
      if (!tolerance_.negligible(v->value, v->scale)) return {Answer::fails, v->value.is_rational()};
      exact = exact && v->value.is_rational();
    }
  return {any && fresh() ? Answer::holds : Answer::unknown, exact};
}

Truth::Decision Truth::vanishes(const ex& residual) const {
  const std::vector<Program> terms = term_programs(residual, layout_, definitions_, angles_);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> pick(1, 10000);
  bool exact = true, any = false;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    Row u;
    for (std::size_t j = 0; j < family_.unknowns.size(); ++j) u.push_back(numeric(pick(rng), 1000));
    const auto v = evaluate_terms(terms, extended(k, u));
    if (!v) continue;
    any = true;
    if (!tolerance_.negligible(v->value, v->scale)) return {Answer::fails, v->value.is_rational()};
    exact = exact && v->value.is_rational();
  }
  return {any ? Answer::holds : Answer::unknown, exact};
}

bool Truth::proportional(const std::vector<Row>& a, const std::vector<Row>& b) const {
  const std::size_t n = std::min(a.size(), b.size());
  for (std::size_t k = 0; k < n; ++k)
    if (!tackle::proportional(a[k], b[k], tolerance_)) return false;
  return n > 0;
}

std::vector<Truth::Part> Truth::combination(const std::vector<Row>& values) const {
  if (values.empty() || at_rows_.empty()) return {};
  // At the first point: all the equations, then each left out (the latest first) while the
  // rest still give it.
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < at_rows_.size(); ++i)
    if (std::any_of(at_rows_[i][0].begin(), at_rows_[i][0].end(), [](const numeric& x) { return !x.is_zero(); })) used.push_back(i);
  auto rows_at = [&](const std::vector<std::size_t>& which, std::size_t k) {
    std::vector<Row> rows;
    for (const std::size_t i : which) rows.push_back(at_rows_[i][k]);
    return rows;
  };
  for (std::size_t j = used.size(); j-- > 0;) {
    std::vector<std::size_t> rest = used;
    rest.erase(rest.begin() + static_cast<std::ptrdiff_t>(j));
    if (combination_of(rows_at(rest, 0), values[0], tolerance_)) used = std::move(rest);
  }
  // Each coefficient at every point, against the first's: plain when the same number at each.
  std::vector<Part> out;
  std::vector<std::optional<Row>> lambdas;
  for (std::size_t k = 0; k < values.size(); ++k) lambdas.push_back(combination_of(rows_at(used, k), values[k], tolerance_));
  for (std::size_t j = 0; j < used.size(); ++j) {
    bool plain = true;
    std::optional<numeric> ratio;
    for (const auto& l : lambdas) {
      if (!l || (*l)[0].is_zero()) {
        plain = false;
        break;
      }
      const numeric r = (*l)[j] / (*l)[0];
      if (ratio && !tolerance_.negligible(r - *ratio, abs(r) + abs(*ratio))) plain = false;
      ratio = r;
    }
    out.push_back({used[j], plain && ratio && ratio->is_rational()});
  }
  return out;
}

}  // namespace tackle

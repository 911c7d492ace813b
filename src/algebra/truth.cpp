#include "algebra/truth.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

namespace {

// Which unknown `f` is (its place), or -1; -2 when it is not one but holds one.
int unknown_place(const ex& f, const std::vector<ex>& unknowns) {
  if (is_exactly<symbol>(f)) {
    for (std::size_t i = 0; i < unknowns.size(); ++i)
      if (unknowns[i].is_equal(f)) return static_cast<int>(i);
    return -1;
  }
  if (is_exactly<numeric>(f)) return -1;
  for (const ex& u : unknowns)
    if (f.has(u)) return -2;
  return -1;
}

// A term of an expanded sum into the parts: its unknown's (its coefficient), or the rest's;
// false when it holds two unknowns, a power of one, or one inside anything else.
bool put_term(const ex& t, const std::vector<ex>& unknowns, std::vector<exvector>& parts) {
  if (!is_exactly<mul>(t)) {
    const int place = unknown_place(t, unknowns);
    if (place == -2) return false;
    if (place >= 0)
      parts[static_cast<std::size_t>(place)].push_back(1);
    else
      parts.back().push_back(t);
    return true;
  }
  int found = -1;
  exvector rest;
  for (std::size_t i = 0; i < t.nops(); ++i) {
    const ex f = t.op(i);
    const int place = unknown_place(f, unknowns);
    if (place == -2 || (place >= 0 && found >= 0)) return false;
    if (place >= 0)
      found = place;
    else
      rest.push_back(f);
  }
  (found >= 0 ? parts[static_cast<std::size_t>(found)] : parts.back()).push_back(mul(rest));
  return true;
}

}  // namespace

std::optional<std::vector<ex>> linear_parts(const ex& residual, const std::vector<ex>& unknowns) {
  try {
    const ex e = residual.expand();
    std::vector<exvector> parts(unknowns.size() + 1);
    if (is_exactly<add>(e)) {
      for (std::size_t i = 0; i < e.nops(); ++i)
        if (!put_term(e.op(i), unknowns, parts)) return std::nullopt;
    } else if (!put_term(e, unknowns, parts)) {
      return std::nullopt;
    }
    std::vector<ex> v;
    for (const auto& p : parts) v.push_back(add(p));
    return v;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Truth::Truth(Family family, const States& states, std::vector<Sample> points, std::size_t fixed,
             const exmap& definitions, Tolerance tolerance)
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
    const bool consistent = family_.free_constants ||
                            std::any_of(null_.back().begin(), null_.back().end(),
                                        [&](const Row& x) { return !tolerance_.negligible(x.back(), size_of(x)); });
    if (!consistent) return;
  }
  usable_ = !points_.empty();
  prepare_basis();
}

void Truth::prepare_basis() {
  std::vector<Row> first;
  for (const auto& r : at_rows_) first.push_back(r[0]);
  basis_ = independent_rows(first, width(), tolerance_);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    std::vector<Row> rows;
    for (const std::size_t i : basis_) rows.push_back(at_rows_[i][k]);
    inverses_.push_back(left_inverse(rows, width(), tolerance_));
  }
}

Sample Truth::extended(std::size_t k, const Row& unknowns) const {
  Sample p = points_[k];
  p.resize(layout_.size());
  for (std::size_t i = points_[k].size(); i < layout_.size(); ++i) p[i] = {layout_[i].first, 0};
  for (std::size_t j = 0; j < unknowns.size() && j < unknown_at_.size(); ++j) p[unknown_at_[j]].second = unknowns[j];
  return p;
}

Truth::Values Truth::values(const std::vector<ex>& parts, bool fixed_only, std::size_t first) const {
  std::vector<Program> programs;
  for (std::size_t j = 0; j < parts.size(); ++j) {
    const bool dropped = family_.free_constants && j + 1 == parts.size();
    programs.emplace_back(dropped ? ex(0) : parts[j], layout_, definitions_, angles_);
  }
  const std::size_t n = fixed_only ? std::min(fixed_, points_.size()) : points_.size();
  std::vector<Row> out;
  const Row none(family_.unknowns.size(), 0);
  for (std::size_t k = first; k < n; ++k) {
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
  bool exact = true, fresh_checked = false;
  for (std::size_t k = 0; k < values.size() && k < null_.size(); ++k) {
    if (!allowed_point(k)) continue;
    fresh_checked = fresh_checked || k >= fixed_;
    const bool rational =
        std::all_of(values[k].begin(), values[k].end(), [](const numeric& x) { return x.is_rational(); });
    for (const Row& x : null_[k])
      if (!orthogonal(values[k], x, tolerance_)) return {Answer::fails, rational && all_rational(null_[k])};
    exact = exact && rational && all_rational(null_[k]);
  }
  return {fresh_checked ? Answer::holds : Answer::unknown, exact};
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
    const numeric size = size_of(x);
    if (tolerance_.negligible(x.back(), size)) continue;
    Row u(x.begin(), x.end() - 1);
    // (A float that is zero up to rounding, an unknown the family holds at 0, made 0: in a
    // product or a quotient it would be taken for a value.)
    for (numeric& v : u) v = tolerance_.negligible(v, size) ? numeric(0) : v / x.back();
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

std::vector<Program> term_programs(const ex& residual, const Sample& layout, const exmap& definitions,
                                   const std::vector<bool>& angles) {
  std::vector<Program> out;
  if (is_exactly<add>(residual)) {
    for (const auto& t : residual) out.emplace_back(t, layout, definitions, angles);
  } else {
    out.emplace_back(residual, layout, definitions, angles);
  }
  return out;
}

}  // namespace

int Truth::sign_asked(const std::string& op) { return op == ">=" || op == ">" ? 1 : op == "<=" || op == "<" ? -1 : 0; }

void Truth::restrict_to(const std::vector<Condition>& conditions) {
  for (const auto& c : conditions) {
    const int sign = sign_asked(c.op);
    if (sign != 0) conditions_.push_back({Program(c.lhs - c.rhs, layout_, definitions_, angles_), sign});
  }
  if (conditions_.empty() || !usable_) return;
  // A point where the unknowns are determined is a state, allowed or not; elsewhere the
  // random solutions are screened one by one (holds_anyhow).
  std::mt19937 rng(3);
  allowed_points_.assign(points_.size(), true);
  bool any_fresh = false;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    if (null_[k].size() == 1)
      if (const auto u = solution(k, rng)) allowed_points_[k] = allowed(k, *u);
    any_fresh = any_fresh || (k >= fixed_ && allowed_points_[k]);
  }
  // None of the fresh states meets the conditions (they fail near the given numbers): the
  // equations alone decide.
  if (!any_fresh) {
    allowed_points_.clear();
    conditions_.clear();
  }
}

bool Truth::allowed(std::size_t k, const Row& unknowns) const {
  if (conditions_.empty()) return true;
  const Sample p = extended(k, unknowns);
  for (const auto& c : conditions_) {
    const auto v = c.difference(p);
    if (!v || !v->is_real()) continue;
    const numeric x = c.sign > 0 ? *v : -*v;
    if (x.is_negative() && !tolerance_.negligible(x, size_of(unknowns) + abs(x))) return false;
  }
  return true;
}

Truth::Decision Truth::holds_anyhow(const ex& residual) const {
  const std::vector<Program> terms = term_programs(residual, layout_, definitions_, angles_);
  std::mt19937 rng(7);
  bool exact = true, any = false;
  for (std::size_t k = 0; k < points_.size(); ++k)
    for (int draw = 0, kept = 0; draw < 8 && kept < 2; ++draw) {
      if (!allowed_point(k)) break;
      const auto u = solution(k, rng);
      if (!u) continue;
      if (!allowed(k, *u)) {
        if (null_[k].size() <= 1) break;  // the one solution there: a state the model leaves out
        continue;
      }
      ++kept;
      const auto v = evaluate_terms(terms, extended(k, *u));
      if (!v) continue;
      any = any || k >= fixed_;  // a fresh state: the fixed ones alone never settle it
      if (!tolerance_.negligible(v->value, v->scale)) return {Answer::fails, v->value.is_rational()};
      exact = exact && v->value.is_rational();
    }
  return {any ? Answer::holds : Answer::unknown, exact};
}

Truth::Decision Truth::vanishes(const ex& residual) const {
  const std::vector<Program> terms = term_programs(residual, layout_, definitions_, angles_);
  std::mt19937 rng(11);
  // Either sign, where the stated conditions allow it: sqrt(T^2) = T says nothing where T >= 0
  // is stated, and says T >= 0 where it is not.
  std::uniform_int_distribution<int> pick(1, 10000), sign(0, 1);
  bool exact = true, any = false;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    Row u;
    // (The last attempt all positive: forces that the conditions keep from pulling or pushing.)
    for (int attempt = 0; attempt < 8 && (attempt == 0 || !allowed(k, u)); ++attempt) {
      u.clear();
      for (std::size_t j = 0; j < family_.unknowns.size(); ++j)
        u.push_back(numeric(attempt == 7 || sign(rng) ? pick(rng) : -pick(rng), 1000));
    }
    if (!allowed(k, u)) continue;
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
  if (values.empty() || basis_.empty()) return {};
  // The coefficients (in the basis) at the first point and at the last, a fresh one, where the
  // left inverse is known: a coefficient that is a rational function of the inputs and not a
  // number takes the same value at both by chance only.
  std::vector<std::optional<Row>> lambdas;
  for (const std::size_t k : {std::size_t{0}, std::min(values.size(), inverses_.size()) - 1})
    lambdas.push_back(inverses_[k] ? std::optional<Row>(inverses_[k]->coefficients(values[k])) : std::nullopt);
  if (lambdas.empty() || !lambdas[0]) return {};
  const Row& at_first = *lambdas[0];
  const numeric scale = size_of(at_first);
  std::vector<std::size_t> used;
  for (std::size_t j = 0; j < at_first.size(); ++j)
    if (!tolerance_.negligible(at_first[j], scale)) used.push_back(j);
  // Plain: each coefficient over the first's the same number at every point.
  std::vector<Part> out;
  for (const std::size_t j : used) {
    bool plain = true;
    for (const auto& l : lambdas) {
      if (!l) {
        plain = false;
        break;
      }
      const numeric a = (*l)[j] * at_first[used.front()], b = (*l)[used.front()] * at_first[j];
      plain = plain && tolerance_.negligible(a - b, abs(a) + abs(b));
    }
    out.push_back({basis_[j], plain});
  }
  // The first is the measure of the others: plain when they all are.
  if (!out.empty()) out.front().plain = std::all_of(out.begin(), out.end(), [](const Part& p) { return p.plain; });
  return out;
}

}  // namespace tackle

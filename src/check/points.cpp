// The states answers are compared at: the fixed points the model's stated conditions allow,
// the points with the defined parameters' values added, and the signs the conditions rule out.
#include "check/check.hpp"
#include "check/internal.hpp"

#include <algorithm>

#include "algebra/truth.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;
using namespace check_detail;

void Checker::choose_fixed_points(const Analysis& analysis) {
  for (const auto& c : analysis.solution.conditions) {
    if (c.depends_on_free || !c.condition) continue;
    const int sign = Truth::sign_asked(c.condition->op);
    const ex form = substituted(c.expr, definitions_);
    if (sign != 0) conditions_.push_back({form, program(form), sign});
  }
  const auto n = static_cast<std::size_t>(std::max(options_.points, 0));
  for (int k = 0; k < 4 * options_.points && points_.size() < n && !conditions_.empty(); ++k)
    if (Sample p = states_.fixed(k); allowed(p)) points_.push_back(std::move(p));
  if (points_.size() == n) return;
  // Too few states meet the conditions (they fail near the given numbers): every state is
  // compared at.
  conditions_.clear();
  points_.clear();
  for (int k = 0; k < options_.points; ++k) points_.push_back(states_.fixed(k));
}

bool Checker::allowed(const Sample& p) const {
  for (const auto& c : conditions_) {
    const auto v = c.at(p);
    if (!v || !v->is_real()) continue;
    const numeric x = c.sign > 0 ? *v : -*v;
    if (x.is_negative() && !same(x, numeric(0))) return false;
  }
  return true;
}

std::optional<bool> Checker::negative_factor(const ex& e) const {
  if (is_exactly<numeric>(e)) {
    const numeric& x = ex_to<numeric>(e);
    if (!x.is_real() || x.is_zero()) return std::nullopt;
    return x.is_negative();
  }
  if (is_exactly<symbol>(e)) {
    // A parameter (a mass, a length, g: drawn positive), not an angle or a coordinate.
    const SymbolInfo* s = symbols_->find(e);
    const auto& layout = states_.layout();
    for (std::size_t i = 0; i < layout.size(); ++i)
      if (layout[i].first.is_equal(e)) {
        if (!s || s->role != SymbolRole::parameter || states_.angles()[i]) return std::nullopt;
        return false;
      }
    return std::nullopt;
  }
  if (is_exactly<power>(e) && is_exactly<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_rational()) {
    if (ex_to<numeric>(e.op(1)).is_even()) return false;
    return negative_factor(e.op(0));
  }
  if (is_exactly<mul>(e)) {
    bool negative = false;
    for (const auto& f : e) {
      const auto n = negative_factor(f);
      if (!n) return std::nullopt;
      negative = negative != *n;
    }
    return negative;
  }
  return std::nullopt;
}

bool Checker::excluded(const ex& argument, bool negative) const {
  for (const auto& c : conditions_) {
    // argument = ratio * form, ratio of a known sign, and the condition says sign * form >= 0.
    const auto ratio_negative = negative_factor(normal(argument / c.form));
    if (!ratio_negative) continue;
    const bool says_negative = (c.sign < 0) != *ratio_negative;
    if (says_negative != negative) return true;
  }
  return false;
}

void Checker::extend_points() {
  std::vector<std::pair<ex, Program>> defined;
  for (const auto& p : parameters_)
    if (const auto d = definitions_.find(p.symbol); d != definitions_.end())
      defined.emplace_back(p.symbol, program(d->second));
  if (defined.empty()) return;
  std::vector<Sample> out;
  for (const Sample& point : points_) {
    Sample e = point;
    for (const auto& [symbol, at] : defined) {
      const auto v = at(point);
      if (!v) return;  // (no extended points: the diagnosis substitutes)
      e.emplace_back(symbol, *v);
    }
    out.push_back(std::move(e));
  }
  extended_points_ = std::move(out);
  extended_angles_ = states_.angles();
  extended_angles_.resize(extended_points_.front().size(), false);
}

}  // namespace tackle

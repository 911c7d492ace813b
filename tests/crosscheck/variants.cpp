#include "crosscheck/variants.hpp"

#include <algorithm>
#include <cctype>

#include "check/check.hpp"

#include "equations/equations.hpp"
#include "expr/print.hpp"

namespace crosscheck {

using namespace GiNaC;

namespace {

using Rng = std::mt19937_64;
using Eq = Variants::Eq;
using Match = std::function<bool(const ex&)>;
using Change = std::function<ex(const ex&)>;

std::size_t pick(Rng& rng, std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
bool coin(Rng& rng) { return pick(rng, 2) == 0; }

template <class T>
std::optional<T> one_of(Rng& rng, const std::vector<T>& v) {
  if (v.empty()) return std::nullopt;
  return v[pick(rng, v.size())];
}

numeric some_factor(Rng& rng) {
  static const std::vector<numeric> factors{2, 3, -1, -2, numeric(1, 2), numeric(-1, 3), numeric(3, 2), numeric(5, 4)};
  return *one_of(rng, factors);
}

// GiNaC keeps a sum's terms in an order that changes from run to run (its hashes take the
// address its libraries are loaded at): every choice here is made among things put in the
// order of their text, so that a seed makes the same items.
std::vector<ex> by_text(std::vector<ex> v) {
  std::stable_sort(v.begin(), v.end(),
                   [](const ex& a, const ex& b) { return tackle::to_text(a) < tackle::to_text(b); });
  v.erase(std::unique(v.begin(), v.end(), [](const ex& a, const ex& b) { return a.is_equal(b); }), v.end());
  return v;
}

std::vector<ex> terms(const ex& side) {
  if (is_a<add>(side)) {
    std::vector<ex> t(side.begin(), side.end());
    std::stable_sort(t.begin(), t.end(),
                     [](const ex& a, const ex& b) { return tackle::to_text(a) < tackle::to_text(b); });
    return t;
  }
  if (side.is_zero()) return {};
  return {side};
}

ex sum(const std::vector<ex>& ts) {
  ex s = 0;
  for (const auto& t : ts) s += t;
  return s;
}

std::string text(const Eq& e) { return tackle::to_text(e.lhs) + " = " + tackle::to_text(e.rhs); }

bool is_sin(const ex& e) { return is_ex_the_function(e, sin); }
bool is_cos(const ex& e) { return is_ex_the_function(e, cos); }
bool is_trig(const ex& e) { return is_sin(e) || is_cos(e) || is_ex_the_function(e, tan); }

// The distinct subexpressions of `e` that match.
std::vector<ex> matches(const Eq& e, const Match& m) {
  std::vector<ex> out;
  for (const ex* side : {&e.lhs, &e.rhs})
    for (const_preorder_iterator it = side->preorder_begin(); it != side->preorder_end(); ++it)
      if (m(*it)) out.push_back(*it);
  return by_text(out);
}

// The equation with one of its matches, drawn at random, changed wherever it stands (nothing
// when none matches).
std::optional<Eq> change_one(const Eq& e, const Match& m, const Change& by, Rng& rng) {
  const auto found = matches(e, m);
  if (found.empty()) return std::nullopt;
  const ex x = found[pick(rng, found.size())];
  const ex y = by(x);
  return Eq{e.lhs.subs(x == y), e.rhs.subs(x == y)};
}

// One term of either side changed by `by` (nothing for it: left out).
std::optional<Eq> change_term(const Eq& e, Rng& rng, const std::function<std::optional<ex>(const ex&)>& by) {
  std::vector<ex> l = terms(e.lhs), r = terms(e.rhs);
  if (l.empty() && r.empty()) return std::nullopt;
  const std::size_t k = pick(rng, l.size() + r.size());
  std::vector<ex>& side = k < l.size() ? l : r;
  const std::size_t i = k < l.size() ? k : k - l.size();
  if (auto t = by(side[i]))
    side[i] = *t;
  else if (l.size() + r.size() < 2)
    return std::nullopt;  // (not the only term)
  else
    side.erase(side.begin() + static_cast<std::ptrdiff_t>(i));
  return Eq{sum(l), sum(r)};
}

// The angles of the trig functions in `e`, added to `out` (in the order of their text).
void angles_in(const ex& e, std::vector<ex>& out) {
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_trig(*it)) out.push_back(it->op(0));
  out = by_text(out);
}

// Trig rewrites of one sine or cosine (true identities), or of a term (sin^2 + cos^2 = 1).
std::optional<Eq> trig_tan(const Eq& e, Rng& rng) {
  if (coin(rng))
    return change_one(
        e, is_sin, [](const ex& s) { return tan(s.op(0)) * cos(s.op(0)); }, rng);
  return change_one(
      e, is_cos, [](const ex& c) { return sin(c.op(0)) / tan(c.op(0)); }, rng);
}

std::optional<Eq> trig_double(const Eq& e, Rng& rng) {
  if (coin(rng))
    return change_one(
        e, is_sin, [](const ex& s) { return 2 * sin(s.op(0) / 2) * cos(s.op(0) / 2); }, rng);
  return change_one(
      e, is_cos, [](const ex& c) { return pow(cos(c.op(0) / 2), 2) - pow(sin(c.op(0) / 2), 2); }, rng);
}

std::optional<Eq> trig_pythagoras(const Eq& e, const std::vector<ex>& problem_angles, Rng& rng) {
  std::vector<ex> angles;
  angles_in(e.lhs, angles);
  angles_in(e.rhs, angles);
  const auto is_cos_squared = [](const ex& x) { return is_a<power>(x) && is_cos(x.op(0)) && x.op(1).is_equal(2); };
  if (coin(rng) && !matches(e, is_cos_squared).empty())
    return change_one(
        e, is_cos_squared, [](const ex& c) { return 1 - pow(sin(c.op(0).op(0)), 2); }, rng);
  const auto x = one_of(rng, angles.empty() ? problem_angles : angles);
  if (!x) return std::nullopt;
  const ex one = pow(sin(*x), 2) + pow(cos(*x), 2);
  return change_term(e, rng, [&](const ex& t) { return std::optional<ex>(t * one); });
}

std::optional<Eq> sin_for_cos(const Eq& e, Rng& rng) {
  return change_one(
      e, [](const ex& x) { return is_sin(x) || is_cos(x); },
      [](const ex& x) { return is_sin(x) ? cos(x.op(0)) : sin(x.op(0)); }, rng);
}

std::optional<Eq> other_mass(const Eq& e, const std::vector<ex>& masses, Rng& rng) {
  if (masses.size() < 2) return std::nullopt;
  const auto is_mass = [&](const ex& x) {
    return std::any_of(masses.begin(), masses.end(), [&](const ex& m) { return m.is_equal(x); });
  };
  return change_one(
      e, is_mass,
      [&](const ex& m) {
        std::vector<ex> others;
        for (const auto& o : masses)
          if (!o.is_equal(m)) others.push_back(o);
        return *one_of(rng, others);
      },
      rng);
}

Eq scaled(const Eq& e, const ex& by, bool expand) {
  Eq out{e.lhs * by, e.rhs * by};
  if (expand) out = {out.lhs.expand(), out.rhs.expand()};
  return out;
}

// Moved across `=`: everything to one side, the sides swapped, or one term moved.
Eq moved(const Eq& e, Rng& rng) {
  switch (pick(rng, 3)) {
    case 0: return coin(rng) ? Eq{e.lhs - e.rhs, 0} : Eq{0, e.rhs - e.lhs};
    case 1: return Eq{e.rhs, e.lhs};
    default: {
      std::vector<ex> l = terms(e.lhs);
      if (l.empty()) return Eq{e.rhs, e.lhs};
      const std::size_t i = pick(rng, l.size());
      const ex t = l[i];
      l.erase(l.begin() + static_cast<std::ptrdiff_t>(i));
      return Eq{sum(l), e.rhs - t};
    }
  }
}

Variant made(const std::optional<Eq>& e, const std::string& family, bool meant) {
  return {text(*e), family, meant, "", nullptr};
}

}  // namespace

Variants::Variants(const tackle::Analysis& a) : table_(a.model.symbols), const_(symbol("const")) {
  const auto& table = *a.model.symbols;
  for (const auto& e : a.system.equations)
    if (!(e.lhs - e.rhs).expand().is_zero()) {  // (not `0 = 0`)
      balances_.push_back({e.lhs, e.rhs});
      balance_dimensions_.push_back(dimension(e.lhs.is_zero() ? e.rhs : e.lhs));
    }
  for (const auto& e : a.system.rate_equations) rates_.push_back({e.lhs, e.rhs});
  for (const auto& e : a.system.position_equations) positions_.push_back({e.lhs, const_});
  for (const auto& d : a.solution.values) {
    const tackle::SymbolInfo* s = table.find(d.unknown);
    if (!s) continue;
    closed_.emplace_back(d.unknown, d.value);
    closed_names_.push_back(s->name);
  }
  for (const auto& s : table.all()) {
    if (s->geometric && s->definition) roots_[s->sym] = *s->definition;
    if (s->role != tackle::SymbolRole::parameter || s->definition) continue;
    parameters_.push_back(s->sym);
    if (s->dimension && *s->dimension == tackle::Dimension::mass()) masses_.push_back(s->sym);
  }
  add_other_balances(a.model);
  for (const auto& e : balances_) {
    angles_in(e.lhs, angles_);
    angles_in(e.rhs, angles_);
  }
  for (const auto& [u, v] : closed_) angles_in(v, angles_);
}

// Whether a student could type it: within the checker's documented bounds on an answer or an
// equation (tackle::answer_limits(): length and tokens; the tokens counted here as names,
// numbers and single characters, with a margin).
bool typeable(const std::string& text) {
  const tackle::ExprLimits limits = tackle::answer_limits();
  std::size_t tokens = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    ++tokens;
    if (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_' || text[i] == '.')
      while (i < text.size() && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_' || text[i] == '.'))
        ++i;
    else
      ++i;
  }
  return text.size() <= limits.max_length && 5 * tokens <= 4 * limits.max_tokens;
}

void Variants::add_other_balances(const tackle::Model& m) {
  const int n = m.dims();
  const tackle::Vec axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<std::vector<int>> groups;
  for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b) {
    groups.push_back({b});
    if (b > 0) groups.push_back({b - 1, b});  // (a system: its internal forces cancel)
  }
  auto add = [&](const tackle::Equation& e) {
    if (!(e.lhs - e.rhs).expand().is_zero()) others_.push_back({e.lhs, e.rhs});
  };
  for (const auto& g : groups)
    for (int i = 0; i < n; ++i)
      add(tackle::lmb_along(m, g, g.size() > 1, axes[i], m.axes[static_cast<std::size_t>(i)]));
  if (n != 2) return;
  for (int b = 0; b < static_cast<int>(m.bodies.size()); ++b) {
    if (!m.bodies[static_cast<std::size_t>(b)].has_mass) continue;
    add(tackle::amb_along(m, {b}, false, m.bodies[static_cast<std::size_t>(b)].cm, "its center", axes[2], "z"));
    for (const auto& p : m.points)
      if (fixed_point(p.position)) add(tackle::amb_along(m, {b}, false, p.position, p.name, axes[2], "z"));
  }
}

bool Variants::fixed_point(const tackle::Vec& at) const {
  for (const auto& c : at)
    for (const_preorder_iterator it = c.preorder_begin(); it != c.preorder_end(); ++it)
      if (is_a<symbol>(*it))
        if (const auto* s = table_->find(*it); !s || s->role != tackle::SymbolRole::parameter) return false;
  return true;
}

std::optional<Variant> Variants::draw(const std::vector<Family>& families, Rng& rng) {
  if (families.empty()) return std::nullopt;
  for (int tries = 0; tries < 20; ++tries) {
    const Family& f = families[pick(rng, families.size())];
    try {
      if (auto v = f.make(rng); v && typeable(v->text)) return v;
    } catch (const std::exception&) {
      // (GiNaC refused a change: another family)
    }
  }
  return std::nullopt;
}

std::optional<Variant> Variants::equation(Rng& rng) const { return draw(equation_families(), rng); }
std::optional<Variant> Variants::answer(Rng& rng) const { return draw(answer_families(), rng); }

std::optional<Eq> Variants::balance(Rng& rng) const { return one_of(rng, balances_); }

std::optional<tackle::Dimension> Variants::dimension(const ex& e) const {
  std::string problem;
  return tackle::dimension_of(e, *table_, problem);
}

std::optional<ex> Variants::coefficient(const tackle::Dimension& from, const tackle::Dimension& to, Rng& rng) const {
  const tackle::Dimension ratio = to / from;
  std::vector<ex> fitting;
  for (const auto& p : parameters_)
    if (const auto d = dimension(p); d && *d == ratio) fitting.push_back(p);
  if (ratio == tackle::Dimension::none() && (fitting.empty() || coin(rng))) return ex(some_factor(rng));
  const auto p = one_of(rng, fitting);
  if (!p) return std::nullopt;
  return *p * (coin(rng) ? ex(1) : ex(some_factor(rng)));
}

std::optional<Eq> Variants::combined(Rng& rng) const {
  // Two balances or constraints added, the second times a coefficient of the dimension that
  // makes it the first's (a constraint in accelerations times a mass, to a balance of forces).
  if (balances_.size() < 2) return std::nullopt;
  const std::size_t i = pick(rng, balances_.size());
  std::size_t j = pick(rng, balances_.size() - 1);
  if (j >= i) ++j;
  if (!balance_dimensions_[i] || !balance_dimensions_[j]) return std::nullopt;
  const auto c = coefficient(*balance_dimensions_[j], *balance_dimensions_[i], rng);
  if (!c) return std::nullopt;
  Eq e{balances_[i].lhs + *c * balances_[j].lhs, balances_[i].rhs + *c * balances_[j].rhs};
  return coin(rng) ? Eq{e.lhs.expand(), e.rhs.expand()} : e;
}

std::optional<Eq> Variants::substituted(Rng& rng) const {
  auto e = balance(rng);
  if (!e) return std::nullopt;
  std::vector<std::pair<ex, ex>> in;
  for (const auto& [u, v] : closed_)
    if (e->lhs.has(u) || e->rhs.has(u)) in.emplace_back(u, v);
  const auto uv = one_of(rng, in);
  if (!uv) return std::nullopt;
  return Eq{e->lhs.subs(uv->first == uv->second), e->rhs.subs(uv->first == uv->second)};
}

std::optional<Eq> Variants::closed_form(Rng& rng) const {
  const auto uv = one_of(rng, closed_);
  if (!uv) return std::nullopt;
  return coin(rng) ? Eq{uv->first, uv->second} : Eq{uv->second, uv->first};
}

std::optional<Eq> Variants::nonlinear(Rng& rng) const {
  const auto a = one_of(rng, closed_), b = one_of(rng, closed_);
  if (!a || !b) return std::nullopt;
  switch (pick(rng, 3)) {
    case 0: {  // a balance times an unknown
      const auto e = balance(rng);
      return Eq{e->lhs * a->first, e->rhs * a->first};
    }
    case 1:  // a ratio of two unknowns
      if (b->second.is_zero() || a->first.is_equal(b->first)) return std::nullopt;
      return Eq{a->first / b->first, a->second / b->second};
    default:  // a product
      return Eq{a->first * b->first, a->second * b->second};
  }
}

std::optional<Eq> Variants::solved_for_parameter(Rng& rng) const {
  const auto e = balance(rng);
  if (!e) return std::nullopt;
  const ex r = (e->lhs - e->rhs).expand();
  std::vector<ex> linear;
  for (const auto& p : parameters_)
    if (r.has(p) && r.is_polynomial(p) && r.degree(p) == 1 && !r.coeff(p, 0).is_zero()) linear.push_back(p);
  const auto p = one_of(rng, linear);
  if (!p) return std::nullopt;
  return Eq{*p, -r.coeff(*p, 0) / r.coeff(*p, 1)};
}

std::optional<Eq> Variants::length_sum(Rng& rng, bool wrong) const {
  auto e = one_of(rng, positions_);
  if (!e) return std::nullopt;
  if (wrong) {
    e = change_term(*e, rng, [&](const ex& t) { return std::optional<ex>(t * (coin(rng) ? 2 : -1)); });
    if (!e) return std::nullopt;
  } else if (coin(rng)) {
    e = scaled(*e, some_factor(rng), true);
  }
  // (a number for the constant, as checking.md allows, where the sum is in coordinates alone)
  bool parameters = false;
  for (const auto& p : parameters_) parameters = parameters || e->lhs.has(p);
  if (!parameters && coin(rng)) e->rhs = e->rhs.subs(const_ == numeric(static_cast<int>(pick(rng, 9)) + 1));
  return e;
}

std::optional<Eq> Variants::extra_term(Rng& rng) const {
  // A term of another balance of the same dimension (a force that acts on another body).
  const auto e = balance(rng), other = balance(rng);
  if (!e || !other) return std::nullopt;
  const auto d = dimension(e->lhs.is_zero() ? e->rhs : e->lhs);
  std::vector<ex> foreign;
  for (const auto& t : terms(other->lhs))
    if (!e->lhs.has(t) && !e->rhs.has(t) && d && dimension(t) == d) foreign.push_back(t);
  const auto t = one_of(rng, foreign);
  if (!t) return std::nullopt;
  return Eq{e->lhs + *t, e->rhs};
}

std::vector<Variants::Family> Variants::equation_families() const {
  std::vector<Family> f;
  auto add = [&](std::string name, bool meant, std::function<std::optional<Eq>(Rng&)> make) {
    f.push_back({name, meant, [name, meant, make](Rng& rng) -> std::optional<Variant> {
                   const auto e = make(rng);
                   if (!e) return std::nullopt;
                   return made(e, name, meant);
                 }});
  };
  auto on_balance = [this](std::function<std::optional<Eq>(const Eq&, Rng&)> change) {
    return [this, change](Rng& rng) -> std::optional<Eq> {
      const auto e = balance(rng);
      return e ? change(*e, rng) : std::nullopt;
    };
  };
  if (balances_.empty()) return f;
  add("as-derived", true, [this](Rng& rng) { return balance(rng); });
  add("moved", true, on_balance([](const Eq& e, Rng& rng) { return std::optional<Eq>(moved(e, rng)); }));
  add("scaled-number", true,
      on_balance([](const Eq& e, Rng& rng) { return std::optional<Eq>(scaled(e, some_factor(rng), coin(rng))); }));
  add("scaled-parameter", true, on_balance([this](const Eq& e, Rng& rng) {
        const ex p = *one_of(rng, parameters_);
        return std::optional<Eq>(scaled(e, coin(rng) ? p : 1 / p, coin(rng)));
      }));
  add("combined", true, [this](Rng& rng) { return combined(rng); });
  add("trig-tan", true, on_balance(trig_tan));
  add("trig-double", true, on_balance(trig_double));
  add("trig-pythagoras", true, on_balance([this](const Eq& e, Rng& rng) { return trig_pythagoras(e, angles_, rng); }));
  add("substituted", true, [this](Rng& rng) { return substituted(rng); });
  add("closed-form", true, [this](Rng& rng) { return closed_form(rng); });
  add("nonlinear", true, [this](Rng& rng) { return nonlinear(rng); });
  add("solved-for-parameter", true, [this](Rng& rng) { return solved_for_parameter(rng); });
  add("squared", true, on_balance([](const Eq& e, Rng&) {
        return std::optional<Eq>(Eq{pow(e.lhs, 2), pow(e.rhs, 2)});
      }));
  if (!roots_.empty())
    add("roots-written-out", true, [this](Rng& rng) -> std::optional<Eq> {
      const auto e = coin(rng) ? balance(rng) : closed_form(rng);
      if (!e) return std::nullopt;
      const Eq out{e->lhs.subs(roots_), e->rhs.subs(roots_)};
      if (out.lhs.is_equal(e->lhs) && out.rhs.is_equal(e->rhs)) return std::nullopt;
      return out;
    });
  if (!others_.empty()) {
    add("other-balance", true, [this](Rng& rng) -> std::optional<Eq> {
      const auto e = one_of(rng, others_);
      return coin(rng) ? e : Eq{e->lhs - e->rhs, 0};
    });
    add("other-balance-sign", false, [this](Rng& rng) {
      return change_term(*one_of(rng, others_), rng, [](const ex& t) { return std::optional<ex>(-t); });
    });
  }
  if (!rates_.empty()) add("rate", true, [this](Rng& rng) { return one_of(rng, rates_); });
  if (!positions_.empty()) add("length-sum", true, [this](Rng& rng) { return length_sum(rng, false); });
  // meant to be false
  add("sign", false, on_balance([](const Eq& e, Rng& rng) {
        return change_term(e, rng, [](const ex& t) { return std::optional<ex>(-t); });
      }));
  add("missing-term", false, on_balance([](const Eq& e, Rng& rng) {
        return change_term(e, rng, [](const ex&) { return std::optional<ex>(); });
      }));
  add("extra-term", false, [this](Rng& rng) { return extra_term(rng); });
  add("other-mass", false, on_balance([this](const Eq& e, Rng& rng) { return other_mass(e, masses_, rng); }));
  add("factor", false, on_balance([](const Eq& e, Rng& rng) {
        return change_term(e, rng, [&](const ex& t) { return std::optional<ex>(t * (coin(rng) ? 2 : 3)); });
      }));
  add("sin-for-cos", false, on_balance(sin_for_cos));
  add("wrong-closed-form", false, [this](Rng& rng) -> std::optional<Eq> {
    const auto e = closed_form(rng);
    if (!e) return std::nullopt;
    return coin(rng) ? Eq{e->lhs, -e->rhs} : Eq{e->lhs, 2 * e->rhs};
  });
  if (!rates_.empty())
    add("rate-sign", false, [this](Rng& rng) {
      const auto e = one_of(rng, rates_);
      return change_term(*e, rng, [](const ex& t) { return std::optional<ex>(-t); });
    });
  if (!positions_.empty()) {
    add("length-sum-wrong", false, [this](Rng& rng) { return length_sum(rng, true); });
    // a parameter of the problem for the constant: it says what the sum is (`x_A - x_B = b`)
    add("length-sum-parameter", false, [this](Rng& rng) -> std::optional<Eq> {
      std::vector<ex> lengths;
      for (const auto& p : parameters_)
        if (dimension(p) == tackle::Dimension::length()) lengths.push_back(p);
      const auto e = one_of(rng, positions_);
      const auto b = one_of(rng, lengths);
      if (!e || !b) return std::nullopt;
      return Eq{e->lhs, *b};
    });
  }
  return f;
}

std::optional<std::pair<std::size_t, ex>> Variants::closed(Rng& rng) const {
  if (closed_.empty()) return std::nullopt;
  const std::size_t i = pick(rng, closed_.size());
  return std::make_pair(i, closed_[i].second);
}

std::optional<Variant> Variants::answer_of(Rng& rng,
                                           const std::function<std::optional<ex>(const ex&, Rng&)>& change) const {
  const auto c = closed(rng);
  if (!c) return std::nullopt;
  const auto a = change(c->second, rng);
  if (!a) return std::nullopt;
  return Variant{tackle::to_text(*a), "", true, closed_names_[c->first], nullptr};
}

std::vector<Variants::Family> Variants::answer_families() const {
  std::vector<Family> f;
  auto add = [&](std::string name, bool meant, std::function<std::optional<ex>(const ex&, Rng&)> change) {
    f.push_back({name, meant, [this, name, meant, change](Rng& rng) -> std::optional<Variant> {
                   auto v = answer_of(rng, change);
                   if (!v) return std::nullopt;
                   v->family = name;
                   v->meant = meant;
                   return v;
                 }});
  };
  // An answer rewritten as one side of an equation: the equation families' rewrites.
  auto as_side = [](std::function<std::optional<Eq>(const Eq&, Rng&)> change) {
    return [change](const ex& v, Rng& rng) -> std::optional<ex> {
      const auto e = change(Eq{v, 0}, rng);
      if (!e) return std::nullopt;
      return e->lhs - e->rhs;
    };
  };
  if (closed_.empty()) return f;
  add("as-solved", true, [](const ex& v, Rng&) { return std::optional<ex>(v); });
  add("expanded", true, [](const ex& v, Rng&) { return std::optional<ex>(v.expand()); });
  add("over-a-parameter", true, [this](const ex& v, Rng& rng) {
    const ex p = *one_of(rng, parameters_);
    const ex nd = v.numer_denom();
    return std::optional<ex>((p * nd.op(0)).expand() / (p * nd.op(1)).expand());
  });
  add("trig-tan", true, as_side(trig_tan));
  add("trig-double", true, as_side(trig_double));
  add("trig-pythagoras", true, as_side([this](const Eq& e, Rng& rng) { return trig_pythagoras(e, angles_, rng); }));
  if (!roots_.empty())
    add("roots-written-out", true, [this](const ex& v, Rng&) -> std::optional<ex> {
      const ex out = v.subs(roots_);
      return out.is_equal(v) ? std::nullopt : std::optional<ex>(out);
    });
  add("sign", false, [](const ex& v, Rng&) { return std::optional<ex>(-v); });
  add("term-sign", false, [](const ex& v, Rng& rng) -> std::optional<ex> {
    const ex nd = v.numer_denom();
    const auto e = change_term(Eq{nd.op(0).expand(), 0}, rng, [](const ex& t) { return std::optional<ex>(-t); });
    if (!e) return std::nullopt;
    return (e->lhs - e->rhs) / nd.op(1);
  });
  add("missing-term", false, [](const ex& v, Rng& rng) -> std::optional<ex> {
    const ex nd = v.numer_denom();
    const auto e = change_term(Eq{nd.op(0).expand(), 0}, rng, [](const ex&) { return std::optional<ex>(); });
    if (!e) return std::nullopt;
    return (e->lhs - e->rhs) / nd.op(1);
  });
  add("factor", false, [](const ex& v, Rng& rng) { return std::optional<ex>(v * some_factor(rng)); });
  add("other-mass", false, as_side([this](const Eq& e, Rng& rng) { return other_mass(e, masses_, rng); }));
  add("sin-for-cos", false, as_side(sin_for_cos));
  return f;
}

}  // namespace crosscheck

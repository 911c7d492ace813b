#include "solve/eliminate.hpp"

#include "expr/fraction.hpp"
#include "expr/pairs.hpp"
#include "expr/trig.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace tackle {

using namespace GiNaC;

namespace {

// The number of nodes of an expression: the pivot of fewest nodes among equally sparse
// candidates keeps the entries small. Counted, not printed, and the same in every run.
std::size_t nodes(const ex& e) { return is_a<numeric>(e) ? 0 : node_count(e); }

using Row = std::map<std::size_t, ex>;

// An entry in normal form, and exactly 0 when it is zero (also by sin^2 + cos^2 = 1). A
// polynomial with rational coefficients (most entries: m_1 + m_2, 1, -k) is only expanded:
// normal() would look for a denominator to cancel against. A sum of fractions over products
// of symbols and irreducible sums (a cascade's entries, over products of masses) is put over
// their factors without a gcd (expr/fraction.hpp); anything else goes to normal().
ex reduced(const ex& x) {
  if (rational_polynomial(x)) return x.expand();
  if (const auto q = normal_by_factors(x)) return *q;
  const ex n = normal(x);
  if (!n.is_zero() && has_trig(n) && normal(pythagoras(n, true)).is_zero()) return 0;
  return n;
}

// One elimination step's bookkeeping: rows as maps, and for each column the active rows
// that hold it.
struct Work {
  std::vector<Row> a;
  std::vector<ex> b;
  std::vector<Row> t;                          // tracking: original row -> coefficient
  std::vector<std::set<std::size_t>> rows_of;  // column -> active rows with a nonzero entry
  std::vector<bool> active;
  bool track = false;

  // row k -= f * row r, in A, b and the tracking, with f = a[k][pivot] / a[r][pivot];
  // entries that cancel are removed. The entry in the pivot's column cancels by the choice of
  // f: it is removed without being computed (a chain's is a sum of up to 256 masses). f is
  // made only when needed: with a number for pivot, a polynomial a[k][pivot] times a number
  // v of row r is a[k][pivot] times v / pivot, one product where f * v takes two.
  void subtract(std::size_t k, std::size_t r, std::size_t pivot_column) {
    const ex a_kc = a[k].at(pivot_column), pivot = a[r].at(pivot_column);
    std::optional<ex> f_made;
    auto f = [&]() -> const ex& {
      if (!f_made) f_made = reduced(a_kc / pivot);
      return *f_made;
    };
    const bool scaled = is_exactly<numeric>(pivot) && rational_polynomial(a_kc);
    auto minus_f_times = [&](const ex& v) -> ex {
      if (scaled && is_exactly<numeric>(v)) return a_kc * (-ex_to<numeric>(v) / ex_to<numeric>(pivot));
      return -f() * v;
    };
    for (const auto& [c, v] : a[r]) {
      auto it = a[k].find(c);
      if (c == pivot_column) {
        if (it != a[k].end()) a[k].erase(it);
        rows_of[c].erase(k);
        continue;
      }
      const ex n = reduced(it == a[k].end() ? minus_f_times(v) : it->second + minus_f_times(v));
      if (n.is_zero()) {
        if (it != a[k].end()) a[k].erase(it);
        rows_of[c].erase(k);
      } else {
        a[k][c] = n;
        rows_of[c].insert(k);
      }
    }
    if (!b[r].is_zero()) b[k] = reduced(b[k] + minus_f_times(b[r]));
    if (track)
      for (const auto& [c, v] : t[r]) {
        auto it = t[k].find(c);
        const ex n = reduced(it == t[k].end() ? minus_f_times(v) : it->second + minus_f_times(v));
        if (n.is_zero()) {
          if (it != t[k].end()) t[k].erase(it);
        } else {
          t[k][c] = n;
        }
      }
  }
};

struct Pivot {
  std::size_t row, column;
};

std::optional<Pivot> choose(const Work& w, const std::vector<bool>& eliminated, Pivoting pivoting) {
  if (pivoting == Pivoting::in_column_order) {
    for (std::size_t c = 0; c < w.rows_of.size(); ++c) {
      if (eliminated[c] || w.rows_of[c].empty()) continue;
      std::optional<Pivot> best;
      std::tuple<std::size_t, std::size_t> best_key{};
      for (const std::size_t r : w.rows_of[c]) {
        const std::tuple<std::size_t, std::size_t> key{w.a[r].size(), nodes(w.a[r].at(c))};
        if (!best || key < best_key) {
          best = Pivot{r, c};
          best_key = key;
        }
      }
      return best;
    }
    return std::nullopt;
  }
  // Markowitz: the smallest (other entries in the row) x (other entries in the column),
  // then the entry of fewest nodes, then the first row and column.
  std::size_t best_count = std::numeric_limits<std::size_t>::max();
  std::vector<Pivot> tied;
  for (std::size_t r = 0; r < w.a.size(); ++r) {
    if (!w.active[r]) continue;
    for (const auto& [c, v] : w.a[r]) {
      const std::size_t count = (w.a[r].size() - 1) * (w.rows_of[c].size() - 1);
      if (count < best_count) {
        best_count = count;
        tied.clear();
      }
      if (count == best_count) tied.push_back({r, c});
    }
  }
  if (tied.empty()) return std::nullopt;
  std::optional<Pivot> best;
  std::size_t best_nodes = 0;
  for (const Pivot& p : tied) {
    const std::size_t n = nodes(w.a[p.row].at(p.column));
    if (!best || n < best_nodes) {
      best = p;
      best_nodes = n;
    }
  }
  return best;
}

// A polynomial in symbols with rational coefficients (what divide() takes): no functions,
// no roots, no floating-point numbers.
bool is_polynomial_form(const ex& e) { return rational_polynomial(e); }

// The irreducible factors of a denominator (each to the first power), and its numeric
// coefficient; nothing when some factor is not known to be irreducible.
std::optional<std::pair<numeric, std::vector<ex>>> irreducible_factors(const ex& den) {
  numeric c = 1;
  std::vector<ex> out;
  auto one = [&](const ex& f) {
    if (is_a<numeric>(f)) {
      c *= ex_to<numeric>(f);
      return true;
    }
    if (is_a<symbol>(f) || linear_irreducible(f)) {
      out.push_back(f);
      return true;
    }
    return false;
  };
  if (is_a<mul>(den)) {
    for (std::size_t i = 0; i < den.nops(); ++i)
      if (!one(den.op(i))) return std::nullopt;
  } else if (!one(den)) {
    return std::nullopt;
  }
  return std::make_pair(c, out);
}

// monomial * sum, expanded; or as a product when it is a monomial times a long primitive
// sum (see content_of_product), the form simplest() factors it into: a chain's tensions
// F*(m_2 + ... + m_256), whose expansion (F*m_2 + ... + F*m_256) simplest() took F out of
// again, a sixth of solving a chain of 256.
ex numerator_of(const ex& monomial, const ex& sum) {
  if (is_exactly<add>(sum) && sum.nops() > factor_term_limit) {
    const Content c = content_of(sum);
    const ex p = times(monomial * c.content, c.rest);
    if (content_of_product(p, factor_term_limit)) return p;
  }
  const ex p = monomial * sum;
  return expanded_polynomial(p) ? p : p.expand();
}

// (b - sum of v x) / pivot in normal form without a gcd, in the common case of a chain or a
// cascade: b and each v polynomials, the pivot a number or a product of irreducible
// polynomials, and every x a polynomial or a fraction whose denominator is such a product
// (factors of degree 1 in some symbol with coprime coefficients, or symbols). The rest is
// put over the product of the distinct factors of the x's denominators; the pivot's factors
// join them; each factor that divides the numerator is divided out, and what is left is
// reduced, its factors being irreducible. Nothing otherwise.
std::optional<ex> quick_quotient(const ex& b, const std::vector<std::pair<ex, ex>>& terms, const ex& pivot) {
  if (!is_polynomial_form(b)) return std::nullopt;
  auto holds = [](const std::vector<ex>& v, const ex& g) {
    return std::any_of(v.begin(), v.end(), [&](const ex& h) { return h.is_equal(g); });
  };
  std::vector<ex> common;  // the distinct factors of the x's denominators
  struct Part {
    ex numerator;             // -v times x's numerator, over x's numeric coefficient
    std::vector<ex> factors;  // x's denominator's factors
  };
  std::vector<Part> parts;
  for (const auto& [v, x] : terms) {
    if (!is_polynomial_form(v)) return std::nullopt;
    const ex nd = numer_denom_of_normal(x);
    if (!is_polynomial_form(nd.op(0)) || !is_polynomial_form(nd.op(1))) return std::nullopt;
    const auto f = irreducible_factors(nd.op(1));
    if (!f) return std::nullopt;
    for (const ex& g : f->second)
      if (!holds(common, g)) common.push_back(g);
    parts.push_back({times(f->first == 1 ? ex(-v) : -v / f->first, nd.op(0)), f->second});
  }
  numeric c = 1;
  std::vector<ex> pivot_factors;
  if (is_a<numeric>(pivot)) {
    c = ex_to<numeric>(pivot);
  } else {
    if (!is_polynomial_form(pivot)) return std::nullopt;
    const auto f = irreducible_factors(pivot);
    if (!f) return std::nullopt;
    c = f->first;
    pivot_factors = f->second;
  }
  // All polynomial with a number for pivot: normal() has no gcd to compute either.
  if (common.empty() && pivot_factors.empty()) return std::nullopt;
  if (common.size() + pivot_factors.size() > 8) return std::nullopt;
  auto over_common = [&](ex e, const std::vector<ex>& have) {
    for (const ex& g : common)
      if (!holds(have, g)) e = times(e, g);
    return e;
  };
  std::vector<ex> pieces{over_common(b, {})};  // the numerator is their sum
  for (const auto& p : parts) pieces.push_back(over_common(p.numerator, p.factors));
  // A monomial held by every piece (a chain's F: each tension is F times a sum of masses) is
  // kept out of the expansion: the numerator is that monomial times the rest expanded, and
  // stays so when the rest is a long sum (see content_of_product), as simplest() would
  // factor it. Otherwise the numerator is expanded whole.
  const ex shared = common_monomial(pieces);
  ex monomial = shared / c, num = 0;
  for (const ex& p : pieces) num += p;
  num = (num / shared).expand();
  if (num.is_zero()) return ex(0);
  std::vector<ex> den = common;
  den.insert(den.end(), pivot_factors.begin(), pivot_factors.end());
  ex kept = 1;  // the factors that do not divide the numerator
  for (const ex& g : den) {
    ex q;
    if (is_exactly<symbol>(g) && monomial.degree(g) > 0)
      monomial /= g;
    else if (may_divide(num, g) && divide(num, g, q))
      num = q.expand();
    else
      kept *= g;
  }
  num = numerator_of(monomial, num);
  // Made without evaluating where GiNaC's evaluation would leave it as it is (a chain's
  // values over m_1 + ... + m_256: the sum's integer content, taken at each evaluation).
  const auto held = evaluated_quotient(num, kept);
  const ex out = with_shared_numbers(held ? *held : num / kept);
  remember_normal(out, out);
  return out;
}

// The elimination with symbolic tracking when asked; also the pivots in their order.
std::pair<Elimination, std::vector<Pivot>> eliminate_symbolically(const SparseSystem& s, const std::vector<ex>& symbols,
                                                                  Pivoting pivoting, bool track) {
  Work w;
  w.a = s.a;
  w.b = s.b;
  w.track = track;
  const std::size_t n_rows = s.a.size();
  w.active.assign(n_rows, true);
  w.rows_of.resize(s.columns);
  if (track) {
    w.t.resize(n_rows);
    for (std::size_t i = 0; i < n_rows; ++i) w.t[i][i] = 1;
  }
  for (std::size_t i = 0; i < n_rows; ++i)
    for (const auto& [c, v] : w.a[i]) w.rows_of[c].insert(i);

  std::vector<bool> eliminated(s.columns, false);
  std::vector<Pivot> order;
  while (const auto p = choose(w, eliminated, pivoting)) {
    const std::size_t r = p->row, c = p->column;
    w.active[r] = false;
    for (const auto& [cc, v] : w.a[r]) w.rows_of[cc].erase(r);
    const std::vector<std::size_t> others(w.rows_of[c].begin(), w.rows_of[c].end());
    for (const std::size_t k : others) w.subtract(k, r, c);
    eliminated[c] = true;
    order.push_back(*p);
  }

  Elimination out;
  out.rank = order.size();
  out.pivot = eliminated;
  out.value.assign(s.columns, ex(0));
  // Back substitution, last pivot first: a pivot row holds its pivot, the columns pivoted
  // after it and free columns.
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    std::vector<std::pair<ex, ex>> terms;  // coefficient, value
    for (const auto& [cc, v] : w.a[it->row])
      if (cc != it->column) terms.emplace_back(v, eliminated[cc] ? out.value[cc] : symbols[cc]);
    const ex& pivot = w.a[it->row].at(it->column);
    if (const auto q = quick_quotient(w.b[it->row], terms, pivot)) {
      out.value[it->column] = *q;
      continue;
    }
    ex rest = w.b[it->row];
    for (const auto& [v, x] : terms) rest -= v * x;
    if (const auto q = normal_by_factors(rest / pivot)) {
      const ex v = with_shared_numbers(*q);
      remember_normal(v, v);
      out.value[it->column] = v;
      continue;
    }
    out.value[it->column] = normal_remembered(rest / pivot);
  }
  for (std::size_t i = 0; i < n_rows; ++i) {
    if (!w.active[i]) continue;
    Elimination::Leftover l;
    l.row = i;
    l.rhs = w.b[i];
    if (track)
      for (const auto& [row, coefficient] : w.t[i]) l.combination.push_back(row);
    out.leftover.push_back(std::move(l));
  }
  return {std::move(out), std::move(order)};
}

// The pivots replayed in exact numbers at random points of integers, keeping track of the
// original rows each row combines: for each row left over, those rows. Nothing when an entry
// is not a rational function of symbols; a point where a pivot or an entry's denominator is
// zero is drawn again (five draws at most).
std::optional<std::vector<std::vector<std::size_t>>> replayed_combinations(const SparseSystem& s,
                                                                           const std::vector<Pivot>& order,
                                                                           const std::vector<std::size_t>& leftover) {
  const std::size_t n_rows = s.a.size();
  lst entries;
  for (const auto& row : s.a)
    for (const auto& [c, v] : row) entries.append(v);
  std::mt19937 rng(20261124);
  for (int draw = 0; draw < 5; ++draw) {
    RationalPoint point;
    for (const auto& [sym, v] : random_point(entries, rng)) point.emplace(sym, ex_to<numeric>(v));
    using NumRow = std::map<std::size_t, numeric>;
    std::vector<NumRow> a(n_rows), t(n_rows);
    bool usable = true;
    for (std::size_t i = 0; i < n_rows && usable; ++i) {
      t[i][i] = 1;
      for (const auto& [c, v] : s.a[i]) {
        const RationalAt r = rational_at(v, point);
        if (r.kind == RationalAt::Kind::other) return std::nullopt;
        if (r.kind == RationalAt::Kind::pole) {
          usable = false;
          break;
        }
        if (!r.value.is_zero()) a[i][c] = r.value;
      }
    }
    if (!usable) continue;
    std::vector<bool> active(n_rows, true);
    auto minus = [](NumRow& into, const numeric& f, const NumRow& from) {
      for (const auto& [c, v] : from) {
        const numeric x = into[c] - f * v;
        if (x.is_zero())
          into.erase(c);
        else
          into[c] = x;
      }
    };
    for (const Pivot& p : order) {
      active[p.row] = false;
      const auto at = a[p.row].find(p.column);
      if (at == a[p.row].end()) {
        usable = false;  // the pivot is zero at this point
        break;
      }
      const numeric pivot = at->second;
      for (std::size_t k = 0; k < n_rows; ++k) {
        if (!active[k]) continue;
        const auto it = a[k].find(p.column);
        if (it == a[k].end()) continue;
        const numeric f = it->second / pivot;
        minus(a[k], f, a[p.row]);
        minus(t[k], f, t[p.row]);
      }
    }
    if (!usable) continue;
    std::vector<std::vector<std::size_t>> out;
    for (const std::size_t l : leftover) {
      std::vector<std::size_t> rows;
      for (const auto& [row, coefficient] : t[l]) rows.push_back(row);
      out.push_back(std::move(rows));
    }
    return out;
  }
  return std::nullopt;
}

}  // namespace

Elimination eliminate(const SparseSystem& s, const std::vector<ex>& symbols, Pivoting pivoting, bool track) {
  auto [out, order] = eliminate_symbolically(s, symbols, pivoting, false);
  if (!track || out.leftover.empty()) return out;
  std::vector<std::size_t> rows;
  for (const auto& l : out.leftover) rows.push_back(l.row);
  if (const auto combinations = replayed_combinations(s, order, rows)) {
    for (std::size_t i = 0; i < rows.size(); ++i) out.leftover[i].combination = (*combinations)[i];
    return out;
  }
  return eliminate_symbolically(s, symbols, pivoting, true).first;
}

}  // namespace tackle

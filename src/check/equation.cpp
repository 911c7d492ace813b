#include "check/equation.hpp"

#include <algorithm>
#include <set>

#include "core/utf8.hpp"
#include "expr/pairs.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "core/units.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// Larger families are not decided (each rank is a symbolic elimination).
constexpr std::size_t max_family = 40;

// The rank of the matrix whose columns are `columns` (and `extra`, when given), exactly.
std::size_t rank_of(const std::vector<std::vector<ex>>& columns, const std::vector<ex>* extra) {
  const std::size_t rows = extra ? extra->size() : columns.front().size();
  const std::size_t n = columns.size() + (extra ? 1 : 0);
  matrix a(rows, n);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < columns.size(); ++j) a(i, j) = columns[j][i];
    if (extra) a(i, columns.size()) = (*extra)[i];
  }
  return a.rank();
}


// The balance as a student names it: "the LMB of A (x)".
std::string balance_name(const Equation& e) { return e.label; }

// The problem's names, and a constant a length sum keeps (`const`, `C`, `C_s`, `L`, `L_1`) where
// the problem has no such name: a symbol of its own, made once per name.
class WithConstants : public NameResolver {
 public:
  explicit WithConstants(const NameResolver& base) : base_(base) {}
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto e = base_.resolve(name)) return e;
    const bool constant = name == "const" || name == "C" || name == "L" ||
                          ((name.rfind("C_", 0) == 0 || name.rfind("L_", 0) == 0) && name.size() > 2);
    if (!constant) return std::nullopt;
    for (const auto& [n, s] : made_)
      if (n == name) return s;
    // Written upright in LaTeX when it is the word const.
    made_.emplace_back(std::string(name), name == "const" ? symbol("const", "\\mathrm{const}") : symbol(std::string(name)));
    return made_.back().second;
  }
  std::vector<std::string> known_names() const override { return base_.known_names(); }
  [[nodiscard]] std::vector<ex> constants() const {
    std::vector<ex> out;
    for (const auto& [n, s] : made_) out.push_back(s);
    return out;
  }

 private:
  const NameResolver& base_;
  mutable std::vector<std::pair<std::string, ex>> made_;
};

}  // namespace

// The source of a term as a student reads it: "a strand of string s at pA", "the weight of A",
// "the force on A".
std::string force_phrase(const std::string& source) {
  const auto colon = source.find(": strand ");
  const auto at = source.rfind(" at ");
  if (colon != std::string::npos && at != std::string::npos && at > colon) {
    const std::string element = source.substr(0, colon), point = source.substr(at + 4);
    if (element.rfind("string ", 0) == 0) return "a strand of " + element + " at " + point;
    return "the force of " + element + " at " + point;
  }
  if (source.rfind("gravity on ", 0) == 0) return "the weight of " + source.substr(11);
  if (source.rfind("force ", 0) == 0) return "the " + source;
  if (source.rfind("sliding at ", 0) == 0) return "the force of the sliding contact at " + source.substr(11);
  return "the force of the " + source;
}


EquationChecker::EquationChecker(const Analysis& analysis, const CheckOptions& options)
    : options_(options),
      symbols_(analysis.model.symbols),
      definitions_(analysis.model.symbols->definitions()),
      equations_(analysis.system.equations),
      rate_equations_(analysis.system.rate_equations) {
  auto family = [&](const std::vector<Equation>& eqs, SymbolRole role, Family& f) {
    std::set<ex, ex_is_less> seen;
    for (const auto& e : eqs) f.equations.push_back(&e);
    for (const auto& s : symbols_->all()) {
      const bool wanted = role == SymbolRole::acceleration
                              ? (s->role == SymbolRole::acceleration || s->role == SymbolRole::unknown)
                              : s->role == SymbolRole::rate;
      if (!wanted) continue;
      for (const auto& e : eqs)
        if ((e.lhs - e.rhs).has(s->sym) && seen.insert(s->sym).second) {
          f.unknowns.push_back(s->sym);
          break;
        }
    }
    for (const auto& e : eqs) {
      const auto v = vector_of(substituted(e.lhs - e.rhs, definitions_), f);
      // (An equation not linear in the unknowns is no column: none is, at these levels.)
      f.vectors.push_back(v ? *v : std::vector<ex>(f.unknowns.size() + 1, 0));
    }
  };
  for (const auto& b : analysis.model.bodies) bodies_.push_back({b.name, b.has_mass ? b.mass : ex(0), b.accel});
  // The point: each parameter at its own small rational (the same in every run).
  {
    int k = 0;
    static const int primes[] = {3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73};
    for (const auto& s : symbols_->all())
      if (s->role == SymbolRole::parameter) {
        const int p = primes[k % 20], q = primes[(k * 7 + 3) % 20] + k / 20;
        point_[s->sym] = numeric(p, q == p ? q + 1 : q);
        ++k;
      }
  }
  family(equations_, SymbolRole::acceleration, acceleration_);
  family(rate_equations_, SymbolRole::rate, rate_);
  // The length sums: every coordinate is a column (one that no sum holds must not be taken for
  // the constant), and the constant is no column.
  for (const auto& c : analysis.system.constraints) {
    const bool named = c.meaning.size() >= c.label.size() && c.meaning.compare(c.meaning.size() - c.label.size(), c.label.size(), c.label) == 0;
    Equation e;
    e.kind = Equation::Kind::constraint_position;
    e.label = named ? c.meaning : c.label + ": " + c.meaning;
    e.lhs = c.quantity;
    e.rhs = 0;
    e.terms = {c.quantity};
    e.sources = {"the " + c.meaning};
    position_equations_.push_back(e);
    position_differentiated_.push_back(c.label + ": acceleration");
  }
  for (const auto& e : position_equations_) position_.equations.push_back(&e);
  for (const auto& s : symbols_->all())
    if (s->role == SymbolRole::coordinate) position_.unknowns.push_back(s->sym);
  for (const auto& e : position_equations_) {
    auto v = vector_of(substituted(e.lhs, definitions_), position_);
    if (v) v->back() = 0;
    position_.vectors.push_back(v ? *v : std::vector<ex>(position_.unknowns.size() + 1, 0));
  }
}

const EquationChecker::Family& EquationChecker::prepared(const Family& f) const {
  std::call_once(f.made, [&] { prepare(f); });
  return f;
}

void EquationChecker::prepare(const Family& f) const {
  if (f.vectors.empty() || f.equations.size() > max_family) return;
  // The equations' own rank (every check compares its rank with the student's added).
  f.rank = rank_of(f.vectors, nullptr);
  // The vectors y with y . column = 0 for every column: the solutions of F^T y = 0, one per
  // free variable of GiNaC's solution (that one 1, the others 0). Checked against the rank.
  const std::size_t m = f.vectors.front().size(), k = f.vectors.size();
  try {
    matrix ft(static_cast<unsigned>(k), static_cast<unsigned>(m)), vars(static_cast<unsigned>(m), 1), zero(static_cast<unsigned>(k), 1);
    std::vector<symbol> y;
    for (std::size_t i = 0; i < m; ++i) {
      y.emplace_back("y" + std::to_string(i));
      vars(static_cast<unsigned>(i), 0) = y.back();
    }
    for (std::size_t j = 0; j < k; ++j)
      for (std::size_t i = 0; i < m; ++i) ft(static_cast<unsigned>(j), static_cast<unsigned>(i)) = f.vectors[j][i];
    const matrix sol = ft.solve(vars, zero);
    std::vector<std::size_t> free;
    for (std::size_t i = 0; i < m; ++i)
      if (sol(static_cast<unsigned>(i), 0).is_equal(y[i])) free.push_back(i);
    if (f.rank && free.size() == m - *f.rank) {
      std::vector<std::vector<ex>> basis;
      for (const std::size_t i : free) {
        exmap pick;
        for (const std::size_t j : free) pick[y[j]] = j == i ? 1 : 0;
        std::vector<ex> b;
        for (std::size_t r = 0; r < m; ++r) b.push_back(normal(sol(static_cast<unsigned>(r), 0).subs(pick)));
        // Scaled by its denominators' lcm: polynomial entries, so that a product with a
        // polynomial vector is decided by expanding it.
        ex scale = 1;
        for (const ex& x : b) scale = lcm(scale, x.denom());
        for (ex& x : b) x = normal(x * scale).expand();
        basis.push_back(std::move(b));
      }
      for (const auto& b : basis) f.orthogonal_at.push_back(at_point(b));
      f.orthogonal = std::move(basis);
    }
  } catch (const std::exception&) {
    // No basis: the rank decides, as before.
  }
  auto at = [&](const std::optional<std::vector<ex>>& v) { return v ? at_point(*v) : std::nullopt; };
  for (std::size_t i = 0; i < f.equations.size(); ++i) {
    const Equation* e = f.equations[i];
    std::vector<std::optional<std::vector<ex>>> terms;
    std::vector<std::optional<std::vector<numeric>>> terms_at;
    for (const ex& t : e->terms) {
      terms.push_back(vector_of(substituted(t, definitions_), f));
      terms_at.push_back(at(terms.back()));
    }
    f.term_vectors.push_back(std::move(terms));
    f.term_vectors_at.push_back(std::move(terms_at));
    f.lhs_vectors.push_back(vector_of(substituted(e->lhs, definitions_), f));
    f.lhs_vectors_at.push_back(at(f.lhs_vectors.back()));
    f.vectors_at.push_back(at_point(f.vectors[i]));
  }
}

std::optional<std::vector<numeric>> EquationChecker::at_point(const std::vector<ex>& v) const {
  std::vector<numeric> out;
  out.reserve(v.size());
  try {
    for (const ex& x : v) {
      const ex y = x.subs(point_);
      if (!is_a<numeric>(y) || !ex_to<numeric>(y).is_rational()) return std::nullopt;
      out.push_back(ex_to<numeric>(y));
    }
  } catch (const std::exception&) {
    return std::nullopt;  // a pole at the point
  }
  return out;
}

bool EquationChecker::in_family(const Family& f, const std::vector<ex>& v) const {
  if (!f.orthogonal) return in_span(f.vectors, v, f.rank);
  // Refuted at the point when a product is not zero there; else each product normalised.
  if (const auto vp = at_point(v))
    for (const auto& y : f.orthogonal_at)
      if (y) {
        numeric dot = 0;
        for (std::size_t i = 0; i < vp->size(); ++i) dot += (*y)[i] * (*vp)[i];
        if (!dot.is_zero()) return false;
      }
  const bool polynomial = std::all_of(v.begin(), v.end(), [](const ex& x) { return rational_polynomial(x); });
  for (const auto& y : *f.orthogonal) {
    ex dot = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (!y[i].is_zero() && !v[i].is_zero()) dot += y[i] * v[i];
    // Polynomials: zero exactly when the expansion is; else normalised.
    if (polynomial ? !dot.expand().is_zero() : !normal(dot).is_zero()) return false;
  }
  return true;
}

std::string EquationChecker::differentiated(const std::string& label) const {
  for (std::size_t i = 0; i < position_equations_.size(); ++i)
    if (position_equations_[i].label == label) return position_differentiated_[i];
  return {};
}

std::optional<std::vector<ex>> EquationChecker::vector_of(const ex& residual, const Family& f) const {
  const ex e = residual.expand();
  std::vector<ex> v;
  exmap zero;
  for (const ex& u : f.unknowns) zero[u] = 0;
  for (const ex& u : f.unknowns) {
    if (e.degree(u) > 1 || e.ldegree(u) < 0) return std::nullopt;
    const ex c = e.coeff(u, 1);
    for (const ex& w : f.unknowns)
      if (c.has(w)) return std::nullopt;  // a product of two unknowns
    v.push_back(c);
  }
  const ex rest = e.subs(zero);
  // Every unknown must appear linearly: what is left must be free of them, and the parts
  // must make the whole (abs(T) has no part linear in T).
  for (const ex& w : f.unknowns)
    if (rest.has(w)) return std::nullopt;
  ex whole = rest;
  for (std::size_t i = 0; i < f.unknowns.size(); ++i) whole += v[i] * f.unknowns[i];
  if (!(e - whole).expand().is_zero()) return std::nullopt;
  v.push_back(rest);
  return v;
}

namespace {

// Whether two vectors at the point may be proportional: false when a 2x2 minor is not zero.
bool may_be_proportional(const std::vector<numeric>& a, const std::vector<numeric>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      if (!(a[i] * b[j] - a[j] * b[i]).is_zero()) return false;
  return true;
}

}  // namespace

bool EquationChecker::proportional(const std::vector<ex>& a, const std::vector<ex>& b, const std::optional<std::vector<numeric>>* ap_given,
                                   const std::optional<std::vector<numeric>>* bp_given) const {
  // Every 2x2 minor zero, and neither is zero.
  bool a_zero = true, b_zero = true;
  for (std::size_t i = 0; i < a.size(); ++i) {
    a_zero = a_zero && a[i].is_zero();
    b_zero = b_zero && b[i].is_zero();
  }
  if (a_zero || b_zero) return false;
  // A minor not zero at the point: not proportional.
  const std::optional<std::vector<numeric>> ap = ap_given ? *ap_given : at_point(a);
  if (ap) {
    const std::optional<std::vector<numeric>> bp = bp_given ? *bp_given : at_point(b);
    if (bp && !may_be_proportional(*ap, *bp)) return false;
  }
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j)
      if (!normal(a[i] * b[j] - a[j] * b[i]).is_zero()) return false;
  return true;
}

bool EquationChecker::in_span(const std::vector<std::vector<ex>>& columns, const std::vector<ex>& v,
                              std::optional<std::size_t> rank) const {
  if (columns.empty()) return std::all_of(v.begin(), v.end(), [](const ex& x) { return x.is_zero(); });
  return (rank ? *rank : rank_of(columns, nullptr)) == rank_of(columns, &v);
}

CheckResult EquationChecker::check(std::string_view text) const {
  CheckResult r;
  r.equation = true;
  auto finish = [&](Verdict v, std::string code, std::string message) { return r.conclude(v, std::move(code), std::move(message)); };
  if (text.size() > options_.limits.max_length)
    return finish(Verdict::invalid, "too_large", "the equation is too long (" + std::to_string(text.size()) +
                                                     " characters; at most " + std::to_string(options_.limits.max_length) + ")");
  if (const auto bad = invalid_utf8_at(text))
    return finish(Verdict::invalid, "syntax", "at column " + std::to_string(*bad + 1) + ": the equation is not valid UTF-8 text");
  // One '=' at the top: "lhs = rhs".
  std::vector<std::size_t> equals;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '=') equals.push_back(i);
  const bool relation = std::any_of(equals.begin(), equals.end(), [&](std::size_t i) {
    return (i > 0 && (text[i - 1] == '<' || text[i - 1] == '>' || text[i - 1] == '!')) || (i + 1 < text.size() && text[i + 1] == '=');
  });
  if (equals.size() != 1 || relation)
    return finish(Verdict::invalid, "not_an_equation",
                  equals.empty() ? "this is not an equation (expected one '=' between two sides, e.g. 2*T - F = m_A*ddot(x_A))"
                                 : "write one '=' between the two sides (found " + std::to_string(equals.size()) + ")");
  const std::size_t eq = equals.front();
  const std::string_view sides[2] = {text.substr(0, eq), text.substr(eq + 1)};
  ex side[2];
  const WithConstants names(*symbols_);
  for (int k = 0; k < 2; ++k) {
    if (sides[k].find_first_not_of(" \t") == std::string_view::npos)
      return finish(Verdict::invalid, "not_an_equation", std::string(k == 0 ? "the left" : "the right") + " side is empty");
    const ParseResult parsed = parse_expression(sides[k], names, options_.limits);
    if (!parsed.value) {
      const ParseProblem& p = parsed.problems.front();
      const bool limit = p.message.find("too ") != std::string::npos || p.message.find("at most") != std::string::npos;
      return finish(Verdict::invalid, limit ? "too_large" : "syntax",
                    "at column " + std::to_string(p.column + 1 + (k == 0 ? 0 : static_cast<int>(eq) + 1)) + ": " + p.message);
    }
    if (is_vector(*parsed.value)) return finish(Verdict::invalid, "syntax", "a side is a vector; write one component at a time");
    side[k] = *parsed.value;
  }
  r.echo_text = to_text(side[0]) + " = " + to_text(side[1]);
  if (options_.echo_latex) r.echo_latex = to_latex(side[0]) + " = " + to_latex(side[1]);
  // Dimensions: each side consistent, and the same on both.
  std::optional<Dimension> dim[2];
  for (int k = 0; k < 2; ++k) {
    std::string problem;
    dim[k] = dimension_of(side[k], *symbols_, problem);
    if (!dim[k] && !problem.empty())
      return finish(Verdict::incorrect, "dimension", std::string(k == 0 ? "the left" : "the right") +
                                                         " side is dimensionally inconsistent: it " + problem);
  }
  const bool zero_side = side[0].is_zero() || side[1].is_zero();
  if (dim[0] && dim[1] && !(*dim[0] == *dim[1]) && !zero_side)
    return finish(Verdict::incorrect, "dimension", "the left side is " + with_article(dim[0]->describe()) + " and the right side " +
                                                       with_article(dim[1]->describe()));
  const ex unexpanded = substituted(side[0] - side[1], definitions_);
  if (expanded_size(unexpanded) > static_cast<double>(options_.exact_size_budget))
    return finish(Verdict::undecided, "too_large", "the equation expands into too many terms to be checked (at most " +
                                                       std::to_string(options_.exact_size_budget) + ")");
  const ex residual = unexpanded.expand();
  if (residual.is_zero())
    return finish(Verdict::incorrect, "trivial", "the equation holds whatever the forces and the motion are (it reads 0 = 0 once simplified): it says nothing about this problem");
  // Which level: the rates' equations when it has rates and no accelerations or forces; the
  // length sums' when it has neither, only coordinates (and a constant).
  bool has_acceleration = false, has_rate = false, has_coordinate = false;
  for (const ex& u : acceleration_.unknowns) has_acceleration = has_acceleration || residual.has(u);
  for (const ex& u : rate_.unknowns) has_rate = has_rate || residual.has(u);
  for (const ex& u : position_.unknowns) has_coordinate = has_coordinate || residual.has(u);
  const std::vector<ex> constants = names.constants();
  if (!constants.empty() && (has_acceleration || has_rate || !has_coordinate))
    return finish(Verdict::invalid, "syntax", "'" + to_text(constants.front()) +
                                                  "' is not a name of this problem: a constant is for a length sum, an equation in the positions alone");
  if (has_coordinate && !has_acceleration && !has_rate && !position_.equations.empty()) return check_position(residual, r);
  const Family& f = prepared(has_rate && !has_acceleration ? rate_ : acceleration_);
  if (f.equations.size() > max_family)
    return finish(Verdict::undecided, "too_large", "this problem has too many equations to decide a combination of them (" +
                                                       std::to_string(f.equations.size()) + ")");
  const auto v = vector_of(residual, f);
  if (!v)
    return finish(Verdict::incorrect, "not_linear",
                  "the equation is not linear in the unknowns (forces and accelerations), as every balance and constraint of this problem is");
  if (in_family(f, *v)) {
    r.verdict = Verdict::correct;
    r.score = 1.0;
    r.method = "exact";
    const auto v_at = at_point(*v);
    for (std::size_t i = 0; i < f.vectors.size(); ++i)
      if (proportional(f.vectors[i], *v, i < f.vectors_at.size() ? &f.vectors_at[i] : nullptr, &v_at))
        r.identified_as.push_back(f.equations[i]->label);
    if (!r.identified_as.empty()) {
      r.follows_from = {r.identified_as.front()};
      r.combination = {{r.identified_as.front(), true}};
      r.summary = "it is " + r.identified_as.front();
      return r;
    }
    r.follows_from = fewest(f, *v);
    r.summary = "it follows from " + (r.follows_from.size() == 1 ? r.follows_from.front()
                                                   : join(std::vector<std::string>(r.follows_from.begin(), r.follows_from.end() - 1)) +
                                                         " and " + r.follows_from.back());
    return r;
  }
  r.method = "exact";
  diagnose(f, *v, r);
  // A force missing or turned is more specific than the inertial term (N_A + N_B = 0 is the
  // vertical balance without the weight, and also the horizontal one without m a).
  const auto rank = [](const Finding& x) { return x.code == "missing_inertia" || x.code == "inertia_sign" ? 1 : 0; };
  std::stable_sort(r.findings.begin(), r.findings.end(), [&](const Finding& a, const Finding& b) { return rank(a) < rank(b); });
  if (r.findings.empty())
    r.findings.push_back({"value", "the equation does not follow from the balances and constraints of this problem"});
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  r.summary = r.findings.front().message;
  return r;
}

CheckResult EquationChecker::check_position(const ex& residual, CheckResult r) const {
  const Family& f = prepared(position_);
  if (f.equations.size() > max_family)
    return r.conclude(Verdict::undecided, "too_large", "this problem has too many constraints to decide a combination of them (" +
                                                           std::to_string(f.equations.size()) + ")");
  auto v = vector_of(residual, f);
  if (!v) return r.conclude(Verdict::incorrect, "not_linear", "the equation is not linear in the positions, as every length sum of this problem is");
  // What is left is the constant the sum keeps: any constant will do (it depends on where the
  // positions are measured from and on the string's length).
  v->back() = 0;
  r.method = "exact";
  if (in_family(f, *v)) {
    r.verdict = Verdict::correct;
    r.score = 1.0;
    const auto v_at = at_point(*v);
    for (std::size_t i = 0; i < f.vectors.size(); ++i)
      if (proportional(f.vectors[i], *v, i < f.vectors_at.size() ? &f.vectors_at[i] : nullptr, &v_at))
        r.identified_as.push_back(f.equations[i]->label);
    r.follows_from = r.identified_as.empty() ? fewest(f, *v) : std::vector<std::string>{r.identified_as.front()};
    r.summary = r.identified_as.empty() ? "it follows from " + join(r.follows_from) : "it is the " + r.identified_as.front() + " kept constant";
    if (r.identified_as.empty() && r.follows_from.size() > 1)
      r.summary = "it follows from " + join(std::vector<std::string>(r.follows_from.begin(), r.follows_from.end() - 1)) + " and " + r.follows_from.back();
    return r;
  }
  // The constraint whose positions these are, where there is one: its sum is not this one.
  std::vector<const Equation*> sharing;
  for (std::size_t i = 0; i < f.vectors.size(); ++i) {
    bool inside = true, shares = false;
    for (std::size_t j = 0; j + 1 < v->size(); ++j) {
      if ((*v)[j].is_zero()) continue;
      if (f.vectors[i][j].is_zero()) inside = false;
      else shares = true;
    }
    if (inside && shares) sharing.push_back(f.equations[i]);
  }
  if (sharing.size() == 1) {
    const std::string& what = sharing.front()->label;
    r.findings.push_back({"length_sum", "this is not the " + what + " kept constant" +
                                            (what.rfind("length of string", 0) == 0 ? ": count the strands at each point the string passes" : "")});
  } else {
    r.findings.push_back({"value", "the equation does not follow from the constraints of this problem"});
  }
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  r.summary = r.findings.front().message;
  return r;
}

std::vector<std::string> EquationChecker::fewest(const Family& f, const std::vector<ex>& v) const {
  // Independent equations combine in one way only: its coefficients, solved for at the point,
  // name the equations (a coefficient zero there is left out, and the rest confirmed exactly).
  if (f.rank && *f.rank == f.vectors.size() && f.vectors_at.size() == f.vectors.size() &&
      std::all_of(f.vectors_at.begin(), f.vectors_at.end(), [](const auto& x) { return x.has_value(); })) {
    if (const auto v_at = at_point(v)) {
      const unsigned rows = static_cast<unsigned>(v.size()), k = static_cast<unsigned>(f.vectors.size());
      matrix a(rows, k), rhs(rows, 1), vars(k, 1);
      std::vector<symbol> c;
      for (unsigned j = 0; j < k; ++j) {
        c.emplace_back("c" + std::to_string(j));
        vars(j, 0) = c.back();
        for (unsigned i = 0; i < rows; ++i) a(i, j) = (*f.vectors_at[j])[i];
      }
      for (unsigned i = 0; i < rows; ++i) rhs(i, 0) = (*v_at)[i];
      try {
        const matrix sol = a.solve(vars, rhs);
        std::vector<std::size_t> support;
        std::vector<std::vector<ex>> columns;
        for (unsigned j = 0; j < k; ++j)
          if (!sol(j, 0).is_zero()) {
            support.push_back(j);
            columns.push_back(f.vectors[j]);
          }
        if (!support.empty() && in_span(columns, v)) {
          std::vector<std::string> out;
          for (const std::size_t j : support) out.push_back(f.equations[j]->label);
          return out;
        }
      } catch (const std::exception&) {
        // Not solvable at the point: the way below.
      }
    }
  }
  // All the equations that say something, then each left out while the rest still give it.
  std::vector<std::size_t> used;
  for (std::size_t i = 0; i < f.vectors.size(); ++i)
    if (std::any_of(f.vectors[i].begin(), f.vectors[i].end(), [](const ex& x) { return !x.is_zero(); })) used.push_back(i);
  for (std::size_t k = used.size(); k-- > 0;) {
    std::vector<std::vector<ex>> rest;
    for (const std::size_t j : used)
      if (j != used[k]) rest.push_back(f.vectors[j]);
    if (in_span(rest, v)) used.erase(used.begin() + static_cast<std::ptrdiff_t>(k));
  }
  std::vector<std::string> out;
  for (const std::size_t j : used) out.push_back(f.equations[j]->label);
  return out;
}

std::vector<std::string> EquationChecker::needed_for(const ex& unknown, const ex& closed_form) const {
  if (acceleration_.equations.size() > max_family) return {};
  (void)prepared(acceleration_);
  const auto v = vector_of(substituted(unknown - closed_form, definitions_), acceleration_);
  if (!v || !in_family(acceleration_, *v)) return {};
  return fewest(acceleration_, *v);
}

const Equation* EquationChecker::equation(const std::string& label) const {
  for (const auto& e : equations_)
    if (e.label == label) return &e;
  for (const auto& e : position_equations_)
    if (e.label == label) return &e;
  for (const auto& e : rate_equations_)
    if (e.label == label) return &e;
  return nullptr;
}

void EquationChecker::diagnose(const Family& f, const std::vector<ex>& v, CheckResult& r) const {
  std::set<std::string> said;
  auto say = [&](const std::string& code, const std::string& message) {
    if (said.insert(message).second) r.findings.push_back({code, message});
  };
  auto matches = [&](const ex& candidate) {
    const auto w = vector_of(substituted(candidate, definitions_), f);
    return w && proportional(*w, v);
  };
  // A candidate made from the family's own vectors: a x + b y (none when one is not linear).
  using Vector = std::optional<std::vector<ex>>;
  auto combined = [](const Vector& x, const ex& a, const Vector& y, const ex& b) -> Vector {
    if (!x || !y) return std::nullopt;
    std::vector<ex> out(x->size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = (a * (*x)[i] + b * (*y)[i]).expand();
    return out;
  };
  const std::optional<std::vector<numeric>> v_at = at_point(v);
  auto matches_vector = [&](const Vector& w) { return w && proportional(*w, v, nullptr, &v_at); };
  // The same, refuted first at the point from the parts' values there (no expression made).
  using Values = std::optional<std::vector<numeric>>;
  auto may_match = [&](const Values& x, const numeric& a, const Values& y, const numeric& b) {
    if (!x || !y || !v_at) return true;
    std::vector<numeric> c(x->size());
    for (std::size_t i = 0; i < c.size(); ++i) c[i] = a * (*x)[i] + b * (*y)[i];
    return may_be_proportional(c, *v_at);
  };
  static const Values none;
  // Every term of every balance, for a force that acts on another body.
  for (std::size_t ei = 0; ei < f.equations.size(); ++ei) {
    const Equation* e = f.equations[ei];
    if (e->kind != Equation::Kind::lmb && e->kind != Equation::Kind::amb) continue;
    const ex whole = e->lhs - e->rhs;
    const Vector whole_vector = f.vectors[ei];
    const bool made = ei < f.term_vectors.size();  // the terms' vectors made once
    const Values& whole_at = made ? f.vectors_at[ei] : none;
    for (std::size_t j = 0; j < e->terms.size() && j < e->sources.size(); ++j) {
      const std::string what = force_phrase(e->sources[j]);
      const Vector term = made ? f.term_vectors[ei][j] : vector_of(substituted(e->terms[j], definitions_), f);
      const Values& term_at = made ? f.term_vectors_at[ei][j] : none;
      if (may_match(whole_at, 1, term_at, -1) && matches_vector(combined(whole_vector, 1, term, -1)))
        say("missing_force", what + " is missing (" + balance_name(*e) + ")");
      else if (may_match(whole_at, 1, term_at, -2) && matches_vector(combined(whole_vector, 1, term, -2)))
        say("force_sign", what + " has the wrong sign or direction (" + balance_name(*e) + ")");
    }
    const Vector lhs_vector = made ? f.lhs_vectors[ei] : vector_of(substituted(e->lhs, definitions_), f);
    const Values& lhs_at = made ? f.lhs_vectors_at[ei] : none;
    if (!e->rhs.is_zero() && may_match(lhs_at, 1, lhs_at, 0) && matches_vector(lhs_vector))
      say("missing_inertia", e->kind == Equation::Kind::lmb ? "the mass times acceleration term is missing (" + balance_name(*e) + ")"
                                                            : "the rate of change of angular momentum is missing (" + balance_name(*e) + ")");
    // Another body's mass, or another body's acceleration, in the balance of one body.
    if (e->kind == Equation::Kind::lmb && !e->system && e->bodies.size() == 1 && !e->rhs.is_zero()) {
      const BodyTerms& own = bodies_[static_cast<std::size_t>(e->bodies.front())];
      for (const BodyTerms& other : bodies_) {
        if (&other == &own) continue;
        if (!own.mass.is_zero() && !other.mass.is_zero() && !other.mass.is_equal(own.mass) &&
            matches(e->lhs - e->rhs.subs(own.mass == other.mass)))
          say("wrong_mass", "the mass is " + other.name + "'s, not " + own.name + "'s (" + balance_name(*e) + ")");
        if (is_a<symbol>(own.accel) && is_a<symbol>(other.accel) && !other.accel.is_equal(own.accel) &&
            matches(e->lhs - e->rhs.subs(own.accel == other.accel)))
          say("wrong_acceleration", "the acceleration is " + other.name + "'s, not " + own.name + "'s (" + balance_name(*e) + ")");
      }
    }
    if (!e->rhs.is_zero() && may_match(lhs_at, 2, whole_at, -1) && matches_vector(combined(lhs_vector, 2, whole_vector, -1)))
      say("inertia_sign", e->kind == Equation::Kind::lmb ? "the mass times acceleration term has the wrong sign (" + balance_name(*e) + ")"
                                                         : "the rate of change of angular momentum has the wrong sign (" + balance_name(*e) + ")");
    // A force from another balance added: it acts on another body.
    for (std::size_t oi = 0; oi < f.equations.size(); ++oi) {
      const Equation* other = f.equations[oi];
      if (other == e || other->kind != e->kind) continue;
      for (std::size_t j = 0; j < other->terms.size() && j < other->sources.size(); ++j) {
        const bool own = std::find(e->sources.begin(), e->sources.end(), other->sources[j]) != e->sources.end();
        if (own) continue;
        const bool other_made = made && oi < f.term_vectors.size();
        const Vector term = other_made ? f.term_vectors[oi][j] : vector_of(substituted(other->terms[j], definitions_), f);
        const Values& term_at = other_made ? f.term_vectors_at[oi][j] : none;
        for (const int sign : {1, -1}) {
          const ex added = sign * other->terms[j];
          if (!may_match(whole_at, 1, term_at, sign) || !matches_vector(combined(whole_vector, 1, term, sign))) continue;
          // Taking away one of the balance's own forces is a force missing (said above); the
          // same force as one of its own is one counted once too often (a strand more); else
          // a force on another body.
          std::string again;
          bool removal = false;
          for (std::size_t i = 0; i < e->terms.size() && i < e->sources.size(); ++i) {
            removal = removal || (e->terms[i] + added).is_zero();
            if (again.empty() && (e->terms[i] - added).is_zero()) again = force_phrase(e->sources[i]);
          }
          if (removal) continue;
          if (!again.empty()) say("extra_force", "one force too many: " + again + " is counted once too often (" + balance_name(*e) + ")");
          else say("extra_force", force_phrase(other->sources[j]) + " does not act on what " + balance_name(*e) + " balances");
        }
      }
    }
  }
}

}  // namespace tackle

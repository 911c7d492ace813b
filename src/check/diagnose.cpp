// Diagnosing a wrong answer in terms a student can act on: a sign, a factor, another unknown's
// value, sin for cos, two parameters swapped, a special case, one term's sign, a term missing
// or too many, the parameters it has or lacks.
#include "check/check.hpp"
#include "check/internal.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <set>

#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;
using namespace check_detail;

namespace {

// "twice", "half", "3 times", "2/3 of"
std::string factor_words(const numeric& c) {
  if (c == 2) return "twice the correct answer";
  if (c == numeric(1, 2)) return "half the correct answer";
  if (c == -1) return "the correct answer with the wrong sign";
  return to_text(c) + " times the correct answer";
}

// A float as the simple fraction it is within 10^-9 (a denominator up to 12), if it is one.
std::optional<numeric> simple_fraction(const numeric& c) {
  if (c.is_rational()) return c;
  if (!c.is_real() || std::abs(c.to_double()) >= 1e12)
    return std::nullopt;  // (a larger one does not fit a long: fuzzing)
  const double x = c.to_double();
  for (int den = 1; den <= 12; ++den)
    if (std::abs(x * den - std::round(x * den)) < 1e-9 * std::max(1.0, std::abs(x * den)))
      return numeric(static_cast<long>(std::round(x * den)), den);
  return std::nullopt;
}

// A rational function as c times powers of factors that are pairwise coprime: symbols, and
// polynomials made primitive (integer content 1, first term positive) that are irreducible
// because they are of degree one in some symbol with a number before it (l - 2 mu h, in l).
// Two such factors are coprime unless equal, so a quotient of two of these, its exponents
// subtracted, is in lowest terms without a gcd. Nothing when a factor is none of these.
struct Factored {
  numeric coefficient = 1;
  std::map<ex, int, ex_is_less> powers;
  bool put(const ex& e, int times);
  bool add_polynomial(const ex& p, int times);
};

bool Factored::add_polynomial(const ex& p, int times) {
  if (is_exactly<numeric>(p)) {
    if (p.is_zero()) return false;
    coefficient *= ex_to<numeric>(p).power(times);
    return true;
  }
  if (!is_exactly<add>(p)) return put(p, times);  // a monomial
  const numeric content = p.integer_content();
  ex primitive = (p / content).expand();
  numeric c = content;
  // The first term's coefficient positive (the sum's terms are in GiNaC's canonical order).
  const ex first = primitive.op(0);
  const ex lead = is_exactly<mul>(first) ? first.op(first.nops() - 1) : first;
  if (is_exactly<numeric>(lead) && ex_to<numeric>(lead).is_negative()) {
    primitive = (-primitive).expand();
    c = -c;
  }
  // Irreducible: of degree one in a symbol, with a number before it.
  bool irreducible = false;
  for (const ex& x : symbols_in(primitive)) {
    if (primitive.degree(x) == 1 && is_exactly<numeric>(primitive.coeff(x, 1))) {
      irreducible = true;
      break;
    }
  }
  if (!irreducible) return false;
  coefficient *= c.power(times);
  powers[primitive] += times;
  return true;
}

bool Factored::put(const ex& e, int times) {
  if (is_exactly<numeric>(e)) {
    if (e.is_zero() || !ex_to<numeric>(e).is_rational()) return false;
    coefficient *= ex_to<numeric>(e).power(times);
    return true;
  }
  if (is_exactly<symbol>(e)) {
    powers[e] += times;
    return true;
  }
  if (is_exactly<power>(e)) {
    if (!is_exactly<numeric>(e.op(1)) || !ex_to<numeric>(e.op(1)).is_integer()) return false;
    const numeric k = ex_to<numeric>(e.op(1));
    if (!k.is_pos_integer() && !(-k).is_pos_integer()) return false;
    if (abs(k) > 16) return false;
    return put(e.op(0), times * static_cast<int>(k.to_long()));
  }
  if (is_exactly<mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!put(e.op(i), times)) return false;
    return true;
  }
  if (is_exactly<add>(e)) {
    const auto [n, d] = as_fraction(e);
    return add_polynomial(n.expand(), times) && add_polynomial(d.expand(), -times);
  }
  return false;
}

// sin written for cos and cos for sin, everywhere (a map, not subs() with patterns: a tenth of
// the cost).
struct SinCosSwapped : map_function {
  ex operator()(const ex& e) override {
    if (is_ex_the_function(e, sin)) return cos((*this)(e.op(0)));
    if (is_ex_the_function(e, cos)) return sin((*this)(e.op(0)));
    return e.map(*this);
  }
};

// A changed point's doubles: those of the point it was changed from, each changed value
// made anew (a rational's double is dear: a screen makes one or two).
std::vector<double> doubles_from(const Sample& changed, const Sample& from, const std::vector<double>& from_doubles) {
  std::vector<double> out = from_doubles;
  for (std::size_t i = 0; i < changed.size() && i < out.size(); ++i)
    if (!changed[i].second.is_equal(from[i].second))
      out[i] = changed[i].second.is_real() ? changed[i].second.to_double() : std::nan("");
  return out;
}

// Can a and b be the same value? A screen in doubles before the exact comparison: a difference
// past 10^-6 of the size is no rounding (NaN, a value doubles cannot say, passes).
bool maybe_same(double a, const numeric& b) {
  if (std::isnan(a) || !b.is_real()) return true;
  const double y = b.to_double();
  if (!std::isfinite(a) || !std::isfinite(y)) return true;
  const double scale = std::max(std::fabs(a), std::fabs(y));
  return scale < 1e-9 || std::fabs(a - y) <= 1e-6 * scale;
}

}  // namespace

const Checker::Reference::Diagnosis& Checker::diagnosis(const Reference& ref) const {
  std::call_once(ref.lazy->made, [&] {
    Reference::Diagnosis& d = ref.lazy->diagnosis;
    d.expanded = ref.shape.expanded ? *ref.shape.expanded : ref.closed_form.expand();
    d.needed = symbols_in(ref.closed_form);
    if (Factored f; ref.shape.rational && f.put(ref.closed_form, 1)) d.factored.emplace(f.coefficient, f.powers);
    auto at_points = [&](const Program& e, const std::function<void(Sample&)>& change) {
      std::vector<std::optional<numeric>> out;
      for (Sample p : points_) {
        change(p);
        out.push_back(e(p));
      }
      return out;
    };
    const auto keep = [](Sample&) {};
    for (std::size_t i = 0; !points_.empty() && i < points_[0].size(); ++i) {
      Sample p = points_[0];
      p[i].second *= 2;
      d.doubled.push_back(ref.program(p));
    }
    if (is_a<add>(d.expanded) && d.expanded.nops() <= 12)
      for (std::size_t i = 0; i < d.expanded.nops(); ++i) {
        d.term_turned.push_back(at_points(program(d.expanded - 2 * d.expanded.op(i)), keep));
        d.term_left_out.push_back(at_points(program(d.expanded - d.expanded.op(i)), keep));
      }
    auto set = [](Sample& p, const ex& s, const std::function<numeric(const Sample&)>& value) {
      const numeric v = value(p);
      for (auto& [sym, x] : p)
        if (sym.is_equal(s)) x = v;
    };
    auto value_of = [](const Sample& p, const ex& s) {
      for (const auto& [sym, x] : p)
        if (sym.is_equal(s)) return std::optional<numeric>(x);
      return std::optional<numeric>();
    };
    for (std::size_t i = 0; i < parameters_.size(); ++i) {
      const ex& p = parameters_[i].symbol;
      if (!ref.closed_form.has(p)) continue;
      d.zeroed[i] = at_points(ref.program, [&](Sample& pt) { set(pt, p, [](const Sample&) { return numeric(0); }); });
    }
    for (std::size_t i = 0; i < parameters_.size() && i < 16; ++i)
      for (std::size_t j = i + 1; j < parameters_.size() && j < 16; ++j) {
        const auto& a = parameters_[i];
        const auto& b = parameters_[j];
        if (!(a.dimension == b.dimension) || !ref.closed_form.has(a.symbol) || !ref.closed_form.has(b.symbol)) continue;
        // (An angle's input is its half-angle's tangent: equal to another's value it is not the same.)
        const auto angle = [&](const ex& x) {
          return std::any_of(states_.inputs().begin(), states_.inputs().end(),
                             [&](const StateInput& in) { return in.angle && in.symbol.is_equal(x); });
        };
        if (angle(a.symbol) || angle(b.symbol)) continue;
        d.equalled[{i, j}] = at_points(ref.program, [&](Sample& pt) {
          if (const auto x = value_of(pt, a.symbol); x && value_of(pt, b.symbol))
            set(pt, b.symbol, [&](const Sample&) { return *x; });
        });
      }
  });
  return ref.lazy->diagnosis;
}

std::optional<Checker::QuotientShape> Checker::quotient_shape(const Reference& ref, const Program& answer_at,
                                                              const std::vector<numeric>& values) const {
  // At the first point, each parameter doubled in turn: the quotient changes by 2^e for a
  // power p^e of it, and not at all when it does not depend on it. Exact rationals, or floats
  // compared within the tolerance (a root in the closed form: sample 12.8's rod length).
  const Reference::Diagnosis& diag = diagnosis(ref);
  if (values.empty() || ref.at_points.empty() || ref.at_points[0].is_zero() || values[0].is_zero() ||
      diag.doubled.size() != points_[0].size())
    return std::nullopt;
  static const std::vector<std::pair<int, numeric>> powers_of_two{
      {1, 2}, {-1, numeric(1, 2)}, {2, 4},  {-2, numeric(1, 4)},
      {3, 8}, {-3, numeric(1, 8)}, {4, 16}, {-4, numeric(1, 16)}};
  const Sample& p0 = points_[0];
  const numeric q0 = values[0] / ref.at_points[0];
  QuotientShape shape;
  std::vector<int> exponents(p0.size(), 0);
  bool powers = true;
  // (The quotients in doubles where they can be: a screen for the exponents, which are
  // confirmed exactly at every point below; exact where doubles cannot say.)
  const std::vector<double>& d0 = point_doubles_[0];
  const double q0d = q0.to_double();
  for (std::size_t i = 0; i < p0.size(); ++i) {
    const auto& b = diag.doubled[i];
    if (!b || b->is_zero()) return std::nullopt;
    std::vector<double> di = d0;
    di[i] *= 2;
    const double rd = answer_at.approx(di) / b->to_double() / q0d;
    if (std::isfinite(rd) && std::fabs(rd) > 1e-300) {
      const auto near = [&](double x) { return std::fabs(rd - x) <= 1e-9 * std::fabs(x); };
      if (near(1)) continue;
      ++shape.depends_on;
      for (const auto& [e, two] : powers_of_two)
        if (near(two.to_double())) exponents[i] = e;
      powers = powers && exponents[i] != 0;
      if (!powers && shape.depends_on > 2) return shape;  // neither kind of simple factor
      continue;
    }
    Sample p = p0;
    p[i].second *= 2;
    const auto a = answer_at(p);
    if (!a) return std::nullopt;
    const numeric r = *a / *b / q0;
    if (same(r, 1)) continue;
    ++shape.depends_on;
    for (const auto& [e, two] : powers_of_two)
      if (same(r, two)) exponents[i] = e;
    powers = powers && exponents[i] != 0;
    if (!powers && shape.depends_on > 2) return shape;  // neither kind of simple factor
  }
  if (!powers) return shape;
  // c times the powers, checked at every point.
  const auto at = [&](const Sample& p) {
    numeric v = 1;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (exponents[i] != 0) v *= p[i].second.power(exponents[i]);
    return v;
  };
  numeric c = q0 / at(p0);
  for (std::size_t k = 1; k < values.size() && k < points_.size(); ++k)
    if (ref.at_points[k].is_zero() || !same(values[k] / ref.at_points[k], c * at(points_[k]))) return shape;
  if (!c.is_rational()) {
    // A float: the simple fraction it is (a denominator up to 12), or no monomial to say.
    const auto simple = simple_fraction(c);
    if (!simple) return shape;
    c = *simple;
  }
  ex monomial = c;
  for (std::size_t i = 0; i < p0.size(); ++i)
    if (exponents[i] != 0) monomial *= GiNaC::pow(p0[i].first, exponents[i]);
  shape.monomial = monomial;
  return shape;
}

// The steps of a wrong answer's diagnosis (see diagnose()), and what they share: the answer
// with the definitions put in, its symbols as typed and as put in, its values at the points.
struct Checker::Diagnosing {
  const Checker& c;
  const Reference& ref;
  const ex& answer;                    // as typed
  const Program& answer_at;            // the answer over the points
  const std::vector<numeric>& values;  // the answer at the fixed points
  CheckResult& r;
  std::size_t n = 0;  // the points with both values
  const Reference::Diagnosis* diag = nullptr;
  ex expanded;  // the answer with the definitions put in
  std::set<ex, ex_is_less> typed_symbols, used;
  std::vector<ex> params;  // the parameters' symbols, in the problem's order

  Diagnosing(const Checker& checker, const Reference& reference, const ex& typed, const Program& typed_at,
             const std::vector<numeric>& at_points, CheckResult& result)
      : c(checker),
        ref(reference),
        answer(typed),
        answer_at(typed_at),
        values(at_points),
        r(result),
        n(std::min(at_points.size(), reference.at_points.size())) {}
  void found(std::string code, std::string message) { r.findings.push_back({std::move(code), std::move(message)}); }
  bool found_any(std::initializer_list<const char*> codes) const {
    return std::any_of(r.findings.begin(), r.findings.end(), [&](const Finding& f) {
      return std::any_of(codes.begin(), codes.end(), [&](const char* code) { return f.code == code; });
    });
  }
  bool constant_ratio();
  void prepare();
  bool matches_at(const std::function<void(Sample&)>& change,
                  const std::vector<std::optional<numeric>>& reference) const;
  bool equals_at_points(const std::vector<std::optional<numeric>>& other) const;
  void other_unknown();
  void trig_swapped();
  std::vector<Finding> factor() const;
  void swapped_parameters();
  bool swapped_in_extended_points(std::size_t i, std::size_t j, std::optional<Program>& raw_at) const;
  bool swapped_in_expression(std::size_t i, std::size_t j) const;
  void special_cases();
  void terms();
  void extra_term();
  void parameters_used();
};

namespace {

// The value of the symbol `s` in the point `p`, or null.
numeric* value_in(Sample& p, const ex& s) {
  for (auto& [sym, v] : p)
    if (sym.is_equal(s)) return &v;
  return nullptr;
}

}  // namespace

void Checker::diagnose(const Reference& ref, const ex& answer, const Program& answer_at,
                       const std::vector<numeric>& values, CheckResult& r) const {
  Diagnosing d(*this, ref, answer, answer_at, values, r);
  // The sign or a constant factor says it all; else, most specific first: another unknown's
  // value, sin for cos, swapped parameters, special cases, one term, then the factor in the
  // parameters and the parameters the answer has or lacks.
  if (d.constant_ratio()) return;
  d.prepare();
  d.other_unknown();
  d.trig_swapped();
  const std::vector<Finding> factor_findings = d.factor();
  d.swapped_parameters();
  d.special_cases();
  d.terms();
  d.extra_term();
  r.findings.insert(r.findings.end(), factor_findings.begin(), factor_findings.end());
  d.parameters_used();
}

// The sign, or a constant factor (exact when the ratio simplifies to a number): found, and
// nothing else is said.
bool Checker::Diagnosing::constant_ratio() {
  bool constant = n > 0;
  std::optional<numeric> ratio;
  for (std::size_t k = 0; k < n && constant; ++k) {
    if (ref.at_points[k].is_zero()) return false;
    const numeric q = values[k] / ref.at_points[k];
    if (!ratio)
      ratio = q;
    else
      constant = c.same(q, *ratio);
  }
  if (!constant || !ratio) return false;
  // Exact when the values are; else the ratio rounded to a simple fraction.
  numeric k = *ratio;
  if (!k.is_rational())
    if (const auto simple = simple_fraction(k)) k = *simple;
  // Still irrational: a square root of a simple fraction (sqrt(3), sqrt(3)/2), said exactly.
  if (!k.is_rational() && std::abs(k.to_double()) < 1e6) {
    const double x2 = k.to_double() * k.to_double();
    for (int den = 1; den <= 12; ++den)
      if (std::abs(x2 * den - std::round(x2 * den)) < 1e-9 * std::max(1.0, x2 * den)) {
        const ex root = (k.is_positive() ? 1 : -1) * sqrt(ex(numeric(static_cast<long>(std::round(x2 * den)), den)));
        found("factor", "off by a factor of " + to_text(root) + " (the answer is " + to_text(root) +
                            " times the correct answer)");
        return true;
      }
  }
  if (k == -1)
    found("sign", "the sign is wrong");
  else
    found("factor", "off by a factor of " + to_text(k) + " (the answer is " + factor_words(k) + ")");
  return true;
}

// What the steps past the ratio share: the reference's part (made once), the answer with the
// definitions put in and its symbols (has() walks the expression for each question: a
// diagnosis asks dozens).
void Checker::Diagnosing::prepare() {
  diag = &c.diagnosis(ref);
  expanded = substituted(answer, c.definitions_);
  typed_symbols = symbols_in(answer);
  used = symbols_in(expanded);
  for (const auto& p : c.parameters_) params.push_back(p.symbol);
}

// Does the answer, at the points changed by `change`, take the reference's values `reference`
// (at the same points changed as the diagnosis says)? Swapping two parameters or setting one
// to zero changes the point, not the expression.
bool Checker::Diagnosing::matches_at(const std::function<void(Sample&)>& change,
                                     const std::vector<std::optional<numeric>>& reference) const {
  if (!c.points_.empty() && !reference.empty() && reference[0]) {  // most fail here, in doubles
    Sample first = c.points_[0];
    change(first);
    if (!maybe_same(answer_at.approx(doubles_from(first, c.points_[0], c.point_doubles_[0])), *reference[0]))
      return false;
  }
  for (std::size_t k = 0; k < c.points_.size(); ++k) {
    Sample pa = c.points_[k];
    change(pa);
    const auto a = answer_at(pa);
    if (!a || k >= reference.size() || !reference[k] || !c.same(*a, *reference[k])) return false;
  }
  return true;
}

// Does the answer take these values at the fixed points?
bool Checker::Diagnosing::equals_at_points(const std::vector<std::optional<numeric>>& other) const {
  if (n == 0) return false;
  for (std::size_t k = 0; k < n; ++k)
    if (k >= other.size() || !other[k] || !c.same(values[k], *other[k])) return false;
  return true;
}

// The value of another unknown of the problem (of the same dimension).
void Checker::Diagnosing::other_unknown() {
  for (const auto& [name, other] : c.references_) {
    if (name == ref.name || !(other.dimension == ref.dimension)) continue;
    bool all = other.at_points.size() == values.size() && !values.empty();
    for (std::size_t k = 0; all && k < values.size(); ++k) all = c.same(values[k], other.at_points[k]);
    if (all) found("other_unknown", "this is the value of " + name + ", not of " + ref.name);
  }
}

// sin written for cos, or the reverse. (Most fail at the first point in doubles, swapped as
// the answer's program runs: the swapped expression is made only for those that pass.)
void Checker::Diagnosing::trig_swapped() {
  bool trig = false;
  for (const_preorder_iterator it = expanded.preorder_begin(); it != expanded.preorder_end() && !trig; ++it)
    trig = is_ex_the_function(*it, sin) || is_ex_the_function(*it, cos);
  if (!trig || n == 0) return;
  if (!c.point_doubles_.empty() && !maybe_same(answer_at.approx(c.point_doubles_[0], true), ref.at_points[0])) return;
  SinCosSwapped swap;
  const ex swapped = swap(expanded);
  if (swapped.is_equal(expanded)) return;
  const Program swapped_at = c.program(swapped);
  for (std::size_t k = 0; k < n; ++k) {
    const auto v = swapped_at(c.points_[k]);
    if (!v || !c.same(*v, ref.at_points[k])) return;
  }
  found("trig_swapped", "sin and cos are swapped");
}

// A factor in the parameters the answer is off by, when it is one worth saying (a few
// symbols); said after the more specific findings.
std::vector<Finding> Checker::Diagnosing::factor() const {
  // (A power with a symbolic exponent, m^h^mu, is no factor a student meant, and normal() of
  // a tower of them takes seconds: found by fuzzing.)
  for (const_preorder_iterator it = answer.preorder_begin(); it != answer.preorder_end(); ++it)
    if (is_exactly<power>(*it) && !is_exactly<numeric>(it->op(1))) return {};
  // The quotient answer/reference, when it can be a factor worth saying (a few symbols):
  // 1. from the values, a product of powers of the parameters (mu h/l), or that it is
  //    neither such a product nor a function of at most two parameters (no factor said: a
  //    sum in three parameters, (l + h) mu, is missed);
  // 2. else, of rational functions whose factors are coprime at sight (see Factored): in
  //    lowest terms once equal factors cancel, without a gcd;
  // 3. else normal(), most of a wrong answer's diagnosis when it runs.
  std::optional<ex> quotient;
  bool simple = true;
  if (const auto shape = c.quotient_shape(ref, answer_at, values)) {
    quotient = shape->monomial;
    simple = shape->monomial || shape->depends_on <= 2;
  }
  bool factored = false;
  if (!quotient && simple && diag->factored && rational_function(expanded, c.lengths_)) {
    Factored q;
    if (q.put(expanded, 1)) {
      factored = true;
      q.coefficient /= diag->factored->first;
      for (const auto& [factor, k] : diag->factored->second) q.powers[factor] -= k;
      ex made = q.coefficient;
      for (const auto& [factor, k] : q.powers)
        if (k != 0) made *= GiNaC::pow(factor, k);
      // (In normal() for its canonical form only when small: a factor said is small.)
      if (node_count(made, 10) <= 9) quotient = normal(made);
    }
  }
  if (!quotient && simple && !factored) quotient = normal(expanded / ref.closed_form);
  if (quotient && !is_a<numeric>(*quotient) && node_count(*quotient, 8) <= 7)
    return {{"factor", "off by a factor of " + to_text(*quotient)}};
  return {};
}

// Two parameters swapped (of the first 16, one of them typed).
void Checker::Diagnosing::swapped_parameters() {
  std::optional<Program> raw_at;  // the answer as typed over the extended points
  const std::vector<std::optional<numeric>> at_points(ref.at_points.begin(), ref.at_points.end());
  for (std::size_t i = 0; i < params.size() && i < 16; ++i)
    for (std::size_t j = i + 1; j < params.size() && j < 16; ++j) {
      if (!typed_symbols.count(params[i]) && !typed_symbols.count(params[j])) continue;
      const bool defined = c.definitions_.count(params[i]) || c.definitions_.count(params[j]);
      bool swapped = false;
      if (defined && !c.extended_points_.empty()) {
        swapped = swapped_in_extended_points(i, j, raw_at);
      } else if (defined) {
        swapped = swapped_in_expression(i, j);
      } else {
        const auto swap = [&](Sample& p) {
          numeric* x = value_in(p, params[i]);
          numeric* y = value_in(p, params[j]);
          if (x && y) std::swap(*x, *y);
        };
        swapped = matches_at(swap, at_points);
      }
      if (swapped) found("swapped", to_text(params[i]) + " and " + to_text(params[j]) + " are swapped");
    }
}

// A defined parameter's value is in the extended points: swapped there, in the answer as typed
// (the same as substituting the swap, then the definitions).
bool Checker::Diagnosing::swapped_in_extended_points(std::size_t i, std::size_t j,
                                                     std::optional<Program>& raw_at) const {
  if (!raw_at) raw_at.emplace(answer, c.extended_points_.front(), c.lengths_, c.extended_angles_);
  const Sample& first = c.extended_points_.front();
  const auto in = [&](const ex& x) {
    for (std::size_t at = 0; at < first.size(); ++at)
      if (first[at].first.is_equal(x)) return at;
    return first.size();
  };
  const std::size_t a = in(params[i]), b = in(params[j]);
  if (a == first.size() || b == first.size()) return false;
  for (std::size_t k = 0; k < c.extended_points_.size() && k < ref.at_points.size(); ++k) {
    Sample pk = c.extended_points_[k];
    std::swap(pk[a].second, pk[b].second);
    if (k == 0) {  // (swapped in doubles: no value changes)
      std::vector<double> dk = c.extended_doubles_[0];
      std::swap(dk[a], dk[b]);
      if (!maybe_same(raw_at->approx(dk), ref.at_points[0])) return false;
    }
    const auto v = (*raw_at)(pk);
    if (!v || !c.same(*v, ref.at_points[k])) return false;
  }
  return true;
}

// A defined parameter without a value of its own at the points: swapped in the expression.
bool Checker::Diagnosing::swapped_in_expression(std::size_t i, std::size_t j) const {
  const exmap swap{{params[i], params[j]}, {params[j], params[i]}};
  const Program swapped_at = c.program(substituted(substituted(answer, swap), c.definitions_));
  for (std::size_t k = 0; k < c.points_.size(); ++k) {
    const auto a = swapped_at(c.points_[k]);
    if (!a || !c.same(*a, ref.at_points[k])) return false;
  }
  return true;
}

// Correct only in a special case: a parameter at zero, or two parameters equal. Only: an
// answer right at some of the points (|a| for a, where a > 0) is no special case.
void Checker::Diagnosing::special_cases() {
  for (std::size_t k = 0; k < n; ++k)
    if (c.same(values[k], ref.at_points[k])) return;
  for (std::size_t i = 0; i < params.size(); ++i) {
    const auto zeroed = diag->zeroed.find(i);
    if (zeroed == diag->zeroed.end() || used.count(params[i])) continue;
    if (matches_at([](Sample&) {}, zeroed->second))
      found("special_case", "this is correct only " + c.describe(params[i]));
  }
  for (const auto& [pair, reference] : diag->equalled) {
    const std::size_t i = pair.first, j = pair.second;  // (clang 14: a lambda cannot capture a structured binding)
    const auto equal_values = [&](Sample& pt) {
      numeric* x = value_in(pt, params[i]);
      numeric* y = value_in(pt, params[j]);
      if (x && y) *y = *x;
    };
    if (matches_at(equal_values, reference))
      found("special_case", "this is correct only when " + c.parameters_[i].name + " = " + c.parameters_[j].name);
  }
}

// One term of the correct answer with the wrong sign, or missing (which term is not said:
// that would give the answer away).
void Checker::Diagnosing::terms() {
  for (std::size_t i = 0; i < diag->term_turned.size(); ++i) {
    if (equals_at_points(diag->term_turned[i])) return found("term_sign", "the sign of one term is wrong");
    if (equals_at_points(diag->term_left_out[i]))
      return found("missing_term", "one term of the correct answer is missing");
  }
}

// One term too many: the answer is the correct one plus a single term (a product of the
// parameters), when no term was found turned or missing.
void Checker::Diagnosing::extra_term() {
  if (found_any({"term_sign", "missing_term"}) || !is_a<add>(diag->expanded) || node_count(expanded, 201) > 200) return;
  const ex answer_expanded = expanded.expand();
  const ex extra = (answer_expanded - diag->expanded).expand();
  if (!extra.is_zero() && !is_a<add>(extra) && !is_a<numeric>(extra) && is_a<add>(answer_expanded))
    found("extra_term", "the answer has one term too many");
}

// Parameters the answer depends on, or misses (named in the problem's order).
void Checker::Diagnosing::parameters_used() {
  std::vector<std::string> extra, missing;
  for (const auto& p : c.parameters_) {
    if (used.count(p.symbol) && !diag->needed.count(p.symbol)) extra.push_back(p.name);
    if (diag->needed.count(p.symbol) && !used.count(p.symbol)) missing.push_back(p.name);
  }
  auto words = [](const std::vector<std::string>& names) {
    if (names.size() == 1) return names[0];
    return join(std::vector<std::string>(names.begin(), names.end() - 1)) + " and " + names.back();
  };
  if (!extra.empty())
    found("extra_parameter", "the answer depends on " + words(extra) + ", which the correct answer does not");
  if (!missing.empty())
    found("missing_parameter", "the correct answer depends on " + words(missing) + ", and this one does not");
}

}  // namespace tackle

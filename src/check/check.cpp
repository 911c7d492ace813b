#include "check/check.hpp"
#include "check/equation.hpp"

#include "core/utf8.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <cln/float.h>
#include <cln/integer.h>
#include <cln/integer_ring.h>
#include <cln/rational.h>
#include <cln/rational_ring.h>
#include <cln/real_ring.h>
#include <cln/real.h>
#include <functional>
#include <random>
#include <set>
#include <tuple>

#include <fmt/format.h>

#include "core/kind.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "expr/trig.hpp"
#include "numeric/evaluate.hpp"
#include "solve/solve.hpp"

namespace tackle {

using namespace GiNaC;

ExprLimits answer_limits() {
  ExprLimits l;
  l.max_length = 1000;
  l.max_tokens = 400;
  l.max_depth = 32;
  l.max_exponent = 32;
  l.max_number_digits = 20;
  return l;
}

std::string verdict_name(Verdict v) {
  switch (v) {
    case Verdict::correct: return "correct";
    case Verdict::incorrect: return "incorrect";
    case Verdict::invalid: return "invalid";
    case Verdict::undecided: return "undecided";
  }
  return "";
}

namespace {

// The names an answer may use, remembering those it could not resolve (for hints).
class AnswerNames : public NameResolver {
 public:
  explicit AnswerNames(const std::map<std::string, ex, std::less<>>& names) : names_(names) {}
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto it = names_.find(name); it != names_.end()) return it->second;
    // (The parser reads pi itself when the problem has no name pi: not a missing name.)
    if (name != "pi") missing_.emplace_back(name);
    return std::nullopt;
  }
  std::vector<std::string> known_names() const override {
    std::vector<std::string> out;
    for (const auto& [k, v] : names_) out.push_back(k);
    return out;
  }
  const std::vector<std::string>& missing() const { return missing_; }

 private:
  const std::map<std::string, ex, std::less<>>& names_;
  mutable std::vector<std::string> missing_;
};

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

std::string lower_without_underscores(std::string_view s) {
  std::string out;
  for (char c : s)
    if (c != '_') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// `ma` -> `m*a` when the identifier splits into known names (longest names first).
std::optional<std::string> split_into_names(const std::string& word, const std::vector<std::string>& names,
                                            int depth = 0) {
  if (word.empty()) return std::string{};
  if (depth > 6) return std::nullopt;
  std::vector<std::string> sorted = names;
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  for (const auto& n : sorted) {
    if (n.empty() || n.find('(') != std::string::npos || word.compare(0, n.size(), n) != 0) continue;
    if (auto rest = split_into_names(word.substr(n.size()), names, depth + 1))
      return rest->empty() ? n : n + "*" + *rest;
  }
  return std::nullopt;
}


// abs(), csgn() and step(): an expression in them may be correct on one side of a kink (where
// the argument changes sign) and not on the other, so agreeing near the parameters' values
// says nothing about the far side.
bool is_kink(const ex& e) {
  if (!is_exactly<function>(e)) return false;
  const unsigned serial = ex_to<function>(e).get_serial();
  return serial == abs_SERIAL::serial || serial == csgn_SERIAL::serial || serial == step_SERIAL::serial;
}

// The kinks of `e` (each once, in the order met) added to `out`.
void kinks_of(const ex& e, std::vector<ex>& out) {
  for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_kink(*it) && std::none_of(out.begin(), out.end(), [&](const ex& k) { return k.is_equal(*it); }))
      out.push_back(*it);
}

// A rational function of independent symbols with rational coefficients: one is zero exactly
// when its numerator over a common denominator expands to zero (as_fraction()), so equality
// with one is decided without any point. A turning strand's length is not independent (its
// square is a polynomial in the others).
bool rational_function(const ex& e, const exmap& lengths) {
  if (is_exactly<numeric>(e)) return ex_to<numeric>(e).is_rational();
  if (is_exactly<symbol>(e)) return !lengths.count(e);
  if (is_exactly<add>(e) || is_exactly<mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!rational_function(e.op(i), lengths)) return false;
    return true;
  }
  if (is_exactly<power>(e))
    return is_exactly<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer() && rational_function(e.op(0), lengths);
  return false;
}

// "6.8 N" -> ("6.8", "N"); "6.8" -> ("6.8", ""); nullopt when the text is not a number,
// optionally followed by something that starts like a unit (a letter).
std::optional<std::pair<std::string, std::string>> number_and_unit(const std::string& t) {
  const std::size_t sign = (!t.empty() && (t[0] == '-' || t[0] == '+')) ? 1 : 0;
  const std::size_t i = scan_number(t, sign);
  if (i == sign) return std::nullopt;
  std::string number = t.substr(0, i);
  std::size_t k = i;
  while (k < t.size() && t[k] == ' ') ++k;
  if (k == t.size()) return std::make_pair(number, std::string());
  if (!std::isalpha(static_cast<unsigned char>(t[k]))) return std::nullopt;  // "2*m", "3/4": an expression
  // The rest must look like a unit: letters, digits, / ^ * . - and spaces.
  for (std::size_t j = k; j < t.size(); ++j) {
    const char c = t[j];
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '/' || c == '^' || c == '*' || c == '.' || c == '-' || c == ' '))
      return std::nullopt;
  }
  return std::make_pair(number, trim(t.substr(k)));
}

std::string fmt_percent(double fraction) { return fmt::format("{:g} %", fraction * 100); }

// "twice", "half", "3 times", "2/3 of"
std::string factor_words(const numeric& c) {
  if (c == 2) return "twice the correct answer";
  if (c == numeric(1, 2)) return "half the correct answer";
  if (c == -1) return "the correct answer with the wrong sign";
  return to_text(c) + " times the correct answer";
}

}  // namespace

namespace {

// A float as the simple fraction it is within 10^-9 (a denominator up to 12), if it is one.
std::optional<numeric> simple_fraction(const numeric& c) {
  if (c.is_rational()) return c;
  if (!c.is_real() || std::abs(c.to_double()) >= 1e12) return std::nullopt;  // (a larger one does not fit a long: fuzzing)
  const double x = c.to_double();
  for (int den = 1; den <= 12; ++den)
    if (std::abs(x * den - std::round(x * den)) < 1e-9 * std::max(1.0, std::abs(x * den)))
      return numeric(static_cast<long>(std::round(x * den)), den);
  return std::nullopt;
}

}  // namespace

double expanded_size(const ex& e) {
  if (is_a<add>(e)) {
    double s = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) s += expanded_size(e.op(i));
    return s;
  }
  if (is_a<mul>(e)) {
    double s = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) s *= expanded_size(e.op(i));
    return s;
  }
  if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    const double k = expanded_size(e.op(0));
    const double n = std::abs(ex_to<numeric>(e.op(1)).to_double());
    // Terms of (t_1 + ... + t_k)^n: C(n + k - 1, k - 1).
    double c = 1;
    for (int i = 1; i < k && c < 1e12; ++i) c = c * (n + i) / i;
    return c;
  }
  return 1;
}

namespace {

// The rates among the answer's names that the constraints' rate forms tie to the others, each
// as an expression in them: the constraints in those rates and the parameters alone, solved
// (linear) for as many as they fix. Nothing when they cannot be solved.
exmap tied_rates(const EquationSystem& system, const std::vector<ex>& names, const SymbolTable& table) {
  exset named(names.begin(), names.end());
  const auto is_rate = [&](const ex& x) {
    const SymbolInfo* s = table.find(x);
    return s && s->role == SymbolRole::rate;
  };
  // The constraints' rate forms in rates and the answer's other names; every rate in them,
  // those the answer does not name first (eliminated first: Gaussian elimination takes its
  // pivots in this order), then the named ones.
  lst equations;
  exset others, own;
  for (const auto& c : system.constraints) {
    bool usable = !c.rate.is_zero();
    for (const ex& x : symbols_in(c.rate)) usable = usable && (is_rate(x) || named.count(x) != 0);
    if (!usable) continue;
    equations.append(c.rate == 0);
    for (const ex& x : symbols_in(c.rate))
      if (is_rate(x)) (named.count(x) ? own : others).insert(x);
  }
  if (equations.nops() == 0 || own.empty()) return {};
  lst rates;
  for (const ex& x : others) rates.append(x);
  for (const ex& x : own) rates.append(x);
  exmap out;
  try {
    const ex solved = lsolve(equations, rates);
    if (!is_a<lst>(solved)) return {};
    for (const ex& e : solved) {
      if (!own.count(e.lhs()) || e.lhs().is_equal(e.rhs())) continue;
      bool in_named = true;  // (in the answer's names alone: not through a rate it cannot name)
      for (const ex& x : symbols_in(e.rhs())) in_named = in_named && named.count(x) != 0 && !x.is_equal(e.lhs());
      if (in_named) out[e.lhs()] = e.rhs();
    }
  } catch (const std::exception&) {
    return {};
  }
  return out;
}

}  // namespace

Checker::Checker(const Analysis& analysis, CheckOptions options) : options_(options), symbols_(analysis.model.symbols) {
  const Model& m = analysis.model;
  GiNaC::Digits = std::max<long>(GiNaC::Digits, options_.digits);
  tolerance_ = ex_to<numeric>(GiNaC::pow(numeric(10), numeric(-(options_.digits - 8))));
  // The names an answer may use: the parameters and the given quantities; and the state's
  // coordinates, rates and time where a closed form holds them (an equation of motion:
  // ddot(x) in x, dot(x) and t), drawn at the points like parameters.
  for (const auto& s : symbols_->all())
    if (s->role == SymbolRole::parameter) parameters_.push_back({s->name, s->sym, s->dimension});
  for (const auto& g : m.given) {
    const SymbolInfo* s = symbols_->find(g);
    parameters_.push_back({s->name, s->sym, s->dimension});
  }
  std::set<ex, ex_is_less> in_closed_forms;
  for (const auto& d : analysis.solution.values)
    for (const ex& x : symbols_in(substituted(d.value, symbols_->definitions(true)))) in_closed_forms.insert(x);
  for (const auto& s : symbols_->all()) {
    const bool state = s->role == SymbolRole::coordinate || s->role == SymbolRole::rate || s->role == SymbolRole::time;
    if (state && in_closed_forms.count(s->sym) && !contains(m.given, s->sym) && !contains(m.candidates, s->sym) &&
        !contains(analysis.system.unknowns, s->sym))
      parameters_.push_back({s->name, s->sym, s->dimension});
  }
  for (const auto& u : m.candidates) problem_unknowns_.push_back(symbols_->find(u)->name);
  for (const auto& p : parameters_) answer_names_.emplace(p.name, p.symbol);
  definitions_ = symbols_->definitions();
  lengths_ = symbols_->definitions(true);
  // Rates the constraints tie together (dot(x_B2) = -dot(x_B1) where a string keeps x_B1 +
  // x_B2): the dependent ones follow from the others at each point, as a defined parameter
  // does; drawn apart, a right answer written in the other rate would differ.
  std::vector<ex> names;
  for (const auto& p : parameters_) names.push_back(p.symbol);
  const exmap tied = tied_rates(analysis.system, names, *symbols_);
  for (const auto& [rate, value] : tied) {
    definitions_[rate] = value;
    lengths_[rate] = value;
  }
  // Fixed random points (algebra/states.hpp): a fixed seed keeps the first comparison (which
  // settles every answer that differs at one of them) and the diagnoses the same in every
  // run; since anyone can find these points, an answer that agrees at all of them is decided
  // by decide(), never by them. Angles through rational points on the circle, so that an
  // answer in their sines and cosines is compared exactly.
  exset angles;
  for (const auto& d : analysis.solution.values) angles_in(substituted(d.value, lengths_), angles);
  for (const auto& w : m.wanted) angles_in(substituted(w.expr, lengths_), angles);
  std::vector<StateInput> inputs;
  for (const auto& p : parameters_) {
    const SymbolInfo* s = symbols_->find(p.symbol);
    if (s->definition || tied.count(p.symbol)) continue;  // follows from the others
    std::optional<ex> value = s->value;
    if (const auto at = m.layout.find(p.symbol); !value && at != m.layout.end()) value = at->second;  // a coordinate's
    inputs.push_back(input_near(p.symbol, value, angles.count(p.symbol) != 0));
  }
  states_ = States(std::move(inputs));
  choose_fixed_points(analysis);
  for (const Sample& p : points_) point_doubles_.push_back(doubles_of(p));
  extend_points();
  for (const Sample& p : extended_points_) extended_doubles_.push_back(doubles_of(p));
  // References: every determined unknown, and the defined quantities of `find`.
  auto add_reference = [&](const std::string& name, const ex& closed_form, std::optional<Dimension> dim) {
    const ex closed = substituted(closed_form, definitions_);
    Reference ref{name, closed, program(closed), dim, std::nullopt, {}, to_text(closed_form).size(),
                  {rational_function(closed, lengths_), expanded_size(closed), std::nullopt}, {}};
    if (ref.shape.rational && ref.shape.size <= static_cast<double>(options_.exact_size_budget))
      ref.shape.expanded = closed.expand();
    kinks_of(closed, ref.kinks);
    if (auto v = evaluate(closed, *symbols_, dim); v && is_a<numeric>(evalf(v->exact)))
      ref.value = ex_to<numeric>(evalf(v->exact));
    bool ok = true;
    for (std::size_t k = 0; k < points_.size() && ok; ++k) {
      auto v = ref.program(points_[k]);
      if (v) ref.at_points.push_back(*v);
      else ok = false;
    }
    if (ok) references_.emplace(name, std::move(ref));
  };
  for (const auto& d : analysis.solution.values) {
    const SymbolInfo* s = symbols_->find(d.unknown);
    add_reference(s->name, d.value, s->dimension);
  }
  for (const auto& w : m.wanted) {
    if (!w.defined) continue;
    const ex general = substituted(w.expr, analysis.solution.general);
    if (std::none_of(analysis.solution.free.begin(), analysis.solution.free.end(), [&](const ex& f) { return general.has(f); }))
      add_reference(w.name, simplest(general), w.dimension);
  }
  equations_ = std::make_shared<const EquationChecker>(analysis, options_);
  for (const auto& w : m.wanted)
    if (references_.count(w.name)) asked_.push_back(w.name);
}

CheckResult& CheckResult::conclude(Verdict v, std::string code, std::string message) {
  verdict = v;
  summary = message;
  if (!code.empty()) findings.push_back({std::move(code), std::move(message)});
  score = v == Verdict::correct ? 1.0 : 0.0;
  return *this;
}

namespace {

// A check's boundary: whatever goes wrong inside one check (an exception from GiNaC on an
// expression nobody foresaw) is that check's verdict, undecided with the reason, never the end
// of a batch, a worked solution or a service. (Out of memory is the process's: every input is
// bounded well below it.)
CheckResult guarded(const std::string& unknown, bool equation, const std::function<CheckResult()>& check) {
  try {
    return check();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    CheckResult r;
    r.unknown = unknown;
    r.equation = equation;
    return r.conclude(Verdict::undecided, "internal",
                      std::string("tackle failed while checking this (an internal error: ") + e.what() + "), so it is left undecided");
  }
}

}  // namespace

CheckResult Checker::check_equation(std::string_view equation) const {
  return guarded("", true, [&] { return equations_->check(equation); });
}

std::vector<std::string> Checker::needed_for(const std::string& unknown) const {
  const auto it = references_.find(unknown);
  const SymbolInfo* s = symbols_->find(unknown);
  if (it == references_.end() || !s || s->definition) return {};
  return equations_->needed_for(s->sym, it->second.closed_form);
}

const Equation* Checker::derivation_equation(const std::string& label) const { return equations_->equation(label); }

std::string Checker::differentiated(const std::string& label) const { return equations_->differentiated(label); }

std::vector<std::string> Checker::unknowns() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : references_) out.push_back(k);
  return out;
}

namespace {

// A rational function (rational_function() holds) as a numerator and a denominator,
// polynomials, made without the gcds normal() takes (most of its time): two are equal
// exactly when n1 d2 - n2 d1 expands to zero.
std::pair<ex, ex> as_fraction(const ex& e) {
  if (is_exactly<numeric>(e)) return {ex_to<numeric>(e).numer(), ex_to<numeric>(e).denom()};
  if (is_exactly<add>(e) || is_exactly<mul>(e)) {
    const bool sum = is_exactly<add>(e);
    ex n = sum ? 0 : 1, d = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const auto [ni, di] = as_fraction(e.op(i));
      if (sum && di.is_equal(d)) {
        n = n + ni;
      } else {
        n = sum ? n * di + ni * d : n * ni;
        d = d * di;
      }
    }
    return {n, d};
  }
  if (is_exactly<power>(e)) {
    const auto [n, d] = as_fraction(e.op(0));
    const numeric& k = ex_to<numeric>(e.op(1));
    return k.is_negative() ? std::pair<ex, ex>{pow(d, -k), pow(n, -k)} : std::pair<ex, ex>{pow(n, k), pow(d, k)};
  }
  return {e, 1};
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

// (x^2)^(1/2) is |x| and not x: an even power under a fractional one is a kink, and is
// written as one (|x|^(n r) for (x^n)^r, n even) so that both its sides are looked at.
struct EvenRootsAsAbs : map_function {
  static bool even_root(const ex& e) {
    if (!is_exactly<power>(e) || !is_exactly<power>(e.op(0)) || !is_exactly<numeric>(e.op(1)) ||
        !is_exactly<numeric>(e.op(0).op(1)))
      return false;
    const numeric& r = ex_to<numeric>(e.op(1));
    return ex_to<numeric>(e.op(0).op(1)).is_even() && r.is_rational() && !r.is_integer();
  }
  ex operator()(const ex& e) override {
    const ex m = e.map(*this);
    if (even_root(m)) return pow(abs(m.op(0).op(0)), ex_to<numeric>(m.op(0).op(1)) * ex_to<numeric>(m.op(1)));
    return m;
  }
  // `e` with its even roots as abs(); `e` itself (not rebuilt) when it has none.
  ex rewrite(const ex& e) {
    for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
      if (even_root(*it)) return (*this)(e);
    return e;
  }
};

// sin written for cos and cos for sin, everywhere (a map, not subs() with patterns: a tenth of
// the cost).
struct SinCosSwapped : map_function {
  ex operator()(const ex& e) override {
    if (is_ex_the_function(e, sin)) return cos((*this)(e.op(0)));
    if (is_ex_the_function(e, cos)) return sin((*this)(e.op(0)));
    return e.map(*this);
  }
};

constexpr std::size_t max_kinks = 4;  // arguments up to their sign: 16 combinations of signs

}  // namespace

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

Sample Checker::draw_point(std::mt19937& rng) const {
  // Finer than the fixed points (1.5 million values between half and twice each value): an
  // answer built to vanish at some values meets one of them by a chance of its degree over
  // that.
  return states_.draw(rng);
}

const std::vector<Sample>& Checker::FreshPoints::get() {
  if (points_) return *points_;
  Reference::Lazy& lazy = *ref_.lazy;
  const std::lock_guard<std::mutex> lock(lazy.fresh_mutex);
  Reference::Fresh& pool = lazy.fresh;
  const bool seeded = checker_.options_.seed.has_value();
  if (!pool.rng) pool.rng = States::generator(checker_.options_.seed);
  if (pool.uses == 0 || (!seeded && pool.uses >= fresh_renewal)) {
    pool.points.clear();
    pool.values.clear();
    pool.uses = 0;
    // Where the reference is defined (a point on a pole is drawn again) and the model's
    // conditions hold.
    for (int k = 0; k < checker_.options_.points; ++k)
      for (int attempt = 0; attempt < 16; ++attempt) {
        Sample p = checker_.draw_point(*pool.rng);
        if (!checker_.allowed(p)) continue;
        if (const auto v = ref_.program(p)) {
          pool.points.push_back(std::move(p));
          pool.values.push_back(*v);
          break;
        }
      }
  }
  ++pool.uses;
  points_ = pool.points;
  values_ = pool.values;
  return *points_;
}

Checker::Agreement Checker::compare(const ex& answer, const ex& reference, const Program& reference_at, const Shape& shape,
                                    FreshPoints& fresh, const std::function<bool()>& over_budget, bool& exact_values) const {
  exact_values = false;
  if (answer.is_equal(reference)) return Agreement::proved;  // the closed form as GiNaC writes it
  const double budget = static_cast<double>(options_.exact_size_budget);
  const double size = expanded_size(answer) + shape.size;
  if (shape.rational && rational_function(answer, lengths_)) {
    // Equal as rational functions or not: certain either way. Most equal answers expand to
    // the closed form's own terms over the same denominators; the others are put over one.
    if (size <= budget && (answer.expand() - (shape.expanded ? *shape.expanded : reference.expand())).is_zero())
      return Agreement::proved;
    const auto [n1, d1] = as_fraction(answer);
    const auto [n2, d2] = as_fraction(reference);
    const ex cross = n1 * d2 - n2 * d1;
    if (expanded_size(cross) <= budget && !over_budget())
      return cross.expand().is_zero() ? Agreement::proved : Agreement::refuted;
  } else if (size <= budget && !over_budget() && !has_trig(answer) && !has_trig(reference)) {
    // Zero is a proof; not zero may still be zero by an identity normal() does not know.
    // (Not tried with a sine or a cosine: normal() knows none of their identities, and the
    // points, rational points on the circle for every angle, compare them exactly.)
    try {
      if (normal(answer - reference).is_zero()) return Agreement::proved;
    } catch (const std::bad_alloc&) {
      throw;  // out of memory is the process's (exit 3), not this answer's
    } catch (const std::exception&) {
    }
  }
  const Program answer_at = program(answer);
  const auto& points = fresh.get();
  // (No points, or fewer than asked where the reference is defined: nothing to go on.)
  if (points.empty() || points.size() < static_cast<std::size_t>(options_.points)) return Agreement::unevaluable;
  exact_values = true;
  // (The reference's own closed form: its values came with the points.)
  const bool own = &reference_at == &fresh.reference().program;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Sample& p = points[k];
    if (over_budget()) return Agreement::budget;
    const auto a = answer_at(p);
    const auto b = own ? std::optional<numeric>(fresh.reference_at(k)) : reference_at(p);
    if (!a || !b) return Agreement::unevaluable;
    if (!same(*a, *b)) return Agreement::differs;
    exact_values = exact_values && a->is_rational() && b->is_rational();
  }
  return Agreement::agrees;
}

Checker::Decision Checker::decide(const Reference& ref, const ex& typed, const std::function<bool()>& over_budget) const {
  FreshPoints fresh(*this, ref);
  EvenRootsAsAbs as_abs;
  const ex answer = as_abs.rewrite(typed);
  const std::string count = std::to_string(points_.size() + static_cast<std::size_t>(options_.points));
  const Decision wrong{Verdict::incorrect, "", "value", "the answer agrees with the correct one only for some values of the parameters"};
  const Decision budget{Verdict::undecided, "", "budget", "the answer took too long to check"};
  const auto correct = [&](bool proved, bool exact_values) {
    if (proved) return Decision{Verdict::correct, "exact", "", "equal to the closed form"};
    if (exact_values)
      return Decision{Verdict::correct, "exact rationals", "", "equal to the closed form (in exact arithmetic at " + count + " random points)"};
    return Decision{Verdict::correct, "numeric", "", "equal to the closed form at " + count + " random points, to " +
                                                         std::to_string(options_.digits - 8) + " digits"};
  };
  std::vector<ex> kinks;
  kinks_of(answer, kinks);
  for (const auto& k : ref.kinks)
    if (std::none_of(kinks.begin(), kinks.end(), [&](const ex& x) { return x.is_equal(k); })) kinks.push_back(k);
  if (kinks.empty()) {
    bool exact_values = false;
    switch (compare(answer, ref.closed_form, ref.program, ref.shape, fresh, over_budget, exact_values)) {
      case Agreement::proved: return correct(true, false);
      case Agreement::agrees: return correct(false, exact_values);
      case Agreement::refuted: return Decision{wrong.verdict, "exact", wrong.code, wrong.message};
      case Agreement::differs: return Decision{wrong.verdict, "numeric", wrong.code, wrong.message};
      case Agreement::unevaluable:
        return Decision{Verdict::undecided, "numeric", "evaluation",
                        "the answer could not be evaluated at the test values (a division by zero, a negative square root, or a number too large to work with?)"};
      case Agreement::budget: return budget;
    }
  }
  // Kinks: each sign of their arguments in turn (abs(x) -> x or -x). Where the answer and the
  // reference agree for every sign, the answer is correct on both sides of every kink. A sign
  // for which they differ is looked for in the parameters: found, the answer is incorrect
  // there; not found (a side no positive values reach, or too narrow a one), undecided.
  const Decision refused{Verdict::undecided, "", "abs",
                         "the answer uses abs(), and tackle could not decide it for every sign of its argument: write it without abs()"};
  // The kinks' arguments, each once up to a constant factor (abs(h - l) and abs(l - h), or
  // abs(mu - 1/10) and abs(10*mu - 1), have one kink).
  std::vector<ex> args;
  std::vector<std::pair<std::size_t, bool>> arg_of;  // per kink: its argument, and whether negated
  for (const auto& k : kinks) {
    std::vector<ex> inner;
    kinks_of(k.op(0), inner);
    if (!inner.empty()) return refused;
    std::size_t j = 0;
    bool negated = false;
    for (; j < args.size(); ++j) {
      if (args[j].is_equal(k.op(0))) break;
      if (const ex ratio = normal(k.op(0) / args[j]); is_exactly<numeric>(ratio) && ex_to<numeric>(ratio).is_real()) {
        negated = ex_to<numeric>(ratio).is_negative();
        break;
      }
    }
    if (j == args.size()) args.push_back(k.op(0));
    arg_of.emplace_back(j, negated);
  }
  if (args.size() > max_kinks) return refused;
  std::vector<std::size_t> differing;  // the signs (bit j set: argument j negative)
  bool all_proved = true, all_exact = true;
  for (std::size_t signs = 0; signs < (std::size_t{1} << args.size()); ++signs) {
    exmap side;
    for (std::size_t i = 0; i < kinks.size(); ++i) {
      const bool negative = (((signs >> arg_of[i].first) & 1) != 0) != arg_of[i].second;
      const ex& arg = kinks[i].op(0);
      const unsigned serial = ex_to<function>(kinks[i]).get_serial();
      side[kinks[i]] = serial == abs_SERIAL::serial ? (negative ? -arg : arg)
                       : serial == csgn_SERIAL::serial ? ex(negative ? -1 : 1)
                                                       : ex(negative ? 0 : 1);
    }
    const ex a = answer.subs(side), b = ref.closed_form.subs(side);
    bool exact_values = false;
    switch (compare(a, b, program(b), Shape{rational_function(b, lengths_), expanded_size(b), std::nullopt}, fresh, over_budget, exact_values)) {
      case Agreement::proved: break;
      case Agreement::agrees:
        all_proved = false;
        all_exact = all_exact && exact_values;
        break;
      case Agreement::budget: return budget;
      default: differing.push_back(signs);
    }
  }
  // A sign the model's conditions leave out (abs(N_A) where N_A >= 0 is stated) is no state.
  std::erase_if(differing, [&](std::size_t signs) {
    for (std::size_t j = 0; j < args.size(); ++j)
      if (excluded(args[j], ((signs >> j) & 1) != 0)) return true;
    return false;
  });
  if (differing.empty()) return correct(all_proved, all_exact);
  // Along each parameter of the kinks' arguments, from each fixed point: values from 2^-64 to
  // 3 * 2^63 times the point's, so both sides of a kink within them are met.
  std::vector<Program> args_at;
  std::set<ex, ex_is_less> used;
  for (const auto& arg : args) {
    args_at.push_back(program(arg));
    for (const auto& s : symbols_in(substituted(arg, lengths_))) used.insert(s);
  }
  const Program answer_at = program(answer);
  for (const Sample& base : points_)
    for (std::size_t i = 0; i < base.size(); ++i) {
      if (!used.count(base[i].first)) continue;
      for (int e = -64; e <= 64; ++e)
        for (const numeric& f : {numeric(2).power(e), numeric(3, 2) * numeric(2).power(e)}) {
          if (over_budget()) return budget;
          Sample p = base;
          p[i].second = base[i].second * f;
          std::size_t signs = 0;
          bool clear = true;
          for (std::size_t k = 0; k < args_at.size() && clear; ++k) {
            const auto v = args_at[k](p);
            clear = v && !v->is_zero();
            if (clear && v->is_negative()) signs |= std::size_t{1} << k;
          }
          if (!clear || std::find(differing.begin(), differing.end(), signs) == differing.end() || !allowed(p)) continue;
          const auto a = answer_at(p), b = ref.program(p);
          if (a && b && !same(*a, *b)) return Decision{wrong.verdict, "numeric", wrong.code, wrong.message};
        }
    }
  return refused;
}

Program Checker::program(const ex& e) const { return Program(e, states_.layout(), lengths_, states_.angles()); }

void Checker::extend_points() {
  std::vector<std::pair<ex, Program>> defined;
  for (const auto& p : parameters_)
    if (const auto d = definitions_.find(p.symbol); d != definitions_.end()) defined.emplace_back(p.symbol, program(d->second));
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

namespace {

// A changed point's doubles: those of the point it was changed from, each changed value
// made anew (a rational's double is dear: a screen makes one or two).
std::vector<double> doubles_from(const Sample& changed, const Sample& from, const std::vector<double>& from_doubles) {
  std::vector<double> out = from_doubles;
  for (std::size_t i = 0; i < changed.size() && i < out.size(); ++i)
    if (!changed[i].second.is_equal(from[i].second)) out[i] = changed[i].second.is_real() ? changed[i].second.to_double() : std::nan("");
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

namespace {

// An answer as people type it, in the parser's ASCII: Greek letters by name (θ -> theta),
// ·, × and ⋅ -> *, − and – -> -, ÷ -> /, superscript digits -> powers (x² -> x^2, x⁻¹ ->
// x^(-1)), √ -> sqrt, ° -> deg, other spaces -> ' '. `origin` gets, for each byte of the
// result, the character (0-based) of the input it comes from, for columns in messages.
std::string as_typed(std::string_view in, std::vector<int>& origin) {
  static const std::vector<std::pair<std::string_view, std::string_view>> table{
      {"\u00b7", "*"}, {"\u00d7", "*"}, {"\u22c5", "*"}, {"\u2217", "*"}, {"\u2212", "-"}, {"\u2013", "-"}, {"\u00f7", "/"},
      {"\u2215", "/"}, {"\u00a0", " "}, {"\u2009", " "}, {"\u202f", " "}, {"\u00b0", " deg"},
      {"\u03b1", "alpha"}, {"\u03b2", "beta"}, {"\u03b3", "gamma"}, {"\u03b4", "delta"}, {"\u03b5", "epsilon"},
      {"\u03b6", "zeta"}, {"\u03b7", "eta"}, {"\u03b8", "theta"}, {"\u03d1", "theta"}, {"\u03b9", "iota"},
      {"\u03ba", "kappa"}, {"\u03bb", "lambda"}, {"\u03bc", "mu"}, {"\u00b5", "mu"}, {"\u03bd", "nu"}, {"\u03be", "xi"},
      {"\u03c0", "pi"}, {"\u03c1", "rho"}, {"\u03c3", "sigma"}, {"\u03c4", "tau"}, {"\u03c6", "phi"}, {"\u03d5", "phi"},
      {"\u03c7", "chi"}, {"\u03c8", "psi"}, {"\u03c9", "omega"}, {"\u0393", "Gamma"}, {"\u0394", "Delta"},
      {"\u0398", "Theta"}, {"\u039b", "Lambda"}, {"\u03a3", "Sigma"}, {"\u03a6", "Phi"}, {"\u03a8", "Psi"},
      {"\u03a9", "Omega"}};
  static const std::vector<std::string_view> superscripts{"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                                          "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  static const std::string_view super_minus = "\u207b", root = "\u221a";
  std::string out;
  origin.clear();
  auto emit = [&](std::string_view t, int from) {
    out += t;
    origin.insert(origin.end(), t.size(), from);
  };
  auto superscript_at = [&](std::size_t i) -> int {  // the digit, 10 for minus, -1 for none
    for (int d = 0; d < 10; ++d)
      if (in.substr(i, superscripts[d].size()) == superscripts[d]) return d;
    return in.substr(i, super_minus.size()) == super_minus ? 10 : -1;
  };
  auto char_length = [&](std::size_t i) {
    const auto c = static_cast<unsigned char>(in[i]);
    return c < 0x80 ? 1 : c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
  };
  int column = 0;
  out.reserve(in.size());
  origin.reserve(in.size() + 1);
  for (std::size_t i = 0; i < in.size();) {
    if (static_cast<unsigned char>(in[i]) < 0x80) {  // ASCII is kept (every entry above starts past it)
      out += in[i++];
      origin.push_back(column++);
      continue;
    }
    if (superscript_at(i) >= 0) {
      // A run of superscripts is one exponent.
      std::string exponent;
      const int from = column;
      while (i < in.size() && superscript_at(i) >= 0) {
        const int d = superscript_at(i);
        exponent += d == 10 ? '-' : static_cast<char>('0' + d);
        i += static_cast<std::size_t>(char_length(i));
        ++column;
      }
      emit(exponent.find('-') == std::string::npos ? "^" + exponent : "^(" + exponent + ")", from);
      continue;
    }
    if (in.substr(i, root.size()) == root) {
      // √3, √x, √(...): sqrt( of what follows (a number or a name; a parenthesis as it is).
      i += root.size();
      const int from = column++;
      if (i < in.size() && in[i] == '(') {
        emit("sqrt", from);
        continue;
      }
      emit("sqrt(", from);
      while (i < in.size() && (std::isalnum(static_cast<unsigned char>(in[i])) || in[i] == '_' || in[i] == '.')) {
        emit(in.substr(i, 1), column++);
        ++i;
      }
      emit(")", column);
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : table)
      if (in.substr(i, from.size()) == from) {
        emit(to, column++);
        i += from.size();
        replaced = true;
        break;
      }
    if (replaced) continue;
    const int length = char_length(i);
    emit(in.substr(i, static_cast<std::size_t>(length)), column++);
    i += static_cast<std::size_t>(length);
  }
  origin.push_back(column);  // one past the end
  return out;
}

// `30 deg` -> (30*pi/180): a number followed by deg (not part of a longer name).
std::string degrees_as_radians(const std::string& in, std::vector<int>& origin) {
  std::string out;
  std::vector<int> where;
  for (std::size_t i = 0; i < in.size();) {
    const bool starts_number = (std::isdigit(static_cast<unsigned char>(in[i])) || in[i] == '.') &&
                               (i == 0 || !(std::isalnum(static_cast<unsigned char>(in[i - 1])) || in[i - 1] == '_'));
    if (starts_number) {
      std::size_t j = i;
      while (j < in.size() && (std::isdigit(static_cast<unsigned char>(in[j])) || in[j] == '.')) ++j;
      std::size_t k = j;
      while (k < in.size() && in[k] == ' ') ++k;
      // (A whole answer `30 deg` stays a number with its unit.)
      const bool whole = i == 0 && k + 3 == in.size();
      if (!whole && in.compare(k, 3, "deg") == 0 &&
          (k + 3 == in.size() || !(std::isalnum(static_cast<unsigned char>(in[k + 3])) || in[k + 3] == '_'))) {
        const std::string t = "(" + in.substr(i, j - i) + "*pi/180)";
        out += t;
        where.insert(where.end(), t.size(), origin[i]);
        i = k + 3;
        continue;
      }
    }
    out += in[i];
    where.push_back(origin[i]);
    ++i;
  }
  where.push_back(origin.back());
  origin = where;
  return out;
}

}  // namespace

bool Checker::same(const numeric& a, const numeric& b) const {
  if (a.is_rational() && b.is_rational()) return a == b;
  if (a.is_real() && b.is_real()) {  // in CLN's reals, without GiNaC's numeric objects
    const cln::cl_R x = cln::the<cln::cl_R>(a.to_cl_N()), y = cln::the<cln::cl_R>(b.to_cl_N());
    const cln::cl_R scale = cln::max(cln::abs(x), cln::abs(y));
    return cln::zerop(scale) || cln::abs(x - y) <= scale * cln::the<cln::cl_R>(tolerance_.to_cl_N());
  }
  const numeric scale = std::max(abs(a), abs(b));
  if (scale.is_zero()) return true;
  return abs(a - b) <= scale * tolerance_;
}

std::string Checker::describe(const ex& parameter) const {
  const std::string name = to_text(parameter);
  // A dimensionless parameter named mu is a friction coefficient.
  if (name.rfind("mu", 0) == 0) return "without friction (" + name + " = 0)";
  return "for " + name + " = 0";
}

std::optional<exmap> Checker::values_for(const std::vector<std::pair<std::string, std::string>>& set, std::string& problem,
                                         bool* out_of_domain) const {
  if (out_of_domain) *out_of_domain = false;
  exmap values = symbols_->values();
  for (const auto& [name, text] : set) {
    const SymbolInfo* s = symbols_->find(name);
    if (!s || s->role != SymbolRole::parameter || s->definition || !s->value) {
      std::vector<std::string> settable;
      for (const auto& x : symbols_->all())
        if (x->role == SymbolRole::parameter && !x->definition && x->value) settable.push_back(x->name);
      problem = "'" + printable(name) + "' is not a parameter with a value (expected one of: " + join(settable) + ")";
      return std::nullopt;
    }
    const auto parsed = parse_expression(text, numbers_only(), answer_limits());
    const ex v = parsed.value ? evalf(*parsed.value) : ex(0);
    if (!parsed.value || !is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) {
      problem = "the value of '" + name + "' is '" + printable(text) + "' (expected a number in " + (s->unit.empty() ? "SI" : s->unit) + ")";
      return std::nullopt;
    }
    // A mass, a length, a stiffness... is a positive symbol: every closed form was simplified
    // with that, so a value it does not hold for would be graded against a wrong answer.
    if (s->positive && !ex_to<numeric>(v).is_positive()) {
      problem = "the value of '" + name + "' is " + printable(trim(text)) + (s->unit.empty() ? "" : " " + s->unit) + ", but '" + name +
                "' is assumed positive" + (s->dimension && !(*s->dimension == Dimension::none()) ? " (" + with_article(s->dimension->describe()) + ")" : "");
      if (out_of_domain) *out_of_domain = true;
      return std::nullopt;
    }
    values[s->sym] = (is_a<numeric>(*parsed.value) ? *parsed.value : v) * s->unit_to_si;
  }
  for (const auto& s : symbols_->all())
    if (s->definition && !s->geometric) {
      if (auto v = tackle::value_at(*s->definition, values)) values[s->sym] = *v;
      else values.erase(s->sym);
    }
  return values;
}


CheckResult Checker::check(const std::string& unknown, std::string_view answer, const exmap* values) const {
  return guarded(unknown, false, [&] { return check_answer(unknown, answer, values); });
}

CheckResult Checker::check_answer(const std::string& unknown, std::string_view answer, const exmap* values) const {
  const auto start = std::chrono::steady_clock::now();
  CheckResult r;
  r.unknown = unknown;
  auto invalid = [&](std::string code, std::string message) {
    r.verdict = Verdict::invalid;
    r.summary = message;
    r.findings.push_back({std::move(code), std::move(message)});
    return r;
  };
  const auto ref_it = references_.find(unknown);
  if (ref_it == references_.end()) {
    std::string msg = "'" + printable(unknown) + "' is not an unknown tackle can check for this problem";
    const auto known = unknowns();
    if (auto near = nearest(unknown, known); !near.empty()) msg += " (did you mean '" + near + "'?)";
    else msg += " (checkable: " + join(known) + ")";
    return invalid("wrong_unknown", msg);
  }
  const Reference& ref = ref_it->second;
  // Length first: nothing else looks at a huge answer.
  if (answer.size() > options_.limits.max_length)
    return invalid("too_large", "the answer is too long (" + std::to_string(answer.size()) + " characters; at most " +
                                    std::to_string(options_.limits.max_length) + ")");
  if (const auto bad = invalid_utf8_at(answer))
    return invalid("syntax", "at column " + std::to_string(*bad + 1) + ": the answer is not valid UTF-8 text");
  std::vector<int> origin;
  std::string text = as_typed(trim(answer), origin);
  if (!answer_names_.count("deg")) text = degrees_as_radians(text, origin);
  std::size_t offset = 0;  // where the expression starts in `text` (after "T =")
  if (trim(text).empty()) return invalid("not_an_answer", "the answer is empty");
  // "T = ...": the left side must name the unknown asked for.
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=' || (i > 0 && (text[i - 1] == '<' || text[i - 1] == '>' || text[i - 1] == '!')) ||
        (i + 1 < text.size() && text[i + 1] == '='))
      continue;
    const std::string lhs = trim(std::string_view(text).substr(0, i));
    if (lhs != unknown) {
      if (std::find(problem_unknowns_.begin(), problem_unknowns_.end(), lhs) != problem_unknowns_.end() ||
          references_.count(lhs))
        return invalid("wrong_unknown", "this is an answer for " + lhs + ", but " + unknown + " was asked for");
      return invalid("not_an_answer", "write '" + unknown + " = ...' or just the expression (found '" + printable(lhs) + " = ')");
    }
    offset = i + 1;
    while (offset < text.size() && std::isspace(static_cast<unsigned char>(text[offset]))) ++offset;
    text = trim(std::string_view(text).substr(i + 1));
    break;
  }
  // A number with a unit: "6.8 N", "0.0068 kN", "1.53 lbf", "-2.25 m/s^2".
  auto split = number_and_unit(text);
  if (split && !split->second.empty()) {
    // Not a unit, but it starts with a parameter's name: read it as an expression ("2 a m"
    // then says "missing '*'").
    std::string err;
    int col = 0;
    const std::string first_word = split->second.substr(0, split->second.find_first_of(" */^.-"));
    if (!parse_unit(split->second, err, col) && answer_names_.count(first_word)) split.reset();
  }
  if (split) {
    CheckResult n = check_number(ref, split->first, split->second, r, values);
    if (n.verdict != Verdict::correct && answer_names_.count(split->second))
      n.findings.push_back({"syntax", "if you meant " + split->first + "*" + split->second + ", write the * (" + text +
                                          " is read as a number with a unit)"});
    return n;
  }
  // A column of `text` as a character of the answer as typed, from where the expression starts.
  const auto column = [&](int c) {
    const std::size_t at = std::min(offset + static_cast<std::size_t>(std::max(c, 0)), origin.size() - 1);
    return origin[at] - origin[std::min(offset, origin.size() - 1)] + 1;
  };
  return check_expression(ref, text, r, start, column);
}

CheckResult Checker::check_number(const Reference& ref, std::string_view number, std::string_view unit_text,
                                  CheckResult r, const exmap* values) const {
  r.method = "number";
  auto finish = [&](Verdict v, std::string code, std::string message) {
    r.verdict = v;
    r.summary = message;
    r.findings.push_back({std::move(code), std::move(message)});
    r.score = v == Verdict::correct ? 1.0 : 0.0;
    return r;
  };
  const auto parsed = parse_expression(number, numbers_only(), options_.limits);
  if (!parsed.value || !is_a<numeric>(*parsed.value))
    return finish(Verdict::invalid, "syntax", "the number could not be read");
  numeric value = ex_to<numeric>(*parsed.value);
  const Dimension expected = ref.dimension.value_or(Dimension::none());
  std::string unit_shown = std::string(unit_text);
  if (unit_text.empty()) {
    // (Zero is zero in every unit: 0 for a force that vanishes needs none.)
    if (!(expected == Dimension::none()) && !value.is_zero())
      return finish(Verdict::invalid, "no_unit", "give the unit: the answer is " + with_article(expected.describe()) + " (in SI, " +
                                                     si_unit_name(expected) + ")");
  } else {
    std::string err;
    int col = 0;
    auto unit = parse_unit(unit_text, err, col);
    if (!unit) return finish(Verdict::invalid, "unit", err + " (expected a unit such as " + si_unit_name(expected) + ")");
    if (!(unit->dimension == expected))
      return finish(Verdict::incorrect, "dimension", "the unit " + std::string(unit_text) + " is " +
                                                         with_article(unit->dimension.describe()) + "; " +
                                                         with_article(expected.describe()) + " was expected");
    const ex si = value * unit->to_si;  // exact for rational factors; degrees go through pi
    value = ex_to<numeric>(is_a<numeric>(si) ? si : evalf(si));
  }
  r.echo_text = std::string(number) + (unit_text.empty() ? "" : " " + std::string(unit_text));
  if (options_.echo_latex) r.echo_latex = std::string(number) + (unit_text.empty() ? "" : "\\," + unit_latex(unit_text));
  // The student's own numbers, when given: the closed form evaluated there (exactly, then
  // to the comparison's precision).
  std::optional<numeric> at_values = ref.value;
  if (values) {
    at_values.reset();
    if (auto v = tackle::value_at(substituted(substituted(ref.closed_form, lengths_), lengths_), *values))
      if (const ex f = evalf(*v); is_a<numeric>(f) && ex_to<numeric>(f).is_real()) at_values = ex_to<numeric>(f);
  }
  if (!at_values)
    return finish(Verdict::invalid, "not_an_answer",
                  "this problem gives no numbers for every parameter: answer with a closed form in its symbols");
  const numeric expect = *at_values;
  const double got = value.to_double(), want = expect.to_double();
  bool ok;
  std::string how;
  if (options_.significant_figures) {
    const int n = *options_.significant_figures;
    auto round_to = [n](double x) {
      if (x == 0) return 0.0;
      const double scale = std::pow(10.0, n - 1 - static_cast<int>(std::floor(std::log10(std::abs(x)))));
      return std::round(x * scale) / scale;
    };
    ok = round_to(got) == round_to(want);
    how = "to " + std::to_string(n) + " significant figures";
  } else {
    ok = std::abs(got - want) <= options_.relative_tolerance * std::abs(want) + 1e-300;
    how = "within " + fmt_percent(options_.relative_tolerance);
  }
  const std::string unit = si_unit_name(expected);
  if (ok) {
    r.verdict = Verdict::correct;
    r.score = 1.0;
    r.summary = "correct " + how + (options_.reveal ? " (the answer is " + decimal_string(expect, 6) + (unit.empty() ? "" : " " + unit) + ")" : "");
    return r;
  }
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  // Why: the sign, a factor of ten (a unit prefix), a simple factor, or g (mass for weight).
  const double ratio = want != 0 ? got / want : 0;
  auto near = [](double x, double y) { return std::abs(x - y) <= 0.01 * std::abs(y); };
  if (near(ratio, -1)) {
    r.findings.push_back({"sign", "the sign is wrong"});
  } else if (ratio != 0) {
    const double l10 = std::log10(std::abs(ratio));
    const double k = std::round(l10);
    if (k != 0 && std::abs(l10 - k) < 0.005)
      r.findings.push_back({"factor", "off by a factor of 10^" + std::to_string(static_cast<int>(k)) +
                                          ": check the unit prefix or the conversion"});
    else if (near(std::abs(ratio), 9.81) || near(std::abs(ratio), 1 / 9.81))
      r.findings.push_back({"factor", "off by a factor of g: a mass where a weight belongs, or the reverse?"});
    else
      for (const double f : {2.0, 0.5, 3.0, 1.0 / 3, 4.0, 0.25})
        if (near(std::abs(ratio), f)) {
          r.findings.push_back({"factor", "off by a factor of " + std::string(f == 2.0 ? "2" : f == 0.5 ? "1/2" : f == 3.0 ? "3" : f == 4.0 ? "4" : f == 0.25 ? "1/4" : "1/3")});
          break;
        }
  }
  const std::string got_text = decimal_string(value, 6) + (unit.empty() ? "" : " " + unit);
  r.findings.push_back({"tolerance", options_.reveal ? "expected " + decimal_string(expect, 6) + (unit.empty() ? "" : " " + unit) + " " +
                                                           how + "; got " + got_text
                                                     : "not " + how + " of the correct value (got " + got_text + ")"});
  r.summary = r.findings.front().message;
  return r;
}

CheckResult Checker::check_expression(const Reference& ref, std::string_view text, CheckResult r,
                                      std::chrono::steady_clock::time_point start,
                                      const std::function<int(int)>& column) const {
  auto over_budget = [&] { return std::chrono::steady_clock::now() - start > options_.time_budget; };
  auto finish = [&](Verdict v, std::string code, std::string message) { return r.conclude(v, std::move(code), std::move(message)); };
  AnswerNames resolver(answer_names_);
  const ParseResult parsed = parse_expression(text, resolver, options_.limits);
  if (!parsed.value) {
    const ParseProblem& p = parsed.problems.front();
    const std::string where = "at column " + std::to_string(column(p.column)) + ": ";
    if (!resolver.missing().empty()) {
      // The most useful hint for a name the problem does not have.
      const std::string& bad = resolver.missing().back();
      std::vector<std::string> known;
      for (const auto& q : parameters_) known.push_back(q.name);
      std::string hint;
      if (std::find(problem_unknowns_.begin(), problem_unknowns_.end(), bad) != problem_unknowns_.end()) {
        hint = bad + " is an unknown of this problem; write the answer in the given quantities (" + join(known) + ")";
      } else {
        for (const auto& k : known)
          if (lower_without_underscores(k) == lower_without_underscores(bad)) {
            hint = "unknown name '" + bad + "': did you mean '" + k + "'? (names are case-sensitive; subscripts are written with _)";
            break;
          }
        if (hint.empty())
          if (auto split = split_into_names(bad, known))
            hint = "unknown name '" + bad + "': did you mean '" + *split + "'? (write products with *)";
        if (hint.empty()) {
          hint = "unknown name '" + bad + "'";
          if (auto near = nearest(bad, known); !near.empty())
            hint += ": did you mean '" + near + "'?";
          else
            hint += " (the problem's names: " + join(known) + ")";
        }
      }
      return finish(Verdict::invalid, "unknown_name", where + hint);
    }
    return finish(Verdict::invalid, p.limit ? "too_large" : "syntax", where + p.message);
  }
  const ex answer = *parsed.value;
  if (is_vector(answer)) return finish(Verdict::invalid, "syntax", "the answer is a vector; a single value was expected");
  // What the expression settles is the same however it was typed (2*m*g/4 and m*g/2): kept
  // from an earlier answer when there was one, else settled and kept (a budget run out is
  // not kept: another run may have the time).
  const std::string unknown = r.unknown;
  std::optional<SettledAnswers::Entry> entry = settled_->find(ref.name, answer);
  if (!entry) {
    entry.emplace(SettledAnswers::Entry{settle(ref, answer, std::move(r), over_budget), std::nullopt});
    const auto& findings = entry->result.findings;
    if (findings.empty() || findings.front().code != "budget") settled_->keep(ref.name, answer, *entry);
  }
  CheckResult settled = std::move(entry->result);
  settled.unknown = unknown;
  if (settled.verdict == Verdict::correct) note_simplified(ref, answer, text, settled);
  return settled;
}

// The answer's expression checked, as far as its spelling does not matter: the echo, the
// dimension, the values at the fixed points, then a decision (equal there) or a diagnosis.
CheckResult Checker::settle(const Reference& ref, const ex& answer, CheckResult r, const std::function<bool()>& over_budget) const {
  auto finish = [&](Verdict v, std::string code, std::string message) { return r.conclude(v, std::move(code), std::move(message)); };
  if (options_.echo_latex)
    std::tie(r.echo_text, r.echo_latex) = to_text_and_latex(answer);
  else
    r.echo_text = to_text(answer);
  // Dimensions, from the parameters' own.
  std::string problem;
  const auto dim = dimension_of(answer, *symbols_, problem);
  if (!dim && !problem.empty()) return finish(Verdict::incorrect, "dimension", "the answer is dimensionally inconsistent: it " + problem);
  if (dim && ref.dimension && !(*dim == *ref.dimension))
    return finish(Verdict::incorrect, "dimension",
                  "this is " + with_article(dim->describe()) + "; " + with_article(ref.dimension->describe()) + " was expected");
  // Numeric first (cheap, and it settles every wrong answer): the answer at the random points,
  // exactly in rationals where it can be, else in CLN floats to `digits`.
  const Program answer_at = program(answer);
  std::vector<numeric> values;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    if (over_budget()) return finish(Verdict::undecided, "budget", "the answer took too long to check");
    auto v = answer_at(points_[k]);
    if (!v)
      return finish(Verdict::undecided, "evaluation",
                    "the answer could not be evaluated at the test values (a division by zero, a negative square root, or a number too large to work with?)");
    values.push_back(*v);
  }
  bool equal = true;
  for (std::size_t k = 0; k < values.size(); ++k) equal = equal && same(values[k], ref.at_points[k]);
  if (equal) {
    // The fixed points prove nothing: anyone can find them and build an answer that vanishes
    // there. A proof decides, or points drawn for this check.
    const Decision d = decide(ref, substituted(answer, definitions_), over_budget);
    r.method = d.method;
    if (d.verdict != Verdict::correct) return finish(d.verdict, d.code, d.message);
    r.verdict = Verdict::correct;
    r.score = 1.0;
    r.summary = d.message;
    return r;
  }
  r.method = "numeric";
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  diagnose(ref, answer, answer_at, values, r);
  if (r.findings.empty()) r.findings.push_back({"value", "the answer differs from the correct one"});
  r.summary = r.findings.front().message;
  return r;
}

// A correct answer typed much longer than its canonical form: said (and with
// require_simplified, incorrect). Only such an answer is simplified (its simplest form is kept
// with what the expression settles).
void Checker::note_simplified(const Reference& ref, const ex& answer, std::string_view text, CheckResult& r) const {
  std::string typed;
  for (char c : text)
    if (!std::isspace(static_cast<unsigned char>(c))) typed += c;
  const auto longer = [](std::size_t a, std::size_t b) { return a > b + b / 2 + 4; };
  if (!longer(typed.size(), r.echo_text.size()) && !longer(typed.size(), ref.text_size)) return;
  const std::string simple = settled_->simplest(ref.name, answer, [&] { return to_text(simplest(answer)); });
  if (!longer(typed.size(), simple.size())) return;
  const std::string msg = "correct, but it simplifies to " + simple;
  r.findings.push_back({"not_simplified", msg});
  if (options_.require_simplified) {
    r.verdict = Verdict::incorrect;
    r.score = 0.0;
    r.summary = msg + " (a simplified answer is required)";
  }
}

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
          return std::any_of(states_.inputs().begin(), states_.inputs().end(), [&](const StateInput& in) { return in.angle && in.symbol.is_equal(x); });
        };
        if (angle(a.symbol) || angle(b.symbol)) continue;
        d.equalled[{i, j}] = at_points(ref.program, [&](Sample& pt) {
          if (const auto x = value_of(pt, a.symbol); x && value_of(pt, b.symbol)) set(pt, b.symbol, [&](const Sample&) { return *x; });
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
  static const std::vector<std::pair<int, numeric>> powers_of_two{{1, 2}, {-1, numeric(1, 2)}, {2, 4}, {-2, numeric(1, 4)},
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

void Checker::diagnose(const Reference& ref, const ex& answer, const Program& answer_at, const std::vector<numeric>& values, CheckResult& r) const {
  const std::size_t n = std::min(values.size(), ref.at_points.size());
  // The sign, or a constant factor (exact when the ratio simplifies to a number).
  bool constant_ratio = n > 0;
  std::optional<numeric> ratio;
  for (std::size_t k = 0; k < n && constant_ratio; ++k) {
    if (ref.at_points[k].is_zero()) {
      constant_ratio = false;
      break;
    }
    const numeric q = values[k] / ref.at_points[k];
    if (!ratio) ratio = q;
    else constant_ratio = same(q, *ratio);
  }
  if (constant_ratio && ratio) {
    // Exact when the values are; else the ratio rounded to a simple fraction.
    numeric c = *ratio;
    if (!c.is_rational())
      if (const auto simple = simple_fraction(c)) c = *simple;
    // Still irrational: a square root of a simple fraction (sqrt(3), sqrt(3)/2), said exactly.
    if (!c.is_rational() && std::abs(c.to_double()) < 1e6) {
      const double x2 = c.to_double() * c.to_double();
      for (int den = 1; den <= 12; ++den)
        if (std::abs(x2 * den - std::round(x2 * den)) < 1e-9 * std::max(1.0, x2 * den)) {
          const ex root = (c.is_positive() ? 1 : -1) * sqrt(ex(numeric(static_cast<long>(std::round(x2 * den)), den)));
          r.findings.push_back({"factor", "off by a factor of " + to_text(root) + " (the answer is " + to_text(root) +
                                              " times the correct answer)"});
          return;
        }
    }
    if (c == -1)
      r.findings.push_back({"sign", "the sign is wrong"});
    else
      r.findings.push_back({"factor", "off by a factor of " + to_text(c) + " (the answer is " + factor_words(c) + ")"});
    return;
  }
  // Past the sign and a factor: the answer with the definitions put in; the reference's part
  // made once.
  const Reference::Diagnosis& diag = diagnosis(ref);
  const ex expanded = substituted(answer, definitions_);
  // The symbols in the answer as typed and with the definitions put in (has() walks the
  // expression for each question: a diagnosis asks dozens).
  const auto typed_symbols = symbols_in(answer), used = symbols_in(expanded);
  bool trig = false;
  for (const_preorder_iterator it = expanded.preorder_begin(); it != expanded.preorder_end() && !trig; ++it)
    trig = is_ex_the_function(*it, sin) || is_ex_the_function(*it, cos);
  // Does the answer, at the points changed by `change`, take the reference's values
  // `reference` (at the same points changed as the diagnosis says)? Swapping two parameters or
  // setting one to zero changes the point, not the expression.
  auto matches_at = [&](const std::function<void(Sample&)>& change, const std::vector<std::optional<numeric>>& reference) {
    if (!points_.empty() && !reference.empty() && reference[0]) {  // most fail here, in doubles
      Sample first = points_[0];
      change(first);
      if (!maybe_same(answer_at.approx(doubles_from(first, points_[0], point_doubles_[0])), *reference[0])) return false;
    }
    for (std::size_t k = 0; k < points_.size(); ++k) {
      Sample pa = points_[k];
      change(pa);
      const auto a = answer_at(pa);
      if (!a || k >= reference.size() || !reference[k] || !same(*a, *reference[k])) return false;
    }
    return true;
  };
  std::vector<std::optional<numeric>> at_points(ref.at_points.begin(), ref.at_points.end());
  auto value_of = [](Sample& p, const ex& s) -> numeric* {
    for (auto& [sym, v] : p)
      if (sym.is_equal(s)) return &v;
    return nullptr;
  };
  // Does the answer take these values at the points?
  auto equals_at_points = [&](const std::vector<std::optional<numeric>>& other) {
    if (n == 0) return false;
    for (std::size_t k = 0; k < n; ++k)
      if (k >= other.size() || !other[k] || !same(values[k], *other[k])) return false;
    return true;
  };
  // The value of another unknown of the problem.
  for (const auto& [name, other] : references_) {
    if (name == ref.name || !(other.dimension == ref.dimension)) continue;
    bool all = other.at_points.size() == values.size() && !values.empty();
    for (std::size_t k = 0; all && k < values.size(); ++k) all = same(values[k], other.at_points[k]);
    if (all) r.findings.push_back({"other_unknown", "this is the value of " + name + ", not of " + ref.name});
  }
  // sin written for cos, or the reverse.
  // (Most fail at the first point in doubles, swapped as the answer's program runs: the
  // swapped expression is made only for those that pass.)
  if (trig && n > 0 && (point_doubles_.empty() || maybe_same(answer_at.approx(point_doubles_[0], true), ref.at_points[0]))) {
    SinCosSwapped swap;
    const ex swapped = swap(expanded);
    if (!swapped.is_equal(expanded)) {
      bool all = true;
      const Program swapped_at = program(swapped);
      for (std::size_t k = 0; all && k < n; ++k) {
        auto v = swapped_at(points_[k]);
        all = v && same(*v, ref.at_points[k]);
      }
      if (all) r.findings.push_back({"trig_swapped", "sin and cos are swapped"});
    }
  }
  // Most specific first: swapped parameters, special cases, a factor in the parameters,
  // then the parameters the answer has or lacks.
  std::vector<Finding> factor_findings;
  // (A power with a symbolic exponent, m^h^mu, is no factor a student meant, and normal() of
  // a tower of them takes seconds: found by fuzzing.)
  bool symbolic_exponent = false;
  for (const_preorder_iterator it = answer.preorder_begin(); it != answer.preorder_end(); ++it)
    symbolic_exponent = symbolic_exponent || (is_exactly<power>(*it) && !is_exactly<numeric>(it->op(1)));
  if (!symbolic_exponent) {
    // The quotient answer/reference, when it can be a factor worth saying (a few symbols):
    // 1. from the values, a product of powers of the parameters (mu h/l), or that it is
    //    neither such a product nor a function of at most two parameters (no factor said: a
    //    sum in three parameters, (l + h) mu, is missed);
    // 2. else, of rational functions whose factors are coprime at sight (see Factored): in
    //    lowest terms once equal factors cancel, without a gcd;
    // 3. else normal(), most of a wrong answer's diagnosis when it runs.
    std::optional<ex> quotient;
    bool simple = true;
    if (const auto shape = quotient_shape(ref, answer_at, values)) {
      quotient = shape->monomial;
      simple = shape->monomial || shape->depends_on <= 2;
    }
    bool factored = false;
    if (!quotient && simple && diag.factored && rational_function(expanded, lengths_)) {
      Factored q;
      if (q.put(expanded, 1)) {
        factored = true;
        q.coefficient /= diag.factored->first;
        for (const auto& [factor, k] : diag.factored->second) q.powers[factor] -= k;
        ex made = q.coefficient;
        for (const auto& [factor, k] : q.powers)
          if (k != 0) made *= GiNaC::pow(factor, k);
        // (In normal() for its canonical form only when small: a factor said is small.)
        if (node_count(made, 10) <= 9) quotient = normal(made);
      }
    }
    if (!quotient && simple && !factored) quotient = normal(expanded / ref.closed_form);
    if (quotient && !is_a<numeric>(*quotient) && node_count(*quotient, 8) <= 7)
      factor_findings.push_back({"factor", "off by a factor of " + to_text(*quotient)});
  }
  // Two parameters swapped.
  std::optional<Program> raw_at;  // the answer as typed over the extended points
  std::vector<ex> params;
  for (const auto& p : parameters_) params.push_back(p.symbol);
  for (std::size_t i = 0; i < params.size() && i < 16; ++i)
    for (std::size_t j = i + 1; j < params.size() && j < 16; ++j) {
      if (!typed_symbols.count(params[i]) && !typed_symbols.count(params[j])) continue;
      if ((definitions_.count(params[i]) || definitions_.count(params[j])) && !extended_points_.empty()) {
        // A defined parameter's value is in the extended points: swapped there, in the answer
        // as typed (the same as substituting the swap, then the definitions).
        if (!raw_at) raw_at.emplace(answer, extended_points_.front(), lengths_, extended_angles_);
        const auto in = [&](const Sample& p, const ex& x) {
          for (std::size_t at = 0; at < p.size(); ++at)
            if (p[at].first.is_equal(x)) return at;
          return p.size();
        };
        const Sample& first = extended_points_.front();
        const std::size_t a = in(first, params[i]), b = in(first, params[j]);
        if (a == first.size() || b == first.size()) continue;
        bool all = true;
        for (std::size_t k = 0; all && k < extended_points_.size() && k < ref.at_points.size(); ++k) {
          Sample pk = extended_points_[k];
          std::swap(pk[a].second, pk[b].second);
          if (k == 0) {  // (swapped in doubles: no value changes)
            std::vector<double> dk = extended_doubles_[0];
            std::swap(dk[a], dk[b]);
            all = maybe_same(raw_at->approx(dk), ref.at_points[0]);
          }
          if (!all) break;
          const auto v = (*raw_at)(pk);
          all = v && same(*v, ref.at_points[k]);
        }
        if (all) r.findings.push_back({"swapped", to_text(params[i]) + " and " + to_text(params[j]) + " are swapped"});
        continue;
      }
      if (definitions_.count(params[i]) || definitions_.count(params[j])) {
        // A defined parameter has no value of its own at the point: swap in the expression.
        const exmap swap{{params[i], params[j]}, {params[j], params[i]}};
        const ex swapped = substituted(substituted(answer, swap), definitions_);
        bool all = true;
        const Program swapped_at = program(swapped);
        for (std::size_t k = 0; all && k < points_.size(); ++k) {
          auto a = swapped_at(points_[k]);
          all = a && same(*a, ref.at_points[k]);
        }
        if (all) r.findings.push_back({"swapped", to_text(params[i]) + " and " + to_text(params[j]) + " are swapped"});
        continue;
      }
      const auto swap = [&](Sample& p) {
        numeric* x = value_of(p, params[i]);
        numeric* y = value_of(p, params[j]);
        if (x && y) std::swap(*x, *y);
      };
      if (matches_at(swap, at_points))
        r.findings.push_back({"swapped", to_text(params[i]) + " and " + to_text(params[j]) + " are swapped"});
    }
  // Correct only in a special case: a parameter at zero, or two parameters equal. Only: an
  // answer right at some of the points (|a| for a, where a > 0) is no special case.
  bool differs_everywhere = true;
  for (std::size_t k = 0; k < n && differs_everywhere; ++k) differs_everywhere = !same(values[k], ref.at_points[k]);
  for (std::size_t i = 0; i < params.size() && differs_everywhere; ++i) {
    const ex& p = params[i];
    const auto zeroed = diag.zeroed.find(i);
    if (zeroed == diag.zeroed.end() || used.count(p)) continue;
    if (matches_at([](Sample&) {}, zeroed->second)) r.findings.push_back({"special_case", "this is correct only " + describe(p)});
  }
  for (const auto& [pair, reference] : diag.equalled) {
    if (!differs_everywhere) break;
    const std::size_t i = pair.first, j = pair.second;  // (clang 14: a lambda cannot capture a structured binding)
    const auto equal_values = [&](Sample& pt) {
      numeric* x = value_of(pt, params[i]);
      numeric* y = value_of(pt, params[j]);
      if (x && y) *y = *x;
    };
    if (matches_at(equal_values, reference))
      r.findings.push_back({"special_case", "this is correct only when " + parameters_[i].name + " = " + parameters_[j].name});
  }
  // One term of the correct answer with the wrong sign, or missing (which term is not said:
  // that would give the answer away).
  for (std::size_t i = 0; i < diag.term_turned.size(); ++i) {
    if (equals_at_points(diag.term_turned[i])) {
      r.findings.push_back({"term_sign", "the sign of one term is wrong"});
      break;
    }
    if (equals_at_points(diag.term_left_out[i])) {
      r.findings.push_back({"missing_term", "one term of the correct answer is missing"});
      break;
    }
  }
  // One term too many: the answer is the correct one plus a single term (a product of the
  // parameters), when nothing above explains it.
  if (std::none_of(r.findings.begin(), r.findings.end(), [](const Finding& f) { return f.code == "term_sign" || f.code == "missing_term"; }) &&
      is_a<add>(diag.expanded) && node_count(expanded, 201) <= 200) {
    const ex answer_expanded = expanded.expand();
    const ex extra = (answer_expanded - diag.expanded).expand();
    if (!extra.is_zero() && !is_a<add>(extra) && !is_a<numeric>(extra) && is_a<add>(answer_expanded))
      r.findings.push_back({"extra_term", "the answer has one term too many"});
  }
  r.findings.insert(r.findings.end(), factor_findings.begin(), factor_findings.end());
  // Parameters the answer depends on, or misses (named in the problem's order).
  const auto& needed = diag.needed;
  std::vector<std::string> extra, missing;
  for (const auto& p : parameters_) {
    if (used.count(p.symbol) && !needed.count(p.symbol)) extra.push_back(p.name);
    if (needed.count(p.symbol) && !used.count(p.symbol)) missing.push_back(p.name);
  }
  auto words = [](const std::vector<std::string>& names) {
    if (names.size() == 1) return names[0];
    return join(std::vector<std::string>(names.begin(), names.end() - 1)) + " and " + names.back();
  };
  if (!extra.empty())
    r.findings.push_back({"extra_parameter", "the answer depends on " + words(extra) + ", which the correct answer does not"});
  if (!missing.empty())
    r.findings.push_back({"missing_parameter", "the correct answer depends on " + words(missing) + ", and this one does not"});
}

}  // namespace tackle

#include "check/check.hpp"
#include "check/equation.hpp"
#include "check/internal.hpp"

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
using namespace check_detail;

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

}  // namespace

namespace check_detail {

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

}  // namespace check_detail

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
    Reference ref{name,
                  closed,
                  program(closed),
                  dim,
                  std::nullopt,
                  {},
                  to_text(closed_form).size(),
                  {rational_function(closed, lengths_), expanded_size(closed), std::nullopt},
                  {}};
    if (ref.shape.rational && ref.shape.size <= static_cast<double>(options_.exact_size_budget))
      ref.shape.expanded = closed.expand();
    kinks_of(closed, ref.kinks);
    if (auto v = evaluate(closed, *symbols_, dim); v && is_a<numeric>(evalf(v->exact)))
      ref.value = ex_to<numeric>(evalf(v->exact));
    bool ok = true;
    for (std::size_t k = 0; k < points_.size() && ok; ++k) {
      auto v = ref.program(points_[k]);
      if (v)
        ref.at_points.push_back(*v);
      else
        ok = false;
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
    if (std::none_of(analysis.solution.free.begin(), analysis.solution.free.end(),
                     [&](const ex& f) { return general.has(f); }))
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
                      std::string("tackle failed while checking this (an internal error: ") + e.what() +
                          "), so it is left undecided");
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

Program Checker::program(const ex& e) const { return Program(e, states_.layout(), lengths_, states_.angles()); }

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
    if (auto near = nearest(unknown, known); !near.empty())
      msg += " (did you mean '" + near + "'?)";
    else
      msg += " (checkable: " + join(known) + ")";
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
      return invalid("not_an_answer",
                     "write '" + unknown + " = ...' or just the expression (found '" + printable(lhs) + " = ')");
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

namespace {}  // namespace

CheckResult Checker::check_expression(const Reference& ref, std::string_view text, CheckResult r,
                                      std::chrono::steady_clock::time_point start,
                                      const std::function<int(int)>& column) const {
  auto over_budget = [&] { return std::chrono::steady_clock::now() - start > options_.time_budget; };
  auto finish = [&](Verdict v, std::string code, std::string message) {
    return r.conclude(v, std::move(code), std::move(message));
  };
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
            hint = "unknown name '" + bad + "': did you mean '" + k +
                   "'? (names are case-sensitive; subscripts are written with _)";
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
  if (is_vector(answer))
    return finish(Verdict::invalid, "syntax", "the answer is a vector; a single value was expected");
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
CheckResult Checker::settle(const Reference& ref, const ex& answer, CheckResult r,
                            const std::function<bool()>& over_budget) const {
  auto finish = [&](Verdict v, std::string code, std::string message) {
    return r.conclude(v, std::move(code), std::move(message));
  };
  if (options_.echo_latex)
    std::tie(r.echo_text, r.echo_latex) = to_text_and_latex(answer);
  else
    r.echo_text = to_text(answer);
  // Dimensions, from the parameters' own.
  std::string problem;
  const auto dim = dimension_of(answer, *symbols_, problem);
  if (!dim && !problem.empty())
    return finish(Verdict::incorrect, "dimension", "the answer is dimensionally inconsistent: it " + problem);
  if (dim && ref.dimension && !(*dim == *ref.dimension))
    return finish(
        Verdict::incorrect, "dimension",
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
                    "the answer could not be evaluated at the test values (a division by zero, a negative square root, "
                    "or a number too large to work with?)");
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

}  // namespace tackle

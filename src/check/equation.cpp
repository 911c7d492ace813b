#include "check/equation.hpp"

#include <algorithm>
#include <set>

#include "equations/equations.hpp"

#include "core/utf8.hpp"
#include "expr/pairs.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "model/kinematics.hpp"
#include "core/units.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// Larger families are not decided: each state's elimination grows with the square of its
// equations.
constexpr std::size_t max_family = 300;

// Fixed points of a checker's states (the diagnoses use these alone) and fresh ones.
constexpr std::size_t fixed_points = 2;

// The problem's names, and a constant a length sum keeps (`const`, `C`, `C_s`, `L`, `L_1`) where
// the problem has no such name: a symbol of its own, made once per name.
class WithConstants : public NameResolver {
 public:
  WithConstants(const NameResolver& base, const std::map<std::string, ex, std::less<>>& defined)
      : base_(base), defined_(defined) {}
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto e = base_.resolve(name)) return e;
    if (const auto d = defined_.find(name); d != defined_.end()) return d->second;
    const bool constant = name == "const" || name == "C" || name == "L" ||
                          ((name.rfind("C_", 0) == 0 || name.rfind("L_", 0) == 0) && name.size() > 2);
    if (!constant) return std::nullopt;
    for (const auto& [n, s] : made_)
      if (n == name) return s;
    // Written upright in LaTeX when it is the word const.
    made_.emplace_back(std::string(name),
                       name == "const" ? symbol("const", "\\mathrm{const}") : symbol(std::string(name)));
    return made_.back().second;
  }
  std::vector<std::string> known_names() const override {
    std::vector<std::string> out = base_.known_names();
    for (const auto& [name, s] : defined_) out.push_back(name);
    return out;
  }
  [[nodiscard]] std::vector<ex> constants() const {
    std::vector<ex> out;
    for (const auto& [n, s] : made_) out.push_back(s);
    return out;
  }

 private:
  const NameResolver& base_;
  const std::map<std::string, ex, std::less<>>& defined_;
  mutable std::vector<std::pair<std::string, ex>> made_;
};

}  // namespace

namespace {

// Term `j` of a balance as a student reads it: its load's phrase ("a strand of string s at pA",
// "the weight of A", "the force on A"); a term from no load, by its sentence.
std::string term_phrase(const Equation& e, std::size_t j) {
  return j < e.origins.size() ? force_phrase(e.origins[j]) : generic_phrase(e.sources[j]);
}

using Rows = std::vector<Row>;

// The unknowns of a level: the symbols of these roles that its equations hold, and `more`
// (those the balances fix, a massless joint's coordinate), in the table's order.
std::vector<ex> unknowns_of(const SymbolTable& table, const std::vector<Equation>& equations,
                            const std::vector<SymbolRole>& roles, const std::vector<ex>& more,
                            const std::vector<ex>& given) {
  std::set<ex, ex_is_less> present;
  for (const auto& e : equations)
    for (const ex& s : symbols_in(e.lhs - e.rhs)) present.insert(s);
  std::vector<ex> out;
  for (const auto& s : table.all()) {
    const bool role = std::find(roles.begin(), roles.end(), s->role) != roles.end();
    if (contains(given, s->sym)) continue;
    if ((role && present.count(s->sym)) || contains(more, s->sym)) out.push_back(s->sym);
  }
  return out;
}

void add_new(std::vector<Equation>& to, const std::vector<Equation>& from) {
  for (const auto& e : from)
    if (std::none_of(to.begin(), to.end(), [&](const Equation& x) { return x.label == e.label; })) to.push_back(e);
}

// A constraint's constant quantity as an equation in the positions (the length sum 3 x_B - 2 x_A).
Equation position_equation(const ConstraintSteps& c) {
  const bool named = c.meaning.size() >= c.label.size() &&
                     c.meaning.compare(c.meaning.size() - c.label.size(), c.label.size(), c.label) == 0;
  Equation e;
  e.kind = Equation::Kind::constraint_position;
  e.label = named ? c.meaning : c.label + ": " + c.meaning;
  e.lhs = c.quantity;
  e.rhs = 0;
  e.terms = {c.quantity};
  e.sources = {"the " + c.meaning};
  return e;
}

// Every balance and constraint of the model: the complete set a description without `derive:`
// gets (none when the model cannot make it).
std::optional<EquationSystem> complete_set(const Model& m) {
  if (m.derive.empty()) return std::nullopt;
  try {
    Model copy = m;
    copy.derive.clear();
    return build_equations(copy);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Family family_of(const std::vector<const Equation*>& equations, std::vector<ex> unknowns, const exmap& definitions,
                 bool free_constants) {
  Family f;
  for (const Equation* e : equations) {
    f.labels.push_back(e->label);
    f.residuals.push_back(substituted(e->lhs - e->rhs, definitions));
  }
  f.unknowns = std::move(unknowns);
  f.free_constants = free_constants;
  return f;
}

std::vector<const Equation*> pointers(const std::vector<Equation>& v, std::size_t n = static_cast<std::size_t>(-1)) {
  std::vector<const Equation*> out;
  for (std::size_t i = 0; i < v.size() && i < n; ++i) out.push_back(&v[i]);
  return out;
}

// A state input for a symbol: drawn near its value, or near a coordinate's in the layout.
StateInput state_input(const SymbolInfo& s, const exmap& layout, bool angle) {
  std::optional<ex> v = s.value;
  if (!v)
    if (const auto it = layout.find(s.sym); it != layout.end()) v = it->second;
  return input_near(s.sym, v, angle);
}

// Whether x a + y b is a multiple of v at every point v has values at (made point by point:
// most candidates of a diagnosis fail at the first).
bool combined_matches(const Truth& truth, const Rows& a, const numeric& x, const Rows& b, const numeric& y,
                      const Rows& v) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (k >= a.size() || k >= b.size()) return false;
    Row c(a[k].size());
    for (std::size_t i = 0; i < c.size() && i < b[k].size(); ++i) c[i] = x * a[k][i] + y * b[k][i];
    if (!truth.proportional({c}, {v[k]})) return false;
  }
  return !v.empty();
}

}  // namespace

EquationChecker::EquationChecker(const Analysis& analysis, const CheckOptions& options)
    : options_(options), symbols_(analysis.model.symbols), definitions_(analysis.model.symbols->definitions(true)) {
  for (const auto& b : analysis.model.bodies)
    bodies_.push_back({b.name, b.has_mass ? b.mass : ex(0), kinematics::acceleration_symbol(analysis.model, b)});
  // The quantities the problem defines (`find: [{t_stop: ...}]`): a name of their own, their
  // definition put in before deciding.
  for (const auto& w : analysis.model.wanted) {
    if (!w.defined) continue;
    const SymbolInfo* s = symbols_->find(w.name);
    const ex name = s ? s->sym : ex(symbol(w.name, w.tex));
    defined_names_.emplace(w.name, name);
    defined_[name] = w.expr;
  }
  build_levels(analysis);
}

void EquationChecker::build_levels(const Analysis& analysis) {
  const Model& m = analysis.model;
  const SymbolTable& table = *symbols_;
  const std::optional<EquationSystem> complete = complete_set(m);
  // The derivation's equations first: a combination names them before the others.
  equations_ = analysis.system.equations;
  rate_equations_ = analysis.system.rate_equations;
  std::vector<ConstraintSteps> constraints = analysis.system.constraints;
  if (complete) {
    add_new(equations_, complete->equations);
    add_new(rate_equations_, complete->rate_equations);
    for (const auto& c : complete->constraints)
      if (std::none_of(constraints.begin(), constraints.end(),
                       [&](const ConstraintSteps& x) { return x.label == c.label; }))
        constraints.push_back(c);
  }
  for (const auto& c : constraints) {
    position_equations_.push_back(position_equation(c));
    position_differentiated_.push_back(c.label + ": acceleration");
  }
  std::vector<ex> more = analysis.system.unknowns;
  if (complete) more.insert(more.end(), complete->unknowns.begin(), complete->unknowns.end());
  const std::vector<ex> accelerations =
      unknowns_of(table, equations_, {SymbolRole::acceleration, SymbolRole::unknown}, more, m.given);
  const std::vector<ex> rates = unknowns_of(table, rate_equations_, {SymbolRole::rate}, {}, m.given);
  std::vector<ex> positions;
  for (const auto& s : table.all())
    if (s->role == SymbolRole::coordinate && !contains(accelerations, s->sym)) positions.push_back(s->sym);
  // The states' inputs: every other symbol without a definition, angles found in every equation.
  exset angles;
  for (const auto* v : {&equations_, &rate_equations_, &position_equations_})
    for (const auto& e : *v) angles_in(substituted(e.lhs - e.rhs, definitions_), angles);
  for (const auto& d : analysis.solution.values) angles_in(substituted(d.value, definitions_), angles);
  for (const auto& s : table.all()) {
    if (s->definition || contains(accelerations, s->sym)) continue;
    if (s->role == SymbolRole::defined || s->role == SymbolRole::motion) continue;
    inputs_.push_back(state_input(*s, m.layout, angles.count(s->sym) != 0));
  }
  auto level = [](Level& l, std::string name, std::vector<const Equation*> equations, std::vector<ex> unknowns) {
    l.name = std::move(name);
    l.equations = std::move(equations);
    l.unknowns = std::move(unknowns);
  };
  level(rate_, "constraints in rates", pointers(rate_equations_), rates);
  level(acceleration_, "balances and constraints", pointers(equations_), accelerations);
  level(position_, "length sums", pointers(position_equations_), positions);
  derivation_size_ = analysis.system.equations.size();
  for (const auto& c : m.conditions) conditions_.push_back({c.lhs, c.rhs, c.op});
}

// The states, then each level's algebra over them (a checker made for answers alone never
// pays for them).
void EquationChecker::prepare() const {
  std::call_once(prepared_, [&] {
    const States states(inputs_);
    std::vector<Sample> points;
    for (std::size_t k = 0; k < fixed_points; ++k) points.push_back(states.fixed(static_cast<int>(k)));
    std::mt19937 rng = States::generator(options_.seed);
    for (int k = 0; k < options_.points; ++k) points.push_back(states.draw(rng));
    const Tolerance tolerance{ex_to<numeric>(GiNaC::pow(numeric(10), numeric(-(options_.digits - 8))))};
    const exmap plain = symbols_->definitions();
    // A level decides with its equations (none past the bound: its checks are undecided).
    auto make = [&](Level& level, std::size_t count, bool free_constants) {
      if (level.equations.size() > max_family) return;
      const std::vector<const Equation*> used(level.equations.begin(),
                                              level.equations.begin() + static_cast<std::ptrdiff_t>(count));
      level.truth.emplace(family_of(used, level.unknowns, plain, free_constants), states, points, fixed_points,
                          definitions_, tolerance);
      if (count < level.equations.size()) level.equations = used;
    };
    // Rates: the constraints' in rates, solved at each point, so that the states are motions
    // the model allows (a rate the constraints fix is set to what they fix it to; the fixed
    // points' the same in every run).
    make(rate_, rate_.equations.size(), false);
    std::mt19937 same(5);
    if (rate_.truth && rate_.truth->usable())
      for (std::size_t k = 0; k < points.size(); ++k)
        if (const auto u = rate_.truth->solution(k, k < fixed_points ? same : rng))
          for (std::size_t j = 0; j < rate_.unknowns.size(); ++j)
            for (auto& [symbol, value] : points[k])
              if (symbol.is_equal(rate_.unknowns[j])) value = (*u)[j];
    make(acceleration_, acceleration_.equations.size(), false);
    // The complete set cannot decide (it contradicts itself at the states): the derivation's own.
    if (acceleration_.truth && !acceleration_.truth->usable() && acceleration_.equations.size() > derivation_size_)
      make(acceleration_, derivation_size_, false);
    if (acceleration_.truth) acceleration_.truth->restrict_to(conditions_);
    make(position_, position_.equations.size(), true);
  });
}

const Equation* EquationChecker::equation(const std::string& label) const {
  for (const auto* v : {&equations_, &position_equations_, &rate_equations_})
    for (const auto& e : *v)
      if (e.label == label) return &e;
  return nullptr;
}

std::string EquationChecker::differentiated(const std::string& label) const {
  for (std::size_t i = 0; i < position_equations_.size(); ++i)
    if (position_equations_[i].label == label) return position_differentiated_[i];
  return {};
}

namespace {

// A side without what a length sum's constant may be: plain numbers and the constants' names
// (3*x_B - 2*x_A = 5 compares a length with a number, which here is the string's length).
ex without_constants(const ex& side, const std::vector<ex>& constants) {
  auto constant = [&](const ex& t) { return is_exactly<numeric>(t) || contains(constants, t); };
  if (constant(side)) return 0;
  if (!is_exactly<add>(side)) return side;
  ex out = 0;
  for (const auto& t : side)
    if (!constant(t)) out += t;
  return out;
}

// The finding when the two sides' dimensions differ or one side's are inconsistent, if any.
std::optional<std::string> dimension_problem(const ex (&side)[2], const SymbolTable& table) {
  std::optional<Dimension> dim[2];
  for (int k = 0; k < 2; ++k) {
    std::string problem;
    dim[k] = dimension_of(side[k], table, problem);
    if (!dim[k] && !problem.empty())
      return std::string(k == 0 ? "the left" : "the right") + " side is dimensionally inconsistent: it " + problem;
  }
  const bool zero_side = side[0].is_zero() || side[1].is_zero();
  if (dim[0] && dim[1] && !(*dim[0] == *dim[1]) && !zero_side)
    return "the left side is " + with_article(dim[0]->describe()) + " and the right side " +
           with_article(dim[1]->describe());
  return std::nullopt;
}

bool has_any(const ex& e, const std::vector<ex>& symbols) {
  return std::any_of(symbols.begin(), symbols.end(), [&](const ex& s) { return e.has(s); });
}

}  // namespace

CheckResult EquationChecker::check(std::string_view text) const {
  prepare();
  CheckResult r;
  r.equation = true;
  auto finish = [&](Verdict v, std::string code, std::string message) {
    return r.conclude(v, std::move(code), std::move(message));
  };
  if (text.size() > options_.limits.max_length)
    return finish(Verdict::invalid, "too_large",
                  "the equation is too long (" + std::to_string(text.size()) + " characters; at most " +
                      std::to_string(options_.limits.max_length) + ")");
  if (const auto bad = invalid_utf8_at(text))
    return finish(Verdict::invalid, "syntax",
                  "at column " + std::to_string(*bad + 1) + ": the equation is not valid UTF-8 text");
  // One '=' at the top: "lhs = rhs".
  std::vector<std::size_t> equals;
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '=') equals.push_back(i);
  const bool relation = std::any_of(equals.begin(), equals.end(), [&](std::size_t i) {
    return (i > 0 && (text[i - 1] == '<' || text[i - 1] == '>' || text[i - 1] == '!')) ||
           (i + 1 < text.size() && text[i + 1] == '=');
  });
  if (equals.size() != 1 || relation)
    return finish(Verdict::invalid, "not_an_equation",
                  equals.empty()
                      ? "this is not an equation (expected one '=' between two sides, e.g. 2*T - F = m_A*ddot(x_A))"
                      : "write one '=' between the two sides (found " + std::to_string(equals.size()) + ")");
  const std::size_t eq = equals.front();
  const std::string_view sides[2] = {text.substr(0, eq), text.substr(eq + 1)};
  ex side[2];
  const WithConstants names(*symbols_, defined_names_);
  for (int k = 0; k < 2; ++k) {
    if (sides[k].find_first_not_of(" \t") == std::string_view::npos)
      return finish(Verdict::invalid, "not_an_equation",
                    std::string(k == 0 ? "the left" : "the right") + " side is empty");
    const ParseResult parsed = parse_expression(sides[k], names, options_.limits);
    if (!parsed.value) {
      const ParseProblem& p = parsed.problems.front();
      return finish(
          Verdict::invalid, p.limit ? "too_large" : "syntax",
          "at column " + std::to_string(p.column + 1 + (k == 0 ? 0 : static_cast<int>(eq) + 1)) + ": " + p.message);
    }
    if (is_vector(*parsed.value))
      return finish(Verdict::invalid, "syntax", "a side is a vector; write one component at a time");
    side[k] = *parsed.value;
  }
  // What the two sides settle is the same however they were typed (see SettledAnswers).
  const ex key = lst{side[0], side[1]};
  if (auto kept = settled_->find("=", key)) return std::move(kept->result);
  CheckResult settled = settle(side, names.constants(), std::move(r));
  settled_->keep("=", key, {settled, std::nullopt});
  return settled;
}

// The equation's two sides checked: its echo, its size, which level it is at, its dimensions,
// then the verdict there. `constants`: the names read as a length sum's constants.
CheckResult EquationChecker::settle(const ex (&side)[2], const std::vector<ex>& constants, CheckResult r) const {
  auto finish = [&](Verdict v, std::string code, std::string message) {
    return r.conclude(v, std::move(code), std::move(message));
  };
  r.echo_text = to_text(side[0]) + " = " + to_text(side[1]);
  if (options_.echo_latex) r.echo_latex = to_latex(side[0]) + " = " + to_latex(side[1]);
  const ex unexpanded = substituted(substituted(side[0] - side[1], defined_), symbols_->definitions());
  if (expanded_size(unexpanded) > static_cast<double>(options_.exact_size_budget))
    return finish(Verdict::undecided, "too_large",
                  "the equation expands into too many terms to be checked (at most " +
                      std::to_string(options_.exact_size_budget) + ")");
  const ex residual = unexpanded.expand();
  if (residual.is_zero())
    return finish(Verdict::incorrect, "trivial",
                  "the equation holds whatever the forces and the motion are (it reads 0 = 0 once simplified): it says "
                  "nothing about this problem");
  // Which level: the rates' equations when it has rates and no accelerations or forces; the
  // length sums' when it has neither, only coordinates (and a constant).
  const bool has_acceleration = has_any(residual, acceleration_.unknowns);
  const bool has_rate = has_any(residual, rate_.unknowns);
  const bool has_coordinate = has_any(residual, position_.unknowns);
  const bool position = has_coordinate && !has_acceleration && !has_rate && !position_.equations.empty();
  if (!constants.empty() && !position)
    return finish(
        Verdict::invalid, "syntax",
        "'" + to_text(constants.front()) +
            "' is not a name of this problem: a constant is for a length sum, an equation in the positions alone");
  const ex compared[2] = {position ? without_constants(side[0], constants) : side[0],
                          position ? without_constants(side[1], constants) : side[1]};
  if (const auto problem = dimension_problem(compared, *symbols_))
    return finish(Verdict::incorrect, "dimension", *problem);
  if (position) return position_verdict(position_, residual, r);
  return decide(has_rate && !has_acceleration ? rate_ : acceleration_, residual, r);
}

std::optional<Rows> EquationChecker::values_of(const Level& level, const ex& e, bool fixed_only) const {
  const auto parts = linear_parts(substituted(e, symbols_->definitions()), level.unknowns);
  if (!parts) return std::nullopt;
  return level.truth->values(*parts, fixed_only);
}

namespace {

bool all_zero(const Rows& rows) {
  return std::all_of(rows.begin(), rows.end(), [](const Row& r) {
    return std::all_of(r.begin(), r.end(), [](const numeric& x) { return x.is_zero(); });
  });
}

const char* const trivial_message =
    "the equation holds whatever the forces and the motion are (it reads 0 = 0 once simplified): it says nothing about "
    "this problem";

}  // namespace

// A linear equation: at the fixed points first (most wrong ones fail there, and are diagnosed
// with those values), then at the fresh ones.
CheckResult EquationChecker::decide_linear(const Level& level, const std::vector<ex>& parts, CheckResult r) const {
  const Truth& truth = *level.truth;
  auto values = truth.values(parts, true);
  if (values) {
    if (const Truth::Decision d = truth.holds(*values); d.answer == Truth::Answer::fails) {
      r.method = d.exact ? "exact rationals" : "numeric";
      return incorrect(level, *values, r);
    }
    if (const auto more = truth.values(parts, false, values->size()))
      values->insert(values->end(), more->begin(), more->end());
    else
      values.reset();
  }
  if (!values)
    return r.conclude(Verdict::undecided, "evaluation",
                      "the equation could not be evaluated at the test values (a division by zero, a negative square "
                      "root, or a number too large to work with?)");
  const Truth::Decision d = truth.holds(*values);
  r.method = d.exact ? "exact rationals" : "numeric";
  if (d.answer == Truth::Answer::fails) return incorrect(level, *values, r);
  if (d.answer == Truth::Answer::unknown)
    return r.conclude(Verdict::undecided, "points", "there are no random points to decide the equation at");
  if (all_zero(*values)) return r.conclude(Verdict::incorrect, "trivial", trivial_message);
  r.verdict = Verdict::correct;
  r.score = 1.0;
  name_it(level, *values, r);
  return r;
}

CheckResult EquationChecker::incorrect(const Level& level, const Rows& values, CheckResult r) const {
  diagnose(level, values, r);
  if (r.findings.empty())
    r.findings.push_back({"value", "the equation does not follow from the balances and constraints of this problem"});
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  r.summary = r.findings.front().message;
  return r;
}

CheckResult EquationChecker::decide(const Level& level, const ex& residual, CheckResult r) const {
  if (level.equations.size() > max_family)
    return r.conclude(Verdict::undecided, "too_large",
                      "this problem has too many equations to decide a combination of them (" +
                          std::to_string(level.equations.size()) + ")");
  if (!level.truth || !level.truth->usable())
    return r.conclude(Verdict::undecided, "model",
                      "tackle cannot decide an equation for this problem: its " + level.name +
                          " are not linear in the unknowns, or contradict each other");
  if (const auto parts = linear_parts(residual, level.unknowns)) return decide_linear(level, *parts, r);
  // Not linear in the unknowns: at random solutions (a ratio of accelerations, a root).
  const Truth& truth = *level.truth;
  const Truth::Decision d = truth.holds_anyhow(residual);
  r.method = d.exact ? "exact rationals" : "numeric";
  if (d.answer == Truth::Answer::unknown)
    return r.conclude(Verdict::undecided, "evaluation",
                      "the equation could not be evaluated at the motions the model allows (a division by zero, a "
                      "negative square root?)");
  if (d.answer == Truth::Answer::fails)
    return r.conclude(Verdict::incorrect, "value",
                      "the equation does not follow from the balances and constraints of this problem");
  if (truth.vanishes(residual).answer == Truth::Answer::holds)
    return r.conclude(Verdict::incorrect, "trivial", trivial_message);
  r.verdict = Verdict::correct;
  r.score = 1.0;
  r.summary = "it holds wherever the " + level.name + " do (it is not linear in the unknowns)";
  return r;
}

void EquationChecker::name_it(const Level& level, const Rows& values, CheckResult& r) const {
  for (std::size_t i = 0; i < level.equations.size(); ++i)
    if (level.truth->proportional(level.truth->equation_values(i), values))
      r.identified_as.push_back(level.equations[i]->label);
  if (!r.identified_as.empty()) {
    r.follows_from = {r.identified_as.front()};
    r.combination = {{r.identified_as.front(), true}};
  } else {
    for (const auto& part : level.truth->combination(values)) {
      r.follows_from.push_back(level.equations[part.equation]->label);
      r.combination.push_back({r.follows_from.back(), part.plain});
    }
  }
  const bool kept = level.equations.front()->kind == Equation::Kind::constraint_position;
  if (!r.identified_as.empty()) {
    r.summary = kept ? "it is the " + r.identified_as.front() + " kept constant" : "it is " + r.identified_as.front();
  } else if (r.follows_from.empty()) {
    r.summary = "it holds wherever the " + level.name + " do";
  } else {
    r.summary =
        "it follows from " + (r.follows_from.size() == 1
                                  ? r.follows_from.front()
                                  : join(std::vector<std::string>(r.follows_from.begin(), r.follows_from.end() - 1)) +
                                        " and " + r.follows_from.back());
  }
}

std::vector<std::string> EquationChecker::needed_for(const ex& unknown, const ex& closed_form) const {
  prepare();
  const Level& level = acceleration_;
  if (!level.truth || !level.truth->usable()) return {};
  const auto values = values_of(level, unknown - closed_form, false);
  if (!values || level.truth->holds(*values).answer != Truth::Answer::holds) return {};
  std::vector<std::string> out;
  for (const auto& part : level.truth->combination(*values)) out.push_back(level.equations[part.equation]->label);
  return out;
}

CheckResult EquationChecker::position_verdict(const Level& level, const ex& residual, CheckResult r) const {
  if (level.equations.size() > max_family)
    return r.conclude(Verdict::undecided, "too_large",
                      "this problem has too many constraints to decide a combination of them (" +
                          std::to_string(level.equations.size()) + ")");
  const auto parts = linear_parts(residual, level.unknowns);
  if (!level.truth || !level.truth->usable() || !parts)
    return r.conclude(Verdict::undecided, "not_linear",
                      "tackle decides an equation in the positions when it and the problem's length sums are linear in "
                      "the positions");
  const auto values = level.truth->values(*parts);
  if (!values)
    return r.conclude(Verdict::undecided, "evaluation",
                      "the equation could not be evaluated at the test values (a division by zero?)");
  const Truth::Decision d = level.truth->holds(*values);
  r.method = d.exact ? "exact rationals" : "numeric";
  if (d.answer == Truth::Answer::holds) {
    // The positions' part holds. What is left is the constant the sum keeps: any constant will
    // do (it depends on where the positions are measured from and on the string's length);
    // the level drops it. A constant in the problem's own names says which constant it is,
    // which depends on the origin: not decided. (A sum that is kept by nothing is incorrect
    // whatever its constant: y_R = d_Q + l_0 where y_R moves.)
    for (const ex& s : symbols_in(parts->back()))
      if (symbols_->find(s))
        return r.conclude(Verdict::undecided, "constant",
                          "the constant a length sum keeps depends on where the positions are measured from, so tackle "
                          "cannot tell whether it is " +
                              to_text(parts->back().is_zero() ? ex(0) : -parts->back()) +
                              ": write it as const, C or a number");
    r.verdict = Verdict::correct;
    r.score = 1.0;
    name_it(level, *values, r);
    return r;
  }
  // The constraint whose positions these are, where there is one: its sum is not this one.
  std::vector<const Equation*> sharing;
  for (std::size_t i = 0; i < level.equations.size(); ++i) {
    const auto own = linear_parts(level.truth->family().residuals[i], level.unknowns);
    if (!own) continue;
    bool inside = true, shares = false;
    for (std::size_t j = 0; j + 1 < parts->size(); ++j) {
      if ((*parts)[j].is_zero()) continue;
      if ((*own)[j].is_zero())
        inside = false;
      else
        shares = true;
    }
    if (inside && shares) sharing.push_back(level.equations[i]);
  }
  if (sharing.size() == 1) {
    const std::string& what = sharing.front()->label;
    r.findings.push_back(
        {"length_sum",
         "this is not the " + what + " kept constant" +
             (what.rfind("length of string", 0) == 0 ? ": count the strands at each point the string passes" : "")});
  } else {
    r.findings.push_back({"value", "the equation does not follow from the constraints of this problem"});
  }
  r.verdict = Verdict::incorrect;
  r.score = 0.0;
  r.summary = r.findings.front().message;
  return r;
}

const std::vector<EquationChecker::Level::Terms>& EquationChecker::terms_of(const Level& level) const {
  std::call_once(level.made, [&] {
    for (const Equation* e : level.equations) {
      Level::Terms t;
      for (const ex& term : e->terms) t.terms.push_back(values_of(level, term, true));
      t.lhs = values_of(level, e->lhs, true);
      other_bodies(level, *e, t);
      level.terms.push_back(std::move(t));
    }
  });
  return level.terms;
}

void EquationChecker::other_bodies(const Level& level, const Equation& e, Level::Terms& t) const {
  if (e.kind != Equation::Kind::lmb || e.system || e.bodies.size() != 1 || e.rhs.is_zero()) return;
  const BodyTerms& own = bodies_[static_cast<std::size_t>(e.bodies.front())];
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const BodyTerms& other = bodies_[i];
    if (&other == &own) continue;
    if (!own.mass.is_zero() && !other.mass.is_zero() && !other.mass.is_equal(own.mass))
      if (auto w = values_of(level, e.lhs - e.rhs.subs(own.mass == other.mass), true))
        t.other_mass.emplace_back(i, std::move(*w));
    if (is_a<symbol>(own.accel) && is_a<symbol>(other.accel) && !other.accel.is_equal(own.accel))
      if (auto w = values_of(level, e.lhs - e.rhs.subs(own.accel == other.accel), true))
        t.other_acceleration.emplace_back(i, std::move(*w));
  }
}

void EquationChecker::diagnose(const Level& level, const Rows& values, CheckResult& r) const {
  const Rows v(values.begin(),
               values.begin() + static_cast<std::ptrdiff_t>(std::min(values.size(), level.truth->fixed())));
  for (std::size_t ei = 0; ei < level.equations.size(); ++ei) {
    const Equation* e = level.equations[ei];
    if (e->kind != Equation::Kind::lmb && e->kind != Equation::Kind::amb) continue;
    diagnose_balance(level, ei, v, r);
    diagnose_other_forces(level, ei, v, r);
  }
  // A force missing or turned is more specific than the inertial term (N_A + N_B = 0 is the
  // vertical balance without the weight, and also the horizontal one without m a).
  const auto rank = [](const Finding& x) { return x.code == "missing_inertia" || x.code == "inertia_sign" ? 1 : 0; };
  std::stable_sort(r.findings.begin(), r.findings.end(),
                   [&](const Finding& a, const Finding& b) { return rank(a) < rank(b); });
}

namespace {

Rows first_rows(const Rows& all, std::size_t n) {
  return Rows(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(std::min(all.size(), n)));
}

void say(CheckResult& r, const std::string& code, const std::string& message) {
  for (const auto& f : r.findings)
    if (f.message == message) return;
  r.findings.push_back({code, message});
}

}  // namespace

// The balance `ei` with one of its forces left out or turned, its inertial term left out or
// turned, another body's mass or acceleration in it: is the student's that, up to a factor?
void EquationChecker::diagnose_balance(const Level& level, std::size_t ei, const Rows& v, CheckResult& r) const {
  const Equation* e = level.equations[ei];
  const Level::Terms& t = terms_of(level)[ei];
  const Rows whole = first_rows(level.truth->equation_values(ei), level.truth->fixed());
  const std::string& name = e->label;
  const bool lmb = e->kind == Equation::Kind::lmb;
  for (std::size_t j = 0; j < t.terms.size() && j < e->sources.size(); ++j) {
    if (!t.terms[j]) continue;
    const std::string what = term_phrase(*e, j);
    if (combined_matches(*level.truth, whole, 1, *t.terms[j], -1, v))
      say(r, "missing_force", what + " is missing (" + name + ")");
    else if (combined_matches(*level.truth, whole, 1, *t.terms[j], -2, v))
      say(r, "force_sign", what + " has the wrong sign or direction (" + name + ")");
  }
  if (e->rhs.is_zero() || !t.lhs) return;
  if (level.truth->proportional(*t.lhs, v))
    say(r, "missing_inertia",
        lmb ? "the mass times acceleration term is missing (" + name + ")"
            : "the rate of change of angular momentum is missing (" + name + ")");
  if (lmb && !e->system && e->bodies.size() == 1) {
    const BodyTerms& own = bodies_[static_cast<std::size_t>(e->bodies.front())];
    for (const auto& [i, w] : t.other_mass)
      if (level.truth->proportional(w, v))
        say(r, "wrong_mass", "the mass is " + bodies_[i].name + "'s, not " + own.name + "'s (" + name + ")");
    for (const auto& [i, w] : t.other_acceleration)
      if (level.truth->proportional(w, v))
        say(r, "wrong_acceleration",
            "the acceleration is " + bodies_[i].name + "'s, not " + own.name + "'s (" + name + ")");
  }
  if (combined_matches(*level.truth, *t.lhs, 2, whole, -1, v))
    say(r, "inertia_sign",
        lmb ? "the mass times acceleration term has the wrong sign (" + name + ")"
            : "the rate of change of angular momentum has the wrong sign (" + name + ")");
}

// The balance `ei` with a force of another balance added: it acts on another body (or, the same
// force as one of its own, it is counted once too often).
void EquationChecker::diagnose_other_forces(const Level& level, std::size_t ei, const Rows& v, CheckResult& r) const {
  const Equation* e = level.equations[ei];
  const Rows whole = first_rows(level.truth->equation_values(ei), level.truth->fixed());
  for (std::size_t oi = 0; oi < level.equations.size(); ++oi) {
    const Equation* other = level.equations[oi];
    if (other == e || other->kind != e->kind) continue;
    const Level::Terms& t = terms_of(level)[oi];
    for (std::size_t j = 0; j < other->terms.size() && j < other->sources.size() && j < t.terms.size(); ++j) {
      if (!t.terms[j] || std::find(e->sources.begin(), e->sources.end(), other->sources[j]) != e->sources.end())
        continue;
      for (const int sign : {1, -1}) {
        if (!combined_matches(*level.truth, whole, 1, *t.terms[j], sign, v)) continue;
        // Taking away one of the balance's own forces is a force missing (said above); the
        // same force as one of its own is one counted once too often (a strand more); else
        // a force on another body.
        const ex added = sign * other->terms[j];
        std::string again;
        bool removal = false;
        for (std::size_t i = 0; i < e->terms.size() && i < e->sources.size(); ++i) {
          removal = removal || (e->terms[i] + added).is_zero();
          if (again.empty() && (e->terms[i] - added).is_zero()) again = term_phrase(*e, i);
        }
        if (removal) continue;
        if (!again.empty())
          say(r, "extra_force", "one force too many: " + again + " is counted once too often (" + e->label + ")");
        else
          say(r, "extra_force", term_phrase(*other, j) + " does not act on what " + e->label + " balances");
      }
    }
  }
}

}  // namespace tackle

#include "solve/bounds.hpp"

#include <unordered_set>

#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// The unit a parameter is stated in (deg, km/h): its bounds are said in it.
std::optional<Unit> stated_unit(const SymbolInfo* s) {
  if (!s || !s->dimension || s->unit.empty()) return std::nullopt;
  return Unit{s->unit_to_si, *s->dimension, s->unit};
}

// The sign of a number's SI value: -1, 0 or +1 (0 also when it cannot be told).
int sign_at(const ex& si) {
  const ex x = evalf(si);
  if (!is_a<numeric>(x) || !ex_to<numeric>(x).is_real() || ex_to<numeric>(x).is_zero()) return 0;
  return ex_to<numeric>(x).is_positive() ? 1 : -1;
}

bool lower_bound(const std::string& op) { return op == ">=" || op == ">"; }

// The parameter a form is solved for: p for `p op ...` and for `p^2 op ...`.
ex base_of(const ex& parameter) { return is_a<power>(parameter) ? parameter.op(0) : parameter; }

}  // namespace

std::optional<BoundNumber> bound_number(const SolvedFor& form, const SymbolTable& table, int digits,
                                        const exmap& definitions) {
  const bool square = is_a<power>(form.parameter);
  const ex p = base_of(form.parameter);
  const SymbolInfo* s = table.find(p);
  const std::optional<Dimension> dim = s ? s->dimension : std::nullopt;
  const std::optional<Unit> unit = stated_unit(s);
  ex bound = form.bound;
  for (int depth = 0; depth < 4 && !definitions.empty(); ++depth) bound = substituted(bound, definitions);
  const auto value = square ? evaluate(bound, table, dim ? std::optional<Dimension>(dim->pow(2)) : std::nullopt, digits)
                            : evaluate(bound, table, dim, digits, unit);
  if (!value) return std::nullopt;
  BoundNumber out{*value, std::nullopt, false, false};
  const bool positive_bound = sign_at(value->si) > 0;
  if (square && positive_bound) out.root = evaluate(sqrt(bound), table, dim, digits, unit);
  if (p.info(info_flags::positive) && !positive_bound) (lower_bound(form.op) ? out.every_value : out.no_value) = true;
  return out;
}

void number_bounds(std::vector<SolvedFor>& forms, const SymbolTable& table, int digits, const exmap& definitions) {
  for (auto& f : forms) f.number = bound_number(f, table, digits, definitions);
}

namespace {

using SymbolSet = std::unordered_set<ex, ExHash, ex_is_equal>;

// A condition's names, and those its defined names stand for (v and R in dot(theta) = v/R).
struct Names {
  SymbolSet direct, through_definitions;
};

Names names_of(const ConditionReport& c, const SymbolTable& table) {
  Names out;
  const auto found = distinct_symbols(c.simplified);
  out.direct.insert(found.begin(), found.end());
  for (const SymbolInfo* d : table.defined())
    if (out.direct.count(d->sym) != 0)
      for (const ex& x : distinct_symbols(*d->definition)) out.through_definitions.insert(x);
  return out;
}

// One condition's bound on p, into `r`; false when the range cannot be told from it.
// `evaluated`: some bound of p was an expression (not a number already said as one).
bool narrow(ParameterRange& r, const ConditionReport& c, const Names& names, bool& evaluated) {
  if (c.always == true) return true;
  if (names.through_definitions.count(r.parameter) != 0) return false;  // it moves a defined name too
  if (names.direct.count(r.parameter) == 0) return c.holds == true;     // p cannot mend it
  const auto f = std::find_if(c.solved.begin(), c.solved.end(),
                              [&](const SolvedFor& x) { return base_of(x.parameter).is_equal(r.parameter); });
  if (f == c.solved.end() || !f->number || f->number->no_value) return false;
  evaluated = evaluated || !is_a<numeric>(f->bound);
  if (f->number->every_value) return true;
  const bool square = is_a<power>(f->parameter);
  if (square && !f->number->root) return false;
  const NumericValue& v = square ? *f->number->root : f->number->value;
  const bool lower = lower_bound(f->op), strict = f->op == ">" || f->op == "<";
  std::optional<NumericValue>& side = lower ? r.low : r.high;
  bool& side_strict = lower ? r.low_strict : r.high_strict;
  // The tighter of the two: the greater lower bound, the lesser upper one (strict when equal).
  const int against = side ? sign_at(v.si - side->si) : (lower ? 1 : -1);
  if (against == 0) {
    side_strict = side_strict || strict;
  } else if ((against > 0) == lower) {
    side = v;
    side_strict = strict;
  }
  return true;
}

}  // namespace

std::vector<ParameterRange> ranges_at_numbers(const std::vector<ConditionReport>& conditions, const SymbolTable& table,
                                              int digits) {
  std::vector<ex> parameters;
  for (const auto& c : conditions)
    for (const auto& f : c.solved)
      if (!contains(parameters, base_of(f.parameter))) parameters.push_back(base_of(f.parameter));
  if (parameters.empty()) return {};
  // Each condition's names, gathered once (a chain's conditions are long sums).
  std::vector<Names> symbols;
  for (const auto& c : conditions) symbols.push_back(names_of(c, table));
  std::vector<ParameterRange> out;
  for (const ex& p : parameters) {
    ParameterRange r;
    r.parameter = p;
    bool known = true, evaluated = false;
    for (std::size_t i = 0; i < conditions.size() && known; ++i)
      known = narrow(r, conditions[i], symbols[i], evaluated);
    if (!known || !evaluated) continue;
    const SymbolInfo* s = table.find(p);
    r.given = evaluate(p, table, s ? s->dimension : std::nullopt, digits, stated_unit(s));
    if (r.low && r.high) {
      const int order = sign_at(r.high->si - r.low->si);
      r.empty = order < 0 || (order == 0 && (r.low_strict || r.high_strict));
    }
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace tackle

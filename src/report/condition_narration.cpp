// The validity conditions as the derivation tells them: each as the rule states it, its
// closed form, the forms solved for a parameter with their numbers, a condition that always
// or never holds in words, and each parameter's range with the others at their given values.
// Narration only: the numbers are made in src/solve/bounds.cpp.
#include "report/narrator.hpp"

#include <algorithm>
#include <unordered_set>

#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

std::pair<std::string, std::vector<ex>> listed_names(const std::vector<ex>& xs) {
  std::string s;
  std::vector<ex> shown;
  std::vector<std::optional<std::pair<std::string, long>>> shapes;
  for (const auto& x : xs) shapes.push_back(index_shape(to_text(x)));
  for (std::size_t i = 0; i < xs.size();) {
    std::size_t run = 1;
    if (shapes[i])
      while (i + run < xs.size() && shapes[i + run] && shapes[i + run]->first == shapes[i]->first &&
             shapes[i + run]->second == shapes[i]->second + static_cast<long>(run))
        ++run;
    s += shown.empty() ? "{}" : ", {}";
    shown.push_back(xs[i]);
    if (run >= 5) {
      s += ", ..., {}";
      shown.push_back(xs[i + run - 1]);
      i += run;
    } else {
      ++i;
    }
  }
  return std::make_pair(s, shown);
}

namespace {

// What the closed form's sign is when a condition always (or never) holds: `expr op 0`.
std::string sign_words(const std::string& op, bool holds) {
  if (op == "=") return holds ? "always zero" : "never zero";
  const bool lower = op == ">=" || op == ">", strict = op == ">" || op == "<";
  // holds for >=: never negative; fails for >=: always negative; and so on.
  const std::string side = lower ? "negative" : "positive", other = lower ? "positive" : "negative";
  if (holds) return strict ? "always " + other : "never " + side;
  return strict ? "never " + other : "always " + side;
}

}  // namespace

void narrate_always(Narrator& n, const std::string& lead, const ex& shown, const ex& expr, const std::string& op,
                    bool holds, const std::string& otherwise) {
  // In the order the description names them (g, m_1, ..., m_33).
  const auto found = distinct_symbols(expr);
  const std::unordered_set<ex, ExHash, ex_is_equal> present(found.begin(), found.end());
  std::vector<ex> names;
  std::unordered_set<ex, ExHash, ex_is_equal> named;
  for (const auto& s : n.table.all())
    if (present.count(s->sym) != 0 && named.insert(s->sym).second) names.push_back(s->sym);
  // (a symbol the table does not hold, if any, after them, by name)
  std::vector<ex> others;
  for (const ex& x : found)
    if (named.count(x) == 0) others.push_back(x);
  std::sort(others.begin(), others.end(), [](const ex& a, const ex& b) { return to_text(a) < to_text(b); });
  names.insert(names.end(), others.begin(), others.end());
  auto [list, listed] = listed_names(names);
  // The last of a few names after "and": g, m and theta.
  if (const auto last = list.rfind(", {}"); last != std::string::npos && list.find("...") == std::string::npos)
    list.replace(last, 2, " and ");
  std::vector<ex> math{shown};
  math.insert(math.end(), listed.begin(), listed.end());
  const std::string outcome = names.empty() ? (holds ? "always holds" : "never holds")
                                            : std::string(holds ? "holds" : "fails") + " for every value of " + list;
  n.text_with(lead + sign_words(op, holds) + ": this " + outcome + (holds ? "." : ": " + otherwise + "."),
              std::move(math));
}

void narrate_solved(Narrator& n, const SolvedFor& form, std::string label, std::vector<ex> math) {
  Step* st = n.equation(std::move(label), form.parameter, form.bound);
  st->math = std::move(math);
  st->relation = form.op;
  if (!form.number) return;
  const BoundNumber& b = *form.number;
  if (is_a<numeric>(form.bound)) return;  // a number already (F >= 0)
  // A square's bound as the square of the bound on the parameter: (19.1206 m/s)^2.
  st->note = with_unit(b.root ? b.root : b.value);
  st->note_squared = b.root.has_value();
  const ex p = is_a<power>(form.parameter) ? form.parameter.op(0) : form.parameter;
  const std::string where = b.value.approx < 0 ? "below 0" : "0";
  if (b.every_value)
    n.text_with(
        "The bound is " + where + ", so every value of {} down to 0 satisfies it: nothing is asked of it from below.",
        {p});
  else if (b.no_value)
    n.text_with("The bound is " + where + ", so no value of {} satisfies it.", {p});
}

namespace {

void narrate_condition(Narrator& n, const ConditionReport& r, const std::function<ex(const ex&)>& named) {
  n.text(r.source + ": the model holds while " + r.meaning + ":");
  Step* rule = n.equation(r.source, r.lhs, r.rhs);
  rule->relation = r.op;
  if (r.always) {
    narrate_always(n, "With the solution, {} is ", named(r.simplified), r.simplified, r.op, *r.always, r.otherwise);
  } else {
    Step* closed = n.equation("closed form", named(r.simplified), 0);
    closed->relation = r.op;
    if (!r.solved.empty() &&
        !(r.solved.size() == 1 && r.solved[0].bound.is_zero() && r.simplified.is_equal(r.solved[0].parameter))) {
      n.text(r.solved.size() == 1 ? "It holds exactly when:" : "It holds exactly when (each form is equivalent):");
      for (const auto& sv : r.solved) {
        const bool provided = !sv.provided.is_zero();
        std::vector<ex> math{sv.parameter};
        if (provided) math.push_back(sv.provided);
        narrate_solved(n, sv, provided ? "solved for {}, while {} > 0 (as at the given numbers)" : "solved for {}",
                       std::move(math));
      }
    }
  }
  if (r.holds)
    n.text(*r.holds ? "This holds for the given numbers."
                    : "This is VIOLATED for the given numbers: " + r.otherwise + ".");
  else if (r.depends_on_free)
    n.text("This depends on an unknown the equations do not determine.");
}

// A number with its unit as display math: `5.3187\,\mathrm{m/s}`.
std::pair<std::string, std::string> number_forms(const NumericValue& v) {
  return {with_unit(v), v.decimal + (v.unit.empty() ? "" : "\\," + unit_latex(v.unit))};
}

// One parameter's range as one piece of math: `5.3187 m/s <= v <= 19.1206 m/s`, `mu >= 0.19245`.
ex range_math(const ParameterRange& r, const SymbolTable& table) {
  const SymbolInfo* s = table.find(r.parameter);
  std::string text = to_text(r.parameter), tex = s ? s->tex : text;
  if (r.low && !r.high) {
    const auto [t, x] = number_forms(*r.low);
    return symbol(text + (r.low_strict ? " > " : " >= ") + t, tex + (r.low_strict ? " > " : " \\ge ") + x);
  }
  if (r.low) {
    const auto [t, x] = number_forms(*r.low);
    text = t + (r.low_strict ? " < " : " <= ") + text;
    tex = x + (r.low_strict ? " < " : " \\le ") + tex;
  }
  if (r.high) {
    const auto [t, x] = number_forms(*r.high);
    text += (r.high_strict ? " < " : " <= ") + t;
    tex += (r.high_strict ? " < " : " \\le ") + x;
  }
  return symbol(text, tex);
}

void narrate_ranges(Narrator& n, const std::vector<ParameterRange>& ranges) {
  if (ranges.empty()) return;
  n.text("In numbers, each parameter on its own (the others at their given values), the model holds for:");
  for (const auto& r : ranges) {
    const std::string given = r.given ? " (given: " + with_unit(r.given) + ")" : "";
    if (r.empty)
      n.step(Step::Kind::bullet, "no value of {}: it would need {}" + given)->math = {r.parameter,
                                                                                      range_math(r, n.table)};
    else if (!r.low && !r.high)
      n.step(Step::Kind::bullet, "every value of {}" + given)->math = {r.parameter};
    else
      n.step(Step::Kind::bullet, "{}" + given)->math = {range_math(r, n.table)};
  }
}

}  // namespace

void narrate_validity(Narrator& n, const std::vector<ConditionReport>& conditions,
                      const std::vector<ParameterRange>& ranges, const std::function<ex(const ex&)>& named) {
  if (conditions.empty()) return;
  n.section("Validity");
  for (const auto& r : conditions) narrate_condition(n, r, named);
  narrate_ranges(n, ranges);
}

}  // namespace tackle

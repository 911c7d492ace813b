// Appending steps to a Derivation: sections, prose (with typeset expressions), bullets and
// equations (defined parameters folded back in). The derivation and the motion narration
// both tell their story through it.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "report/derivation.hpp"

namespace tackle {

/// A number with its unit ("20 N"), or "" when there is none.
inline std::string with_unit(const std::optional<NumericValue>& v) {
  if (!v) return {};
  return v->decimal + (v->unit.empty() ? "" : " " + v->unit);
}

struct Narrator {
  Derivation& d;
  const SymbolTable& table;

  Step* step(Step::Kind kind, std::string t) {
    Step st;
    st.kind = kind;
    st.text = std::move(t);
    d.steps.push_back(std::move(st));
    return &d.steps.back();
  }
  void section(std::string t) { step(Step::Kind::section, std::move(t)); }
  void text(std::string t) { step(Step::Kind::text, std::move(t)); }
  // Prose with expressions: each "{}" in `t` is typeset from the next of `math`.
  void text_with(std::string t, std::vector<GiNaC::ex> math) {
    step(Step::Kind::text, std::move(t))->math = std::move(math);
  }
  void bullet(std::string t) { step(Step::Kind::bullet, std::move(t)); }
  Step* equation(std::string label, const GiNaC::ex& lhs, const GiNaC::ex& rhs) {
    Step* st = step(Step::Kind::equation, std::move(label));
    st->lhs = fold_definitions(lhs, table);
    st->rhs = fold_definitions(rhs, table);
    return st;
  }
};

/// A list of names as prose: runs of five or more names of one shape with indices going up
/// by one are written with dots (x_1, ..., x_256), so that 511 unknowns make a line. Returns
/// the text with a placeholder per name shown, and those names.
[[nodiscard]] std::pair<std::string, std::vector<GiNaC::ex>> listed_names(const std::vector<GiNaC::ex>& xs);

/// A condition solved for a parameter, as an equation (`label` with its "{}"s filled from
/// `math`) with its bound's number, and what a bound at or below 0 means for a positive
/// parameter (report/condition_narration.cpp).
void narrate_solved(Narrator& n, const SolvedFor& form, std::string label, std::vector<GiNaC::ex> math);

/// A condition that holds (or fails) whatever the values, in words and never as a trivial
/// inequality: `lead` with a "{}" for `shown`, then its sign and the names it holds for
/// ("With the solution, g m is never negative: this holds for every value of g and m.").
void narrate_always(Narrator& n, const std::string& lead, const GiNaC::ex& shown, const GiNaC::ex& expr,
                    const std::string& op, bool holds, const std::string& otherwise);

/// The Validity section: each condition, its closed form, its solved forms with their
/// numbers, a condition that always or never holds in words; then each parameter's range at
/// the given numbers. `named` names what the closed forms share (the derivation's sum).
void narrate_validity(Narrator& n, const std::vector<ConditionReport>& conditions,
                      const std::vector<ParameterRange>& ranges,
                      const std::function<GiNaC::ex(const GiNaC::ex&)>& named);

}  // namespace tackle

// Appending steps to a Derivation: sections, prose (with typeset expressions), bullets and
// equations (defined parameters folded back in). The derivation and the motion narration
// both tell their story through it.
#pragma once

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
  void text_with(std::string t, std::vector<GiNaC::ex> math) { step(Step::Kind::text, std::move(t))->math = std::move(math); }
  void bullet(std::string t) { step(Step::Kind::bullet, std::move(t)); }
  Step* equation(std::string label, const GiNaC::ex& lhs, const GiNaC::ex& rhs) {
    Step* st = step(Step::Kind::equation, std::move(label));
    st->lhs = fold_definitions(lhs, table);
    st->rhs = fold_definitions(rhs, table);
    return st;
  }
};

}  // namespace tackle

// What the format writers share: prose with typeset expressions, headings, names of
// statuses and kinds, the answers as result steps, sheets' problems with their values.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "report/derivation.hpp"
#include "report/key.hpp"
#include "report/sheet.hpp"

namespace tackle::writers {

[[nodiscard]] std::string status_name(Answer::Status s);
[[nodiscard]] std::string kind_name(Equation::Kind k);
[[nodiscard]] std::string tex_relation(const std::string& op);
/// A number with its unit ("20 N"), or "".
[[nodiscard]] std::string value_text(const std::optional<NumericValue>& v);
/// An equation step's number (its note) as text: "20 N", or "(19.1206 m/s)^2" when squared.
[[nodiscard]] std::string note_text(const Step& st);
/// The same in LaTeX: `20\,\mathrm{N}`, `(19.1206\,\mathrm{m/s})^{2}`.
[[nodiscard]] std::string note_latex(const Step& st);
/// A step's text with its "{}" placeholders filled from its expressions, in format `f`
/// (text: as text; LaTeX: escaped prose, $math$; Markdown: $math$; HTML: escaped, KaTeX spans).
[[nodiscard]] std::string prose(const Step& st, Format f);
/// Text from the description (a title, a statement) for Markdown, whose readers pass HTML
/// through: `<`, `>` and `&` as entities outside $math$, `<` and `>` as \lt and \gt inside
/// it (where an entity would be shown as typed), so that no tag reaches the page.
[[nodiscard]] std::string markdown_text(const std::string& s);
/// The title of a derivation, with its phase when it is one of a phased description's.
[[nodiscard]] std::string heading(const Derivation& d);
/// The closed forms as boxed equations with their numbers (`solve`'s report).
[[nodiscard]] std::vector<Step> result_steps(const Derivation& d);

/// One problem of a sheet: its title (with the variant), what it asks, and its values.
struct SheetProblem {
  int number = 0;
  std::string title;
  const Derivation* derivation = nullptr;
  const Model* model = nullptr;
  std::map<std::string, Quantity> values;  // the description's, a variant's over them
  GiNaC::exmap variant_values;             // a variant's drawn values (SI, by symbol); empty: the description's
  bool last_of_entry = false;
};
[[nodiscard]] std::vector<SheetProblem> sheet_problems(const std::vector<SheetEntry>& entries);
/// The statement with each {name} replaced by its value and unit: `$140\,\mathrm{N}$` for
/// LaTeX and HTML (`math`), `140 N` for Markdown. A problem without a `statement` gets one
/// generated from its description (its bodies, connections and given values).
[[nodiscard]] std::string statement_of(const SheetProblem& p, bool math);

/// The drawn figures' steps of a derivation: the mechanism's sketch, and the free body
/// diagrams when `diagrams`.
[[nodiscard]] std::vector<const Step*> figures_of(const Derivation& d, bool diagrams);
/// A sheet problem's figures (as figures_of): a variant's drawn again at its own values, and
/// left out where they cannot be drawn there.
[[nodiscard]] std::vector<Step> sheet_figures(const SheetProblem& p, bool diagrams);

/// The key's variant table: its header names ("#", the parameters, the answers).
[[nodiscard]] std::vector<std::string> variant_head(const KeyEntry& e);

/// Installs the person's order of factors for LaTeX while it lives, for the names of every
/// derivation given (each problem of a key or a sheet, each phase).
class Ordered {
 public:
  explicit Ordered(const std::vector<const Derivation*>& ds);

 private:
  std::optional<PersonOrder> order_;
};

}  // namespace tackle::writers

// A derivation shown in a notebook (Jupyter; the Python module's rich display): an HTML
// fragment that the notebook's page hosts and whose math the page's MathJax typesets, and
// the equations in LaTeX. Written by the HTML and LaTeX writers (report/writers/), as their
// documents are.
#pragma once

#include <string>

#include "model/model.hpp"
#include "report/derivation.hpp"

namespace tackle {

enum class NotebookView {
  problem,     // the statement with its numbers, the sketch, what is asked, the answers boxed
               // with their numbers, and the whole derivation folded in a <details>
  derivation,  // the whole derivation, as `derive --format html` shows it
  answers,     // the answers only, as `solve --format html` shows them
};

/// `d` (its model `m`) as a fragment of HTML: one <div id="`id`"> with its own style scoped
/// to it, its title as a heading; no document around it and no script. Math as `\(...\)` and
/// `\[...\]` in spans for the page's MathJax; figures as inline SVG whose ids begin with
/// `id` (letters, digits and '-': unique on the page).
[[nodiscard]] std::string notebook_html(const Derivation& d, const Model& m, const std::string& id, NotebookView view);

/// The equations of `d` (every one when `full`, else the results) as one align* block, each
/// labelled by \tag*: LaTeX that MathJax typesets and that a LaTeX document (nbconvert's) takes.
[[nodiscard]] std::string notebook_latex(const Derivation& d, bool full);

}  // namespace tackle

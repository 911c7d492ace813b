// A page to try the step checker (issue "check the student's work", part 4): one
// self-contained HTML page (KaTeX inlined) with the problem as a sheet shows it (its statement
// with its numbers, its sketch, what is asked) and a worked-solution form (equations, final
// answers, free body diagrams), each step sent to a checker as it is typed and its verdict shown
// beside it; the whole solution graded on request. The checker answers JSON over POST
// (docs/checking.md, "A page to try it"): `scripts/step-server` is one.
#pragma once

#include <string>

#include "model/model.hpp"
#include "report/derivation.hpp"

namespace tackle {

/// Whether `endpoint` can be the page's checker: empty (the page's own location), a path or an
/// http(s) URL, without spaces, quotes, `;`, `,`, `<`, `>`, `\`, `?` or `#` (it goes into the
/// page's Content-Security-Policy). Returns "" when it can, else what is wrong.
[[nodiscard]] std::string endpoint_problem(const std::string& endpoint);

/// The page for `d` (its model `m`): the form posts each step to `{endpoint}/step` and the
/// solution to `{endpoint}/solution` (relative `step` and `solution` when `endpoint` is empty);
/// the page connects to nothing else (its policy says so). std::invalid_argument when
/// endpoint_problem() finds a problem; SetupError without KaTeX.
[[nodiscard]] std::string step_page(const Derivation& d, const Model& m, const std::string& endpoint = "");

}  // namespace tackle

// HTML pages: one self-contained file, KaTeX (Debian's libjs-katex) inlined with its fonts,
// so that a report opens anywhere with no network.
#pragma once

#include <stdexcept>
#include <string>

namespace tackle {

/// Something the machine lacks (KaTeX for HTML): said as it is, exit code 3.
struct SetupError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// `s` with &, <, > and " escaped.
[[nodiscard]] std::string html_escape(const std::string& s);
/// LaTeX math for KaTeX to typeset in the page (inline, or displayed).
[[nodiscard]] std::string html_math(const std::string& tex, bool display = false);
/// A whole page: `body` (HTML) under `title`, with KaTeX's script, style and fonts inlined
/// from TACKLE_KATEX_DIR (default: where libjs-katex installs it). Throws SetupError
/// naming the file when KaTeX is not there. `head`: more of the page's head (HTML), after
/// KaTeX and the common style (a page's own policy, style and script).
[[nodiscard]] std::string html_page(const std::string& title, const std::string& body, const std::string& head = "");

}  // namespace tackle

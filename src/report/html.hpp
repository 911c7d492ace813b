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

/// While one lives (on its thread), the HTML writers write a fragment for a page that is not
/// tackle's and typesets math itself, with MathJax (a Jupyter notebook, an exported notebook):
/// html_math writes `\(tex\)` and `\[tex\]` in its span, which that MathJax finds, and every id
/// of the fragment (each figure's arrowhead) begins with `ids`, so that two fragments on one
/// page do not share one.
class HostedHtml {
 public:
  explicit HostedHtml(std::string ids);
  ~HostedHtml();
  HostedHtml(const HostedHtml&) = delete;
  HostedHtml& operator=(const HostedHtml&) = delete;
  /// The one living on this thread, or null (a page of tackle's own).
  [[nodiscard]] static const HostedHtml* current();
  [[nodiscard]] const std::string& ids() const { return ids_; }

 private:
  std::string ids_;
  const HostedHtml* outer_;
};

/// The style of a derivation's content (equations, figures, tables), every selector under
/// `scope` (a fragment's own id: "#tackle-1f3a .eq{...}"), for a page whose own style is not
/// tackle's.
[[nodiscard]] std::string content_style(const std::string& scope);

}  // namespace tackle

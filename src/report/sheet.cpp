#include "report/sheet.hpp"

#include <map>

#include "core/placeholders.hpp"
#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "report/html.hpp"
#include "report/tex.hpp"

namespace tackle {

namespace {

// The statement with each {name} replaced by the value (number and unit) at hand.
std::string filled(const std::string& statement, const std::map<std::string, Quantity>& values, bool latex) {
  std::string out;
  std::size_t from = 0;
  for (const auto& p : placeholders(statement)) {
    out += statement.substr(from, p.open - from);
    const auto it = values.find(std::string(p.name));
    if (it == values.end()) {
      out += statement.substr(p.open, p.close - p.open + 1);
    } else if (latex) {
      out += "$" + it->second.number + (it->second.unit.empty() ? "" : "\\," + unit_latex(it->second.unit)) + "$";
    } else {
      out += it->second.text();
    }
    from = p.close + 1;
  }
  return out + statement.substr(from);
}

// A statement's text for HTML: its $math$ for KaTeX, the rest escaped.
std::string html_statement(const std::string& s) {
  std::string out;
  bool math = false;
  std::string run;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '$') {
      run += '$';
      ++i;
    } else if (s[i] == '$') {
      out += math ? html_math(run) : html_escape(run);
      run.clear();
      math = !math;
    } else {
      run += s[i];
    }
  }
  return out + (math ? html_escape("$" + run) : html_escape(run));
}

}  // namespace

std::string write_sheet(const std::vector<SheetEntry>& entries, Format f, bool figures) {
  const bool latex = f == Format::latex, html = f == Format::html;
  std::optional<PersonOrder> order;
  if (!entries.empty() && entries[0].derivation->symbols) order.emplace(factor_rank(entries[0].derivation->symbols));
  std::string out = latex ? "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
                            "\\usepackage[margin=2.5cm]{geometry}\n\\usepackage{tikz}\n\\begin{document}\n"
                          : html ? "<h1>Problems</h1>\n" : "";
  int number = 0;
  for (const auto& e : entries) {
    const Derivation& d = *e.derivation;
    // The description's own values, then a variant's drawn ones over them.
    std::map<std::string, Quantity> base;
    for (const auto& p : d.parameters) {
      const auto& v = p.stated ? p.stated : p.si;
      if (v && p.kind == "parameter") base[p.name] = {p.name, v->decimal, v->unit, v->approx};
    }
    std::vector<std::map<std::string, Quantity>> sheets;
    if (e.variants.empty()) sheets.push_back(base);
    for (const auto& v : e.variants) {
      auto values = base;
      for (const auto& q : v.parameters) values[q.name] = q;
      sheets.push_back(values);
    }
    for (std::size_t k = 0; k < sheets.size(); ++k) {
      ++number;
      const std::string title = d.title + (e.variants.empty() ? "" : " (variant " + std::to_string(e.variants[k].index) + ")");
      std::vector<std::string> asked;
      for (const auto& a : d.answers) asked.push_back(html ? html_math(a.tex) : "$" + a.tex + "$");
      const std::string statement = e.model && e.model->statement ? filled(e.model->statement->text, sheets[k], latex || html) : "";
      // The drawn free body diagrams, when asked for.
      std::string drawn;
      if (figures)
        for (const auto& st : d.steps)
          if (st.kind == Step::Kind::figure) {
            if (latex) drawn += "\\begin{center}\n" + to_tikz(*st.figure) + "\\\\[2pt]{\\small " + tex_escape(st.text) + "}\n\\end{center}\n";
            else drawn += "<figure>\n" + to_svg(*st.figure) + "<figcaption>" + (html ? html_escape(st.text) : st.text) + "</figcaption>\n</figure>\n\n";
          }
      if (latex) {
        out += "\\section*{Problem " + std::to_string(number) + ": " + tex_escape(title) + "}\n";
        if (!statement.empty()) out += statement + "\n\n";
        out += drawn;
        out += "Find " + join(asked) + ".\n";
        if (k + 1 < sheets.size()) out += "\\clearpage\n";
      } else if (html) {
        out += "<h2>Problem " + std::to_string(number) + ": " + html_escape(title) + "</h2>\n";
        if (!statement.empty()) out += "<p>" + html_statement(statement) + "</p>\n";
        out += drawn;
        out += "<p>Find " + join(asked) + ".</p>\n";
      } else {
        out += "## Problem " + std::to_string(number) + ": " + title + "\n\n";
        if (!statement.empty()) out += statement + "\n\n";
        out += drawn;
        out += "Find " + join(asked) + ".\n\n";
      }
    }
  }
  if (html) return html_page("Problems", out);
  return out + (latex ? "\\end{document}\n" : "");
}

}  // namespace tackle

// The HTML format: one self-contained page per document, every formula typeset by KaTeX
// (inlined by html.cpp), figures as inline SVG: the derivation, the phases, the answer key,
// the sheets.
#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "report/html.hpp"
#include "report/notebook.hpp"
#include "report/sweep.hpp"
#include "report/writer.hpp"
#include "report/writers/common.hpp"
#include "report/break.hpp"

namespace tackle {

using namespace GiNaC;
using namespace writers;

namespace {

std::string html_figure(const Step& st) {
  const HostedHtml* hosted = HostedHtml::current();
  return "<figure>\n" + to_svg(*st.figure, hosted ? hosted->ids() + "-" : "") + "<figcaption>" + html_escape(st.text) +
         "</figcaption>\n</figure>\n";
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

// One equation: typeset by KaTeX, its label as a tag, its number as a note.
std::string html_equation(const Step& st) {
  const std::string note = st.note.empty() ? "" : " \\quad \\left(= " + note_latex(st) + "\\right)";
  const std::string lhs = to_latex(st.lhs), rel = st.equals_constant ? "=" : tex_relation(st.relation);
  const std::string rhs = st.equals_constant ? "\\text{const}" : to_latex(st.rhs);
  // A formula too wide for the column is broken (a broken one is not boxed).
  const double width = 58 - 0.5 * static_cast<double>(st.text.size());
  std::string body = displayed(lhs, rel, rhs, note, std::max(30.0, width));
  if (st.boxed && body.rfind("\\begin{aligned}", 0) != 0) body = "\\boxed{" + lhs + " " + rel + " " + rhs + "}" + note;
  std::string out = "<div class=\"eq\">" + html_math(body, true);
  if (!st.text.empty()) out += "<span class=\"tag\">(" + prose(st, Format::html) + ")</span>";
  return out + "</div>\n";
}

// The body of one derivation (its title a heading of `level`, none when empty), without the
// page around it.
std::string html_body(const Derivation& d, bool full, const std::string& title, int level) {
  const std::string h = std::to_string(level), h2 = std::to_string(level + 1);
  std::string out = title.empty() ? "" : "<h" + h + ">" + html_escape(title) + "</h" + h + ">\n";
  if (!full) {
    for (const auto& st : result_steps(d)) out += html_equation(st);
    return out;
  }
  bool in_list = false, in_table = false;
  for (const auto& st : d.steps) {
    const bool listed = st.kind == Step::Kind::bullet, table = st.kind == Step::Kind::given;
    if (in_list && !listed) out += "</ul>\n";
    if (!in_list && listed) out += "<ul>\n";
    if (in_table && !table) out += "</table>\n";
    if (!in_table && table)
      out += "<table class=\"parameters\">\n<tr><th>Parameter</th><th>Value</th><th>Unit</th></tr>\n";
    in_list = listed;
    in_table = table;
    switch (st.kind) {
      case Step::Kind::section: out += "<h" + h2 + ">" + html_escape(st.text) + "</h" + h2 + ">\n"; break;
      case Step::Kind::text: out += "<p>" + prose(st, Format::html) + "</p>\n"; break;
      case Step::Kind::bullet: out += "<li>" + prose(st, Format::html) + "</li>\n"; break;
      case Step::Kind::given:
        out += "<tr><td>" + html_math(to_latex(st.lhs)) + "</td><td class=\"number\">" + html_escape(st.number) +
               "</td><td>" + (st.note.empty() ? "" : html_math(unit_latex(st.note))) + "</td></tr>\n";
        break;
      case Step::Kind::equation: out += html_equation(st); break;
      case Step::Kind::figure: out += html_figure(st); break;
    }
  }
  if (in_list) out += "</ul>\n";
  if (in_table) out += "</table>\n";
  // The plots, as SVG: the described sweep, the motion integrated numerically.
  if (d.sweep_plot) out += "<h" + h2 + ">Sweep</h" + h2 + ">\n<figure>\n" + sweep_svg(*d.sweep_plot) + "</figure>\n";
  if (d.motion_plot) {
    out += "<h" + h2 + ">Motion, integrated numerically</h" + h2 + ">\n";
    for (const auto& e : d.motion_events) out += "<p>" + html_escape(e) + "</p>\n";
    out += "<figure>\n" + sweep_svg(*d.motion_plot) + "</figure>\n";
  }
  return out;
}

// One problem of a sheet, below its heading: the statement, the figures, what is asked.
std::string html_problem(const SheetProblem& p, bool figures) {
  std::vector<std::string> asked;
  for (const auto& a : p.derivation->answers) asked.push_back(html_math(a.tex));
  const std::string statement = statement_of(p, true);
  std::string out;
  if (!statement.empty()) out += "<p>" + html_statement(statement) + "</p>\n";
  for (const Step& st : sheet_figures(p, figures)) out += html_figure(st);
  return out + "<p>Find " + join(asked) + ".</p>\n";
}

class HtmlWriter final : public Writer {
 public:
  const char* name() const override { return "html"; }
  std::string derivation(const Derivation& d, bool full) const override {
    return html_page(heading(d), html_body(d, full, heading(d), 1));
  }
  std::string phases(const std::vector<Derivation>& ds, bool full) const override {
    std::string body = "<h1>" + html_escape(ds[0].title) + "</h1>\n";
    for (const auto& d : ds) body += html_body(d, full, "Phase " + std::to_string(d.phase_number) + ": " + d.phase, 2);
    return html_page(ds[0].title, body);
  }

  std::string key(const std::vector<KeyEntry>& entries) const override {
    std::string out = "<h1>Answer key</h1>\n";
    for (const auto& e : entries) {
      const Derivation& d = *e.derivation;
      std::vector<std::string> asked;
      for (const auto& a : d.answers) asked.push_back(html_math(to_latex(a.symbol)));
      out += "<h2>" + html_escape(d.title) + "</h2>\n<p>Find " + join(asked) + ".</p>\n";
      for (const auto& a : d.answers) {
        if (a.closed_form) {
          const std::string value =
              a.value ? " = " + a.value->decimal + (a.value->unit.empty() ? "" : "\\," + unit_latex(a.value->unit))
                      : "";
          const std::string eq = displayed(to_latex(a.symbol), "=", to_latex(*a.closed_form), value, 58);
          out += "<div class=\"eq\">" + html_math(eq, true) + "</div>\n";
        } else if (a.general) {
          out += "<div class=\"eq\">" + html_math(to_latex(a.symbol) + " = " + to_latex(*a.general), true) +
                 "<span class=\"tag\">(not determined alone)</span></div>\n";
        }
      }
      if (e.variants.empty()) {
        if (e.variants_asked) out += "<p>No variants: no parameter of this problem has a <code>range</code>.</p>\n";
        continue;
      }
      std::map<std::string, std::string> tex;
      for (const auto& p : d.parameters) tex[p.name] = p.tex;
      for (const auto& a : d.answers) tex[a.name] = a.tex;
      out += "<table class=\"parameters\">\n<tr>";
      for (const auto& h : variant_head(e))
        out += "<th>" +
               (h == "#"                          ? std::string("#")
                : tex.count(h) && !tex[h].empty() ? html_math(tex[h])
                                                  : html_escape(h)) +
               "</th>";
      out += "</tr>\n";
      auto cell = [](const Quantity& q) {
        return "<td class=\"number\">" + html_math(q.number + (q.unit.empty() ? "" : "\\," + unit_latex(q.unit))) +
               "</td>";
      };
      for (const auto& v : e.variants) {
        out += "<tr><td>" + std::to_string(v.index) + "</td>";
        for (const auto& q : v.parameters) out += cell(q);
        for (const auto& q : v.answers) out += cell(q);
        out += "</tr>\n";
      }
      out += "</table>\n";
    }
    return html_page("Answer key", out);
  }

  std::string sheet(const std::vector<SheetEntry>& entries, bool figures) const override {
    std::string out = "<h1>Problems</h1>\n";
    for (const auto& p : sheet_problems(entries))
      out += "<h2>Problem " + std::to_string(p.number) + ": " + html_escape(p.title) + "</h2>\n" +
             html_problem(p, figures);
    return html_page("Problems", out);
  }
};

}  // namespace

std::string sheet_problem_html(const SheetEntry& e, bool figures) {
  const auto problems = sheet_problems({e});
  if (problems.empty()) return "";
  writers::Ordered order({e.derivation});
  return html_problem(problems.front(), figures);
}

std::string notebook_html(const Derivation& d, const Model& m, const std::string& id, NotebookView view) {
  const HostedHtml hosted(id);
  writers::Ordered order({&d});
  std::string out = "<div class=\"tackle\" id=\"" + id + "\">\n<style>\n#" + id + "{line-height:1.45}\n#" + id +
                    " details>summary{cursor:pointer;font-weight:600;margin:.6em 0}\n" + content_style("#" + id) +
                    "</style>\n";
  if (view == NotebookView::problem) {
    out += "<h3>" + html_escape(heading(d)) + "</h3>\n" + sheet_problem_html(SheetEntry{&d, &m, {}});
    const std::vector<Step> results = result_steps(d);
    for (const auto& st : results) out += html_equation(st);
    out += "<details>\n<summary>Derivation: the free body diagrams and equations</summary>\n" +
           html_body(d, true, "", 3) + "</details>\n";
  } else {
    out += html_body(d, view == NotebookView::derivation, heading(d), 3);
  }
  return out + "</div>\n";
}

const Writer& html_writer() {
  static const HtmlWriter w;
  return w;
}

}  // namespace tackle

// The Markdown format: $math$ for the formulas, figures as inline SVG, tables for the
// parameters and the variants: the derivation, the phases, the answer key, the sheets.
#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "report/sweep.hpp"
#include "report/writer.hpp"
#include "report/writers/common.hpp"

namespace tackle {

using namespace GiNaC;
using namespace writers;

namespace {

// A drawn figure as raw HTML (CommonMark passes it through).
std::string markdown_figure(const Step& st) {
  return "<figure>\n" + to_svg(*st.figure) + "<figcaption>" + markdown_text(st.text) + "</figcaption>\n</figure>\n\n";
}

std::string markdown_document(const Derivation& d, bool full) {
  std::string out = "# " + markdown_text(heading(d)) + "\n\n";
  auto eq = [](const Step& st) {
    std::string body = st.equals_constant ? to_latex(st.lhs) + " = \\text{const}"
                                          : to_latex(st.lhs) + " " + tex_relation(st.relation) + " " + to_latex(st.rhs);
    if (st.boxed) body = "\\boxed{" + body + "}";
    std::string line = "$$" + body + "$$" + (st.text.empty() ? "" : " *(" + prose(st, Format::markdown) + ")*");
    if (!st.note.empty()) line += " = " + note_text(st);
    return line + "\n\n";
  };
  if (full) {
    bool in_list = false, in_table = false;
    for (const auto& st : d.steps) {
      const bool listed = st.kind == Step::Kind::bullet, table = st.kind == Step::Kind::given;
      if ((in_list && !listed) || (in_table && !table)) out += "\n";
      if (table && !in_table)
        out += (in_list ? "\n" : "") + std::string("| Parameter | Value | Unit |\n|---|--:|---|\n");
      in_list = listed;
      in_table = table;
      switch (st.kind) {
        case Step::Kind::section: out += "## " + markdown_text(st.text) + "\n\n"; break;
        case Step::Kind::text: out += prose(st, Format::markdown) + "\n\n"; break;
        case Step::Kind::bullet: out += "- " + prose(st, Format::markdown) + "\n"; break;
        case Step::Kind::given:
          out += "| $" + to_latex(st.lhs) + "$ | " + st.number + " | " +
                 (st.note.empty() ? "" : "$" + unit_latex(st.note) + "$") + " |\n";
          break;
        case Step::Kind::equation: out += eq(st); break;
        case Step::Kind::figure: out += markdown_figure(st); break;
      }
    }
    // The plots, as SVG: the described sweep, the motion integrated numerically.
    if (d.sweep_plot) out += "## Sweep\n\n<figure>\n" + sweep_svg(*d.sweep_plot) + "</figure>\n\n";
    if (d.motion_plot) {
      out += "## Motion, integrated numerically\n\n";
      for (const auto& e : d.motion_events) out += markdown_text(e) + "\n\n";
      out += "<figure>\n" + sweep_svg(*d.motion_plot) + "</figure>\n\n";
    }
  } else {
    for (Step st : result_steps(d)) {
      st.boxed = false;  // Markdown's answers stay plain
      out += eq(st);
    }
  }
  return out;
}

class MarkdownWriter final : public Writer {
 public:
  const char* name() const override { return "markdown"; }
  std::string derivation(const Derivation& d, bool full) const override { return markdown_document(d, full); }
  std::string phases(const std::vector<Derivation>& ds, bool full) const override {
    std::string out;
    for (const auto& d : ds) out += markdown_document(d, full);
    return out;
  }

  std::string key(const std::vector<KeyEntry>& entries) const override {
    std::string out = "# Answer key\n";
    for (const auto& e : entries) {
      const Derivation& d = *e.derivation;
      std::vector<std::string> asked;
      for (const auto& a : d.answers) asked.push_back("$" + to_latex(a.symbol) + "$");
      out += "\n## " + markdown_text(d.title) + "\n\nFind " + join(asked) + ".\n\n";
      for (const auto& a : d.answers) {
        if (a.closed_form) {
          out += "- $" + to_latex(a.symbol) + " = " + to_latex(*a.closed_form) + "$";
          if (a.value) out += " = " + a.value->decimal + (a.value->unit.empty() ? "" : " " + a.value->unit);
          out += "\n";
        } else if (a.general) {
          out += "- $" + to_latex(a.symbol) + " = " + to_latex(*a.general) + "$ (not determined alone)\n";
        }
      }
      if (e.variants.empty()) {
        if (e.variants_asked) out += "\nNo variants: no parameter of this problem has a `range`.\n";
        continue;
      }
      const std::vector<std::string> head = variant_head(e);
      out += "\nVariants:\n\n| " + join(head, " | ") + " |\n|";
      for (std::size_t i = 0; i < head.size(); ++i) out += "---|";
      out += "\n";
      for (const auto& v : e.variants) {
        std::vector<std::string> cells{std::to_string(v.index)};
        for (const auto& q : v.parameters) cells.push_back(q.text());
        for (const auto& q : v.answers) cells.push_back(q.text());
        out += "| " + join(cells, " | ") + " |\n";
      }
    }
    return out;
  }

  std::string sheet(const std::vector<SheetEntry>& entries, bool figures) const override {
    std::string out;
    for (const auto& p : sheet_problems(entries)) {
      std::vector<std::string> asked;
      for (const auto& a : p.derivation->answers) asked.push_back("$" + a.tex + "$");
      const std::string statement = statement_of(p, false);
      out += "## Problem " + std::to_string(p.number) + ": " + markdown_text(p.title) + "\n\n";
      if (!statement.empty()) out += markdown_text(statement) + "\n\n";
      for (const Step& st : sheet_figures(p, figures)) out += markdown_figure(st);
      out += "Find " + join(asked) + ".\n\n";
    }
    return out;
  }
};

}  // namespace

const Writer& markdown_writer() {
  static const MarkdownWriter w;
  return w;
}

}  // namespace tackle

// The LaTeX format: standalone documents that compile with pdflatex (lmodern, amsmath,
// TikZ figures, siunitx tables): the derivation, the phases, the answer key, the sheets.
#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "report/notebook.hpp"
#include "report/sweep.hpp"
#include "report/tex.hpp"
#include "report/writer.hpp"
#include "report/writers/common.hpp"
#include "report/break.hpp"

namespace tackle {

using namespace GiNaC;
using namespace writers;

namespace {

// A drawn figure, centred, with its caption: one box, which a page never splits.
std::string latex_figure(const Step& st) {
  // Scaled down to the line where it is wider (a wide 2-D diagram), never up.
  return "\\begin{center}\n\\begin{minipage}{\\linewidth}\\centering\n"
         "\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{%\n" +
         to_tikz(*st.figure) + "}\\\\[2pt]{\\small " + tex_escape(st.text) + "}\n\\end{minipage}\n\\end{center}\n";
}

// One line of an align* block: aligned on its relation (a boxed result is one box, aligned
// at its start), its number as a note, its label as a tag.
std::string latex_line(const Step& st) {
  const std::string lhs = to_latex(st.lhs);
  const std::string rhs = st.equals_constant ? "\\text{const}" : to_latex(st.rhs);
  const std::string rel = st.equals_constant ? "=" : tex_relation(st.relation);
  const std::string note = st.note.empty() ? "" : " \\quad \\left(= " + note_latex(st) + "\\right)";
  // A long label is set in a box at most half the line wide (as narrow as its text), on as
  // many lines as it needs, beside the equation: a tag wider than the room beside it went
  // below the equation, past the left margin.
  const std::string label = prose(st, Format::latex);
  const std::string tag =
      st.text.empty()        ? ""
      : st.text.size() <= 40 ? " \\tag*{" + label + "}"
                             : " \\tag*{\\begin{varwidth}[t]{0.5\\linewidth}\\raggedleft " + label + "\\end{varwidth}}";
  // A line too long for the page is broken after the relation and at the sum's + and -, the
  // rest indented, as the HTML breaks it (a broken result is not boxed: a box cannot span lines).
  const auto lines =
      displayed_lines(lhs, rel, rhs, note, std::max(30.0, 62.0 - 0.6 * static_cast<double>(st.text.size())));
  if (lines.size() > 1) return join(lines, " \\\\\n  ") + tag;
  const std::string body = st.boxed ? "&\\boxed{" + lhs + " " + rel + " " + rhs + "}" : lhs + " &" + rel + " " + rhs;
  return body + note + tag;
}

// Equations one after another, in one align* block.
std::string latex_equations(const std::vector<const Step*>& steps) {
  std::string out = "\\begin{align*}\n";
  for (std::size_t i = 0; i < steps.size(); ++i)
    out += "  " + latex_line(*steps[i]) + (i + 1 < steps.size() ? " \\\\\n" : "\n");
  return out + "\\end{align*}\n";
}

std::string latex_preamble(bool plots) {
  return "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
         "\\allowdisplaybreaks\n\\usepackage{graphicx}\n\\usepackage{varwidth}\n\\setlength{\\emergencystretch}{3em}\n"
         "\\usepackage[margin=2.5cm]{geometry}\n\\usepackage{tikz}\n\\usepackage{siunitx}\n" +
         std::string(plots ? "\\usepackage{pgfplots}\n\\pgfplotsset{compat=1.16}\n" : "") + "\\begin{document}\n";
}

// The body of a derivation: its title as a section, its steps (or answers) below.
std::string latex_body(const Derivation& d, bool full, const std::string& title) {
  std::string out = "\\section*{" + tex_escape(title) + "}\n";
  if (full) {
    bool in_list = false;
    std::vector<const Step*> run;    // equations waiting for their align* block
    std::vector<const Step*> given;  // parameters waiting for their table
    auto flush = [&] {
      if (!run.empty()) out += latex_equations(run);
      run.clear();
    };
    auto flush_given = [&] {
      if (given.empty()) return;
      out +=
          "\\begin{center}\n\\begin{tabular}{lrl}\n\\hline\n"
          "Parameter & Value & Unit \\\\\n\\hline\n";
      for (const Step* g : given)
        out += "$" + to_latex(g->lhs) + "$ & \\num{" + g->number + "} & " +
               (g->note.empty() ? "" : "$" + unit_latex(g->note) + "$") + " \\\\\n";
      out += "\\hline\n\\end{tabular}\n\\end{center}\n";
      given.clear();
    };
    for (const auto& st : d.steps) {
      const bool listed = st.kind == Step::Kind::bullet;
      if (st.kind != Step::Kind::equation) flush();
      if (st.kind != Step::Kind::given) flush_given();
      if (!listed && in_list) {
        out += "\\end{itemize}\n";
        in_list = false;
      }
      switch (st.kind) {
        case Step::Kind::section: out += "\\subsection*{" + tex_escape(st.text) + "}\n"; break;
        case Step::Kind::text: out += prose(st, Format::latex) + "\n\n"; break;
        case Step::Kind::bullet:
          if (!in_list) out += "\\begin{itemize}\n";
          in_list = true;
          out += "  \\item " + prose(st, Format::latex) + "\n";
          break;
        case Step::Kind::given: given.push_back(&st); break;
        case Step::Kind::equation: run.push_back(&st); break;
        case Step::Kind::figure: out += latex_figure(st); break;
      }
    }
    flush();
    flush_given();
    if (in_list) out += "\\end{itemize}\n";
    if (d.sweep_plot)
      out +=
          "\\subsection*{Sweep}\n\\begin{center}\n\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!"
          "}{%\n" +
          sweep_pgfplots(*d.sweep_plot) + "}\n\\end{center}\n";
    if (d.motion_plot) {
      out += "\\subsection*{Motion, integrated numerically}\n";
      for (const auto& e : d.motion_events) out += tex_escape(e) + "\n\n";
      out += "\\begin{center}\n\\resizebox{\\ifdim\\width>\\linewidth\\linewidth\\else\\width\\fi}{!}{%\n" +
             sweep_pgfplots(*d.motion_plot) + "}\n\\end{center}\n";
    }
  } else {
    const std::vector<Step> results = result_steps(d);
    std::vector<const Step*> run;
    for (const auto& st : results) run.push_back(&st);
    if (!run.empty()) out += latex_equations(run);
  }
  return out;
}

std::string latex_document_(const Derivation& d, bool full) {
  return latex_preamble(d.sweep_plot || d.motion_plot) + latex_body(d, full, d.title) + "\\end{document}\n";
}

class LatexWriter final : public Writer {
 public:
  const char* name() const override { return "latex"; }
  std::string derivation(const Derivation& d, bool full) const override { return latex_document_(d, full); }
  std::string phases(const std::vector<Derivation>& ds, bool full) const override {
    bool plots = false;
    for (const auto& d : ds) plots = plots || d.sweep_plot || d.motion_plot;
    std::string out = latex_preamble(plots) + "\\section*{" + tex_escape(ds[0].title) + "}\n";
    for (const auto& d : ds) {
      std::string body = latex_body(d, full, "Phase " + std::to_string(d.phase_number) + ": " + d.phase);
      // One level down: the phase is a subsection, its parts subsubsections.
      for (const auto& [from, to] : {std::pair<std::string, std::string>{"\\subsection*{", "\\subsubsection*{"},
                                     std::pair<std::string, std::string>{"\\section*{", "\\subsection*{"}})
        for (std::size_t at = body.find(from); at != std::string::npos; at = body.find(from, at + to.size()))
          body.replace(at, from.size(), to);
      out += body;
    }
    return out + "\\end{document}\n";
  }

  std::string key(const std::vector<KeyEntry>& entries) const override {
    std::string out =
        "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
        "\\usepackage[margin=2cm]{geometry}\n\\begin{document}\n\\section*{Answer key}\n";
    for (const auto& e : entries) {
      const Derivation& d = *e.derivation;
      std::vector<std::string> asked;
      for (const auto& a : d.answers) asked.push_back("$" + to_latex(a.symbol) + "$");
      out += "\\subsection*{" + tex_escape(d.title) + "}\nFind " + join(asked) + ".\n";
      for (const auto& a : d.answers) {
        if (a.closed_form) {
          const std::string value =
              a.value ? " = " + a.value->decimal + (a.value->unit.empty() ? "" : "\\," + unit_latex(a.value->unit))
                      : "";
          const auto lines = displayed_lines(to_latex(a.symbol), "=", to_latex(*a.closed_form), value, 62);
          if (lines.size() == 1)
            out += "\\begin{equation*}\n  " + lines[0] + "\n\\end{equation*}\n";
          else  // broken as the derivation breaks it
            out += "\\begin{align*}\n  " + join(lines, " \\\\\n  ") + "\n\\end{align*}\n";
        } else if (a.general) {
          out += "\\begin{equation*}\n  " + to_latex(a.symbol) + " = " + to_latex(*a.general) +
                 " \\quad\\text{(not determined alone)}\n\\end{equation*}\n";
        }
      }
      if (e.variants.empty()) {
        // Asked for, but nothing to draw from: said, not silently left out.
        if (e.variants_asked)
          out += "\\par\\medskip\\noindent No variants: no parameter of this problem has a \\texttt{range}.\n";
        continue;
      }
      // A table: the drawn parameters, then the answers, each name typeset as in the
      // derivation ($\\ddot{x}_{A}$, not ddot(x_A)).
      const std::vector<std::string> head = variant_head(e);
      auto tex_cell = [](const Quantity& q) {
        return "$" + q.number + (q.unit.empty() ? "" : "\\," + unit_latex(q.unit)) + "$";
      };
      out += "\\par\\medskip\\noindent Variants:\\par\\smallskip\\noindent\n\\begin{tabular}{" +
             std::string(head.size(), 'l') + "}\n";
      std::map<std::string, std::string> tex;
      for (const auto& p : d.parameters) tex[p.name] = p.tex;
      for (const auto& a : d.answers) tex[a.name] = a.tex;
      std::vector<std::string> cells;
      for (const auto& h : head)
        cells.push_back(h == "#"                          ? "\\#"
                        : tex.count(h) && !tex[h].empty() ? "$" + tex[h] + "$"
                                                          : "\\texttt{" + tex_escape(h) + "}");
      out += join(cells, " & ") + " \\\\\n\\hline\n";
      for (const auto& v : e.variants) {
        cells = {std::to_string(v.index)};
        for (const auto& q : v.parameters) cells.push_back(tex_cell(q));
        for (const auto& q : v.answers) cells.push_back(tex_cell(q));
        out += join(cells, " & ") + " \\\\\n";
      }
      out += "\\end{tabular}\n";
    }
    return out + "\\end{document}\n";
  }

  std::string sheet(const std::vector<SheetEntry>& entries, bool figures) const override {
    std::string out =
        "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
        "\\usepackage[margin=2.5cm]{geometry}\n\\usepackage{tikz}\n\\begin{document}\n";
    for (const auto& p : sheet_problems(entries)) {
      std::vector<std::string> asked;
      for (const auto& a : p.derivation->answers) asked.push_back("$" + a.tex + "$");
      const std::string statement = statement_of(p, true);
      out += "\\section*{Problem " + std::to_string(p.number) + ": " + tex_escape(p.title) + "}\n";
      if (!statement.empty()) out += statement + "\n\n";
      for (const Step& st : sheet_figures(p, figures)) out += latex_figure(st);
      out += "Find " + join(asked) + ".\n";
      if (!p.last_of_entry) out += "\\clearpage\n";
    }
    return out + "\\end{document}\n";
  }
};

}  // namespace

std::string notebook_latex(const Derivation& d, bool full) {
  writers::Ordered order({&d});
  const std::vector<Step> results = full ? std::vector<Step>{} : result_steps(d);
  std::vector<const Step*> run;
  for (const auto& st : full ? d.steps : results)
    if (st.kind == Step::Kind::equation) run.push_back(&st);
  return run.empty() ? "" : latex_equations(run);
}

const Writer& latex_writer() {
  static const LatexWriter w;
  return w;
}

}  // namespace tackle

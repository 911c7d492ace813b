#include "report/writers/common.hpp"

#include <stdexcept>

#include "core/placeholders.hpp"
#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "model/symbols.hpp"
#include "report/break.hpp"
#include "report/html.hpp"
#include "report/tex.hpp"
#include "report/writer.hpp"

namespace tackle::writers {

std::string status_name(Answer::Status s) {
  switch (s) {
    case Answer::Status::determined: return "determined";
    case Answer::Status::free: return "free";
    case Answer::Status::in_combination: return "in_combination";
    case Answer::Status::not_in_equations: return "not_in_equations";
    case Answer::Status::undetermined: return "undetermined";
  }
  return "";
}

std::string kind_name(Equation::Kind k) {
  switch (k) {
    case Equation::Kind::lmb: return "lmb";
    case Equation::Kind::amb: return "amb";
    case Equation::Kind::constraint_acceleration: return "constraint";
    case Equation::Kind::constraint_rate: return "constraint_rate";
    case Equation::Kind::constraint_position: return "constraint_position";
    case Equation::Kind::interval: return "interval";
    case Equation::Kind::impact: return "impact";
  }
  return "";
}

std::string tex_relation(const std::string& op) {
  if (op == ">=") return "\\geq";
  if (op == "<=") return "\\leq";
  if (op == "!=") return "\\neq";
  return op;
}

std::string value_text(const std::optional<NumericValue>& v) {
  if (!v) return "";
  return v->decimal + (v->unit.empty() ? "" : " " + v->unit);
}

std::string prose(const Step& st, Format f) {
  std::string out;
  std::size_t from = 0, k = 0;
  // A spaced hyphen in prose is a dash (an en dash in LaTeX and HTML).
  auto dashed = [](std::string s, const std::string& dash) {
    for (std::size_t at = s.find(" - "); at != std::string::npos; at = s.find(" - ", at + dash.size()))
      s.replace(at, 3, dash);
    return s;
  };
  auto plain = [&](const std::string& s) {
    return f == Format::latex      ? dashed(tex_escape(s), " -- ")
           : f == Format::html     ? dashed(html_escape(s), " &ndash; ")
           : f == Format::markdown ? markdown_text(s)
                                   : s;
  };
  for (std::size_t at; (at = st.text.find("{}", from)) != std::string::npos && k < st.math.size(); from = at + 2, ++k) {
    out += plain(st.text.substr(from, at - from));
    out += f == Format::text   ? to_text(st.math[k])
           : f == Format::html ? html_math(inline_tex(to_latex(st.math[k])))
                               : "$" + inline_tex(to_latex(st.math[k])) + "$";
  }
  return out + plain(st.text.substr(from));
}

std::string note_text(const Step& st) { return st.note_squared ? "(" + st.note + ")^2" : st.note; }

std::string note_latex(const Step& st) {
  // The note is "decimal unit".
  const auto sp = st.note.find(' ');
  const std::string v =
      sp == std::string::npos ? st.note : st.note.substr(0, sp) + "\\," + unit_latex(st.note.substr(sp + 1));
  return st.note_squared ? "\\left(" + v + "\\right)^{2}" : v;
}

std::string markdown_text(const std::string& s) {
  std::string out;
  bool math = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\\' && i + 1 < s.size() && s[i + 1] == '$') {
      out += "\\$";  // an escaped dollar opens no math
      ++i;
    } else if (c == '$') {
      math = !math;
      out += c;
    } else if (c == '<') {
      out += math ? "\\lt " : "&lt;";
    } else if (c == '>') {
      out += math ? "\\gt " : "&gt;";
    } else if (c == '&' && !math) {
      out += "&amp;";
    } else {
      out += c;
    }
  }
  return out;
}

std::string heading(const Derivation& d) {
  return d.phase.empty() ? d.title : d.title + ": phase " + std::to_string(d.phase_number) + ", " + d.phase;
}

std::vector<Step> result_steps(const Derivation& d) {
  std::vector<Step> out;
  for (const auto& a : d.answers) {
    if (!a.closed_form) continue;
    Step st;
    st.kind = Step::Kind::equation;
    st.lhs = a.symbol;
    st.rhs = *a.closed_form;
    st.boxed = true;
    st.note = value_text(a.value);
    out.push_back(st);
  }
  return out;
}

std::vector<SheetProblem> sheet_problems(const std::vector<SheetEntry>& entries) {
  std::vector<SheetProblem> out;
  int number = 0;
  for (const auto& e : entries) {
    const Derivation& d = *e.derivation;
    // The description's own values, then a variant's drawn ones over them.
    std::map<std::string, Quantity> base;
    for (const auto& p : d.parameters) {
      const auto& v = p.stated ? p.stated : p.si;
      if (v && p.kind == "parameter") base[p.name] = {p.name, v->decimal, v->unit, v->approx};
    }
    const std::size_t n = e.variants.empty() ? 1 : e.variants.size();
    for (std::size_t k = 0; k < n; ++k) {
      SheetProblem p;
      p.number = ++number;
      p.title = d.title + (e.variants.empty() ? "" : " (variant " + std::to_string(e.variants[k].index) + ")");
      p.derivation = &d;
      p.model = e.model;
      p.values = base;
      if (!e.variants.empty()) {
        for (const auto& q : e.variants[k].parameters) p.values[q.name] = q;
        p.variant_values = e.variants[k].values;
      }
      p.last_of_entry = k + 1 == n;
      out.push_back(std::move(p));
    }
  }
  return out;
}

namespace {

// "a, b and c"
std::string listed_in_words(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) out += (i ? (i + 1 == items.size() ? " and " : ", ") : "") + items[i];
  return out;
}

// A problem without a statement, said from its description: the bodies, the connections (the
// rules' own sentences in this problem's symbols) and the given values, the variant's where it
// has them, every name and value typeset as $...$ (Markdown renders it too).
std::string generated_statement(const SheetProblem& p) {
  const bool math = true;
  // Words of the description (block_1, s_1) as math, the way LaTeX, KaTeX and Markdown agree
  // on them: a raw underscore is a subscript in LaTeX and emphasis in Markdown.
  auto words = [](const std::string& text) {
    std::string out, word;
    auto flush = [&] {
      if (word.find('_') != std::string::npos)
        out += "$" + default_tex(word) + "$";
      else
        out += word;
      word.clear();
    };
    for (char c : text) {
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
        word += c;
      } else {
        flush();
        out += c;
      }
    }
    flush();
    return out;
  };
  const Model& m = *p.model;
  const Derivation& d = *p.derivation;
  auto term = [&](const GiNaC::ex& e) { return math ? "$" + to_latex(e) + "$" : to_text(e); };
  std::vector<std::string> bodies;
  for (const auto& b : m.bodies) {
    std::string what = words(b.name);
    if (b.has_mass && b.mass.is_zero())
      what += " (no mass)";
    else if (b.has_mass)
      what += " (mass " + term(b.mass) + ")";
    bodies.push_back(what);
  }
  std::string out = (bodies.size() == 1 ? "A body, " : "Bodies ") + listed_in_words(bodies) + ". ";
  std::vector<std::string> connections;
  for (const auto& c : m.connections) {
    std::string summary;
    std::size_t from = 0, k = 0;
    for (std::size_t at; (at = c.summary.find("{}", from)) != std::string::npos; from = at + 2)
      summary += words(c.summary.substr(from, at - from)) + (k < c.terms.size() ? term(c.terms[k++]) : "{}");
    summary += words(c.summary.substr(from));
    connections.push_back(words(c.label) + ": " + summary);
  }
  if (!connections.empty()) out += "Connections: " + listed_in_words(connections) + ". ";
  std::vector<std::string> given;
  for (const auto& q : d.parameters) {
    if (q.kind != "parameter" && q.kind != "given") continue;
    const auto it = p.values.find(q.name);
    std::string number, unit;
    if (it != p.values.end()) {
      number = it->second.number;
      unit = it->second.unit;
    } else if (const auto& v = q.stated ? q.stated : q.si) {
      number = v->decimal;
      unit = v->unit;
    } else {
      continue;
    }
    given.push_back(math ? "$" + q.tex + " = " + number + (unit.empty() ? "" : "\\," + unit_latex(unit)) + "$"
                         : q.name + " = " + number + (unit.empty() ? "" : " " + unit));
  }
  if (!given.empty()) out += "Given: " + listed_in_words(given) + ".";
  return out;
}

}  // namespace

bool has_statement(const SheetProblem& p) { return p.model && p.model->statement; }

std::string statement_of(const SheetProblem& p, bool math) {
  if (!p.model) return "";
  if (!p.model->statement) return generated_statement(p);
  const std::string& statement = p.model->statement->text;
  std::string out;
  std::size_t from = 0;
  for (const auto& ph : placeholders(statement)) {
    out += statement.substr(from, ph.open - from);
    const auto it = p.values.find(std::string(ph.name));
    if (it == p.values.end()) {
      out += statement.substr(ph.open, ph.close - ph.open + 1);
    } else if (math) {
      out += "$" + it->second.number + (it->second.unit.empty() ? "" : "\\," + unit_latex(it->second.unit)) + "$";
    } else {
      out += it->second.text();
    }
    from = ph.close + 1;
  }
  return out + statement.substr(from);
}

std::vector<const Step*> figures_of(const Derivation& d, bool diagrams) {
  std::vector<const Step*> out;
  for (const auto& st : d.steps)
    if (st.kind == Step::Kind::figure && (diagrams || st.figure->sketch)) out.push_back(&st);
  return out;
}

std::vector<Step> sheet_figures(const SheetProblem& p, bool diagrams) {
  std::vector<Step> out;
  const std::vector<const Step*> steps = figures_of(*p.derivation, diagrams);
  if (p.variant_values.empty() || !p.model || steps.empty()) {
    for (const Step* st : steps) out.push_back(*st);
    return out;
  }
  const FigureMaker maker(*p.model, p.variant_values);
  for (const Step* st : steps)
    if (auto fig = maker.redraw(*st->figure)) {
      Step again = *st;
      again.figure = std::make_shared<const Figure>(std::move(*fig));
      out.push_back(std::move(again));
    }
  return out;
}

std::vector<std::string> variant_head(const KeyEntry& e) {
  std::vector<std::string> head{"#"};
  if (e.variants.empty()) return head;
  for (const auto& q : e.variants.front().parameters) head.push_back(q.name);
  for (const auto& q : e.variants.front().answers) head.push_back(q.name);
  return head;
}

Ordered::Ordered(const std::vector<const Derivation*>& ds) {
  std::vector<std::shared_ptr<const SymbolTable>> tables;
  for (const Derivation* d : ds)
    if (d->symbols) tables.push_back(d->symbols);
  if (!tables.empty()) order_.emplace(factor_rank(std::move(tables)));
}

}  // namespace tackle::writers

namespace tackle {

std::string Writer::key(const std::vector<KeyEntry>&) const {
  throw std::logic_error(std::string("the ") + name() + " format has no answer key");
}
std::string Writer::sheet(const std::vector<SheetEntry>&, bool) const {
  throw std::logic_error(std::string("the ") + name() + " format has no problem sheets");
}
std::string Writer::isolations(const Model&, const std::vector<Isolation>&) const {
  throw std::logic_error(std::string("the ") + name() + " format has no isolation report");
}

std::string write(const Derivation& d, Format f, bool full) {
  writers::Ordered order({&d});
  return writer_for(f).derivation(d, full);
}

std::string write(const std::vector<Derivation>& ds, Format f, bool full) {
  if (ds.size() == 1 && ds[0].phase.empty()) return write(ds[0], f, full);
  std::vector<const Derivation*> all;
  for (const auto& d : ds) all.push_back(&d);
  writers::Ordered order(all);
  return writer_for(f).phases(ds, full);
}

void write_to(std::ostream& out, const Derivation& d, Format f, bool full) {
  writers::Ordered order({&d});
  writer_for(f).derivation_to(out, d, full);
}

void write_to(std::ostream& out, const std::vector<Derivation>& ds, Format f, bool full) {
  if (ds.size() == 1 && ds[0].phase.empty()) return write_to(out, ds[0], f, full);
  std::vector<const Derivation*> all;
  for (const auto& d : ds) all.push_back(&d);
  writers::Ordered order(all);
  writer_for(f).phases_to(out, ds, full);
}

std::string write_key(const std::vector<KeyEntry>& entries, Format f) {
  std::vector<const Derivation*> all;
  for (const auto& e : entries) all.push_back(e.derivation);
  writers::Ordered order(all);
  return writer_for(f).key(entries);
}

std::string write_sheet(const std::vector<SheetEntry>& entries, Format f, bool figures) {
  std::vector<const Derivation*> all;
  for (const auto& e : entries) all.push_back(e.derivation);
  writers::Ordered order(all);
  return writer_for(f).sheet(entries, figures);
}

std::string write_isolations(const Model& m, const std::vector<Isolation>& found, Format f) {
  return writer_for(f).isolations(m, found);
}

std::string tex_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '_': out += "\\_"; break;
      case '&': out += "\\&"; break;
      case '%': out += "\\%"; break;
      case '#': out += "\\#"; break;
      case '$': out += "\\$"; break;
      case '{': out += "\\{"; break;
      case '}': out += "\\}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '\\': out += "\\textbackslash{}"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace tackle

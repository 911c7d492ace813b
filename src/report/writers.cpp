// Writers: the same Derivation as text, LaTeX (a standalone document), Markdown or JSON.
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "expr/print.hpp"
#include "figure/figure.hpp"
#include "report/derivation.hpp"
#include "report/html.hpp"
#include "report/tex.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

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

// Prose with its "{}" placeholders filled from the step's expressions, as text, LaTeX
// (escaped prose, $math$) or Markdown ($math$).
std::string prose(const Step& st, Format f) {
  std::string out;
  std::size_t from = 0, k = 0;
  auto plain = [&](const std::string& s) { return f == Format::latex ? tex_escape(s) : f == Format::html ? html_escape(s) : s; };
  for (std::size_t at; (at = st.text.find("{}", from)) != std::string::npos && k < st.math.size(); from = at + 2, ++k) {
    out += plain(st.text.substr(from, at - from));
    out += f == Format::text ? to_text(st.math[k]) : f == Format::html ? html_math(to_latex(st.math[k])) : "$" + to_latex(st.math[k]) + "$";
  }
  return out + plain(st.text.substr(from));
}

// The title of a derivation, with its phase when it is one of a phased description's.
std::string heading(const Derivation& d) {
  return d.phase.empty() ? d.title : d.title + ": phase " + std::to_string(d.phase_number) + ", " + d.phase;
}

// The closed forms as boxed equations with their numbers (`solve`'s report).
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

// ---- text ---------------------------------------------------------------------------------

std::string answers_text(const Derivation& d) {
  std::string out;
  for (const auto& a : d.answers) {
    if (a.closed_form) {
      out += a.name + " = " + to_text(*a.closed_form);
      if (a.value) out += "  = " + value_text(a.value);
      out += "\n";
    } else if (a.general) {
      out += a.name + " = " + to_text(*a.general) + "  (" + status_name(a.status) + ")\n";
    } else {
      out += a.name + ": " + status_name(a.status) + (a.reason.empty() ? "" : ": " + a.reason) + "\n";
    }
  }
  for (const auto& c : d.combinations)
    out += to_text(c.combination) + " = " + to_text(c.value) + (c.number ? "  = " + value_text(c.number) : "") +
           "  (determined combination)\n";
  if (!d.conflicts.empty()) out += "inconsistent: " + join(d.conflicts, ", ") + "\n";
  for (const auto& c : d.conditions)
    if (c.holds && !*c.holds) out += "warning: " + c.source + ": " + c.otherwise + " (" + to_text(c.simplified) + " " + c.op + " 0 fails)\n";
  return out;
}

std::string derivation_text(const Derivation& d) {
  const std::string title = heading(d);
  std::string out = title + "\n" + std::string(title.size(), '=') + "\n";
  for (const auto& st : d.steps) {
    switch (st.kind) {
      case Step::Kind::section: out += "\n" + st.text + "\n" + std::string(st.text.size(), '-') + "\n"; break;
      case Step::Kind::text: out += prose(st, Format::text) + "\n"; break;
      case Step::Kind::bullet: out += "  - " + prose(st, Format::text) + "\n"; break;
      case Step::Kind::given:
        out += "  - " + to_text(st.lhs) + " = " + st.number + (st.note.empty() ? "" : " " + st.note) + "\n";
        break;
      case Step::Kind::figure: break;  // drawn in LaTeX, Markdown and HTML
      case Step::Kind::equation: {
        std::string eq = st.equals_constant ? to_text(st.lhs) + " = const"
                                            : to_text(st.lhs) + " " + st.relation + " " + to_text(st.rhs);
        if (!st.note.empty()) eq += "  = " + st.note;
        out += "    " + eq + (st.text.empty() ? "" : "    [" + prose(st, Format::text) + "]") + "\n";
        break;
      }
    }
  }
  return out;
}

// ---- LaTeX --------------------------------------------------------------------------------

// One line of an align* block: aligned on its relation (a boxed result is one box, aligned
// at its start), its number as a note, its label as a tag.
std::string latex_line(const Step& st) {
  const std::string lhs = to_latex(st.lhs);
  const std::string rhs = st.equals_constant ? "\\text{const}" : to_latex(st.rhs);
  const std::string rel = st.equals_constant ? "=" : tex_relation(st.relation);
  std::string body = st.boxed ? "&\\boxed{" + lhs + " " + rel + " " + rhs + "}" : lhs + " &" + rel + " " + rhs;
  if (!st.note.empty()) body += " \\quad \\left(= " + [&] {
    // note is "decimal unit"
    const auto sp = st.note.find(' ');
    if (sp == std::string::npos) return st.note;
    return st.note.substr(0, sp) + "\\," + unit_latex(st.note.substr(sp + 1));
  }() + "\\right)";
  return body + (st.text.empty() ? "" : " \\tag*{" + prose(st, Format::latex) + "}");
}

// Equations one after another, in one align* block.
std::string latex_equations(const std::vector<const Step*>& steps) {
  std::string out = "\\begin{align*}\n";
  for (std::size_t i = 0; i < steps.size(); ++i) out += "  " + latex_line(*steps[i]) + (i + 1 < steps.size() ? " \\\\\n" : "\n");
  return out + "\\end{align*}\n";
}

std::string latex_preamble(bool plots) {
  return "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n\\usepackage{amsmath}\n"
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
      out += "\\begin{center}\n\\begin{tabular}{lrl}\n\\hline\n"
             "Parameter & Value & Unit \\\\\n\\hline\n";
      for (const Step* g : given)
        out += "$" + to_latex(g->lhs) + "$ & \\num{" + g->number + "} & " + (g->note.empty() ? "" : "$" + unit_latex(g->note) + "$") + " \\\\\n";
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
        case Step::Kind::figure:
          out += "\\begin{center}\n" + to_tikz(*st.figure) + "\\\\[2pt]{\\small " + tex_escape(st.text) + "}\n\\end{center}\n";
          break;
      }
    }
    flush();
    flush_given();
    if (in_list) out += "\\end{itemize}\n";
    if (!d.figure_pgfplots.empty())
      out += "\\subsection*{Sweep}\n\\begin{center}\n" + d.figure_pgfplots + "\\end{center}\n";
    if (!d.motion_pgfplots.empty()) {
      out += "\\subsection*{Motion, integrated numerically}\n";
      for (const auto& e : d.motion_events) out += tex_escape(e) + "\n\n";
      out += "\\begin{center}\n" + d.motion_pgfplots + "\\end{center}\n";
    }
  } else {
    const std::vector<Step> results = result_steps(d);
    std::vector<const Step*> run;
    for (const auto& st : results) run.push_back(&st);
    if (!run.empty()) out += latex_equations(run);
  }
  return out;
}

std::string latex_document(const Derivation& d, bool full) {
  return latex_preamble(!d.figure_pgfplots.empty() || !d.motion_pgfplots.empty()) + latex_body(d, full, d.title) + "\\end{document}\n";
}

// ---- JSON ---------------------------------------------------------------------------------

// Motion in time for the JSON: the equations of motion, the response, the quantities and the
// conditions along it (text and LaTeX for each expression).
nlohmann::ordered_json motion_json(const Motion& mo) {
  using J = nlohmann::ordered_json;
  const EquationsOfMotion& e = mo.eom;
  auto expr = [](const GiNaC::ex& x) { return J{{"text", to_text(x)}, {"latex", to_latex(x)}}; };
  auto mat = [](const GiNaC::matrix& m) {
    J rows = J::array();
    for (unsigned i = 0; i < m.rows(); ++i) {
      J row = J::array();
      for (unsigned k = 0; k < m.cols(); ++k) row.push_back(to_text(m(i, k)));
      rows.push_back(row);
    }
    return rows;
  };
  J j{{"degrees_of_freedom", e.dof}, {"coordinates", J::array()}, {"linear", e.linear}};
  for (const auto& q : e.q) j["coordinates"].push_back(to_text(q));
  if (!e.linear) j["nonlinear"] = e.nonlinear;
  j["accelerations"] = J::array();
  for (std::size_t i = 0; i < e.dof; ++i)
    j["accelerations"].push_back({{"coordinate", to_text(e.q[i])}, {"acceleration", expr(e.acceleration[i])}});
  if (e.linear) {
    j["mass"] = mat(e.M);
    j["damping"] = mat(e.C);
    j["stiffness"] = mat(e.K);
    j["forcing"] = J::array();
    for (const auto& f : e.forcing) j["forcing"].push_back(to_text(f));
    j["natural_frequencies"] = e.natural_frequencies;
    j["equilibrium"] = J(nullptr);
    if (e.equilibrium) {
      j["equilibrium"] = J::array();
      for (const auto& q : *e.equilibrium) j["equilibrium"].push_back(to_text(q));
    }
  }
  if (mo.response) {
    static const char* const regimes[] = {"undamped", "underdamped", "critically_damped", "overdamped", "free_particle",
                                          "damped_particle"};
    const Response& r = *mo.response;
    J resp{{"regime", regimes[static_cast<int>(r.regime)]}, {"coordinate", expr(r.q)}, {"rate", expr(r.rate)},
           {"definitions", J::array()}, {"assumptions", J::array()}, {"verified", r.verified}};
    for (const auto& a : r.assumptions)
      resp["assumptions"].push_back(to_text(a.lhs) + " " + a.op + " " + to_text(a.rhs) + " (" + a.why + ")");
    for (const auto& [sym, def] : r.definitions) resp["definitions"].push_back({{"name", to_text(sym)}, {"definition", expr(def)}});
    j["response"] = resp;
  } else {
    j["response"] = J(nullptr);
    j["no_response"] = mo.no_response;
  }
  if (mo.energy) {
    const EnergyAnswer& en = *mo.energy;
    J e{{"position", to_text(en.position)}, {"numeric_only", en.numeric_only}};
    if (!en.not_possible.empty()) e["not_possible"] = en.not_possible;
    if (!en.numeric_only && en.not_possible.empty()) e["work"] = expr(en.work);
    e["rate_squared"] = en.rate_squared ? expr(*en.rate_squared) : J(nullptr);
    e["rate_squared_value"] = en.rate_squared_number ? J(*en.rate_squared_number) : J(nullptr);
    e["speed_value"] = en.rate_squared_number && *en.rate_squared_number >= 0 ? J(std::sqrt(*en.rate_squared_number)) : J(nullptr);
    j["energy"] = e;
  }
  j["quantities"] = J::array();
  for (const auto& q : mo.quantities) j["quantities"].push_back({{"name", q.name}, {"in_time", expr(q.of_t)}});
  j["conditions"] = J::array();
  for (const auto& c : mo.conditions) {
    const std::string& op = c.condition->condition->op;
    J x{{"source", c.condition->condition->source}, {"in_time", to_text(c.of_t) + " " + op + " 0"}};
    x["extreme"] = c.extreme ? J(to_text(*c.extreme) + " " + op + " 0") : J(nullptr);
    x["extreme_at"] = c.extreme_at ? J(to_text(*c.extreme_at)) : J(nullptr);
    x["for_all_t"] = J::array();
    for (const auto& sv : c.solved) x["for_all_t"].push_back(to_text(sv.parameter) + " " + sv.op + " " + to_text(sv.bound));
    x["holds_for_all_t"] = c.holds_for_all_t ? J(*c.holds_for_all_t) : J(nullptr);
    x["first_failure"] = c.first_failure ? J(to_text(*c.first_failure)) : J(nullptr);
    x["first_failure_s"] = c.first_failure_s ? J(*c.first_failure_s) : J(nullptr);
    if (c.steady_of_t) {
      J st{{"in_time", to_text(*c.steady_of_t) + " " + op + " 0"}, {"offset", to_text(*c.steady_offset)}};
      st["amplitude_condition"] = c.steady_amplitude_condition ? J(to_text(*c.steady_amplitude_condition) + " >= 0") : J(nullptr);
      st["holds"] = c.steady_holds ? J(*c.steady_holds) : J(nullptr);
      st["band"] = J(nullptr);
      if (c.band)
        st["band"] = {{"variable", to_text(c.band->variable)}, {"low", to_text(c.band->low)}, {"high", to_text(c.band->high)},
                      {"fails_between", c.band->fails_between}};
      x["steady_state"] = st;
    }
    j["conditions"].push_back(x);
  }
  return j;
}

nlohmann::ordered_json json_object(const Derivation& d, bool full) {
  nlohmann::ordered_json j;
  j["version"] = 2;
  j["title"] = d.title;
  if (!d.phase.empty()) j["phase"] = d.phase;
  j["file"] = d.file;
  j["status"] = d.status;
  j["rank"] = d.rank;
  // Self-contained: every name a closed form may use, with its value, unit and definition.
  j["parameters"] = nlohmann::ordered_json::array();
  for (const auto& p : d.parameters) {
    nlohmann::ordered_json x{{"name", p.name}, {"tex", p.tex}, {"kind", p.kind}};
    if (p.si) {
      x["value"] = p.si->approx;
      x["exact"] = to_text(p.si->exact);
      x["unit"] = p.si->unit;
    } else {
      x["value"] = nullptr;
    }
    if (p.stated) x["stated"] = {{"value", p.stated->approx}, {"exact", to_text(p.stated->exact)}, {"unit", p.stated->unit}};
    if (p.definition) {
      x["definition"] = to_text(*p.definition);
      x["definition_latex"] = to_latex(*p.definition);
    }
    j["parameters"].push_back(x);
  }
  j["unknowns"] = nlohmann::ordered_json::array();
  for (const auto& a : d.answers) {
    nlohmann::ordered_json u{{"name", a.name}, {"status", status_name(a.status)}};
    if (a.closed_form) {
      u["closed_form"] = to_text(*a.closed_form);
      u["latex"] = to_latex(*a.closed_form);
      if (a.in_parameters) u["in_parameters"] = to_text(*a.in_parameters);
    }
    if (a.general) u["general"] = to_text(*a.general);
    if (!a.reason.empty()) {
      u["missing"] = nlohmann::ordered_json::array();
      for (const auto& x : a.missing) u["missing"].push_back(to_text(x));
      u["reason"] = a.reason;
    }
    if (a.value) {
      u["value"] = a.value->approx;
      u["exact"] = to_text(a.value->exact);
      u["decimal"] = a.value->decimal;
      u["unit"] = a.value->unit;
    }
    j["unknowns"].push_back(u);
  }
  j["combinations"] = nlohmann::ordered_json::array();
  for (const auto& c : d.combinations) {
    nlohmann::ordered_json x{{"expression", to_text(c.combination)}, {"closed_form", to_text(c.value)},
                     {"latex", to_latex(c.combination) + " = " + to_latex(c.value)}};
    if (c.number) {
      x["value"] = c.number->approx;
      x["unit"] = c.number->unit;
    }
    j["combinations"].push_back(x);
  }
  j["free"] = d.free;
  if (!d.minimum_norm.empty()) {
    j["minimum_norm"] = nlohmann::ordered_json::object();
    for (const auto& [name, v] : d.minimum_norm) j["minimum_norm"][name] = {{"value", v->approx}, {"unit", v->unit}};
  }
  j["conflicts"] = d.conflicts;
  j["conditions"] = nlohmann::ordered_json::array();
  for (const auto& c : d.conditions) {
    nlohmann::ordered_json x{{"source", c.source},
                     {"inequality", to_text(c.lhs) + " " + c.op + " " + to_text(c.rhs)},
                     {"simplified", to_text(c.simplified) + " " + c.op + " 0"},
                     {"meaning", c.meaning},
                     {"otherwise", c.otherwise}};
    x["holds"] = c.holds ? nlohmann::ordered_json(*c.holds) : nlohmann::ordered_json(nullptr);
    x["always"] = c.always ? nlohmann::ordered_json(*c.always) : nlohmann::ordered_json(nullptr);
    x["solved"] = nlohmann::ordered_json::array();
    for (const auto& sv : c.solved)
      x["solved"].push_back({{"parameter", to_text(sv.parameter)},
                             {"condition", to_text(sv.parameter) + " " + sv.op + " " + to_text(sv.bound)},
                             {"latex", to_latex(sv.parameter) + " " + tex_relation(sv.op) + " " + to_latex(sv.bound)}});
    j["conditions"].push_back(x);
  }
  {
    // The power balance: d/dt(E_k) = P, checked with the solution put in.
    static const char* const names[] = {"holds", "fails", "not_applicable"};
    nlohmann::ordered_json p{{"status", names[static_cast<int>(d.power.status)]}};
    if (d.power.status == PowerCheck::Status::not_applicable) {
      p["reason"] = d.power.reason;
    } else {
      p["kinetic_energy_rate"] = to_text(d.power.kinetic_rate);
      p["power"] = to_text(d.power.power);
      if (d.power.status == PowerCheck::Status::fails) p["residual"] = to_text(d.power.residual);
    }
    j["power_check"] = p;
  }
  if (d.motion) j["motion"] = motion_json(*d.motion);
  if (full && d.system) {
    j["equations"] = nlohmann::ordered_json::array();
    for (const auto& eq : d.system->equations) {
      nlohmann::ordered_json e{{"label", eq.label},
                       {"kind", kind_name(eq.kind)},
                       {"lhs", to_text(eq.lhs)},
                       {"rhs", to_text(eq.rhs)},
                       {"latex", to_latex(eq.lhs) + " = " + to_latex(eq.rhs)},
                       {"sources", eq.sources}};
      j["equations"].push_back(e);
    }
    // The unknowns the equations are solved for, in the solver's order (the answers asked
    // for may be fewer): with the equations, everything a program needs to solve them again.
    j["solved_for"] = nlohmann::ordered_json::array();
    for (const auto& u : d.system->unknowns) j["solved_for"].push_back(to_text(u));
    j["constraints"] = nlohmann::ordered_json::array();
    for (const auto& c : d.system->constraints)
      j["constraints"].push_back({{"label", c.label},
                                  {"quantity", to_text(c.quantity)},
                                  {"rate", to_text(c.rate)},
                                  {"acceleration", to_text(c.acceleration)}});
  }
  if (full && d.impact) {
    for (const auto& eq : d.impact->equations)
      j["equations"].push_back({{"label", eq.label}, {"kind", kind_name(eq.kind)}, {"lhs", to_text(eq.lhs)}, {"rhs", to_text(eq.rhs)},
                                {"latex", to_latex(eq.lhs) + " = " + to_latex(eq.rhs)}, {"sources", eq.sources}});
  }
  return j;
}

std::string json_document(const Derivation& d, bool full) {
  return json_object(d, full).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

// ---- Markdown -----------------------------------------------------------------------------

std::string markdown_document(const Derivation& d, bool full) {
  std::string out = "# " + heading(d) + "\n\n";
  auto eq = [](const Step& st) {
    std::string body = st.equals_constant ? to_latex(st.lhs) + " = \\text{const}"
                                          : to_latex(st.lhs) + " " + tex_relation(st.relation) + " " + to_latex(st.rhs);
    if (st.boxed) body = "\\boxed{" + body + "}";
    std::string line = "$$" + body + "$$" + (st.text.empty() ? "" : " *(" + prose(st, Format::markdown) + ")*");
    if (!st.note.empty()) line += " = " + st.note;
    return line + "\n\n";
  };
  if (full) {
    bool in_list = false, in_table = false;
    for (const auto& st : d.steps) {
      const bool listed = st.kind == Step::Kind::bullet, table = st.kind == Step::Kind::given;
      if ((in_list && !listed) || (in_table && !table)) out += "\n";
      if (table && !in_table) out += (in_list ? "\n" : "") + std::string("| Parameter | Value | Unit |\n|---|--:|---|\n");
      in_list = listed;
      in_table = table;
      switch (st.kind) {
        case Step::Kind::section: out += "## " + st.text + "\n\n"; break;
        case Step::Kind::text: out += prose(st, Format::markdown) + "\n\n"; break;
        case Step::Kind::bullet: out += "- " + prose(st, Format::markdown) + "\n"; break;
        case Step::Kind::given:
          out += "| $" + to_latex(st.lhs) + "$ | " + st.number + " | " + (st.note.empty() ? "" : "$" + unit_latex(st.note) + "$") + " |\n";
          break;
        case Step::Kind::equation: out += eq(st); break;
        case Step::Kind::figure: out += "<figure>\n" + to_svg(*st.figure) + "<figcaption>" + st.text + "</figcaption>\n</figure>\n\n"; break;
      }
    }
  } else {
    for (Step st : result_steps(d)) {
      st.boxed = false;  // Markdown's answers stay plain
      out += eq(st);
    }
  }
  return out;
}

// ---- HTML ---------------------------------------------------------------------------------

// One equation: typeset by KaTeX, its label as a tag, its number as a note.
std::string html_equation(const Step& st) {
  std::string body = st.equals_constant ? to_latex(st.lhs) + " = \\text{const}"
                                        : to_latex(st.lhs) + " " + tex_relation(st.relation) + " " + to_latex(st.rhs);
  if (st.boxed) body = "\\boxed{" + body + "}";
  if (!st.note.empty()) {
    const auto sp = st.note.find(' ');
    body += " \\quad \\left(= " + (sp == std::string::npos ? st.note : st.note.substr(0, sp) + "\\," + unit_latex(st.note.substr(sp + 1))) +
            "\\right)";
  }
  std::string out = "<div class=\"eq\">" + html_math(body, true);
  if (!st.text.empty()) out += "<span class=\"tag\">(" + prose(st, Format::html) + ")</span>";
  return out + "</div>\n";
}

// The body of one derivation (its title a heading of `level`), without the page around it.
std::string html_body(const Derivation& d, bool full, const std::string& title, int level) {
  const std::string h = std::to_string(level), h2 = std::to_string(level + 1);
  std::string out = "<h" + h + ">" + html_escape(title) + "</h" + h + ">\n";
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
    if (!in_table && table) out += "<table class=\"parameters\">\n<tr><th>Parameter</th><th>Value</th><th>Unit</th></tr>\n";
    in_list = listed;
    in_table = table;
    switch (st.kind) {
      case Step::Kind::section: out += "<h" + h2 + ">" + html_escape(st.text) + "</h" + h2 + ">\n"; break;
      case Step::Kind::text: out += "<p>" + prose(st, Format::html) + "</p>\n"; break;
      case Step::Kind::bullet: out += "<li>" + prose(st, Format::html) + "</li>\n"; break;
      case Step::Kind::given:
        out += "<tr><td>" + html_math(to_latex(st.lhs)) + "</td><td class=\"number\">" + html_escape(st.number) + "</td><td>" +
               (st.note.empty() ? "" : html_math(unit_latex(st.note))) + "</td></tr>\n";
        break;
      case Step::Kind::equation: out += html_equation(st); break;
      case Step::Kind::figure:
        out += "<figure>\n" + to_svg(*st.figure) + "<figcaption>" + html_escape(st.text) + "</figcaption>\n</figure>\n";
        break;
    }
  }
  if (in_list) out += "</ul>\n";
  if (in_table) out += "</table>\n";
  return out;
}

}  // namespace

std::string write(const std::vector<Derivation>& ds, Format f, bool full) {
  if (ds.size() == 1 && ds[0].phase.empty()) return write(ds[0], f, full);
  std::optional<PersonOrder> order;
  if (!ds.empty() && ds[0].symbols) order.emplace(factor_rank(ds[0].symbols));
  std::string out;
  switch (f) {
    case Format::text:
      for (std::size_t i = 0; i < ds.size(); ++i) {
        if (full) out += (i ? "\n\n" : "") + derivation_text(ds[i]);
        else out += (i ? "\n" : "") + heading(ds[i]) + "\n" + answers_text(ds[i]);
      }
      return out;
    case Format::markdown:
      for (const auto& d : ds) out += markdown_document(d, full);
      return out;
    case Format::latex: {
      bool plots = false;
      for (const auto& d : ds) plots = plots || !d.figure_pgfplots.empty() || !d.motion_pgfplots.empty();
      out = latex_preamble(plots) + "\\section*{" + tex_escape(ds[0].title) + "}\n";
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
    case Format::html: {
      std::string body = "<h1>" + html_escape(ds[0].title) + "</h1>\n";
      for (const auto& d : ds) body += html_body(d, full, "Phase " + std::to_string(d.phase_number) + ": " + d.phase, 2);
      return html_page(ds[0].title, body);
    }
    case Format::json: {
      nlohmann::ordered_json j;
      j["version"] = 2;
      j["title"] = ds[0].title;
      j["file"] = ds[0].file;
      j["phases"] = nlohmann::ordered_json::array();
      for (const auto& d : ds) j["phases"].push_back(json_object(d, full));
      return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
    }
  }
  return out;
}

std::string write(const Derivation& d, Format f, bool full) {
  std::optional<PersonOrder> order;
  if (d.symbols) order.emplace(factor_rank(d.symbols));
  switch (f) {
    case Format::text: return full ? derivation_text(d) : answers_text(d);
    case Format::latex: return latex_document(d, full);
    case Format::json: return json_document(d, full);
    case Format::markdown: return markdown_document(d, full);
    case Format::html: return html_page(heading(d), html_body(d, full, heading(d), 1));
  }
  return {};
}

}  // namespace tackle

namespace tackle {

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

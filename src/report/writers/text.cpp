// The text format: the derivation as plain text (the approved goldens), the answers, the
// isolations.
#include <sstream>

#include "expr/print.hpp"
#include "report/writer.hpp"
#include "report/writers/common.hpp"

namespace tackle {

using namespace GiNaC;
using namespace writers;

namespace {

// Each line is written as it is made: a chain of 2048 blocks has 88 MB of answers, and the
// text made whole took twice that again while it grew.
void answers_text(std::ostream& out, const Derivation& d) {
  for (const auto& a : d.answers) {
    if (a.closed_form) {
      out << a.name << " = " << to_text(*a.closed_form);
      if (a.value) out << "  = " << value_text(a.value);
      out << "\n";
    } else if (a.general) {
      out << a.name << " = " << to_text(*a.general) << "  (" << status_name(a.status) << ")\n";
    } else {
      out << a.name << ": " << status_name(a.status) << (a.reason.empty() ? "" : ": " + a.reason) << "\n";
    }
  }
  for (const auto& c : d.combinations)
    out << to_text(c.combination) << " = " << to_text(c.value) << (c.number ? "  = " + value_text(c.number) : "")
        << "  (determined combination)\n";
  if (!d.conflicts.empty()) out << "inconsistent: " << join(d.conflicts, ", ") << "\n";
  for (const auto& c : d.conditions)
    if (c.holds && !*c.holds)
      out << "warning: " << c.source << ": " << c.otherwise << " (" << to_text(c.simplified) << " " << c.op
          << " 0 fails)\n";
}

void derivation_text(std::ostream& out, const Derivation& d) {
  const std::string title = heading(d);
  out << title << "\n" << std::string(title.size(), '=') << "\n";
  for (const auto& st : d.steps) {
    switch (st.kind) {
      case Step::Kind::section: out << "\n" << st.text << "\n" << std::string(st.text.size(), '-') << "\n"; break;
      case Step::Kind::text: out << prose(st, Format::text) << "\n"; break;
      case Step::Kind::bullet: out << "  - " << prose(st, Format::text) << "\n"; break;
      case Step::Kind::given:
        out << "  - " << to_text(st.lhs) << " = " << st.number << (st.note.empty() ? "" : " " + st.note) << "\n";
        break;
      case Step::Kind::figure: break;  // drawn in LaTeX, Markdown and HTML
      case Step::Kind::equation: {
        std::string eq = st.equals_constant ? to_text(st.lhs) + " = const"
                                            : to_text(st.lhs) + " " + st.relation + " " + to_text(st.rhs);
        if (!st.note.empty()) eq += "  = " + note_text(st);
        out << "    " << eq << (st.text.empty() ? "" : "    [" + prose(st, Format::text) + "]") << "\n";
        break;
      }
    }
  }
}

// One of the two, whole.
std::string text_of(const Derivation& d, bool full) {
  std::ostringstream out;
  if (full)
    derivation_text(out, d);
  else
    answers_text(out, d);
  return std::move(out).str();
}

class TextWriter final : public Writer {
 public:
  const char* name() const override { return "text"; }
  std::string derivation(const Derivation& d, bool full) const override { return text_of(d, full); }
  std::string phases(const std::vector<Derivation>& ds, bool full) const override {
    std::ostringstream out;
    phases_to(out, ds, full);
    return std::move(out).str();
  }
  void derivation_to(std::ostream& out, const Derivation& d, bool full) const override {
    if (full)
      derivation_text(out, d);
    else
      answers_text(out, d);
  }
  void phases_to(std::ostream& out, const std::vector<Derivation>& ds, bool full) const override {
    for (std::size_t i = 0; i < ds.size(); ++i) {
      if (full) {
        out << (i ? "\n\n" : "");
        derivation_text(out, ds[i]);
      } else {
        out << (i ? "\n" : "") << heading(ds[i]) << "\n";
        answers_text(out, ds[i]);
      }
    }
  }
  std::string isolations(const Model& m, const std::vector<Isolation>& found) const override {
    const SymbolTable& table = *m.symbols;
    auto shown = [&](const GiNaC::ex& e) { return to_text(fold_definitions(e, table)); };
    std::string out;
    for (const auto& r : found) {
      const std::string name = to_text(r.unknown);
      if (!r.equation) {
        if (r.impossible)
          out += name +
                 ": no single balance equation of one body contains it alone (no direction, point or axis "
                 "does); it takes a system of equations.\n";
        else
          out += name + ": none of the " + std::to_string(r.tried) + " balance equations tried contains it alone.\n";
        continue;
      }
      out += name + ": " + r.equation->label + " contains it alone.\n";
      out += "    " + shown(r.equation->lhs) + " = " + shown(r.equation->rhs) + "\n";
      out += "    " + name + " = " + shown(*r.value);
      if (auto v = evaluate(*r.value, table, table.find(r.unknown)->dimension))
        out += "  = " + v->decimal + (v->unit.empty() ? "" : " " + v->unit);
      out += "\n";
    }
    return out;
  }
};

}  // namespace

const Writer& text_writer() {
  static const TextWriter w;
  return w;
}

}  // namespace tackle

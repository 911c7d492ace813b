// Writers for `tackle isolate`: which single equation gives each unknown alone.
#include <nlohmann/json.hpp>

#include "expr/print.hpp"
#include "report/isolation_report.hpp"

namespace tackle {

std::string write_isolations(const Model& m, const std::vector<Isolation>& found, Format f) {
  const SymbolTable& table = *m.symbols;
  auto shown = [&](const GiNaC::ex& e) { return to_text(fold_definitions(e, table)); };
  if (f == Format::json) {
    nlohmann::ordered_json j;
    j["version"] = 1;
    j["title"] = m.title;
    j["isolations"] = nlohmann::ordered_json::array();
    for (const auto& r : found) {
      nlohmann::ordered_json x;
      x["unknown"] = to_text(r.unknown);
      x["found"] = r.equation.has_value();
      x["impossible"] = r.impossible;
      x["tried"] = r.tried;
      if (r.equation) {
        x["equation"] = {{"label", r.equation->label},
                         {"lhs", shown(r.equation->lhs)},
                         {"rhs", shown(r.equation->rhs)},
                         {"latex", to_latex(fold_definitions(r.equation->lhs, table)) + " = " +
                                       to_latex(fold_definitions(r.equation->rhs, table))}};
        x["closed_form"] = shown(*r.value);
        x["latex"] = to_latex(fold_definitions(*r.value, table));
        if (auto v = evaluate(*r.value, table, table.find(r.unknown)->dimension)) {
          x["value"] = v->approx;
          x["unit"] = v->unit;
        }
      }
      j["isolations"].push_back(x);
    }
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  }
  std::string out;
  for (const auto& r : found) {
    const std::string name = to_text(r.unknown);
    if (!r.equation) {
      if (r.impossible)
        out += name + ": no single balance equation of one body contains it alone (no direction, point or axis "
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

}  // namespace tackle

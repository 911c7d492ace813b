// The JSON format: the derivation (version 2, self-contained: parameters, definitions,
// equations, answers; derivation.schema.json), the phases, the answer key, the isolations.
#include <nlohmann/json.hpp>

#include "expr/print.hpp"
#include "report/writer.hpp"
#include "report/writers/common.hpp"

namespace tackle {

using namespace GiNaC;
using namespace writers;

namespace {

// A number with its unit: the value (in the unit), its exact form and its decimal.
nlohmann::ordered_json number_json(const NumericValue& v) {
  return {{"value", v.approx}, {"exact", to_text(v.exact)}, {"decimal", v.decimal}, {"unit", v.unit}};
}

// A condition solved for a parameter, with its bound's number at the given numbers.
nlohmann::ordered_json solved_json(const SolvedFor& sv) {
  using J = nlohmann::ordered_json;
  J y{{"parameter", to_text(sv.parameter)},
      {"condition", to_text(sv.parameter) + " " + sv.op + " " + to_text(sv.bound)},
      {"latex", to_latex(sv.parameter) + " " + tex_relation(sv.op) + " " + to_latex(sv.bound)}};
  if (!sv.provided.is_zero()) y["while_positive"] = to_text(sv.provided);  // as at the given numbers
  y["bound_value"] = sv.number ? number_json(sv.number->value) : J(nullptr);
  if (sv.number && sv.number->root) y["root_value"] = number_json(*sv.number->root);
  y["every_value"] = sv.number && sv.number->every_value;
  y["no_value"] = sv.number && sv.number->no_value;
  return y;
}

// A parameter's range at the given numbers: each side's bound (null: none asked).
nlohmann::ordered_json range_json(const ParameterRange& r) {
  using J = nlohmann::ordered_json;
  auto side = [](const std::optional<NumericValue>& v, bool strict) {
    if (!v) return J(nullptr);
    J x = number_json(*v);
    x["strict"] = strict;
    return x;
  };
  return J{{"parameter", to_text(r.parameter)},
           {"low", side(r.low, r.low_strict)},
           {"high", side(r.high, r.high_strict)},
           {"given", r.given ? number_json(*r.given) : J(nullptr)},
           {"empty", r.empty}};
}

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
  if (e.linearised && e.dof > 1)
    j["linearised"] = {{"about", to_text(e.linearised->about)},
                       {"stiffness", mat(e.linearised->stiffness_matrix)},
                       {"frequencies", e.linearised->frequencies}};
  else if (e.linearised)
    j["linearised"] = {{"about", to_text(e.linearised->about)},
                       {"lambda_squared", expr(e.linearised->stiffness)},
                       {"lambda", e.linearised->lambda ? J(*e.linearised->lambda) : J(nullptr)}};
  j["accelerations"] = J::array();
  for (std::size_t i = 0; i < e.acceleration.size(); ++i)  // (none in the mass-matrix form)
    j["accelerations"].push_back({{"coordinate", to_text(e.q[i])}, {"acceleration", expr(e.acceleration[i])}});
  if (e.mass_form) {  // M(q) q'' = F: the mass matrix in the coordinates, and F
    j["mass"] = mat(e.M);
    j["forcing"] = J::array();
    for (const auto& f : e.forcing) j["forcing"].push_back(to_text(f));
  }
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
    static const char* const regimes[] = {"undamped",   "underdamped",   "critically_damped",
                                          "overdamped", "free_particle", "damped_particle"};
    const Response& r = *mo.response;
    J resp{{"regime", regimes[static_cast<int>(r.regime)]},
           {"coordinate", expr(r.q)},
           {"rate", expr(r.rate)},
           {"definitions", J::array()},
           {"assumptions", J::array()},
           {"verified", r.verified}};
    for (const auto& a : r.assumptions)
      resp["assumptions"].push_back(to_text(a.lhs) + " " + a.op + " " + to_text(a.rhs) + " (" + a.why + ")");
    for (const auto& [sym, def] : r.definitions)
      resp["definitions"].push_back({{"name", to_text(sym)}, {"definition", expr(def)}});
    j["response"] = resp;
    if (!mo.direction_assumed_by.empty()) {
      // The interval on which the response holds: while the rate keeps its sign.
      J dir{{"assumed_by", mo.direction_assumed_by}};
      dir["until"] = mo.direction_until ? expr(*mo.direction_until) : J(nullptr);
      dir["until_value"] = mo.direction_until_s ? J(*mo.direction_until_s) : J(nullptr);
      dir["kept"] = mo.direction_kept;
      dir["against_at_start"] = mo.direction_against.empty() ? J(nullptr) : J(mo.direction_against);
      j["direction"] = dir;
    }
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
    e["speed_value"] =
        en.rate_squared_number && *en.rate_squared_number >= 0 ? J(std::sqrt(*en.rate_squared_number)) : J(nullptr);
    j["energy"] = e;
  }
  j["quantities"] = J::array();
  for (const auto& q : mo.quantities) j["quantities"].push_back({{"name", q.name}, {"in_time", expr(q.of_t)}});
  j["not_followed"] = J::array();
  for (const auto& [source, why] : mo.not_followed) j["not_followed"].push_back({{"source", source}, {"why", why}});
  j["conditions"] = J::array();
  for (const auto& c : mo.conditions) {
    const std::string& op = c.condition.op;
    J x{{"source", c.condition.source}, {"in_time", to_text(c.of_t) + " " + op + " 0"}};
    x["extreme"] = c.extreme ? J(to_text(*c.extreme) + " " + op + " 0") : J(nullptr);
    x["extreme_at"] = c.extreme_at ? J(to_text(*c.extreme_at)) : J(nullptr);
    x["for_all_t"] = J::array();
    x["for_all_t_solved"] = J::array();
    for (const auto& sv : c.solved) {
      x["for_all_t"].push_back(to_text(sv.parameter) + " " + sv.op + " " + to_text(sv.bound));
      x["for_all_t_solved"].push_back(solved_json(sv));
    }
    x["holds_for_all_t"] = c.holds_for_all_t ? J(*c.holds_for_all_t) : J(nullptr);
    x["first_failure"] = c.first_failure ? J(to_text(*c.first_failure)) : J(nullptr);
    x["first_failure_s"] = c.first_failure_s ? J(*c.first_failure_s) : J(nullptr);
    if (c.steady_of_t) {
      J st{{"in_time", to_text(*c.steady_of_t) + " " + op + " 0"}, {"offset", to_text(*c.steady_offset)}};
      st["amplitude_condition"] =
          c.steady_amplitude_condition ? J(to_text(*c.steady_amplitude_condition) + " >= 0") : J(nullptr);
      st["holds"] = c.steady_holds ? J(*c.steady_holds) : J(nullptr);
      st["band"] = J(nullptr);
      if (c.band)
        st["band"] = {{"variable", to_text(c.band->variable)},
                      {"low", to_text(c.band->low)},
                      {"high", to_text(c.band->high)},
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
    if (p.stated)
      x["stated"] = {{"value", p.stated->approx}, {"exact", to_text(p.stated->exact)}, {"unit", p.stated->unit}};
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
    nlohmann::ordered_json x{{"expression", to_text(c.combination)},
                             {"closed_form", to_text(c.value)},
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
    for (const auto& sv : c.solved) x["solved"].push_back(solved_json(sv));
    j["conditions"].push_back(x);
  }
  j["ranges"] = nlohmann::ordered_json::array();
  for (const auto& r : d.ranges) j["ranges"].push_back(range_json(r));
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
  if (!d.regimes.empty()) {
    // Connections decided at the numbers: sticking, or slipping where sticking cannot hold.
    auto& regimes = j["regimes"] = nlohmann::ordered_json::array();
    for (const auto& c : d.regimes) {
      nlohmann::ordered_json r{{"connection", c.connection},
                               {"tried", c.first},
                               {"chosen", c.chosen},
                               {"failed", c.failed},
                               {"decided", !c.undecided}};
      auto& bounds = r["holds_while"] = nlohmann::ordered_json::array();
      auto text_or_null = [](const std::string& t) {
        return t.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(t);
      };
      for (const auto& b : c.holds_while)
        bounds.push_back({{"meaning", b.meaning},
                          {"parameter", to_text(b.parameter)},
                          {"op", b.op},
                          {"bound", to_text(b.bound)},
                          {"bound_value", text_or_null(b.value)},
                          {"tightest", b.tightest}});
      if (c.friction) {
        const auto& f = *c.friction;
        r["friction"] = {{"on", f.body},
                         {"unknown", to_text(f.unknown)},
                         {"closed_form", to_text(f.value)},
                         {"value", text_or_null(f.value_number)},
                         {"limit", f.limit.is_zero() ? nlohmann::ordered_json(nullptr)
                                                     : nlohmann::ordered_json(to_text(f.limit_value))},
                         {"limit_value", text_or_null(f.limit_number)}};
      } else {
        r["friction"] = nullptr;
      }
      regimes.push_back(std::move(r));
    }
  }
  if (d.motion) j["motion"] = motion_json(*d.motion);
  if (full) {
    j["equations"] = nlohmann::ordered_json::array();
    for (const auto& eq : d.equations) {
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
    for (const auto& u : d.unknowns) j["solved_for"].push_back(to_text(u));
    j["constraints"] = nlohmann::ordered_json::array();
    for (const auto& c : d.constraint_steps)
      j["constraints"].push_back({{"label", c.label},
                                  {"quantity", to_text(c.quantity)},
                                  {"rate", to_text(c.rate)},
                                  {"acceleration", to_text(c.acceleration)}});
  }
  if (full) {
    for (const auto& eq : d.impact_equations)
      j["equations"].push_back({{"label", eq.label},
                                {"kind", kind_name(eq.kind)},
                                {"lhs", to_text(eq.lhs)},
                                {"rhs", to_text(eq.rhs)},
                                {"latex", to_latex(eq.lhs) + " = " + to_latex(eq.rhs)},
                                {"sources", eq.sources}});
  }
  return j;
}

std::string json_document(const Derivation& d, bool full) {
  return json_object(d, full).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

class JsonWriter final : public Writer {
 public:
  const char* name() const override { return "json"; }
  std::string derivation(const Derivation& d, bool full) const override { return json_document(d, full); }
  std::string phases(const std::vector<Derivation>& ds, bool full) const override {
    nlohmann::ordered_json j;
    j["version"] = 2;
    j["title"] = ds[0].title;
    j["file"] = ds[0].file;
    j["phases"] = nlohmann::ordered_json::array();
    for (const auto& d : ds) j["phases"].push_back(json_object(d, full));
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  }

  std::string key(const std::vector<KeyEntry>& entries) const override {
    nlohmann::ordered_json j;
    j["version"] = 1;
    j["problems"] = nlohmann::ordered_json::array();
    for (const auto& e : entries) {
      const Derivation& d = *e.derivation;
      nlohmann::ordered_json p;
      p["title"] = d.title;
      p["file"] = d.file;
      p["status"] = d.status;
      p["answers"] = nlohmann::ordered_json::array();
      for (const auto& a : d.answers) {
        nlohmann::ordered_json x{{"name", a.name}};
        if (a.closed_form) {
          x["closed_form"] = to_text(*a.closed_form);
          x["latex"] = to_latex(*a.closed_form);
        } else if (a.general) {
          x["general"] = to_text(*a.general);
        }
        if (a.value) {
          x["value"] = a.value->approx;
          x["decimal"] = a.value->decimal;
          x["unit"] = a.value->unit;
        }
        p["answers"].push_back(x);
      }
      p["variants"] = nlohmann::ordered_json::array();
      if (e.variants_asked && e.variants.empty()) p["no_variants"] = "no parameter of this problem has a 'range'";
      for (const auto& v : e.variants) {
        nlohmann::ordered_json x{{"index", v.index}};
        // Numbers as JSON numbers, like the answers above; `decimal` as printed in the key.
        for (const auto& q : v.parameters)
          x["parameters"][q.name] = {{"value", q.value}, {"decimal", q.number}, {"unit", q.unit}};
        for (const auto& q : v.answers)
          x["answers"][q.name] = {{"value", q.value}, {"decimal", q.number}, {"unit", q.unit}};
        p["variants"].push_back(x);
      }
      j["problems"].push_back(p);
    }
    return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
  }

  std::string isolations(const Model& m, const std::vector<Isolation>& found) const override {
    const SymbolTable& table = *m.symbols;
    auto shown = [&](const GiNaC::ex& e) { return to_text(fold_definitions(e, table)); };
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
};

}  // namespace

const Writer& json_writer() {
  static const JsonWriter w;
  return w;
}

}  // namespace tackle

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

using J = nlohmann::ordered_json;

// A number with its unit: the value (in the unit), its exact form and its decimal.
nlohmann::ordered_json number_json(const NumericValue& v) {
  return {{"value", v.approx}, {"exact", to_text(v.exact)}, {"decimal", v.decimal}, {"unit", v.unit}};
}

// A condition solved for a parameter, with its bound's number at the given numbers.
nlohmann::ordered_json solved_json(const SolvedFor& sv) {
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

// An expression as text and LaTeX.
J expr_json(const GiNaC::ex& x) { return J{{"text", to_text(x)}, {"latex", to_latex(x)}}; }

// A matrix as rows of text.
J matrix_json(const GiNaC::matrix& m) {
  J rows = J::array();
  for (unsigned i = 0; i < m.rows(); ++i) {
    J row = J::array();
    for (unsigned k = 0; k < m.cols(); ++k) row.push_back(to_text(m(i, k)));
    rows.push_back(row);
  }
  return rows;
}

// A list of expressions as text.
J texts_json(const std::vector<GiNaC::ex>& xs) {
  J out = J::array();
  for (const auto& x : xs) out.push_back(to_text(x));
  return out;
}

// The equations of motion: the coordinates, linear or not, linearised about a point, the
// accelerations, and the matrices of the mass-matrix form or of a linear motion.
void equations_of_motion_json(J& j, const EquationsOfMotion& e) {
  j = J{{"degrees_of_freedom", e.dof}, {"coordinates", J::array()}, {"linear", e.linear}};
  for (const auto& q : e.q) j["coordinates"].push_back(to_text(q));
  if (!e.linear) j["nonlinear"] = e.nonlinear;
  if (e.linearised && e.dof > 1)
    j["linearised"] = {{"about", to_text(e.linearised->about)},
                       {"stiffness", matrix_json(e.linearised->stiffness_matrix)},
                       {"frequencies", e.linearised->frequencies}};
  else if (e.linearised)
    j["linearised"] = {{"about", to_text(e.linearised->about)},
                       {"lambda_squared", expr_json(e.linearised->stiffness)},
                       {"lambda", e.linearised->lambda ? J(*e.linearised->lambda) : J(nullptr)}};
  j["accelerations"] = J::array();
  for (std::size_t i = 0; i < e.acceleration.size(); ++i)  // (none in the mass-matrix form)
    j["accelerations"].push_back({{"coordinate", to_text(e.q[i])}, {"acceleration", expr_json(e.acceleration[i])}});
  if (e.mass_form) {  // M(q) q'' = F: the mass matrix in the coordinates, and F
    j["mass"] = matrix_json(e.M);
    j["forcing"] = texts_json(e.forcing);
  }
  if (e.linear) {
    j["mass"] = matrix_json(e.M);
    j["damping"] = matrix_json(e.C);
    j["stiffness"] = matrix_json(e.K);
    j["forcing"] = texts_json(e.forcing);
    j["natural_frequencies"] = e.natural_frequencies;
    j["equilibrium"] = J(nullptr);
    if (e.equilibrium) j["equilibrium"] = texts_json(*e.equilibrium);
  }
}

// The response in closed form, and the interval on which it holds (while the rate keeps its
// sign); or why there is none.
void response_json(J& j, const Motion& mo) {
  if (!mo.response) {
    j["response"] = J(nullptr);
    j["no_response"] = mo.no_response;
    return;
  }
  static const char* const regimes[] = {"undamped",   "underdamped",   "critically_damped",
                                        "overdamped", "free_particle", "damped_particle"};
  const Response& r = *mo.response;
  J resp{{"regime", regimes[static_cast<int>(r.regime)]},
         {"coordinate", expr_json(r.q)},
         {"rate", expr_json(r.rate)},
         {"definitions", J::array()},
         {"assumptions", J::array()},
         {"verified", r.verified}};
  for (const auto& a : r.assumptions)
    resp["assumptions"].push_back(to_text(a.lhs) + " " + a.op + " " + to_text(a.rhs) + " (" + a.why + ")");
  for (const auto& [sym, def] : r.definitions)
    resp["definitions"].push_back({{"name", to_text(sym)}, {"definition", expr_json(def)}});
  j["response"] = resp;
  if (mo.direction_assumed_by.empty()) return;
  J dir{{"assumed_by", mo.direction_assumed_by}};
  dir["until"] = mo.direction_until ? expr_json(*mo.direction_until) : J(nullptr);
  dir["until_value"] = mo.direction_until_s ? J(*mo.direction_until_s) : J(nullptr);
  dir["kept"] = mo.direction_kept;
  dir["against_at_start"] = mo.direction_against.empty() ? J(nullptr) : J(mo.direction_against);
  j["direction"] = dir;
}

// The energy answer: the work done to a position, and the rate squared there.
J energy_json(const EnergyAnswer& en) {
  J e{{"position", to_text(en.position)}, {"numeric_only", en.numeric_only}};
  if (!en.not_possible.empty()) e["not_possible"] = en.not_possible;
  if (!en.numeric_only && en.not_possible.empty()) e["work"] = expr_json(en.work);
  e["rate_squared"] = en.rate_squared ? expr_json(*en.rate_squared) : J(nullptr);
  e["rate_squared_value"] = en.rate_squared_number ? J(*en.rate_squared_number) : J(nullptr);
  e["speed_value"] =
      en.rate_squared_number && *en.rate_squared_number >= 0 ? J(std::sqrt(*en.rate_squared_number)) : J(nullptr);
  return e;
}

// The steady state of a condition in time: the condition, its offset and amplitude, the band
// of a parameter where it fails.
J steady_state_json(const ConditionInTime& c) {
  const std::string& op = c.condition.op;
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
  return st;
}

// A validity condition along the motion: in time, its extreme, solved for all t, where it
// first fails, its steady state.
J motion_condition_json(const ConditionInTime& c) {
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
  if (c.steady_of_t) x["steady_state"] = steady_state_json(c);
  return x;
}

// Motion in time for the JSON: the equations of motion, the response, the quantities and the
// conditions along it (text and LaTeX for each expression).
J motion_json(const Motion& mo) {
  J j;
  equations_of_motion_json(j, mo.eom);
  response_json(j, mo);
  if (mo.energy) j["energy"] = energy_json(*mo.energy);
  j["quantities"] = J::array();
  for (const auto& q : mo.quantities) j["quantities"].push_back({{"name", q.name}, {"in_time", expr_json(q.of_t)}});
  j["not_followed"] = J::array();
  for (const auto& [source, why] : mo.not_followed) j["not_followed"].push_back({{"source", source}, {"why", why}});
  j["conditions"] = J::array();
  for (const auto& c : mo.conditions) j["conditions"].push_back(motion_condition_json(c));
  return j;
}

// A parameter: its name, kind, value in SI and as stated, its definition.
J parameter_json(const ParameterReport& p) {
  J x{{"name", p.name}, {"tex", p.tex}, {"kind", p.kind}};
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
  return x;
}

// An answer: its status, closed form, what it misses, its number.
J unknown_json(const Answer& a) {
  J u{{"name", a.name}, {"status", status_name(a.status)}};
  if (a.closed_form) {
    u["closed_form"] = to_text(*a.closed_form);
    u["latex"] = to_latex(*a.closed_form);
    if (a.in_parameters) u["in_parameters"] = to_text(*a.in_parameters);
  }
  if (a.general) u["general"] = to_text(*a.general);
  if (!a.reason.empty()) {
    u["missing"] = J::array();
    for (const auto& x : a.missing) u["missing"].push_back(to_text(x));
    u["reason"] = a.reason;
  }
  if (a.value) {
    u["value"] = a.value->approx;
    u["exact"] = to_text(a.value->exact);
    u["decimal"] = a.value->decimal;
    u["unit"] = a.value->unit;
  }
  return u;
}

// A combination of undetermined unknowns that is determined.
J combination_json(const CombinationReport& c) {
  J x{{"expression", to_text(c.combination)},
      {"closed_form", to_text(c.value)},
      {"latex", to_latex(c.combination) + " = " + to_latex(c.value)}};
  if (c.number) {
    x["value"] = c.number->approx;
    x["unit"] = c.number->unit;
  }
  return x;
}

// A validity condition: as written and simplified, whether it holds, its solved forms.
J condition_json(const ConditionReport& c) {
  J x{{"source", c.source},
      {"inequality", to_text(c.lhs) + " " + c.op + " " + to_text(c.rhs)},
      {"simplified", to_text(c.simplified) + " " + c.op + " 0"},
      {"meaning", c.meaning},
      {"otherwise", c.otherwise}};
  x["holds"] = c.holds ? J(*c.holds) : J(nullptr);
  x["always"] = c.always ? J(*c.always) : J(nullptr);
  x["solved"] = J::array();
  for (const auto& sv : c.solved) x["solved"].push_back(solved_json(sv));
  return x;
}

// The power balance: d/dt(E_k) = P, checked with the solution put in.
J power_json(const PowerCheck& power) {
  static const char* const names[] = {"holds", "fails", "not_applicable"};
  J p{{"status", names[static_cast<int>(power.status)]}};
  if (power.status == PowerCheck::Status::not_applicable) {
    p["reason"] = power.reason;
  } else {
    p["kinetic_energy_rate"] = to_text(power.kinetic_rate);
    p["power"] = to_text(power.power);
    if (power.status == PowerCheck::Status::fails) p["residual"] = to_text(power.residual);
  }
  return p;
}

// Text, or null when there is none.
J text_or_null(const std::string& t) { return t.empty() ? J(nullptr) : J(t); }

// A connection decided at the numbers: sticking, or slipping where sticking cannot hold; the
// bounds it holds within, and its friction.
J regime_json(const RegimeChoice& c) {
  J r{{"connection", c.connection},
      {"tried", c.first},
      {"chosen", c.chosen},
      {"failed", c.failed},
      {"decided", !c.undecided}};
  auto& bounds = r["holds_while"] = J::array();
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
                     {"limit", f.limit.is_zero() ? J(nullptr) : J(to_text(f.limit_value))},
                     {"limit_value", text_or_null(f.limit_number)}};
  } else {
    r["friction"] = nullptr;
  }
  return r;
}

// An equation that was solved: its label, kind, sides and sources.
J equation_json(const Equation& eq) {
  return J{{"label", eq.label},
           {"kind", kind_name(eq.kind)},
           {"lhs", to_text(eq.lhs)},
           {"rhs", to_text(eq.rhs)},
           {"latex", to_latex(eq.lhs) + " = " + to_latex(eq.rhs)},
           {"sources", eq.sources}};
}

// What was solved, for a program to solve it again: the equations, the unknowns they are
// solved for (in the solver's order: the answers asked for may be fewer), the constraints,
// then an impact's equations.
void what_was_solved_json(J& j, const Derivation& d) {
  j["equations"] = J::array();
  for (const auto& eq : d.equations) j["equations"].push_back(equation_json(eq));
  j["solved_for"] = J::array();
  for (const auto& u : d.unknowns) j["solved_for"].push_back(to_text(u));
  j["constraints"] = J::array();
  for (const auto& c : d.constraint_steps)
    j["constraints"].push_back({{"label", c.label},
                                {"quantity", to_text(c.quantity)},
                                {"rate", to_text(c.rate)},
                                {"acceleration", to_text(c.acceleration)}});
  for (const auto& eq : d.impact_equations) j["equations"].push_back(equation_json(eq));
}

// The results: the answers, the combinations, the free unknowns, the least-norm member, the
// conflicts, the conditions and the parameters' ranges.
void results_json(J& j, const Derivation& d) {
  j["unknowns"] = J::array();
  for (const auto& a : d.answers) j["unknowns"].push_back(unknown_json(a));
  j["combinations"] = J::array();
  for (const auto& c : d.combinations) j["combinations"].push_back(combination_json(c));
  j["free"] = d.free;
  if (!d.minimum_norm.empty()) {
    j["minimum_norm"] = J::object();
    for (const auto& [name, v] : d.minimum_norm) j["minimum_norm"][name] = {{"value", v->approx}, {"unit", v->unit}};
  }
  j["conflicts"] = d.conflicts;
  j["conditions"] = J::array();
  for (const auto& c : d.conditions) j["conditions"].push_back(condition_json(c));
  j["ranges"] = J::array();
  for (const auto& r : d.ranges) j["ranges"].push_back(range_json(r));
}

J json_object(const Derivation& d, bool full) {
  J j;
  j["version"] = 2;
  j["title"] = d.title;
  if (!d.phase.empty()) j["phase"] = d.phase;
  j["file"] = d.file;
  j["status"] = d.status;
  j["rank"] = d.rank;
  // Self-contained: every name a closed form may use, with its value, unit and definition.
  j["parameters"] = J::array();
  for (const auto& p : d.parameters) j["parameters"].push_back(parameter_json(p));
  results_json(j, d);
  j["power_check"] = power_json(d.power);
  if (!d.regimes.empty()) {
    auto& regimes = j["regimes"] = J::array();
    for (const auto& c : d.regimes) regimes.push_back(regime_json(c));
  }
  if (d.motion) j["motion"] = motion_json(*d.motion);
  if (full) what_was_solved_json(j, d);
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

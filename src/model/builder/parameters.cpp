// The axes and the parameters: the problem's first symbols, with their dimensions, units,
// signs, values and ranges.
#include "model/builder/stages.hpp"

#include <set>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"

namespace tackle::build {

using namespace GiNaC;

void axes(BuildContext& ctx) {
  if (ctx.d.axes.empty()) return;  // default: one axis named x
  if (ctx.d.axes.size() > 3) {
    ctx.diags.error(ctx.d.axes[3].at,
                    "'axes' lists " + std::to_string(ctx.d.axes.size()) + " axes (expected one to three)");
    return;
  }
  std::set<std::string> seen;
  ctx.m.axes.clear();
  for (const auto& a : ctx.d.axes) {
    if (!is_identifier(a.text)) ctx.diags.error(a.at, "axis name '" + a.text + "' is not a valid name");
    if (!seen.insert(a.text).second) ctx.diags.error(a.at, "duplicate axis '" + a.text + "'");
    ctx.m.axes.push_back(a.text);
  }
  ctx.m.axis = ctx.m.axes[0];
}

namespace {

// A parameter's unit, as written; reported when it cannot be read.
std::optional<Unit> unit_of(BuildContext& ctx, const ParameterDesc& p) {
  std::optional<Unit> unit;
  if (p.unit) {
    std::string err;
    int col = 0;
    unit = parse_unit(p.unit->text, err, col);
    if (!unit)
      ctx.diags.error(p.unit->at.shifted(col), "unit of parameter '" + p.name.text + "': " + err +
                                                   " (expected SI units such as kg, m, s, N, m/s^2, kN)");
  }
  return unit;
}

// A parameter's dimension: its unit's, or the one it names (which must agree with its unit); a
// value with neither unit nor dimension is a pure number.
std::optional<Dimension> dimension_of_parameter(BuildContext& ctx, const ParameterDesc& p,
                                                const std::optional<Unit>& unit) {
  std::optional<Dimension> dim;
  if (unit) dim = unit->dimension;
  // A value with neither unit nor dimension is a pure number (a friction coefficient).
  if (!p.unit && !p.dimension && p.value && !p.define) dim = Dimension::none();
  if (p.dimension) {
    auto named = Dimension::from_name(p.dimension->text);
    if (!named)
      ctx.diags.error(p.dimension->at, "unknown dimension '" + p.dimension->text +
                                           "' (expected force, mass, length, time, velocity, acceleration, ...)");
    else if (dim && !(*dim == *named))
      ctx.diags.error(p.dimension->at,
                      "parameter '" + p.name.text + "' has dimension " + named->describe() + " but its unit " +
                          p.unit->text + " is " +
                          (*dim == Dimension::none() ? std::string("dimensionless (an angle or a pure number)")
                                                     : with_article(dim->describe())));
    else
      dim = named;
  }
  return dim;
}

// A parameter's `range` (low < high, positive for a positive parameter) and the step it is
// rounded to.
void read_range(BuildContext& ctx, const ParameterDesc& p, bool positive) {
  std::optional<numeric> bounds[2], step;
  for (int i = 0; i < 2; ++i) {
    auto v = ctx.parse(p.range[i], none, "'range' of parameter '" + p.name.text + "'");
    if (v && is_a<numeric>(*v)) bounds[i] = ex_to<numeric>(*v);
  }
  if (p.round) {
    auto v = ctx.parse(*p.round, none, "'round' of parameter '" + p.name.text + "'");
    if (v && is_a<numeric>(*v) && ex_to<numeric>(*v).is_positive())
      step = ex_to<numeric>(*v);
    else if (v)
      ctx.diags.error(p.round->at, "'round' of parameter '" + p.name.text + "' is not a positive number");
  }
  if (bounds[0] && bounds[1]) {
    if (!(*bounds[0] < *bounds[1]))
      ctx.diags.error(p.range[0].at, "'range' of parameter '" + p.name.text + "' is empty (expected low < high)");
    else if (positive && !bounds[0]->is_positive())
      ctx.diags.error(p.range[0].at, "'range' of parameter '" + p.name.text + "' reaches " + to_text(*bounds[0]) +
                                         ", but the parameter is positive");
    else
      ctx.table->set_range(p.name.text, *bounds[0], *bounds[1], step);
  }
}

// A parameter's value: a number, or an exact real constant such as pi/6 or sqrt(2), in its
// unit; positive for a positive parameter.
void read_value(BuildContext& ctx, const ParameterDesc& p, const std::optional<Unit>& unit, bool positive) {
  auto v = ctx.parse(*p.value, none, "value of parameter '" + p.name.text + "'");
  // A number, or an exact real constant such as pi/6 or sqrt(2).
  const ex approx = v ? evalf(*v) : ex(0);
  if (v && !(is_a<numeric>(approx) && ex_to<numeric>(approx).is_real()))
    ctx.diags.error(p.value->at, "value of parameter '" + p.name.text + "' is not a number");
  else if (v) {
    const ex value = unit ? *v * unit->to_si : *v;
    if (positive && !ex_to<numeric>(approx).is_positive())
      ctx.diags.error(p.value->at, "parameter '" + p.name.text + "' is assumed positive but its value is " +
                                       to_text(*v) + " (set 'positive: false' to allow it)");
    ctx.table->set_value(p.name.text, value);
  }
}

// One parameter into the symbol table: its unit and dimension, its definition, sign, range and value.
void parameter(BuildContext& ctx, const ParameterDesc& p) {
  if (!ctx.claim(p.name, "parameter")) return;
  const std::optional<Unit> unit = unit_of(ctx, p);
  std::optional<Dimension> dim = dimension_of_parameter(ctx, p, unit);
  // A defined parameter: its dimension, sign and value come from its expression.
  std::optional<ex> definition;
  if (p.define) {
    definition = ctx.parse(*p.define, *ctx.table, "'define' of parameter '" + p.name.text + "'");
    if (!definition) return;
    std::string problem;
    dim = dimension_of(*definition, *ctx.table, problem);
    if (!problem.empty()) ctx.diags.error(p.define->at, "'define' of parameter '" + p.name.text + "' " + problem);
  }
  const bool positive = p.positive.value_or(p.name.text == "g" ||
                                            (dim && (*dim == Dimension::mass() || *dim == Dimension::length() ||
                                                     *dim == Dimension::force() / Dimension::length() ||
                                                     *dim == Dimension::force() / Dimension::velocity())) ||
                                            (definition && definition->info(info_flags::positive)));
  ctx.table->add(p.name.text, p.tex ? std::optional<std::string>(p.tex->text) : std::nullopt, SymbolRole::parameter,
                 dim, positive, p.name.at);
  if (definition) {
    ctx.table->set_definition(p.name.text, *definition);
    if (NormalForm(*definition).undefined_at(ctx.table->values()))
      ctx.diags.error(p.define->at, "'define' of parameter '" + p.name.text + "' is undefined at the given values (" +
                                        to_text(*definition) + " divides by zero there)");
  }
  ctx.table->set_unit(p.name.text, p.unit && unit ? p.unit->text : si_unit_name(dim.value_or(Dimension{})),
                      unit ? unit->to_si : numeric(1));
  if (!p.range.empty()) read_range(ctx, p, positive);
  if (p.value) read_value(ctx, p, unit, positive);
}

}  // namespace

void parameters(BuildContext& ctx) {
  for (const auto& p : ctx.d.parameters) parameter(ctx, p);
  // Time, t, for loads and points that move with it and for motion in time; unless the
  // description names a parameter t, in which case nothing may depend on time.
  if (!ctx.table->find("t")) {
    ctx.m.time = ctx.table->add("t", std::string("t"), SymbolRole::time, Dimension::time(), false, Location{}).sym;
    ctx.names_in_use["t"] = Location{};
  }
}

}  // namespace tackle::build
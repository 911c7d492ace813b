// The questions: the given quantities and their values, the quantities to find, the
// constraints' constants for position questions, and the balances asked for (derive).
#include "model/builder/stages.hpp"

#include "core/placeholders.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"

#include <algorithm>
#include <cctype>
#include <set>

namespace tackle::build {

using namespace GiNaC;

namespace {

// The unit a `find` entry asks for, checked against the quantity's dimension.
std::optional<Unit> output_unit(BuildContext& ctx, const FindDesc& f, std::optional<Dimension> dim) {
  if (!f.unit) return std::nullopt;
  std::string err;
  int col = 0;
  auto unit = parse_unit(f.unit->text, err, col);
  if (!unit) {
    ctx.diags.error(f.unit->at.shifted(col), "unit of '" + f.name.text + "' in 'find': " + err);
    return std::nullopt;
  }
  if (dim && !(unit->dimension == *dim)) {
    ctx.diags.error(f.unit->at, "'" + f.name.text + "' is " + with_article(dim->describe()) + ", but " + f.unit->text +
                                    " is " + with_article(unit->dimension.describe()));
    return std::nullopt;
  }
  return unit;
}

// A given value names parameters only (another given quantity or an unknown has no value to
// give), is real at their values, and, without a unit, has the quantity's dimension.
bool given_in_parameters(const ex& v, const SymbolInfo& s, bool with_unit, const SymbolTable& table, const Location& at,
                         const std::string& what, Diagnostics& to) {
  for (const ex& x : distinct_symbols(v)) {
    const SymbolInfo* info = table.find(x);
    if (info && info->role == SymbolRole::parameter) continue;
    to.error(at,
             what + ": '" + to_text(x) + "' is not a parameter (expected a number or an expression in the parameters)");
    return false;
  }
  const ex approx = evalf(substituted(v, table.values()));
  if (is_a<numeric>(approx) && !ex_to<numeric>(approx).is_real()) {
    to.error(at, what + " is not a real number (expected a real value at the parameters' values)");
    return false;
  }
  if (with_unit || is_a<numeric>(v) || !s.dimension) return true;
  std::string problem;
  const auto dim = dimension_of(v, table, problem);
  if (!dim && !problem.empty())
    to.error(at, what + " " + problem + " (expected " + with_article(s.dimension->describe()) + ")");
  else if (dim && !(*dim == *s.dimension))
    to.error(at, what + " is " + with_article(dim->describe()) + " (expected " + with_article(s.dimension->describe()) +
                     ")");
  return !dim || *dim == *s.dimension;
}

}  // namespace

// The value of a `given` entry in SI, a number or an expression in the parameters (v/R),
// checked against the quantity's dimension; nothing (with the problem reported to `to`) when
// it is neither, or of another dimension.
std::optional<ex> given_value(const GivenDesc& g, const SymbolInfo& s, const SymbolTable& table, Diagnostics& to,
                              std::string* unit_text, ex* to_si) {
  const std::string what = "'given' value of '" + g.name.text + "'";
  std::optional<Unit> unit;
  if (g.unit) {
    std::string err;
    int col = 0;
    unit = parse_unit(g.unit->text, err, col);
    if (!unit) {
      to.error(g.unit->at.shifted(col), "unit of " + what + ": " + err);
      return std::nullopt;
    }
    if (s.dimension && !(unit->dimension == *s.dimension)) {
      to.error(g.unit->at, "'" + g.name.text + "' is " + with_article(s.dimension->describe()) + ", but " +
                               g.unit->text + " is " + with_article(unit->dimension.describe()));
      return std::nullopt;
    }
  }
  auto r = parse_expression(g.value->text, table);
  if (!r.value) {
    for (const auto& p : r.problems) to.error(g.value->at.shifted(p.column), what + ": " + p.message);
    return std::nullopt;
  }
  if (!given_in_parameters(*r.value, s, unit.has_value(), table, g.value->at, what, to)) return std::nullopt;
  if (unit_text) *unit_text = unit ? g.unit->text : si_unit_name(s.dimension.value_or(Dimension{}));
  if (to_si) *to_si = unit ? ex(unit->to_si) : ex(1);
  return unit ? *r.value * unit->to_si : *r.value;
}

namespace {

// A given value: a number is the quantity's value; an expression in the parameters is its
// definition (its value follows from theirs, and what is solved for a parameter in it knows
// that the quantity moves with it). With a motion the instant's given values are numbers: the
// motion's coordinates and rates vary, and start from `initial`.
void set_given(BuildContext& ctx, const SymbolInfo& s, const ex& v, const Text& written) {
  if (distinct_symbols(v).empty()) {
    ctx.table->set_value(s.name, v);
    return;
  }
  if (!ctx.d.motion) {
    ctx.table->set_definition(s.name, v);
    return;
  }
  const ex at = substituted(v, ctx.table->values());
  if (distinct_symbols(at).empty()) {
    ctx.table->set_value(s.name, at);
    return;
  }
  ctx.diags.error(written.at, "'given' value of '" + s.name +
                                  "': with a 'motion', the instant's given values are numbers, and " +
                                  to_text(distinct_symbols(at).front()) +
                                  " has no value (expected a value for it in 'parameters')");
}

// The steady rate or its period when a `find` entry names one of them.
const Wanted* steady_reported(const BuildContext& ctx, const FindDesc& f) {
  if (!ctx.m.steady || f.expr) return nullptr;
  for (const auto& w : ctx.m.steady->reported)
    if (w.name == f.name.text) return &w;
  return nullptr;
}

}  // namespace

void given_and_find(BuildContext& ctx) {
  for (const auto& gd : ctx.d.given) {
    const Text& g = gd.name;
    auto r = parse_expression(g.text, *ctx.table);
    if (!r.value) {
      for (const auto& p : r.problems) ctx.diags.error(g.at.shifted(p.column), "'given': " + p.message);
      continue;
    }
    const SymbolInfo* s = ctx.table->find(*r.value);
    if (!s || (s->role != SymbolRole::acceleration && s->role != SymbolRole::rate && s->role != SymbolRole::unknown &&
               s->role != SymbolRole::coordinate)) {
      ctx.diags.error(g.at, "'" + g.text +
                                "' cannot be given (expected a coordinate, a velocity or an acceleration such as "
                                "ddot(x_B), or an unknown)");
      continue;
    }
    if (gd.value) {
      std::string unit_text;
      ex to_si = 1;
      if (auto v = given_value(gd, *s, *ctx.table, ctx.diags, &unit_text, &to_si)) {
        set_given(ctx, *s, *v, *gd.value);
        ctx.table->set_unit(s->name, unit_text, to_si);
      }
    }
    ctx.m.given.push_back(s->sym);
    ctx.m.candidates.erase(std::remove(ctx.m.candidates.begin(), ctx.m.candidates.end(), s->sym),
                           ctx.m.candidates.end());
  }
  // A steady motion's unknown: its rate's square, after the others; its rate and period are
  // reported where `find` names them (else after what it asks for).
  if (ctx.m.steady) ctx.m.candidates.push_back(ctx.m.steady->squared);
  for (const auto& f : ctx.d.find) {
    if (const Wanted* w = steady_reported(ctx, f)) {
      ctx.m.wanted.push_back(*w);
      continue;
    }
    if (f.expr) {
      if (!ctx.claim(f.name, "quantity")) continue;
      auto e = ctx.parse(*f.expr, *ctx.table, "'" + f.name.text + "' in 'find'");
      if (!e) continue;
      std::string problem;
      auto dim = dimension_of(*e, *ctx.table, problem);
      if (!dim && !problem.empty()) ctx.diags.error(f.expr->at, "'" + f.name.text + "' in 'find' " + problem);
      const SymbolInfo& s = ctx.table->add(f.name.text, f.tex ? std::optional<std::string>(f.tex->text) : std::nullopt,
                                           SymbolRole::defined, dim, false, f.name.at);
      ctx.m.wanted.push_back({s.name, s.tex, *e, true, dim, output_unit(ctx, f, dim)});
    } else {
      auto r = parse_expression(f.name.text, *ctx.table);
      if (!r.value) {
        for (const auto& p : r.problems) ctx.diags.error(f.name.at.shifted(p.column), "'find': " + p.message);
        continue;
      }
      const SymbolInfo* s = ctx.table->find(*r.value);
      if (!s) {
        ctx.diags.error(f.name.at,
                        "'find' lists '" + f.name.text + "', which is not a single name (use {name: ..., expr: ...})");
        continue;
      }
      ctx.m.wanted.push_back({s->name, s->tex, s->sym, false, s->dimension, output_unit(ctx, f, s->dimension)});
    }
  }
}

// Position questions: each constraint's constant (the varying part of its quantity keeps
// the value it has; the layout only tells directions, so the constant is a symbol,
// `C_s` for string s, as a person writes "x_S = 2 x + const").
void constraint_constants(BuildContext& ctx) {
  const auto in_questions = symbols_asked(ctx.m.wanted);
  const bool asked = std::any_of(ctx.m.coordinates.begin(), ctx.m.coordinates.end(),
                                 [&](const Coordinate& c) { return in_questions.count(c.q) != 0; });
  if (!asked) return;
  for (auto& c : ctx.m.constraints) {
    const std::string base = c.connection.empty() ? c.label : c.connection;
    std::string name = "C_" + base;
    for (char& ch : name)
      if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_') ch = '_';
    if (ctx.table->find(name)) continue;  // a parameter of that name: no constant for this one
    std::string problem;
    const auto dim = dimension_of(c.quantity, *ctx.table, problem);
    c.constant = ctx.table->add(name, std::nullopt, SymbolRole::parameter, dim, false, Location{}).sym;
  }
}

namespace {

// Bodies named by an lmb or amb entry; all need a mass.
std::optional<std::vector<int>> selected_bodies(BuildContext& ctx, const DeriveDesc& dd) {
  std::vector<int> out;
  bool ok = true;
  for (const auto& item : dd.items) {
    auto it = ctx.body_index.find(item.text);
    if (it == ctx.body_index.end()) {
      ctx.unknown_name(item, "body", ctx.body_names());
      ok = false;
    } else if (!ctx.m.bodies[it->second].has_mass) {
      ctx.diags.error(item.at,
                      "body '" + item.text + "' has no 'mass' (needed for its momentum balance; 0 for a pulley block)");
      ok = false;
    } else {
      out.push_back(it->second);
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace

void derive(BuildContext& ctx) {
  std::set<std::string> constraint_names;
  for (const auto& c : ctx.m.constraints) constraint_names.insert(c.connection);
  for (const auto& dd : ctx.d.derive) {
    if (dd.kind.text == "lmb") {
      Selection s{Selection::Kind::lmb, {}, dd.is_list, {}, {}, zero_vec(), std::nullopt, {}};
      if (auto bodies = selected_bodies(ctx, dd)) {
        s.bodies = *bodies;
        ctx.m.derive.push_back(s);
      }
    } else if (dd.kind.text == "amb") {
      if (ctx.m.dims() == 1) {
        ctx.diags.error(dd.kind.at, "angular momentum balance needs a 2-D or 3-D problem (this one has one axis)");
        continue;
      }
      Selection s{Selection::Kind::amb, {}, dd.is_list, {}, {}, zero_vec(), std::nullopt, {}};
      auto bodies = selected_bodies(ctx, dd);
      if (!bodies || !dd.about) continue;
      s.bodies = *bodies;
      auto p = ctx.point_index.find(dd.about->text);
      if (p == ctx.point_index.end()) {
        ctx.unknown_name(*dd.about, "point", ctx.point_names());
        continue;
      }
      s.about = dd.about->text;
      s.about_position = ctx.m.points[p->second].position;
      if (dd.axis) {
        // Two point names: the line through them; else a direction vector.
        const auto& items = dd.axis->items;
        if (items.size() == 2 && ctx.point_index.count(items[0].text) && ctx.point_index.count(items[1].text)) {
          const Vec from = ctx.m.points[ctx.point_index[items[0].text]].position;
          const Vec to = ctx.m.points[ctx.point_index[items[1].text]].position;
          if (is_zero_vec(to - from)) {
            ctx.diags.error(dd.axis->at, "the axis " + items[0].text + items[1].text +
                                             " has zero length (expected two different points)");
            continue;
          }
          s.axis = unit(to - from);
          s.axis_label = items[0].text + items[1].text;
        } else if (auto v = ctx.vector(*dd.axis, *ctx.table, "'axis' of an 'amb' entry", std::nullopt)) {
          if (is_zero_vec(*v)) {
            ctx.diags.error(dd.axis->at, "the axis of an 'amb' entry is a zero vector");
            continue;
          }
          s.axis = unit(*v);
          std::vector<std::string> parts;
          for (const auto& t : items) parts.push_back(t.text);
          s.axis_label = "[" + join(parts) + "]";
        } else {
          continue;
        }
      }
      ctx.m.derive.push_back(s);
    } else {
      for (const auto& item : dd.items) {
        if (!constraint_names.count(item.text)) {
          std::vector<std::string> known(constraint_names.begin(), constraint_names.end());
          known.erase(std::remove(known.begin(), known.end(), std::string{}), known.end());
          ctx.unknown_name(item, "constraint (a named connection with a constraint)", known);
          continue;
        }
        ctx.m.derive.push_back({Selection::Kind::constraint, {}, false, item.text, {}, zero_vec(), std::nullopt, {}});
      }
    }
  }
}

void statement(BuildContext& ctx) {
  if (!ctx.d.statement) return;
  const Text& st = *ctx.d.statement;
  std::vector<std::string> names;
  for (const auto& s : ctx.table->all())
    if (s->role == SymbolRole::parameter) names.push_back(s->name);
  for (const auto& p : placeholders(st.text)) {
    const std::string name(p.name);
    const SymbolInfo* s = ctx.table->find(name);
    if (!s || s->role != SymbolRole::parameter)
      ctx.diags.error(
          st.at, "'statement' names '{" + name + "}', which is not a parameter (expected one of: " + join(names) + ")");
  }
  ctx.m.statement = st;
}

}  // namespace tackle::build

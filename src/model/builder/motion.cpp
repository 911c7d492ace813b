// Motion in time (`motion:`): which coordinates describe the motion (as many as the degrees
// of freedom, independent under the constraints), their values and rates at t = 0, and the
// defaults of `tackle simulate`.
#include "model/builder/stages.hpp"

#include <algorithm>
#include <functional>

#include "expr/print.hpp"
#include "expr/rational.hpp"
#include "model/kinematics.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

// The rank of the constraints' rate rows over the moving coordinates' rates, with a unit
// row for each coordinate in `fixed` (taken as known).
unsigned rank_with(const std::vector<std::vector<ex>>& rows, const std::vector<std::size_t>& fixed, std::size_t n) {
  const std::size_t r = rows.size() + fixed.size();
  if (r == 0 || n == 0) return 0;
  matrix a(static_cast<unsigned>(r), static_cast<unsigned>(n));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < n; ++j) a(i, j) = rows[i][j];
  for (std::size_t k = 0; k < fixed.size(); ++k) a(rows.size() + k, fixed[k]) = 1;
  return a.rank();
}

// A name that is free in the table: `base`, else `base_n`, else `base_n2`, ...
std::string free_name(const SymbolTable& t, const std::string& base) {
  if (!t.find(base)) return base;
  for (int i = 1;; ++i) {
    std::string n = base + "_n" + (i == 1 ? "" : std::to_string(i));
    if (!t.find(n)) return n;
  }
}

// The steps of reading `motion:` and what they share: the description and the model, the
// moving coordinates (indices into m.coordinates, in body order) with the constraints' rates
// over theirs, the columns chosen as the motion's coordinates, and the spec being made.
// Problems are reported and the checks go on, so that every problem is reported at once; the
// motion is kept only when there were none.
struct MotionReader {
  BuildContext& ctx;
  const MotionDesc& md;
  Model& m;
  bool usable = false;
  MotionSpec spec;
  std::vector<ex> by_balance;             // coordinates that massless bodies' balances fix
  std::vector<int> moving;                // the moving coordinates
  std::vector<std::string> moving_names;  // ... as written
  // The constraints' rates: one row per constraint, one column per moving coordinate.
  std::vector<std::vector<ex>> rows;
  std::size_t n = 0, dof = 0;       // the moving coordinates, the degrees of freedom
  std::vector<std::size_t> chosen;  // columns: the motion's coordinates

  MotionReader(BuildContext& context, const MotionDesc& desc) : ctx(context), md(desc), m(context.m) {
    spec.at = md.at;
  }

  // Time must be the symbol t, not a parameter.
  void check_time() {
    if (!is_a<symbol>(m.time)) {
      const SymbolInfo* t = ctx.table->find("t");
      ctx.diags.error(md.at, "'motion' needs t as time, but 't' is a parameter (line " +
                                 std::to_string(t ? t->where.line : 0) + "; expected another name for it)");
    }
    usable = is_a<symbol>(m.time);
  }

  // The moving coordinates, in body order. (A massless body's coordinate that its balance
  // fixes is no degree of freedom.)
  void find_moving() {
    by_balance = balance_coordinates(m, *ctx.table);
    for (std::size_t i = 0; i < m.coordinates.size(); ++i)
      if (!contains(by_balance, m.coordinates[i].q)) moving.push_back(static_cast<int>(i));
  }

  // A body that moves in a straight line without a coordinate: nothing to integrate.
  void check_bodies_without_coordinate() {
    for (std::size_t i = 0; i < m.bodies.size(); ++i) {
      const Body& b = m.bodies[i];
      const bool has_coordinate = std::any_of(m.coordinates.begin(), m.coordinates.end(),
                                              [&](const Coordinate& c) { return c.body == static_cast<int>(i); });
      if (!has_coordinate && b.has_mass && !is_zero_vec(b.given_acceleration)) {
        // Straight-line motion without a coordinate: nothing to integrate.
        bool unknown = false;
        for (const auto& c : m.candidates)
          for (int k = 0; k < 3; ++k) unknown = unknown || b.given_acceleration[k].has(c);
        if (unknown)
          ctx.diags.error(b.at, "body '" + b.name +
                                    "' moves without a coordinate (expected 'position' and a center_of_mass "
                                    "written in it, for motion in time)");
      }
    }
  }

  // The constraints' rates, one row per constraint, one column per moving coordinate; the
  // degrees of freedom they leave.
  void rate_rows() {
    spec.moving = moving.size();
    for (const auto& c : m.constraints) {
      const ex rate = time_derivative(c.quantity, m);
      std::vector<ex> row;
      for (int i : moving) row.push_back(rate.diff(ex_to<symbol>(m.coordinates[i].rate)));
      rows.push_back(std::move(row));
    }
    n = moving.size();
    dof = n - rank_with(rows, {}, n);
    for (int i : moving) moving_names.push_back(to_text(m.coordinates[i].q));
  }

  // The column of a moving coordinate, or -1.
  int column_of(const ex& q) const {
    for (std::size_t j = 0; j < n; ++j)
      if (m.coordinates[moving[j]].q.is_equal(q)) return static_cast<int>(j);
    return -1;
  }

  // Whether column j is independent of those chosen under the constraints.
  bool independent(std::size_t j) const {
    std::vector<std::size_t> with = chosen;
    with.push_back(j);
    return rank_with(rows, with, n) > rank_with(rows, chosen, n);
  }

  // One of the coordinates 'coordinates' lists, chosen; false when it is reported (not a
  // moving coordinate, listed twice, or fixed by those before it).
  bool take_listed(const Text& c) {
    const auto r = parse_expression(c.text, *ctx.table);
    const int j = r.value ? column_of(*r.value) : -1;
    if (j < 0) {
      ctx.unknown_name(c, "coordinate of a moving body", moving_names);
      return false;
    }
    if (std::find(chosen.begin(), chosen.end(), static_cast<std::size_t>(j)) != chosen.end()) {
      ctx.diags.error(c.at, "'" + c.text + "' is listed twice in 'coordinates' of 'motion'");
      return false;
    }
    std::vector<std::size_t> with = chosen;
    with.push_back(static_cast<std::size_t>(j));
    if (rank_with(rows, with, n) == rank_with(rows, chosen, n)) {
      std::vector<std::string> before;
      for (auto k : chosen) before.push_back(moving_names[k]);
      ctx.diags.error(
          c.at, "'" + c.text + "' is fixed by the constraints" +
                    (before.empty() ? std::string()
                                    : " once " + join(before) + (before.size() == 1 ? " is" : " are") + " known") +
                    " (expected independent coordinates)");
      return false;
    }
    chosen.push_back(static_cast<std::size_t>(j));
    return true;
  }

  // The coordinates 'coordinates' lists: each independent, as many as the degrees of freedom.
  void choose_listed() {
    bool ok = true;
    for (const auto& c : md.coordinates)
      if (!take_listed(c)) ok = false;
    if (ok && chosen.size() != dof) {
      std::vector<std::string> more;
      for (std::size_t j = 0; j < n; ++j)
        if (independent(j)) more.push_back(moving_names[j]);
      ctx.diags.error(md.at, "the motion has " + std::to_string(dof) + (dof == 1 ? " degree" : " degrees") +
                                 " of freedom, but 'coordinates' lists " + std::to_string(chosen.size()) +
                                 " (expected also one of: " + join(more) + ")");
      usable = false;
    }
    if (!ok) usable = false;
  }

  // Whether `initial` gives a value of q.
  bool in_initial(const ex& q) const {
    return std::any_of(md.initial.begin(), md.initial.end(), [&](const auto& kv) {
      const auto r = parse_expression(kv.first.text, *ctx.table);
      return r.value && r.value->is_equal(q);
    });
  }

  // Given coordinates of bodies with mass first, then those `initial` gives, then those of
  // bodies with mass, then the others in body order, each when it is independent of those
  // chosen before it (a massless ring tied to a block by a string is described by the
  // block's coordinate, also when the ring's place is given at the instant).
  void choose_preferred() {
    std::vector<std::size_t> order;
    auto massive = [&](const Coordinate& c) { return m.bodies[c.body].has_mass && !m.bodies[c.body].mass.is_zero(); };
    // (Only the motion's own rates may be given: a rate in `initial` names its coordinate.)
    const std::vector<std::function<bool(const Coordinate&)>> preferences = {
        [&](const Coordinate& c) { return contains(m.given, c.q) && massive(c); },
        [&](const Coordinate& c) { return in_initial(c.rate); }, [&](const Coordinate& c) { return in_initial(c.q); },
        massive, [&](const Coordinate&) { return true; }};
    for (const auto& preferred : preferences)
      for (std::size_t j = 0; j < n; ++j)
        if (std::find(order.begin(), order.end(), j) == order.end() && preferred(m.coordinates[moving[j]]))
          order.push_back(j);
    for (auto j : order) {
      if (chosen.size() == dof) break;
      if (independent(j)) chosen.push_back(j);
    }
  }

  // A motion needs a degree of freedom.
  void check_freedom() {
    if (dof == 0) {
      std::vector<std::string> massless;
      for (const auto& q : by_balance) massless.push_back(to_text(q));
      ctx.diags.error(
          md.at, "the motion has no degree of freedom: the constraints fix every coordinate" +
                     std::string(!massless.empty() ? " (the balances of massless bodies fix " + join(massless) + ")"
                                 : n == 0          ? " (no body has a 'position')"
                                                   : ""));
      usable = false;
    }
  }

  // The chosen coordinates into the spec; they and their rates are known at every instant.
  void take_chosen() {
    for (auto j : chosen) {
      const Coordinate& b = m.coordinates[moving[j]];
      spec.coordinates.push_back(b.q);
      spec.rates.push_back(b.rate);
      spec.accelerations.push_back(b.accel);
      spec.bodies.push_back(b.body);
    }
    // The motion's coordinates and rates are known at every instant.
    for (const auto& q : {spec.coordinates, spec.rates})
      for (const auto& s : q)
        if (!contains(m.given, s)) {
          m.given.push_back(s);
          m.candidates.erase(std::remove(m.candidates.begin(), m.candidates.end(), s), m.candidates.end());
        }
  }

  // Whether v is an expression in the parameters only.
  bool in_parameters(const ex& v) const {
    bool only = true;
    for (const auto& sym : ctx.table->all())
      if (v.has(sym->sym) && sym->role != SymbolRole::parameter) only = false;
    return only;
  }

  // The coordinate or rate of a moving body an entry of `initial` names; none when reported
  // (a massless body's, or no moving body's).
  const SymbolInfo* initial_symbol(const Text& key) {
    const auto r = parse_expression(key.text, *ctx.table);
    const SymbolInfo* s = r.value ? ctx.table->find(*r.value) : nullptr;
    int body = -1;
    if (s)
      for (int i : moving)
        if (m.coordinates[i].q.is_equal(s->sym) || m.coordinates[i].rate.is_equal(s->sym)) body = m.coordinates[i].body;
    if (body < 0 && s) {
      const auto fixed = std::find_if(m.coordinates.begin(), m.coordinates.end(), [&](const Coordinate& c) {
        return contains(by_balance, c.q) && (c.q.is_equal(s->sym) || c.rate.is_equal(s->sym));
      });
      if (fixed != m.coordinates.end()) {
        ctx.diags.error(key.at,
                        "initial value of '" + key.text + "': body '" + m.bodies[fixed->body].name +
                            "' has no mass, so its balance gives it at every instant (expected initial values of the "
                            "motion's coordinates only)");
        return nullptr;
      }
    }
    if (body < 0) {
      std::vector<std::string> known;
      for (int i : moving)
        known.push_back(to_text(m.coordinates[i].q)), known.push_back(to_text(m.coordinates[i].rate));
      ctx.unknown_name(key, "coordinate or rate of a moving body", known);
      return nullptr;
    }
    return s;
  }

  // An initial value given with a unit ({value: 60, unit: deg}): the value in that unit, in
  // SI. A wrong unit is reported once: the value is kept, so it is not reported missing too.
  void in_unit(ex& v, const Text& key, const Text& unit_text, const Dimension& expected) {
    std::string err;
    int col = 0;
    const auto unit = parse_unit(unit_text.text, err, col);
    if (!unit)
      ctx.diags.error(unit_text.at.shifted(col), "unit of the initial value of '" + key.text + "': " + err);
    else if (!(unit->dimension == expected))
      ctx.diags.error(unit_text.at, "initial value of '" + key.text + "' is " + with_article(expected.describe()) +
                                        ", but " + unit_text.text + " is " + with_article(unit->dimension.describe()));
    else
      v = v * unit->to_si;
  }

  // One entry of `initial`: a coordinate or rate of a moving body, its value in the parameters.
  void read_initial(std::size_t entry) {
    const auto& [key, value] = md.initial[entry];
    const std::optional<Text>& unit_text = entry < md.initial_units.size() ? md.initial_units[entry] : std::nullopt;
    const SymbolInfo* s = initial_symbol(key);
    if (!s) return;
    const bool is_rate = s->role == SymbolRole::rate;
    // (A dependent rate is checked against the one the constraints give, in the motion.)
    auto v = ctx.parse(value, *ctx.table, "initial value of '" + key.text + "'");
    if (!v) return;
    if (!in_parameters(*v)) {
      ctx.diags.error(value.at, "initial value of '" + key.text + "' is not an expression in the parameters");
      return;
    }
    // A length or an angle, a velocity or an angular velocity.
    const Dimension expected = s->dimension.value_or(is_rate ? Dimension::velocity() : Dimension::length());
    if (unit_text) {  // {value: 60, unit: deg}: the value in that unit
      in_unit(*v, key, *unit_text, expected);
    } else if (!is_a<numeric>(*v)) {
      ctx.check_dimension(*v, expected, value.at, "initial value of '" + key.text + "'");
    }
    spec.initial[s->sym] = *v;
    spec.initial_at.emplace_back(s->sym, value.at);
  }

  // Initial values: coordinates and rates of moving bodies, in the parameters; when any is
  // given, every coordinate's and rate's of the motion.
  void read_initial_values() {
    for (std::size_t entry = 0; entry < md.initial.size(); ++entry) read_initial(entry);
    std::vector<std::string> missing;
    for (std::size_t i = 0; i < spec.coordinates.size(); ++i)
      for (const auto& s : {spec.coordinates[i], spec.rates[i]})
        if (!spec.initial.count(s)) missing.push_back(to_text(s));
    if (!missing.empty() && !md.initial.empty())
      ctx.diags.error(md.at, "'initial' of 'motion' has no value for " + join(missing) +
                                 " (expected the value at t = 0 of each of the motion's coordinates and their rates)");
  }

  // The factor of `until`'s unit to seconds (1 without a unit); none when the unit is reported.
  std::optional<ex> until_to_si() {
    std::optional<ex> to_si = ex(1);
    if (md.until_unit) {
      std::string err;
      int col = 0;
      auto unit = parse_unit(md.until_unit->text, err, col);
      if (!unit) {
        ctx.diags.error(md.until_unit->at.shifted(col), "unit of 'until' of 'motion': " + err);
        to_si.reset();
      } else if (!(unit->dimension == Dimension::time())) {
        ctx.diags.error(md.until_unit->at, "'until' of 'motion' is a time, but " + md.until_unit->text + " is " +
                                               with_article(unit->dimension.describe()));
        to_si.reset();
      } else {
        to_si = ex(unit->to_si);
      }
    }
    return to_si;
  }

  // `until`: simulate's end time, a positive number of seconds.
  void read_until() {
    if (!md.until) return;
    std::optional<ex> to_si = until_to_si();
    auto v = ctx.number_in_parameters(*md.until, "'until' of 'motion'",
                                      md.until_unit ? std::nullopt : std::optional(Dimension::time()));
    if (v && to_si) {
      const ex seconds = evalf(*v * *to_si);
      if (!is_a<numeric>(seconds) || !ex_to<numeric>(seconds).is_real() || !ex_to<numeric>(seconds).is_positive())
        ctx.diags.error(md.until->at, "'until' of 'motion' is not a positive number");
      else
        spec.until = *v * *to_si;
    }
  }

  // `speed_at`: the one coordinate of the motion and a length in the parameters where the
  // speed is asked for.
  void read_speed_at() {
    if (!md.speed_at) return;
    const auto& [key, value] = *md.speed_at;
    const auto r = parse_expression(key.text, *ctx.table);
    if (!r.value || !contains(spec.coordinates, *r.value)) {
      std::vector<std::string> known;
      for (const auto& q : spec.coordinates) known.push_back(to_text(q));
      ctx.unknown_name(key, "coordinate of the motion", known);
    } else if (spec.coordinates.size() != 1) {
      ctx.diags.error(key.at, "'speed_at' needs one degree of freedom (the motion has " +
                                  std::to_string(spec.coordinates.size()) + ")");
    } else if (auto v = ctx.parse(value, *ctx.table, "'speed_at' value of '" + key.text + "'")) {
      if (!in_parameters(*v))
        ctx.diags.error(value.at, "'speed_at' value of '" + key.text + "' is not an expression in the parameters");
      else {
        if (!is_a<numeric>(*v))
          ctx.check_dimension(*v, Dimension::length(), value.at, "'speed_at' value of '" + key.text + "'");
        spec.speed_at = std::pair{*r.value, *v};
      }
    }
  }

  // The symbols of the motion's natural frequency, damping ratio and damped frequency, each
  // under a name that is free.
  void add_frequency_symbols() {
    const std::string lambda = free_name(*ctx.table, "lambda"), zeta = free_name(*ctx.table, "zeta"),
                      omega_d = free_name(*ctx.table, "omega_d");
    spec.lambda =
        ctx.table->add(lambda, std::nullopt, SymbolRole::motion, Dimension::none() / Dimension::time(), true, md.at)
            .sym;
    spec.zeta = ctx.table->add(zeta, std::nullopt, SymbolRole::motion, Dimension::none(), true, md.at).sym;
    spec.omega_d =
        ctx.table->add(omega_d, std::nullopt, SymbolRole::motion, Dimension::none() / Dimension::time(), true, md.at)
            .sym;
  }
};

}  // namespace

void motion(BuildContext& ctx) {
  if (!ctx.d.motion) return;
  MotionReader r(ctx, *ctx.d.motion);
  r.check_time();
  r.find_moving();
  r.check_bodies_without_coordinate();
  r.rate_rows();
  if (!r.md.coordinates.empty())
    r.choose_listed();
  else
    r.choose_preferred();
  r.check_freedom();
  r.take_chosen();
  r.read_initial_values();
  r.read_until();
  r.spec.plot = r.md.plot;
  r.read_speed_at();
  r.add_frequency_symbols();
  if (r.usable) ctx.m.motion = std::move(r.spec);
}

}  // namespace tackle::build

namespace tackle::build {

namespace {

// An expression in the parameters only (an interval's ends, an impact's rates before), with
// the dimension `dim`; reported at `t` otherwise.
std::optional<ex> parameters_only(BuildContext& ctx, const Text& t, const std::string& what, const Dimension& dim) {
  auto v = ctx.parse(t, *ctx.table, what);
  if (!v) return std::nullopt;
  for (const auto& s : ctx.table->all())
    if (v->has(s->sym) && s->role != SymbolRole::parameter) {
      ctx.diags.error(t.at, what + " is not an expression in the parameters");
      return std::nullopt;
    }
  if (!is_a<numeric>(*v)) ctx.check_dimension(*v, dim, t.at, what);
  return v;
}

// The body whose rate `key` names (dot(x_A)), or -1 with the problem reported.
int body_of_rate(BuildContext& ctx, const Text& key) {
  const auto r = parse_expression(key.text, *ctx.table);
  for (const auto& q : ctx.m.coordinates)  // (in body order)
    if (q.kind == Coordinate::Kind::translation && r.value && q.rate.is_equal(*r.value)) return q.body;
  std::vector<std::string> known;
  for (const auto& q : ctx.m.coordinates)
    if (q.kind == Coordinate::Kind::translation) known.push_back(to_text(q.rate));
  ctx.unknown_name(key, "rate", known);
  return -1;
}

}  // namespace

void interval(BuildContext& ctx) {
  if (!ctx.d.interval) return;
  const IntervalDesc& d = *ctx.d.interval;
  Model& m = ctx.m;
  IntervalSpec spec;
  spec.at = d.at;
  auto quantity = [&](const std::optional<Text>& t, const std::string& what,
                      const Dimension& dim) -> std::optional<ex> {
    return t ? parameters_only(ctx, *t, what, dim) : std::nullopt;
  };
  spec.duration = quantity(d.duration, "'duration' of 'interval'", Dimension::time());
  spec.distance = quantity(d.distance, "'distance' of 'interval'", Dimension::length());
  // The rates: each a moving body's, given at both ends.
  std::map<int, std::pair<std::optional<ex>, std::optional<ex>>> ends;
  std::vector<int> order;
  for (const bool at_end : {false, true})
    for (const auto& [key, value] : at_end ? d.to : d.from) {
      const std::string what = std::string(at_end ? "'to'" : "'from'") + " of 'interval'";
      const int body = body_of_rate(ctx, key);
      if (body < 0) continue;
      auto v = quantity(Text{value.text, value.at}, "value of '" + key.text + "' in " + what, Dimension::velocity());
      if (!v) continue;
      if (!ends.count(body)) order.push_back(body);
      (at_end ? ends[body].second : ends[body].first) = *v;
    }
  for (int b : order) {
    const auto& [from, to] = ends[b];
    if (!from) {
      ctx.diags.error(d.at, "'interval' gives " + to_text(kinematics::translation(m, m.bodies[b])->rate) +
                                " at its end only (expected it in 'from' too)");
      continue;
    }
    spec.changes.push_back({b, *from, to});
  }
  m.interval = std::move(spec);
}

void impact(BuildContext& ctx) {
  if (!ctx.d.impact) return;
  const ImpactDesc& d = *ctx.d.impact;
  Model& m = ctx.m;
  ImpactSpec spec;
  spec.at = d.at;
  bool usable = true;
  if (m.dims() != 1) {
    ctx.diags.error(d.at, "'impact' is along one axis (expected a description with one axis)");
    return;
  }
  // The finite forces give no impulse while an impact lasts: nothing else is modelled.
  for (const auto& c : ctx.d.connections) {
    ctx.diags.error(c.at,
                    "a description with 'impact' has no connections or loads (the finite forces give no impulse while "
                    "the impact lasts; expected the bodies and their rates before it only)");
    usable = false;
  }
  if (!ctx.d.find.empty()) {
    ctx.diags.error(ctx.d.find[0].name.at,
                    "a description with 'impact' has no 'find' (it reports the rates after the impact, "
                    "the impulses and the kinetic energy lost)");
    usable = false;
  }
  for (const char* other : {"interval", "motion"})
    if ((std::string(other) == "interval" && ctx.d.interval) || (std::string(other) == "motion" && ctx.d.motion)) {
      ctx.diags.error(d.at, std::string("a description with 'impact' has no '") + other + "' (expected one of them)");
      usable = false;
    }
  std::map<int, ex> before;
  for (const auto& [key, value] : d.from) {
    const int body = body_of_rate(ctx, key);
    if (body < 0) {
      usable = false;
      continue;
    }
    auto v = parameters_only(ctx, value, "value of '" + key.text + "' in 'from' of 'impact'", Dimension::velocity());
    if (!v) {
      usable = false;
      continue;
    }
    before[body] = *v;
  }
  for (std::size_t i = 0; i < m.bodies.size(); ++i) {
    const Body& b = m.bodies[i];
    if (!b.has_mass || b.mass.is_zero()) {
      ctx.diags.error(b.at, "body '" + b.name + "' has no mass (expected every body of an impact to have one)");
      usable = false;
    } else if (const Coordinate* q = kinematics::translation(m, b); !before.count(static_cast<int>(i)) && q) {
      ctx.diags.error(d.at, "'impact' gives no rate of body '" + b.name + "' before it (expected " + to_text(q->rate) +
                                " in 'from')");
      usable = false;
    }
  }
  if (m.bodies.size() < 2) {
    ctx.diags.error(d.at,
                    "'impact' has " + std::to_string(m.bodies.size()) + " body (expected two or more that collide)");
    usable = false;
  }
  if (d.restitution) {
    spec.restitution = parameters_only(ctx, *d.restitution, "'restitution' of 'impact'", Dimension::none());
    if (!spec.restitution) usable = false;
    if (m.bodies.size() > 2) {
      ctx.diags.error(d.restitution->at, "'restitution' of 'impact' is for two bodies, and there are " +
                                             std::to_string(m.bodies.size()) + " (expected two, or 'plastic: true')");
      usable = false;
    }
  }
  if (!usable) return;
  for (const auto& [body, v] : before) {
    const Text name{"J_" + m.bodies[body].name, d.at};
    if (!ctx.claim(name, "impulse")) return;
    const ex sym = ctx.table
                       ->add(name.text, "J_{\\mathrm{" + m.bodies[body].name + "}}", SymbolRole::unknown,
                             Dimension::force() * Dimension::time(), false, d.at)
                       .sym;
    spec.before.push_back({body, v, sym});
  }
  const Text lost{"E_lost", d.at};
  if (!ctx.claim(lost, "energy")) return;
  spec.energy_lost = ctx.table
                         ->add(lost.text, std::string("E_{\\mathrm{lost}}"), SymbolRole::unknown,
                               Dimension::force() * Dimension::length(), false, d.at)
                         .sym;
  m.impact = std::move(spec);
}

}  // namespace tackle::build

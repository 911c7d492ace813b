#include "crosscheck/worlds.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include <fmt/format.h>

namespace crosscheck {

namespace {

// A residual this small against its terms' size holds; one this large fails; between, the
// model does not decide (the model's numbers carry about 1e-12).
constexpr double holds_below = 1e-8;
constexpr double fails_above = 1e-5;

bool is_quantity(const World& w, const std::string& name) { return w.instant.find(name) != nullptr; }
const Quantity* quantity(const World& w, const std::string& name) { return w.instant.find(name); }

// The states of one draw: the layout (its massless bodies settled), then random ones near it.
std::vector<State> states_of(const Model& m, std::mt19937_64& rng, int count) {
  std::vector<State> states;
  State base = m.base_state();
  if (m.has_massless())
    if (auto s = m.random_state(rng, 0.0)) base = *s;
  states.push_back(base);
  for (int tries = 0; static_cast<int>(states.size()) < count && tries < 10 * count; ++tries)
    if (auto s = m.random_state(rng, 0.1)) states.push_back(*s);
  return states;
}

// Each definition evaluated with the world's values (a name it uses that the world lacks
// leaves it out).
void define(World& w, const Definitions& definitions) {
  for (const auto& [name, text] : definitions)
    if (const auto v = evaluate_text(text, w.values)) w.values[name] = *v;
}

World world_at(const Model& m, const State& s, int draw) {
  World w;
  w.draw = draw;
  w.state = s;
  w.instant = m.solve(s);
  w.values = m.values_at(s);
  for (const auto& [name, value] : m.parameters()) w.parameters.push_back(name);
  w.free_directions = w.instant.free_directions;
  w.accel_scale = std::max(1.0, m.gravity_magnitude());
  double forces = 0;
  for (const auto& q : w.instant.quantities) {
    if (q.name.rfind("guide", 0) == 0) continue;
    w.values[q.name] = q.value;
    if (q.free.size() && q.free.norm() > 1e-9) w.free[q.name] = q.free;
    if (q.force)
      forces = std::max(forces, std::abs(q.value));
    else
      w.accel_scale = std::max(w.accel_scale, std::abs(q.value));
  }
  w.scale = std::max({forces, m.largest_mass() * w.accel_scale, 1e-3});
  return w;
}

// A text compiled with the names it uses, each a slot of its own (`pi` is the number unless
// the world names it).
struct Compiled {
  Expr lhs, rhs;  // an answer: lhs only
  std::vector<std::string> names;
};

std::function<int(const std::string&)> slots_into(std::vector<std::string>& names) {
  return [&names](const std::string& n) {
    if (n == "pi") return -1;
    auto it = std::find(names.begin(), names.end(), n);
    if (it != names.end()) return static_cast<int>(it - names.begin());
    names.push_back(n);
    return static_cast<int>(names.size()) - 1;
  };
}

// The single '=' of an equation (not part of <=, >=, ==, !=).
std::optional<std::size_t> equals_sign(const std::string& text) {
  std::optional<std::size_t> at;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '=') continue;
    const bool part = (i > 0 && std::string("<>=!").find(text[i - 1]) != std::string::npos) ||
                      (i + 1 < text.size() && text[i + 1] == '=');
    if (part || at) return std::nullopt;
    at = i;
  }
  return at;
}

std::optional<Compiled> compile_equation(const std::string& text, std::string& why) {
  const auto eq = equals_sign(text);
  if (!eq) {
    why = "not one equation";
    return std::nullopt;
  }
  Compiled c;
  try {
    c.lhs = Expr::compile(text.substr(0, *eq), slots_into(c.names));
    c.rhs = Expr::compile(text.substr(*eq + 1), slots_into(c.names));
  } catch (const std::runtime_error& e) {
    why = e.what();
    return std::nullopt;
  }
  return c;
}

struct Residual {
  double value = 0, size = 0;
  double floor = 0;  // what the model's own rounding can make of it (noise_floor)
};

// The variables of a compiled text in a world, moved along the free directions by `shift`
// (a name the world lacks: nothing, and `why` names it). `const` is 0.
std::optional<std::vector<double>> variables(const Compiled& c, const World& w, const Eigen::VectorXd* shift,
                                             std::string& why) {
  std::vector<double> vars;
  for (const auto& n : c.names) {
    if (n == "const") {
      vars.push_back(0);
      continue;
    }
    auto it = w.values.find(n);
    if (it == w.values.end()) {
      why = "the model has no value for " + n;
      return std::nullopt;
    }
    double v = it->second;
    if (auto f = w.free.find(n); shift && f != w.free.end()) v += f->second.dot(*shift);
    vars.push_back(v);
  }
  return vars;
}

// How far the model's numbers are from exact: a solved quantity to 1e-10 of its scale, any
// other number to 1e-13 of itself.
double noise(const World& w, const std::string& name, double value) {
  if (const Quantity* q = quantity(w, name)) return 1e-10 * (q->force ? w.scale : w.accel_scale);
  return 1e-13 * std::abs(value) + 1e-15;
}

// How much the residual moves when each number moves by its noise (a residual within a few
// times that is 0 as far as the model can tell: H_z/H_x with H_z 1e-15 of the forces).
double noise_floor(const Compiled& c, const World& w, std::vector<double> vars, double value) {
  double floor = 0;
  for (std::size_t i = 0; i < vars.size(); ++i) {
    const double v = vars[i], step = 1e-6 * (std::abs(v) + 1), n = noise(w, c.names[i], v);
    vars[i] = v + step;
    const double moved = c.lhs.eval(vars) - c.rhs.eval(vars);
    vars[i] = v;
    if (std::isfinite(moved)) floor += std::abs(moved - value) / step * n;
  }
  return floor;
}

// Whether the text divides by something that is 0 at this state, as far as the model's numbers
// tell (`(H_z x_A - H_z x_B)/H_z` with H_z = 0: not defined there).
bool divides_by_zero(const Compiled& c, const World& w, const std::vector<double>& vars) {
  for (const Expr* side : {&c.lhs, &c.rhs})
    for (const Expr& d : side->divisors()) {
      const Compiled part{d, Expr::constant(0), c.names};
      const double v = d.eval(vars);
      if (std::abs(v) <= 100 * noise_floor(part, w, vars, v) + 1e-300) return true;
    }
  return false;
}

std::optional<Residual> residual_at(const Compiled& c, const World& w, const Eigen::VectorXd* shift, std::string& why) {
  const auto vars = variables(c, w, shift, why);
  if (!vars) return std::nullopt;
  if (divides_by_zero(c, w, *vars)) {
    why = "it divides by a quantity that is 0 at a state of the model";
    return std::nullopt;
  }
  Residual r{c.lhs.eval(*vars) - c.rhs.eval(*vars), c.lhs.magnitude(*vars) + c.rhs.magnitude(*vars), 0};
  if (!std::isfinite(r.value) || !std::isfinite(r.size)) {
    why = "not a real number at a state of the model";
    return std::nullopt;
  }
  r.floor = noise_floor(c, w, *vars, r.value);
  return r;
}

// Whether the residual changes along the directions the model leaves free (then the model
// does not determine it). `names`: those of the free quantities used.
bool depends_on_free(const Compiled& c, const World& w, const Residual& at, std::string& names) {
  for (const auto& n : c.names)
    if (w.free.count(n)) names += (names.empty() ? "" : ", ") + n;
  if (names.empty() || w.free_directions == 0) return false;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 3; ++k) {
    Eigen::VectorXd shift(w.free_directions);
    for (int i = 0; i < shift.size(); ++i) shift(i) = u(rng) * w.scale;
    std::string why;
    const auto r = residual_at(c, w, &shift, why);
    if (!r || std::abs(r->value - at.value) > holds_below * std::max({r->size, at.size, 1e-300})) return true;
  }
  return false;
}

// Whether a side reads no name (a number).
bool number_side(const Compiled& c, const Expr& side) {
  for (std::size_t i = 0; i < c.names.size(); ++i)
    if (side.uses(static_cast<int>(i))) return false;
  return true;
}

// A length sum kept constant: coordinates and parameters, no force, rate or acceleration, and
// a constant that is `const`, or, in coordinates alone, one side that is a number
// (docs/checking.md: the constant depends on where positions are measured from). A parameter
// is no such constant (`b = x_A - x_B` says what b is), nor is a number where the sum has a
// parameter in it (`k_1 x - (k_1 + k_2) x_S + k_2 l_2 = 0`, a massless joint's balance with a
// term left out, is off by a force).
bool length_sum(const Compiled& c, const World& w) {
  bool coordinate = false, named = false, parameter = false;
  for (const auto& n : c.names) {
    if (n == "const") {
      named = true;
      continue;
    }
    if (is_quantity(w, n) || n.rfind("dot(", 0) == 0 || n.rfind("ddot(", 0) == 0) return false;
    coordinate = coordinate || (w.values.count("dot(" + n + ")") > 0);
    parameter = parameter || std::find(w.parameters.begin(), w.parameters.end(), n) != w.parameters.end();
  }
  return coordinate && (named || (!parameter && (number_side(c, c.lhs) || number_side(c, c.rhs))));
}

// An equation in coordinates and parameters alone with a parameter in it (`x_A + x_B = w`):
// whether it holds is whether the sum of the coordinates is kept (the model decides) and its
// constant is that one, which the description does not fix where it gives no positions to
// measure from (the string's length, the origin): unknown when the sum is kept.
bool parameter_sum(const Compiled& c, const World& w) {
  bool coordinate = false, parameter = false;
  for (const auto& n : c.names) {
    if (n == "const" || is_quantity(w, n) || n.rfind("dot(", 0) == 0 || n.rfind("ddot(", 0) == 0) return false;
    coordinate = coordinate || (w.values.count("dot(" + n + ")") > 0);
    parameter = parameter || std::find(w.parameters.begin(), w.parameters.end(), n) != w.parameters.end();
  }
  return coordinate && parameter;
}

std::string state_text(const World& w) {
  std::string out = fmt::format("draw {}", w.draw);
  for (const auto& [k, v] : w.values)
    if (k.rfind("dot(", 0) == 0) out += fmt::format(", {} = {:.6g}", k, v);
  return out;
}

// Whether the equation holds with every name but the parameters at random values.
bool tautology(const Compiled& c, const World& w) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 3; ++k) {
    World moved = w;
    for (const auto& n : c.names)
      if (std::find(w.parameters.begin(), w.parameters.end(), n) == w.parameters.end() && moved.values.count(n))
        moved.values[n] = u(rng) * (std::abs(moved.values[n]) + 1);
    moved.free.clear();
    std::string why;
    const auto r = residual_at(c, moved, nullptr, why);
    if (!r || std::abs(r->value) > holds_below * r->size + 100 * r->floor) return false;
  }
  return true;
}

// Relative residuals of an equation, world by world (a length sum's: against the first state
// of its draw), or why the model cannot decide.
Judgement decide(const Compiled& c, const std::vector<World>& worlds) {
  Judgement j;
  if (worlds.empty()) {
    j.why = "no state of the model balances";
    return j;
  }
  const bool with_parameter = parameter_sum(c, worlds.front());
  const bool sum = length_sum(c, worlds.front()) || with_parameter;
  std::map<int, Residual> first;  // a length sum's residual at the first state of each draw
  bool fails = false;
  for (const auto& w : worlds) {
    std::string why, free;
    const auto r = residual_at(c, w, nullptr, why);
    if (!r) {
      j.why = why;
      return j;
    }
    if (depends_on_free(c, w, *r, free)) {
      j.why = "the model leaves " + free + " undetermined";
      return j;
    }
    double value = r->value, size = r->size, floor = r->floor;
    if (sum) {
      auto [it, fresh] = first.emplace(w.draw, *r);
      value -= it->second.value;
      size = std::max(size, it->second.size);
      floor += it->second.floor;
    }
    // (within 100 times the noise floor: 0; the floor counts against the residual)
    const double rel = std::max(std::abs(value) - 100 * floor, 0.0) / std::max(size, 1e-300);
    if (rel > j.worst) {
      j.worst = rel;
      if (rel > fails_above && !fails)
        j.why = "fails at " + state_text(w) + fmt::format(" (relative residual {:.3g})", rel);
    }
    fails = fails || rel > fails_above;
  }
  if (fails)
    j.truth = Truth::fails;
  else if (j.worst <= holds_below && with_parameter)
    j.why = "a kept sum whose constant is a parameter: the description does not fix the constant";
  else if (j.worst <= holds_below)
    j.truth = Truth::holds;
  else
    j.why = fmt::format("too close to call (relative residual {:.3g})", j.worst);
  j.tautology =
      j.truth == Truth::holds && tautology(c, worlds.back());  // (a drawn world: no coincidence of the given values)
  return j;
}

// Whether a parameter's value (an expression in numbers) is 0.
bool is_zero(const std::string& value) {
  try {
    return Expr::compile(value, [](const std::string&) { return -1; }).eval(std::vector<double>{}) == 0;
  } catch (const std::runtime_error&) {
    return false;
  }
}

}  // namespace

tackle::Description redrawn(const tackle::Description& d, std::mt19937_64& rng, double spread) {
  tackle::Description out = d;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (auto& p : out.parameters) {
    if (p.define || !p.value) continue;
    const double factor = std::exp(u(rng) * std::log(spread));
    // (a parameter given as 0, an amplitude or an offset, is a symbol to tackle: some value)
    if (is_zero(p.value->text))
      p.value->text = fmt::format("{:.17g}", 0.55 + 0.45 * u(rng));
    else
      p.value->text = fmt::format("({})*{:.17g}", p.value->text, factor);
  }
  return out;
}

std::vector<World> make_worlds(const tackle::Description& d, std::mt19937_64& rng, const WorldOptions& o,
                               const Definitions& definitions) {
  std::vector<World> worlds;
  const Model first(d, rng);
  const auto directions = first.strand_vectors(first.base_state());
  for (int draw = 0; draw < o.draws; ++draw) {
    const Model m(draw == 0 ? d : redrawn(d, rng, o.spread), rng);
    // (parameters that place the points may turn a strand over: not the mechanism tackle derived)
    if (!same_directions(m.strand_vectors(m.base_state()), directions)) continue;
    for (const State& s : states_of(m, rng, o.states)) {
      World w = world_at(m, s, draw);
      if (w.instant.residual > 1e-8) continue;  // no balance at this state
      define(w, definitions);
      worlds.push_back(std::move(w));
    }
  }
  return worlds;
}

Judgement judge_equation(const std::string& equation, const std::vector<World>& worlds) {
  Judgement j;
  const auto c = compile_equation(equation, j.why);
  if (!c) return j;
  return decide(*c, worlds);
}

Judgement judge_answer(const std::string& unknown, const std::string& answer, const std::vector<World>& worlds) {
  Judgement j;
  if (worlds.empty()) {
    j.why = "no state of the model balances";
    return j;
  }
  Compiled c;
  try {
    c.lhs = Expr::compile(answer, slots_into(c.names));
  } catch (const std::runtime_error& e) {
    j.why = e.what();
    return j;
  }
  c.rhs = Expr::constant(0);
  bool fails = false;
  for (const auto& w : worlds) {
    const Quantity* q = quantity(w, unknown);
    if (!q) {
      j.why = "the model has no quantity " + unknown;
      return j;
    }
    if (!q->determined) {
      j.why = "the model leaves " + unknown + " undetermined";
      return j;
    }
    std::string why;
    const auto r = residual_at(c, w, nullptr, why);
    if (!r) {
      j.why = why;
      return j;
    }
    const double diff = std::abs(r->value - q->value), scale = q->force ? w.scale : w.accel_scale;
    const double size = std::max(std::abs(r->value), std::abs(q->value));
    const double rel = diff / std::max(size + 1e-2 * scale, 1e-300);
    if (diff > fails_above * size + 1e-8 * scale && !fails) {
      fails = true;
      j.why = fmt::format("{} at {}, the model {}", r->value, state_text(w), q->value);
    }
    j.worst = std::max(j.worst, rel);
    if (diff > holds_below * size + 1e-10 * scale && !fails && j.why.empty())
      j.why = fmt::format("too close to call ({:.3g} against the model's {:.3g})", r->value, q->value);
  }
  if (fails)
    j.truth = Truth::fails;
  else if (j.why.empty())
    j.truth = Truth::holds;
  return j;
}

}  // namespace crosscheck

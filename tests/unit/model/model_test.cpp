// The model: paths whose strands turn as the bodies move, and quantities given with a value.
#include <catch2/catch.hpp>

#include "expr/print.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;
using namespace GiNaC;

namespace {

using Messages = std::vector<std::string>;

// Block C slides on a smooth floor; a string runs from it up to a pulley P at height h
// above the origin and down to the hanging block B. The strand C-P turns as C moves.
const std::string raised_pulley = R"(title: "a block on a smooth floor pulled over a raised pulley by a hanging block"
axes: [x, y]
parameters:
  m: {value: 2, unit: kg}
  M: {value: 1, unit: kg}
  h: {value: 3, unit: m}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, -g]
bodies:
  C: {mass: m, position: x, center_of_mass: [x, 0]}
  B: {mass: M, position: y, center_of_mass: [0, y]}
points:
  P: [0, h]
connections:
  - {type: roller, body: C, at: C, normal: [0, 1]}
  - {type: pulley, at: P}
strings:
  - {name: s, path: [C, P, B], tension: T}
layout: {x: -4, y: 1}
given:
  x: {value: -4, unit: m}
  dot(x): 0
)";

}  // namespace

TEST_CASE("Path: a strand that turns keeps its length as a symbol, l_CP^2 = h^2 + x^2", "[path]") {
  const auto a = test::run_text(raised_pulley + "find: [ddot(x), T, N_C, dot(y)]\n");
  const Model& m = a->model;
  REQUIRE(m.lengths.size() == 1);
  const SymbolInfo* l = m.symbols->find("l_CP");
  REQUIRE(l);
  CHECK(l->tex == "\\ell_{CP}");
  CHECK(l->geometric);
  const ex h = m.symbols->find("h")->sym, x = m.symbols->find("x")->sym, v = m.symbols->find("dot(x)")->sym,
           g = m.symbols->find("g")->sym, mass = m.symbols->find("m")->sym, M = m.symbols->find("M")->sym;
  CHECK((m.lengths[0].squared - (h * h + x * x)).expand().is_zero());
  CHECK(to_text(*l->definition) == "sqrt(h^2 + x^2)");
  // Not a parameter definition a report folds in or expands (its root stays out of normal()).
  CHECK(m.symbols->definitions().count(l->sym) == 0);
  CHECK(m.symbols->definitions(true).count(l->sym) == 1);
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 4);
  // By hand: the string's length is l_CP - y, so dot(y) = x dot(x)/l_CP and ddot(y) =
  // x ddot(x)/l_CP + h^2 dot(x)^2/l_CP^3. B: T - M g = M ddot(y); C along x: m ddot(x) =
  // -x T/l_CP; across: N_C + h T/l_CP - m g = 0. Hence ddot(x) (m + M x^2/l^2) =
  // -M x (g/l + h^2 dot(x)^2/l^4).
  const ex L = l->sym;
  const ex xdd = -M * x * (g / L + h * h * v * v / pow(L, 4)) / (mass + M * x * x / (L * L));
  const ex T = M * (g + x * xdd / L + h * h * v * v / pow(L, 3));
  const ex expected[] = {xdd, T, mass * g - h * T / L, x * v / L};
  for (int i = 0; i < 4; ++i) {
    INFO(d.answers[i].name << " = " << to_text(*d.answers[i].closed_form));
    REQUIRE(d.answers[i].closed_form);
    CHECK(normal(reduced_on_lengths(*d.answers[i].closed_form - expected[i], m)).is_zero());
  }
  // At x = -4 m from rest: l_CP = 5 m, m ddot(x) = 4 T/5, T = M (g - 4 ddot(x)/5).
  REQUIRE(d.answers[0].value);
  CHECK(d.answers[0].value->approx == Approx(0.8 * 9.81 / (2 + 0.64)));
  CHECK(d.answers[1].value->approx == Approx(9.81 - 0.8 * 0.8 * 9.81 / 2.64));
}

TEST_CASE("Path: a length through a turning strand is not solved for the coordinate inside the root", "[path]") {
  std::string text = raised_pulley;
  text.erase(text.find("  x: {value: -4, unit: m}\n"), 26);
  const auto a = test::run_text(text + "find: [y, x]\n");
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 2);
  // y follows from the length sum l_CP - y = C_s (with l_CP what x makes it) ...
  REQUIRE(d.answers[0].closed_form);
  CHECK(to_text(*d.answers[0].closed_form) == "l_CP - C_s");
  // ... but x, inside the root, is not solved for from it: it only looks linear there.
  CHECK(d.answers[1].status == Answer::Status::undetermined);
  CHECK_FALSE(d.answers[1].closed_form);
}

TEST_CASE("Validity: a condition is not solved for a name inside a turning strand's length", "[path][validity]") {
  const auto a = test::run_text(raised_pulley + "find: [N_C]\n");
  const Derivation d = explain(*a);
  const SymbolTable& t = *a->model.symbols;
  REQUIRE(!d.conditions.empty());
  for (const auto& c : d.conditions)
    for (const auto& s : c.solved) {
      INFO(to_text(s.parameter));
      CHECK_FALSE(t.find(s.parameter)->name == "h");  // h is inside l_CP = sqrt(h^2 + x^2)
      CHECK_FALSE(t.find(s.parameter)->name == "x");
      CHECK_FALSE(t.find(s.parameter)->name == "l_CP");
    }
}

TEST_CASE("Given: a coordinate or velocity with its value at the instant", "[given]") {
  const auto a = test::run_text(raised_pulley + "find: [T]\n");
  const SymbolTable& t = *a->model.symbols;
  REQUIRE(t.find("x")->value);
  CHECK(to_text(*t.find("x")->value) == "-4");
  CHECK(to_text(*t.find("dot(x)")->value) == "0");
  const std::string text = write(explain(*a), Format::text, true);
  CHECK(text.find("  - x = -4 m\n") != std::string::npos);
  CHECK(text.find("    l_CP = sqrt(h^2 + x^2)  = 5 m    [definition]\n") != std::string::npos);
}

TEST_CASE("Given: a value may be an expression in the parameters, the quantity's definition", "[given]") {
  // x = -4 h/3 = -4 m at h = 3 m: the same instant as x = -4 m, so by hand (as the example
  // with -4) l_CP = sqrt(h^2 + x^2) = 5 m, and every answer has the same number.
  std::string text = raised_pulley + "find: [T, N_C]\n";
  const auto plain = test::run_text(text);
  text.replace(text.find("x: {value: -4, unit: m}"), 23, "x: -4*h/3");
  const auto a = test::run_text(text);
  const SymbolTable& t = *a->model.symbols;
  REQUIRE(t.find("x")->definition);
  CHECK(to_text(*t.find("x")->definition) == "-4*h/3");
  const Derivation d = explain(*a), e = explain(*plain);
  REQUIRE(d.answers.size() == e.answers.size());
  for (std::size_t i = 0; i < d.answers.size(); ++i) {
    INFO(d.answers[i].name);
    REQUIRE(d.answers[i].value);
    CHECK(d.answers[i].value->approx == Approx(e.answers[i].value->approx));
  }
  const std::string report = write(d, Format::text, true);
  CHECK(report.find("    x = -4*h/3  = -4 m    [given]\n") != std::string::npos);
  CHECK(report.find("    l_CP = sqrt(h^2 + x^2)  = 5 m    [definition]\n") != std::string::npos);
  // No condition is solved for h with x held: x moves with h.
  for (const auto& c : d.conditions)
    for (const auto& s : c.solved) CHECK(to_text(s.parameter) != "h");
}

TEST_CASE("Given: with a motion, a value in the parameters is the number it comes to", "[given][motion]") {
  // The pendulum at 30 deg with dot(theta) = sqrt(g/l) = 3.13209 rad/s: by hand T = m (g
  // cos(theta) + l dot(theta)^2) = 9.81 (0.866025 + 1) = 18.3056 N. The motion, which starts
  // from its own 'initial', keeps its coordinates free of the instant's values.
  const auto a = test::run_text(
      test::example_with("rotation-pendulum.yaml", "dot(theta): {value: 2, unit: rad/s}", "dot(theta): sqrt(g/l)"));
  const SymbolInfo* rate = a->model.symbols->find("dot(theta)");
  REQUIRE(rate->value);
  CHECK_FALSE(rate->definition);
  CHECK(to_text(*rate->value) == "sqrt(981)/10");
  const Derivation d = explain(*a);
  REQUIRE(d.answers[1].value);
  CHECK(d.answers[1].value->approx == Approx(18.3056).epsilon(1e-5));
  const std::string symbolic = test::example_with("rotation-pendulum.yaml", "  l: {value: 1, unit: m}",
                                                  "  l: {value: 1, unit: m}\n  w: {unit: rad/s}");
  CHECK(test::errors_of(std::string(symbolic).replace(symbolic.find("{value: 2, unit: rad/s}"), 23, "w")) ==
        Messages{
            "t.yaml:31:52: 'given' value of 'dot(theta)': with a 'motion', the instant's given values are numbers, and "
            "w has no value (expected a value for it in 'parameters')"});
}

TEST_CASE("Given: a value must be a number in a unit of the quantity", "[given][errors]") {
  auto with = [](const std::string& from, const std::string& to) {
    std::string text = raised_pulley + "find: [T]\n";
    text.replace(text.find(from), from.size(), to);
    return test::errors_of(text);
  };
  CHECK(with("x: {value: -4, unit: m}", "x: {value: -4, unit: kg}") ==
        Messages{"t.yaml:21:24: 'x' is a length, but kg is a mass"});
  CHECK(with("x: {value: -4, unit: m}", "x: {value: k, unit: m}") ==
        Messages{"t.yaml:21:14: 'given' value of 'x': unknown name 'k' (known: m, M, h, g, t, x, y, N_C, T, l_CP)"});
  CHECK(
      with("x: {value: -4, unit: m}", "x: {value: T, unit: m}") ==
      Messages{"t.yaml:21:14: 'given' value of 'x': 'T' is not a parameter (expected a number or an expression in the "
               "parameters)"});
  CHECK(with("x: {value: -4, unit: m}", "x: g") ==
        Messages{"t.yaml:21:6: 'given' value of 'x' is an acceleration (expected a length)"});
  CHECK(
      with("x: {value: -4, unit: m}", "x: sqrt(-h)") ==
      Messages{
          "t.yaml:21:6: 'given' value of 'x' is not a real number (expected a real value at the parameters' values)"});
  CHECK(with("x: {value: -4, unit: m}", "x: {unit: m}") ==
        Messages{"t.yaml:21:13: 'given' value of 'x' has a 'unit' but no 'value'"});
  CHECK(with("x: {value: -4, unit: m}", "x: {value: -4, units: m}") ==
        Messages{"t.yaml:21:18: unknown key 'units' in 'given' value of 'x' (did you mean 'unit'?)"});
  CHECK(with("dot(x): 0", "dot(x): {value: 2, unit: m}") ==
        Messages{"t.yaml:22:28: 'dot(x)' is a velocity, but m is a length"});
}

TEST_CASE("Pulley: a radius drops out while the strands keep their directions, and says so", "[path][pulley]") {
  const std::string plain = test::read_example("incline-and-hanging-block.yaml");
  const std::string with_radius =
      test::example_with("incline-and-hanging-block.yaml", "{type: pulley, at: P}", "{type: pulley, at: P, radius: r}");
  const auto a = test::run_text(plain),
             b = test::run_text(std::string(with_radius)
                                    .replace(with_radius.find("  L: {value: 2, unit: m}\n"), 24,
                                             "  L: {value: 2, unit: m}\n  r: {value: 0.05, unit: m}\n"));
  const Derivation da = explain(*a), db = explain(*b);
  REQUIRE(da.answers.size() == db.answers.size());
  for (std::size_t i = 0; i < da.answers.size(); ++i) {
    REQUIRE(db.answers[i].closed_form);
    CHECK(to_text(*da.answers[i].closed_form) == to_text(*db.answers[i].closed_form));
  }
  const auto& said = b->model.assumptions;
  CHECK(std::find(said.begin(), said.end(),
                  "a pulley's radius changes only the length wrapped on it, which is constant while its strands keep "
                  "their directions: the length sum and its derivatives do not depend on it") != said.end());
  CHECK(a->model.assumptions.size() + 1 == said.size());
}

TEST_CASE("Pulley: a radius where a strand turns, or a radius that is not positive, is an error",
          "[path][pulley][errors]") {
  std::string text = raised_pulley + "find: [T]\n";
  text.replace(text.find("{type: pulley, at: P}"), 21, "{type: pulley, at: P, radius: r}");
  text.replace(text.find("  g: {value"), 0, "  r: {value: 0.1, unit: m}\n");
  CHECK(
      test::errors_of(text) ==
      Messages{"t.yaml:17:5: strand C-P at point 'P' of a 'pulley' connection turns as the bodies move, so the length "
               "wrapped on it would change (expected strands that keep their directions there, or the pulley as a "
               "point: no 'radius')"});
  text.replace(text.find("r: {value: 0.1, unit: m}"), 24, "r: {value: -0.1, unit: m, positive: false}");
  CHECK(
      test::errors_of(text) ==
      Messages{"t.yaml:17:5: strand C-P at point 'P' of a 'pulley' connection turns as the bodies move, so the length "
               "wrapped on it would change (expected strands that keep their directions there, or the pulley as a "
               "point: no 'radius')",
               "t.yaml:17:35: 'radius' of a 'pulley' connection is r = -0.1 m (expected a positive value)"});
}

TEST_CASE("Path: a string over a fixed point that nothing holds is an error", "[path][errors]") {
  std::string text = raised_pulley + "find: [T]\n";
  text.replace(text.find("  - {type: pulley, at: P}\n"), 26, "");
  CHECK(test::errors_of(text) ==
        Messages{
            "t.yaml:17:5: the path of a 'string' connection 's' runs over point 'P', which nothing holds (expected a "
            "pulley there: {type: pulley, at: P})"});
  // A point on a body holds the string itself (a ring on the block).
  const std::string ring =
      test::example_with("figure-12.5d-motion-doubled.yaml", "connections:\n  - {type: pulley, at: B}\n", "");
  CHECK(test::errors_of(ring).empty());
}

TEST_CASE("Spring: a stretch stated where every coordinate is 0 gives the force the rest length gives", "[spring]") {
  // Sample 12.4: y is measured from the equilibrium, where the spring is compressed by y_s.
  const auto by_rest = test::run_text(test::read_example("sample-12.4-stacked-blocks-on-spring.yaml"));
  const auto by_stretch = test::run_text(
      test::example_with("sample-12.4-stacked-blocks-on-spring.yaml", "rest_length: l_0}", "stretch: -y_s}"));
  const Derivation a = explain(*by_rest), b = explain(*by_stretch);
  REQUIRE(a.answers.size() == 2);
  REQUIRE(b.answers.size() == 2);
  for (int i = 0; i < 2; ++i) {
    REQUIRE(b.answers[i].closed_form);
    CHECK(to_text(*a.answers[i].closed_form) == to_text(*b.answers[i].closed_form));
  }
  CHECK(test::errors_of(test::example_with("sample-12.4-stacked-blocks-on-spring.yaml", "rest_length: l_0}",
                                           "rest_length: l_0, stretch: y_s}")) ==
        Messages{"t.yaml:40:5: a 'spring' connection 'k_s' has rest_length and stretch (expected one of them)"});
}

namespace {

// Cart A (on two rollers R and S) pulled by F, and block B, whose center is h above the line
// of A's; `joint` joins them.
std::string cart_and_block(const std::string& joint, const std::string& rest) {
  return R"(title: a cart and a block joined
axes: [x, y]
parameters:
  m_A: {value: 3, unit: kg}
  m_B: {value: 1, unit: kg}
  F: {value: 8, unit: N}
  g: {value: 9.81, unit: m/s^2}
  b: {value: 1, unit: m}
  h: {value: 0.5, unit: m}
  c: {value: 0.4, unit: m}
gravity: [0, -g]
bodies:
  A: {mass: m_A, position: x_A, center_of_mass: [x_A, 0]}
  B: {mass: m_B, position: x_B, center_of_mass: [x_B, h]}
points:
  R: {on: A, offset: [c, 0]}
  S: {on: A, offset: ["-c", 0]}
  W: {on: A, offset: ["-b", 0]}
connections:
  - {type: roller, body: A, at: R, normal: [0, 1]}
  - {type: roller, body: A, at: S, normal: [0, 1]}
  - {type: force, on: A, at: A, force: [F, 0]}
)" + joint +
         rest;
}

}  // namespace

TEST_CASE("Joints: a weld between two moving bodies carries a force and a couple, reversed on the other", "[joint]") {
  // The weld W is a distance b behind A's center of mass, straight below B's center. By
  // hand: a = F/(m_A + m_B); LMB B: -W_x = m_B a, -W_y - m_B g = 0; AMB B about its center:
  // -h W_x - (x_A - b - x_B) W_y - M_W = 0.
  const auto a = test::run_text(cart_and_block("  - {type: weld_joint, body: A, other: B, at: W}\n",
                                               "layout: {x_A: 2, x_B: 1}\ngiven: {x_A: 2, x_B: 1}\n"
                                               "find: [ddot(x_A), W_x, W_y, M_W]\n"));
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 4);
  std::vector<std::string> got;
  for (const auto& ans : d.answers) got.push_back(to_text(*ans.closed_form) + " = " + ans.value->decimal);
  CHECK(std::vector<std::string>(got.begin(), got.begin() + 3) ==
        std::vector<std::string>{"F/(m_A + m_B) = 2", "-F*m_B/(m_A + m_B) = -2", "-g*m_B = -9.81"});
  // M_W = -h W_x - (x_A - b - x_B) W_y in general (W is below B's center in the layout).
  const auto& t = *a->model.symbols;
  auto s = [&](const char* n) { return t.find(n)->sym; };
  const ex expected =
      s("h") * s("m_B") * s("F") / (s("m_A") + s("m_B")) + s("m_B") * s("g") * (s("x_A") - s("b") - s("x_B"));
  CHECK(normal(*d.answers[3].closed_form - expected).is_zero());
  CHECK(d.answers[3].value->decimal == "1");
}

TEST_CASE("Joints: a slider between two moving bodies pushes across the slide only", "[joint]") {
  // Block B rides on cart A through a smooth slider at B's center: no force along x reaches
  // B, so ddot(x_B) = 0 and ddot(x_A) = F/m_A; the slider holds B up (the push on A is
  // N_B = -m_B g along [0, 1]) with no couple.
  const auto a = test::run_text(cart_and_block("  - {type: slider_joint, body: A, other: B, at: B, normal: [0, 1]}\n",
                                               "layout: {x_A: 0, x_B: 1}\nfind: [ddot(x_A), ddot(x_B), N_B, M_B]\n"));
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 4);
  std::vector<std::string> got;
  for (const auto& ans : d.answers) got.push_back(to_text(*ans.closed_form) + " = " + ans.value->decimal);
  CHECK(got == std::vector<std::string>{"F/m_A = 2.66667", "0 = 0", "-g*m_B = -9.81", "0 = 0"});
}

TEST_CASE("Spring: a string that pulls a spring moves its end twice as far: x_S = 2 x + const", "[spring][path]") {
  // The string runs from the wall W around a pulley on block A and back to S, where a spring
  // to the wall Q (at -L) takes it: its length is x + (x - x_S), so x_S = 2 x - C_s. The
  // spring's length is x_S + L, its tension k (x_S + L - l_0), and the string's T equals it
  // (S is massless); A: -F - 2 T = m ddot(x).
  const auto a = test::run_text(R"(title: a string that pulls a spring
parameters:
  m: {value: 2, unit: kg}
  k: {value: 100, unit: N/m}
  l_0: {value: 0.5, unit: m}
  F: {value: 10, unit: N}
  L: {value: 5, unit: m}
bodies:
  A: {mass: m, position: x}
  S: {mass: 0, position: x_S}
points:
  W: 0
  pA: {on: A}
  Q: -L
loads:
  - {on: A, force: -F}
strings:
  - {name: s, path: [W, pA, S], tension: T}
connections:
  - {type: pulley, at: pA}
  - {type: spring, path: [S, Q], k: k, rest_length: l_0}
layout: {x: 3, x_S: 1}
given: [x]
find: [x_S, T, ddot(x)]
)");
  const Derivation d = explain(*a);
  REQUIRE(d.answers.size() == 3);
  CHECK(to_text(*d.answers[0].closed_form) == "2*x - C_s");
  const auto& t = *a->model.symbols;
  auto s = [&](const char* n) { return t.find(n)->sym; };
  const ex x_S = 2 * s("x") - s("C_s"), T = s("k") * (x_S + s("L") - s("l_0"));
  CHECK(normal(*d.answers[1].closed_form - T).is_zero());
  CHECK(normal(*d.answers[2].closed_form - (-s("F") - 2 * T) / s("m")).is_zero());
}

TEST_CASE("Power: the balance holds for a solution and fails for a wrong one", "[power]") {
  const auto a = test::run_text(test::read_example("atwood-machine.yaml"));
  const PowerCheck ok = check_power(a->model, a->system, a->solution);
  CHECK(ok.status == PowerCheck::Status::holds);
  CHECK(to_text(ok.kinetic_rate) == "m_A*ddot(y_A)*dot(y_A) + m_B*ddot(y_B)*dot(y_B)");
  // The tension does no work (the string's length is constant): a wrong T passes, a wrong
  // acceleration does not.
  Solution wrong = a->solution;
  const ex T = a->model.symbols->find("T")->sym, a_A = a->model.symbols->find("ddot(y_A)")->sym,
           a_B = a->model.symbols->find("ddot(y_B)")->sym;
  wrong.general[T] = 2 * wrong.general[T];
  CHECK(check_power(a->model, a->system, wrong).status == PowerCheck::Status::holds);
  wrong.general[a_A] = 2 * wrong.general[a_A];
  wrong.general[a_B] = 2 * wrong.general[a_B];
  const PowerCheck bad = check_power(a->model, a->system, wrong);
  CHECK(bad.status == PowerCheck::Status::fails);
  CHECK_FALSE(bad.residual.is_zero());
  // Bodies at rest: nothing to check.
  const auto rest = test::run_text(R"(title: a block at rest on a support
bodies: {A: {mass: m, position: x}}
parameters: {m: {value: 1, unit: kg}, g: {value: 9.81, unit: m/s^2}}
gravity: -g
connections: [{type: fixed, body: A}]
)");
  const PowerCheck none = check_power(rest->model, rest->system, rest->solution);
  CHECK(none.status == PowerCheck::Status::holds);
}

TEST_CASE("Values: a definition or a point undefined at the given values is a located error", "[errors]") {
  // Both made GiNaC throw (exit 3) while the model was built.
  std::string text = raised_pulley + "find: [T]\n";
  text.replace(text.find("  g: {value"), 0, "  c: {value: 3, unit: m}\n");
  text.replace(text.find("  P: [0, h]"), 11, "  P: [\"h - h^2/(h - c)\", h]");
  CHECK(test::errors_of(text) ==
        Messages{"t.yaml:14:6: position of point 'P' is undefined at the given values (h + h^2/(c - h) divides by zero "
                 "there)"});
  std::string def = raised_pulley + "find: [T]\n";
  def.replace(def.find("  g: {value"), 0, "  c: {value: 3, unit: m}\n  d: {define: \"h^2/(h - c)\"}\n");
  CHECK(test::errors_of(def) ==
        Messages{"t.yaml:8:16: 'define' of parameter 'd' is undefined at the given values (h^2/(h - c) divides by zero "
                 "there)"});
}

TEST_CASE("Layout and until: numbers or expressions in parameters with values", "[given][motion]") {
  // A block on a spring from P at L: the layout puts it at L/4 = 0.5 m, the run lasts 2 T_0 = 3 s.
  const std::string text = R"(title: layout in parameters
parameters:
  m: {value: 2, unit: kg}
  k: {value: 50, unit: N/m}
  L: {value: 2, unit: m}
  T_0: {value: 1.5, unit: s}
  a: {unit: m}
bodies:
  A: {mass: m, position: x}
points:
  P: L
connections:
  - {type: spring, path: [A, P], k: k, rest_length: L/2}
layout: {x: L/4}
given: [x]
find: [ddot(x)]
motion:
  initial: {x: L/4, dot(x): 0}
  until: 2*T_0
)";
  const auto a = test::run_text(text);
  CHECK(to_text(a->model.layout.at(a->model.symbols->find("x")->sym)) == "1/2");
  REQUIRE(a->model.motion->until);
  CHECK(to_text(*a->model.motion->until) == "3");
  auto with = [&](const std::string& from, const std::string& to) {
    return test::errors_of(std::string(text).replace(text.find(from), from.size(), to));
  };
  CHECK(with("until: 2*T_0", "until: 2*L") ==
        Messages{"t.yaml:19:10: 'until' of 'motion' is a length (expected a time)"});
  CHECK(with("layout: {x: L/4}", "layout: {x: a}") ==
        Messages{"t.yaml:13:5: cannot tell the direction of strand A-P of spring (give 'layout' values for x)",
                 "t.yaml:14:13: layout value of 'x': 'a' has no value (expected a number, or parameters with values)"});
  CHECK(
      with("layout: {x: L/4}", "layout: {x: ddot(x)}") ==
      Messages{
          "t.yaml:13:5: cannot tell the direction of strand A-P of spring (give 'layout' values for x)",
          "t.yaml:14:13: layout value of 'x': 'ddot(x)' is not a parameter (expected a number or an expression in the "
          "parameters)"});
}

// Bad descriptions: each kind of mistake gets a located message, word for word, and every
// problem in a file is reported at once.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "../../support/helpers.hpp"

using tackle::test::errors_of;
using Messages = std::vector<std::string>;

namespace {
// A correct two-mass pulley problem; the cases below break one thing at a time.
const std::string good = R"(title: ok
parameters:
  F: {value: 130, unit: N}
  m: {value: 40, unit: kg}
bodies:
  A: {mass: m, position: x_A}
  B: {mass: m, position: x_B}
points:
  C: 0
loads:
  - {on: A, force: -F}
strings:
  - {name: s, path: [B, C, A], tension: T}
layout: {x_A: -1, x_B: 1}
connections:
  - {type: pulley, at: C}
)";

std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  REQUIRE(pos != std::string::npos);
  text.replace(pos, from.size(), to);
  return text;
}
}  // namespace

TEST_CASE("Description: the unbroken problem is accepted", "[errors]") { CHECK(errors_of(good).empty()); }

TEST_CASE("Description: bad YAML is located", "[errors]") {
  CHECK(errors_of(with(good, "layout: {x_A: -1, x_B: 1}", "layout: {x_A: -1, x_B: 1")) ==
        Messages{"t.yaml:15:12: invalid YAML: did not find expected ',' or '}' (while parsing a flow mapping "
                 "started at line 14, column 9)"});
}

TEST_CASE("Description: an unknown key suggests the nearest valid key", "[errors]") {
  CHECK(errors_of(with(good, "A: {mass: m,", "A: {mas: m,")) ==
        Messages{"t.yaml:6:7: unknown key 'mas' in body 'A' (did you mean 'mass'?)"});
  CHECK(errors_of(with(good, "layout:", "layuot:")) ==
        Messages{"t.yaml:13:5: cannot tell the direction of strand B-C of string s (give 'layout' values for x_B)",
                 "t.yaml:13:5: cannot tell the direction of strand C-A of string s (give 'layout' values for x_A)",
                 "t.yaml:14:1: unknown key 'layuot' in the description (did you mean 'layout'?)"});
}

TEST_CASE("Description: an undefined name in an expression is located inside it", "[errors]") {
  CHECK(errors_of(with(good, "force: -F", "force: -G")) ==
        Messages{"t.yaml:11:21: 'force' of a 'force' connection: unknown name 'G' (known: F, m, t, x_A, x_B)"});
}

TEST_CASE("Description: a duplicate name says where the first one is", "[errors]") {
  // A point may not share a body's name; a coordinate may not share a parameter's.
  CHECK(errors_of(with(good, "  C: 0", "  A: 0")) ==
        Messages{"t.yaml:9:3: duplicate name 'A' (first defined at line 6)",
                 "t.yaml:13:25: unknown point 'C' (known: A, B)", "t.yaml:16:24: unknown point 'C' (known: A, B)"});
  CHECK(errors_of(with(good, "position: x_B", "position: m")) ==
        Messages{"t.yaml:7:26: duplicate name 'm' (first defined at line 4)",
                 "t.yaml:14:19: 'layout' names 'x_B', which is not a coordinate or a parameter (did you mean 'x_A'?)"});
}

TEST_CASE("Description: an expression that does not parse", "[errors]") {
  CHECK(errors_of(with(good, "A: {mass: m,", "A: {mass: 2*m*,")) ==
        Messages{"t.yaml:6:17: mass of body 'A': expression ends too early"});
}

TEST_CASE("Description: a string path through an unknown point", "[errors]") {
  CHECK(errors_of(with(good, "path: [B, C, A]", "path: [B, D, A]")) ==
        Messages{"t.yaml:13:25: unknown point 'D' (known: A, B, C)"});
}

TEST_CASE("Description: an unknown unit and a unit of the wrong dimension", "[errors]") {
  CHECK(
      errors_of(with(good, "unit: kg}", "unit: kgg}")) ==
      Messages{
          "t.yaml:4:24: unit of parameter 'm': unknown unit 'kgg' (expected SI units such as kg, m, s, N, m/s^2, kN)"});
  CHECK(errors_of(with(good, "unit: kg}", "unit: m}")) ==
        Messages{"t.yaml:6:13: mass of body 'A' is a length (expected a mass)",
                 "t.yaml:7:13: mass of body 'B' is a length (expected a mass)"});
}

TEST_CASE("Description: a force that is not a force", "[errors]") {
  CHECK(errors_of(with(good, "force: -F", "force: -m")) ==
        Messages{"t.yaml:11:20: 'force' of a 'force' connection is a mass (expected a force)"});
}

TEST_CASE("Description: an unknown connection type suggests the nearest rule", "[errors]") {
  CHECK(errors_of(good + "  - {type: pully, at: C}\n") ==
        Messages{"t.yaml:17:12: unknown connection type 'pully' (did you mean 'pulley'?)"});
}

TEST_CASE("Description: a connection without what its rule needs", "[errors]") {
  CHECK(errors_of(good + "  - {type: fixed}\n") == Messages{"t.yaml:17:5: a 'fixed' connection needs 'body'"});
  CHECK(errors_of(with(good, "path: [B, C, A]", "length: x_B - x_A, path: [B, C, A]")) ==
        Messages{"t.yaml:13:5: a 'string' connection 's' has path and length (expected one of them)"});
}

TEST_CASE("Description: a pulley that no string runs over", "[errors]") {
  CHECK(errors_of(good + "  - {type: pulley, at: A}\n") ==
        Messages{"t.yaml:17:5: no string runs over point 'A' of a 'pulley' connection (expected it inside some "
                 "string's path)"});
}

TEST_CASE("Description: a strand whose direction cannot be told", "[errors]") {
  CHECK(errors_of(with(good, "layout: {x_A: -1, x_B: 1}", "layout: {x_A: 0, x_B: 1}")) ==
        Messages{"t.yaml:13:5: strand C-A of string s has zero length in the layout (expected its ends apart)"});
}

TEST_CASE("Description: duplicate keys and wrong shapes", "[errors]") {
  CHECK(errors_of(with(good, "  C: 0\n", "  C: 0\n  C: 1\n")) ==
        Messages{"t.yaml:10:3: duplicate key 'C' in 'points'"});
  CHECK(errors_of(with(good, "points:", "points: 3\nx:")) ==
        Messages{"t.yaml:8:9: 'points' is a scalar (expected a mapping of names)",
                 "t.yaml:9:1: unknown key 'x' in the description (expected one of: title, source, statement, axes, "
                 "parameters, "
                 "gravity, bodies, points, connections, loads, strings, layout, given, find, derive, expected, "
                 "expected_combinations, expected_conditions, expected_ranges, expected_free, expected_power, notes, "
                 "sweep, motion, expected_motion, interval, impact, steady)",
                 "t.yaml:14:25: unknown point 'C' (known: A, B)", "t.yaml:17:24: unknown point 'C' (known: A, B)"});
}

TEST_CASE("Description: every problem in the file is reported at once", "[errors]") {
  std::string bad = with(good, "A: {mass: m,", "A: {mas: m,");
  bad = with(bad, "force: -F", "force: -G");
  bad = with(bad, "path: [B, C, A]", "path: [B, Q, A]");
  CHECK(errors_of(bad) ==
        Messages{"t.yaml:6:7: unknown key 'mas' in body 'A' (did you mean 'mass'?)",
                 "t.yaml:11:21: 'force' of a 'force' connection: unknown name 'G' (known: F, m, t, x_A, x_B)",
                 "t.yaml:13:25: unknown point 'Q' (known: A, B, C)"});
}

TEST_CASE("Description: a missing title and missing bodies", "[errors]") {
  CHECK(errors_of("axes: [x]\n") ==
        Messages{"t.yaml:1:1: the description has no 'title' (expected a one-line title)",
                 "t.yaml:1:1: the description has no 'bodies' (expected at least one body)"});
  CHECK(errors_of("- just\n- a list\n") ==
        Messages{"t.yaml:1:1: the description is a list (expected a mapping with title, bodies, ...)"});
}

namespace {
// A correct 2-D problem (a block on a cart held by a pin and a rod); cases break one thing.
const std::string plate = R"(title: ok
axes: [x, y]
parameters:
  m: {value: 10, unit: kg}
  g: {value: 9.81, unit: m/s^2}
gravity: [0, -g]
points:
  B: [0, 0]
  D: [2, 2]
  E: [3, 0]
bodies:
  plate: {mass: m, center_of_mass: [1, 1], acceleration: [3, 0]}
connections:
  - {type: pin, body: plate, at: B}
  - {type: rod, body: plate, from: D, to: E}
)";
}  // namespace

TEST_CASE("Description: the unbroken 2-D problem is accepted", "[errors]") { CHECK(errors_of(plate).empty()); }

TEST_CASE("Description: a support at an unknown point, and a rule used in the wrong dimension", "[errors]") {
  CHECK(errors_of(with(plate, "to: E}", "to: Q}")) ==
        Messages{"t.yaml:15:43: unknown point 'Q' (known: plate, B, D, E)"});
  CHECK(errors_of(with(plate, "type: pin", "type: ball_and_socket")) ==
        Messages{"t.yaml:14:12: a 'ball_and_socket' connection is for 3-D problems (this one has 2 axes)"});
  CHECK(errors_of(plate + "  - {type: fixed, body: plate}\n") ==
        Messages{"t.yaml:16:12: a 'fixed' connection is for 1-D problems (this one has 2 axes)"});
}

TEST_CASE("Description: a vector with the wrong number of entries", "[errors]") {
  CHECK(errors_of(with(plate, "D: [2, 2]", "D: [2, 2, 0]")) ==
        Messages{"t.yaml:9:6: position of point 'D' has 3 entries (expected 2, one per axis: x, y)"});
}

TEST_CASE("Description: a force in 2-D needs its point of application", "[errors]") {
  CHECK(errors_of(plate + "loads: [{on: plate, force: [1, 0]}]\n") ==
        Messages{"t.yaml:16:9: a 'force' connection needs a point of application in a 2-D problem (give 'at')"});
  CHECK(errors_of(plate + "loads: [{on: plate, force: 5, at: D}]\n") ==
        Messages{"t.yaml:16:28: 'force' of a 'force' connection has 1 entry (expected 2, one per axis: x, y)"});
}

TEST_CASE("Description: a 2-D body needs its center of mass, and AMB needs 2-D or 3-D", "[errors]") {
  CHECK(errors_of(with(plate, "center_of_mass: [1, 1], ", "")) ==
        Messages{"t.yaml:12:10: body 'plate' has no 'center_of_mass' (needed for its weight and its angular momentum "
                 "balance)"});
  CHECK(errors_of(good + "derive: [{amb: A, about: C}]\n") ==
        Messages{"t.yaml:17:11: angular momentum balance needs a 2-D or 3-D problem (this one has one axis)"});
  CHECK(errors_of(plate + "derive: [{amb: plate, about: Z}]\n") ==
        Messages{"t.yaml:16:30: unknown point 'Z' (known: plate, B, D, E)"});
}

TEST_CASE("Description: an output unit must be a unit of the quantity's dimension", "[errors][units]") {
  CHECK(errors_of(good + "find: [{name: T, unit: kg}, {name: ddot(x_A), unit: fts}]\n") ==
        Messages{"t.yaml:17:24: 'T' is a force, but kg is a mass",
                 "t.yaml:17:53: unit of 'ddot(x_A)' in 'find': unknown unit 'fts'"});
  CHECK(errors_of(good + "find: [{name: T, unit: lbf}]\n").empty());
}

TEST_CASE("Description: a variant range must be a non-empty range of numbers", "[errors][key]") {
  CHECK(errors_of(with(good, "F: {value: 130, unit: N}", "F: {value: 130, unit: N, range: [200, 100]}")) ==
        Messages{"t.yaml:3:36: 'range' of parameter 'F' is empty (expected low < high)"});
  CHECK(errors_of(with(good, "m: {value: 40, unit: kg}", "m: {value: 40, unit: kg, range: [-1, 5]}")) ==
        Messages{"t.yaml:4:36: 'range' of parameter 'm' reaches -1, but the parameter is positive"});
}

namespace {
const std::string spring_block = R"(title: a block on a spring
parameters:
  m: {value: 1, unit: kg}
  k: {value: 100, unit: N/m}
  c: {value: 3, unit: N*s/m}
  L: {value: 2, unit: m}
  l_0: {value: 1, unit: m}
bodies:
  A: {mass: m, position: x}
points:
  W: 0
connections:
  - {type: spring, path: [W, A], k: k, rest_length: l_0}
  - {type: damper, path: [W, A], c: c}
layout: {x: 1}
)";
}  // namespace

TEST_CASE("Description: springs, dampers and angles are checked where they are written", "[errors][spring]") {
  CHECK(errors_of(spring_block).empty());
  CHECK(errors_of(with(spring_block, "k: {value: 100, unit: N/m}", "k: {value: -100, unit: N/m, positive: false}")) ==
        Messages{"t.yaml:13:37: 'k' of a 'spring' connection is k = -100 N/m (expected a positive value)"});
  CHECK(errors_of(with(spring_block, "k: k, rest", "k: -k, rest")) ==
        Messages{"t.yaml:13:37: 'k' of a 'spring' connection is -k = -100 N/m (expected a positive value)"});
  CHECK(errors_of(with(spring_block, "{type: damper, path: [W, A], c: c}", "{type: damper, c: c}")) ==
        Messages{"t.yaml:14:5: a 'damper' connection needs 'path'"});
  CHECK(errors_of(with(spring_block, "path: [W, A], c", "path: [W, Q], c")) ==
        Messages{"t.yaml:14:30: unknown point 'Q' (known: A, W)"});
  CHECK(errors_of(with(spring_block, "L: {value: 2, unit: m}", "L: {value: 2, unit: deg, dimension: length}")) ==
        Messages{"t.yaml:6:39: parameter 'L' has dimension length but its unit deg is dimensionless (an angle or a "
                 "pure number)"});
  CHECK(errors_of(with(spring_block, "rest_length: l_0", "rest_length: m")) ==
        Messages{"t.yaml:13:53: 'rest_length' of a 'spring' connection is a mass (expected a length)"});
}

TEST_CASE("Spring: the force comes from the path, k times the stretch, and the damper's from its rate", "[spring]") {
  const auto a = tackle::test::run_text(spring_block + "given: [x, dot(x)]\nfind: [ddot(x)]\n");
  const tackle::Derivation d = tackle::explain(*a);
  REQUIRE(d.answers.size() == 1);
  REQUIRE(d.answers[0].closed_form);
  // By hand: the spring (length x, rest length l_0) pulls A back with k (x - l_0), the
  // damper with c dot(x): m ddot(x) = -k (x - l_0) - c dot(x).
  const auto& t = a->model.symbols;
  const GiNaC::ex k = t->find("k")->sym, c = t->find("c")->sym, m = t->find("m")->sym, x = t->find("x")->sym,
                  v = t->find("dot(x)")->sym, l_0 = t->find("l_0")->sym;
  CHECK(GiNaC::normal(*d.answers[0].closed_form - (-k * (x - l_0) - c * v) / m).is_zero());
}

TEST_CASE("Description: a joint between a body and itself is an error", "[errors][joint]") {
  const std::string two = tackle::test::read_example("two-blocks-joined-by-a-pin.yaml");
  CHECK(errors_of(with(two, "other: B, at: H", "other: A, at: H")) ==
        Messages{"t.yaml:30:5: a 'pin_joint' connection joins body 'A' to itself (expected two different bodies)"});
  CHECK(
      errors_of(with(two, "  - {type: force, on: A, at: A, force: [F, 0]}\n",
                     "  - {type: force, on: A, at: A, force: [F, 0]}\n  - {type: same_motion, body: B, other: Z}\n")) ==
      Messages{"t.yaml:32:41: unknown body 'Z' (known: A, B)"});
}

TEST_CASE("Description: gravity by magnitude and tilt needs both, with their dimensions", "[errors][gravity]") {
  CHECK(errors_of(good + "gravity: {magnitude: g}\n") ==
        Messages{"t.yaml:17:10: 'gravity' as a mapping needs 'magnitude' and 'tilt' (the angle the first axis rises "
                 "above the horizontal)"});
  CHECK(errors_of(good + "gravity: {magnitude: F, tilt: m}\n") ==
        Messages{"t.yaml:17:22: 'magnitude' of 'gravity' is a force (expected an acceleration)",
                 "t.yaml:17:31: 'tilt' of 'gravity' is a mass (expected a pure number)"});
}

TEST_CASE("Description: a force element whose path never changes length is an error", "[errors][spring]") {
  CHECK(
      errors_of(with(spring_block, "layout:", "  - {type: contact, name: c, between: [A, A]}\nlayout:")) ==
      Messages{"t.yaml:15:5: the path of a 'contact' connection 'c' never changes length (its ends are on one body, or "
               "fixed; expected a path between points that move apart)"});
}

TEST_CASE("Spring: at one instant the position and velocity are known symbols of the answer (issue 30)",
          "[spring][trust]") {
  // Without `given`, the answer keeps x and dot(x) as a person writes it (a regression had made
  // it "not determined: it depends on x, dot(x)").
  const auto a = tackle::test::run_text(spring_block + "find: [ddot(x)]\n");
  const tackle::Derivation d = tackle::explain(*a);
  REQUIRE(d.answers.size() == 1);
  CHECK(d.answers[0].status == tackle::Answer::Status::determined);
  REQUIRE(d.answers[0].closed_form);
  // By hand: m ddot(x) = -k (x - l_0) - c dot(x).
  const auto& t = a->model.symbols;
  const GiNaC::ex k = t->find("k")->sym, c = t->find("c")->sym, m = t->find("m")->sym, x = t->find("x")->sym,
                  v = t->find("dot(x)")->sym, l_0 = t->find("l_0")->sym;
  CHECK(GiNaC::normal(*d.answers[0].closed_form - (-k * (x - l_0) - c * v) / m).is_zero());
  CHECK(d.status == "determined");
}

TEST_CASE("Spring: a position asked for that the equations cannot give says what is missing", "[spring][trust]") {
  // A position question makes positions unknowns: the spring's x is not given by any
  // constraint, and the answer is never x itself.
  const auto a = tackle::test::run_text(spring_block + "find: [x, ddot(x)]\n");
  const tackle::Derivation d = tackle::explain(*a);
  REQUIRE(d.answers.size() == 2);
  CHECK(d.answers[0].status == tackle::Answer::Status::undetermined);
  CHECK(d.answers[1].status == tackle::Answer::Status::undetermined);
  CHECK(d.answers[1].reason == "it depends on x (give it in 'given' for the answer at any instant)");
}

TEST_CASE("Description: an argument that is not a name is reported once, not used (found by fuzzing)",
          "[errors][fuzz]") {
  CHECK(errors_of(with(plate, "at: B}", "at: {B: 1}}")) ==
        Messages{"t.yaml:14:34: 'at' is a mapping (expected a list of names)"});
}

TEST_CASE("Answers: a defined quantity that divides by an unknown equal to zero says so (found by fuzzing)",
          "[errors][fuzz]") {
  // The string no longer reaches A, so nothing moves B: ddot(x_B) = 0 and m_eff = F/ddot(x_B)
  // has no value. GiNaC threw from the substitution (exit 3).
  const auto a = tackle::test::run_text(
      tackle::test::example_with("figure-12.5d-motion-doubled.yaml", "path: [A, B, W]", "path: [B, B, W]"));
  const tackle::Derivation d = tackle::explain(*a);
  REQUIRE(d.answers.size() == 4);
  CHECK(d.answers[3].name == "m_eff");
  CHECK(d.answers[3].status == tackle::Answer::Status::undetermined);
  CHECK(d.answers[3].reason == "its definition F/ddot(x_B) divides by zero (ddot(x_B) = 0 here)");
  CHECK(tackle::write(d, tackle::Format::text, false)
            .find("m_eff: undetermined: its definition F/ddot(x_B) divides by zero (ddot(x_B) = 0 here)\n") !=
        std::string::npos);
  CHECK(tackle::write(d, tackle::Format::text, true)
            .find("m_eff is not determined: its definition divides by zero (ddot(x_B) = 0 here).") !=
        std::string::npos);
}

TEST_CASE("Description: LaTeX that reads or writes files is refused in a statement or a tex name, at the command",
          "[errors][latex]") {
  const std::string why =
      " is not allowed (expected LaTeX that reads and writes no files: no \\input, \\include, \\openin, "
      "\\write, \\read, \\catcode, \\def, \\usepackage, ^^, ...; see docs/grading.md)";
  // An environment that writes a file; columns count from the first character after the quote.
  CHECK(errors_of(with(good, "title: ok\n", "title: ok\nstatement: 'Pulled by $F$; \\begin{filecontents}'\n")) ==
        Messages{"t.yaml:2:28: \\begin{filecontents} in 'statement'" + why});
  // In a double-quoted scalar the backslash is written twice; the error is at the first.
  CHECK(errors_of(with(good, "title: ok\n", "title: ok\nstatement: \"A \\\\immediate\\\\write18{rm x}\"\n")) ==
        Messages{"t.yaml:2:15: \\immediate in 'statement'" + why});
  // In a block scalar, on the line where it is.
  CHECK(errors_of(with(good, "title: ok\n", "title: ok\nstatement: |\n  First line.\n  Then \\openout here.\n")) ==
        Messages{"t.yaml:4:8: \\openout in 'statement'" + why});
  CHECK(errors_of(with(good, "F: {value: 130, unit: N}", "F: {value: 130, unit: N, tex: '\\def\\F{x}'}")) ==
        Messages{"t.yaml:3:34: \\def in 'tex' of parameter 'F'" + why});
  // < and > would reach Markdown through the math; \lt and \gt say the same.
  CHECK(errors_of(with(good, "F: {value: 130, unit: N}", "F: {value: 130, unit: N, tex: 'F_{<}'}")) ==
        Messages{"t.yaml:3:34: 'tex' of parameter 'F' has '<', '>' or a line break (expected one line of LaTeX math; "
                 "\\lt and \\gt for < and >)"});
  // What statements use: math, text commands, a line break (\\ is not \input below), \$.
  CHECK(errors_of(
            with(good, "title: ok\n",
                 "title: ok\nstatement: 'A force $F$ on $\\mu_{k}$, \\textbf{half} ($\\tfrac12$) \\\\input \\$5.'\n"))
            .empty());
}

TEST_CASE("Description: a title or a phase's name is one line", "[errors][latex]") {
  // A blank line inside \section*{...} ends the paragraph there and breaks the document.
  CHECK(errors_of(with(good, "title: ok", "title: \"two\\n\\nlines\"")) ==
        Messages{"t.yaml:1:9: 'title' has a line break (expected a one-line title)"});
  std::ifstream in(TACKLE_SOURCE_DIR "/examples/sample-12.5-pile-driver.yaml");
  std::stringstream pile;
  pile << in.rdbuf();
  CHECK(errors_of(with(pile.str(), "  - name: fall", "  - name: \"fall\\n\\nfree\"")) ==
        Messages{
            "t.yaml:26:12: 'name' of a phase has a line break (expected one line: it is part of the phase's title)"});
}

TEST_CASE("Description: a bare letter is suggested as the name of its kind, T as the tension T_s, not t", "[errors]") {
  // Issue 32, item 7: 'find: [T]' used to suggest 't' (time, one case away).
  CHECK(errors_of(R"(title: t
axes: [y]
parameters:
  m: {value: 1, unit: kg}
  g: {value: 9.81, unit: m/s^2}
gravity: -g
bodies:
  A: {mass: m, position: y}
points:
  C: 0
strings:
  - {name: s, path: [C, A]}
layout: {y: -1}
find: [T]
)") == std::vector<std::string>{"t.yaml:14:8: 'find': unknown name 'T' (did you mean 'T_s'?)"});
}

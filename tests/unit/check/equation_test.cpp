// Checking the equations a student writes (issue "check the student's work"): each step's
// verdict and finding, from hand derivations of the examples (the examples' notes), never from
// tackle's own output.
#include <catch2/catch.hpp>

#include <map>
#include <memory>

#include "grade/batch.hpp"
#include "check/steps.hpp"

#include <nlohmann/json.hpp>
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

std::pair<std::unique_ptr<const Analysis>, std::unique_ptr<Checker>>& made_for(const std::string& example) {
  static std::map<std::string, std::pair<std::unique_ptr<const Analysis>, std::unique_ptr<Checker>>> made;
  auto it = made.find(example);
  if (it == made.end()) {
    auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/" + example + ".yaml", test::rules());
    auto c = std::make_unique<Checker>(*a);
    it = made.emplace(example, std::make_pair(std::move(a), std::move(c))).first;
  }
  return it->second;
}

const Checker& checker_for(const std::string& example) { return *made_for(example).second; }
const Model& model_for(const std::string& example) { return made_for(example).first->model; }

struct EquationStep {
  const char* example;
  const char* equation;
  Verdict verdict;
  const char* code;     // the first finding's code (correct: empty)
  const char* summary;  // the first thing said, word for word (empty: not asserted)
};

// By hand. Sample 12.3: LMB A: 2T - F = m_A a_A; LMB B: -3T = m_B a_B; the string's length
// 3 x_B - 2 x_A + const, so 3 ddot(x_B) = 2 ddot(x_A) (and the same in rates); T = 2 m_B F/(9
// m_A + 4 m_B). Sample 12.1: car 1 pulled by the chain, T = m_1 a; car 2: F - T = m_2 a.
// The Atwood machine: T - m_A g = m_A ddot(y_A), the same for B, R_C = 2T,
// ddot(y_A) + ddot(y_B) = 2 ddot(y_C) = 0. The suitcase sliding on both feet: x: -mu (N_A +
// N_B) = m a_C; y: N_A + N_B = m g; about G: (N_B - N_A) l/2 - mu h (N_A + N_B) = 0.
// Sample 12.8: about the axis OG only the rod's tension has a moment:
// T_HI d (c - e)/l = m a (c - e)/2. The massive pulley: T_1 - m_1 g = m_1 ddot(y_1),
// R (T_1 - T_2) = (M R^2/2) ddot(phi), ddot(y_1) = -R ddot(phi), ddot(y_2) = R ddot(phi).
const std::vector<EquationStep> steps{
    // Correct, each one of the derivation's equations, rearranged or scaled.
    {"sample-12.3-two-mass-pulley", "2*T - F = m_A*ddot(x_A)", Verdict::correct, "", "it is LMB A (x)"},
    {"sample-12.3-two-mass-pulley", "F - 2*T = -m_A*ddot(x_A)", Verdict::correct, "", "it is LMB A (x)"},
    {"sample-12.3-two-mass-pulley", "4*T - 2*F = 2*m_A*ddot(x_A)", Verdict::correct, "", "it is LMB A (x)"},
    {"sample-12.3-two-mass-pulley", "-3*T = m_B*ddot(x_B)", Verdict::correct, "", "it is LMB B (x)"},
    {"sample-12.3-two-mass-pulley", "T = -m_B*ddot(x_B)/3", Verdict::correct, "", "it is LMB B (x)"},
    {"sample-12.3-two-mass-pulley", "3*ddot(x_B) - 2*ddot(x_A) = 0", Verdict::correct, "",
     "it is string s: acceleration"},
    {"sample-12.3-two-mass-pulley", "ddot(x_A) = 3*ddot(x_B)/2", Verdict::correct, "", "it is string s: acceleration"},
    {"sample-12.3-two-mass-pulley", "3*dot(x_B) = 2*dot(x_A)", Verdict::correct, "", "it is string s: rate"},
    // The length sum itself, with any constant (it depends on the origin and the string).
    {"sample-12.3-two-mass-pulley", "3*x_B - 2*x_A = const", Verdict::correct, "",
     "it is the length of string s kept constant"},
    {"sample-12.3-two-mass-pulley", "6*x_B = 4*x_A + L", Verdict::correct, "",
     "it is the length of string s kept constant"},
    {"sample-12.3-two-mass-pulley", "2*x_B - 2*x_A = C_s", Verdict::incorrect, "length_sum",
     "this is not the length of string s kept constant: count the strands at each point the string passes"},
    {"sample-12.3-two-mass-pulley", "T = C", Verdict::invalid, "syntax",
     "'C' is not a name of this problem: a constant is for a length sum, an equation in the positions alone"},
    {"atwood-machine", "y_A + y_B - 2*y_C = L", Verdict::correct, "", "it is the length of string s kept constant"},
    {"sample-12.3-two-mass-pulley", "T = 2*F*m_B/(9*m_A + 4*m_B)", Verdict::correct, "",
     "it follows from LMB A (x), LMB B (x) and string s: acceleration"},
    {"sample-12.3-two-mass-pulley", "ddot(x_A) = -9*F/(9*m_A + 4*m_B)", Verdict::correct, "",
     "it follows from LMB A (x), LMB B (x) and string s: acceleration"},
    {"sample-12.3-two-mass-pulley", "2*T - F = 3*m_A*ddot(x_B)/2", Verdict::correct, "",
     "it follows from LMB A (x) and string s: acceleration"},
    {"sample-12.1-towing", "T = m_1*ddot(x_1)", Verdict::correct, "", "it is LMB car1 (x)"},
    {"sample-12.1-towing", "F - T = m_2*ddot(x_2)", Verdict::correct, "", "it is LMB car2 (x)"},
    {"sample-12.1-towing", "F = (m_1 + m_2)*ddot(x_1)", Verdict::correct, "", ""},
    {"sample-12.1-towing", "ddot(x_1) = ddot(x_2)", Verdict::correct, "", "it is string chain: acceleration"},
    {"atwood-machine", "T - m_A*g = m_A*ddot(y_A)", Verdict::correct, "", "it is LMB A (y)"},
    {"atwood-machine", "T = m_B*(g + ddot(y_B))", Verdict::correct, "", "it is LMB B (y)"},
    {"atwood-machine", "R_C = 2*T", Verdict::correct, "", "it is LMB C (y)"},
    {"atwood-machine", "ddot(y_A) + ddot(y_B) = 0", Verdict::correct, "", ""},
    {"atwood-machine", "R_C = 4*m_A*m_B*g/(m_A + m_B)", Verdict::correct, "", ""},
    {"sample-12.7-suitcase", "N_A + N_B = m*g", Verdict::correct, "", "it is LMB suitcase (y)"},
    {"sample-12.7-suitcase", "-mu*(N_A + N_B) = m*a_C", Verdict::correct, "", "it is LMB suitcase (x)"},
    {"sample-12.7-suitcase", "(N_B - N_A)*l/2 = mu*h*(N_A + N_B)", Verdict::correct, "",
     "it is AMB suitcase about its center of mass (z)"},
    {"sample-12.7-suitcase", "a_C = -mu*g", Verdict::correct, "",
     "it follows from LMB suitcase (x) and LMB suitcase (y)"},
    {"sample-12.8-sign-board", "T_HI*d*(c - e)/l = a*m*(c - e)/2", Verdict::correct, "",
     "it is AMB board about G (axis OG)"},
    {"sample-12.8-sign-board", "2*T_HI*d = m*a*l", Verdict::correct, "", "it is AMB board about G (axis OG)"},
    {"sample-12.8-sign-board", "T_HI = m*a*l/(2*d)", Verdict::correct, "", "it is AMB board about G (axis OG)"},
    {"rotation-atwood-massive-pulley", "T_1 - m_1*g = m_1*ddot(y_1)", Verdict::correct, "", "it is LMB block_1 (y)"},
    {"rotation-atwood-massive-pulley", "R*(T_1 - T_2) = M*R^2*ddot(phi)/2", Verdict::correct, "",
     "it is AMB P about its center of mass (z)"},
    {"rotation-atwood-massive-pulley", "ddot(y_1) = -R*ddot(phi)", Verdict::correct, "",
     "it is string s_1: acceleration"},
    {"rotation-atwood-massive-pulley", "ddot(y_2) = -ddot(y_1)", Verdict::correct, "",
     "it follows from string s_1: acceleration and string s_2: acceleration"},
    // Incorrect, diagnosed in the free body diagram's words.
    {"sample-12.3-two-mass-pulley", "T - F = m_A*ddot(x_A)", Verdict::incorrect, "missing_force",
     "a strand of string s at pA is missing (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "2*T + F = m_A*ddot(x_A)", Verdict::incorrect, "force_sign",
     "the force on A has the wrong sign or direction (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "-2*T = m_B*ddot(x_B)", Verdict::incorrect, "missing_force",
     "a strand of string s at pB is missing (LMB B (x))"},
    {"sample-12.3-two-mass-pulley", "-4*T = m_B*ddot(x_B)", Verdict::incorrect, "extra_force",
     "one force too many: a strand of string s at pB is counted once too often (LMB B (x))"},
    {"sample-12.3-two-mass-pulley", "3*T - F = m_A*ddot(x_A)", Verdict::incorrect, "extra_force",
     "one force too many: a strand of string s at pA is counted once too often (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "2*T - F = 0", Verdict::incorrect, "missing_inertia",
     "the mass times acceleration term is missing (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "2*T - F = -m_A*ddot(x_A)", Verdict::incorrect, "inertia_sign",
     "the mass times acceleration term has the wrong sign (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "2*ddot(x_B) = 3*ddot(x_A)", Verdict::incorrect, "value", ""},
    {"sample-12.3-two-mass-pulley", "2*T - F = m_A*ddot(x_B)", Verdict::incorrect, "wrong_acceleration",
     "the acceleration is B's, not A's (LMB A (x))"},
    {"sample-12.3-two-mass-pulley", "2*T - F = m_B*ddot(x_A)", Verdict::incorrect, "wrong_mass",
     "the mass is B's, not A's (LMB A (x))"},
    {"atwood-machine", "T - m_A*g = m_B*ddot(y_A)", Verdict::incorrect, "wrong_mass",
     "the mass is B's, not A's (LMB A (y))"},
    {"sample-12.3-two-mass-pulley", "T = 2*F*m_A/(9*m_A + 4*m_B)", Verdict::incorrect, "value", ""},
    {"sample-12.3-two-mass-pulley", "T = T", Verdict::incorrect, "trivial", ""},
    {"sample-12.3-two-mass-pulley", "2*T - F = m_A", Verdict::incorrect, "dimension",
     "the left side is a force and the right side a mass"},
    // Not linear in the unknowns: decided on the solution (T = F does not hold there).
    {"sample-12.3-two-mass-pulley", "T*ddot(x_A) = F*ddot(x_A)", Verdict::incorrect, "value", ""},
    {"sample-12.1-towing", "F = m_2*ddot(x_2)", Verdict::incorrect, "missing_force",
     "a strand of string chain at car2 is missing (LMB car2 (x))"},
    {"sample-12.1-towing", "F + T = m_2*ddot(x_2)", Verdict::incorrect, "force_sign",
     "a strand of string chain at car2 has the wrong sign or direction (LMB car2 (x))"},
    {"sample-12.1-towing", "T + F = m_1*ddot(x_1)", Verdict::incorrect, "extra_force",
     "the force on car2 does not act on what LMB car1 (x) balances"},
    {"atwood-machine", "T = m_A*ddot(y_A)", Verdict::incorrect, "missing_force",
     "the weight of A is missing (LMB A (y))"},
    {"atwood-machine", "T + m_A*g = m_A*ddot(y_A)", Verdict::incorrect, "force_sign",
     "the weight of A has the wrong sign or direction (LMB A (y))"},
    {"atwood-machine", "T - m_A*g = 0", Verdict::incorrect, "missing_inertia",
     "the mass times acceleration term is missing (LMB A (y))"},
    {"atwood-machine", "R_C = T", Verdict::incorrect, "missing_force",
     "a strand of string s at C is missing (LMB C (y))"},
    {"atwood-machine", "R_C = 3*T", Verdict::incorrect, "extra_force",
     "one force too many: a strand of string s at C is counted once too often (LMB C (y))"},
    {"atwood-machine", "ddot(y_A) = ddot(y_B)", Verdict::incorrect, "value", ""},
    {"sample-12.7-suitcase", "N_A + N_B = 0", Verdict::incorrect, "missing_force",
     "the weight of suitcase is missing (LMB suitcase (y))"},
    {"sample-12.7-suitcase", "N_A = m*g", Verdict::incorrect, "missing_force",
     "the force of the sliding contact at B is missing (LMB suitcase (y))"},
    {"sample-12.7-suitcase", "-mu*N_A = m*a_C", Verdict::incorrect, "missing_force",
     "the force of the sliding contact at B is missing (LMB suitcase (x))"},
    {"sample-12.7-suitcase", "mu*(N_A + N_B) = m*a_C", Verdict::incorrect, "", ""},
    {"sample-12.7-suitcase", "N_B*l/2 = N_A*l/2", Verdict::incorrect, "value", ""},
    {"sample-12.7-suitcase", "N_A + N_B = m", Verdict::incorrect, "dimension",
     "the left side is a force and the right side a mass"},
    {"sample-12.8-sign-board", "0 = a*m*(c - e)/2", Verdict::incorrect, "missing_force",
     "the force of the rod from H is missing (AMB board about G (axis OG))"},
    {"sample-12.8-sign-board", "T_HI*d*(c - e)/l = 0", Verdict::incorrect, "missing_inertia",
     "the rate of change of angular momentum is missing (AMB board about G (axis OG))"},
    {"sample-12.8-sign-board", "T_HI*d = m*a*l", Verdict::incorrect, "value", ""},
    {"rotation-atwood-massive-pulley", "R*T_1 = M*R^2*ddot(phi)/2", Verdict::incorrect, "missing_force",
     "a strand of string s_2 at E is missing (AMB P about its center of mass (z))"},
    {"rotation-atwood-massive-pulley", "R*(T_1 + T_2) = M*R^2*ddot(phi)/2", Verdict::incorrect, "force_sign",
     "a strand of string s_2 at E has the wrong sign or direction (AMB P about its center of mass (z))"},
    {"rotation-atwood-massive-pulley", "R*(T_1 - T_2) = 0", Verdict::incorrect, "missing_inertia",
     "the rate of change of angular momentum is missing (AMB P about its center of mass (z))"},
    {"rotation-atwood-massive-pulley", "T_1 = m_1*ddot(y_1)", Verdict::incorrect, "missing_force",
     "the weight of block_1 is missing (LMB block_1 (y))"},
    // Issue "verdicts": angles, roots, every balance of the model, equations not linear in
    // the unknowns. The incline (its notes): along the incline T - m_A g sin(theta) = m_A
    // ddot(s), across it N_A = m_A g cos(theta); the derivation balances A along x and y, so
    // these are cos and sin times those (sin^2 + cos^2 = 1 makes them so); T - N_A tan(theta)
    // = m_A ddot(s) is the x balance over cos(theta).
    {"incline-and-hanging-block", "T - g*m_A*sin(theta) = m_A*ddot(s)", Verdict::correct, "",
     "it follows from LMB A (x) and LMB A (y)"},
    {"incline-and-hanging-block", "N_A = m_A*g*cos(theta)", Verdict::correct, "",
     "it follows from LMB A (x) and LMB A (y)"},
    {"incline-and-hanging-block", "T - N_A*tan(theta) = m_A*ddot(s)", Verdict::correct, "", "it is LMB A (x)"},
    {"incline-and-hanging-block", "ddot(s) = g*(m_B - m_A*sin(theta))/(m_A + m_B)", Verdict::correct, "", ""},
    {"incline-and-hanging-block", "T*(1 - sin(theta)^2) = m_A*cos(theta)^2*(g*sin(theta) + ddot(s))", Verdict::correct,
     "", ""},
    {"incline-and-hanging-block", "T + g*m_A*sin(theta) = m_A*ddot(s)", Verdict::incorrect, "", ""},
    {"incline-and-hanging-block", "N_A = m_A*g*sin(theta)", Verdict::incorrect, "", ""},
    {"incline-and-hanging-block", "ddot(s) = g*(m_B - m_A*cos(theta))/(m_A + m_B)", Verdict::incorrect, "", ""},
    // The pendulum (its notes): along the tangent -m g sin(theta) = m l ddot(theta).
    {"rotation-pendulum", "l*ddot(theta) + g*sin(theta) = 0", Verdict::correct, "", ""},
    {"rotation-pendulum", "T = m*g*cos(theta) + m*l*dot(theta)^2", Verdict::correct, "", ""},
    {"rotation-pendulum", "l*ddot(theta) - g*sin(theta) = 0", Verdict::incorrect, "", ""},
    {"rotation-pendulum", "T = m*g*cos(theta) - m*l*dot(theta)^2", Verdict::incorrect, "", ""},
    // `derive:` chooses what the derivation prints, not what is true: the towing cars' system
    // balance is derived, each car's own balance still holds (car 1: T = m_1 a).
    {"sample-12.1-towing-system", "T = m_1*ddot(x_1)", Verdict::correct, "", "it is LMB car1 (x)"},
    {"sample-12.1-towing-system", "F - T = m_2*ddot(x_2)", Verdict::correct, "", "it is LMB car2 (x)"},
    {"sample-12.1-towing-system", "T = m_1*F/(m_1 + m_2)", Verdict::correct, "", ""},
    {"sample-12.1-towing-system", "T = m_2*ddot(x_1)", Verdict::incorrect, "", ""},
    // Sample 12.8 derives only the moment about the axis OG; the board's x balance (its notes:
    // the ball and socket's, the hinge's and the rod's x components make m a) still holds.
    {"sample-12.8-sign-board", "G_x + O_x + T_HI*d/l = a*m", Verdict::correct, "", "it is LMB board (x)"},
    {"sample-12.8-sign-board", "G_x + O_x + T_HI*d/sqrt(b^2 + d^2 + e^2) = a*m", Verdict::correct, "",
     "it is LMB board (x)"},
    {"sample-12.8-sign-board", "G_x + O_x - T_HI*d/l = a*m", Verdict::incorrect, "force_sign",
     "the force of the rod from H has the wrong sign or direction (LMB board (x))"},
    // Not linear in the unknowns, true on the solution (the Atwood machine's A: T - m_A g =
    // m_A ddot(y_A)); a ratio of the accelerations (sample 12.3: 3 ddot(x_B) = 2 ddot(x_A)).
    {"atwood-machine", "m_A = T/(g + ddot(y_A))", Verdict::correct, "", ""},
    {"sample-12.3-two-mass-pulley", "ddot(x_A)/ddot(x_B) = 3/2", Verdict::correct, "", ""},
    {"sample-12.3-two-mass-pulley", "ddot(x_A)/ddot(x_B) = 2/3", Verdict::incorrect, "value", ""},
    // (A tension is not negative: sqrt(T^2) = T holds whatever T is, saying nothing.)
    {"sample-12.3-two-mass-pulley", "sqrt(T^2) = T", Verdict::incorrect, "trivial", ""},
    {"sample-12.3-two-mass-pulley", "sqrt(T^2) = -T", Verdict::incorrect, "value", ""},
    // An acceleration has either sign: sqrt(a^2) = a says something, and it is false.
    {"sample-12.3-two-mass-pulley", "sqrt(ddot(x_B)^2) = ddot(x_B)", Verdict::incorrect, "value", ""},
    // Sample 12.7: N_A < 0 (the suitcase tips) at some parameters near the given ones, which
    // the model's N_A >= 0 leaves out: as T above, whatever the states drawn.
    {"sample-12.7-suitcase", "sqrt(N_A^2) = N_A", Verdict::incorrect, "trivial", ""},
    {"sample-12.7-suitcase", "N_A*abs(N_A) = N_A^2", Verdict::incorrect, "trivial", ""},
    {"sample-12.7-suitcase", "N_A = sqrt((m*g*(1/2 - mu*h/l))^2)", Verdict::correct, "", ""},
    {"sample-12.7-suitcase", "N_A = -sqrt((m*g*(1/2 - mu*h/l))^2)", Verdict::incorrect, "value", ""},
    {"sample-12.3-two-mass-pulley", "log(F/T) = 0", Verdict::incorrect, "value", ""},
    {"sample-12.3-two-mass-pulley", "sin(ddot(x_A)/ddot(x_B)) = 0", Verdict::incorrect, "value", ""},
    {"sample-12.3-two-mass-pulley", "sin(ddot(x_A)/ddot(x_B)) = sin(3/2)", Verdict::correct, "", ""},
    // A cube root of a negative acceleration has no real value: undecided, not a crash.
    {"sample-12.3-two-mass-pulley", "(ddot(x_A)^3)^(1/3) = ddot(x_B)", Verdict::undecided, "evaluation", ""},
    // sin^2 + cos^2 = 1 says nothing about the problem.
    {"incline-and-hanging-block", "sin(theta)^2 + cos(theta)^2 = 1", Verdict::incorrect, "trivial", ""},
    // A length sum's constant may be a number (docs/checking.md).
    {"sample-12.3-two-mass-pulley", "3*x_B - 2*x_A = 5", Verdict::correct, "",
     "it is the length of string s kept constant"},
    {"sample-12.3-two-mass-pulley", "3*x_B - 2*x_A = 5 + const", Verdict::correct, "",
     "it is the length of string s kept constant"},
    {"sample-12.3-two-mass-pulley", "2*x_B - 2*x_A = 5", Verdict::incorrect, "length_sum", ""},
    // Cannot be read.
    {"sample-12.3-two-mass-pulley", "2*T - F", Verdict::invalid, "not_an_equation", ""},
    {"sample-12.3-two-mass-pulley", "2*T = F = 3", Verdict::invalid, "not_an_equation",
     "write one '=' between the two sides (found 2)"},
    {"sample-12.3-two-mass-pulley", "2*T >= F", Verdict::invalid, "not_an_equation", ""},
    {"sample-12.3-two-mass-pulley", "2*T - Q = m_A*ddot(x_A)", Verdict::invalid, "syntax", ""},
    {"sample-12.3-two-mass-pulley", " = m_A*ddot(x_A)", Verdict::invalid, "not_an_equation", "the left side is empty"},
};

}  // namespace

TEST_CASE("Equations: each step's verdict and finding, from the examples' hand derivations", "[check][equation]") {
  int correct = 0, incorrect = 0;
  for (const EquationStep& s : steps) {
    INFO(s.example << ": " << s.equation);
    const CheckResult r = checker_for(s.example).check_equation(s.equation);
    CHECK(r.verdict == s.verdict);
    if (s.verdict == Verdict::correct) {
      ++correct;
      CHECK(r.findings.empty());
      // (An equation not linear in the unknowns is no combination of the model's.)
      CHECK(r.follows_from.empty() == (r.summary.find("not linear") != std::string::npos));
    } else if (*s.code) {
      REQUIRE(!r.findings.empty());
      CHECK(r.findings.front().code == s.code);
    }
    if (s.verdict == Verdict::incorrect) ++incorrect;
    if (*s.summary) CHECK(r.summary == s.summary);
    CHECK(r.score == (s.verdict == Verdict::correct ? 1.0 : 0.0));
  }
  CHECK(correct >= 30);
  CHECK(incorrect >= 30);
}

TEST_CASE("Equations: one equation typed two ways is one verdict, its sides kept as typed", "[check][equation]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/incline-and-hanging-block.yaml", test::rules());
  const Checker checker(*a);
  const CheckResult first = checker.check_equation("T - g*m_A*sin(theta) = m_A*ddot(s)");
  const CheckResult again = checker.check_equation("T - m_A*g*sin(theta) = ddot(s)*m_A");
  const CheckResult turned = checker.check_equation("m_A*ddot(s) = T - g*m_A*sin(theta)");
  for (const auto* r : {&first, &again, &turned}) {
    CHECK(r->verdict == Verdict::correct);
    CHECK(r->follows_from == std::vector<std::string>{"LMB A (x)", "LMB A (y)"});
  }
  CHECK(first.echo_text == "T - g*m_A*sin(theta) = m_A*ddot(s)");
  CHECK(again.echo_text == first.echo_text);
  CHECK(turned.echo_text == "m_A*ddot(s) = T - g*m_A*sin(theta)");
  // The sign of the weight's component turned, after the right one: incorrect.
  const CheckResult wrong = checker.check_equation("T + g*m_A*sin(theta) = m_A*ddot(s)");
  CHECK(wrong.verdict == Verdict::incorrect);
  CHECK(wrong.echo_text == "T + g*m_A*sin(theta) = m_A*ddot(s)");
}

TEST_CASE("Equations: feedback never shows the correct equation", "[check][equation]") {
  // No finding writes an equation or a balance's terms: only the names of the forces and of
  // the balance. Each incorrect step's messages are searched for '=' and for the unknowns.
  for (const EquationStep& s : steps) {
    if (s.verdict != Verdict::incorrect) continue;
    INFO(s.example << ": " << s.equation);
    const CheckResult r = checker_for(s.example).check_equation(s.equation);
    for (const auto& f : r.findings) {
      if (f.code == "trivial") continue;  // "it reads 0 = 0": the student's own equation
      CHECK(f.message.find('=') == std::string::npos);
      CHECK(f.message.find("ddot") == std::string::npos);
      CHECK(f.message.find('*') == std::string::npos);
    }
  }
}

TEST_CASE("Equations: a correct combination names the fewest equations it follows from", "[check][equation]") {
  const CheckResult r = checker_for("sample-12.3-two-mass-pulley").check_equation("T = 2*F*m_B/(9*m_A + 4*m_B)");
  CHECK(r.identified_as.empty());
  CHECK(r.follows_from == std::vector<std::string>{"LMB A (x)", "LMB B (x)", "string s: acceleration"});
  const CheckResult one = checker_for("sample-12.3-two-mass-pulley").check_equation("-3*T = m_B*ddot(x_B)");
  CHECK(one.identified_as == std::vector<std::string>{"LMB B (x)"});
  CHECK(one.follows_from == std::vector<std::string>{"LMB B (x)"});
}

TEST_CASE("Equations: in a batch, a line with an equation, and the JSON names what it follows from",
          "[check][equation][batch]") {
  std::istringstream in(R"J({"id": "s1", "equation": "2*T - F = m_A*ddot(x_A)"}
{"id": "s2", "equation": "T - F = m_A*ddot(x_A)"}
{"id": "s3", "unknown": "T", "answer": "2*m_B*F/(9*m_A + 4*m_B)"}
{"id": "s4", "equation": "2*T = F", "answer": "1"}
)J");
  std::ostringstream out;
  const auto s = check_batch(checker_for("sample-12.3-two-mass-pulley"), in, out);
  CHECK(s.lines == 4);
  CHECK(s.correct == 2);
  CHECK(s.invalid == 1);
  const std::string text = out.str();
  CHECK(
      text.find(
          R"J("id":"s1","unknown":"","answer":"2*T - F = m_A*ddot(x_A)","verdict":"correct","score":1.0,"summary":"it is LMB A (x)")J") !=
      std::string::npos);
  CHECK(text.find(R"J("identified_as":["LMB A (x)"],"follows_from":["LMB A (x)"]})J") != std::string::npos);
  CHECK(text.find(R"J("summary":"a strand of string s at pA is missing (LMB A (x))")J") != std::string::npos);
  CHECK(text.find(R"J(a line has an \"equation\" or an \"answer\", not both)J") != std::string::npos);
  // An answer's line keeps its fields: no identified_as.
  const auto s3 = text.find(R"J("id":"s3")J");
  CHECK(text.find("identified_as", s3) > text.find('\n', s3));
}
TEST_CASE("Equations: a correct equation says which equations it combines, and whether the student added them",
          "[check][equation]") {
  // Sample 12.1 (its notes): car 1, T = m_1 a_1; car 2, F - T = m_2 a_2. Their sum, F = m_1 a_1 +
  // m_2 a_2, adds them (coefficients 1 and 1); T = m_1 F/(m_1 + m_2) eliminates the
  // accelerations (coefficients in the masses).
  const Checker& towing = checker_for("sample-12.1-towing");
  const CheckResult sum = towing.check_equation("F = m_1*ddot(x_1) + m_2*ddot(x_2)");
  REQUIRE(sum.verdict == Verdict::correct);
  REQUIRE(sum.combination.size() == 2);
  CHECK(sum.combination[0].label == "LMB car1 (x)");
  CHECK(sum.combination[1].label == "LMB car2 (x)");
  CHECK(sum.combination[0].plain);
  CHECK(sum.combination[1].plain);
  const CheckResult derived = towing.check_equation("T = m_1*F/(m_1 + m_2)");
  REQUIRE(derived.verdict == Verdict::correct);
  REQUIRE(derived.combination.size() == 3);
  CHECK(std::none_of(derived.combination.begin(), derived.combination.end(),
                     [](const CheckResult::Part& p) { return p.plain; }));
  // One of the model's own, up to a factor: itself, plain.
  const CheckResult own = towing.check_equation("2*T = 2*m_1*ddot(x_1)");
  REQUIRE(own.combination.size() == 1);
  CHECK(own.combination[0].plain);
}

// Checking a free body diagram the student drew (issue "check the student's work", part 2).
// Every expectation is from the examples' hand derivations (their notes): which forces act on
// each body, at which point, along which line and which way; never from tackle's own output.
#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <memory>

#include "grade/batch.hpp"
#include "check/fbd.hpp"
#include "check/steps.hpp"

#include <nlohmann/json.hpp>
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {

const Analysis& analysis_for(const std::string& example) {
  static std::map<std::string, std::unique_ptr<const Analysis>> made;
  auto it = made.find(example);
  if (it == made.end())
    it = made.emplace(example, analyze_file(TACKLE_SOURCE_DIR "/examples/" + example + ".yaml", test::rules())).first;
  return *it->second;
}

FbdGrade grade(const std::string& example, const std::string& yaml, const FbdRubric& rubric = {}) {
  const Model& m = analysis_for(example).model;
  const StudentFbd fbd = read_fbd_file(yaml, "fbd.yaml", m);
  std::vector<Diagnostic> problems;
  FbdGrade g = check_fbd(m, fbd, rubric, problems);
  CHECK(problems.empty());
  return g;
}

struct FbdCase {
  const char* example;
  const char* fbd;
  Verdict verdict;
  const char* code;     // the first finding's (correct: empty)
  const char* summary;  // word for word
  double score, max_score;
};

// By hand.
// Sample 12.3 (x to the right, C at 0, A at x = -1 left of it, B at x = 1): A is pulled left by
// F and by two strands of the string toward C (right); B by three strands toward C (left).
// The Atwood machine (y up): A and B each hang from a strand (up) and weigh (down); the pulley
// block C is held by the ceiling (R_C up) and pulled down by the two strands.
// The incline (theta = 30 deg, x right, y up): A has the incline's normal force (at 120 deg),
// the string's pull up the incline toward P (at 30 deg) and its weight (down); B the string
// (up) and its weight. The system of A and B: the string runs over the fixed pulley P, so both
// strands are external.
// The suitcase slides right: each foot has N up and friction mu N left.
// The wheel: the axle couple -M_0 (clockwise), the ground's N_C (up) and friction F_C along x,
// of either sign (static friction; the notes find it forward), the weight at the center.
// Two blocks joined by a pin at H: the pin's force on B, of unknown direction; B's roller
// (up) and weight. For the system of A and B the pin is internal.
// Towing: the chain pulls car 1 toward car 2 (+x); F acts on car 2.
// Sample 12.8: the ball and socket at O and the hinge at G, forces of unknown direction; the
// rod from H to I, along H -> I = (d, b, e) = (3, 1.5, 0.5) m, tension or compression; the
// weight along -z.
// The ladder: the floor pushes up at A, the wall pushes left (-x) at B; the weight at G. A and
// B are the ends, off G: where N_A and N_B act sets their moments about G; the weight's is
// nothing wherever along its line through G it is drawn.
// The massive pulley P (pinned at its center O, which is its center of mass): the pin's force
// (unknown direction) at O, the weight M g down at O, the strand s_1 down at L (the left rim,
// block 1 hangs below it), the strand s_2 down at E (the right rim). A second arrow down at O
// named like the weight, or both said to be weights, is the weight again, not the pin's force.
// The Atwood machine's pulley block C is massless: R_C up and the two strands down, no weight.
// The sense of a force the sketch knows (issue 41, item 6). The block on the elastic cord: at
// the sketch y = -1 and t = 0, the support S is at a cos 0 = 0.02 m, so the cord is 1.02 m long,
// 0.52 m past its rest length: taut, it pulls the block up with k 0.52 = 52 N. Drawn down, it
// points the other way (the weight, said to be one, is down). The springs in series at the
// sketch (x = 1.2, x_S = 0.6): sp2 from the wall at 0 to S is 0.6 m long, 0.1 m past l_2, and
// pulls S toward the wall (-x, 30 N); sp1 from S to A is 0.6 m long, 0.1 m past l_1, and pulls
// S toward A (+x, 10 N). Both drawn +x: one is sp1, the other is sp2 the wrong way.
// Figure 12.5b (A at x = -2, B at -1, the pulley C at 0): the load F on B acts at B, the strand
// C-B pulls B toward C (+x); the load drawn at A is at the wrong point.
// The box K in the truck T (same_motion, no force asked for): the box accelerates with the
// truck, a = F/(M + m) = 2 m/s^2, so the bed pushes it forward with m a = 600 N, and it pushes
// the truck back with 600 N (F - 600 = M a = 3000 N): K's diagram is that one force (its sense
// an unknown's, either), T's is F and the box's force, the system's is F alone.
const std::vector<FbdCase> cases{
    {"sample-12.3-two-mass-pulley",
     "body: B\nforces:\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, "
     "at: pB, direction: [-1]}\n",
     Verdict::correct, "", "every force on B is drawn, each along its line and at its point", 3, 3},
    {"sample-12.3-two-mass-pulley",
     "body: B\nforces:\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [-1]}\n",
     Verdict::incorrect, "missing_force", "a strand of string s at pB is missing", 2, 3},
    {"sample-12.3-two-mass-pulley",
     "body: B\nforces:\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, "
     "at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [-1]}\n",
     Verdict::incorrect, "extra_force", "your T counts a strand of string s at pB once too often", 2, 3},
    {"sample-12.3-two-mass-pulley",
     "body: A\nforces:\n  - {name: F, direction: [-1]}\n  - {name: T, at: pA, direction: [1]}\n  - {name: T, at: pA, "
     "direction: [1]}\n",
     Verdict::correct, "", "every force on A is drawn, each along its line and at its point", 3, 3},
    {"sample-12.3-two-mass-pulley",
     "body: A\nforces:\n  - {name: F, direction: [1]}\n  - {name: T, at: pA, direction: [1]}\n  - {name: T, at: pA, "
     "direction: [1]}\n",
     Verdict::incorrect, "force_direction", "your F stands for the force on A, which points the other way", 2.5, 3},
    {"sample-12.3-two-mass-pulley",
     "body: A\nforces:\n  - {name: F, direction: [-1]}\n  - {name: T, at: pA, direction: [1]}\n  - {name: T, at: pA, "
     "direction: [1]}\n  - {name: W, at: A, direction: [-1]}\n",
     Verdict::incorrect, "extra_force", "your W is not one of the forces on A at A", 2, 3},
    {"atwood-machine",
     "body: C\nforces:\n  - {name: R, direction: [1]}\n  - {name: T, direction: [-1]}\n  - {name: T, direction: "
     "[-1]}\n",
     Verdict::correct, "", "every force on C is drawn, each along its line and at its point", 3, 3},
    {"atwood-machine", "body: A\nforces:\n  - {name: T, direction: [-1]}\n  - {name: W, direction: [-1]}\n",
     Verdict::incorrect, "force_direction", "your T stands for a strand of string s at A, which points the other way",
     1.5, 2},
    {"atwood-machine", "body: A\nforces:\n  - {name: T, direction: [1]}\n", Verdict::incorrect, "missing_force",
     "the weight of A is missing", 1, 2},
    {"incline-and-hanging-block",
     "body: A\nforces:\n  - {name: N, at: A, angle: 120}\n  - {name: T, at: A, angle: 30}\n  - {name: W, at: A, "
     "direction: [0, -1]}\n",
     Verdict::correct, "", "every force on A is drawn, each along its line and at its point", 3, 3},
    {"incline-and-hanging-block",
     "body: A\nforces:\n  - {name: N, at: A, angle: 90}\n  - {name: T, at: A, angle: 30}\n  - {name: W, at: A, "
     "direction: [0, -1]}\n",
     Verdict::incorrect, "force_direction", "your N stands for the force of the roller at A, but is not along its line",
     2.5, 3},
    {"incline-and-hanging-block",
     "body: A\nforces:\n  - {name: N, at: A, angle: 121.5}\n  - {name: T, at: A, direction: [0.866, 0.5]}\n  - {name: "
     "W, at: A, angle: -90}\n",
     Verdict::correct, "", "every force on A is drawn, each along its line and at its point", 3, 3},
    {"incline-and-hanging-block",
     "body: A\nforces:\n  - {name: N, at: A, angle: 120}\n  - {name: T, at: A, direction: any}\n  - {name: W, at: A, "
     "direction: [0, -1]}\n",
     Verdict::incorrect, "force_direction",
     "your T stands for a strand of string s at A, whose line is known: draw it along that line", 2.5, 3},
    {"incline-and-hanging-block",
     "bodies: [A, B]\nforces:\n  - {name: N, at: A, angle: 120}\n  - {name: T, at: A, angle: 30}\n  - {name: W_A, at: "
     "A, direction: [0, -1]}\n  - {name: T, at: B, direction: [0, 1]}\n  - {name: W_B, at: B, direction: [0, -1]}\n",
     Verdict::correct, "", "every force on the system of A and B is drawn, each along its line and at its point", 5, 5},
    {"sample-12.7-suitcase",
     "body: suitcase\nforces:\n  - {name: W, at: suitcase, direction: [0, -1]}\n  - {name: N_A, at: A, direction: [0, "
     "1]}\n  - {name: N_B, at: B, direction: [0, 1]}\n  - {name: F_A, at: A, direction: [1, 0]}\n  - {name: F_B, at: "
     "B, direction: [-1, 0]}\n",
     Verdict::incorrect, "force_direction",
     "your F_A stands for the force of the sliding contact at A (its mu*N_A part), which points the other way", 4.5, 5},
    {"sample-12.7-suitcase",
     "body: suitcase\nforces:\n  - {name: W, at: suitcase, direction: [0, -1]}\n  - {name: N_A, at: A, direction: [0, "
     "1]}\n  - {name: N_B, at: B, direction: [0, 1]}\n  - {name: F_A, at: A, direction: [-1, 0]}\n",
     Verdict::incorrect, "missing_force", "the force of the sliding contact at B (its mu*N_B part) is missing", 4, 5},
    {"rotation-wheel-driven-by-a-couple",
     "body: wheel\nforces:\n  - {name: W, at: wheel, direction: [0, -1]}\n  - {name: N, at: C, direction: [0, 1]}\n  - "
     "{name: F, at: C, direction: [-1, 0]}\ncouples:\n  - {name: M, sense: clockwise}\n",
     Verdict::correct, "", "every force on wheel is drawn, each along its line and at its point", 4, 4},
    {"rotation-wheel-driven-by-a-couple",
     "body: wheel\nforces:\n  - {name: W, at: wheel, direction: [0, -1]}\n  - {name: N, at: C, direction: [0, 1]}\n  - "
     "{name: F, at: C, direction: [1, 0]}\ncouples:\n  - {name: M, sense: counterclockwise}\n",
     Verdict::incorrect, "force_direction", "your couple M stands for the couple on wheel, which turns the other way",
     3.5, 4},
    {"two-blocks-joined-by-a-pin",
     "body: B\nforces:\n  - {name: N, at: B, direction: [0, 1]}\n  - {name: W, at: B, direction: [0, -1]}\n  - {name: "
     "H, at: H, direction: any}\n",
     Verdict::correct, "", "every force on B is drawn, each along its line and at its point", 3, 3},
    {"two-blocks-joined-by-a-pin",
     "body: B\nforces:\n  - {name: N, at: B, direction: [0, 1]}\n  - {name: W, at: B, direction: [0, -1]}\n  - {name: "
     "H_x, at: H, direction: [1, 0]}\n  - {name: H_y, at: H, direction: [0, -1]}\n",
     Verdict::correct, "", "every force on B is drawn, each along its line and at its point", 3, 3},
    {"two-blocks-joined-by-a-pin",
     "bodies: [A, B]\nforces:\n  - {name: N_A, at: A, direction: [0, 1]}\n  - {name: N_B, at: B, direction: [0, 1]}\n  "
     "- {name: W_A, at: A, direction: [0, -1]}\n  - {name: W_B, at: B, direction: [0, -1]}\n  - {name: F, at: A, "
     "direction: [1, 0]}\n  - {name: H, at: H, direction: any}\n",
     Verdict::incorrect, "internal_force",
     "your H is the force of the pin joint at H, which is internal to the system of A and B (its forces on the "
     "system's bodies cancel)",
     4, 5},
    {"sample-12.1-towing", "body: car1\nforces:\n  - {name: T, at: car1, direction: [1]}\n", Verdict::correct, "",
     "every force on car1 is drawn, each along its line and at its point", 1, 1},
    {"sample-12.1-towing",
     "body: car1\nforces:\n  - {name: T, at: car1, direction: [1]}\n  - {name: F, at: car2, direction: [1]}\n",
     Verdict::incorrect, "other_body", "your F is the force on car2, which acts on car2, not on car1", 0, 1},
    {"sample-12.8-sign-board",
     "body: board\nforces:\n  - {name: W, at: board, direction: [0, 0, -1]}\n  - {name: O, at: O, direction: any}\n  - "
     "{name: G, at: G, direction: any}\n  - {name: T, at: H, direction: [-3, -1.5, -0.5]}\n",
     Verdict::correct, "", "every force on board is drawn, each along its line and at its point", 4, 4},
    {"sample-12.8-sign-board",
     "body: board\nforces:\n  - {name: W, at: board, direction: [0, 0, -1]}\n  - {name: O, at: O, direction: any}\n  - "
     "{name: G, at: G, direction: any}\n  - {name: T, at: H, direction: [1, 0, 0]}\n",
     Verdict::incorrect, "force_direction", "your T stands for the force of the rod from H, but is not along its line",
     3.5, 4},
    {"rotation-ladder-sliding-on-smooth-wall-and-floor",
     "body: ladder\nforces:\n  - {name: N_A, at: A, direction: [0, 1]}\n  - {name: N_B, at: B, direction: [-1, 0]}\n  "
     "- {name: W, at: ladder, direction: [0, -1]}\n",
     Verdict::correct, "", "every force on ladder is drawn, each along its line and at its point", 3, 3},
    {"rotation-ladder-sliding-on-smooth-wall-and-floor",
     "body: ladder\nforces:\n  - {name: N_A, at: A, direction: [0, 1]}\n  - {name: N_B, at: A, direction: [-1, 0]}\n  "
     "- {name: W, at: ladder, direction: [0, -1]}\n",
     Verdict::incorrect, "wrong_point", "your N_B stands for the force of the roller at B, which does not act at A",
     2.5, 3},
    {"rotation-ladder-sliding-on-smooth-wall-and-floor",
     "body: ladder\nforces:\n  - {name: N_A, direction: [0, 1]}\n  - {name: N_B, at: B, direction: [-1, 0]}\n  - "
     "{name: W, at: ladder, direction: [0, -1]}\n",
     Verdict::incorrect, "wrong_point",
     "your N_A stands for the force of the roller at A, but is drawn at no point (where it acts sets its moment)", 2.5,
     3},
    {"rotation-ladder-sliding-on-smooth-wall-and-floor",
     "body: ladder\nforces:\n  - {name: N_A, at: A, direction: [0, 1]}\n  - {name: N_B, at: B, direction: [-1, 0]}\n  "
     "- {name: W, direction: [0, -1]}\n",
     Verdict::correct, "", "every force on ladder is drawn, each along its line and at its point", 3, 3},
    {"rotation-atwood-massive-pulley",
     "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n  - "
     "{name: W, at: P, direction: [0, -1]}\n"
     "  - {name: W, at: P, direction: [0, -1]}\n",
     Verdict::incorrect, "missing_force", "the force of the pin at O is missing", 2, 4},
    {"rotation-atwood-massive-pulley",
     "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n  - "
     "{name: W, at: P, direction: [0, -1], kind: weight}\n"
     "  - {name: R, at: O, direction: [0, -1], kind: weight}\n",
     Verdict::incorrect, "missing_force", "the force of the pin at O is missing", 2, 4},
    {"rotation-atwood-massive-pulley",
     "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n  - "
     "{name: W, at: P, direction: [0, -1]}\n"
     "  - {name: R, at: O, direction: [0, -1]}\n",
     Verdict::correct, "", "every force on P is drawn, each along its line and at its point", 4, 4},
    {"atwood-machine",
     "body: C\nforces:\n  - {name: R, direction: [1], kind: weight}\n  - {name: T, direction: [-1]}\n  - {name: T, "
     "direction: [-1]}\n",
     Verdict::incorrect, "missing_force", "the force of the fixed body C is missing", 1, 3},
    {"cord-driven-support-band",
     "body: block\nforces:\n  - {name: C, at: block, direction: [-1]}\n  - {name: W, at: block, direction: [-1], kind: "
     "weight}\n",
     Verdict::incorrect, "force_direction",
     "your C stands for the force of elastic cord c at block, which points the other way", 1.5, 2},
    {"cord-driven-support-band",
     "body: block\nforces:\n  - {name: C, at: block, direction: [1]}\n  - {name: W, at: block, direction: [-1]}\n",
     Verdict::correct, "", "every force on block is drawn, each along its line and at its point", 2, 2},
    {"springs-in-series-massless-joint",
     "body: S\nforces:\n  - {name: F, at: S, direction: [1]}\n  - {name: F, at: S, direction: [1]}\n",
     Verdict::incorrect, "force_direction",
     "your F stands for the force of spring sp2 at S, which points the other way", 1.5, 2},
    {"springs-in-series-massless-joint",
     "body: S\nforces:\n  - {name: F_2, at: S, direction: [-1]}\n  - {name: F_1, at: S, direction: [1]}\n",
     Verdict::correct, "", "every force on S is drawn, each along its line and at its point", 2, 2},
    {"figure-12.5b-redirect",
     "body: B\nforces:\n  - {name: P, at: A, direction: [-1]}\n  - {name: T, at: B, direction: [1]}\n",
     Verdict::incorrect, "wrong_point", "your P stands for the force on B, which does not act at A", 1.5, 2},
    {"figure-12.5b-redirect",
     "body: B\nforces:\n  - {name: P, direction: [-1]}\n  - {name: T, at: B, direction: [1]}\n", Verdict::correct, "",
     "every force on B is drawn, each along its line and at its point", 2, 2},
    {"box-in-a-truck-system", "body: K\nforces:\n  - {name: f, at: K, direction: [1]}\n", Verdict::correct, "",
     "every force on K is drawn, each along its line and at its point", 1, 1},
    {"box-in-a-truck-system", "body: T\nforces:\n  - {name: F, at: T, direction: [1]}\n", Verdict::incorrect,
     "missing_force", "the force of K on T (same motion carried) is missing", 1, 2},
    {"box-in-a-truck-system",
     "body: T\nforces:\n  - {name: F, at: T, direction: [1]}\n  - {name: f, at: T, direction: [1]}\n", Verdict::correct,
     "", "every force on T is drawn, each along its line and at its point", 2, 2},
    {"box-in-a-truck-system", "bodies: [T, K]\nforces:\n  - {name: F, at: T, direction: [1]}\n", Verdict::correct, "",
     "every force on the system of T and K is drawn, each along its line and at its point", 1, 1},
};

}  // namespace

TEST_CASE("FBD: each drawing's verdict, finding and score, from the examples' hand derivations", "[check][fbd]") {
  for (const FbdCase& c : cases) {
    INFO(c.example << "\n" << c.fbd);
    const FbdGrade g = grade(c.example, c.fbd);
    CHECK(verdict_name(g.verdict) == verdict_name(c.verdict));
    CHECK(g.summary == c.summary);
    if (c.verdict == Verdict::correct)
      CHECK(g.findings.empty());
    else if (!g.findings.empty())
      CHECK(g.findings.front().code == c.code);
    CHECK(g.score == Approx(c.score));
    CHECK(g.max_score == Approx(c.max_score));
  }
}

TEST_CASE("FBD: a weight drawn twice is the weight twice, never another force", "[check][fbd]") {
  // By hand (see the cases): the pin at O is missing, and the second weight is one too many,
  // whether it is named like the first or both are said to be weights. (One said to be a weight
  // and one down at O said to be nothing: that one may be the pin's force, drawn down.)
  const char* const twice =
      "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n"
      "  - {name: W, at: P, direction: [0, -1]}\n  - {name: W, at: P, direction: [0, -1]}\n";
  CHECK(fbd_text(grade("rotation-atwood-massive-pulley", twice)) ==
        "free body diagram of P: incorrect: the force of the pin at O is missing\n"
        "  the force of the pin at O (O_x, O_y): missing\n"
        "  a strand of string s_1 at L (T_1): drawn as your T_1\n"
        "  a strand of string s_2 at E (T_2): drawn as your T_2\n"
        "  the weight of P (M*g): drawn as your W\n"
        "  extra: your W counts the weight of P once too often\n"
        "score: 2 of 4\n");
  const FbdGrade said =
      grade("rotation-atwood-massive-pulley",
            "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n"
            "  - {name: W, at: P, direction: [0, -1], kind: weight}\n  - {name: R, at: O, direction: [0, -1], kind: "
            "weight}\n");
  REQUIRE(said.extras.size() == 1);
  CHECK(said.extras[0].message == "your R counts the weight of P once too often");
  // Said to be a weight where the body has none (the massless pulley block C): not its R_C.
  const FbdGrade none = grade("atwood-machine", "body: C\nforces:\n  - {name: R, direction: [1], kind: weight}\n");
  REQUIRE(none.extras.size() == 1);
  CHECK(none.extras[0].message == "your R is not one of the forces on C");
}

TEST_CASE("FBD: a force of unknown direction drawn as its components, at one point", "[check][fbd]") {
  // By hand (see the cases): the massive pulley's pin force drawn as its components at O, O_x
  // along x and O_y up (either sense), is right. A second arrow down at P beside them is the
  // weight again (drawn like W, the second of the two the one too many), not a third component.
  const std::string drawn =
      "body: P\nforces:\n  - {name: T_1, at: L, direction: [0, -1]}\n  - {name: T_2, at: E, direction: [0, -1]}\n"
      "  - {name: W, at: P, direction: [0, -1]}\n  - {name: O_x, at: O, direction: [1, 0]}\n  - {name: O_y, at: O, "
      "direction: [0, 1]}\n";
  const FbdGrade right = grade("rotation-atwood-massive-pulley", drawn);
  CHECK(right.summary == "every force on P is drawn, each along its line and at its point");
  CHECK(right.score == Approx(4));
  CHECK(fbd_text(grade("rotation-atwood-massive-pulley", drawn + "  - {name: W2, at: P, direction: [0, -1]}\n")) ==
        "free body diagram of P: incorrect: your W2 counts the weight of P once too often\n"
        "  the force of the pin at O (O_x, O_y): drawn as your O_x, O_y\n"
        "  a strand of string s_1 at L (T_1): drawn as your T_1\n"
        "  a strand of string s_2 at E (T_2): drawn as your T_2\n"
        "  the weight of P (M*g): drawn as your W\n"
        "  extra: your W2 counts the weight of P once too often\n"
        "score: 3 of 4\n");
  // The two blocks with the pin H put at A's center (by hand, A's forces: the roller's N_A up,
  // the weight down, the pull F along +x, all at A, and the pin's force of unknown direction at
  // H, the same point). Five arrows: up, down, +x and down at A, and one 4 degrees below +x at
  // H. Two of those at A along independent lines are the pin's components, the one at H is the
  // pull (within 5 degrees of its line, at its point): every force drawn, nothing extra.
  const auto pinned = test::run_text(test::example_with(
      "two-blocks-joined-by-a-pin.yaml", "H: {on: A, offset: [\"-b\", 0]}", "H: {on: A, offset: [0, 0]}"));
  std::vector<Diagnostic> problems;
  const FbdGrade at_a = check_fbd(
      pinned->model,
      read_fbd_file(
          "body: A\nforces:\n  - {name: W, at: A, direction: [0, -1]}\n  - {name: N, at: A, direction: [0, 1]}\n"
          "  - {name: P, at: A, direction: [1, 0]}\n  - {name: Q, at: H, direction: [1, -0.07]}\n"
          "  - {name: R, at: A, direction: [0, -1]}\n",
          "fbd.yaml", pinned->model),
      FbdRubric{}, problems);
  CHECK(at_a.summary == "every force on A is drawn, each along its line and at its point");
  CHECK(at_a.score == Approx(4));
  CHECK(at_a.extras.empty());
}

TEST_CASE("FBD: a force that is nothing in the sketch earns its share, drawn at its point or left out",
          "[check][fbd]") {
  // The block on the incline with the spring at its rest length (by hand: its length D - x =
  // 1.5 - 1 = 0.5 m is l_0): the spring's force is nothing there, the weight points down the
  // axis. Left out or drawn at A along the axis: every point; drawn at the anchor Q: half.
  const auto a =
      test::run_text(test::example_with("incline-1d-block-on-spring.yaml", "layout: {x: 0.9}", "layout: {x: 1}"));
  auto graded = [&](const std::string& yaml) {
    std::vector<Diagnostic> problems;
    return check_fbd(a->model, read_fbd_file(yaml, "fbd.yaml", a->model), FbdRubric{}, problems);
  };
  CHECK(fbd_text(graded("body: A\nforces:\n  - {name: W, at: A, direction: [-1]}\n")) ==
        "free body diagram of A: correct: every force on A is drawn, each along its line and at its point\n"
        "  the force of spring sp at A (-k*(l_0 + x - D)): nothing at this position (not needed)\n"
        "  the weight of A (g*m*sin(theta)): drawn as your W\n"
        "score: 2 of 2\n");
  CHECK(fbd_text(graded(
            "body: A\nforces:\n  - {name: W, at: A, direction: [-1]}\n  - {name: S, at: A, direction: [1]}\n")) ==
        "free body diagram of A: correct: every force on A is drawn, each along its line and at its point\n"
        "  the force of spring sp at A (-k*(l_0 + x - D)): drawn as your S\n"
        "  the weight of A (g*m*sin(theta)): drawn as your W\n"
        "score: 2 of 2\n");
  const FbdGrade anchor =
      graded("body: A\nforces:\n  - {name: W, at: A, direction: [-1]}\n  - {name: S, at: Q, direction: [1]}\n");
  CHECK(anchor.summary == "your S stands for the force of spring sp at A, which does not act at Q");
  CHECK(anchor.score == Approx(1.5));
  CHECK(anchor.max_score == Approx(2));
}

TEST_CASE("FBD: a friction with mu = 0 and a couple of 0 are nothing in the sketch", "[check][fbd]") {
  auto graded = [](const std::string& text, const std::string& yaml) {
    const auto a = test::run_text(text);
    std::vector<Diagnostic> problems;
    return check_fbd(a->model, read_fbd_file(yaml, "fbd.yaml", a->model), FbdRubric{}, problems);
  };
  // The suitcase with mu = 0 (by hand): each foot pushes up (N_A, N_B), no friction; the weight
  // at the center. The three drawn: every point, the frictions earned left out.
  const FbdGrade smooth = graded(test::example_with("sample-12.7-suitcase.yaml", "mu: {value: 0.3, positive: true}",
                                                    "mu: {value: 0, positive: false}"),
                                 "body: suitcase\nforces:\n  - {name: W, at: suitcase, direction: [0, -1]}\n  - {name: "
                                 "N_A, at: A, direction: [0, 1]}\n"
                                 "  - {name: N_B, at: B, direction: [0, 1]}\n");
  CHECK(
      fbd_text(smooth) ==
      "free body diagram of suitcase: correct: every force on suitcase is drawn, each along its line and at its point\n"
      "  the force of the sliding contact at A (its N_A part): drawn as your N_A\n"
      "  the force of the sliding contact at A (its mu*N_A part): nothing at this position (not needed)\n"
      "  the force of the sliding contact at B (its N_B part): drawn as your N_B\n"
      "  the force of the sliding contact at B (its mu*N_B part): nothing at this position (not needed)\n"
      "  the weight of suitcase (g*m): drawn as your W\n"
      "score: 5 of 5\n");
  // The wheel with M_0 = 0 (by hand): no couple; the weight, the ground's N_C up and F_C along
  // x (static friction, either sense). Left out or drawn either way, the couple earns its share.
  const std::string wheel = test::example_with("rotation-wheel-driven-by-a-couple.yaml", "M_0: {value: 6, unit: N*m}",
                                               "M_0: {value: 0, unit: N*m, positive: false}");
  const std::string forces =
      "body: wheel\nforces:\n  - {name: W, at: wheel, direction: [0, -1]}\n  - {name: N, at: C, direction: [0, 1]}\n  "
      "- {name: F, at: C, direction: [-1, 0]}\n";
  CHECK(fbd_text(graded(wheel, forces)) ==
        "free body diagram of wheel: correct: every force on wheel is drawn, each along its line and at its point\n"
        "  the couple on wheel (-M_0): nothing at this position (not needed)\n"
        "  the force of the rolling at C (its N_C part): drawn as your N\n"
        "  the force of the rolling at C (its F_C part): drawn as your F\n"
        "  the weight of wheel (g*m): drawn as your W\n"
        "score: 4 of 4\n");
  const FbdGrade turned = graded(wheel, forces + "couples:\n  - {name: M, sense: counterclockwise}\n");
  CHECK(verdict_name(turned.verdict) == "correct");
  CHECK(turned.score == Approx(4));
}

TEST_CASE("FBD: an arrow's kind, and a rubric's weights, are read with their problems located", "[check][fbd]") {
  const Model& m = analysis_for("incline-and-hanging-block").model;
  std::vector<std::string> out;
  try {
    (void)read_fbd_file("body: A\nforces:\n  - {name: W, at: A, direction: [0, -1], kind: gravity}\n", "f.yaml", m);
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
  }
  CHECK(out == std::vector<std::string>{"f.yaml:3:48: 'gravity' is not a kind of force (expected weight, tension, "
                                        "spring, damper, applied or support)"});
  out.clear();
  // By hand, the incline's forces: the roller at A (N_A), the string's strands A-P on A and P-B
  // on B (tension T), the weights of A and B; no C.
  try {
    (void)read_rubric("fbd:\n  weights: {N_A: 2, gravity on C: 1, T: 1}\n", "r.yaml", m);
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
  }
  CHECK(out ==
        std::vector<std::string>{
            "r.yaml:2:21: 'gravity on C' names no force of the problem (expected a force's unknown or source: N_A, T, "
            "roller at A, string s: strand A-P, string s: strand P-B, gravity on A, gravity on B)"});
}

TEST_CASE("FBD: the student's names are mapped to the forces they stand for", "[check][fbd]") {
  const FbdGrade g = grade("incline-and-hanging-block",
                           "body: A\nforces:\n  - {name: P, at: A, angle: 30}\n  - {name: R, at: A, angle: 120}\n  - "
                           "{name: W, at: A, direction: [0, -1]}\n");
  REQUIRE(g.forces.size() == 3);
  CHECK(fbd_text(g) ==
        "free body diagram of A: correct: every force on A is drawn, each along its line and at its point\n"
        "  the force of the roller at A (N_A): drawn as your R\n"
        "  a strand of string s at A (T): drawn as your P\n"
        "  the weight of A (g*m_A): drawn as your W\n"
        "score: 3 of 3\n");
  const auto json = nlohmann::json::parse(fbd_json(g));
  CHECK(json["forces"][1]["label"] == "T");
  CHECK(json["forces"][1]["drawn_as"] == nlohmann::json::array({"P"}));
  CHECK(json["forces"][1]["status"] == "drawn");
}

TEST_CASE("FBD: an instructor's weights and penalties", "[check][fbd]") {
  FbdRubric r;
  r.weights["gravity on A"] = 2;
  r.wrong_direction = 0.25;
  r.extra = 0.5;
  // The weight drawn up (half... a quarter of its 2 points), and one extra arrow.
  const FbdGrade g = grade(
      "atwood-machine",
      "body: A\nforces:\n  - {name: T, direction: [1]}\n  - {name: W, direction: [1]}\n  - {name: X, direction: [1]}\n",
      r);
  CHECK(g.max_score == Approx(3));
  CHECK(g.score == Approx(1 + 0.5 - 0.5));
  CHECK(g.findings.front().code == "force_direction");
  CHECK(g.extras.size() == 1);
}

TEST_CASE("FBD: a diagram with problems says each, located, in the file's order", "[check][fbd]") {
  const Model& m = analysis_for("incline-and-hanging-block").model;
  std::vector<std::string> out;
  try {
    (void)read_fbd_file(
        "body: Q\nforces:\n  - {name: N, at: Z, angle: 90}\n  - {name: T, at: A, direction: [1, 2, 3]}\n  - {name: W, "
        "at: A}\n"
        "  - {name: X, at: A, direction: [0, \"a\"]}\ncouples:\n  - {name: M, sense: left}\n",
        "f.yaml", m);
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
  }
  CHECK(out ==
        std::vector<std::string>{
            "f.yaml:1:7: 'Q' is not a body of the problem (expected one of: A, B)",
            "f.yaml:3:19: 'Z' is not a point or body of the problem (expected one of: A, B, P)",
            "f.yaml:4:33: 'direction' has 3 numbers (expected 2, one per axis)",
            "f.yaml:5:5: a force needs its 'direction' (expected a list of 2 numbers, 'angle' in degrees, or 'any')",
            "f.yaml:6:38: 'a' is not a number (expected a number from -10^6 to 10^6)",
            "f.yaml:8:22: 'left' is not a sense (expected counterclockwise, clockwise or any)",
        });
  out.clear();
  const Model& line = analysis_for("sample-12.3-two-mass-pulley").model;
  try {
    (void)read_fbd_file("forces:\n  - {name: T, angle: 30}\ncouples: [{sense: any}]\n", "g.yaml", line);
  } catch (const InputError& e) {
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
  }
  CHECK(out ==
        std::vector<std::string>{
            "g.yaml:1:1: the free body diagram has no 'body' (expected body: NAME, or bodies: [A, B] for a system)",
            "g.yaml:2:22: 'angle' is for a plane problem (expected 'direction' with 1 number)",
            "g.yaml:3:10: 'couples' are for a plane problem (this one has 1 axis)",
        });
}

TEST_CASE("FBD: a worked solution's diagrams earn the rubric's fbds points", "[check][fbd][steps]") {
  const Analysis& a = analysis_for("sample-12.3-two-mass-pulley");
  const Checker c(a);
  // LMB A and LMB B are needed (by hand), so the diagrams of A and of B are wanted.
  const auto steps = read_solution(R"Y(steps:
  - fbd: {body: A, forces: [{name: F, direction: [-1]}, {name: T, at: pA, direction: [1]}, {name: T, at: pA, direction: [1]}]}
  - fbd: {body: B, forces: [{name: T, at: pB, direction: [-1]}, {name: T, at: pB, direction: [-1]}]}
  - equation: "2*T - F = m_A*ddot(x_A)"
)Y",
                                   "s.yaml", a.model);
  const Rubric rubric = read_rubric("fbds: 2\nbalances: 2\nconstraints: 0\nanswers: 0\n", "r.yaml", a.model);
  const SolutionGrade g = grade_solution(c, a.model, steps, rubric);
  REQUIRE(g.steps.size() == 3);
  CHECK(g.steps[0].result.verdict == Verdict::correct);
  CHECK(g.steps[1].result.summary == "a strand of string s at pB is missing");
  CHECK(g.first_wrong == std::optional<std::size_t>(2));
  REQUIRE(!g.parts.empty());
  CHECK(g.parts[0].name == "fbds");
  CHECK(g.parts[0].score == Approx(2 * (1 + 2.0 / 3) / 2));
  CHECK(g.parts[0].done == 1);
  CHECK(g.parts[0].of == 2);
  const auto results = nlohmann::json::parse(solution_results(g, ResultsFormat::gradescope));
  CHECK(results["tests"][1]["name"] == "step 2: free body diagram of B");
  CHECK(results["tests"][1]["output"] == "incorrect: a strand of string s at pB is missing");
}

TEST_CASE("FBD: a batch line with a diagram is graded, with partial credit", "[check][fbd][batch]") {
  const Analysis& a = analysis_for("sample-12.3-two-mass-pulley");
  const Checker c(a);
  // By hand: B has three strands at pB pulling along -x; one drawn earns a third.
  std::istringstream in(R"J({"id": "a", "fbd": {"body": "B", "forces": [{"name": "T", "at": "pB", "direction": [-1]}]}}
{"id": "b", "fbd": {"body": "Q", "forces": []}}
{"id": "c", "fbd": 3}
)J");
  std::ostringstream out, results;
  GradeOptions options;
  options.model = &a.model;
  options.points = 3;
  const BatchSummary s = check_batch(c, in, out, results, options);
  CHECK(s.lines == 3);
  CHECK(s.points == Approx(1));
  const auto grader = nlohmann::json::parse(results.str());
  CHECK(grader["tests"][0]["name"] == "a: free body diagram of B");
  CHECK(grader["tests"][0]["output"] == "incorrect: a strand of string s at pB is missing");
  CHECK(grader["tests"][1]["output"] == "invalid: line 2: 'Q' is not a body of the problem (expected one of: A, B)");
  CHECK(grader["tests"][2]["output"] ==
        "invalid: line 3: \"fbd\" is not an object (expected {\"body\": ..., \"forces\": [...]})");
  // Without the model (a caller that did not give it), the line is invalid, not a crash.
  std::istringstream again(R"J({"id": "a", "fbd": {"body": "B"}}
)J");
  std::ostringstream out2, results2;
  (void)check_batch(c, again, out2, results2, GradeOptions{});
  CHECK(nlohmann::json::parse(out2.str())["summary"] == "line 1: free body diagrams are not checked here");
}

// Checking answers: verdicts and the feedback a student sees, word for word.
#include <catch2/catch.hpp>

#include <fstream>

#include <chrono>
#include <sstream>

#include <nlohmann/json.hpp>

#include "grade/batch.hpp"
#include "../../support/helpers.hpp"

using namespace tackle;

namespace {
const Checker& checker(const std::string& example) {
  static std::map<std::string, std::pair<std::unique_ptr<const Analysis>, std::unique_ptr<Checker>>> made;
  auto it = made.find(example);
  if (it == made.end()) {
    auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/" + example, test::rules());
    auto c = std::make_unique<Checker>(*a);
    it = made.emplace(example, std::make_pair(std::move(a), std::move(c))).first;
  }
  return *it->second.second;
}
const Checker& board() { return checker("sample-12.8-sign-board.yaml"); }
const Checker& suitcase() { return checker("sample-12.7-suitcase.yaml"); }
}  // namespace

TEST_CASE("Check: equivalent forms of the sign-board tension are correct", "[check]") {
  for (const char* a : {"m*a*l/(2*d)", "a*m*sqrt(d^2+b^2+e^2)/d/2", "m*a*sqrt(b^2 + d^2 + e^2)/(2*d)",
                        "T_HI = (m*a/2) * l/d", "0.5*m*a*l/d", "m*a*(b^2+d^2+e^2)/(2*d*sqrt(b^2+d^2+e^2))"}) {
    INFO(a);
    const auto r = board().check("T_HI", a);
    CHECK(r.verdict == Verdict::correct);
    CHECK(r.score == 1.0);
  }
}

TEST_CASE("Check: an answer in a turning strand's length is evaluated, as the closed form is written", "[check]") {
  // The bead's acceleration is printed with l_bead_P = sqrt(D^2 + x^2); an answer copied from
  // it was undecided (the length had no value at the points) until the lengths were put in.
  const Checker& bead = checker("problem-12.63-bead-on-wire.yaml");
  for (const char* a : {"k*x*(l_0 - l_bead_P)/(l_bead_P*m)", "k*x*(l_0 - sqrt(D^2 + x^2))/(m*sqrt(D^2 + x^2))"}) {
    INFO(a);
    CHECK(bead.check("ddot(x)", a).verdict == Verdict::correct);
  }
  CHECK(bead.check("ddot(x)", "k*x*(l_bead_P - l_0)/(l_bead_P*m)").summary == "the sign is wrong");
}

TEST_CASE("Check: values kept as unreduced fractions are reduced before they are judged too large", "[check][limits]") {
  // S = h^32 + l^32 + h^16 l^16 + h^8 l^24 + h^24 l^8 and the same sum written so that GiNaC
  // does not see it: the answer is the closed form times (S/S)^6. S's terms have different
  // denominators at a point, so S as an unreduced fraction has five times the bits it has in
  // lowest terms, and its sixth power more than the 8192 allowed; reduced, it is decided.
  const std::string s = "(h^32+l^32+h^16*l^16+h^8*l^24+h^24*l^8)";
  const std::string same_s = "((h^16+l^16)*(h^16-l^16)+2*l^32+h^16*l^16+h^8*l^24+h^24*l^8)";
  const auto r = suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(" + s + "/" + same_s + ")^6");
  CHECK(r.verdict == Verdict::correct);
  CHECK(r.method == "exact rationals");
  const auto twice = suitcase().check("N_A", "2*m*g*(1/2 - mu*h/l)*(" + s + "/" + same_s + ")^6");
  CHECK(twice.summary == "off by a factor of 2 (the answer is twice the correct answer)");
}

TEST_CASE("Check: a fraction to a whole power, zero and negative bases", "[check]") {
  // The evaluator's own rule for whole powers of fractions: negative powers of negative bases,
  // the zeroth power, and 0 to a negative power (a division by zero at every point).
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(-h/l)^(-3)*(-h/l)^3").verdict == Verdict::correct);
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(-h/l)^(-3)*(h/l)^3").summary == "the sign is wrong");
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(h - h)^(-1)").verdict != Verdict::correct);
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(mu*h*l - l*h*mu + 1)^0").verdict == Verdict::correct);
}

TEST_CASE("Check: off by a factor of 2, wrong sign, swapped l and d", "[check]") {
  auto r = board().check("T_HI", "m*a*sqrt(b^2+d^2+e^2)/d");
  CHECK(r.verdict == Verdict::incorrect);
  CHECK(r.summary == "off by a factor of 2 (the answer is twice the correct answer)");
  r = board().check("T_HI", "-m*a*l/(2*d)");
  CHECK(r.summary == "the sign is wrong");
  r = board().check("T_HI", "m*a*d/(2*l)");
  CHECK(r.verdict == Verdict::incorrect);
  CHECK(r.summary == "d and l are swapped");
}

TEST_CASE("Check: a factor in the parameters is named, whichever way it is found", "[check]") {
  // A product of powers (found from the values), a sum in two parameters (the factors cancel
  // at sight), the same with the reference's sum inside a fraction, and a sum in three
  // parameters, which is not named (the values show it is neither).
  const Checker& pulley = checker("sample-12.3-two-mass-pulley.yaml");
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*mu*h/l").summary == "off by a factor of h*mu/l");
  CHECK(pulley.check("T", "2*F*(m_A + m_B)/(9*m_A + 4*m_B)").summary == "off by a factor of (m_A + m_B)/m_B");
  CHECK(pulley.check("T", "2*m_B*F/(9*m_A + 4*m_B)/(m_A + m_B)*m_B").summary == "off by a factor of m_B/(m_A + m_B)");
  CHECK(suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(l + h)/l").summary == "off by a factor of (h + l)/l");
  const auto three = suitcase().check("N_A", "m*g*(1/2 - mu*h/l)*(l + h)*mu/h");
  CHECK(three.verdict == Verdict::incorrect);
  CHECK(
      std::none_of(three.findings.begin(), three.findings.end(), [](const Finding& f) { return f.code == "factor"; }));
}

TEST_CASE("Check: the suitcase's normal force without friction is correct only for mu = 0", "[check]") {
  const auto r = suitcase().check("N_A", "m*g/2");
  CHECK(r.verdict == Verdict::incorrect);
  CHECK(r.summary == "this is correct only without friction (mu = 0)");
  std::vector<std::string> codes;
  for (const auto& f : r.findings) codes.push_back(f.code);
  // N_A = m g (1/2 - mu h/l): m g/2 is also the first term alone.
  CHECK(codes == std::vector<std::string>{"special_case", "special_case", "missing_term", "missing_parameter"});
  CHECK(r.findings[1].message == "this is correct only for h = 0");
  CHECK(r.findings[2].message == "one term of the correct answer is missing");
  CHECK(r.findings[3].message == "the correct answer depends on mu, l and h, and this one does not");
}

TEST_CASE("Check: the other contact's force is recognised", "[check]") {
  CHECK(suitcase().check("N_A", "m*g*(1/2 + mu*h/l)").summary == "this is the value of N_B, not of N_A");
}

TEST_CASE("Check: dimensions, from the problem's own parameters", "[check]") {
  auto r = board().check("T_HI", "m + a");
  CHECK(r.verdict == Verdict::incorrect);
  CHECK(r.summary == "the answer is dimensionally inconsistent: it adds an acceleration to a mass");
  r = board().check("T_HI", "m*a/d");
  CHECK(r.summary == "this is a stiffness (force per length); a force was expected");
  CHECK(board().check("T_HI", "sqrt(m)*a").summary ==
        "the answer is dimensionally inconsistent: it takes a fractional power of a mass");
  // Three dimensions in one sum, and two sums with different mixes: what is said does not
  // follow the order of the terms (which follows addresses, so changed from run to run).
  CHECK(board().check("T_HI", "m + a + b + d + e").summary ==
        "the answer is dimensionally inconsistent: it adds an acceleration to a length");
  CHECK(board().check("T_HI", "m*a*(b + m) + a*(d + a)").summary ==
        "the answer is dimensionally inconsistent: it adds a length to a mass");
}

TEST_CASE("Check: invalid answers name what to fix", "[check][invalid]") {
  CHECK(board().check("T_HI", "ma*l/(2*d)").summary ==
        "at column 1: unknown name 'ma': did you mean 'm*a'? (write products with *)");
  CHECK(board().check("T_HI", "M*a").summary ==
        "at column 1: unknown name 'M': did you mean 'm'? (names are case-sensitive; subscripts are written with _)");
  CHECK(board().check("T_HI", "T_HI*2").summary ==
        "at column 1: T_HI is an unknown of this problem; write the answer in the given quantities (m, a, g, b, c, d, "
        "e, l)");
  const auto two_m = board().check("T_HI", "2 m");
  CHECK(two_m.summary == "the unit m is a length; a force was expected");
  CHECK(two_m.findings.back().message == "if you meant 2*m, write the * (2 m is read as a number with a unit)");
  CHECK(board().check("T_HI", "2 a m").summary == "at column 3: missing '*' before 'a'");
  CHECK(board().check("T_HI", "foo(m)").summary ==
        "at column 1: unknown function 'foo' (known: sqrt, abs, sin, cos, tan, asin, acos, atan, sinh, cosh, exp, log, "
        "dot, ddot, unit, norm, cross, "
        "inner, perp1, perp2)");
  CHECK(board().check("T_HI", "O_z = m*a").summary == "this is an answer for O_z, but T_HI was asked for");
  CHECK(board().check("Q", "m").summary == "'Q' is not an unknown tackle can check for this problem (checkable: T_HI)");
  CHECK(board().check("T_HI", "").verdict == Verdict::invalid);
}

TEST_CASE("Check: hostile inputs are invalid within the budget", "[check][invalid][limits]") {
  const auto start = std::chrono::steady_clock::now();
  const std::string deep = std::string(10000, '(') + "m" + std::string(10000, ')');
  CHECK(board().check("T_HI", deep).summary == "the answer is too long (20001 characters; at most 1000)");
  CHECK(board().check("T_HI", std::string(1 << 20, 'x')).summary ==
        "the answer is too long (1048576 characters; at most 1000)");
  const std::string nested = std::string(100, '(') + "m" + std::string(100, ')');
  CHECK(board().check("T_HI", nested).summary == "at column 33: expression is nested too deeply (at most 32 levels)");
  CHECK(board().check("T_HI", "9^(9^9)").summary == "at column 2: exponent is too large (at most 32)");
  // Found by fuzzing: a tower of powers raised to a parameter made CLN build an integer of
  // 10^16 digits; numbers past 8192 bits are not used to decide.
  const auto tower = tackle::Checker(*tackle::test::run_text(tackle::test::read_example("sample-12.7-suitcase.yaml")))
                         .check("N_A", "m*g*(98355^ .3^2.3^5^355.32^ .355^ .2/mu- mu)^(h)");
  CHECK(tower.verdict == Verdict::undecided);
  CHECK(tower.summary ==
        "the answer could not be evaluated at the test values (a division by zero, a negative square "
        "root, or a number too large to work with?)");
  // Found by fuzzing: bytes that are not UTF-8 reached the JSON writer, which threw.
  const auto latin1 = board().check("T_HI",
                                    "m\x91"
                                    "a");
  CHECK(latin1.verdict == Verdict::invalid);
  CHECK(latin1.summary == "at column 2: the answer is not valid UTF-8 text");
  CHECK(tackle::result_json(latin1,
                            "m\x91"
                            "a")
            .find("m\xEF\xBF\xBD"
                  "a") != std::string::npos);                                      // U+FFFD in the echo
  CHECK(board().check("T_HI", "(m+a+b+d+e)^32*l/d").verdict != Verdict::correct);  // bounded: no blow-up
  CHECK(board().check("T_HI", "sqrt(-1)*m*a*l/(2*d)").verdict == Verdict::undecided);
  for (const char* a : {"m/0", "1e99 N", "m^m^m^m^m^m^m", "[m, a]"}) {
    INFO(a);
    const auto r = board().check("T_HI", a);
    CHECK(r.verdict != Verdict::correct);
  }
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}

TEST_CASE("Check: numbers with units, converted, within the tolerance", "[check][units]") {
  for (const char* a : {"6.8 N", "0.0068 kN", "1.53 lbf", "T_HI = 6.78 N", "6.78233 kg*m/s^2"}) {
    INFO(a);
    CHECK(board().check("T_HI", a).verdict == Verdict::correct);
  }
  CHECK(board().check("T_HI", "6.78").summary == "give the unit: the answer is a force (in SI, N)");
  CHECK(board().check("T_HI", "6.78 m").summary == "the unit m is a length; a force was expected");
  CHECK(board().check("T_HI", "6.78 kgg").summary == "unknown unit 'kgg' (expected a unit such as N)");
  CHECK(board().check("T_HI", "678 N").summary == "off by a factor of 10^2: check the unit prefix or the conversion");
  CHECK(board().check("T_HI", "-6.78 N").summary == "the sign is wrong");
  CHECK(board().check("T_HI", "7.0 N").verdict == Verdict::incorrect);  // 3.2 % off
  CheckOptions loose;
  loose.relative_tolerance = 0.05;
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  CHECK(Checker(*a, loose).check("T_HI", "7.0 N").verdict == Verdict::correct);
  CheckOptions figures;
  figures.significant_figures = 3;
  const Checker sig(*a, figures);
  CHECK(sig.check("T_HI", "6.78 N").verdict == Verdict::correct);
  CHECK(sig.check("T_HI", "6.8 N").verdict == Verdict::incorrect);
}

TEST_CASE("Check: a correct answer that is not simplified is said so, and can be required", "[check]") {
  const std::string long_form = "m*a*l*d*d/(2*d*d*d) + 0*m";
  auto r = board().check("T_HI", long_form);
  CHECK(r.verdict == Verdict::correct);
  REQUIRE(!r.findings.empty());
  CHECK(r.findings.back().message == "correct, but it simplifies to a*l*m/(2*d)");
  CheckOptions strict;
  strict.require_simplified = true;
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  r = Checker(*a, strict).check("T_HI", long_form);
  CHECK(r.verdict == Verdict::incorrect);
}

TEST_CASE("Check: an expression is settled once whatever its spelling, and the spelling's own note stays its own",
          "[check]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  const Checker checker(*a);
  // One expression once read (a*l*m/(2*d)), typed three ways: the first two short, the third
  // much longer than its simplest form. Each is correct; only the long one is told to simplify.
  const auto short_one = checker.check("T_HI", "m*a*l/(2*d)");
  const auto again = checker.check("T_HI", "(l*m*a)/(d*2)");
  const auto long_one = checker.check("T_HI", "2*m*a*l*d*d/(4*d*d*d) + 0*m");
  for (const auto* r : {&short_one, &again, &long_one}) {
    CHECK(r->verdict == Verdict::correct);
    CHECK(r->unknown == "T_HI");
    CHECK(r->echo_text == "a*l*m/(2*d)");
  }
  CHECK(short_one.findings.empty());
  CHECK(again.findings.empty());
  REQUIRE(long_one.findings.size() == 1);
  CHECK(long_one.findings[0].message == "correct, but it simplifies to a*l*m/(2*d)");
  // And the short one after the long one: no note carried over.
  CHECK(checker.check("T_HI", "a*m*l/(2*d)").findings.empty());
  // A wrong expression in two spellings: the same findings, worked out once.
  const auto wrong = checker.check("T_HI", "m*a*l/d");
  const auto wrong_again = checker.check("T_HI", "2*m*a*l/(2*d)");
  CHECK(wrong.verdict == Verdict::incorrect);
  REQUIRE(wrong.findings.size() == wrong_again.findings.size());
  for (std::size_t i = 0; i < wrong.findings.size(); ++i)
    CHECK(wrong.findings[i].message == wrong_again.findings[i].message);
  CHECK(wrong.findings[0].message == "off by a factor of 2 (the answer is twice the correct answer)");
}

TEST_CASE("Check: a batch grades every line and writes the grader shape", "[check][batch]") {
  std::istringstream in(
      "{\"id\": \"s1\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n"
      "{\"id\": \"s2\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/d\"}\n"
      "not json\n"
      "\n"
      "{\"id\": 3, \"unknown\": \"T_HI\", \"answer\": 6.8}\n");
  std::ostringstream out;
  const BatchSummary s = check_batch(board(), in, out);
  CHECK(s.lines == 4);
  CHECK(s.correct == 1);
  std::vector<nlohmann::json> lines;
  std::istringstream results(out.str());
  for (std::string l; std::getline(results, l);) lines.push_back(nlohmann::json::parse(l));
  REQUIRE(lines.size() == 4);
  CHECK(lines[0]["verdict"] == "correct");
  CHECK(lines[1]["verdict"] == "incorrect");
  CHECK(lines[1]["findings"][0]["code"] == "factor");
  CHECK(lines[2]["verdict"] == "invalid");
  CHECK(lines[2]["summary"] == "line 3: not a JSON object with id, unknown and answer");
  CHECK(lines[3]["id"] == "3");
  CHECK(lines[3]["verdict"] == "invalid");  // a bare number for a force: no unit
  // Gradescope by default: the tests' scores, and no top-level score (it would override them).
  const auto grader = nlohmann::json::parse(s.results);
  CHECK_FALSE(grader.contains("score"));
  CHECK(grader["output"] == "1 of 4 answers correct");
  CHECK(grader["tests"].size() == 4);
  CHECK(grader["tests"][0]["score"] == 1);
  CHECK(grader["tests"][0]["max_score"] == 1);
  CHECK(grader["tests"][0]["status"] == "passed");
  CHECK(grader["tests"][1]["score"] == 0);
  CHECK(grader["tests"][1]["output"] == "incorrect: off by a factor of 2 (the answer is twice the correct answer)");
}

namespace {

// Every field of `ours` is a field of the platform's documented example `doc`, with the same
// JSON type (numbers of either kind alike); the objects in arrays against the example's first.
void same_shape(const nlohmann::json& ours, const nlohmann::json& doc, const std::string& path) {
  auto kind = [](const nlohmann::json& j) {
    return j.is_number() ? std::string("number") : std::string(j.type_name());
  };
  INFO(path);
  REQUIRE(kind(ours) == kind(doc));
  if (ours.is_object())
    for (auto it = ours.begin(); it != ours.end(); ++it) {
      INFO("field " << path << "/" << it.key());
      REQUIRE(doc.contains(it.key()));
      same_shape(it.value(), doc[it.key()], path + "/" + it.key());
    }
  if (ours.is_array() && !doc.empty())
    for (const auto& x : ours) same_shape(x, doc[0], path + "[]");
}

nlohmann::json fixture(const std::string& name) {
  std::ifstream in(TACKLE_SOURCE_DIR "/tests/data/platforms/" + name);
  return nlohmann::json::parse(in);
}

BatchSummary grade(const std::string& lines, const GradeOptions& options, const Checker& c = board()) {
  std::istringstream in(lines);
  std::ostringstream out;
  return check_batch(c, in, out, options);
}

}  // namespace

TEST_CASE("Grading: Gradescope's results.json, points per unknown, no top-level score unless asked",
          "[check][batch][platform]") {
  GradeOptions options;
  options.points = 2;
  options.points_for["T_HI"] = 5;
  const std::string lines =
      "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n"
      "{\"id\": \"b\", \"unknown\": \"T_HI\", \"answer\": \"30 N\"}\n"
      "{\"id\": \"c\", \"unknown\": \"l\", \"answer\": \"m\"}\n";
  const BatchSummary s = grade(lines, options);
  CHECK(s.points == 5);
  CHECK(s.max_points == 12);
  const auto j = nlohmann::json::parse(s.results);
  same_shape(j, fixture("gradescope-results.json"), "");
  CHECK_FALSE(j.contains("score"));
  CHECK(j["tests"][0]["score"] == 5);
  CHECK(j["tests"][0]["max_score"] == 5);
  CHECK(j["tests"][1]["score"] == 0);
  CHECK(j["tests"][2]["max_score"] == 2);
  options.top_level_score = true;
  const auto with_total = nlohmann::json::parse(grade(lines, options).results);
  CHECK(with_total["score"] == 5);
}

TEST_CASE("Grading: feedback never names the correct value unless asked", "[check][batch][platform]") {
  // T_HI = 6.78233 N (sample 12.8).
  const CheckResult wrong = board().check("T_HI", "30 N");
  CHECK(wrong.summary == "not within 1 % of the correct value (got 30 N)");
  CHECK(board().check("T_HI", "6.8 N").summary == "correct within 1 %");
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  CheckOptions reveal;
  reveal.reveal = true;
  const Checker told(*a, reveal);
  CHECK(told.check("T_HI", "30 N").summary == "expected 6.78233 N within 1 %; got 30 N");
  CHECK(told.check("T_HI", "6.8 N").summary == "correct within 1 % (the answer is 6.78233 N)");
  const BatchSummary s = grade("{\"id\": \"b\", \"unknown\": \"T_HI\", \"answer\": \"30 N\"}\n", {});
  CHECK(s.results.find("6.78") == std::string::npos);
}

TEST_CASE("Grading: PrairieLearn's results.json, where an answer that cannot be graded charges no attempt",
          "[check][batch][platform]") {
  GradeOptions options;
  options.format = ResultsFormat::prairielearn;
  const std::string good =
      "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n"
      "{\"id\": \"b\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/d\"}\n";
  const auto graded = nlohmann::json::parse(grade(good, options).results);
  same_shape(graded, fixture("prairielearn-results.json"), "");
  CHECK(graded["gradable"] == true);
  CHECK(graded["score"] == Approx(0.5));
  CHECK(graded["tests"][1]["points"] == 0);
  CHECK(graded["tests"][1]["max_points"] == 1);
  const auto bad = nlohmann::json::parse(
      grade(good + "{\"id\": \"c\", \"unknown\": \"T_HI\", \"answer\": \"m*a*\"}\n", options).results);
  same_shape(bad, fixture("prairielearn-results.json"), "");
  CHECK(bad["gradable"] == false);
  CHECK_FALSE(bad.contains("score"));
  REQUIRE(bad["format_errors"].size() == 1);
  CHECK(bad["format_errors"][0].get<std::string>().rfind("c: T_HI: ", 0) == 0);
  CHECK(bad["message"] == "1 of 3 answers cannot be graded as typed: fix them and submit again");
}

TEST_CASE("Grading: PrairieLearn lists the first 100 answers that cannot be graded, then how many more",
          "[check][batch][platform]") {
  // The results file is written as the batch goes; only the first 100 format errors are kept.
  GradeOptions options;
  options.format = ResultsFormat::prairielearn;
  std::string lines;
  for (int i = 1; i <= 150; ++i)
    lines += "{\"id\": \"s" + std::to_string(i) + "\", \"unknown\": \"T_HI\", \"answer\": \"m*a*\"}\n";
  const BatchSummary s = grade(lines, options);
  CHECK(s.invalid == 150);
  const auto j = nlohmann::json::parse(s.results);
  same_shape(j, fixture("prairielearn-results.json"), "");
  CHECK(j["gradable"] == false);
  CHECK(!j.contains("tests"));  // not gradable: no test tells which other answers are right
  REQUIRE(j["format_errors"].size() == 101);
  CHECK(j["format_errors"][99].get<std::string>().rfind("s100: T_HI: ", 0) == 0);
  CHECK(j["format_errors"][100] == "and 50 more");
  CHECK(j["message"] == "150 of 150 answers cannot be graded as typed: fix them and submit again");
}

TEST_CASE("Grading: a line longer than 1 MiB stops the batch at that line, a long line under it is invalid",
          "[check][batch][limits]") {
  // Exactly 1 MiB (1048576 bytes) is read, and is an invalid answer (past the checker's bound).
  GradeOptions options;
  options.source = "batch.jsonl";
  const std::string good = "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n";
  BatchSummary s = grade(good + std::string(1048576, 'x') + "\n" + good, options);
  CHECK(s.lines == 3);
  CHECK(s.correct == 2);
  CHECK(s.invalid == 1);
  // One byte more, even with no newline after it (/dev/zero has none), stops the batch there.
  try {
    (void)grade(good + "\n" + std::string(1048577, 'x'), options);
    FAIL("no error");
  } catch (const InputError& e) {
    CHECK(format(e.diagnostics().at(0)) ==
          "batch.jsonl:3: the line is longer than 1 MiB (expected JSON Lines: one object with id, unknown and answer "
          "per line)");
  }
}

TEST_CASE("Grading: a batch whose output fails stops reading, and its results file is still whole JSON",
          "[check][batch]") {
  std::istringstream in("{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n");
  std::ostringstream out, results;
  out.setstate(std::ios::badbit);  // as a full disk leaves it
  const BatchSummary s = check_batch(board(), in, out, results, {});
  CHECK(s.lines == 0);
  const auto j = nlohmann::json::parse(results.str());
  CHECK(j["tests"].empty());
  CHECK(j["output"] == "0 of 0 answers correct");
}

TEST_CASE("Check: a kinematic answer may use a given acceleration without its coordinate", "[check]") {
  const Checker& k = checker("sample-12.2-pulley-kinematics.yaml");
  CHECK(k.check("ddot(y_A)", "-ddot(y_B)/2").verdict == Verdict::correct);
  CHECK(k.check("ddot(y_A)", "-2*ddot(y_B)").summary ==
        "off by a factor of 4 (the answer is 4 times the correct answer)");
  CHECK(k.check("ddot(y_A)", "ddot(y_A)").summary ==
        "at column 1: ddot(y_A) is an unknown of this problem; write the answer in the given quantities (d, dot(y_B), "
        "ddot(y_B))");
}

TEST_CASE("Grading: each student's own numbers, from --set or a line's params", "[check][batch][variants]") {
  // Sample 12.3: T = 2 F m_B/(9 m_A + 4 m_B); by hand with F = 120 N, m_A = m_B = 40 kg:
  // 9600/520 = 18.4615 N; with m_A = 20 kg as well, 9600/340 = 28.2353 N.
  const Checker& c = checker("sample-12.3-two-mass-pulley.yaml");
  std::string problem;
  const auto values = c.values_for({{"F", "120"}}, problem);
  REQUIRE(values);
  CHECK(c.check("T", "18.46 N", &*values).verdict == Verdict::correct);
  CHECK(c.check("T", "20 N", &*values).verdict == Verdict::incorrect);
  CHECK(c.check("T", "20 N").verdict == Verdict::correct);  // the description's own F = 130 N
  const auto both = c.values_for({{"F", "120"}, {"m_A", "20"}}, problem);
  REQUIRE(both);
  CHECK(c.check("T", "28.24 N", &*both).verdict == Verdict::correct);
  CHECK_FALSE(c.values_for({{"G", "1"}}, problem));
  CHECK(problem == "'G' is not a parameter with a value (expected one of: F, m_A, m_B)");
  CHECK_FALSE(c.values_for({{"F", "lots"}}, problem));
  CHECK(problem == "the value of 'F' is 'lots' (expected a number in N)");
  std::istringstream in(
      "{\"id\": \"s1\", \"unknown\": \"T\", \"answer\": \"18.46 N\", \"params\": {\"F\": 120}}\n"
      "{\"id\": \"s2\", \"unknown\": \"T\", \"answer\": \"28.24 N\", \"params\": {\"m_A\": \"20\"}}\n"
      "{\"id\": \"s3\", \"unknown\": \"T\", \"answer\": \"20 N\", \"params\": [1]}\n");
  std::ostringstream out;
  GradeOptions options;
  options.set = {{"F", "120"}};
  const BatchSummary s = check_batch(c, in, out, options);
  CHECK(s.correct == 2);
  std::istringstream results(out.str());
  std::vector<nlohmann::json> lines;
  for (std::string l; std::getline(results, l);) lines.push_back(nlohmann::json::parse(l));
  REQUIRE(lines.size() == 3);
  CHECK(lines[2]["summary"] == "line 3: \"params\" is not an object of parameter values");
}

TEST_CASE("Check: answers as people type them: Unicode, degrees, roots, superscripts", "[check][typed]") {
  // The incline (examples/incline-and-hanging-block.yaml): N_A = m_A g cos(theta), theta = 30 deg.
  const Checker& c = checker("incline-and-hanging-block.yaml");
  for (const char* a : {"m_A\u00b7g\u00b7cos(\u03b8)", "N_A = m_A\u00d7g\u00d7cos(\u03b8)", "m_A*g*cos(\u03b8)\u00b9",
                        "\u2212(\u2212m_A*g*cos(theta))", "m_A*g*\u221a(cos(\u03b8))\u00b2"}) {
    INFO(a);
    CHECK(c.check("N_A", a).verdict == Verdict::correct);
  }
  // The root of the square is |cos(theta)|, not cos(theta): they differ past 90 degrees, but
  // there N_A < 0, which the model's N_A >= 0 leaves out: right wherever the model holds.
  CHECK(c.check("N_A", "m_A*g*\u221a(cos(\u03b8)\u00b2)").verdict == Verdict::correct);
  // The acceleration has either sign (m_A sin(theta) > m_B runs the other way): |a| is wrong,
  // and not "correct only when m_A = m_B" (it is right wherever a > 0).
  CHECK(c.check("ddot(s)", "abs(g*(m_B - m_A*sin(theta))/(m_A + m_B))").summary ==
        "the answer differs from the correct one");
  // 30 deg inside an expression is pi/6 (a number: the closed form is in theta).
  const CheckResult deg = c.check("N_A", "m_A*g*cos(30 deg)");
  CHECK(deg.echo_text == "g*m_A*sqrt(3)/2");
  CHECK(c.check("N_A", "m_A*g*cos(30\u00b0)").echo_text == "g*m_A*sqrt(3)/2");
  CHECK(c.check("N_A", "m_A*g\u00b2*g\u207b\u00b9*cos(theta)").verdict == Verdict::correct);  // g^2 g^(-1)
  // Columns count the characters as typed.
  CHECK(c.check("N_A", "m_A\u00b7g\u00b7cos(\u03b8").summary == "at column 12: expected ')' to close 'cos('");
  CHECK(c.check("N_A", "m_A*g*cos(\u03b8)*x").summary ==
        "at column 14: unknown name 'x' (the problem's names: m_A, m_B, g, theta, L)");
}

TEST_CASE("Check: diagnoses of sin for cos, one term's sign, a missing term, a root factor", "[check]") {
  // By hand: ddot(s) = g (m_B - m_A sin(theta))/(m_A + m_B).
  const Checker& c = checker("incline-and-hanging-block.yaml");
  CHECK(c.check("N_A", "m_A*g*sin(theta)").summary == "sin and cos are swapped");
  CHECK(c.check("ddot(s)", "g*(m_B + m_A*sin(theta))/(m_A + m_B)").summary == "the sign of one term is wrong");
  const CheckResult missing = c.check("ddot(s)", "g*m_B/(m_A + m_B)");
  CHECK(missing.summary == "this is correct only for theta = 0");
  REQUIRE(missing.findings.size() >= 2);
  CHECK(missing.findings[1].message == "one term of the correct answer is missing");
  CHECK(c.check("ddot(s)", "g*(m_B - m_A*sin(theta))/(m_A + m_B) + g").summary == "the answer has one term too many");
  CHECK(c.check("N_A", "m_A*g*cos(theta)*sqrt(3)/2").summary ==
        "off by a factor of sqrt(3)/2 (the answer is sqrt(3)/2 times the correct answer)");
}

namespace {
// A checker whose fresh points are drawn from `seed`.
std::unique_ptr<const Checker> seeded(const Analysis& analysis, std::uint64_t seed) {
  CheckOptions options;
  options.seed = seed;
  return std::make_unique<const Checker>(analysis, options);
}
}  // namespace

TEST_CASE("Check: an answer built to vanish at the fixed points is incorrect", "[check][trust]") {
  // Sample 12.3: T = 2 F m_B/(9 m_A + 4 m_B). The first comparison's points are drawn from a
  // fixed seed, so anyone can find them: these four ratios m_A/m_B are theirs. The product
  // vanishes at each of them and nowhere near most other values, so the answer is not the
  // closed form, and no points may say it is.
  const Checker& c = checker("sample-12.3-two-mass-pulley.yaml");
  const std::string t = "2*F*m_B/(9*m_A + 4*m_B)";
  const std::string vanishing = "(m_A/m_B - 1169/1610)*(m_A/m_B - 895/629)*(m_A/m_B - 1586/521)*(m_A/m_B - 1879/550)";
  const CheckResult attack = c.check("T", t + " + F*" + vanishing);
  CHECK(attack.verdict == Verdict::incorrect);
  CHECK(attack.method == "exact");
  CHECK(attack.summary == "the answer agrees with the correct one only for some values of the parameters");
  // A rational answer is decided by normal(), with no random points at all: the same verdict
  // from every seed, for the honest answers too.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.3-two-mass-pulley.yaml", test::rules());
  for (const std::uint64_t seed : {1u, 2u, 77u}) {
    const auto s = seeded(*a, seed);
    const CheckResult right = s->check("T", "F*m_B/(4.5*m_A + 2*m_B)");
    CHECK(right.verdict == Verdict::correct);
    CHECK(right.method == "exact");
    CHECK(right.summary == "equal to the closed form");
    CHECK(s->check("T", t + " + F*" + vanishing).method == "exact");
    // With a root in it the product is no rational function, and normal() proves nothing:
    // the points drawn for the check, where it does not vanish, decide.
    const CheckResult root = s->check("T", t + " + F*sqrt(m_A/m_B)*" + vanishing);
    CHECK(root.verdict == Verdict::incorrect);
    CHECK(root.method == "numeric");
    CHECK(root.summary == "the answer agrees with the correct one only for some values of the parameters");
  }
}

TEST_CASE("Check: an answer correct only on one side of an abs() kink is incorrect", "[check][trust]") {
  // Sample 12.7: N_A = m g (1/2 - mu h/l), mu = 0.3, so every point near the values has
  // mu > 1/10, where abs(mu - 1/10) - (mu - 1/10) is 0; below 1/10 it is 2 (1/10 - mu), not 0.
  const std::string n_a = "m*g*(1/2 - mu*h/l)";
  const CheckResult one_side = suitcase().check("N_A", n_a + " + m*g*(abs(mu - 1/10) - (mu - 1/10))");
  CHECK(one_side.verdict == Verdict::incorrect);
  CHECK(one_side.summary == "the answer agrees with the correct one only for some values of the parameters");
  // sqrt(x^2) is |x|: the same kink.
  CHECK(suitcase().check("N_A", n_a + " + m*g*(sqrt((mu - 1/10)^2) - (mu - 1/10))").summary ==
        "the answer agrees with the correct one only for some values of the parameters");
  CHECK(suitcase().check("N_A", n_a + " + m*g*(((mu - 1/10)^4)^(1/4) - abs(mu - 1/10))").verdict == Verdict::correct);
  // abs() of the correct answer: N_A < 0 once mu h/l > 1/2, where the two differ; but there
  // the suitcase tips, which the model's N_A >= 0 leaves out: right wherever the model holds.
  CHECK(suitcase().check("N_A", "abs(" + n_a + ")").verdict == Verdict::correct);
  CHECK(suitcase().check("N_A", "-abs(" + n_a + ")").summary == "the sign is wrong");
  // Equal on both sides of the kink: (|x| + x)(|x| - x) = |x|^2 - x^2 = 0 for every x.
  const CheckResult both =
      suitcase().check("N_A", n_a + " + m*g*(abs(mu - 1/10) + mu - 1/10)*(abs(mu - 1/10) - mu + 1/10)");
  CHECK(both.verdict == Verdict::correct);
  CHECK(both.echo_text.find("abs(") != std::string::npos);
  // |l - h| = |h - l| whatever the signs: one kink, not two. Five arguments up to their sign
  // would be 32 combinations, more than are tried.
  CHECK(suitcase().check("N_A", n_a + " + m*g*(abs(l - h) - abs(h - l))/l").verdict == Verdict::correct);
  const std::string three =
      " + m*g*(abs(mu - 1/3) - abs(1/3 - mu)) + m*g*(abs(l - h) - abs(h - l) + abs(l - 2*h) - abs(2*h - l))/l";
  CHECK(suitcase().check("N_A", n_a + three + " + m*g*(abs(l - 3*h) - abs(3*h - l))/l").verdict == Verdict::correct);
  CHECK(suitcase()
            .check("N_A", n_a + three + " + m*g*(abs(l - 3*h) - abs(3*h - l) + abs(l - 4*h) - abs(4*h - l))/l")
            .summary ==
        "the answer uses abs(), and tackle could not decide it for every sign of its argument: write it without abs()");
  // A side too narrow to find (|mu - 1/10| < 10^-15): undecided, never correct.
  const CheckResult narrow =
      suitcase().check("N_A", n_a + " + m*g*(abs((mu - 1/10)^2 - 10^(-30)) - ((mu - 1/10)^2 - 10^(-30)))");
  CHECK(narrow.verdict == Verdict::undecided);
  CHECK(narrow.summary ==
        "the answer uses abs(), and tackle could not decide it for every sign of its argument: write it without abs()");
}

TEST_CASE("Check: the points a numeric verdict rests on are drawn for each check", "[check][trust]") {
  // The incline: N_A = m_A g cos(theta). sin(theta + pi/2) is cos(theta), an identity normal()
  // does not know: decided at points, exactly (theta's points are rational points on the
  // circle). A correct answer is correct at every point, so from every seed (an answer wrong
  // away from the fixed points is wrong at the fresh ones: above).
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/incline-and-hanging-block.yaml", test::rules());
  for (const std::uint64_t seed : {1u, 5u, 123456789u}) {
    const CheckResult r = seeded(*a, seed)->check("N_A", "g*m_A*sin(theta + pi/2)");
    CHECK(r.verdict == Verdict::correct);
    CHECK(r.method == "exact rationals");
    CHECK(r.summary == "equal to the closed form (in exact arithmetic at 8 random points)");
  }
  // With no points to draw (a library caller's choice), an answer only points could decide
  // is never correct; a rational one is still proved.
  CheckOptions none;
  none.points = 0;
  const Checker pointless(*a, none);
  CHECK(pointless.check("N_A", "g*m_A*sin(theta + pi/2)").verdict == Verdict::undecided);
  const auto pulley = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.3-two-mass-pulley.yaml", test::rules());
  CHECK(Checker(*pulley, none).check("T", "F*m_B/(4.5*m_A + 2*m_B)").summary == "equal to the closed form");
  // Without a seed: unpredictable points, the same verdict.
  const Checker unseeded(*a);
  CHECK(unseeded.check("N_A", "g*m_A*sin(theta + pi/2)").verdict == Verdict::correct);
  CHECK(unseeded.check("N_A", "g*m_A*sin(theta - pi/2)").summary == "the sign is wrong");
}

TEST_CASE("Check: pi in an answer is a number, and sin(pi) divides by zero", "[check][typed]") {
  const Checker& incline = checker("incline-and-hanging-block.yaml");
  CHECK(incline.check("N_A", "g*m_A*sin(theta + pi/2)").verdict == Verdict::correct);
  CHECK(incline.check("N_A", "g*m_A*cos(theta)*sin(pi/2)^2").verdict == Verdict::correct);
  // sin(pi) is 0: the division is what is wrong, not the name pi.
  const CheckResult r = checker("sample-12.3-two-mass-pulley.yaml").check("T", "F/(sin(pi))");
  CHECK(r.verdict == Verdict::invalid);
  CHECK(r.summary == "at column 2: division by zero");
}

TEST_CASE("Check: messages echo whole characters and escape control bytes", "[check][invalid]") {
  // The euro sign is three bytes (E2 82 AC); the bell is byte 7.
  CHECK(board().check("T_HI", "m*a\u20ac").summary == "at column 4: unexpected character '\u20ac'");
  CHECK(board().check("T_HI", "m*a\x07").summary == "at column 4: unexpected character '\\x07'");
  CHECK(board().check("T_HI", "m*a\u202e").summary == "at column 4: unexpected character '\\u202E'");
  CHECK(board()
            .check("T\x1b[2J", "m")
            .summary.rfind("'T\\x1B[2J' is not an unknown tackle can check for this problem (", 0) == 0);
  CHECK(board().check("T_HI", "x\x01 = m").summary == "write 'T_HI = ...' or just the expression (found 'x\\x01 = ')");
  std::string problem;
  CHECK_FALSE(checker("sample-12.3-two-mass-pulley.yaml").values_for({{"F", "1\x08"}}, problem));
  CHECK(problem == "the value of 'F' is '1\\x08' (expected a number in N)");
}

TEST_CASE("Check: a value a positive parameter cannot have is out of its domain", "[check][variants]") {
  // Masses are assumed positive (README, Units): a variant with m_A = -40 kg would be graded
  // against closed forms simplified for positive masses.
  const Checker& c = checker("sample-12.3-two-mass-pulley.yaml");
  std::string problem;
  bool out_of_domain = false;
  CHECK_FALSE(c.values_for({{"m_A", "-40"}}, problem, &out_of_domain));
  CHECK(out_of_domain);
  CHECK(problem == "the value of 'm_A' is -40 kg, but 'm_A' is assumed positive (a mass)");
  CHECK_FALSE(c.values_for({{"m_B", "0"}}, problem, &out_of_domain));
  CHECK(problem == "the value of 'm_B' is 0 kg, but 'm_B' is assumed positive (a mass)");
  // A force may have either sign; a name that is not a parameter is another kind of problem.
  CHECK(c.values_for({{"F", "-120"}}, problem, &out_of_domain));
  CHECK_FALSE(c.values_for({{"G", "1"}}, problem, &out_of_domain));
  CHECK_FALSE(out_of_domain);
}

namespace {
nlohmann::json prairielearn_results(const std::string& lines) {
  GradeOptions options;
  options.format = ResultsFormat::prairielearn;
  return nlohmann::json::parse(grade(lines, options).results);
}
}  // namespace

TEST_CASE("Grading: PrairieLearn's ungradable submission tells nothing of the other answers",
          "[check][batch][platform]") {
  const auto bad = prairielearn_results(
      "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n"
      "{\"id\": \"b\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/d\"}\n"
      "{\"id\": \"c\", \"unknown\": \"T_HI\", \"answer\": \"m*a*\"}\n");
  CHECK(bad["gradable"] == false);
  CHECK_FALSE(bad.contains("score"));
  CHECK_FALSE(bad.contains("tests"));
  const std::string text = bad.dump();
  for (const char* word : {"correct", "factor", "points"}) {
    INFO(word);
    CHECK(text.find(word) == std::string::npos);
  }
}

TEST_CASE("Grading: a format error names its line once", "[check][batch][platform]") {
  const auto j = prairielearn_results(
      "not json\n"
      "{\"unknown\": \"T_HI\", \"answer\": \"m\", \"params\": [1]}\n"
      "{\"id\": \"s3\", \"unknown\": \"T_HI\", \"answer\": \"m\", \"params\": 2}\n");
  REQUIRE(j["format_errors"].size() == 3);
  CHECK(j["format_errors"][0] == "line 1: not a JSON object with id, unknown and answer");
  CHECK(j["format_errors"][1] == "line 2: T_HI: \"params\" is not an object of parameter values");
  CHECK(j["format_errors"][2] == "s3: T_HI: line 3: \"params\" is not an object of parameter values");
}

TEST_CASE("Grading: a batch line is the JSON library's own dump of the result, byte for byte", "[check][batch]") {
  // The batch writes its lines itself (a sixth of a check went into building JSON objects);
  // the library's dump of the same object is the reference.
  static const char with_nul[] = "nul\0one\x01\x1f";  // (its length from its size: it holds a NUL)
  const std::vector<std::string> texts{"",
                                       "plain",
                                       "quote \" and backslash \\",
                                       "tab\tnew\nline\rcr\bbs\fff",
                                       std::string(with_nul, sizeof with_nul - 1),
                                       "del \x7f",
                                       "UTF-8: \xce\xbc N, \xe2\x89\xa5",
                                       "not UTF-8: \xe9t\xe9",
                                       "cut \xe2\x89",
                                       "\xf0\x9f\x98\x80 emoji"};
  for (const double score : {0.0, 1.0, 0.5, 0.25, 1e-7, 2.0 / 3.0})
    for (const auto& t : texts) {
      CheckResult r;
      r.unknown = t;
      r.verdict = Verdict::incorrect;
      r.score = score;
      r.summary = t + " summary";
      r.findings = {{"code", t}, {t, "message"}};
      r.method = "numeric";
      r.echo_text = t;
      r.echo_latex = "\\frac{" + t + "}{2}";
      for (const std::string& id : {std::string(), t, std::string("s1")}) {
        // The single answer's JSON (the library's), without its version: the same fields.
        auto j = nlohmann::ordered_json::parse(result_json(r, t, id));
        j.erase("version");
        CHECK(result_line(r, t, id) == j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
      }
    }
  // No findings: an empty array.
  CheckResult ok;
  ok.unknown = "T";
  ok.verdict = Verdict::correct;
  ok.score = 1.0;
  CHECK(
      result_line(ok, "T = 1", "") ==
      R"({"unknown":"T","answer":"T = 1","verdict":"correct","score":1.0,"summary":"","findings":[],"method":"","read_as":"","latex":""})");
}

TEST_CASE("Check: without the LaTeX echo, no answer gets one, a number with a unit neither", "[check]") {
  auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  CheckOptions options;
  options.echo_latex = false;
  const Checker quiet(*a, options);
  for (const std::string& answer : {std::string("m*g*(1/2 - mu*h/l)"), std::string("29.43 N"), std::string("m*g")}) {
    const auto r = quiet.check("N_A", answer);
    CHECK(r.echo_latex.empty());
    CHECK(!r.echo_text.empty());  // the text echo stays
  }
  CHECK(suitcase().check("N_A", "29.43 N").echo_latex == "29.43\\,\\mathrm{N}");
}

TEST_CASE("Check: rates a string ties are drawn tied, so a right answer in either is correct", "[check]") {
  // An Atwood machine whose blocks are also joined by a damper c. By hand: the string keeps
  // y_A + y_B, so dot(y_B) = -dot(y_A) = -v; the damper's length y_A - y_B grows at 2 v and
  // pulls A down and B up with 2 c v. A: T - m_A g - 2 c v = m_A a; B: T - m_B g + 2 c v =
  // -m_B a; their difference: a = (g (m_B - m_A) - 4 c v)/(m_A + m_B). Written in dot(y_A)
  // alone or in dot(y_B) alone it is right; drawn apart, the rates made it wrong.
  const std::string text = R"(title: "An Atwood machine whose blocks are joined by a damper too"
parameters:
  m_A: {value: 3, unit: kg}
  m_B: {value: 5, unit: kg}
  g: {value: 9.81, unit: m/s^2}
  c: {value: 4, unit: N*s/m}
gravity: -g
bodies:
  A: {mass: m_A, position: y_A}
  B: {mass: m_B, position: y_B}
  C: {mass: 0, position: y_C}
strings:
  - {name: s, path: [A, C, B], tension: T}
connections:
  - {type: fixed, body: C}
  - {type: pulley, at: C}
  - {type: damper, name: dp, path: [A, B], c: c}
layout: {y_A: -2, y_B: -3, y_C: 0}
find: [ddot(y_A), T]
)";
  const auto analysis = analyze_text(text, "atwood-damper.yaml", test::rules());
  const Checker c(*analysis);
  for (const char* a : {"(g*(m_B - m_A) - 4*c*dot(y_A))/(m_A + m_B)", "(g*(m_B - m_A) + 4*c*dot(y_B))/(m_A + m_B)",
                        "(g*(m_B - m_A) - 2*c*dot(y_A) + 2*c*dot(y_B))/(m_A + m_B)"}) {
    INFO(a);
    CHECK(c.check("ddot(y_A)", a).verdict == Verdict::correct);
  }
  // The damper's force counted once (2 c v, not 4 c v): wrong whichever rate it is written in.
  CHECK(c.check("ddot(y_A)", "(g*(m_B - m_A) - 2*c*dot(y_A))/(m_A + m_B)").verdict == Verdict::incorrect);
  CHECK(c.check("ddot(y_A)", "(g*(m_B - m_A) + 2*c*dot(y_B))/(m_A + m_B)").verdict == Verdict::incorrect);
}

TEST_CASE("Check: an answer that ends too early is a syntax error, one past a limit is too large", "[check][limits]") {
  const auto early = suitcase().check("a_C", "((((((");
  CHECK(early.verdict == Verdict::invalid);
  CHECK(early.summary == "at column 7: expression ends too early");
  CHECK(early.findings.front().code == "syntax");
  const auto deep = suitcase().check("a_C", "mu*g^1000000");
  CHECK(deep.verdict == Verdict::invalid);
  CHECK(deep.findings.front().code == "too_large");
  const auto step = suitcase().check_equation("N_A + N_B = (((");
  CHECK(step.verdict == Verdict::invalid);
  CHECK(step.findings.front().code == "syntax");
}

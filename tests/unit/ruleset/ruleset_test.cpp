#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "core/diagnostics.hpp"
#include "ruleset/builtin_rules.hpp"
#include "ruleset/ruleset.hpp"

using namespace tackle;

namespace {

// Every problem a rule text has, formatted; empty when it reads.
std::vector<std::string> rule_errors(const std::string& text, const std::string& file) {
  try {
    (void)parse_rule(text, file);
  } catch (const InputError& e) {
    std::vector<std::string> got;
    for (const auto& d : e.diagnostics()) got.push_back(format(d));
    return got;
  }
  return {};
}

}  // namespace

TEST_CASE("Rules: the bundled rules load and declare what they need", "[rules]") {
  const RuleSet rules = load_rules(TACKLE_SOURCE_DIR "/rules");
  CHECK(rules.names() == std::vector<std::string>{"ball_and_socket",
                                                  "ball_joint",
                                                  "cable",
                                                  "collar",
                                                  "contact",
                                                  "couple",
                                                  "damper",
                                                  "driven_wheel",
                                                  "elastic_cord",
                                                  "fixed",
                                                  "fixed_support",
                                                  "force",
                                                  "free_wheel",
                                                  "friction_between",
                                                  "hinge",
                                                  "hinge_with_moments",
                                                  "link",
                                                  "pin",
                                                  "pin_joint",
                                                  "pulley",
                                                  "rod",
                                                  "roller",
                                                  "rolling",
                                                  "same_motion",
                                                  "skidding_wheel",
                                                  "slider_joint",
                                                  "sliding",
                                                  "sliding_between",
                                                  "spring",
                                                  "sticking",
                                                  "sticking_between",
                                                  "string",
                                                  "unknown_force",
                                                  "weld",
                                                  "weld_joint"});
  const Rule* s = rules.find("string");
  REQUIRE(s);
  REQUIRE(s->unknowns.size() == 1);
  CHECK(s->unknowns[0].name_template == "T_{name}");
  CHECK(s->unknowns[0].dimension == Dimension::force());
  CHECK(s->validity.size() == 1);
  CHECK(s->one_of == std::vector<std::vector<std::string>>{{"path", "length"}});
}

TEST_CASE("Rules: a rule file with errors is reported like a description, all at once", "[rules]") {
  const std::string text =
      "type: spring\n"
      "summry: a spring\n"
      "needs: {on: bdy}\n"
      "loads:\n"
      "  - {on: on, force: \"-k*\"}\n";
  CHECK(rule_errors(text, "rules/spring.yaml") ==
        std::vector<std::string>{
            "rules/spring.yaml:2:1: unknown key 'summry' in the rule (did you mean 'summary'?)",
            "rules/spring.yaml:3:13: unknown argument kind 'bdy' (expected one of: body, point, points, expr, name, "
            "vector, moment)",
            "rules/spring.yaml:5:5: in '-k*': unknown name 'k' (known: on)",
        });
}

TEST_CASE("Rules: a sketch kind and the summary's symbols are checked", "[rules]") {
  const std::string text =
      "type: bumper\n"
      "summary: a bumper pushing with {N}, at most {mu*M}\n"
      "sketch: zigzag\n"
      "needs: {on: body, mu: expr}\n"
      "unknowns:\n"
      "  - {local: N, name: N_b, dimension: force}\n";
  CHECK(rule_errors(text, "rules/bumper.yaml") ==
        std::vector<std::string>{
            "rules/bumper.yaml:3:9: 'sketch' is 'zigzag' (expected line, spring, damper, pulley, support, arrow, "
            "contact, surface, wheel, pin, joint, rod or couple)",
            "rules/bumper.yaml:2:10: in 'mu*M': unknown name 'M' (known: mu, N)",
        });
  // Read, the rule keeps them: the sketch kind, and the summary as written.
  const Rule r = parse_rule(
      "type: bumper\nsummary: pushing with {N}\nsketch: spring\nneeds: {on: body}\nunknowns:\n"
      "  - {local: N, name: N_b, dimension: force}\n",
      "rules/bumper.yaml");
  CHECK(r.sketch == "spring");
  CHECK(r.summary == "pushing with {N}");
}

TEST_CASE("Rules: an argument used as the wrong kind", "[rules]") {
  const std::string text =
      "type: weight\n"
      "needs: {on: expr}\n"
      "loads:\n"
      "  - {on: on, force: on}\n";
  try {
    (void)parse_rule(text, "rules/weight.yaml");
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(format(e.diagnostics()[0]) ==
          "rules/weight.yaml:4:5: a load uses argument 'on' as body but the rule declares it as expr");
  }
}

TEST_CASE("Rules: every bundled rule reads without a problem", "[rules]") {
  const RuleSet rules = load_rules(TACKLE_SOURCE_DIR "/rules", RuleLoading::all);
  CHECK(rules.names().size() == 35);
  CHECK_NOTHROW(load_rules(TACKLE_SOURCE_DIR "/rules").read_all());
}

TEST_CASE("Rules: a rule is read when first used, its problems then, or all at once from read_all", "[rules]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("tackle-rules-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "good.yaml")
      << "type: good\nsummary: a force\nneeds: {on: body, force: expr}\nloads:\n  - {on: on, force: force}\n";
  std::ofstream(dir / "broken.yaml") << "type: broken  # a comment\nsummry: oops\n";
  std::ofstream(dir / "flow.yaml") << "{type: flow, summry: read at once}\n";
  // The flow-style file has no plain type line: it is read at once, and its problem reported.
  try {
    (void)load_rules(dir.string());
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(e.diagnostics()[0].message == "unknown key 'summry' in the rule (did you mean 'summary'?)");
  }
  fs::remove(dir / "flow.yaml");
  const RuleSet rules = load_rules(dir.string());
  CHECK(rules.names() == std::vector<std::string>{"broken", "good"});
  REQUIRE(rules.find("good"));
  CHECK(rules.find("good")->loads.size() == 1);
  CHECK(rules.find("nothing") == nullptr);
  try {
    (void)rules.find("broken");
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    REQUIRE(e.diagnostics().size() == 1);
    CHECK(format(e.diagnostics()[0]) ==
          (dir / "broken.yaml").string() + ":2:1: unknown key 'summry' in the rule (did you mean 'summary'?)");
  }
  CHECK_THROWS_AS(rules.read_all(), InputError);
  CHECK_THROWS_AS(load_rules(dir.string(), RuleLoading::all), InputError);
  fs::remove_all(dir);
}

TEST_CASE("Rules: every rule compiled in is the rule its file reads as, and is used only for that very text",
          "[rules]") {
  namespace fs = std::filesystem;
  // One compiled rule per rules/*.yaml, each the same as parse_rule() of the file (a field the
  // build-time writer left out would differ here).
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(TACKLE_SOURCE_DIR "/rules"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  REQUIRE(builtin_rules().size() == files.size());
  for (const BuiltinRule& b : builtin_rules()) {
    const fs::path f = fs::path(TACKLE_SOURCE_DIR "/rules") / std::string(b.name);
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    CHECK(text.str() == b.text);
    CHECK(made_from(b, f.string()) == parse_rule(text.str(), f.string()));
  }
  // Loaded with them: every rule is the one read from its file, locations and all.
  const RuleSet with = load_rules(TACKLE_SOURCE_DIR "/rules", RuleLoading::when_used, builtin_rules());
  const RuleSet without = load_rules(TACKLE_SOURCE_DIR "/rules");
  REQUIRE(with.names() == without.names());
  for (const auto& name : with.names()) CHECK(*with.find(name) == *without.find(name));
  // An edited rule file is read from its text, not made from the compiled rule.
  const fs::path dir = fs::temp_directory_path() / ("tackle-builtin-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& f : files) fs::copy_file(f, dir / f.filename());
  {
    std::ifstream in(dir / "hinge.yaml");
    std::ostringstream text;
    text << in.rdbuf();
    std::string edited = text.str();
    const std::string from = "summary: a hinge";
    REQUIRE(edited.find(from) != std::string::npos);
    edited.replace(edited.find(from), from.size(), "summary: an edited hinge");
    std::ofstream(dir / "hinge.yaml", std::ios::trunc) << edited;
  }
  const RuleSet edited = load_rules(dir.string(), RuleLoading::when_used, builtin_rules());
  CHECK(edited.find("hinge")->summary.rfind("an edited hinge", 0) == 0);
  CHECK(edited.find("rod")->at.file == (dir / "rod.yaml").string());
  fs::remove_all(dir);
}

TEST_CASE("Rules: a missing rules directory is an input error", "[rules]") {
  CHECK_THROWS_AS(load_rules("/nonexistent/rules"), InputError);
}

TEST_CASE("Rules: a mapping where a list belongs is an error, not a crash (found by fuzzing)", "[rules][fuzz]") {
  const std::string text =
      "type: skidding\n"
      "unknowns:\n"
      "  mptions:\n"
      "  - a list under a key\n"
      "one_of: [[a], b]\n"
      "assumptions: {a: b}\n";
  CHECK(
      rule_errors(text, "rules/skidding.yaml") ==
      std::vector<std::string>{"rules/skidding.yaml:5:11: 'one_of' names argument 'a', which the rule does not declare",
                               "rules/skidding.yaml:5:15: a group of 'one_of' is a scalar (expected a list)",
                               "rules/skidding.yaml:3:3: 'unknowns' is a mapping (expected a list)",
                               "rules/skidding.yaml:6:14: 'assumptions' is a mapping (expected a list)"});
}

TEST_CASE("Rules: a check or an assumption 'when' an argument names one the rule declares", "[rules]") {
  const std::string text =
      "type: wheel\n"
      "needs: {at: point}\n"
      "optional: {radius: {kind: expr, dimension: length}}\n"
      "checks:\n"
      "  - {steady_at: at, when: radiuss}\n"
      "assumptions:\n"
      "  - {text: \"a radius\", when: radios}\n"
      "  - {text: \"fine\", when: radius}\n";
  CHECK(rule_errors(text, "rules/wheel.yaml") ==
        std::vector<std::string>{
            "rules/wheel.yaml:5:5: 'when' names argument 'radiuss', which the rule does not declare",
            "rules/wheel.yaml:7:5: 'when' names argument 'radios', which the rule does not declare"});
}

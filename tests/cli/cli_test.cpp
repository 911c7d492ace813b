// The tackle command as a user runs it: outputs, golden reports, exit codes.
#include <algorithm>
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "description/yaml_reader.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "../support/helpers.hpp"

namespace fs = std::filesystem;

namespace {

struct Run {
  int code;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Run run_tackle(const std::string& args, const std::string& cwd = "") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-cli-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string cmd = (cwd.empty() ? "" : "cd '" + cwd + "' && ") + std::string(TACKLE_BINARY) + " " + args + " >" +
                          (dir / "out").string() + " 2>" + (dir / "err").string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out"), slurp(dir / "err")};
  fs::remove_all(dir);
  return r;
}

const std::string examples = TACKLE_SOURCE_DIR "/examples/";

}  // namespace

TEST_CASE("CLI: solve --format json gives sample 12.3's numbers and parseable closed forms", "[cli]") {
  const Run r = run_tackle("solve " + examples + "sample-12.3-two-mass-pulley.yaml --format json");
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["version"] == 2);
  CHECK(j["status"] == "determined");
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& u : j["unknowns"]) by_name[u["name"]] = u;
  CHECK(by_name["T"]["value"] == 20.0);
  CHECK(by_name["T"]["unit"] == "N");
  CHECK(by_name["T"]["closed_form"] == "2*F*m_B/(9*m_A + 4*m_B)");
  CHECK(by_name["T"]["latex"] == "\\frac{2 m_{B} F}{9 m_{A} + 4 m_{B}}");
  CHECK(by_name["ddot(x_A)"]["value"] == -2.25);
  CHECK(by_name["ddot(x_A)"]["unit"] == "m/s^2");
  CHECK(by_name["ddot(x_B)"]["value"] == -1.5);
  // closed_form parses back with the problem's own symbols.
  const auto a = tackle::analyze_file(examples + "sample-12.3-two-mass-pulley.yaml", tackle::test::rules());
  for (const auto& [name, u] : by_name) {
    auto parsed = tackle::parse_expression(u["closed_form"].get<std::string>(), *a->model.symbols);
    REQUIRE(parsed.value);
    CHECK(GiNaC::normal(*parsed.value - *a->solution.value_of(a->model.symbols->find(name)->sym)).is_zero());
  }
}

TEST_CASE("CLI: derive prints each example as in its approved text report", "[cli][golden]") {
  for (const auto& e : fs::directory_iterator(examples)) {
    if (e.path().extension() != ".yaml") continue;
    SECTION(e.path().stem().string()) {
      // Run from the source directory so that file names in the report are relative.
      const Run r = run_tackle("derive examples/" + e.path().filename().string());
      REQUIRE(r.code == 0);
      const fs::path approved = fs::path(TACKLE_SOURCE_DIR) / "tests/approved" / (e.path().stem().string() + ".txt");
      if (std::getenv("TACKLE_UPDATE_GOLDEN")) {
        std::ofstream(approved, std::ios::binary) << r.out;
      }
      CHECK(r.out == slurp(approved));
    }
  }
}

// Output identical from run to run, across processes and memory layouts: see
// tests/determinism/run.sh (the ctest entry determinism_across_processes).

TEST_CASE("CLI: exit codes: 0 ok, 1 input error, 2 usage", "[cli]") {
  CHECK(run_tackle("--help").code == 0);
  CHECK(run_tackle("derive --help").code == 0);
  const Run version = run_tackle("--version");
  CHECK(version.code == 0);
  CHECK(version.out.rfind("tackle 0.1.0 (rules: ", 0) == 0);
  CHECK(run_tackle("").code == 2);
  CHECK(run_tackle("derive").code == 2);
  CHECK(run_tackle("solve " + examples + "atwood-machine.yaml --format pdf").code == 2);
  CHECK(run_tackle("frobnicate").code == 2);
  const Run missing = run_tackle("solve no/such/file.yaml");
  CHECK(missing.code == 1);
  CHECK(missing.err == "no/such/file.yaml: cannot read the file\n");
}

TEST_CASE("CLI: page writes one self-contained page, a bad endpoint is a usage error, a bad file an input error",
          "[cli][page]") {
  const Run page = run_tackle("page " + examples + "sample-12.3-two-mass-pulley.yaml --endpoint /tackle");
  CHECK(page.code == 0);
  CHECK(page.out.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(page.out.find("\"endpoint\":\"/tackle\"") != std::string::npos);
  CHECK(page.out.find("katex.render") != std::string::npos);
  const Run endpoint =
      run_tackle("page " + examples + "sample-12.3-two-mass-pulley.yaml --endpoint \"/a; script-src *\"");
  CHECK(endpoint.code == 2);
  CHECK(endpoint.err.find("--endpoint") != std::string::npos);
  CHECK(endpoint.err.find("';'") != std::string::npos);
  const Run missing = run_tackle("page no/such/file.yaml");
  CHECK(missing.code == 1);
  CHECK(missing.err == "no/such/file.yaml: cannot read the file\n");
  CHECK(run_tackle("page").code == 2);
}

// Only the subcommand named gets its options defined (start-up): what each one accepts and
// says must not depend on that.
TEST_CASE("CLI: each subcommand's options are there whichever way it is named", "[cli]") {
  for (const std::string prefix :
       {"", "--rules " TACKLE_SOURCE_DIR "/rules ", "--rules=" TACKLE_SOURCE_DIR "/rules "}) {
    const Run help = run_tackle(prefix + "check --help");
    CHECK(help.code == 0);
    CHECK(help.out.find("--require-simplified") != std::string::npos);
    CHECK(help.out.find("--results-format") != std::string::npos);
    const Run isolate = run_tackle(prefix + "isolate --help");
    CHECK(isolate.out.find("--all") != std::string::npos);
    CHECK(isolate.out.find("--require-simplified") == std::string::npos);
  }
  const Run top = run_tackle("--help");
  for (const char* sub : {"derive", "solve", "isolate", "key", "sheet", "page", "sweep", "simulate", "check"})
    CHECK(top.out.find(std::string("  ") + sub) != std::string::npos);
  const Run needs = run_tackle("check " + examples + "sample-12.8-sign-board.yaml --answer x");
  CHECK(needs.code == 2);
  CHECK(needs.err == "--answer requires --unknown\nRun with --help for more information.\n");
  const Run checked = run_tackle("--rules " TACKLE_SOURCE_DIR "/rules check " + examples +
                                 "sample-12.8-sign-board.yaml --unknown T_HI --answer 'm*a*l/(2*d)'");
  CHECK(checked.code == 0);
  CHECK(checked.out.rfind("correct", 0) == 0);
}

TEST_CASE("CLI: a bad description reports every located problem on stderr and exits 1", "[cli]") {
  const fs::path bad = fs::temp_directory_path() / "tackle-bad.yaml";
  std::ofstream(bad) << "title: bad\nbodies:\n  A: {mas: m, position: x_A}\nloads:\n  - {on: Q, force: F}\n";
  const Run r = run_tackle("derive " + bad.string());
  CHECK(r.code == 1);
  CHECK(r.out.empty());
  CHECK(r.err == bad.string() + ":3:7: unknown key 'mas' in body 'A' (did you mean 'mass'?)\n" + bad.string() +
                     ":5:10: unknown body 'Q' (known: A)\n" + bad.string() +
                     ":5:20: 'force' of a 'force' connection: unknown name 'F' (known: t, x_A)\n");
  fs::remove(bad);
}

TEST_CASE("CLI: each kind of bad description gets its located errors and exit 1", "[cli][errors]") {
  // tests/data/bad/NAME.yaml holds one mistake; NAME.expected is the exact stderr.
  const fs::path dir = fs::path(TACKLE_SOURCE_DIR) / "tests/data/bad";
  int kinds = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".yaml") continue;
    ++kinds;
    SECTION(e.path().stem().string()) {
      const Run r = run_tackle("solve " + e.path().filename().string(), dir.string());
      CHECK(r.code == 1);
      CHECK(r.out.empty());
      fs::path expected = e.path();
      expected.replace_extension(".expected");
      CHECK(r.err == slurp(expected));
    }
  }
  CHECK(kinds >= 10);
}

TEST_CASE("CLI: a bad rules directory is an input error", "[cli]") {
  const Run r = run_tackle("--rules /no/such/dir solve " + examples + "atwood-machine.yaml");
  CHECK(r.code == 1);
  CHECK(r.err == "/no/such/dir: the rules directory does not exist (expected rules/*.yaml)\n");
}

TEST_CASE("CLI: -o writes the report to a file", "[cli]") {
  const fs::path out = fs::temp_directory_path() / "tackle-out.tex";
  const Run r = run_tackle("derive " + examples + "figure-12.5c-force-doubled.yaml --format latex -o " + out.string());
  CHECK(r.code == 0);
  CHECK(r.out.empty());
  const std::string tex = slurp(out);
  CHECK(tex.find("\\documentclass") == 0);
  CHECK(tex.find("m_{\\mathrm{eff}} = \\frac{m}{4}") != std::string::npos);
  fs::remove(out);
}

TEST_CASE("CLI: sample 12.9 reports exactly the O_y + G_y combination and the other five values", "[cli]") {
  const Run r = run_tackle("solve " + examples + "sample-12.9-indeterminate.yaml --format json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["status"] == "underdetermined");
  CHECK(j["free"] == nlohmann::json::array({"G_y"}));
  REQUIRE(j["combinations"].size() == 1);
  CHECK(j["combinations"][0]["expression"] == "G_y + O_y");
  CHECK(j["combinations"][0]["closed_form"] == "-a*b*m/(2*d)");
  CHECK(j["combinations"][0]["value"] == Approx(-3.0));
  CHECK(j["combinations"][0]["unit"] == "N");
  std::map<std::string, double> values;
  for (const auto& u : j["unknowns"]) values[u["name"]] = u["value"];
  CHECK(values["O_x"] == Approx(0.0).margin(1e-12));
  CHECK(values["O_z"] == Approx(97.0));
  CHECK(values["G_x"] == Approx(6.0));
  CHECK(values["G_z"] == Approx(102.0));
  CHECK(values["T_HI"] == Approx(6.78233).epsilon(1e-5));
}

TEST_CASE("CLI: sample 12.8's JSON gives T = 6.78 N and its closed form", "[cli]") {
  const Run r = run_tackle("solve " + examples + "sample-12.8-sign-board.yaml --format json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["unknowns"][0]["closed_form"] == "a*l*m/(2*d)");  // the book: T = m a l/(2 d)
  // The same in the parameters alone, for a program that does not know l = sqrt(b^2 + d^2 + e^2).
  CHECK(j["unknowns"][0]["in_parameters"] == "a*m*sqrt(b^2 + d^2 + e^2)/(2*d)");
  CHECK(j["unknowns"][0]["value"] == Approx(6.78233).epsilon(1e-5));
}

TEST_CASE("CLI: JSON conditions carry the solved forms and whether they hold", "[cli][validity]") {
  const Run r = run_tackle("solve " + examples + "sample-12.7-suitcase.yaml --format json");
  REQUIRE(r.code == 0);
  const auto c = nlohmann::json::parse(r.out)["conditions"][0];
  CHECK(c["inequality"] == "N_A >= 0");
  CHECK(c["simplified"] == "g*m*(l - 2*h*mu)/(2*l) >= 0");
  CHECK(c["holds"] == true);
  CHECK(c["solved"][1]["condition"] == "l >= 2*h*mu");
  CHECK(c["meaning"] == "the contact pushes");
}

TEST_CASE("CLI: isolate finds axis OG for the sign-board's rod, with usage and input errors", "[cli][isolate]") {
  const Run r = run_tackle("isolate " + examples + "sample-12.8-sign-board.yaml T_HI");
  CHECK(r.code == 0);
  CHECK(r.out ==
        "T_HI: AMB board about G (axis OG, along y) contains it alone.\n"
        "    T_HI*d*(c - e)/l = a*m*(c - e)/2\n"
        "    T_HI = a*l*m/(2*d)  = 6.78233 N\n");
  CHECK(run_tackle("isolate " + examples + "sample-12.8-sign-board.yaml").code == 2);
  CHECK(run_tackle("isolate " + examples + "sample-12.8-sign-board.yaml T_HI --all").code == 2);
  const Run bad = run_tackle("isolate " + examples + "sample-12.8-sign-board.yaml T");
  CHECK(bad.code == 1);
  CHECK(bad.err == examples +
                       "sample-12.8-sign-board.yaml: 'T' is not an unknown of this problem (unknowns: O_x, O_y, "
                       "O_z, G_x, G_y, G_z, T_HI)\n");
  const auto j = nlohmann::json::parse(
      run_tackle("isolate " + examples + "sample-12.9-indeterminate.yaml --all --format json").out);
  REQUIRE(j["isolations"].size() == 7);
  CHECK(j["isolations"][1]["unknown"] == "O_y");
  CHECK(j["isolations"][1]["found"] == false);
  CHECK(j["isolations"][1]["impossible"] == true);
}

// By hand, for block A on block B with kinetic friction between them (A slips back on B):
// A's LMB along (1, -mu_k) is mu_k N_A - mu_k (N_A - m_A g) = m_A ddot(x_A), so ddot(x_A) =
// mu_k g; A's LMB (y) gives N_A = m_A g. B's acceleration needs the friction mu_k N_A, and
// N_B the weight of A: each takes two of the balances. A's and B's contacts are points, so no
// balance of B's moments is used (it would say F = m_B ddot(x_B)).
TEST_CASE("CLI: isolate analyses friction between two blocks in the regime that holds", "[cli][isolate]") {
  const Run r = run_tackle("isolate " + examples + "friction-block-on-block.yaml --all");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(r.out ==
        "ddot(x_A): LMB A (along [1, -mu_k]) contains it alone.\n"
        "    g*m_A*mu_k = m_A*ddot(x_A)\n"
        "    ddot(x_A) = g*mu_k  = 2.4525 m/s^2\n"
        "ddot(x_B): no single balance equation of one body contains it alone (no direction, point or axis does); it "
        "takes a system of equations.\n"
        "N_A: LMB A (y) contains it alone.\n"
        "    N_A - g*m_A = 0\n"
        "    N_A = g*m_A  = 19.62 N\n"
        "N_B: no single balance equation of one body contains it alone (no direction, point or axis does); it takes "
        "a system of equations.\n");
}

TEST_CASE("CLI: check one answer, as text and JSON, and usage errors exit 2", "[cli][check]") {
  const std::string board = examples + "sample-12.8-sign-board.yaml";
  Run r = run_tackle("check " + board + " --unknown T_HI --answer 'm*a*sqrt(b^2+d^2+e^2)/d'");
  CHECK(r.code == 0);
  CHECK(r.out ==
        "incorrect: off by a factor of 2 (the answer is twice the correct answer)\n"
        "  read as: a*m*sqrt(b^2 + d^2 + e^2)/d\n");
  r = run_tackle("check " + board + " --unknown T_HI --answer '1.53 lbf' --format json");
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["version"] == 1);
  CHECK(j["verdict"] == "correct");
  CHECK(j["method"] == "number");
  CHECK(run_tackle("check " + board).code == 2);
  CHECK(run_tackle("check " + board + " --unknown T_HI").code == 2);
  CHECK(run_tackle("check " + board + " --answer 3").code == 2);
  CHECK(run_tackle("check " + board + " --unknown T_HI --answer x --tolerance 2").code == 2);
}

TEST_CASE("CLI: check a free body diagram, as text and JSON, bad diagrams exit 1, usage 2", "[cli][check][fbd]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-fbd-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // By hand (sample 12.3): three strands of the string pull B toward C, along -x.
  std::ofstream(dir / "b.yaml")
      << "body: B\nforces:\n  - {name: T, at: pB, direction: [-1]}\n  - {name: T, at: pB, direction: [-1]}\n";
  std::ofstream(dir / "bad.yaml") << "body: B\nforces:\n  - {name: T, at: pQ, direction: [-1, 0]}\n";
  std::ofstream(dir / "rubric.yaml") << "fbd: {extra: 2, weights: {T: 2}}\n";
  const std::string pulley = examples + "sample-12.3-two-mass-pulley.yaml";
  Run r = run_tackle("check " + pulley + " --fbd " + (dir / "b.yaml").string());
  CHECK(r.code == 0);
  CHECK(r.out ==
        "free body diagram of B: incorrect: a strand of string s at pB is missing\n"
        "  a strand of string s at pB (T): drawn as your T\n"
        "  a strand of string s at pB (T): drawn as your T\n"
        "  a strand of string s at pB (T): missing\n"
        "score: 2 of 3\n");
  r = run_tackle("check " + pulley + " --fbd " + (dir / "b.yaml").string() + " --rubric " +
                 (dir / "rubric.yaml").string() + " --format json");
  CHECK(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["verdict"] == "incorrect");
  CHECK(j["score"] == 4.0);
  CHECK(j["max_score"] == 6.0);
  r = run_tackle("check " + pulley + " --fbd " + (dir / "bad.yaml").string());
  CHECK(r.code == 1);
  const std::string bad = (dir / "bad.yaml").string();
  CHECK(r.err == bad + ":3:19: 'pQ' is not a point or body of the problem (expected one of: A, B, C, pA, pB)\n" + bad +
                     ":3:34: 'direction' has 2 numbers (expected 1, one per axis)\n");
  CHECK(run_tackle("check " + pulley + " --fbd " + (dir / "b.yaml").string() + " --equation 'T = 1'").code == 2);
  CHECK(run_tackle("check " + pulley + " --unknown T --answer 1 --rubric " + (dir / "rubric.yaml").string()).code == 2);
  fs::remove_all(dir);
}

TEST_CASE("CLI: check a batch into JSON Lines and a grader results file", "[cli][check][batch]") {
  const fs::path dir = fs::temp_directory_path() / "tackle-batch";
  fs::create_directories(dir);
  std::ofstream(dir / "subs.jsonl") << "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n"
                                    << "{\"id\": \"b\", \"unknown\": \"T_HI\", \"answer\": \"9^(9^9)\"}\n";
  const Run r = run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " +
                           (dir / "subs.jsonl").string() + " --results " + (dir / "results.json").string());
  CHECK(r.code == 0);
  std::istringstream lines(r.out);
  std::string first, second;
  std::getline(lines, first);
  std::getline(lines, second);
  CHECK(nlohmann::json::parse(first)["verdict"] == "correct");
  CHECK(nlohmann::json::parse(second)["verdict"] == "invalid");
  const auto grader = nlohmann::json::parse(slurp(dir / "results.json"));
  CHECK_FALSE(grader.contains("score"));  // Gradescope: the tests' scores add up
  CHECK(grader["tests"][0]["score"] == 1);
  CHECK(grader["tests"][1]["score"] == 0);
  // PrairieLearn: the unreadable second answer makes the submission not gradable.
  const Run pl =
      run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + (dir / "subs.jsonl").string() +
                 " --results " + (dir / "pl.json").string() + " --results-format prairielearn --points T_HI=3");
  CHECK(pl.code == 0);
  const auto prairie = nlohmann::json::parse(slurp(dir / "pl.json"));
  CHECK(prairie["gradable"] == false);
  CHECK_FALSE(prairie.contains("tests"));  // they would tell that the first answer is right
  // The first answer alone is gradable, with its 3 points.
  std::ofstream(dir / "first.jsonl") << "{\"id\": \"a\", \"unknown\": \"T_HI\", \"answer\": \"m*a*l/(2*d)\"}\n";
  CHECK(run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + (dir / "first.jsonl").string() +
                   " --results " + (dir / "pl.json").string() + " --results-format prairielearn --points T_HI=3")
            .code == 0);
  const auto gradable = nlohmann::json::parse(slurp(dir / "pl.json"));
  CHECK(gradable["gradable"] == true);
  CHECK(gradable["tests"][0]["points"] == 3);
  CHECK(run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + (dir / "subs.jsonl").string() +
                   " --points lots")
            .code == 2);
  CHECK(run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch /no/such.jsonl").code == 1);
  fs::remove_all(dir);
}

TEST_CASE("CLI: sweep writes CSV, SVG and pgfplots, and without a range it is a usage error", "[cli][sweep]") {
  const fs::path dir = fs::temp_directory_path() / "tackle-sweep";
  fs::create_directories(dir);
  const Run r = run_tackle("sweep " + examples + "figure-12.28-suitcase-normal-forces.yaml --svg " +
                           (dir / "f.svg").string() + " --pgfplots " + (dir / "f.tex").string());
  CHECK(r.code == 0);
  // The description plots against h/l (l = 1 m): h's column, then the axis'.
  CHECK(r.out.rfind("h [m],h/l,N_A [N],N_B [N],N_A - N_B [N],valid\n0,0,0.5,0.5,0,true\n", 0) == 0);
  CHECK(slurp(dir / "f.tex").find("xlabel={$h/l$}") != std::string::npos);
  // --against on the command line; --vary alone drops the description's axis.
  CHECK(run_tackle("sweep " + examples +
                   "figure-12.28-suitcase-normal-forces.yaml --vary h=0:1:2 --against 2*h --plot N_A")
            .out == "h [m],2*h [m],N_A [N],valid\n0,0,0.5,true\n1,2,0,true\n");
  CHECK(run_tackle("sweep " + examples + "figure-12.28-suitcase-normal-forces.yaml --vary h=0:1:2 --plot N_A").out ==
        "h [m],N_A [N],valid\n0,0.5,true\n1,0,true\n");
  CHECK(slurp(dir / "f.svg").find("</svg>") != std::string::npos);
  CHECK(slurp(dir / "f.tex").find("\\begin{axis}") != std::string::npos);
  const Run custom = run_tackle("sweep " + examples + "sample-12.7-suitcase.yaml --vary l=0.5:1:2 --plot N_B");
  // By hand: N_B = m g (1/2 + mu h/l) = 98.1 (0.5 + 0.12/l): 72.594 N at l = 0.5 m, 60.822 N at 1 m.
  CHECK(custom.out == "l [m],N_B [N],valid\n0.5,72.594,true\n1,60.822,true\n");
  CHECK(run_tackle("sweep " + examples + "sample-12.7-suitcase.yaml").code == 2);
  fs::remove_all(dir);
}

TEST_CASE("CLI: a velocity the equations do not give is undetermined, never equal to itself", "[cli][trust]") {
  // Regression: with given: [dot(y_B)] and find: [dot(y_A)], tackle printed
  // `dot(y_A) = dot(y_A)` with status determined. Now the rate equation is solved; with
  // nothing given, the answer says what is missing.
  const fs::path dir = fs::temp_directory_path() / ("tackle-vel-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string from = "given: [dot(y_B), ddot(y_B)]\nfind: [dot(y_A), ddot(y_A)]\n";
  {
    std::string text = tackle::test::example_with("sample-12.2-pulley-kinematics.yaml", from,
                                                  "given: [ddot(y_B)]\nfind: [dot(y_A)]\n");
    std::ofstream(dir / "v.yaml") << text.substr(0, text.find("expected:"));
  }
  const Run out = run_tackle("solve " + (dir / "v.yaml").string());
  CHECK(out.code == 0);
  CHECK(out.out.find("dot(y_A) = dot(y_A)") == std::string::npos);
  CHECK(out.out ==
        "dot(y_A): undetermined: it depends on dot(y_B), which the constraints leave free (give it in 'given')\n");
  const Run json = run_tackle("solve " + (dir / "v.yaml").string() + " --format json");
  const auto j = nlohmann::json::parse(json.out);
  const auto u = j["unknowns"][0];
  CHECK(u["status"] == "undetermined");
  CHECK(u["missing"] == nlohmann::json::array({"dot(y_B)"}));
  CHECK_FALSE(u.contains("closed_form"));
  fs::remove_all(dir);
}

TEST_CASE("Kinematics: a velocity is undetermined at the acceleration level when no constraint is derived", "[trust]") {
  // Only a balance is derived, so no rate equation exists to give the velocity.
  const auto a = tackle::test::run_text(R"(
title: one block
parameters: {F: {value: 10, unit: N}, m: {value: 2, unit: kg}}
bodies: {A: {mass: m, position: x_A}}
loads: [{on: A, force: F}]
find: [dot(x_A), ddot(x_A)]
)");
  const tackle::Derivation d = tackle::explain(*a);
  REQUIRE(d.answers.size() == 2);
  CHECK(d.answers[0].status == tackle::Answer::Status::undetermined);
  CHECK(
      d.answers[0].reason ==
      "no solved equation gives dot(x_A); the equations solved are at the acceleration level (balances and constraints "
      "differentiated twice)");
  REQUIRE(d.answers[1].closed_form);
  CHECK(tackle::to_text(*d.answers[1].closed_form) == "F/m");
}

TEST_CASE("CLI: JSON exact, value, decimal and unit agree in the unit asked for", "[cli][trust]") {
  // Regression: with an output unit, `exact` was in SI while `value` was in the unit asked.
  const Run r = run_tackle("solve " + examples + "car-braking-us-units.yaml --format json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& u : j["unknowns"]) {
    INFO(u.dump());
    REQUIRE(u.contains("exact"));
    const auto exact = tackle::parse_expression(u["exact"].get<std::string>(), tackle::numbers_only());
    REQUIRE(exact.value);
    CHECK(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(*exact.value)).to_double() == Approx(u["value"].get<double>()));
    CHECK(std::stod(u["decimal"].get<std::string>()) == Approx(u["value"].get<double>()).epsilon(1e-5));
  }
}

TEST_CASE("CLI: JSON names each equation's kind: lmb, amb or constraint", "[cli][trust]") {
  // Regression: sample 12.8's AMB about axis OG was labelled "kind": "constraint".
  const Run r = run_tackle("derive " + examples + "sample-12.8-sign-board.yaml --format json");
  REQUIRE(r.code == 0);
  const auto eqs = nlohmann::json::parse(r.out)["equations"];
  REQUIRE(eqs.size() == 1);
  CHECK(eqs[0]["label"].get<std::string>().rfind("AMB", 0) == 0);
  CHECK(eqs[0]["kind"] == "amb");
  const Run p = run_tackle("derive " + examples + "sample-12.3-two-mass-pulley.yaml --format json");
  const auto pulley = nlohmann::json::parse(p.out);
  std::set<std::string> kinds;
  for (const auto& e : pulley["equations"]) kinds.insert(e["kind"].get<std::string>());
  CHECK(kinds == std::set<std::string>{"lmb", "constraint"});
}

TEST_CASE("CLI: a directory given as FILE is named as a directory, exit 1", "[cli][errors]") {
  const Run r = run_tackle("derive " + examples);
  CHECK(r.code == 1);
  CHECK(r.err == examples + ": is a directory (expected a file)\n");
  const Run b = run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + examples);
  CHECK(b.code == 1);
  CHECK(b.err == examples + ": is a directory (expected a file)\n");
}

TEST_CASE("CLI: -o and --results are written whole or not at all", "[cli][errors]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-atomic-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string kept = (dir / "kept.txt").string();
  std::ofstream(kept) << "previous contents\n";
  // A failed run leaves the old output as it was, and no temporary file behind.
  const Run bad =
      run_tackle(std::string("derive ") + TACKLE_SOURCE_DIR + "/tests/data/bad/02-unknown-key.yaml -o " + kept);
  CHECK(bad.code == 1);
  CHECK(slurp(kept) == "previous contents\n");
  // A successful one replaces it.
  const Run good = run_tackle("solve " + examples + "sample-12.3-two-mass-pulley.yaml -o " + kept);
  CHECK(good.code == 0);
  CHECK(slurp(kept).rfind("T = 2*F*m_B/(9*m_A + 4*m_B)", 0) == 0);
  // An output that is a directory, or in a directory that does not exist, is an error.
  const Run to_dir = run_tackle("solve " + examples + "sample-12.3-two-mass-pulley.yaml -o " + dir.string());
  CHECK(to_dir.code == 1);
  CHECK(to_dir.err == dir.string() + ": is a directory (expected a file to write)\n");
  // A batch whose results file cannot be made writes neither output.
  const std::string batch = (dir / "b.jsonl").string();
  std::ofstream(batch) << R"x({"id": "s1", "unknown": "T_HI", "answer": "m*a*l/(2*d)"})x"
                       << "\n";
  const Run no_results =
      run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + batch + " -o " +
                 (dir / "out.jsonl").string() + " --results " + (dir / "missing" / "r.json").string());
  CHECK(no_results.code == 1);
  CHECK_FALSE(fs::exists(dir / "out.jsonl"));
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir))
    files += e.path().filename().string().find(".tackle-") != std::string::npos;
  CHECK(files == 0);
  fs::remove_all(dir);
}

TEST_CASE("CLI: key variants are JSON numbers, and a problem without ranges says it has none", "[cli][key]") {
  const std::string ex = std::string(TACKLE_SOURCE_DIR) + "/examples/";
  const Run r = run_tackle("key " + ex + "atwood-machine.yaml " + ex +
                           "sample-12.3-two-mass-pulley.yaml --variants 1 --format json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["problems"][0]["variants"].empty());
  CHECK(j["problems"][0]["no_variants"] == "no parameter of this problem has a 'range'");
  const auto& v = j["problems"][1]["variants"][0];
  CHECK(v["parameters"]["F"]["value"].is_number());
  CHECK(v["parameters"]["F"]["decimal"].is_string());
  CHECK(v["answers"]["T"]["value"].is_number());
  const Run md =
      run_tackle("key " + ex + "atwood-machine.yaml " + ex + "sample-12.3-two-mass-pulley.yaml --variants 1");
  CHECK(md.out.find("\nNo variants: no parameter of this problem has a `range`.\n") != std::string::npos);
  // None of the problems has a range: the request cannot be met at all.
  const Run none = run_tackle("key " + ex + "atwood-machine.yaml --variants 2");
  CHECK(none.code == 1);
  CHECK(none.err == ex +
                        "atwood-machine.yaml:1:1: variants were asked for, but no parameter has a 'range' to draw them "
                        "from (expected, for instance, F: {value: 130, unit: N, range: [100, 160]})\n");
}

TEST_CASE("CLI: simulate stops where the blocks of sample 12.4 separate, and writes CSV, SVG and pgfplots",
          "[cli][motion]") {
  const fs::path dir = fs::temp_directory_path() / "tackle-simulate";
  fs::create_directories(dir);
  const Run r = run_tackle(
      "simulate " + examples + "sample-12.4-stacked-blocks-on-spring.yaml --plot y,N --samples 4 --csv " +
      (dir / "m.csv").string() + " --svg " + (dir / "m.svg").string() + " --pgfplots " + (dir / "m.tex").string());
  CHECK(r.code == 0);
  // By hand: y = y_0 cos(lambda t) with lambda = 10 rad/s; N = m (g + y_0 lambda^2 cos(lambda t))
  // reaches 0 at t = acos(-0.654)/10 = 0.228366 s, where y = -g/lambda^2 = -0.0981 m.
  CHECK(r.out.find("Stopped: the model no longer holds after t = 0.228366 s (contact c: the bodies separate") !=
        std::string::npos);
  CHECK(r.out.find("Event at t = 0.228366 s: contact c: the bodies separate (the contact would have to pull) (the run "
                   "ends)\n") != std::string::npos);
  const std::string csv = slurp(dir / "m.csv");
  CHECK(csv.rfind("t [s],y,N,valid\n0,0.15,24.81,true\n0.2,-0.062422,3.5678,true\n0.228366,-0.0981,", 0) == 0);
  CHECK(slurp(dir / "m.svg").find("</svg>") != std::string::npos);
  CHECK(slurp(dir / "m.tex").find("\\begin{axis}") != std::string::npos);
  // Usage and input errors.
  CHECK(run_tackle("simulate " + examples + "sample-12.4-stacked-blocks-on-spring.yaml --until -1").code == 2);
  const Run none = run_tackle("simulate " + examples + "atwood-machine.yaml");
  CHECK(none.code == 1);
  CHECK(none.err ==
        "--until/--plot: the description has no 'motion' (expected, e.g., motion: {initial: {x: 0, dot(x): 0}})\n");
  const Run bad_plot = run_tackle("simulate " + examples + "sample-12.4-stacked-blocks-on-spring.yaml --plot Q");
  CHECK(bad_plot.code == 1);
  CHECK(bad_plot.err ==
        "--until/--plot: plot 'Q': unknown name 'Q' (known: m, M, k, g, l_0, y_s, y_0, t, y_m, y, N, lambda, ...)\n");
  fs::remove_all(dir);
}

TEST_CASE("CLI: simulate runs the damped, driven block to the end, matching its closed form", "[cli][motion]") {
  const Run r = run_tackle("simulate " + examples + "damped-block-on-spring-forced.yaml --until 1 --samples 2");
  CHECK(r.code == 0);
  // By hand (the example's notes): x(1 s) = 0.0106279 m; the model holds throughout.
  CHECK(r.out.find("; the model holds throughout.\n") != std::string::npos);
  CHECK(r.out.find("\n1,0.0106279") != std::string::npos);
}

TEST_CASE("CLI: a sheet and a key from one seed show the same numbers", "[cli][sheet]") {
  const std::string file = examples + "sample-12.3-two-mass-pulley.yaml";
  const Run key = run_tackle("key " + file + " --variants 3 --seed 9 --format json");
  const Run sheet = run_tackle("sheet " + file + " --variants 3 --seed 9 --format markdown");
  REQUIRE(key.code == 0);
  REQUIRE(sheet.code == 0);
  const auto variants = nlohmann::json::parse(key.out)["problems"][0]["variants"];
  REQUIRE(variants.size() == 3);
  std::size_t at = 0;
  for (const auto& v : variants) {
    // The statement says "a force $F$ = {F}": the key's F of that variant.
    const std::string F =
        v["parameters"]["F"]["decimal"].get<std::string>() + " " + v["parameters"]["F"]["unit"].get<std::string>();
    at = sheet.out.find("a force $F$ = " + F, at);
    CHECK(at != std::string::npos);
  }
  CHECK(sheet.out.find("Find $T$, $\\ddot{x}_{A}$, $\\ddot{x}_{B}$.") != std::string::npos);
  // Without variants: the description's own numbers.
  CHECK(run_tackle("sheet " + file + " --format markdown").out.find("a force $F$ = 130 N") != std::string::npos);
}

TEST_CASE("CLI: a problem without a statement is stated from its description, with each variant's numbers",
          "[cli][sheet]") {
  // The Atwood machine has no 'statement': the sheet names its bodies, connections and given
  // values, the key's numbers per variant, and says once that it wrote the statement.
  const std::string file = examples + "atwood-machine.yaml";
  const Run sheet = run_tackle("sheet " + file + " --format markdown");
  REQUIRE(sheet.code == 0);
  CHECK(sheet.out.find("Bodies A (mass $m_{A}$), B (mass $m_{B}$) and C (no mass). Connections: fixed body C: ") !=
        std::string::npos);
  CHECK(sheet.out.find(
            "Given: $m_{A} = 3\\,\\mathrm{kg}$, $m_{B} = 5\\,\\mathrm{kg}$ and $g = 9.81\\,\\mathrm{m/s^{2}}$.") !=
        std::string::npos);
  CHECK(sheet.err ==
        "tackle: warning: " + file +
            " has no 'statement'; the sheet states the problem from the description (its bodies, connections and "
            "given values)\n");
  // With variants: each problem gives its own numbers, as the key draws them.
  const std::string ranged = examples + "sample-12.7-suitcase.yaml";
  const Run key = run_tackle("key " + ranged + " --variants 2 --seed 4 --format json");
  const Run two = run_tackle("sheet " + ranged + " --variants 2 --seed 4 --format markdown");
  REQUIRE(key.code == 0);
  REQUIRE(two.code == 0);
  std::size_t at = 0;
  const auto keyed = nlohmann::json::parse(key.out);  // (kept: a range-for over a temporary's part dangles)
  for (const auto& v : keyed["problems"][0]["variants"])
    for (const auto& [name, q] : v["parameters"].items()) {
      INFO(name);
      CHECK(two.out.find(" = " + q["decimal"].get<std::string>(), at) != std::string::npos);
    }
  // A statement the description gives is used as it is, without the warning.
  CHECK(run_tackle("sheet " + examples + "sample-12.3-two-mass-pulley.yaml --format markdown").err.empty());
}

TEST_CASE("CLI: a sheet shows the mechanism's sketch, and the free body diagrams only when asked", "[cli][sheet]") {
  const std::string file = examples + "sample-12.3-two-mass-pulley.yaml";
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  const Run plain = run_tackle("sheet " + file + " --format markdown");
  REQUIRE(plain.code == 0);
  CHECK(count(plain.out, "<figcaption>Sketch of the mechanism</figcaption>") == 1);
  CHECK(count(plain.out, "<figcaption>Free body diagram") == 0);
  const Run all = run_tackle("sheet " + file + " --format markdown --figures");
  CHECK(count(all.out, "<figcaption>Sketch of the mechanism</figcaption>") == 1);
  CHECK(count(all.out, "<figcaption>Free body diagram") == 2);
  // The sketch comes before what is asked.
  CHECK(all.out.find("Sketch of the mechanism") < all.out.find("Find $T$"));
}

namespace {

// The command's exit code (128 + the signal's number when one killed it) and standard error, standard output sent
// to `out` (a device here); `before` is shell run first (a ulimit).
Run run_tackle_to(const std::string& args, const std::string& out, const std::string& before = "") {
  const fs::path err = fs::temp_directory_path() / ("tackle-cli-err-" + std::to_string(::getpid()));
  // The shell's own stderr, where it reports "Segmentation fault" of a process a limit killed,
  // goes nowhere.
  const std::string cmd = "exec 2>/dev/null; (" + before + std::string(TACKLE_BINARY) + " " + args + ") >" + out +
                          " 2>" + err.string() + " </dev/null";
  const int status = std::system(cmd.c_str());
  Run r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, "", slurp(err)};
  fs::remove(err);
  return r;
}

bool character_device(const char* path) {
  struct stat st {};
  return ::stat(path, &st) == 0 && S_ISCHR(st.st_mode);
}

std::size_t temporaries_in(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().filename().string().find(".tackle-") != std::string::npos;
  return n;
}

}  // namespace

TEST_CASE("CLI: a write that fails is an error, exit 1: standard output or -o full", "[cli][errors][files]") {
  if (!character_device("/dev/full")) {
    WARN("no /dev/full on this machine");
    return;
  }
  // A short report (all of it in stdio's buffer until the end) and a long one (past it).
  for (const char* command : {"solve", "derive"}) {
    INFO(command);
    const Run r = run_tackle_to(std::string(command) + " " + examples + "sample-12.8-sign-board.yaml", "/dev/full");
    CHECK(r.code == 1);
    CHECK(r.err == "tackle: cannot write to standard output (No space left on device)\n");
  }
  // A batch to standard output stops, and writes no results file of part of the batch.
  const fs::path dir = fs::temp_directory_path() / ("tackle-full-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string batch = (dir / "b.jsonl").string();
  std::ofstream(batch) << R"x({"id": "s1", "unknown": "T_HI", "answer": "m*a*l/(2*d)"})x"
                       << "\n";
  const Run b = run_tackle_to(
      "check " + examples + "sample-12.8-sign-board.yaml --batch " + batch + " --results " + (dir / "r.json").string(),
      "/dev/full");
  CHECK(b.code == 1);
  CHECK(b.err == "tackle: cannot write to standard output (No space left on device)\n");
  CHECK_FALSE(fs::exists(dir / "r.json"));
  CHECK(temporaries_in(dir) == 0);
  // -o to the device: written into (never replaced), and its failure said.
  const Run o = run_tackle("solve " + examples + "sample-12.8-sign-board.yaml -o /dev/full");
  CHECK(o.code == 1);
  CHECK(o.err == "/dev/full: cannot write the file (No space left on device)\n");
  CHECK(character_device("/dev/full"));
  fs::remove_all(dir);
}

TEST_CASE("CLI: -o and --results to /dev/null and to a FIFO write into them, never replace them", "[cli][files]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-devices-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string batch = (dir / "b.jsonl").string();
  std::ofstream(batch) << R"x({"id": "s1", "unknown": "T_HI", "answer": "m*a*l/(2*d)"})x"
                       << "\n";
  const Run r = run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch " + batch +
                           " -o /dev/null --results /dev/null");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(character_device("/dev/null"));
  // A FIFO with a reader: the report arrives through it, and the FIFO stays a FIFO.
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string read;
  std::thread reader([&] { read = slurp(fifo); });
  const Run s = run_tackle("solve " + examples + "sample-12.3-two-mass-pulley.yaml -o " + fifo.string());
  reader.join();
  CHECK(s.code == 0);
  CHECK(read.rfind("T = 2*F*m_B/(9*m_A + 4*m_B)", 0) == 0);
  struct stat st {};
  REQUIRE(::stat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(temporaries_in(dir) == 0);
  fs::remove_all(dir);
}

TEST_CASE("CLI: stopped by SIGINT or SIGTERM while grading, tackle leaves no temporary file", "[cli][files]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-signal-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path fifo = dir / "in.jsonl";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  for (const int sig : {SIGINT, SIGTERM}) {
    INFO("signal " << sig);
    // tackle reads the batch from a FIFO that is kept open: it has made its two temporary
    // files and waits for the next line when the signal comes.
    const std::string board = examples + "sample-12.8-sign-board.yaml", out = (dir / "out.jsonl").string(),
                      results = (dir / "r.json").string();
    std::vector<std::string> args{TACKLE_BINARY, "check", board,       "--batch", fifo.string(),
                                  "-o",          out,     "--results", results};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);  // a test run in the background may ignore SIGINT
    sigaddset(&defaults, SIGTERM);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
    pid_t pid = 0;
    REQUIRE(::posix_spawn(&pid, TACKLE_BINARY, nullptr, &attr, argv.data(), environ) == 0);
    posix_spawnattr_destroy(&attr);
    const int writer = ::open(fifo.c_str(), O_WRONLY);  // waits for tackle to open it
    REQUIRE(writer >= 0);
    const std::string line = R"x({"id": "s1", "unknown": "T_HI", "answer": "m*a*l/(2*d)"})x"
                             "\n";
    REQUIRE(::write(writer, line.data(), line.size()) == static_cast<ssize_t>(line.size()));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (temporaries_in(dir) < 2 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    CHECK(temporaries_in(dir) == 2);
    ::kill(pid, sig);
    int status = 0;
    REQUIRE(::waitpid(pid, &status, 0) == pid);
    ::close(writer);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == sig);
    CHECK(temporaries_in(dir) == 0);
    CHECK_FALSE(fs::exists(out));
    CHECK_FALSE(fs::exists(results));
  }
  fs::remove_all(dir);
}

TEST_CASE("CLI: /dev/zero as a description, a rule file or a batch stops at the input limit, exit 1",
          "[cli][errors][limits]") {
  const Run d = run_tackle("derive /dev/zero");
  CHECK(d.code == 1);
  CHECK(d.err == "/dev/zero: is longer than 16 MiB (expected a description or rule file of at most 16 MiB)\n");
  const fs::path rules = fs::temp_directory_path() / ("tackle-zero-rules-" + std::to_string(::getpid()));
  fs::create_directories(rules);
  fs::create_symlink("/dev/zero", rules / "zero.yaml");
  const Run r = run_tackle("--rules " + rules.string() + " solve " + examples + "atwood-machine.yaml");
  CHECK(r.code == 1);
  CHECK(r.err == (rules / "zero.yaml").string() +
                     ": is longer than 16 MiB (expected a description or rule file of at most 16 MiB)\n");
  fs::remove_all(rules);
  const Run b = run_tackle("check " + examples + "sample-12.8-sign-board.yaml --batch /dev/zero");
  CHECK(b.code == 1);
  CHECK(b.err ==
        "/dev/zero:1: the line is longer than 1 MiB (expected JSON Lines: one object with id, unknown and answer per "
        "line)\n");
}

TEST_CASE("CLI: text from the description reaches Markdown and HTML escaped: no tag of its own", "[cli][sheet]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-escape-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string file = (dir / "p.yaml").string();
  std::ofstream(file) << "title: 'Pulled <script>alert(1)</script>'\n"
                         "statement: 'A force {F} <img src=x onerror=alert(1)> pulls A; $a<b$ & so on.'\n"
                         "parameters:\n  F: {value: 10, unit: N}\n  m: {value: 2, unit: kg}\n"
                         "bodies:\n  A: {mass: m, position: x}\nloads:\n  - {on: A, force: F}\nfind: [ddot(x)]\n";
  // Markdown readers pass HTML through: entities outside math, \lt inside it.
  const Run md = run_tackle("sheet --format markdown " + file);
  REQUIRE(md.code == 0);
  CHECK(md.out.find("## Problem 1: Pulled &lt;script&gt;alert(1)&lt;/script&gt;\n") != std::string::npos);
  CHECK(md.out.find("A force 10 N &lt;img src=x onerror=alert(1)&gt; pulls A; $a\\lt b$ &amp; so on.\n") !=
        std::string::npos);
  CHECK(md.out.find("<script") == std::string::npos);  // the sketch of the mechanism is the only HTML
  CHECK(md.out.find("<img") == std::string::npos);
  const Run derived = run_tackle("derive --format markdown " + file);
  REQUIRE(derived.code == 0);
  CHECK(derived.out.rfind("# Pulled &lt;script&gt;alert(1)&lt;/script&gt;\n", 0) == 0);
  // HTML escapes it too (the page's own <script> elements are KaTeX's).
  const Run html = run_tackle("sheet --format html " + file);
  REQUIRE(html.code == 0);
  CHECK(html.out.find("<script>alert") == std::string::npos);
  CHECK(html.out.find("<img src=x") == std::string::npos);  // KaTeX's own script has "<img "
  CHECK(
      html.out.find("A force <span class=\"math\">10\\,\\mathrm{N}</span> &lt;img src=x onerror=alert(1)&gt; pulls A; "
                    "<span class=\"math\">a&lt;b</span> &amp; so on.") != std::string::npos);
  CHECK(html.out.find("Pulled &lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
  // A sweep's SVG plot is titled with it, escaped as well.
  const fs::path svg = dir / "sweep.svg";
  const Run sweep = run_tackle("sweep " + file + " --vary F=1:2:3 --plot 'ddot(x)' --svg " + svg.string());
  REQUIRE(sweep.code == 0);
  CHECK(slurp(svg).find(">Pulled &lt;script&gt;alert(1)&lt;/script&gt;</text>") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("CLI: out of memory is exit 3 with a message, and leaves no temporary file",
          "[cli][errors][files][address-space]") {
  // Under each address-space limit from 8 to 40 MB, tackle either finishes, or says it ran
  // out of memory (exit 3) with its output's temporary file removed; or the limit is too
  // small for the program to start at all (then --version dies too, before any of tackle's
  // code, or runs out of memory itself). A limit between those is an out-of-memory in the
  // middle of the derivation.
  const fs::path dir = fs::temp_directory_path() / ("tackle-oom-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string out = (dir / "report.txt").string();
  const Run whole = run_tackle("derive " + examples + "hoist-two-masts-3d.yaml");
  REQUIRE(whole.code == 0);
  int out_of_memory = 0;
  for (int kb = 8 * 1024; kb <= 40 * 1024; kb += 256) {
    INFO("ulimit -v " << kb);
    const std::string limit = "ulimit -v " + std::to_string(kb) + "; exec ";
    const Run r = run_tackle_to("derive " + examples + "hoist-two-masts-3d.yaml -o " + out, "/dev/null", limit);
    // (127: the shell could not even start the program under the limit.)
    if (r.code > 128 || r.code == 127) {
      // Too small to start: --version dies too, or runs out of memory itself (at the edge,
      // the C++ runtime has no memory left even to throw: it aborts).
      const int version = run_tackle_to("--version", "/dev/null", limit).code;
      CHECK((version > 128 || version == 127 || version == 3));
    } else if (r.code == 3) {
      CHECK(r.err == "tackle: out of memory\n");
      CHECK_FALSE(fs::exists(out));
      ++out_of_memory;
    } else {
      CHECK(r.code == 0);
      CHECK(slurp(out) == whole.out);
      fs::remove(out);
    }
    CHECK(temporaries_in(dir) == 0);
  }
  CHECK(out_of_memory > 0);
  fs::remove_all(dir);
}

TEST_CASE("CLI: a batch whose outputs are larger than the memory tackle may use is graded whole",
          "[cli][batch][limits][address-space]") {
  // 100,000 lines that are not JSON: about 29 MB of results and 14 MB of results file, under
  // a 24 MB address-space limit (tackle itself needs about 11 MB of it): only a batch read,
  // graded and written a line at a time fits.
  const fs::path dir = fs::temp_directory_path() / ("tackle-stream-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string batch = (dir / "b.jsonl").string(), out = (dir / "out.jsonl").string(),
                    results = (dir / "r.json").string();
  {
    std::ofstream b(batch);
    for (int i = 1; i <= 100000; ++i) b << "not json " << i << "\n";
  }
  const Run r = run_tackle_to("check " + examples + "sample-12.8-sign-board.yaml --batch " + batch + " -o " + out +
                                  " --results " + results + " --results-format prairielearn",
                              "/dev/null", "ulimit -v 24576; exec ");
  REQUIRE(r.code == 0);
  CHECK(r.err.empty());
  std::ifstream lines(out);
  std::size_t n = 0;
  for (std::string l; std::getline(lines, l);) ++n;
  CHECK(n == 100000);
  CHECK(fs::file_size(out) + fs::file_size(results) > 24576 * 1024);
  const auto j = nlohmann::json::parse(slurp(results));
  // Not gradable: no tests (they would tell which other answers are right).
  CHECK(!j.contains("tests"));
  CHECK(j["gradable"] == false);
  REQUIRE(j["format_errors"].size() == 101);
  CHECK(j["format_errors"][0] == "line 1: not a JSON object with id, unknown and answer");
  CHECK(j["format_errors"][100] == "and 99900 more");
  fs::remove_all(dir);
}

TEST_CASE("CLI: NaN tolerances and end times, and seeds outside 0..2^64-1, are usage errors", "[cli][check]") {
  const std::string pulley = examples + "sample-12.3-two-mass-pulley.yaml";
  const Run tolerance = run_tackle("check " + pulley + " --unknown T --answer '20 N' --tolerance nan");
  CHECK(tolerance.code == 2);
  CHECK(tolerance.err.find("'nan' is not a finite number") != std::string::npos);
  CHECK(run_tackle("check " + pulley + " --unknown T --answer '20 N' --tolerance inf").code == 2);
  const Run until = run_tackle("simulate " + examples + "sample-12.4-stacked-blocks-on-spring.yaml --until nan");
  CHECK(until.code == 2);
  CHECK(until.err.find("'nan' is not a finite number") != std::string::npos);
  // -1 wrapped to 2^64 - 1, and 2^64 and 10^23 were cut down to it: three spellings, one key.
  for (const char* seed : {"-1", "18446744073709551616", "100000000000000000000000", "1e3", "0x10"}) {
    INFO(seed);
    const Run r = run_tackle("key " + pulley + " --variants 1 --seed " + seed);
    CHECK(r.code == 2);
    CHECK(r.err.find("is not a seed (expected a whole number from 0 to 18446744073709551615)") != std::string::npos);
  }
  const Run largest = run_tackle("key " + pulley + " --variants 1 --seed 18446744073709551615");
  const Run smallest = run_tackle("key " + pulley + " --variants 1 --seed 0");
  CHECK(largest.code == 0);
  CHECK(smallest.code == 0);
  CHECK(largest.out != smallest.out);
  CHECK(run_tackle("sheet " + pulley + " --variants 1 --seed -1").code == 2);
  CHECK(run_tackle("check " + pulley + " --unknown T --answer '2*F*m_B/(9*m_A + 4*m_B)' --seed -1").code == 2);
  CHECK(run_tackle("check " + pulley + " --unknown T --answer '2*F*m_B/(9*m_A + 4*m_B)' --seed 7").code == 0);
}

TEST_CASE("CLI: --set of a negative mass is an input error", "[cli][check]") {
  const std::string pulley = examples + "sample-12.3-two-mass-pulley.yaml";
  const Run negative = run_tackle("check " + pulley + " --unknown T --answer '20 N' --set m_A=-40");
  CHECK(negative.code == 1);
  CHECK(negative.out.empty());
  CHECK(negative.err == "tackle check: --set: the value of 'm_A' is -40 kg, but 'm_A' is assumed positive (a mass)\n");
  // A name that is not a parameter stays a usage error.
  CHECK(run_tackle("check " + pulley + " --unknown T --answer '20 N' --set G=1").code == 2);
}

TEST_CASE("CLI: the Gradescope example grades each asked unknown once", "[cli][check][platform]") {
  // Sample 12.3 asks for T (10 points). ddot(x_A) is another unknown of the problem, answered
  // right: no points for it; T answered twice: the first answer is graded, once.
  const fs::path root = fs::temp_directory_path() / ("tackle-gradescope-" + std::to_string(::getpid()));
  fs::create_directories(root / "submission");
  const std::string script = TACKLE_SOURCE_DIR "/examples/gradescope/pulley-tension/run_autograder";
  auto grade = [&](const std::string& answers) {
    std::ofstream(root / "submission/answers.json") << answers;
    const std::string cmd =
        "AUTOGRADER='" + root.string() + "' TACKLE='" + TACKLE_BINARY + "' '" + script + "' >/dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    return nlohmann::json::parse(slurp(root / "results/results.json"));
  };
  const auto extra = grade("{\"T\": \"2*F*m_B/(9*m_A + 4*m_B)\", \"ddot(x_A)\": \"-9*F/(9*m_A + 4*m_B)\"}");
  REQUIRE(extra["tests"].size() == 1);
  CHECK(extra["tests"][0]["name"] == "answers.json: T");
  CHECK(extra["tests"][0]["score"] == 10);
  CHECK(extra["output"] == "1 of 1 answers correct\n\"ddot(x_A)\" was not asked for and is not graded");
  const auto twice = grade("{\"T\": \"30 N\", \"T\": \"2*F*m_B/(9*m_A + 4*m_B)\"}");
  REQUIRE(twice["tests"].size() == 1);
  CHECK(twice["tests"][0]["score"] == 0);
  CHECK(twice["output"] == "0 of 1 answers correct\nT is answered more than once: only the first answer is graded");
  // Nothing for T: graded as empty, no points.
  const auto none = grade("{\"t\": \"20 N\"}");
  REQUIRE(none["tests"].size() == 1);
  CHECK(none["tests"][0]["score"] == 0);
  CHECK(none["tests"][0]["output"] == "invalid: the answer is empty");
  fs::remove_all(root);
}

TEST_CASE("CLI: the README's first problem gives what the README shows", "[cli][readme]") {
  // The door must stay true: its YAML blocks, put together, solve, check and simulate as its
  // console blocks say (the lines shown, in order, each found in the output).
  const std::string readme = slurp(TACKLE_SOURCE_DIR "/README.md");
  std::vector<std::string> yaml, console;
  std::vector<std::pair<std::string, std::string>> named;  // file name, text
  for (std::size_t at = 0; (at = readme.find("```", at)) != std::string::npos;) {
    const std::size_t eol = readme.find('\n', at);
    const std::string kind = readme.substr(at + 3, eol - at - 3);
    const std::size_t end = readme.find("```", eol);
    REQUIRE(end != std::string::npos);
    if (kind == "yaml") yaml.push_back(readme.substr(eol + 1, end - eol - 1));
    // A block that names its file in its first line (`# fbd.yaml: ...`) is that file.
    if (kind == "yaml" && yaml.back().rfind("# ", 0) == 0 && yaml.back().find(".yaml") != std::string::npos) {
      named.emplace_back(yaml.back().substr(2, yaml.back().find(".yaml") + 3), yaml.back());
      yaml.pop_back();
    }
    if (kind == "console") console.push_back(readme.substr(eol + 1, end - eol - 1));
    at = end + 3;
  }
  REQUIRE(yaml.size() == 2);
  const fs::path dir = fs::temp_directory_path() / ("tackle-readme-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "atwood.yaml") << yaml[0] << yaml[1];
  for (const auto& [name, text] : named) std::ofstream(dir / name) << text;
  CHECK(named.size() == 1);
  std::size_t commands = 0;
  for (const auto& block : console) {
    std::istringstream lines(block);
    std::string line, output;
    std::vector<std::pair<std::string, std::string>> runs;  // command, the output shown
    while (std::getline(lines, line)) {
      if (line.rfind("$ build/tackle ", 0) == 0)
        runs.push_back({line.substr(15), ""});
      else if (!runs.empty() && line != "...")
        runs.back().second += line + "\n";
    }
    for (const auto& [args, shown] : runs) {
      INFO(args);
      const Run r = run_tackle(args, dir.string());
      CHECK((r.code == 0 || args.rfind("check", 0) == 0));
      ++commands;
      // Each shown line appears in the output, in order (a long line may be wrapped in the README).
      std::istringstream want(shown);
      std::string w, out = r.out;
      for (char& c : out) c = c == '\n' ? ' ' : c;
      std::size_t from = 0;
      while (std::getline(want, w)) {
        const std::size_t first = w.find_first_not_of(' ');
        if (first == std::string::npos) continue;
        const std::string text = w.substr(first);
        const std::size_t found = out.find(text, from);
        INFO("shown: " << text);
        CHECK(found != std::string::npos);
        if (found != std::string::npos) from = found + text.size();
      }
    }
  }
  CHECK(commands == 5);
  fs::remove_all(dir);
}

TEST_CASE("Docs: every YAML block in the README and docs/ reads as YAML, and a whole description in one derives",
          "[docs]") {
  // Documentation that cannot drift silently: a block that is a whole description (it starts
  // with a title) is derived; every other block at least reads as YAML.
  std::vector<fs::path> files{fs::path(TACKLE_SOURCE_DIR) / "README.md"};
  for (const auto& e : fs::directory_iterator(fs::path(TACKLE_SOURCE_DIR) / "docs"))
    if (e.path().extension() == ".md") files.push_back(e.path());
  std::size_t blocks = 0, derived = 0;
  for (const auto& f : files) {
    const std::string text = slurp(f);
    for (std::size_t at = 0; (at = text.find("```yaml\n", at)) != std::string::npos;) {
      const std::size_t begin = at + 8, close = text.find("```", begin);  // (a closing fence may be indented)
      REQUIRE(close != std::string::npos);
      const std::size_t end = text.rfind('\n', close);
      const std::string block = text.substr(begin, end - begin + 1);
      const std::size_t line =
          static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(begin), '\n')) +
          1;
      INFO(f.filename().string() << ":" << line);
      tackle::Diagnostics diags;
      (void)tackle::yaml::load(block, f.filename().string(), diags);
      CHECK(diags.empty());
      // (A sketch of every key, with "..." in it, is not a problem to derive.)
      if (block.rfind("title:", 0) == 0 && block.find("...") == std::string::npos) {
        const fs::path dir = fs::temp_directory_path() / ("tackle-docs-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        std::ofstream(dir / "block.yaml") << block;
        const Run r = run_tackle("derive " + (dir / "block.yaml").string());
        CHECK(r.code == 0);
        CHECK(r.err.empty());
        fs::remove_all(dir);
        ++derived;
      }
      ++blocks;
      at = close + 3;
    }
  }
  CHECK(blocks >= 10);
  CHECK(derived >= 1);
}

TEST_CASE(
    "CLI: check --batch --gradebook grades a class of five, the line that cannot be read is that student's invalid",
    "[cli][check][batch][gradebook]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-gradebook-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string data = TACKLE_SOURCE_DIR "/tests/data/gradebook/";
  const std::string base =
      "check " + examples + "sample-12.3-two-mass-pulley.yaml --batch " + data + "class.jsonl --points T=2";
  const Run plain = run_tackle(base + " --gradebook " + (dir / "grades.csv").string());
  REQUIRE(plain.code == 0);
  CHECK(plain.err.empty());
  // cy's q1 (2 F m_B/...) cannot be read: cy's cell is invalid, every other cell is graded; eve
  // answered q1 twice (the last counts) and q2 not at all.
  CHECK(slurp(dir / "grades.csv") == slurp(data + "plain.csv"));
  // The results are those of the batch without --gradebook, line for line.
  const Run without = run_tackle(base);
  REQUIRE(without.code == 0);
  CHECK(plain.out == without.out);
  CHECK(std::count(plain.out.begin(), plain.out.end(), '\n') == 15);
  std::istringstream lines(plain.out);
  std::string line;
  for (int k = 0; k < 7; ++k) std::getline(lines, line);
  CHECK(nlohmann::json::parse(line)["verdict"] == "invalid");

  const Run canvas = run_tackle(base + " --gradebook " + (dir / "canvas.csv").string() +
                                " --gradebook-format canvas -o " + (dir / "out.jsonl").string());
  REQUIRE(canvas.code == 0);
  CHECK(canvas.out.empty());
  CHECK(canvas.err == "tackle check: " + (dir / "canvas.csv").string() +
                          ": cy: q1 cannot be graded as typed: its cell is left without a grade\n");
  CHECK(slurp(dir / "canvas.csv") == slurp(data + "canvas.csv"));
  CHECK(slurp(dir / "out.jsonl") == without.out);

  const Run moodle =
      run_tackle(base + " --gradebook " + (dir / "moodle.csv").string() + " --gradebook-format moodle -o /dev/null");
  REQUIRE(moodle.code == 0);
  CHECK(slurp(dir / "moodle.csv") == slurp(data + "moodle.csv"));
  fs::remove_all(dir);
}

TEST_CASE("CLI: --gradebook: the tutorial's class is tests/data/gradebook/class.jsonl, word for word",
          "[cli][gradebook][docs]") {
  const std::string tutorial = slurp(TACKLE_SOURCE_DIR "/docs/tutorial.md");
  const std::string class_file = slurp(TACKLE_SOURCE_DIR "/tests/data/gradebook/class.jsonl");
  CHECK(tutorial.find("Save this as `class.jsonl`:\n\n```json\n" + class_file + "```\n") != std::string::npos);
  // And its gradebook, as the tutorial shows it (its lines end in CRLF; the page's in LF).
  std::string shown = slurp(TACKLE_SOURCE_DIR "/tests/data/gradebook/plain.csv");
  shown.erase(std::remove(shown.begin(), shown.end(), '\r'), shown.end());
  CHECK(tutorial.find("$ cat grades.csv\n" + shown + "```\n") != std::string::npos);
}

TEST_CASE("CLI: --gradebook: a line without a student is an input error and nothing is written, usage errors",
          "[cli][check][batch][gradebook]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-gradebook-errors-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string pulley = examples + "sample-12.3-two-mass-pulley.yaml";
  const std::string batch = (dir / "class.jsonl").string();
  std::ofstream(batch) << "{\"student\": \"ada\", \"id\": \"q1\", \"unknown\": \"T\", \"answer\": \"20 N\"}\n"
                       << "{\"id\": \"q1\", \"unknown\": \"T\", \"answer\": \"20 N\"}\n"
                       << "\n"
                       << "not json\n"
                       << "{\"student\": \"ben\", \"unknown\": \"T\", \"answer\": \"20 N\"}\n";
  const std::string outputs = " -o " + (dir / "out.jsonl").string() + " --results " + (dir / "results.json").string() +
                              " --gradebook " + (dir / "grades.csv").string();
  const Run r = run_tackle("check " + pulley + " --batch " + batch + outputs);
  CHECK(r.code == 1);
  CHECK(r.err ==
        batch + ":2: no \"student\" (expected the student's name or id, a string, on every line with --gradebook)\n" +
            batch +
            ":4: the line is not a JSON object, so whose answer it is is not known (expected {\"student\": ..., "
            "\"id\": ..., ...} on "
            "every line with --gradebook)\n" +
            batch + ":5: no \"id\" (expected the question's id on every line with --gradebook)\n");
  for (const char* name : {"out.jsonl", "results.json", "grades.csv"}) CHECK_FALSE(fs::exists(dir / name));
  // Without --gradebook the same batch is graded as ever (the lines' own verdicts).
  CHECK(run_tackle("check " + pulley + " --batch " + batch + " -o " + (dir / "out.jsonl").string()).code == 0);

  // A student's answer that is too long to grade is still that student's, and invalid.
  std::ofstream(batch) << "{\"student\": \"ada\", \"id\": \"q1\", \"unknown\": \"T\", \"answer\": \""
                       << std::string(20000, '1') << "\"}\n";
  const Run long_line = run_tackle("check " + pulley + " --batch " + batch + " -o /dev/null --gradebook " +
                                   (dir / "grades.csv").string());
  CHECK(long_line.code == 0);
  CHECK(slurp(dir / "grades.csv") == "student,q1,total\r\nada,invalid,0\r\n");

  // Usage: --gradebook needs --batch, --gradebook-format needs --gradebook, and only the three layouts.
  const Run no_batch =
      run_tackle("check " + pulley + " --unknown T --answer '20 N' --gradebook " + (dir / "g.csv").string());
  CHECK(no_batch.code == 2);
  CHECK(no_batch.err == "tackle check: --gradebook needs --batch\n");
  const Run no_gradebook = run_tackle("check " + pulley + " --batch " + batch + " --gradebook-format canvas");
  CHECK(no_gradebook.code == 2);
  CHECK(no_gradebook.err == "--gradebook-format requires --gradebook\nRun with --help for more information.\n");
  const Run other = run_tackle("check " + pulley + " --batch " + batch + " --gradebook " + (dir / "g.csv").string() +
                               " --gradebook-format blackboard");
  CHECK(other.code == 2);
  CHECK(other.err ==
        "--gradebook-format: blackboard not in {plain,canvas,moodle}\nRun with --help for more information.\n");
  CHECK_FALSE(fs::exists(dir / "g.csv"));
  fs::remove_all(dir);
}

TEST_CASE(
    "CLI: check --batch --jobs grades in several processes and writes what one process writes, in the batch's order",
    "[cli][check][batch]") {
  const fs::path dir = fs::temp_directory_path() / ("tackle-jobs-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // Every kind of line (answers, equations, diagrams, numbers, params, lines that are not
  // answers, the poisoned ones), 10,000 lines, over 9,000 of them not blank: with 2 jobs, two
  // blocks (of 8,192 lines and the rest).
  std::string kinds;
  for (const char* seed : {"01-mixed.jsonl", "02-equations.jsonl", "03-poisoned.jsonl"})
    kinds += slurp(fs::path(TACKLE_SOURCE_DIR) / "tests/fuzz/seeds/batch" / seed);
  kinds +=
      "\n   \n{\"id\": \"f1\", \"fbd\": {\"body\": \"A\", \"forces\": []}}\nnot json\n[1, 2]\n"
      "{\"id\": \"p\", \"unknown\": \"N_A\", \"answer\": \"30 N\", \"params\": {\"m\": 12}}\n";
  std::size_t lines = 0;
  std::string batch_text;
  while (lines < 10000) {
    batch_text += kinds;
    lines += static_cast<std::size_t>(std::count(kinds.begin(), kinds.end(), '\n'));
  }
  const std::string batch = (dir / "batch.jsonl").string();
  std::ofstream(batch) << batch_text;
  const std::string suitcase = examples + "sample-12.7-suitcase.yaml";
  for (const char* format : {"gradescope", "prairielearn", "jsonl"}) {
    int run = 0;
    const auto graded = [&](const std::string& jobs) {
      const std::string results = (dir / ("results-" + std::to_string(++run) + ".json")).string();
      // (A generous budget: a line past 250 ms on a busy machine would be undecided in one run
      // and not in another.)
      const Run r = run_tackle("check " + suitcase + " --seed 1 --time-budget 60000 --batch " + batch + " --results " +
                               results + " --results-format " + format + jobs);
      return std::tuple{r.code, r.out, r.err, slurp(results)};
    };
    const auto one = graded("");
    CHECK(std::get<0>(one) == 0);
    CHECK(std::count(std::get<1>(one).begin(), std::get<1>(one).end(), '\n') > 8192);
    for (const std::string jobs : {" --jobs 2", " --jobs 3", " --jobs 0"}) CHECK(graded(jobs) == one);
  }
  // A class's gradebook, the same.
  const std::string pulley = examples + "sample-12.3-two-mass-pulley.yaml";
  const std::string class_batch = TACKLE_SOURCE_DIR "/tests/data/gradebook/class.jsonl";
  for (const std::string jobs : {"1", "4"})
    CHECK(run_tackle("check " + pulley + " --seed 1 --batch " + class_batch + " -o /dev/null --gradebook " +
                     (dir / ("grades-" + jobs + ".csv")).string() + " --jobs " + jobs)
              .code == 0);
  CHECK(slurp(dir / "grades-1.csv") == slurp(dir / "grades-4.csv"));
  // A line too long to read: the lines before it are graded and written, then the error.
  std::ofstream(batch) << "{\"id\": \"a\", \"unknown\": \"a_C\", \"answer\": \"-mu*g\"}\n{\"id\": \"b\", \"answer\": \""
                       << std::string(std::size_t{2} << 20, 'x')
                       << "\"}\n{\"id\": \"c\", \"unknown\": \"a_C\", \"answer\": \"mu*g\"}\n";
  const Run stopped = run_tackle("check " + suitcase + " --batch " + batch + " --jobs 2");
  CHECK(stopped.code == 1);
  CHECK(stopped.out.rfind("{\"id\":\"a\",\"unknown\":\"a_C\",\"answer\":\"-mu*g\",\"verdict\":\"correct\"", 0) == 0);
  CHECK(std::count(stopped.out.begin(), stopped.out.end(), '\n') == 1);
  CHECK(
      stopped.err ==
      batch +
          ":2: the line is longer than 1 MiB (expected JSON Lines: one object with id, unknown and answer per line)\n");
  // Usage: a number of processes from 0 to 256, with --batch.
  const Run many = run_tackle("check " + suitcase + " --batch " + batch + " --jobs 257");
  CHECK(many.code == 2);
  CHECK(many.err == "--jobs: Value 257 not in range 0 to 256\nRun with --help for more information.\n");
  const Run alone = run_tackle("check " + suitcase + " --unknown a_C --answer '-mu*g' --jobs 2");
  CHECK(alone.code == 2);
  CHECK(alone.err == "--jobs requires --batch\nRun with --help for more information.\n");
  fs::remove_all(dir);
}

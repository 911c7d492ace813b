#include <catch2/catch.hpp>

#include <map>

#include "expr/print.hpp"
#include "report/key.hpp"
#include "support/helpers.hpp"

using namespace tackle;
using GiNaC::ex;

namespace {
std::vector<Variant> variants_of(const std::string& example, int n, unsigned long long seed) {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/" + example, test::rules());
  const Derivation d = explain(*a);
  return draw_variants(a->model, d, n, seed, 6);
}
std::string rows(const std::vector<Variant>& vs) {
  std::string s;
  for (const auto& v : vs) {
    for (const auto& q : v.parameters) s += q.name + "=" + q.text() + " ";
    for (const auto& q : v.answers) s += q.name + "=" + q.text() + " ";
    s += "\n";
  }
  return s;
}
}  // namespace

TEST_CASE("Key: the same seed gives the same variants, another seed others", "[key]") {
  const auto a = variants_of("sample-12.3-two-mass-pulley.yaml", 5, 1);
  REQUIRE(a.size() == 5);
  CHECK(rows(a) == rows(variants_of("sample-12.3-two-mass-pulley.yaml", 5, 1)));
  CHECK(rows(a) != rows(variants_of("sample-12.3-two-mass-pulley.yaml", 5, 2)));
}

TEST_CASE("Key: drawn values are multiples of the step, inside the range, and answers follow them", "[key]") {
  for (const auto& v : variants_of("sample-12.3-two-mass-pulley.yaml", 20, 7)) {
    const double F = std::stod(v.parameters[0].number), mA = std::stod(v.parameters[1].number),
                 mB = std::stod(v.parameters[2].number);
    CHECK(F >= 100);
    CHECK(F <= 200);
    CHECK(std::fmod(F, 10.0) == 0.0);
    CHECK(std::fmod(mA, 5.0) == 0.0);
    // T = 2 F m_B/(9 m_A + 4 m_B), derived by hand (the example's notes).
    CHECK(std::stod(v.answers[0].number) == Approx(2 * F * mB / (9 * mA + 4 * mB)).epsilon(1e-5));
  }
}

TEST_CASE("Key: a variant that breaks a validity condition is never drawn", "[key][validity]") {
  // The suitcase tips (N_A < 0) when l < 2 mu h; its ranges reach there.
  const auto vs = variants_of("sample-12.7-suitcase.yaml", 50, 3);
  REQUIRE(vs.size() == 50);
  for (const auto& v : vs) {
    const double l = std::stod(v.parameters[0].number), h = std::stod(v.parameters[1].number);
    CHECK(l >= 2 * 0.3 * h);
    CHECK(std::stod(v.answers[1].number) >= 0);
  }
}

TEST_CASE("Key: the Markdown key has every problem's title and closed forms", "[key]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  const Derivation d = explain(*a);
  const std::string md = write_key({{&d, {}}}, Format::markdown);
  CHECK(md ==
        "# Answer key\n\n## Sample 12.8: an accelerating sign-board in 3-D\n\nFind $T_{HI}$.\n\n"
        "- $T_{HI} = \\frac{m a l}{2 d}$ = 6.78233 N\n");
}

TEST_CASE("Key: the LaTeX table's headers are typeset as in the derivation", "[key]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.3-two-mass-pulley.yaml", test::rules());
  const Derivation d = explain(*a);
  const std::vector<KeyEntry> entries{{&d, draw_variants(a->model, d, 2, 1, 6), true}};
  const std::string latex = write_key(entries, Format::latex);
  CHECK(latex.find("\\# & $F$ & $m_{A}$ & $m_{B}$ & $T$ & $\\ddot{x}_{A}$ & $\\ddot{x}_{B}$ \\\\") !=
        std::string::npos);
  CHECK(latex.find("\\texttt{ddot") == std::string::npos);
}

TEST_CASE("Key: every problem of a key writes its products in a person's order, not only the first", "[key]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.8-sign-board.yaml", test::rules());
  const auto b = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", test::rules());
  const Derivation da = explain(*a), db = explain(*b);
  const std::string md = write_key({{&da, {}}, {&db, {}}}, Format::markdown);
  CHECK(md.find("- $a_{C} = -\\mu g$ = -2.943 m/s^2\n") != std::string::npos);
  CHECK(md.find("- $N_{A} = \\frac{m g \\left(l - 2 \\mu h\\right)}{2 l}$ = 29.43 N\n") != std::string::npos);
}

TEST_CASE("Derivation: a report outlives its analysis, its motion and figures included", "[report]") {
  // The Derivation holds values (its motion in time is a copy whose conditions are the
  // model's, copied): written after the analysis is gone, the JSON still says the motion.
  std::vector<Derivation> phases;
  {
    const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.4-stacked-blocks-on-spring.yaml", test::rules());
    phases = explain_phases(*a);
  }
  REQUIRE(!phases.empty());
  REQUIRE(phases[0].motion);
  const std::string json = write(phases, Format::json, true);
  CHECK(json.find("\"degrees_of_freedom\": 1") != std::string::npos);
  CHECK(json.find("\"source\": \"contact c\"") != std::string::npos);
  const std::string html = write(phases, Format::html, true);
  CHECK(html.find("Sketch of the mechanism") != std::string::npos);
}

namespace {
// The derivation's step naming a shared sum (if any), and its boxed results by name.
std::pair<const Step*, std::map<std::string, ex>> named_sum_and_results(const Derivation& d) {
  const Step* named = nullptr;
  std::map<std::string, ex> results;
  for (const auto& st : d.steps)
    if (st.kind == Step::Kind::equation) {
      if (st.text == "a name for the sum the closed forms share")
        named = &st;
      else if (st.boxed)
        results[to_text(st.lhs)] = st.rhs;
    }
  return {named, results};
}
}  // namespace

TEST_CASE("Derivation: a sum the closed forms share is named once (a chain's M = m_1 + ... + m_5)", "[report]") {
  std::string yaml = "title: a chain of five blocks\naxes: [x]\nparameters:\n  F: {unit: N}\n";
  for (int i = 1; i <= 5; ++i) yaml += "  m_" + std::to_string(i) + ": {unit: kg}\n";
  yaml += "bodies:\n";
  for (int i = 1; i <= 5; ++i)
    yaml +=
        "  b" + std::to_string(i) + ": {mass: m_" + std::to_string(i) + ", position: x_" + std::to_string(i) + "}\n";
  yaml += "loads:\n  - {on: b5, force: F}\nstrings:\n";
  for (int i = 1; i <= 4; ++i)
    yaml += "  - {name: s" + std::to_string(i) + ", path: [b" + std::to_string(i) + ", b" + std::to_string(i + 1) +
            "], tension: T_" + std::to_string(i) + "}\n";
  yaml += "layout: {x_1: 1, x_2: 2, x_3: 3, x_4: 4, x_5: 5}\nfind: [ddot(x_1), T_1, T_4]\n";
  const auto a = test::run_text(yaml);
  const Derivation d = explain(*a);
  const SymbolTable& table = *a->model.symbols;
  const ex F = table.find("F")->sym, m1 = table.find("m_1")->sym;
  ex total = 0;
  for (int i = 1; i <= 5; ++i) total += table.find("m_" + std::to_string(i))->sym;
  // By hand: every block accelerates at F/(m_1 + ... + m_5); the string behind block k pulls
  // the k blocks behind it: T_1 = m_1 F/M, T_4 = (m_1 + ... + m_4) F/M.
  const auto [named, results] = named_sum_and_results(d);
  REQUIRE(named);
  CHECK(to_text(named->lhs) == "M");
  CHECK(normal(named->rhs - total).is_zero());
  const ex M = named->lhs;
  REQUIRE(results.count("ddot(x_1)"));
  CHECK(normal(results.at("ddot(x_1)") - F / M).is_zero());
  CHECK(normal(results.at("T_1") - m1 * F / M).is_zero());
  CHECK(normal(results.at("T_4") - (total - table.find("m_5")->sym) * F / M).is_zero());
  // The answers themselves (JSON, `tackle solve`) stay whole.
  CHECK(normal(*d.answers[0].closed_form - F / total).is_zero());
}

TEST_CASE("Derivation: a compound Atwood machine's sum of reciprocal masses is named S", "[report]") {
  const auto a = test::run_text(test::read_example("compound-atwood-8-levels.yaml"));
  const Derivation d = explain(*a);
  const SymbolTable& table = *a->model.symbols;
  const ex g = table.find("g")->sym;
  std::vector<ex> m{0};
  for (int i = 1; i <= 9; ++i) m.push_back(table.find("m_" + std::to_string(i))->sym);
  // By hand (the example's notes): T_8 = 256 g/S with S = 16384/m_1 + 4096/m_2 + ... + 4/m_7
  // + 1/m_8 + 1/m_9, T_k = 2^(8-k) T_8, ddot(y_k) = 2^(8-k) T_8/m_k - g.
  ex total = 1 / m[9];
  for (int k = 1; k <= 8; ++k) total += pow(4, 8 - k) / m[static_cast<std::size_t>(k)];
  const auto [named, results] = named_sum_and_results(d);
  REQUIRE(named);
  CHECK(to_text(named->lhs) == "S");
  CHECK(normal(named->rhs - total).is_zero());
  const ex S = named->lhs;
  CHECK(to_text(results.at("T_1")) == "32768*g/S");
  CHECK(normal(results.at("T_8") - 256 * g / S).is_zero());
  CHECK(normal(results.at("ddot(y_3)").subs(S == total) - (pow(2, 5) * 256 * g / (m[3] * total) - g)).is_zero());
}

#include <catch2/catch.hpp>

#include "report/sweep.hpp"
#include "support/helpers.hpp"

using namespace tackle;

namespace {
SweepResult figure_12_28(const SweepSpec& spec) {
  static const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/figure-12.28-suitcase-normal-forces.yaml", test::rules());
  static const Derivation d = explain(*a);
  return run_sweep(a->model, d, spec, Location{"test", 0, 0});
}
}  // namespace

TEST_CASE("Sweep: figure 12.28, N1, N2 and N1 - N2 against h/l for mg = 1, mu = 0.5", "[sweep]") {
  const auto r = figure_12_28({"h=0:2:41", {}, {"N_A", "N_B", "N_A - N_B"}});
  REQUIRE(r.x.size() == 41);
  CHECK(r.y_unit == "N");
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    const double h = r.x[i];
    // By hand (the example's notes): N_A = 1/2 - h/2, N_B = 1/2 + h/2, N_A - N_B = -h.
    CHECK(*r.y[0][i] == Approx(0.5 - h / 2).margin(1e-12));
    CHECK(*r.y[1][i] == Approx(0.5 + h / 2).margin(1e-12));
    CHECK(*r.y[2][i] == Approx(-h).margin(1e-12));
    // The suitcase tips once N_A < 0: past h/l = 1/(2 mu) = 1.
    CHECK(r.valid[i] == (h <= 1 + 1e-9));
  }
  const std::string csv = sweep_csv(r);
  CHECK(csv.rfind("h [m],N_A [N],N_B [N],N_A - N_B [N],valid\n0,0.5,0.5,0,true\n0.05,0.475,0.525,-0.05,true\n", 0) == 0);
  const std::string svg = sweep_svg(r);
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("stroke-dasharray=\"6,4\"") != std::string::npos);  // the tipped part
  const std::string pgf = sweep_pgfplots(r);
  CHECK(pgf.find("\\addlegendentry{$N_{A} - N_{B}$}") != std::string::npos);
  // As the SVG, the tipped part (h > l/(2 mu) = 1 m, N_A < 0) dashed, joined to the solid part.
  CHECK(pgf.find("\\addplot[color=blue, thick, forget plot, dashed] coordinates {(1.05,-0.025) (1.1,-0.05)") != std::string::npos);
  CHECK(pgf.find("\\addlegendentry{dashed: invalid}") != std::string::npos);
}

TEST_CASE("Sweep: fixed values are in the parameter's unit", "[sweep]") {
  const auto r = figure_12_28({"h=0:1:3", {"mu=0", "g=2"}, {"N_A"}});
  for (std::size_t i = 0; i < 3; ++i) CHECK(*r.y[0][i] == Approx(1.0));  // m g/2 with g = 2
}

TEST_CASE("Sweep: a bad spec is reported, all at once", "[sweep]") {
  try {
    (void)figure_12_28({"x=0:1:0", {"q=1"}, {"N_Q"}});
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    std::vector<std::string> got;
    for (const auto& d : e.diagnostics()) got.push_back(d.message);
    CHECK(got == std::vector<std::string>{
                     "the range to vary names 'x', which is not a parameter (parameters: m, g, mu, l, h)",
                     "the count '0' is not a whole number from 2 to 100000",
                     "'q=1' names 'q', which is not a parameter (parameters: m, g, mu, l, h)",
                     "plot 'N_Q': unknown name 'N_Q' (did you mean 'N_A'?)"});
  }
}

TEST_CASE("Sweep: a point where a curve is undefined is a gap, not a crash (found by fuzzing)", "[sweep][fuzz]") {
  // A tilted contact normal makes the normal forces' denominator vanish inside the sweep of h
  // (exit 3: GiNaC threw while substituting). Now that point has no value and is not valid.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/tests/fuzz/regressions/description/sweep-through-a-pole", test::rules());
  const Derivation d = explain(*a);
  const auto r = run_sweep(a->model, d, {"h=0:2:41", {}, {"N_A", "N_B"}}, Location{"test", 0, 0});
  REQUIRE(r.x.size() == 41);
  int gaps = 0;
  for (std::size_t i = 0; i < r.x.size(); ++i)
    if (!r.y[0][i]) {
      ++gaps;
      CHECK_FALSE(r.valid[i]);
    }
  CHECK(gaps >= 1);
}

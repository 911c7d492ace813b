#include <catch2/catch.hpp>
#include <algorithm>

#include "report/sweep.hpp"
#include "support/helpers.hpp"

using namespace tackle;

namespace {
SweepResult figure_12_28(const SweepSpec& spec) {
  static const auto a =
      analyze_file(TACKLE_SOURCE_DIR "/examples/figure-12.28-suitcase-normal-forces.yaml", test::rules());
  static const Derivation d = explain(*a);
  return run_sweep(a->model, d, spec, Location{"test", 0, 0});
}
}  // namespace

TEST_CASE("Sweep: figure 12.28, N1, N2 and N1 - N2 against h/l for mg = 1, mu = 0.5", "[sweep]") {
  const auto r = figure_12_28({"h=0:2:41", {}, {"N_A", "N_B", "N_A - N_B"}, ""});
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
  CHECK(csv.rfind("h [m],N_A [N],N_B [N],N_A - N_B [N],valid\n0,0.5,0.5,0,true\n0.05,0.475,0.525,-0.05,true\n", 0) ==
        0);
  const std::string svg = sweep_svg(r);
  CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK(svg.find("stroke-dasharray=\"6,4\"") != std::string::npos);  // the tipped part
  const std::string pgf = sweep_pgfplots(r);
  CHECK(pgf.find("\\addlegendentry{$N_{A} - N_{B}$}") != std::string::npos);
  // As the SVG, the tipped part (h > l/(2 mu) = 1 m, N_A < 0) dashed from where N_A = 0, the
  // sample at h = 1 m, where the solid part ends.
  CHECK(pgf.find("\\addplot[color=blue, thick, forget plot, dashed] coordinates {(1,0) (1.05,-0.025) (1.1,-0.05)") !=
        std::string::npos);
  CHECK(pgf.find("(0.95,0.025) (1,0) };") != std::string::npos);
  CHECK(pgf.find("\\addlegendentry{dashed: invalid}") != std::string::npos);
  // The y axis says what it shows, in its unit (issue 32, item 5).
  CHECK(svg.find(">N_A, N_B, N_A - N_B [N]</text>") != std::string::npos);
  CHECK(pgf.find("ylabel={$N_{A}$, $N_{B}$, $N_{A} - N_{B}$ [$\\mathrm{N}$]}") != std::string::npos);
}

TEST_CASE("Sweep: the dashed part begins where the condition fails, between two samples", "[sweep]") {
  // Samples at h = 0, 2/3, 4/3 and 2 m: the suitcase tips at h = l/(2 mu) = 1 m (N_A = 1/2 - h/2
  // = 0), between the second and the third. The point h = 1 m is put in: the solid part ends
  // and the dashed part begins there; the CSV keeps the four samples.
  const auto r = figure_12_28({"h=0:2:4", {}, {"N_A"}, ""});
  REQUIRE(r.x.size() == 5);
  CHECK(r.x[2] == Approx(1.0).epsilon(1e-12));
  CHECK(*r.y[0][2] == Approx(0.0).margin(1e-12));
  CHECK(r.is_boundary(2));
  CHECK(r.is_inserted(2));
  CHECK(std::count(r.inserted.begin(), r.inserted.end(), true) == 1);
  CHECK(sweep_csv(r) ==
        "h [m],N_A [N],valid\n0,0.5,true\n0.666667,0.166667,true\n1.33333,-0.166667,false\n2,-0.5,false\n");
  const std::string pgf = sweep_pgfplots(r);
  CHECK(pgf.find("\\addplot[color=blue, thick, forget plot] coordinates {(0,0.5) (0.666667,0.166667) (1,") !=
        std::string::npos);
  CHECK(pgf.find("\\addplot[color=blue, thick, forget plot, dashed] coordinates {(1,") != std::string::npos);
  CHECK(pgf.find("(1.33333,-0.166667) (2,-0.5) };") != std::string::npos);
  // Both ways: valid again after invalid (a sweep downwards).
  const auto down = figure_12_28({"h=2:0:4", {}, {"N_A"}, ""});
  REQUIRE(down.x.size() == 5);
  CHECK(down.x[2] == Approx(1.0).epsilon(1e-12));
  CHECK(!down.valid[1]);
  CHECK(down.valid[3]);
  const std::string pgf_down = sweep_pgfplots(down);
  CHECK(pgf_down.find(
            "\\addplot[color=blue, thick, forget plot, dashed] coordinates {(2,-0.5) (1.33333,-0.166667) (1,") !=
        std::string::npos);
  CHECK(pgf_down.find("\\addplot[color=blue, thick, forget plot] coordinates {(1,") != std::string::npos);
}

TEST_CASE("Sweep: against h/l, the book's axis, with h's own values beside it", "[sweep]") {
  // With l fixed at 2 m, h/l is h/2: N_A = m g (1/2 - mu h/l) = 1/2 - (h/l)/2 in N.
  const auto r = figure_12_28({"h=0:2:5", {"l=2"}, {"N_A"}, "h/l"});
  REQUIRE(r.x.size() == 5);
  CHECK(r.x_name == "h/l");
  CHECK(r.x_unit.empty());
  CHECK(r.x_latex == "h/l");
  for (std::size_t i = 0; i < 5; ++i) {
    CHECK(r.varied[i] == Approx(0.5 * static_cast<double>(i)));
    CHECK(r.x[i] == Approx(0.25 * static_cast<double>(i)));
    CHECK(*r.y[0][i] == Approx(0.5 - r.x[i] / 2).margin(1e-12));
  }
  CHECK(sweep_csv(r).rfind("h [m],h/l,N_A [N],valid\n0,0,0.5,true\n0.5,0.25,0.375,true\n", 0) == 0);
  CHECK(sweep_pgfplots(r).find("xlabel={$h/l$}") != std::string::npos);
  // Where the axis is undefined (l/h at h = 0) the point is left out, in the CSV too.
  const auto inverse = figure_12_28({"h=0:2:3", {}, {"N_A"}, "l/h"});
  CHECK(!inverse.y[0][0]);
  CHECK(sweep_csv(inverse).find("\n0,,,") != std::string::npos);
}

TEST_CASE("Sweep: a bad axis is reported", "[sweep]") {
  auto errors = [](const std::string& against) {
    std::vector<std::string> got;
    try {
      (void)figure_12_28({"h=0:1:3", {}, {"N_A"}, against});
    } catch (const InputError& e) {
      for (const auto& d : e.diagnostics()) got.push_back(d.message);
    }
    return got;
  };
  CHECK(errors("l") ==
        std::vector<std::string>{"against 'l' does not change with h (expected an expression in it, e.g. h/l)"});
  CHECK(errors("h + g") == std::vector<std::string>{"against 'h + g': adds an acceleration to a length"});
  CHECK(errors("h/q") ==
        std::vector<std::string>{"against 'h/q': unknown name 'q' (known: m, g, mu, l, h, t, a_C, N_A, N_B)"});
  CHECK(errors("h - h") ==
        std::vector<std::string>{"against 'h - h' does not change with h (expected an expression in it, e.g. h/l)"});
}

TEST_CASE("Sweep: fixed values are in the parameter's unit", "[sweep]") {
  const auto r = figure_12_28({"h=0:1:3", {"mu=0", "g=2"}, {"N_A"}, ""});
  for (std::size_t i = 0; i < 3; ++i) CHECK(*r.y[0][i] == Approx(1.0));  // m g/2 with g = 2
}

TEST_CASE("Sweep: a bad spec is reported, all at once", "[sweep]") {
  try {
    (void)figure_12_28({"x=0:1:0", {"q=1"}, {"N_Q"}, ""});
    FAIL("expected an InputError");
  } catch (const InputError& e) {
    std::vector<std::string> got;
    for (const auto& d : e.diagnostics()) got.push_back(d.message);
    CHECK(got ==
          std::vector<std::string>{"the range to vary names 'x', which is not a parameter (parameters: m, g, mu, l, h)",
                                   "the count '0' is not a whole number from 2 to 100000",
                                   "'q=1' names 'q', which is not a parameter (parameters: m, g, mu, l, h)",
                                   "plot 'N_Q': unknown name 'N_Q' (did you mean 'N_A'?)"});
  }
}

TEST_CASE("Sweep: a point where a curve is undefined is a gap, not a crash (found by fuzzing)", "[sweep][fuzz]") {
  // A tilted contact normal makes the normal forces' denominator vanish inside the sweep of h
  // (exit 3: GiNaC threw while substituting). Now that point has no value and is not valid.
  const auto a =
      analyze_file(TACKLE_SOURCE_DIR "/tests/fuzz/regressions/description/sweep-through-a-pole", test::rules());
  const Derivation d = explain(*a);
  const auto r = run_sweep(a->model, d, {"h=0:2:41", {}, {"N_A", "N_B"}, {}}, Location{"test", 0, 0});
  REQUIRE(r.x.size() == 41);
  int gaps = 0;
  for (std::size_t i = 0; i < r.x.size(); ++i)
    if (!r.y[0][i]) {
      ++gaps;
      CHECK_FALSE(r.valid[i]);
    }
  CHECK(gaps >= 1);
}

TEST_CASE("Sweep: curves of different units get a panel each, the time axis labelled under the lowest", "[sweep]") {
  SweepResult r;
  r.title = "two units";
  r.x_name = "t";
  r.x_unit = "s";
  r.x_latex = "t";
  r.names = {"y", "N", "y_B"};
  r.latex = {"y", "N", "y_{B}"};
  r.units = {"m", "N", "m"};  // no common unit: r.y_unit stays empty
  r.x = {0, 1, 2};
  r.y = {{0.0, 0.5, 1.0}, {10.0, 20.0, 30.0}, {1.0, 1.0, 1.0}};
  r.valid = {true, true, true};
  const std::string pgf = sweep_pgfplots(r);
  // Two axes: metres (y and y_B) above, newtons below it; t [s] only under the lowest.
  CHECK(pgf.find("\\begin{axis}[name=panel0, width=0.8\\textwidth, height=0.32\\textwidth, xticklabels={}, "
                 "ylabel={$y$, $y_{B}$ [$\\mathrm{m}$]}") != std::string::npos);
  CHECK(pgf.find("\\begin{axis}[name=panel1, width=0.8\\textwidth, height=0.32\\textwidth, at={(panel0.south west)}, "
                 "anchor=north west, yshift=-0.6cm, xlabel={$t$ [$\\mathrm{s}$]}, ylabel={$N$ [$\\mathrm{N}$]}") !=
        std::string::npos);
  CHECK(pgf.find("\\begin{axis}[name=panel2") == std::string::npos);
  const std::string svg = sweep_svg(r);
  CHECK(svg.find(">y, y_B [m]</text>") != std::string::npos);
  CHECK(svg.find(">N [N]</text>") != std::string::npos);
  CHECK(svg.find(">t [s]</text>") != std::string::npos);
  // Two plot frames.
  std::size_t frames = 0;
  for (std::size_t p = svg.find("fill=\"none\" stroke=\"black\"/>"); p != std::string::npos;
       p = svg.find("fill=\"none\" stroke=\"black\"/>", p + 1))
    ++frames;
  CHECK(frames == 2);
  // One unit: one panel, as before.
  r.y_unit = "m";
  r.units = {"m", "m", "m"};
  CHECK(sweep_pgfplots(r).find("name=panel1") == std::string::npos);
}

TEST_CASE("Sweep: the described runs are a stage of their own, which the derivation only carries", "[sweep]") {
  // The description's sweep, computed from the analysis and its answers (analysis/runs.hpp);
  // explain() narrates the same result, and computes nothing without the narration.
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/figure-12.28-suitcase-normal-forces.yaml", test::rules());
  const DescribedRuns runs = run_described(*a, answer(a->model, a->system, a->solution, 6));
  REQUIRE(runs.sweep);
  CHECK_FALSE(runs.motion);  // no motion in time asked for
  const Derivation d = explain(*a);
  REQUIRE(d.sweep_plot);
  CHECK(sweep_csv(*d.sweep_plot) == sweep_csv(*runs.sweep));
  CHECK(sweep_svg(*d.sweep_plot) == sweep_svg(*runs.sweep));
  CHECK(d.sweep_plot->title == a->model.title);
  CHECK_FALSE(explain(*a, ReportOptions{.narrate = false}).sweep_plot);
}

TEST_CASE("Sweep: the described motion is run as a stage, its events told by the derivation", "[sweep][motion]") {
  const auto a = analyze_file(TACKLE_SOURCE_DIR "/examples/rotation-pendulum.yaml", test::rules());
  REQUIRE(a->model.motion);
  REQUIRE(a->model.motion->until);
  const DescribedRuns runs = run_described(*a, answer(a->model, a->system, a->solution, 6));
  REQUIRE(runs.motion);
  CHECK_FALSE(runs.sweep);
  const Derivation d = explain(*a);
  REQUIRE(d.motion_plot);
  CHECK(sweep_csv(*d.motion_plot) == sweep_csv(runs.motion->table));
  REQUIRE_FALSE(d.motion_events.empty());
  CHECK(d.motion_events.front().rfind("Integrated to t = ", 0) == 0);
  const Derivation plain = explain(*a, ReportOptions{.narrate = false});
  CHECK_FALSE(plain.motion_plot);
  CHECK(plain.motion_events.empty());
}

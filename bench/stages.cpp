// Per-stage times of one description: build/bench/tackle_stages FILE (for reading, never for
// pass/fail). The chain is run stage by stage, then whole (analyze, explain, write).
#include <chrono>
#include <cstdio>
#include "pipeline/pipeline.hpp"
#include "core/files.hpp"
using namespace tackle;
using clk = std::chrono::steady_clock;
static double ms(clk::time_point a, clk::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}
int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: tackle_stages FILE\n");
    return 2;
  }
  auto t0 = clk::now();
  RuleSet rules = load_rules(TACKLE_SOURCE_DIR "/rules");
  auto t1 = clk::now();
  Description d = read_description(argv[1]);
  auto t2 = clk::now();
  Model m = build_model(d, rules);
  auto t3 = clk::now();
  EquationSystem s = build_equations(m);
  auto t4 = clk::now();
  auto dims = check_dimensions(m, s);
  auto t5 = clk::now();
  Solution lin = solve_equations(m.file, s.equations, s.unknowns);
  auto t6 = clk::now();
  Solution sol = solve(m, s);
  auto t7 = clk::now();
  PowerCheck pc = check_power(m, s, sol);
  auto t8 = clk::now();
  auto a = analyze_file(argv[1], rules);
  auto t9 = clk::now();
  Derivation der = explain(*a);
  auto t10 = clk::now();
  std::string out = write(der, Format::text, false);
  auto t11 = clk::now();
  std::printf(
      "rules %.1f read %.1f model %.1f equations %.1f dims %.1f linsolve %.1f solve(all) %.1f power %.1f | analyze "
      "%.1f explain %.1f write %.1f ms\n",
      ms(t0, t1), ms(t1, t2), ms(t2, t3), ms(t3, t4), ms(t4, t5), ms(t5, t6), ms(t6, t7), ms(t7, t8), ms(t8, t9),
      ms(t9, t10), ms(t10, t11));
}

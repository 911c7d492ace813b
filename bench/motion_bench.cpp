// Motion in time: the equations of motion with the closed-form response and the validity in
// time (sample 12.4, one degree of freedom), and a numeric integration of 10 s of a
// three-degree-of-freedom chain with its conditions watched (events). In process; the whole
// process is timed with `perf stat` (see the README). Timings are for reading, never for
// pass/fail.
#include <benchmark/benchmark.h>

#include "motion/simulate.hpp"
#include "pipeline/pipeline.hpp"

namespace {

const tackle::RuleSet& rules() {
  static const tackle::RuleSet r = tackle::load_rules(TACKLE_SOURCE_DIR "/rules");
  return r;
}

// The motion stage alone: equations of motion, response, quantities and conditions in time.
void motion_closed_form(benchmark::State& state) {
  const auto a = tackle::analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.4-stacked-blocks-on-spring.yaml", rules());
  for (auto _ : state) {
    auto m = tackle::analyze_motion(a->model, a->system, a->solution);
    benchmark::DoNotOptimize(m->conditions.size());
  }
}
BENCHMARK(motion_closed_form)->Name("motion/closed-form+validity/sample-12.4")->Unit(benchmark::kMillisecond);

// The whole analysis of sample 12.4 with its motion (read, build, solve, motion, explain).
void motion_whole_analysis(benchmark::State& state) {
  for (auto _ : state) {
    auto a = tackle::analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.4-stacked-blocks-on-spring.yaml", rules());
    auto d = tackle::explain(*a);
    benchmark::DoNotOptimize(d.steps.size());
  }
}
BENCHMARK(motion_whole_analysis)->Name("motion/analyze+explain/sample-12.4")->Unit(benchmark::kMillisecond);

// 10 s of three coupled degrees of freedom, compiled right-hand side, conditions watched.
void simulate_three_dof(benchmark::State& state) {
  const auto a = tackle::analyze_file(TACKLE_SOURCE_DIR "/examples/three-blocks-on-springs.yaml", rules());
  tackle::SimulationSpec spec;
  spec.until = 10;
  for (auto _ : state) {
    auto s = tackle::simulate(*a, spec, tackle::Location{});
    benchmark::DoNotOptimize(s.steps);
  }
}
BENCHMARK(simulate_three_dof)->Name("motion/simulate-10s/three-blocks-on-springs")->Unit(benchmark::kMillisecond);

}  // namespace

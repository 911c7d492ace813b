// Times the whole chain (read, build, balance, solve, explain) for every example, in process.
// Run: build/bench/tackle_bench  (timings are for reading, never for pass/fail)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <filesystem>

#include "pipeline/pipeline.hpp"

namespace {

void derive_and_solve(benchmark::State& state, const std::string& path) {
  const tackle::RuleSet rules = tackle::load_rules(TACKLE_SOURCE_DIR "/rules");
  for (auto _ : state) {
    auto analysis = tackle::analyze_file(path, rules);
    auto derivation = tackle::explain(*analysis);
    benchmark::DoNotOptimize(derivation.answers.size());
  }
}

void solve_only(benchmark::State& state, const std::string& path) {
  const tackle::RuleSet rules = tackle::load_rules(TACKLE_SOURCE_DIR "/rules");
  const auto analysis = tackle::analyze_file(path, rules);
  for (auto _ : state) {
    auto solution = tackle::solve(analysis->model, analysis->system);
    benchmark::DoNotOptimize(solution.rank);
  }
}

int register_examples() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(TACKLE_SOURCE_DIR "/examples"))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    benchmark::RegisterBenchmark(("derive+solve/" + f.stem().string()).c_str(), derive_and_solve, f.string())
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("solve/" + f.stem().string()).c_str(), solve_only, f.string())
        ->Unit(benchmark::kMicrosecond);
  }
  return 0;
}

const int registered = register_examples();

}  // namespace

BENCHMARK_MAIN();

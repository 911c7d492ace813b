// Checking answers in batch: a fixed set of answers (equivalent forms, wrong by a factor,
// wrong by sign, another form) for two problems, timed per check. bench/check_vs_sympy runs
// the same decisions through SymPy in the same run and prints the ratio.
#include <benchmark/benchmark.h>

#include "check/check.hpp"

namespace {

struct Case {
  const char* example;
  const char* unknown;
  const char* answer;
  const char* expect;
};

// Shared with bench/check_vs_sympy.py (keep the two lists equal).
const Case cases[] = {
    {"sample-12.8-sign-board.yaml", "T_HI", "m*a*l/(2*d)", "correct"},
    {"sample-12.8-sign-board.yaml", "T_HI", "a*m*sqrt(d^2+b^2+e^2)/d/2", "correct"},
    {"sample-12.8-sign-board.yaml", "T_HI", "m*a*sqrt(b^2+d^2+e^2)/d", "incorrect"},
    {"sample-12.8-sign-board.yaml", "T_HI", "-m*a*l/(2*d)", "incorrect"},
    {"sample-12.7-suitcase.yaml", "N_A", "m*g*(1/2 - mu*h/l)", "correct"},
    {"sample-12.7-suitcase.yaml", "N_A", "m*g*(l - 2*mu*h)/(2*l)", "correct"},
    {"sample-12.7-suitcase.yaml", "N_A", "m*g*(l - 2*mu*h)/l", "incorrect"},
    {"sample-12.7-suitcase.yaml", "N_A", "m*g/2", "incorrect"},
};

const tackle::Checker& checker_for(const std::string& example, bool latex = true) {
  static std::map<std::string, std::pair<std::unique_ptr<const tackle::Analysis>, std::unique_ptr<tackle::Checker>>>
      made;
  const std::string key = example + (latex ? "" : " (no latex)");
  auto it = made.find(key);
  if (it == made.end()) {
    static const tackle::RuleSet rules = tackle::load_rules(TACKLE_SOURCE_DIR "/rules");
    auto analysis = tackle::analyze_file(TACKLE_SOURCE_DIR "/examples/" + example, rules);
    tackle::CheckOptions options;
    options.echo_latex = latex;
    auto checker = std::make_unique<tackle::Checker>(*analysis, options);
    it = made.emplace(key, std::make_pair(std::move(analysis), std::move(checker))).first;
  }
  return *it->second.second;
}

void check_one(benchmark::State& state, const Case& c, bool latex) {
  const tackle::Checker& checker = checker_for(c.example, latex);
  const auto first = checker.check(c.unknown, c.answer);
  if (tackle::verdict_name(first.verdict) != c.expect) {
    state.SkipWithError(("unexpected verdict " + tackle::verdict_name(first.verdict)).c_str());
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(checker.check(c.unknown, c.answer).score);
}

// The whole set, one check after another, as a batch does: time per check.
void check_batch(benchmark::State& state) {
  for (const auto& c : cases) (void)checker_for(c.example);
  for (auto _ : state)
    for (const auto& c : cases) benchmark::DoNotOptimize(checker_for(c.example).check(c.unknown, c.answer).score);
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(std::size(cases)));
}

int register_cases() {
  for (const auto& c : cases) {
    benchmark::RegisterBenchmark((std::string("check/") + c.unknown + "/" + c.answer).c_str(), check_one, c, true)
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark((std::string("check-no-latex/") + c.unknown + "/" + c.answer).c_str(), check_one, c,
                                 false)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("check/batch", check_batch)->Unit(benchmark::kMicrosecond);
  return 0;
}

const int registered = register_cases();

}  // namespace

#include "pipeline/pipeline.hpp"

namespace tackle {

std::unique_ptr<const Analysis> analyze(const Description& d, const RuleSet& rules) {
  auto a = std::make_unique<Analysis>();
  a->model = build_model(d, rules);
  a->system = build_equations(a->model);
  a->solution = solve(a->model, a->system);
  return a;
}

std::unique_ptr<const Analysis> analyze_file(const std::string& path, const RuleSet& rules) {
  return analyze(read_description(path), rules);
}

Derivation explain(const Analysis& a) { return explain(a.model, a.system, a.solution); }

}  // namespace tackle

// Derives a problem through the installed library and prints its answers.
#include <iostream>

#include "expr/print.hpp"
#include "pipeline/pipeline.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const tackle::RuleSet rules = tackle::load_rules(RULES_DIR);
  const auto analysis = tackle::analyze_file(argv[1], rules);
  const tackle::Derivation d = tackle::explain(*analysis);
  for (const auto& a : d.answers)
    if (a.closed_form) std::cout << a.name << " = " << tackle::to_text(*a.closed_form) << "\n";
  return 0;
}

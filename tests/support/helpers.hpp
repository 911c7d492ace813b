// Test helpers: run the chain on inline YAML, collect diagnostics as strings.
#pragma once

#include <string>
#include <vector>

#include "pipeline/pipeline.hpp"

namespace tackle::test {

inline const RuleSet& rules() {
  static const RuleSet r = load_rules(TACKLE_SOURCE_DIR "/rules");
  return r;
}

inline std::unique_ptr<const Analysis> run_text(const std::string& yaml, const std::string& file = "t.yaml") {
  return tackle::analyze_text(yaml, file, rules());
}

/// An example's text, to vary it in a test.
inline std::string read_example(const std::string& name) { return read_text_file(TACKLE_SOURCE_DIR "/examples/" + name); }

/// Every diagnostic the text produces, formatted; empty when it is accepted.
inline std::vector<std::string> errors_of(const std::string& yaml) {
  try {
    (void)run_text(yaml);
  } catch (const InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
    return out;
  }
  return {};
}

}  // namespace tackle::test

// Fuzz target: a rule file through the rule reader; a rule that reads is then put in place
// of the built-in rule of its type and every example that uses that type is analyzed with
// it, so a mutated rule also exercises instantiation. Seeds: rules/.
#include "common.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include "core/files.hpp"

namespace {

// Each rule type -> the examples whose text mentions it, read once.
const std::map<std::string, std::vector<std::string>>& examples_by_type() {
  static const auto table = [] {
    std::map<std::string, std::vector<std::string>> t;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(TACKLE_SOURCE_DIR "/examples"))
      if (e.path().extension() == ".yaml" && !tackle::fuzz::slow_example(e.path().string())) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& type : tackle::fuzz::rules().names())
      for (const auto& f : files) {
        const std::string text = tackle::read_text_file(f.string());
        if (text.find("type: " + type + "\n") != std::string::npos ||
            text.find("type: " + type + ",") != std::string::npos ||
            text.find("type: " + type + "}") != std::string::npos)
          t[type].push_back(text);
      }
    return t;
  }();
  return table;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto& uses = examples_by_type();
  tackle::Rule rule;
  try {
    rule = tackle::parse_rule(tackle::fuzz::text_of(data, size), "fuzz-rule.yaml");
  } catch (const tackle::InputError&) {
    return 0;
  }
  const auto it = uses.find(rule.type);
  if (it == uses.end()) return 0;
  tackle::RuleSet set = tackle::fuzz::rules();
  set.add(rule);
  for (const auto& text : it->second) {
    try {
      const auto analysis = tackle::analyze_text(text, "example.yaml", set);
      (void)tackle::explain_phases(*analysis);
    } catch (const tackle::InputError&) {
    }
  }
  return 0;
}

// Shared by the fuzz targets: the rules and examples of this source tree, read once.
// A target returns normally for any input tackle handles (an answer, or an input error with
// a location); anything else (a crash, a sanitizer report, an exception that is not an
// InputError, a hang past libFuzzer's -timeout) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/files.hpp"
#include "pipeline/pipeline.hpp"
#include "ruleset/ruleset.hpp"

namespace tackle::fuzz {

inline const RuleSet& rules() {
  static const RuleSet r = load_rules(TACKLE_SOURCE_DIR "/rules");
  return r;
}

/// Examples too slow for libFuzzer's -timeout=2 under the sanitizers (listed, with the
/// reason, in tests/fuzz/slow-seeds.txt): the rule target leaves them out.
inline bool slow_example(const std::string& path) {
  static const std::string listed = [] {
    try {
      return read_text_file(TACKLE_SOURCE_DIR "/tests/fuzz/slow-seeds.txt");
    } catch (const std::exception&) {
      return std::string();
    }
  }();
  const auto slash = path.rfind('/');
  const std::string name = "examples/" + (slash == std::string::npos ? path : path.substr(slash + 1));
  return listed.find(name + "\n") != std::string::npos;
}

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// A check guards itself (an exception inside is the verdict undecided, code `internal`): for
/// the fuzzer such a verdict is still a finding, so it aborts on one (in a JSON result too).
inline void no_internal_verdict(const std::string& findings_or_json) {
  if (findings_or_json.find("\"internal\"") != std::string::npos || findings_or_json == "internal") {
    std::fprintf(stderr, "an internal error became a verdict: %s\n", findings_or_json.substr(0, 2000).c_str());
    std::abort();
  }
}

}  // namespace tackle::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

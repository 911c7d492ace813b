// Shared by the fuzz targets: the rules and examples of this source tree, read once.
// A target returns normally for any input tackle handles (an answer, or an input error with
// a location); anything else (a crash, a sanitizer report, an exception that is not an
// InputError, a hang past libFuzzer's -timeout) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "pipeline/pipeline.hpp"
#include "ruleset/ruleset.hpp"

namespace tackle::fuzz {

inline const RuleSet& rules() {
  static const RuleSet r = load_rules(TACKLE_SOURCE_DIR "/rules");
  return r;
}

inline std::string text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

}  // namespace tackle::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

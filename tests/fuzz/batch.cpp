// Fuzz target: a JSON Lines batch of submissions through the batch reader and the checker,
// with the grader summary. Seeds in seeds/batch/.
#include "common.hpp"

#include <sstream>

#include "grade/batch.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const auto analysis =
      tackle::analyze_file(TACKLE_SOURCE_DIR "/examples/sample-12.7-suitcase.yaml", tackle::fuzz::rules());
  // A seed for the points drawn for each check: a finding must replay the same way.
  static const tackle::Checker checker(*analysis, [] {
    tackle::CheckOptions options;
    options.seed = 1;
    return options;
  }());
  std::istringstream in(tackle::fuzz::text_of(data, size));
  std::ostringstream out;
  (void)tackle::check_batch(checker, in, out);
  tackle::fuzz::no_internal_verdict(out.str());
  return 0;
}

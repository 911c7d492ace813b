// Batch checking: JSON Lines in (`id`, `unknown`, `answer`), JSON Lines out, and a summary in
// the shape autograders read (Gradescope's results.json and PrairieLearn's external grader).
#pragma once

#include <istream>
#include <ostream>
#include <string>

#include "check/check.hpp"

namespace tackle {

struct BatchSummary {
  std::size_t lines = 0;
  std::size_t correct = 0;
  std::string grader_json;  // {"gradable", "score" (0-1), "tests": [...]}
};

/// Checks every line of `in`, writes one JSON result per line to `out`. A line that is not a
/// JSON object with those fields gets an `invalid` result that says why; nothing stops the
/// batch.
BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out);

/// One result as a JSON object (the single-answer `--format json` output).
[[nodiscard]] std::string result_json(const CheckResult& r, const std::string& answer, const std::string& id = {});
/// One result as text.
[[nodiscard]] std::string result_text(const CheckResult& r);

}  // namespace tackle

// Verdicts written: a checked answer's or equation's, a free body diagram's and a worked
// solution's, as text and JSON, a batch's result lines and the grading platforms' results
// files. The checker (check/) decides; these write what it decided (src/report/verdicts/).
#pragma once

#include <string>
#include <string_view>

#include "check/check.hpp"
#include "check/fbd.hpp"
#include "check/steps.hpp"

namespace tackle {

/// The results file for a grading platform, each as the platform documents it:
/// - gradescope: Gradescope's results.json, one test per line (`name`, `score`, `max_score`,
///   `status`, `output`, `visibility`) and the `output` summary; no top-level `score` (it
///   would override the tests' sum) unless `top_level_score`.
/// - prairielearn: PrairieLearn's external grader results.json: `gradable`, `score` (0-1),
///   `message`, `tests` (`name`, `points`, `max_points`, `message`); a submission with an answer
///   that cannot be graded as typed is `gradable: false` with `format_errors` (no attempt is
///   charged), and no score or tests (which would tell which other answers are right).
/// - jsonl: the per-line results again.
enum class ResultsFormat { gradescope, prairielearn, jsonl };

/// A string as JSON writes it (quoted, escaped), and a number (".0" when whole).
[[nodiscard]] std::string json_quoted(std::string_view s);
[[nodiscard]] std::string json_number(double v);
/// One test of a platform's results file (Gradescope: score, max_score, status, output;
/// PrairieLearn: points, max_points, message), on one line.
[[nodiscard]] std::string platform_test(ResultsFormat format, const std::string& name, double score, double max,
                                        bool passed, const std::string& output);
/// One result as one line of JSON, as a batch writes it (no newline).
[[nodiscard]] std::string result_line(const CheckResult& r, const std::string& answer, const std::string& id = {});
/// One result as a JSON object (the single-answer `--format json` output).
[[nodiscard]] std::string result_json(const CheckResult& r, const std::string& answer, const std::string& id = {});
/// One result as text.
[[nodiscard]] std::string result_text(const CheckResult& r);
/// A graded free body diagram as text, and as JSON.
[[nodiscard]] std::string fbd_text(const FbdGrade& g);
[[nodiscard]] std::string fbd_json(const FbdGrade& g);
/// A graded worked solution as text, as JSON, and as a grading platform's results file.
[[nodiscard]] std::string solution_text(const SolutionGrade& g);
[[nodiscard]] std::string solution_json(const SolutionGrade& g);
[[nodiscard]] std::string solution_results(const SolutionGrade& g, ResultsFormat format);

}  // namespace tackle

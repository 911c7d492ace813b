// Batch checking: JSON Lines in (`id`, `unknown`, `answer`), JSON Lines out, and a summary in
// the shape autograders read (Gradescope's results.json and PrairieLearn's external grader).
#pragma once

#include <functional>
#include <istream>
#include <map>
#include <optional>
#include <ostream>
#include <string>

#include "check/check.hpp"

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

/// One line of a batch once it is graded, as a gradebook takes it.
struct GradedLine {
  std::size_t line = 0;  // its line number in the batch (blank lines counted)
  bool object = false;   // whether it was a JSON object at all
  std::optional<std::string>
      student;  // `student` as written (a number as its JSON); none when absent or not a string or number
  std::optional<std::string> id;  // `id` as written; none when absent
  double points = 0, max_points = 0;
  Verdict verdict = Verdict::invalid;
};

struct GradeOptions {
  ResultsFormat format = ResultsFormat::gradescope;
  double points = 1;                         // each line's points, unless its unknown has its own
  std::map<std::string, double> points_for;  // by unknown
  bool top_level_score = false;              // gradescope: also a top-level score (the sum)
  // Values for every line (`--set F=120`), in each parameter's stated unit; a line's own
  // `params` object adds to them.
  std::vector<std::pair<std::string, std::string>> set;
  std::string source = "-";  // the batch's name in its errors ("-": standard input)
  // The problem's model, for lines with a free body diagram (`{"id", "fbd": {...}}`); none:
  // such a line is invalid.
  const Model* model = nullptr;
  // Called with each line once it is graded (`--gradebook`); none: not called.
  std::function<void(const GradedLine&)> graded;
  // Processes grading side by side (`--jobs`): this one and jobs - 1 children forked for each
  // block of lines, each a run of consecutive lines, their results written in the batch's
  // order. 1: one line at a time, in this process.
  int jobs = 1;
};
/// With several jobs, the lines of a block for each (a fork per child and block: a child's
/// caches go with it, and the pages GiNaC's reference counts write to are copied into it, so
/// blocks are large; 512 lines were slower than one process on 2 cores).
inline constexpr std::size_t block_lines_per_job = 4096;

/// At most this many of PrairieLearn's `format_errors` are listed (then how many more): the
/// results file is written as the batch is graded, and only totals are kept in memory.
inline constexpr std::size_t max_format_errors = 100;

struct BatchSummary {
  std::size_t lines = 0;
  std::size_t correct = 0;
  std::size_t invalid = 0;
  double points = 0, max_points = 0;
  std::string results;  // the results file in the asked format (the overload without a stream)
};

/// Checks every line of `in`, writes one JSON result per line to `out` as it goes, and the
/// platform's results file to `results`, also as it goes: memory stays bounded whatever the
/// size of the batch. A line is an object with `id`, `unknown`, `answer` and optionally
/// `params` (`{"F": 120}`: the student's own numbers, in the parameters' stated units). A line
/// that is not such an object gets an `invalid` result that says why, and the batch goes on;
/// only a line longer than `max_batch_line_bytes` stops it (InputError at that line, since
/// the line may never end), or a failed write to `out` (the caller finds `out` failed).
BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, std::ostream& results,
                         const GradeOptions& options = {});
/// The same, with the results file returned in `results` of the summary.
BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, const GradeOptions& options = {});

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

}  // namespace tackle

// Batch grading (a room above check/ and report/: it grades with the one and writes with the
// other). Batch checking: JSON Lines in (`id`, `unknown`, `answer`), JSON Lines out, and a summary in
// the shape autograders read (Gradescope's results.json and PrairieLearn's external grader).
#pragma once

#include <functional>
#include <istream>
#include <map>
#include <optional>
#include <ostream>
#include <string>

#include "check/check.hpp"
#include "report/verdicts.hpp"

namespace tackle {

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

}  // namespace tackle

// A class's gradebook from a batch (`check --batch FILE --gradebook grades.csv`): one row per
// student, one column per question (a line's `id`), the total; CSV as a spreadsheet reads it,
// or as Canvas's and Moodle's grade imports expect it (docs/grading.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/diagnostics.hpp"

namespace tackle {

/// - plain: `student`, a column per question, `total`; an answer that cannot be graded as typed
///   is `invalid`, a question not answered is empty.
/// - canvas: Canvas's gradebook import: `Student`, `ID`, `SIS User ID`, `SIS Login ID`,
///   `Section`, a column per question, `Final Points` (read only in Canvas: the import ignores
///   it); a `Points Possible` row; an `invalid` cell and a question not answered are empty (no
///   score).
/// - moodle: Moodle's CSV grade import: `student` (mapped to a user field at the import), a
///   column per question, `total`; an `invalid` cell and a question not answered are `-` (no
///   grade; text would stop Moodle's import).
enum class GradebookFormat { plain, canvas, moodle };
/// The layout named `plain`, `canvas` or `moodle` (the command line checks the name first).
[[nodiscard]] GradebookFormat gradebook_format(std::string_view name);

/// At most this many lines without a student or an id are reported (then how many more).
inline constexpr std::size_t max_gradebook_problems = 100;

/// The cells of a gradebook, filled one graded line at a time. Students and questions keep the
/// order they first appear in; memory is a cell per student and question, whatever the batch's
/// size.
class Gradebook {
 public:
  /// `source`: the batch's name in the problems' locations.
  explicit Gradebook(std::string source) : source_(std::move(source)) {}

  /// One graded line (its line number in the batch): the student's cell for the question is
  /// the points it earned of `max_points`, or `invalid`. A later line for the same student
  /// and question replaces the cell (the last submission counts). A line whose student or
  /// question is not known (std::nullopt, or an empty student) is a problem of the batch,
  /// located at its line; `readable` says whether the line was a JSON object at all.
  void add(std::size_t line, bool readable, const std::optional<std::string>& student,
           const std::optional<std::string>& question, double points, double max_points, bool invalid);

  /// The lines that could not be placed: with any, no gradebook is written (InputError).
  /// The first max_gradebook_problems, then one that says how many more.
  [[nodiscard]] std::vector<Diagnostic> problems() const;
  [[nodiscard]] std::size_t students() const { return students_.size(); }
  [[nodiscard]] std::size_t questions() const { return questions_.size(); }
  /// How many cells a later line replaced.
  [[nodiscard]] std::size_t replaced() const { return replaced_; }
  /// "name: question" of each `invalid` cell, in the rows' and columns' order.
  [[nodiscard]] std::vector<std::string> invalid_cells() const;

  /// The gradebook as CSV (RFC 4180: CRLF line ends, a field with a comma, a quote or a line
  /// break quoted, its quotes doubled).
  [[nodiscard]] std::string csv(GradebookFormat format) const;

 private:
  struct Cell {
    bool answered = false, invalid = false;
    double points = 0;
  };
  std::string source_;
  std::vector<std::string> students_, questions_;
  std::unordered_map<std::string, std::size_t> student_index_, question_index_;
  std::vector<double> possible_;          // by question: the most points a line of it was worth
  std::vector<std::vector<Cell>> cells_;  // [student][question]
  std::vector<Diagnostic> problems_;
  std::size_t unplaced_ = 0, replaced_ = 0;
};

/// A field of a CSV record as RFC 4180 writes it: as it is, or quoted (quotes doubled) when it
/// has a comma, a quote, a carriage return or a line feed.
[[nodiscard]] std::string csv_field(std::string_view text);

/// Points in a gradebook: at most 4 decimals, without trailing zeros ("1", "0.5", "0.6667").
[[nodiscard]] std::string gradebook_number(double points);

}  // namespace tackle

#include "report/gradebook.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace tackle {

GradebookFormat gradebook_format(std::string_view name) {
  if (name == "canvas") return GradebookFormat::canvas;
  if (name == "moodle") return GradebookFormat::moodle;
  return GradebookFormat::plain;
}

std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string gradebook_number(double points) {
  std::string out = fmt::format("{:.4f}", points);
  out.erase(out.find_last_not_of('0') + 1);
  if (out.back() == '.') out.pop_back();
  if (out == "-0") out = "0";
  return out;
}

void Gradebook::add(std::size_t line, bool readable, const std::optional<std::string>& student,
                    const std::optional<std::string>& question, double points, double max_points, bool invalid) {
  std::string problem;
  if (!readable)
    problem =
        "the line is not a JSON object, so whose answer it is is not known (expected {\"student\": ..., \"id\": ..., "
        "...} on every line with --gradebook)";
  else if (!student || student->empty())
    problem = "no \"student\" (expected the student's name or id, a string, on every line with --gradebook)";
  else if (!question)
    problem = "no \"id\" (expected the question's id on every line with --gradebook)";
  if (!problem.empty()) {
    if (++unplaced_ <= max_gradebook_problems) problems_.push_back({{source_, static_cast<int>(line), 0}, problem});
    return;
  }
  const auto [s, new_student] = student_index_.try_emplace(*student, students_.size());
  if (new_student) {
    students_.push_back(*student);
    cells_.emplace_back(questions_.size());
  }
  const auto [q, new_question] = question_index_.try_emplace(*question, questions_.size());
  if (new_question) {
    questions_.push_back(*question);
    possible_.push_back(0);
    for (auto& row : cells_) row.emplace_back();
  }
  Cell& cell = cells_[s->second][q->second];
  if (cell.answered) ++replaced_;
  cell = {true, invalid, invalid ? 0.0 : points};
  possible_[q->second] = std::max(possible_[q->second], max_points);
}

std::vector<Diagnostic> Gradebook::problems() const {
  std::vector<Diagnostic> out = problems_;
  if (unplaced_ > problems_.size())
    out.push_back(
        {{source_, 0, 0},
         "and " + std::to_string(unplaced_ - problems_.size()) + " more lines that the gradebook cannot place"});
  return out;
}

std::vector<std::string> Gradebook::invalid_cells() const {
  std::vector<std::string> out;
  for (std::size_t s = 0; s < students_.size(); ++s)
    for (std::size_t q = 0; q < questions_.size(); ++q)
      if (cells_[s][q].invalid) out.push_back(students_[s] + ": " + questions_[q]);
  return out;
}

std::string Gradebook::csv(GradebookFormat format) const {
  const char* eol = "\r\n";
  std::string out;
  const auto header = [&](std::initializer_list<std::string_view> before, std::string_view after) {
    bool first = true;
    for (const auto name : before) {
      out += (first ? "" : ",") + csv_field(name);
      first = false;
    }
    for (const auto& q : questions_) out += "," + csv_field(q);
    out += "," + csv_field(after) + eol;
  };
  // What a cell without points says: plain tells `invalid` from not answered; the platforms
  // take neither as text (Canvas: empty is no score; Moodle: `-` is no grade, and text stops
  // the import).
  const auto no_points = [&](const Cell& c) -> std::string {
    if (format == GradebookFormat::moodle) return "-";
    if (format == GradebookFormat::plain && c.invalid) return "invalid";
    return "";
  };
  if (format == GradebookFormat::canvas) {
    header({"Student", "ID", "SIS User ID", "SIS Login ID", "Section"}, "Final Points");
    out += "Points Possible,,,,";
    for (const double p : possible_) out += "," + gradebook_number(p);
    out += std::string(",") + eol;
  } else {
    header({"student"}, "total");
  }
  for (std::size_t s = 0; s < students_.size(); ++s) {
    const std::string name = csv_field(students_[s]);
    // Canvas finds a student by ID (left empty), then SIS User ID, then SIS Login ID, then the
    // name: the batch's student may be any of the last three.
    out += format == GradebookFormat::canvas ? name + ",," + name + "," + name + "," : name;
    double total = 0;
    for (std::size_t q = 0; q < questions_.size(); ++q) {
      const Cell& c = cells_[s][q];
      const bool graded = c.answered && !c.invalid;
      out += "," + (graded ? gradebook_number(c.points) : no_points(c));
      if (graded) total += c.points;
    }
    out += "," + gradebook_number(total) + eol;
  }
  return out;
}

}  // namespace tackle

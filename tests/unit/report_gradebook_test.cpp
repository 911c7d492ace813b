// The gradebook writer: cells, the three layouts, CSV escaping, the lines it cannot place.
#include <catch2/catch.hpp>

#include "report/gradebook.hpp"

using namespace tackle;

TEST_CASE("gradebook: a CSV field is quoted when it has a comma, a quote or a line break (RFC 4180)",
          "[report][gradebook]") {
  CHECK(csv_field("ada") == "ada");
  CHECK(csv_field("") == "");
  CHECK(csv_field("Doe, Jane") == "\"Doe, Jane\"");
  CHECK(csv_field("Jane \"JJ\" Doe") == "\"Jane \"\"JJ\"\" Doe\"");
  CHECK(csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(csv_field("cr\rhere") == "\"cr\rhere\"");
  CHECK(csv_field("\"") == "\"\"\"\"");
  CHECK(csv_field("Zoë Ø") == "Zoë Ø");  // UTF-8 as it is
}

TEST_CASE("gradebook: points have at most 4 decimals and no trailing zeros", "[report][gradebook]") {
  CHECK(gradebook_number(1) == "1");
  CHECK(gradebook_number(0) == "0");
  CHECK(gradebook_number(-0.0) == "0");
  CHECK(gradebook_number(0.5) == "0.5");
  CHECK(gradebook_number(2.0 / 3.0) == "0.6667");
  CHECK(gradebook_number(10) == "10");
  CHECK(gradebook_number(1000000) == "1000000");
  CHECK(gradebook_number(3 * (1.0 / 3.0)) == "1");
}

namespace {

// Three students, two questions; bo's q2 cannot be read; cy never answered q1.
Gradebook small_class() {
  Gradebook book("class.jsonl");
  book.add(1, true, "ada", "q1", 2, 2, false);
  book.add(2, true, "ada", "q2", 1, 1, false);
  book.add(3, true, "Doe, \"Bo\"", "q1", 0, 2, false);
  book.add(4, true, "Doe, \"Bo\"", "q2", 0, 1, true);
  book.add(5, true, "cy", "q2", 0.5, 1, false);
  return book;
}

}  // namespace

TEST_CASE("gradebook: plain: a row per student, a column per question, the total, invalid and unanswered cells",
          "[report][gradebook]") {
  const Gradebook book = small_class();
  CHECK(book.problems().empty());
  CHECK(book.students() == 3);
  CHECK(book.questions() == 2);
  CHECK(book.csv(GradebookFormat::plain) ==
        "student,q1,q2,total\r\n"
        "ada,2,1,3\r\n"
        "\"Doe, \"\"Bo\"\"\",0,invalid,0\r\n"
        "cy,,0.5,0.5\r\n");
  CHECK(book.invalid_cells() == std::vector<std::string>{"Doe, \"Bo\": q2"});
}

TEST_CASE("gradebook: canvas: the student columns, a Points Possible row, Final Points, no text in a grade",
          "[report][gradebook]") {
  CHECK(small_class().csv(GradebookFormat::canvas) ==
        "Student,ID,SIS User ID,SIS Login ID,Section,q1,q2,Final Points\r\n"
        "Points Possible,,,,,2,1,\r\n"
        "ada,,ada,ada,,2,1,3\r\n"
        "\"Doe, \"\"Bo\"\"\",,\"Doe, \"\"Bo\"\"\",\"Doe, \"\"Bo\"\"\",,0,,0\r\n"
        "cy,,cy,cy,,,0.5,0.5\r\n");
}

TEST_CASE("gradebook: moodle: an identifier column, the questions, the total, no grade is -", "[report][gradebook]") {
  CHECK(small_class().csv(GradebookFormat::moodle) ==
        "student,q1,q2,total\r\n"
        "ada,2,1,3\r\n"
        "\"Doe, \"\"Bo\"\"\",0,-,0\r\n"
        "cy,-,0.5,0.5\r\n");
}

TEST_CASE("gradebook: a later line for the same student and question replaces the cell", "[report][gradebook]") {
  Gradebook book("b.jsonl");
  book.add(1, true, "ada", "q1", 0, 1, false);
  book.add(2, true, "ada", "q1", 1, 1, false);
  book.add(3, true, "ben", "q1", 1, 1, false);
  book.add(4, true, "ben", "q1", 0, 1, true);  // the last one counts, even when it cannot be read
  CHECK(book.replaced() == 2);
  CHECK(book.csv(GradebookFormat::plain) == "student,q1,total\r\nada,1,1\r\nben,invalid,0\r\n");
}

TEST_CASE("gradebook: a question's points possible are the most any of its lines was worth", "[report][gradebook]") {
  Gradebook book("b.jsonl");
  book.add(1, true, "ada", "q1", 1, 1, false);
  book.add(2, true, "ben", "q1", 3, 3, false);
  CHECK(book.csv(GradebookFormat::canvas) ==
        "Student,ID,SIS User ID,SIS Login ID,Section,q1,Final Points\r\n"
        "Points Possible,,,,,3,\r\n"
        "ada,,ada,ada,,1,1\r\n"
        "ben,,ben,ben,,3,3\r\n");
}

TEST_CASE("gradebook: a line without a student or an id is a located problem, not a row", "[report][gradebook]") {
  Gradebook book("class.jsonl");
  book.add(1, false, std::nullopt, std::nullopt, 0, 1, true);
  book.add(2, true, std::nullopt, "q1", 1, 1, false);
  book.add(3, true, "", "q1", 1, 1, false);
  book.add(4, true, "ada", std::nullopt, 1, 1, false);
  book.add(5, true, "ada", "q1", 1, 1, false);
  const auto problems = book.problems();
  REQUIRE(problems.size() == 4);
  CHECK(format(problems[0]) ==
        "class.jsonl:1: the line is not a JSON object, so whose answer it is is not known (expected {\"student\": ..., "
        "\"id\": ..., ...} "
        "on every line with --gradebook)");
  CHECK(format(problems[1]) ==
        "class.jsonl:2: no \"student\" (expected the student's name or id, a string, on every line with --gradebook)");
  CHECK(format(problems[2]) ==
        "class.jsonl:3: no \"student\" (expected the student's name or id, a string, on every line with --gradebook)");
  CHECK(format(problems[3]) == "class.jsonl:4: no \"id\" (expected the question's id on every line with --gradebook)");
  CHECK(book.students() == 1);
}

TEST_CASE("gradebook: past 100 lines that cannot be placed, one problem says how many more", "[report][gradebook]") {
  Gradebook book("class.jsonl");
  for (std::size_t line = 1; line <= max_gradebook_problems + 7; ++line)
    book.add(line, true, std::nullopt, "q1", 1, 1, false);
  const auto problems = book.problems();
  REQUIRE(problems.size() == max_gradebook_problems + 1);
  CHECK(format(problems.back()) == "class.jsonl: and 7 more lines that the gradebook cannot place");
}

TEST_CASE("gradebook: an empty batch is a header and nothing else", "[report][gradebook]") {
  const Gradebook book("empty.jsonl");
  CHECK(book.csv(GradebookFormat::plain) == "student,total\r\n");
  CHECK(book.csv(GradebookFormat::canvas) ==
        "Student,ID,SIS User ID,SIS Login ID,Section,Final Points\r\nPoints Possible,,,,,\r\n");
}

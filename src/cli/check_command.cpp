// tackle check: one answer, one equation, a free body diagram, a worked solution or a batch,
// each read, checked and written by its own step.
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "grade/batch.hpp"
#include "check/fbd.hpp"
#include "check/steps.hpp"
#include "report/verdicts.hpp"
#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "core/files.hpp"
#include "core/utf8.hpp"
#include "report/gradebook.hpp"

namespace tackle::cli {

namespace {

// check: what is checked (an answer, an equation, a worked solution, a free body diagram, a
// batch); the options usage rules read are kept in `c`, and the unknown's is returned.
CLI::Option* define_check_inputs(CLI::App* sub, Options& o, Commands& c) {
  CLI::Option* unknown = nullptr;
  sub->add_option("file", o.file, "Problem description (YAML)")->required();
  unknown = sub->add_option("--unknown", o.unknown, "The unknown the answer is for, e.g. T_HI");
  c.answer = sub->add_option("--answer", o.answer, "The answer: an expression, 'T = ...', or a number with a unit");
  c.equation =
      sub->add_option("--equation", o.equation,
                      "An equation the student wrote, e.g. '2*T - F = m_A*ddot(x_A)': is it one of the balances and "
                      "constraints, or does it follow from them?")
          ->each([&](const std::string&) { o.equation_given = true; });
  c.steps = sub->add_option("--steps", o.steps,
                            "A worked solution (YAML: steps: [{fbd: ...}, {equation: ...}, {answer: ..., "
                            "unknown: T}]) graded as a whole: "
                            "each step, the equations used and missing, the first wrong step, a score");
  c.fbd = sub->add_option(
      "--fbd", o.fbd,
      "A free body diagram the student drew (YAML: body: B, forces: [{name: T, at: pB, direction: [-1]}]): "
      "each force drawn, missing, extra or the wrong way, and a score");
  sub->add_option("--rubric", o.rubric,
                  "With --steps or --fbd: points for FBDs, balances, constraints and answers, what a wrong "
                  "step costs, and how an FBD is scored (YAML)");
  c.batch = sub->add_option(
      "--batch", o.batch,
      "JSON Lines file of {\"id\", \"unknown\", \"answer\"}, {\"id\", \"equation\"} or {\"id\", \"fbd\"} "
      "(- for standard input)");
  return unknown;
}

// check: what a batch or a worked solution writes besides its lines (results for a grading
// platform, a gradebook) and how it is graded (jobs, points).
void define_check_grading(CLI::App* sub, Options& o, const Commands& c) {
  auto* results_opt =
      sub->add_option("--results", o.results, "With --batch or --steps: also write a grading platform's results file");
  sub->add_option("--results-format", o.results_format, "The results file's platform")
      ->check(CLI::IsMember({"gradescope", "prairielearn", "jsonl"}))
      ->capture_default_str()
      ->needs(results_opt);
  auto* gradebook_opt =
      sub->add_option("--gradebook", o.gradebook,
                      "With --batch: also write the class's gradebook (CSV): a row per line's \"student\", "
                      "a column per question \"id\", the points and the total");
  sub->add_option("--gradebook-format", o.gradebook_format,
                  "The gradebook's layout: a spreadsheet's, or Canvas's or Moodle's grade import")
      ->check(CLI::IsMember({"plain", "canvas", "moodle"}))
      ->capture_default_str()
      ->needs(gradebook_opt);
  sub->add_option("--jobs", o.jobs,
                  "With --batch: grade with N processes side by side (0: one per core); the results are the "
                  "same, in the batch's order")
      ->check(CLI::Range(0, 256))
      ->capture_default_str()
      ->needs(c.batch);
  sub->add_option("--points", o.points_text,
                  "Points for each answer (N), or for one unknown's answers (NAME=N); repeatable")
      ->needs(c.batch);
  sub->add_flag("--top-level-score", o.top_level_score,
                "Gradescope: also write the total as the top-level score "
                "(it overrides the tests' sum)")
      ->needs(results_opt);
}

// check: the numbers (a student's own values, tolerance, figures, seed, time) and the output.
void define_check_numbers(CLI::App* sub, Options& o) {
  sub->add_option("--set", o.set_values,
                  "A parameter's value for this check, in its stated unit (NAME=VALUE, repeatable): "
                  "a student's own variant");
  sub->add_flag("--reveal", o.reveal, "Name the correct value in the feedback (never, without it)");
  sub->add_option("--tolerance", o.tolerance, "Relative tolerance for numbers with units")
      ->check(finite_number)
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  sub->add_option("--sig-figs", o.sig_figs,
                  "Instead of the tolerance: numbers must match to this many significant figures")
      ->check(CLI::Range(1, 15));
  sub->add_option("--seed", o.seed,
                  "Draw the check's own random points from this seed (reproducible tests only: "
                  "a student who knows the points can build a wrong answer that passes)")
      ->check(seed_number)
      ->each([&](const std::string&) { o.seeded = true; });
  sub->add_option("--time-budget", o.time_budget_ms,
                  "Milliseconds to check one answer in; past them it is undecided (code budget). A slow or busy "
                  "machine may need more")
      ->check(CLI::Range(1, 600000))
      ->capture_default_str();
  sub->add_flag("--require-simplified", o.require_simplified, "A correct answer that is not simplified is incorrect");
  sub->add_flag("--no-latex", o.no_latex, "Do not echo answers in LaTeX (faster batches)");
  sub->add_option("--format", o.format, "Output format (single answers)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
  with_phase(sub, o);
}

// check: its options, then which need or exclude which.
}  // namespace

void define_check(CLI::App* sub, Options& o, Commands& c) {
  CLI::Option* unknown = define_check_inputs(sub, o, c);
  define_check_grading(sub, o, c);
  define_check_numbers(sub, o);
  c.answer->needs(unknown);
  unknown->needs(c.answer);
  c.batch->excludes(c.answer);
  c.equation->excludes(c.answer)->excludes(c.batch)->excludes(unknown);
  c.steps->excludes(c.answer)->excludes(c.batch)->excludes(unknown)->excludes(c.equation);
  c.fbd->excludes(c.answer)->excludes(c.batch)->excludes(unknown)->excludes(c.equation)->excludes(c.steps);
}

namespace {

using Values = std::vector<std::pair<std::string, std::string>>;

// The checker's options, as the command line gave them.
tackle::CheckOptions check_options(const Options& o) {
  tackle::CheckOptions options;
  options.relative_tolerance = o.tolerance;
  if (o.sig_figs > 0) options.significant_figures = o.sig_figs;
  options.require_simplified = o.require_simplified;
  options.echo_latex = !o.no_latex;
  options.reveal = o.reveal;
  if (o.seeded) options.seed = o.seed;
  options.time_budget = std::chrono::milliseconds(o.time_budget_ms);
  return options;
}

// --set NAME=VALUE, as pairs; nothing (the usage problem said) when one has no '='.
std::optional<Values> set_values(const Options& o) {
  Values set;
  for (const auto& v : o.set_values) {
    const auto eq = v.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::cerr << "tackle check: --set " << tackle::printable(v) << ": expected NAME=VALUE\n";
      return std::nullopt;
    }
    set.emplace_back(v.substr(0, eq), v.substr(eq + 1));
  }
  return set;
}

// --points N or NAME=N into `grade`; false (the usage problem said) for one that is not a number.
bool read_points(const Options& o, tackle::GradeOptions& grade) {
  for (const auto& p : o.points_text) {
    const auto eq = p.find('=');
    const std::string number = eq == std::string::npos ? p : p.substr(eq + 1);
    char* end = nullptr;
    const double v = std::strtod(number.c_str(), &end);
    if (number.empty() || *end != '\0' || !(v >= 0) || v > 1e6) {
      std::cerr << "tackle check: --points " << p << ": expected a number of points from 0 to 10^6, or NAME=N\n";
      return false;
    }
    if (eq == std::string::npos)
      grade.points = v;
    else
      grade.points_for[p.substr(0, eq)] = v;
  }
  return true;
}

// How a batch is graded: the results' platform, points, values, jobs.
std::optional<tackle::GradeOptions> grade_options(const Options& o, const Values& set, const tackle::Model& model) {
  tackle::GradeOptions grade;
  grade.format = o.results_format == "prairielearn" ? tackle::ResultsFormat::prairielearn
                 : o.results_format == "jsonl"      ? tackle::ResultsFormat::jsonl
                                                    : tackle::ResultsFormat::gradescope;
  grade.top_level_score = o.top_level_score;
  grade.set = set;
  if (!read_points(o, grade)) return std::nullopt;
  grade.source = o.batch;
  grade.model = &model;
  grade.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return grade;
}

// A batch's outputs: each through a temporary file, renamed into place only when the whole
// batch was graded (standard output when not given).
struct BatchOutputs {
  std::optional<tackle::AtomicOutput> out, results, gradebook;

  // Opens the files given; false (said) when one cannot be made.
  bool open(const Options& o) {
    for (auto& [file, path] :
         {std::pair{&out, &o.out}, std::pair{&results, &o.results}, std::pair{&gradebook, &o.gradebook}}) {
      if (path->empty() || *path == "-") continue;
      file->emplace(*path);
      if (!(*file)->ok()) {
        std::cerr << (*file)->error() << "\n";
        return false;
      }
    }
    return true;
  }

  // Renames every file into place: 0, or 1 (said) when one cannot be.
  int commit() {
    for (auto* file : {&out, &results, &gradebook})
      if (*file && !(*file)->commit()) {
        std::cerr << (*file)->error() << "\n";
        return 1;
      }
    return 0;
  }
};

// The class's gradebook, once the whole batch was graded: 0, 1 when it cannot be written.
int write_gradebook(const Options& o, const tackle::Gradebook& book, BatchOutputs& files) {
  // A line whose student or question is not known: no gradebook (and no other output),
  // rather than one that leaves a student out.
  if (const auto problems = book.problems(); !problems.empty()) throw tackle::InputError(problems);
  const auto format = tackle::gradebook_format(o.gradebook_format);
  const std::string csv = book.csv(format);
  if (files.gradebook)
    files.gradebook->stream() << csv;
  else if (std::cout << csv; !standard_output_written())
    return 1;
  if (format != tackle::GradebookFormat::plain)
    for (const auto& cell : book.invalid_cells())
      std::cerr << "tackle check: " << o.gradebook << ": " << cell
                << " cannot be graded as typed: its cell is left without a grade\n";
  return 0;
}

// --batch: read and graded line by line (or by blocks of lines with several jobs), each
// result written as it goes: memory stays bounded whatever the size of the batch.
int run_batch(const Options& o, const tackle::Checker& checker, const tackle::Model& model, const Values& set) {
  auto grade = grade_options(o, set, model);
  if (!grade) return 2;
  std::unique_ptr<std::istream> batch_file;
  if (o.batch != "-") batch_file = tackle::open_text_file(o.batch);
  std::istream& batch = batch_file ? *batch_file : std::cin;
  // A gradebook: each graded line's cell, written when the whole batch was graded.
  std::optional<tackle::Gradebook> book;
  if (!o.gradebook.empty()) {
    book.emplace(o.batch);
    grade->graded = [&book](const tackle::GradedLine& g) {
      book->add(g.line, g.object, g.student, g.id, g.points, g.max_points, g.verdict == tackle::Verdict::invalid);
    };
  }
  BatchOutputs files;
  if (!files.open(o)) return 1;
  std::ostream& sink = files.out ? files.out->stream() : std::cout;
  std::ostream null_results(nullptr);  // no --results: nothing is kept (badbit: every write dropped)
  std::ostream& results = files.results ? files.results->stream() : null_results;
  (void)tackle::check_batch(checker, batch, sink, results, *grade);
  // Standard output failed part of the way: the batch stopped there, and a results file of
  // part of the batch is not written.
  if (!files.out && !standard_output_written()) return 1;
  if (book)
    if (const int rc = write_gradebook(o, *book, files); rc != 0) return rc;
  return files.commit();
}

// The rubric of --rubric, or the default one.
tackle::Rubric rubric_of(const Options& o, const tackle::Model& model) {
  return o.rubric.empty() ? tackle::Rubric{} : tackle::read_rubric(tackle::read_text_file(o.rubric), o.rubric, model);
}

// --fbd: a free body diagram, graded.
int run_fbd(const Options& o, const tackle::Model& model) {
  const tackle::StudentFbd fbd = tackle::read_fbd_file(tackle::read_text_file(o.fbd), o.fbd, model);
  const tackle::Rubric rubric = rubric_of(o, model);
  std::vector<tackle::Diagnostic> problems;
  const tackle::FbdGrade grade = tackle::check_fbd(model, fbd, rubric.fbd, problems);
  if (!problems.empty()) throw tackle::InputError(problems);  // a name the problem does not have
  return emit(o.format == "json" ? tackle::fbd_json(grade) : tackle::fbd_text(grade), o.out);
}

// --steps: a worked solution, graded as a whole (and its platform's results file if asked).
int run_steps(const Options& o, const tackle::Checker& checker, const tackle::Model& model) {
  const auto solution = tackle::read_solution(tackle::read_text_file(o.steps), o.steps, model);
  const tackle::Rubric rubric = rubric_of(o, model);
  const tackle::SolutionGrade grade = tackle::grade_solution(checker, model, solution, rubric);
  if (!o.results.empty()) {
    const auto format =
        o.results_format == "prairielearn" ? tackle::ResultsFormat::prairielearn : tackle::ResultsFormat::gradescope;
    if (o.results_format == "jsonl") {
      std::cerr << "tackle check: --steps writes gradescope or prairielearn results, not jsonl (its --format json is "
                   "the lines' form)\n";
      return 2;
    }
    if (const int rc = emit(tackle::solution_results(grade, format), o.results); rc != 0) return rc;
  }
  return emit(o.format == "json" ? tackle::solution_json(grade) : tackle::solution_text(grade), o.out);
}

}  // namespace

int run_check(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  const tackle::Checker checker(*analysis, check_options(o));
  const auto set = set_values(o);
  if (!set) return 2;
  std::optional<GiNaC::exmap> values;
  if (!set->empty()) {
    std::string problem;
    bool out_of_domain = false;
    values = checker.values_for(*set, problem, &out_of_domain);
    if (!values) {
      std::cerr << "tackle check: --set: " << problem << "\n";
      return out_of_domain ? 1 : 2;  // a value the problem does not allow is bad input
    }
  }
  if (!o.batch.empty()) return run_batch(o, checker, analysis->model, *set);
  if (!o.fbd.empty()) return run_fbd(o, analysis->model);
  if (!o.steps.empty()) return run_steps(o, checker, analysis->model);
  if (o.equation_given) {
    const auto result = checker.check_equation(o.equation);
    return emit(o.format == "json" ? tackle::result_json(result, o.equation) : tackle::result_text(result), o.out);
  }
  const auto result = checker.check(o.unknown, o.answer, values ? &*values : nullptr);
  return emit(o.format == "json" ? tackle::result_json(result, o.answer) : tackle::result_text(result), o.out);
}

}  // namespace tackle::cli

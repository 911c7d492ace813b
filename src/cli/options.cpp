// The command line's subcommands and their options (see options.hpp).
#include "cli/options.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <limits>

#include "core/utf8.hpp"
#include "report/step_page.hpp"
#include "report/writer.hpp"

namespace tackle::cli {

namespace {

// CLI11's ranges let NaN through (every comparison with it is false), and its conversion of
// an unsigned number wraps -1 and saturates past 2^64 - 1: these check the text first.
const CLI::Validator finite_number(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || !std::isfinite(v))
        return "'" + tackle::printable(text) + "' is not a finite number";
      return {};
    },
    "NUMBER");
const CLI::Validator seed_number(
    [](std::string& text) -> std::string {
      const std::string max = std::to_string(std::numeric_limits<std::uint64_t>::max());
      const bool digits =
          !text.empty() && std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
      const std::string significant = text.substr(std::min(text.find_first_not_of('0'), text.size()));
      if (!digits || significant.size() > max.size() || (significant.size() == max.size() && significant > max))
        return "'" + tackle::printable(text) + "' is not a seed (expected a whole number from 0 to " + max + ")";
      return {};
    },
    "SEED");

// --phase, of every command that analyzes one description.
void with_phase(CLI::App* sub, Options& o) {
  sub->add_option("--phase", o.phase, "A phase of a description with 'phases', by name");
}

// derive and solve: the file, its phase, digits, format and output.
void with_common_options(CLI::App* sub, Options& o) {
  sub->add_option("file", o.file, "Problem description (YAML)")->required();
  with_phase(sub, o);
  sub->add_option("--digits", o.digits, "Significant digits of the numbers (any precision)")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  sub->add_option("--format", o.format, "Output format")
      ->check(CLI::IsMember(tackle::format_names()))
      ->capture_default_str();
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
}

// isolate: one unknown, or --all.
void define_isolate(CLI::App* sub, Options& o) {
  sub->add_option("file", o.file, "Problem description (YAML)")->required();
  auto* target_opt = sub->add_option("unknown", o.target, "The unknown, e.g. T_HI");
  auto* all_opt = sub->add_flag("--all", o.all, "Report for every unknown whether one equation gives it");
  target_opt->excludes(all_opt);
  sub->add_option("--format", o.format, "Output format")->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
  with_phase(sub, o);
}

// key: the files, their variants and format.
void define_key(CLI::App* sub, Options& o) {
  sub->add_option("files", o.key_files, "Problem descriptions (YAML)")->required();
  sub->add_option("--format", o.key_format, "Output format")
      ->check(CLI::IsMember({"latex", "markdown", "json", "html"}))
      ->capture_default_str();
  sub->add_option("--variants", o.variants, "Numeric variants per problem, drawn from the parameters' 'range'")
      ->check(CLI::Range(0, 10000));
  sub->add_option("--seed", o.seed, "Seed for the variants (the same seed gives the same variants)")
      ->check(seed_number)
      ->capture_default_str();
  sub->add_option("--digits", o.digits, "Significant digits of the numbers")->check(CLI::Range(1, 1000));
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
}

// sheet: as key, with figures if asked.
void define_sheet(CLI::App* sub, Options& o) {
  sub->add_option("files", o.key_files, "Problem descriptions (YAML)")->required();
  sub->add_option("--format", o.key_format, "Output format")
      ->check(CLI::IsMember({"latex", "markdown", "html"}))
      ->capture_default_str();
  sub->add_flag("--figures", o.figures,
                "Also draw each problem's free body diagrams under its statement (a 1-D or 2-D mechanism's "
                "sketch is always drawn)");
  sub->add_option("--variants", o.variants, "Numeric variants per problem, drawn from the parameters' 'range'")
      ->check(CLI::Range(0, 10000));
  sub->add_option("--seed", o.seed, "Seed for the variants (as for key)")->check(seed_number)->capture_default_str();
  sub->add_option("--digits", o.digits, "Significant digits of the numbers")->check(CLI::Range(1, 1000));
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
}

// page: the checker's endpoint.
void define_page(CLI::App* sub, Options& o) {
  sub->add_option("file", o.file, "Problem description (YAML)")->required();
  sub->add_option("--endpoint", o.endpoint,
                  "Where the checker answers (POST {endpoint}/step and {endpoint}/solution): "
                  "a path or an http(s) URL; default: the page's own location")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const std::string problem = tackle::endpoint_problem(text);
            return problem.empty() ? std::string() : "'" + tackle::printable(text) + "' " + problem;
          },
          "URL"));
  sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
  with_phase(sub, o);
}

// sweep: the range, the fixed values, the axis and the outputs.
void define_sweep(CLI::App* sub, Options& o) {
  sub->add_option("file", o.file, "Problem description (YAML)")->required();
  sub->add_option("--vary", o.vary, "name=start:end:count, in the parameter's unit (default: the description's sweep)");
  sub->add_option("--fix", o.fixes, "name=value, in the parameter's unit (repeatable)");
  sub->add_option("--against", o.against,
                  "The horizontal axis: an expression in the parameters, e.g. h/l (default: the varied parameter)");
  sub->add_option("--plot", o.plot, "Comma-separated expressions in the answers and parameters, e.g. N_A,N_B,N_A-N_B");
  sub->add_option("--csv", o.csv_out, "Write the data as CSV here (default: standard output)");
  sub->add_option("--svg", o.svg_out, "Write an SVG plot here");
  sub->add_option("--pgfplots", o.pgf_out, "Write a pgfplots figure (LaTeX) here");
  with_phase(sub, o);
}

// simulate: the end time, the samples and the outputs.
void define_simulate(CLI::App* sub, Options& o) {
  sub->add_option("file", o.file, "Problem description (YAML) with a 'motion' section")->required();
  sub->add_option("--until", o.until, "End time in seconds (default: the description's 'until')")
      ->check(finite_number)
      ->check(CLI::PositiveNumber);
  sub->add_option("--plot", o.sim_plot,
                  "Comma-separated expressions in the answers, coordinates, rates, parameters and t, e.g. y,N");
  sub->add_option("--samples", o.samples, "Rows of the table, evenly spaced in time")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  sub->add_option("--csv", o.csv_out, "Write the table as CSV here");
  sub->add_option("--svg", o.svg_out, "Write an SVG plot here");
  sub->add_option("--pgfplots", o.pgf_out, "Write a pgfplots figure (LaTeX) here");
  sub->add_option("-o,--output", o.out, "Write the report (events and table) here instead of standard output");
  with_phase(sub, o);
}

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

}  // namespace

Commands define_commands(CLI::App& app, Options& o, const std::string& asked) {
  Commands c;
  // Every subcommand is made, but only the one asked for gets its options (all of them when
  // none is named, as for --help): the options are defined once every subcommand is there.
  std::vector<std::pair<CLI::App*, std::function<void(CLI::App*)>>> definitions;
  auto add = [&](const std::string& name, const std::string& description, std::function<void(CLI::App*)> define) {
    CLI::App* sub = app.add_subcommand(name, description);
    definitions.emplace_back(sub, std::move(define));
    return sub;
  };
  auto with = [&o](void (*define)(CLI::App*, Options&)) { return [&o, define](CLI::App* sub) { define(sub, o); }; };
  c.derive =
      add("derive", "Print the derivation: FBD equations, constraints, solve, results", with(with_common_options));
  c.solve = add("solve", "Print the answers only: closed forms and numbers", with(with_common_options));
  c.isolate = add("isolate",
                  "Find one balance equation (LMB along a direction, AMB about a point "
                  "and axis) that contains an unknown alone",
                  with(define_isolate));
  c.key = add("key", "An answer key for one or more problems, with numeric variants if asked", with(define_key));
  c.sheet = add("sheet",
                "Problem sheets: each problem's statement with its numbers, per variant "
                "(the same numbers as key with the same seed)",
                with(define_sheet));
  c.page = add("page",
               "A page to try the step checker: the problem, its sketch and a worked-solution form whose "
               "steps a checker (scripts/step-server) judges as they are typed",
               with(define_page));
  c.sweep = add("sweep", "Evaluate the closed forms over a range of one parameter: CSV, SVG plot, pgfplots",
                with(define_sweep));
  c.simulate = add("simulate",
                   "Integrate the motion in time numerically, with events (a string going slack, "
                   "a contact lost, a body turning): a table, CSV, SVG, pgfplots",
                   with(define_simulate));
  c.check = add("check", "Check a student's answer (or a batch of them) against the closed form",
                [&](CLI::App* sub) { define_check(sub, o, c); });
  const bool named =
      std::any_of(definitions.begin(), definitions.end(), [&](const auto& d) { return d.first->get_name() == asked; });
  for (const auto& [sub, define] : definitions)
    if (!named || sub->get_name() == asked) define(sub);
  return c;
}

int usage_problem(const Commands& c, const Options& o) {
  const auto said = [](const char* message) {
    std::cerr << message;
    return 2;
  };
  const bool check = c.check->parsed();
  if (check && !o.results.empty() && c.batch->count() == 0 && c.steps->count() == 0)
    return said("tackle check: --results needs --batch or --steps\n");
  if (check && !o.gradebook.empty() && c.batch->count() == 0) return said("tackle check: --gradebook needs --batch\n");
  if (check && c.answer->count() == 0 && c.batch->count() == 0 && c.equation->count() == 0 && c.steps->count() == 0 &&
      c.fbd->count() == 0)
    return said("tackle check: give --unknown and --answer, --equation, --fbd, --steps or --batch\n");
  if (check && !o.rubric.empty() && c.steps->count() == 0 && c.fbd->count() == 0)
    return said("tackle check: --rubric needs --steps or --fbd\n");
  if (c.isolate->parsed() && o.target.empty() && !o.all) return said("tackle isolate: give an unknown or --all\n");
  return 0;
}

}  // namespace tackle::cli

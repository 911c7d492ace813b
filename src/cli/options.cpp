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

namespace {

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

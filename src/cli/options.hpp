// The command line's options: every command's, in one struct each command reads from, and the
// subcommands that define them (only the asked command's options are made: a third of a short
// run's start-up was making them all).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "ruleset/ruleset.hpp"

namespace tackle::cli {

// Every option of every command; each command reads its own.
struct Options {
  std::string rules_dir = tackle::default_rules_dir();
  // derive, solve (and the file, output, format and phase of the others)
  std::string file, out, format = "text", phase;
  int digits = 6;
  // isolate
  std::string target;
  bool all = false;
  // key
  std::vector<std::string> key_files;
  std::string key_format = "markdown";
  int variants = 0;
  unsigned long long seed = 1;
  bool seeded = false;       // check: --seed given
  int time_budget_ms = 250;  // check: per answer
  // sweep and simulate
  std::string vary, plot, csv_out, svg_out, pgf_out, sim_plot;
  std::vector<std::string> fixes;
  std::string against;  // sweep
  double until = 0;
  int samples = 201;
  // check
  std::string unknown, answer, equation, steps, fbd, rubric, batch, results, results_format = "gradescope";
  std::string gradebook, gradebook_format = "plain";
  int jobs = 1;  // check --batch: processes grading side by side (0: one per core)
  bool equation_given = false;
  double tolerance = 0.01;
  int sig_figs = 0;
  bool require_simplified = false, no_latex = false, reveal = false, top_level_score = false;
  bool figures = false;  // sheet
  std::string endpoint;  // page
  std::vector<std::string> points_text, set_values;
};

/// The subcommands, made on `app`, and the check's options that usage rules read.
struct Commands {
  CLI::App *derive = nullptr, *solve = nullptr, *isolate = nullptr, *key = nullptr, *sheet = nullptr, *page = nullptr,
           *sweep = nullptr, *simulate = nullptr, *check = nullptr;
  CLI::Option *answer = nullptr, *batch = nullptr, *equation = nullptr, *steps = nullptr, *fbd = nullptr;
};

/// CLI11's ranges let NaN through and its unsigned conversion wraps -1: a finite number, and a
/// seed (a whole number from 0 to 2^64 - 1), checked as text first.
extern const CLI::Validator finite_number, seed_number;

/// --phase, of every command that analyzes one description.
void with_phase(CLI::App* sub, Options& o);

/// check's options (check_command.cpp, beside the command's run: a new kind of check is its
/// option and its run there); those the usage rules read are kept in `c`.
void define_check(CLI::App* sub, Options& o, Commands& c);

/// Makes every subcommand on `app` and defines the options of the one `asked` names (all of
/// them when it names none, as for --help), reading into `o`.
[[nodiscard]] Commands define_commands(CLI::App& app, Options& o, const std::string& asked);

/// The usage rules CLI11 cannot say (an option that needs one of several others): the message
/// on standard error and 2, or 0 when the command line is fine.
[[nodiscard]] int usage_problem(const Commands& c, const Options& o);

}  // namespace tackle::cli

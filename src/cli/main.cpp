// The tackle command: a thin shell over the library. Exit codes: 0 ok, 1 input error or an
// output that cannot be written, 2 usage error, 3 internal error or out of memory.
#include <system_error>
#include <algorithm>
#include <thread>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cmath>
#include <cstdint>
#include <limits>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

#include <CLI/CLI.hpp>
#include <cln/malloc.h>

#include "core/diagnostics.hpp"
#include "core/utf8.hpp"
#include "check/batch.hpp"
#include "check/fbd.hpp"
#include "check/steps.hpp"
#include "expr/parse.hpp"
#include "expr/rational.hpp"
#include "isolate/isolate.hpp"
#include "pipeline/pipeline.hpp"
#include "report/isolation_report.hpp"
#include "report/gradebook.hpp"
#include "report/key.hpp"
#include "report/writer.hpp"
#include "report/html.hpp"
#include "report/sheet.hpp"
#include "report/step_page.hpp"
#include "core/files.hpp"
#include "report/sweep.hpp"
#include "ruleset/builtin_rules.hpp"
#include "motion/simulate.hpp"

namespace {

int report_input_error(const tackle::InputError& e) {
  for (const auto& d : e.diagnostics()) std::cerr << tackle::format(d) << "\n";
  return 1;
}

// Whether everything written to standard output so far reached it; when not, says so once
// (`tackle derive FILE > /dev/full` must not exit 0). errno is read right after the flush
// that failed; a write that failed earlier (output past stdio's buffer) may have left no
// reason behind, and then none is given.
bool standard_output_written() {
  static bool said = false;
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && std::cout && !std::ferror(stdout)) return true;
  if (!said)
    std::cerr << "tackle: cannot write to standard output"
              << (err != 0 ? std::string(" (") + std::strerror(err) + ")" : "") << "\n";
  said = true;
  return false;
}

// To standard output, or to the file atomically (a failed run leaves no partial output).
int emit(const std::string& text, const std::string& out) {
  if (out.empty() || out == "-") {
    std::cout << text;
    return standard_output_written() ? 0 : 1;
  }
  std::string error;
  if (tackle::write_file_atomically(out, text, error)) return 0;
  std::cerr << error << "\n";
  return 1;
}

// The same for a document written as it is made (`write` takes the stream): to standard
// output as it goes, or into a temporary file renamed into place when it is complete.
int emit_to(const std::function<void(std::ostream&)>& write, const std::string& out) {
  if (out.empty() || out == "-") {
    write(std::cout);
    return standard_output_written() ? 0 : 1;
  }
  tackle::AtomicOutput file(out);
  if (file.ok()) write(file.stream());
  if (file.commit()) return 0;
  std::cerr << file.error() << "\n";
  return 1;
}

// "y,N" -> {"y", "N"} (--plot of sweep and simulate).
std::vector<std::string> split_commas(const std::string& list) {
  std::vector<std::string> out;
  for (std::size_t start = 0, comma; start <= list.size(); start = comma + 1) {
    comma = list.find(',', start);
    if (comma == std::string::npos) comma = list.size();
    out.push_back(list.substr(start, comma - start));
  }
  return out;
}

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

// A format's name, as --format checked it (report/writer.hpp lists them).
tackle::Format format_of(const std::string& name) {
  const auto f = tackle::format_named(name);
  if (!f) throw tackle::InternalError("no format named '" + name + "'");
  return *f;
}

// The analysis of one phase (or of the whole description when it has none); nullptr, with
// the usage problem said, when the phase named is not there.
const tackle::Analysis* the_phase(const tackle::Analysis& whole, const Options& o) {
  std::string problem;
  const tackle::Analysis* a = tackle::pick_phase(whole, o.phase, problem);
  if (!a) std::cerr << "tackle: " << o.file << ": " << problem << "\n";
  return a;
}

// derive and solve: every phase of a phased description, unless --phase names one.
int run_report(const Options& o, const tackle::RuleSet& rules, bool full) {
  const auto whole = tackle::analyze_file(o.file, rules);
  // solve prints no steps, figures or plots; text and JSON show no figures.
  const tackle::Format format = format_of(o.format);
  const tackle::ReportOptions options{
      .digits = o.digits, .narrate = full, .figures = format != tackle::Format::text && format != tackle::Format::json};
  // Written as it is made: the answers of a chain of 2048 blocks are 88 MB of text.
  if (o.phase.empty() && !whole->phases.empty()) {
    const auto phases = tackle::explain_phases(*whole, options);
    return emit_to([&](std::ostream& out) { tackle::write_to(out, phases, format, full); }, o.out);
  }
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  const tackle::Derivation d = tackle::explain(*analysis, options);
  return emit_to([&](std::ostream& out) { tackle::write_to(out, d, format, full); }, o.out);
}

// The files of key and sheet: each analyzed (every problem of every file reported at once),
// each phase a part, the variants drawn once per file (the phases share the parameters); a
// sheet and a key with one seed show the same numbers.
struct Parts {
  std::vector<std::unique_ptr<const tackle::Analysis>> analyses;
  std::vector<std::vector<tackle::Derivation>> derivations;  // per file, per phase
  std::vector<std::vector<const tackle::Analysis*>> phases;  // the same shape
  std::vector<std::vector<std::vector<tackle::Variant>>> variants;
};

Parts analyze_parts(const Options& o, const tackle::RuleSet& rules) {
  Parts p;
  std::vector<tackle::Diagnostic> problems;
  for (const auto& f : o.key_files) {
    try {
      p.analyses.push_back(tackle::analyze_file(f, rules));
    } catch (const tackle::InputError& e) {
      problems.insert(problems.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
  }
  if (!problems.empty()) throw tackle::InputError(problems);
  bool any = false;
  for (const auto& a : p.analyses) {
    p.derivations.push_back(tackle::explain_phases(*a, tackle::ReportOptions{o.digits}));
    auto& ds = p.derivations.back();
    std::vector<const tackle::Analysis*> phases;
    std::vector<std::pair<const tackle::Model*, const tackle::Derivation*>> parts;
    for (std::size_t k = 0; k < ds.size(); ++k) {
      phases.push_back(a->phases.empty() ? a.get() : a->phases[k].analysis.get());
      parts.emplace_back(&phases.back()->model, &ds[k]);
    }
    p.variants.push_back(tackle::draw_variants(parts, o.variants, o.seed, o.digits));
    for (const auto& v : p.variants.back()) any = any || !v.empty();
    for (auto& d : ds)
      if (!d.phase.empty()) d.title += ": phase " + std::to_string(d.phase_number) + ", " + d.phase;
    p.phases.push_back(phases);
  }
  // Variants asked for and none possible anywhere: an input error, not a key without them.
  if (o.variants > 0 && !any) {
    std::vector<tackle::Diagnostic> none;
    for (const auto& f : o.key_files)
      none.push_back({{f, 1, 1},
                      "variants were asked for, but no parameter has a 'range' to draw them from "
                      "(expected, for instance, F: {value: 130, unit: N, range: [100, 160]})"});
    throw tackle::InputError(none);
  }
  return p;
}

int run_key(const Options& o, const tackle::RuleSet& rules) {
  const Parts p = analyze_parts(o, rules);
  std::vector<tackle::KeyEntry> entries;
  for (std::size_t i = 0; i < p.derivations.size(); ++i)
    for (std::size_t k = 0; k < p.derivations[i].size(); ++k)
      entries.push_back({&p.derivations[i][k], p.variants[i][k], o.variants > 0});
  return emit(tackle::write_key(entries, format_of(o.key_format)), o.out);
}

int run_sheet(const Options& o, const tackle::RuleSet& rules) {
  const Parts p = analyze_parts(o, rules);
  std::vector<tackle::SheetEntry> entries;
  std::vector<std::string> generated;
  for (std::size_t i = 0; i < p.derivations.size(); ++i)
    for (std::size_t k = 0; k < p.derivations[i].size(); ++k) {
      entries.push_back({&p.derivations[i][k], &p.phases[i][k]->model, p.variants[i][k]});
      if (!p.phases[i][k]->model.statement && (generated.empty() || generated.back() != o.key_files[i]))
        generated.push_back(o.key_files[i]);
    }
  // Said once: a sheet whose statements tackle wrote from the descriptions.
  if (!generated.empty())
    std::cerr
        << "tackle: warning: "
        << (generated.size() == 1 ? generated[0] + " has" : std::to_string(generated.size()) + " files have")
        << " no 'statement'; the sheet states the problem from the description (its bodies, connections and given "
           "values)\n";
  return emit(tackle::write_sheet(entries, format_of(o.key_format), o.figures), o.out);
}

// A page to try the step checker: the problem and a worked-solution form posting to a checker.
int run_page(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  return emit(tackle::step_page(tackle::explain(*analysis), analysis->model, o.endpoint), o.out);
}

int run_isolate(const Options& o, const tackle::RuleSet& rules) {
  const tackle::Description description = tackle::read_description(o.file);
  std::unique_ptr<const tackle::Analysis> phased;
  if (!description.phases.empty() || !o.phase.empty()) phased = tackle::analyze(description, rules);
  const tackle::Analysis* picked = nullptr;
  if (phased) {
    std::string problem;
    picked = tackle::pick_phase(*phased, o.phase, problem);
    if (!picked) {
      std::cerr << "tackle isolate: " << o.file << ": " << problem << "\n";
      return 2;
    }
  }
  const tackle::Model model = picked ? picked->model : tackle::build_model(description, rules);
  const auto unknowns = tackle::model_unknowns(model);
  std::vector<GiNaC::ex> wanted = unknowns;
  if (!o.all) {
    const auto parsed = tackle::parse_expression(o.target, *model.symbols);
    if (!parsed.value || !tackle::contains(unknowns, *parsed.value)) {
      std::vector<std::string> names;
      for (const auto& u : unknowns) names.push_back(model.symbols->find(u)->name);
      std::cerr << o.file << ": '" << o.target
                << "' is not an unknown of this problem (unknowns: " << tackle::join(names) << ")\n";
      return 1;
    }
    wanted = {*parsed.value};
  }
  const auto candidates = tackle::candidate_equations(model);
  std::vector<tackle::Isolation> found;
  for (const auto& u : wanted) found.push_back(tackle::isolate(model, candidates, u));
  return emit(tackle::write_isolations(model, found, format_of(o.format)), o.out);
}

int run_sweep(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  tackle::SweepSpec spec;
  if (analysis->model.sweep) spec = tackle::sweep_spec(*analysis->model.sweep);
  if (!o.vary.empty()) {
    spec.vary = o.vary;
    spec.against.clear();  // the description's axis was for its own range
  }
  if (!o.fixes.empty()) spec.fix = o.fixes;
  if (!o.against.empty()) spec.against = o.against;
  if (!o.plot.empty()) spec.plot = split_commas(o.plot);
  if (spec.vary.empty()) {
    std::cerr << "tackle sweep: give --vary (the description has no 'sweep')\n";
    return 2;
  }
  const tackle::Derivation d = tackle::explain(*analysis, tackle::ReportOptions{.narrate = false});
  const auto result = tackle::run_sweep(analysis->model, d, spec, tackle::Location{"--vary/--plot", 0, 0});
  for (const auto& [path, text] :
       {std::pair{o.svg_out, tackle::sweep_svg(result)}, std::pair{o.pgf_out, tackle::sweep_pgfplots(result)}})
    if (!path.empty() && emit(text, path) != 0) return 1;
  return emit(tackle::sweep_csv(result), o.csv_out);
}

int run_simulate(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  tackle::SimulationSpec spec;
  if (o.until > 0) spec.until = o.until;
  spec.samples = o.samples;
  if (!o.sim_plot.empty()) spec.plot = split_commas(o.sim_plot);
  const auto result = tackle::simulate(*analysis, spec, tackle::Location{"--until/--plot", 0, 0});
  for (const auto& [path, text] :
       {std::pair{o.csv_out, tackle::sweep_csv(result.table)}, std::pair{o.svg_out, tackle::sweep_svg(result.table)},
        std::pair{o.pgf_out, tackle::sweep_pgfplots(result.table)}})
    if (!path.empty() && emit(text, path) != 0) return 1;
  return emit(tackle::simulation_text(result), o.out);
}

int run_check(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  tackle::CheckOptions options;
  options.relative_tolerance = o.tolerance;
  if (o.sig_figs > 0) options.significant_figures = o.sig_figs;
  options.require_simplified = o.require_simplified;
  options.echo_latex = !o.no_latex;
  options.reveal = o.reveal;
  if (o.seeded) options.seed = o.seed;
  options.time_budget = std::chrono::milliseconds(o.time_budget_ms);
  const tackle::Checker checker(*analysis, options);
  std::vector<std::pair<std::string, std::string>> set;
  for (const auto& v : o.set_values) {
    const auto eq = v.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::cerr << "tackle check: --set " << tackle::printable(v) << ": expected NAME=VALUE\n";
      return 2;
    }
    set.emplace_back(v.substr(0, eq), v.substr(eq + 1));
  }
  std::optional<GiNaC::exmap> values;
  if (!set.empty()) {
    std::string problem;
    bool out_of_domain = false;
    values = checker.values_for(set, problem, &out_of_domain);
    if (!values) {
      std::cerr << "tackle check: --set: " << problem << "\n";
      return out_of_domain ? 1 : 2;  // a value the problem does not allow is bad input
    }
  }
  if (!o.batch.empty()) {
    tackle::GradeOptions grade;
    grade.format = o.results_format == "prairielearn" ? tackle::ResultsFormat::prairielearn
                   : o.results_format == "jsonl"      ? tackle::ResultsFormat::jsonl
                                                      : tackle::ResultsFormat::gradescope;
    grade.top_level_score = o.top_level_score;
    grade.set = set;
    for (const auto& p : o.points_text) {
      const auto eq = p.find('=');
      const std::string number = eq == std::string::npos ? p : p.substr(eq + 1);
      char* end = nullptr;
      const double v = std::strtod(number.c_str(), &end);
      if (number.empty() || *end != '\0' || !(v >= 0) || v > 1e6) {
        std::cerr << "tackle check: --points " << p << ": expected a number of points from 0 to 10^6, or NAME=N\n";
        return 2;
      }
      if (eq == std::string::npos)
        grade.points = v;
      else
        grade.points_for[p.substr(0, eq)] = v;
    }
    grade.source = o.batch;
    grade.model = &analysis->model;
    grade.jobs = o.jobs > 0 ? o.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    // Read and graded line by line (or by blocks of lines with several jobs), each result
    // written as it goes: memory stays bounded whatever the size of the batch.
    std::unique_ptr<std::istream> batch_file;
    if (o.batch != "-") batch_file = tackle::open_text_file(o.batch);
    std::istream& batch = batch_file ? *batch_file : std::cin;
    // A gradebook: each graded line's cell, written when the whole batch was graded.
    std::optional<tackle::Gradebook> book;
    if (!o.gradebook.empty()) {
      book.emplace(o.batch);
      grade.graded = [&book](const tackle::GradedLine& g) {
        book->add(g.line, g.object, g.student, g.id, g.points, g.max_points, g.verdict == tackle::Verdict::invalid);
      };
    }
    // The outputs go through temporary files and are renamed into place only when the whole
    // batch was graded.
    std::optional<tackle::AtomicOutput> out_file, results_file, gradebook_file;
    for (auto& [file, path] : {std::pair{&out_file, &o.out}, std::pair{&results_file, &o.results},
                               std::pair{&gradebook_file, &o.gradebook}}) {
      if (path->empty() || *path == "-") continue;
      file->emplace(*path);
      if (!(*file)->ok()) {
        std::cerr << (*file)->error() << "\n";
        return 1;
      }
    }
    std::ostream& sink = out_file ? out_file->stream() : std::cout;
    std::ostream null_results(nullptr);  // no --results: nothing is kept (badbit: every write dropped)
    std::ostream& results = results_file ? results_file->stream() : null_results;
    (void)tackle::check_batch(checker, batch, sink, results, grade);
    // Standard output failed part of the way: the batch stopped there, and a results file of
    // part of the batch is not written.
    if (!out_file && !standard_output_written()) return 1;
    if (book) {
      // A line whose student or question is not known: no gradebook (and no other output),
      // rather than one that leaves a student out.
      if (const auto problems = book->problems(); !problems.empty()) throw tackle::InputError(problems);
      const auto format = tackle::gradebook_format(o.gradebook_format);
      const std::string csv = book->csv(format);
      if (gradebook_file)
        gradebook_file->stream() << csv;
      else if (std::cout << csv; !standard_output_written())
        return 1;
      if (format != tackle::GradebookFormat::plain)
        for (const auto& cell : book->invalid_cells())
          std::cerr << "tackle check: " << o.gradebook << ": " << cell
                    << " cannot be graded as typed: its cell is left without a grade\n";
    }
    for (auto* file : {&out_file, &results_file, &gradebook_file})
      if (*file && !(*file)->commit()) {
        std::cerr << (*file)->error() << "\n";
        return 1;
      }
    return 0;
  }
  if (!o.fbd.empty()) {
    const tackle::StudentFbd fbd = tackle::read_fbd_file(tackle::read_text_file(o.fbd), o.fbd, analysis->model);
    const tackle::Rubric rubric =
        o.rubric.empty() ? tackle::Rubric{}
                         : tackle::read_rubric(tackle::read_text_file(o.rubric), o.rubric, analysis->model);
    std::vector<tackle::Diagnostic> problems;
    const tackle::FbdGrade grade = tackle::check_fbd(analysis->model, fbd, rubric.fbd, problems);
    if (!problems.empty()) throw tackle::InputError(problems);  // a name the problem does not have
    return emit(o.format == "json" ? tackle::fbd_json(grade) : tackle::fbd_text(grade), o.out);
  }
  if (!o.steps.empty()) {
    const auto solution = tackle::read_solution(tackle::read_text_file(o.steps), o.steps, analysis->model);
    const tackle::Rubric rubric =
        o.rubric.empty() ? tackle::Rubric{}
                         : tackle::read_rubric(tackle::read_text_file(o.rubric), o.rubric, analysis->model);
    const tackle::SolutionGrade grade = tackle::grade_solution(checker, analysis->model, solution, rubric);
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
  if (o.equation_given) {
    const auto result = checker.check_equation(o.equation);
    return emit(o.format == "json" ? tackle::result_json(result, o.equation) : tackle::result_text(result), o.out);
  }
  const auto result = checker.check(o.unknown, o.answer, values ? &*values : nullptr);
  return emit(o.format == "json" ? tackle::result_json(result, o.answer) : tackle::result_text(result), o.out);
}

// The subcommand a command line asks for: the first argument that is not an option (nor the
// value of --rules, the one option before it that takes a value), or "" when there is none.
std::string asked_subcommand(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--rules") {
      ++i;
      continue;
    }
    if (!arg.empty() && arg[0] == '-') continue;
    return arg;
  }
  return {};
}

int run(int argc, char** argv) {
  Options o;
  CLI::App app{"tackle: free-body-diagram equations for constrained straight-line motion, solved in closed form"};
  app.require_subcommand(1);
  app.set_version_flag("--version",
                       std::string("tackle ") + TACKLE_VERSION + " (rules: " + tackle::default_rules_dir() + ")");
  app.add_option("--rules", o.rules_dir, "Directory of connection rules (rules/*.yaml)")->capture_default_str();
  auto with_phase = [&](CLI::App* sub) {
    sub->add_option("--phase", o.phase, "A phase of a description with 'phases', by name");
  };
  auto with_common_options = [&](CLI::App* sub) {
    sub->add_option("file", o.file, "Problem description (YAML)")->required();
    with_phase(sub);
    sub->add_option("--digits", o.digits, "Significant digits of the numbers (any precision)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--format", o.format, "Output format")
        ->check(CLI::IsMember(tackle::format_names()))
        ->capture_default_str();
    sub->add_option("-o,--output", o.out, "Write to this file instead of standard output");
  };
  // Every subcommand is made, but only the one asked for gets its options (all of them when
  // none is named, as for --help): making them all was a third of a short run's start-up.
  // The options are defined once every subcommand is there (below).
  std::vector<std::pair<CLI::App*, std::function<void(CLI::App*)>>> definitions;
  auto add = [&](const std::string& name, const std::string& description, std::function<void(CLI::App*)> define) {
    CLI::App* sub = app.add_subcommand(name, description);
    definitions.emplace_back(sub, std::move(define));
    return sub;
  };
  auto* derive = add("derive", "Print the derivation: FBD equations, constraints, solve, results", with_common_options);
  add("solve", "Print the answers only: closed forms and numbers", with_common_options);

  auto* isolate = add("isolate",
                      "Find one balance equation (LMB along a direction, AMB about a point "
                      "and axis) that contains an unknown alone",
                      [&](CLI::App* isolate) {
                        isolate->add_option("file", o.file, "Problem description (YAML)")->required();
                        auto* target_opt = isolate->add_option("unknown", o.target, "The unknown, e.g. T_HI");
                        auto* all_opt =
                            isolate->add_flag("--all", o.all, "Report for every unknown whether one equation gives it");
                        target_opt->excludes(all_opt);
                        isolate->add_option("--format", o.format, "Output format")
                            ->check(CLI::IsMember({"text", "json"}))
                            ->capture_default_str();
                        isolate->add_option("-o,--output", o.out, "Write to this file instead of standard output");
                        with_phase(isolate);
                      });

  auto* key = add("key", "An answer key for one or more problems, with numeric variants if asked", [&](CLI::App* key) {
    key->add_option("files", o.key_files, "Problem descriptions (YAML)")->required();
    key->add_option("--format", o.key_format, "Output format")
        ->check(CLI::IsMember({"latex", "markdown", "json", "html"}))
        ->capture_default_str();
    key->add_option("--variants", o.variants, "Numeric variants per problem, drawn from the parameters' 'range'")
        ->check(CLI::Range(0, 10000));
    key->add_option("--seed", o.seed, "Seed for the variants (the same seed gives the same variants)")
        ->check(seed_number)
        ->capture_default_str();
    key->add_option("--digits", o.digits, "Significant digits of the numbers")->check(CLI::Range(1, 1000));
    key->add_option("-o,--output", o.out, "Write to this file instead of standard output");
  });

  auto* sheet = add(
      "sheet",
      "Problem sheets: each problem's statement with its numbers, per variant "
      "(the same numbers as key with the same seed)",
      [&](CLI::App* sheet) {
        sheet->add_option("files", o.key_files, "Problem descriptions (YAML)")->required();
        sheet->add_option("--format", o.key_format, "Output format")
            ->check(CLI::IsMember({"latex", "markdown", "html"}))
            ->capture_default_str();
        sheet->add_flag("--figures", o.figures,
                        "Also draw each problem's free body diagrams under its statement (a 1-D or 2-D mechanism's "
                        "sketch is always drawn)");
        sheet->add_option("--variants", o.variants, "Numeric variants per problem, drawn from the parameters' 'range'")
            ->check(CLI::Range(0, 10000));
        sheet->add_option("--seed", o.seed, "Seed for the variants (as for key)")
            ->check(seed_number)
            ->capture_default_str();
        sheet->add_option("--digits", o.digits, "Significant digits of the numbers")->check(CLI::Range(1, 1000));
        sheet->add_option("-o,--output", o.out, "Write to this file instead of standard output");
      });

  auto* page = add("page",
                   "A page to try the step checker: the problem, its sketch and a worked-solution form whose "
                   "steps a checker (scripts/step-server) judges as they are typed",
                   [&](CLI::App* page) {
                     page->add_option("file", o.file, "Problem description (YAML)")->required();
                     page->add_option("--endpoint", o.endpoint,
                                      "Where the checker answers (POST {endpoint}/step and {endpoint}/solution): "
                                      "a path or an http(s) URL; default: the page's own location")
                         ->check(CLI::Validator(
                             [](std::string& text) -> std::string {
                               const std::string problem = tackle::endpoint_problem(text);
                               return problem.empty() ? std::string() : "'" + tackle::printable(text) + "' " + problem;
                             },
                             "URL"));
                     page->add_option("-o,--output", o.out, "Write to this file instead of standard output");
                     with_phase(page);
                   });

  auto* sweep =
      add("sweep", "Evaluate the closed forms over a range of one parameter: CSV, SVG plot, pgfplots",
          [&](CLI::App* sweep) {
            sweep->add_option("file", o.file, "Problem description (YAML)")->required();
            sweep->add_option("--vary", o.vary,
                              "name=start:end:count, in the parameter's unit (default: the description's sweep)");
            sweep->add_option("--fix", o.fixes, "name=value, in the parameter's unit (repeatable)");
            sweep->add_option(
                "--against", o.against,
                "The horizontal axis: an expression in the parameters, e.g. h/l (default: the varied parameter)");
            sweep->add_option("--plot", o.plot,
                              "Comma-separated expressions in the answers and parameters, e.g. N_A,N_B,N_A-N_B");
            sweep->add_option("--csv", o.csv_out, "Write the data as CSV here (default: standard output)");
            sweep->add_option("--svg", o.svg_out, "Write an SVG plot here");
            sweep->add_option("--pgfplots", o.pgf_out, "Write a pgfplots figure (LaTeX) here");
            with_phase(sweep);
          });

  auto* simulate =
      add("simulate",
          "Integrate the motion in time numerically, with events (a string going slack, "
          "a contact lost, a body turning): a table, CSV, SVG, pgfplots",
          [&](CLI::App* simulate) {
            simulate->add_option("file", o.file, "Problem description (YAML) with a 'motion' section")->required();
            simulate->add_option("--until", o.until, "End time in seconds (default: the description's 'until')")
                ->check(finite_number)
                ->check(CLI::PositiveNumber);
            simulate->add_option(
                "--plot", o.sim_plot,
                "Comma-separated expressions in the answers, coordinates, rates, parameters and t, e.g. y,N");
            simulate->add_option("--samples", o.samples, "Rows of the table, evenly spaced in time")
                ->check(CLI::Range(2, 100000))
                ->capture_default_str();
            simulate->add_option("--csv", o.csv_out, "Write the table as CSV here");
            simulate->add_option("--svg", o.svg_out, "Write an SVG plot here");
            simulate->add_option("--pgfplots", o.pgf_out, "Write a pgfplots figure (LaTeX) here");
            simulate->add_option("-o,--output", o.out,
                                 "Write the report (events and table) here instead of standard output");
            with_phase(simulate);
          });

  CLI::Option *answer_opt = nullptr, *batch_opt = nullptr, *equation_opt = nullptr, *steps_opt = nullptr,
              *fbd_opt = nullptr;
  auto* check =
      add("check", "Check a student's answer (or a batch of them) against the closed form", [&](CLI::App* check) {
        check->add_option("file", o.file, "Problem description (YAML)")->required();
        auto* unknown_opt = check->add_option("--unknown", o.unknown, "The unknown the answer is for, e.g. T_HI");
        answer_opt =
            check->add_option("--answer", o.answer, "The answer: an expression, 'T = ...', or a number with a unit");
        equation_opt =
            check
                ->add_option(
                    "--equation", o.equation,
                    "An equation the student wrote, e.g. '2*T - F = m_A*ddot(x_A)': is it one of the balances and "
                    "constraints, or does it follow from them?")
                ->each([&](const std::string&) { o.equation_given = true; });
        steps_opt = check->add_option("--steps", o.steps,
                                      "A worked solution (YAML: steps: [{fbd: ...}, {equation: ...}, {answer: ..., "
                                      "unknown: T}]) graded as a whole: "
                                      "each step, the equations used and missing, the first wrong step, a score");
        fbd_opt = check->add_option(
            "--fbd", o.fbd,
            "A free body diagram the student drew (YAML: body: B, forces: [{name: T, at: pB, direction: [-1]}]): "
            "each force drawn, missing, extra or the wrong way, and a score");
        check->add_option("--rubric", o.rubric,
                          "With --steps or --fbd: points for FBDs, balances, constraints and answers, what a wrong "
                          "step costs, and how an FBD is scored (YAML)");
        batch_opt = check->add_option(
            "--batch", o.batch,
            "JSON Lines file of {\"id\", \"unknown\", \"answer\"}, {\"id\", \"equation\"} or {\"id\", \"fbd\"} "
            "(- for standard input)");
        auto* results_opt = check->add_option("--results", o.results,
                                              "With --batch or --steps: also write a grading platform's results file");
        check->add_option("--results-format", o.results_format, "The results file's platform")
            ->check(CLI::IsMember({"gradescope", "prairielearn", "jsonl"}))
            ->capture_default_str()
            ->needs(results_opt);
        auto* gradebook_opt =
            check->add_option("--gradebook", o.gradebook,
                              "With --batch: also write the class's gradebook (CSV): a row per line's \"student\", "
                              "a column per question \"id\", the points and the total");
        check
            ->add_option("--gradebook-format", o.gradebook_format,
                         "The gradebook's layout: a spreadsheet's, or Canvas's or Moodle's grade import")
            ->check(CLI::IsMember({"plain", "canvas", "moodle"}))
            ->capture_default_str()
            ->needs(gradebook_opt);
        check
            ->add_option("--jobs", o.jobs,
                         "With --batch: grade with N processes side by side (0: one per core); the results are the "
                         "same, in the batch's order")
            ->check(CLI::Range(0, 256))
            ->capture_default_str()
            ->needs(batch_opt);
        check
            ->add_option("--points", o.points_text,
                         "Points for each answer (N), or for one unknown's answers (NAME=N); repeatable")
            ->needs(batch_opt);
        check
            ->add_flag("--top-level-score", o.top_level_score,
                       "Gradescope: also write the total as the top-level score "
                       "(it overrides the tests' sum)")
            ->needs(results_opt);
        check->add_option("--set", o.set_values,
                          "A parameter's value for this check, in its stated unit (NAME=VALUE, repeatable): "
                          "a student's own variant");
        check->add_flag("--reveal", o.reveal, "Name the correct value in the feedback (never, without it)");
        check->add_option("--tolerance", o.tolerance, "Relative tolerance for numbers with units")
            ->check(finite_number)
            ->check(CLI::Range(0.0, 1.0))
            ->capture_default_str();
        check
            ->add_option("--sig-figs", o.sig_figs,
                         "Instead of the tolerance: numbers must match to this many significant figures")
            ->check(CLI::Range(1, 15));
        check
            ->add_option("--seed", o.seed,
                         "Draw the check's own random points from this seed (reproducible tests only: "
                         "a student who knows the points can build a wrong answer that passes)")
            ->check(seed_number)
            ->each([&](const std::string&) { o.seeded = true; });
        check
            ->add_option("--time-budget", o.time_budget_ms,
                         "Milliseconds to check one answer in; past them it is undecided (code budget). A slow or busy "
                         "machine may need more")
            ->check(CLI::Range(1, 600000))
            ->capture_default_str();
        check->add_flag("--require-simplified", o.require_simplified,
                        "A correct answer that is not simplified is incorrect");
        check->add_flag("--no-latex", o.no_latex, "Do not echo answers in LaTeX (faster batches)");
        check->add_option("--format", o.format, "Output format (single answers)")
            ->check(CLI::IsMember({"text", "json"}))
            ->capture_default_str();
        check->add_option("-o,--output", o.out, "Write to this file instead of standard output");
        with_phase(check);
        answer_opt->needs(unknown_opt);
        unknown_opt->needs(answer_opt);
        batch_opt->excludes(answer_opt);
        equation_opt->excludes(answer_opt)->excludes(batch_opt)->excludes(unknown_opt);
        steps_opt->excludes(answer_opt)->excludes(batch_opt)->excludes(unknown_opt)->excludes(equation_opt);
        fbd_opt->excludes(answer_opt)
            ->excludes(batch_opt)
            ->excludes(unknown_opt)
            ->excludes(equation_opt)
            ->excludes(steps_opt);
      });
  const std::string asked = asked_subcommand(argc, argv);
  const bool named =
      std::any_of(definitions.begin(), definitions.end(), [&](const auto& d) { return d.first->get_name() == asked; });
  for (const auto& [sub, define] : definitions)
    if (!named || sub->get_name() == asked) define(sub);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (check->parsed() && !o.results.empty() && batch_opt->count() == 0 && steps_opt->count() == 0) {
    std::cerr << "tackle check: --results needs --batch or --steps\n";
    return 2;
  }
  if (check->parsed() && !o.gradebook.empty() && batch_opt->count() == 0) {
    std::cerr << "tackle check: --gradebook needs --batch\n";
    return 2;
  }
  if (check->parsed() && answer_opt->count() == 0 && batch_opt->count() == 0 && equation_opt->count() == 0 &&
      steps_opt->count() == 0 && fbd_opt->count() == 0) {
    std::cerr << "tackle check: give --unknown and --answer, --equation, --fbd, --steps or --batch\n";
    return 2;
  }
  if (check->parsed() && !o.rubric.empty() && steps_opt->count() == 0 && fbd_opt->count() == 0) {
    std::cerr << "tackle check: --rubric needs --steps or --fbd\n";
    return 2;
  }
  if (isolate->parsed() && o.target.empty() && !o.all) {
    std::cerr << "tackle isolate: give an unknown or --all\n";
    return 2;
  }
  try {
    const tackle::RuleSet rules =
        tackle::load_rules(o.rules_dir, tackle::RuleLoading::when_used, tackle::builtin_rules());
    if (key->parsed()) return run_key(o, rules);
    if (sheet->parsed()) return run_sheet(o, rules);
    if (page->parsed()) return run_page(o, rules);
    if (isolate->parsed()) return run_isolate(o, rules);
    if (sweep->parsed()) return run_sweep(o, rules);
    if (simulate->parsed()) return run_simulate(o, rules);
    if (check->parsed()) return run_check(o, rules);
    return run_report(o, rules, derive->parsed());
  } catch (const tackle::InputError& e) {
    return report_input_error(e);
  } catch (const tackle::InternalError& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  } catch (const tackle::SetupError& e) {
    std::cerr << "tackle: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    // To main, which says so; the outputs unwound on the way have removed their temporary files.
    throw;
  } catch (const std::system_error& e) {
    // A system call that ran out of memory (listing the rules directory under a small address
    // space) is out of memory too, not a bug.
    if (e.code() == std::errc::not_enough_memory) throw std::bad_alloc();
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  }
}

}  // namespace

namespace {

// CLN's allocator reports a failed allocation as a runtime error ("Out of virtual memory."),
// which would read as an internal error: here it is out of memory, std::bad_alloc.
void* cln_allocate(std::size_t size) {
  if (void* p = std::malloc(size)) return p;
  throw std::bad_alloc();
}

}  // namespace

int main(int argc, char** argv) {
  cln::malloc_hook = cln_allocate;
  int code = 0;
  try {
    code = run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::cerr << "tackle: out of memory\n";
    code = 3;
  }
  // Help, version and usage messages go to standard output too: a failed write there is an
  // error whatever the command (exit 1 unless the run had failed already).
  if (!standard_output_written() && code == 0) code = 1;
  return code;
}

// The tackle command: a thin shell over the library. Exit codes: 0 ok, 1 input error,
// 2 usage error, 3 internal error.
#include <iostream>
#include <optional>
#include <sstream>

#include <CLI/CLI.hpp>

#include "core/diagnostics.hpp"
#include "check/batch.hpp"
#include "expr/parse.hpp"
#include "isolate/isolate.hpp"
#include "pipeline/pipeline.hpp"
#include "report/isolation_report.hpp"
#include "report/key.hpp"
#include "core/files.hpp"
#include "report/sweep.hpp"
#include "motion/simulate.hpp"

namespace {

int report_input_error(const tackle::InputError& e) {
  for (const auto& d : e.diagnostics()) std::cerr << tackle::format(d) << "\n";
  return 1;
}

// To standard output, or to the file atomically (a failed run leaves no partial output).
int emit(const std::string& text, const std::string& out) {
  if (out.empty() || out == "-") {
    std::cout << text;
    return 0;
  }
  std::string error;
  if (tackle::write_file_atomically(out, text, error)) return 0;
  std::cerr << error << "\n";
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"tackle: free-body-diagram equations for constrained straight-line motion, solved in closed form"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tackle ") + TACKLE_VERSION + " (rules: " + tackle::default_rules_dir() + ")");
  std::string rules_dir = tackle::default_rules_dir();
  app.add_option("--rules", rules_dir, "Directory of connection rules (rules/*.yaml)")->capture_default_str();

  std::string file, out, format = "text";
  const std::map<std::string, tackle::Format> formats{{"text", tackle::Format::text},
                                                     {"latex", tackle::Format::latex},
                                                     {"markdown", tackle::Format::markdown},
                                                     {"json", tackle::Format::json}};
  int digits = 6;
  std::string phase;
  auto with_phase = [&](CLI::App* sub) {
    sub->add_option("--phase", phase, "A phase of a description with 'phases', by name");
  };
  auto with_common_options = [&](CLI::App* sub) {
    sub->add_option("file", file, "Problem description (YAML)")->required();
    with_phase(sub);
    sub->add_option("--digits", digits, "Significant digits of the numbers (any precision)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    sub->add_option("--format", format, "Output format")
        ->check(CLI::IsMember({"text", "latex", "markdown", "json"}))
        ->capture_default_str();
    sub->add_option("-o,--output", out, "Write to this file instead of standard output");
    return sub;
  };
  auto* derive = with_common_options(
      app.add_subcommand("derive", "Print the derivation: FBD equations, constraints, solve, results"));
  auto* solve = with_common_options(app.add_subcommand("solve", "Print the answers only: closed forms and numbers"));

  std::string target;
  bool all = false;
  auto* isolate = app.add_subcommand("isolate", "Find one balance equation (LMB along a direction, AMB about a point "
                                                "and axis) that contains an unknown alone");
  isolate->add_option("file", file, "Problem description (YAML)")->required();
  auto* target_opt = isolate->add_option("unknown", target, "The unknown, e.g. T_HI");
  auto* all_opt = isolate->add_flag("--all", all, "Report for every unknown whether one equation gives it");
  target_opt->excludes(all_opt);
  isolate->add_option("--format", format, "Output format")->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  isolate->add_option("-o,--output", out, "Write to this file instead of standard output");
  with_phase(isolate);

  std::vector<std::string> key_files;
  std::string key_format = "markdown";
  int variants = 0;
  unsigned long long seed = 1;
  auto* key = app.add_subcommand("key", "An answer key for one or more problems, with numeric variants if asked");
  key->add_option("files", key_files, "Problem descriptions (YAML)")->required();
  key->add_option("--format", key_format, "Output format")
      ->check(CLI::IsMember({"latex", "markdown", "json"}))
      ->capture_default_str();
  key->add_option("--variants", variants, "Numeric variants per problem, drawn from the parameters' 'range'")
      ->check(CLI::Range(0, 10000));
  key->add_option("--seed", seed, "Seed for the variants (the same seed gives the same variants)")->capture_default_str();
  key->add_option("--digits", digits, "Significant digits of the numbers")->check(CLI::Range(1, 1000));
  key->add_option("-o,--output", out, "Write to this file instead of standard output");

  std::string vary, plot, csv_out, svg_out, pgf_out;
  std::vector<std::string> fixes;
  auto* sweep = app.add_subcommand("sweep", "Evaluate the closed forms over a range of one parameter: CSV, SVG plot, pgfplots");
  sweep->add_option("file", file, "Problem description (YAML)")->required();
  sweep->add_option("--vary", vary, "name=start:end:count, in the parameter's unit (default: the description's sweep)");
  sweep->add_option("--fix", fixes, "name=value, in the parameter's unit (repeatable)");
  sweep->add_option("--plot", plot, "Comma-separated expressions in the answers and parameters, e.g. N_A,N_B,N_A-N_B");
  sweep->add_option("--csv", csv_out, "Write the data as CSV here (default: standard output)");
  sweep->add_option("--svg", svg_out, "Write an SVG plot here");
  sweep->add_option("--pgfplots", pgf_out, "Write a pgfplots figure (LaTeX) here");
  with_phase(sweep);

  double until = 0;
  int samples = 201;
  std::string sim_plot;
  auto* simulate = app.add_subcommand("simulate", "Integrate the motion in time numerically, with events (a string going slack, "
                                                  "a contact lost, a body turning): a table, CSV, SVG, pgfplots");
  simulate->add_option("file", file, "Problem description (YAML) with a 'motion' section")->required();
  simulate->add_option("--until", until, "End time in seconds (default: the description's 'until')")->check(CLI::PositiveNumber);
  simulate->add_option("--plot", sim_plot, "Comma-separated expressions in the answers, coordinates, rates, parameters and t, e.g. y,N");
  simulate->add_option("--samples", samples, "Rows of the table, evenly spaced in time")->check(CLI::Range(2, 100000))->capture_default_str();
  simulate->add_option("--csv", csv_out, "Write the table as CSV here");
  simulate->add_option("--svg", svg_out, "Write an SVG plot here");
  simulate->add_option("--pgfplots", pgf_out, "Write a pgfplots figure (LaTeX) here");
  simulate->add_option("-o,--output", out, "Write the report (events and table) here instead of standard output");
  with_phase(simulate);

  std::string unknown, answer, batch, results;
  double tolerance = 0.01;
  int sig_figs = 0;
  bool require_simplified = false;
  auto* check = app.add_subcommand("check", "Check a student's answer (or a batch of them) against the closed form");
  check->add_option("file", file, "Problem description (YAML)")->required();
  auto* unknown_opt = check->add_option("--unknown", unknown, "The unknown the answer is for, e.g. T_HI");
  auto* answer_opt = check->add_option("--answer", answer, "The answer: an expression, 'T = ...', or a number with a unit");
  auto* batch_opt = check->add_option("--batch", batch, "JSON Lines file of {\"id\", \"unknown\", \"answer\"} (- for standard input)");
  auto* results_opt = check->add_option("--results", results, "With --batch: also write a grading platform's results file")
      ->needs(batch_opt);
  std::string results_format = "gradescope";
  check->add_option("--results-format", results_format, "The results file's platform")
      ->check(CLI::IsMember({"gradescope", "prairielearn", "jsonl"}))
      ->capture_default_str()
      ->needs(results_opt);
  std::vector<std::string> points_text;
  check->add_option("--points", points_text, "Points for each answer (N), or for one unknown's answers (NAME=N); repeatable")
      ->needs(batch_opt);
  bool top_level_score = false;
  check->add_flag("--top-level-score", top_level_score, "Gradescope: also write the total as the top-level score "
                                                         "(it overrides the tests' sum)")
      ->needs(results_opt);
  std::vector<std::string> set_values;
  check->add_option("--set", set_values, "A parameter's value for this check, in its stated unit (NAME=VALUE, repeatable): "
                                         "a student's own variant");
  bool reveal = false;
  check->add_flag("--reveal", reveal, "Name the correct value in the feedback (never, without it)");
  check->add_option("--tolerance", tolerance, "Relative tolerance for numbers with units")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  check->add_option("--sig-figs", sig_figs, "Instead of the tolerance: numbers must match to this many significant figures")
      ->check(CLI::Range(1, 15));
  check->add_flag("--require-simplified", require_simplified, "A correct answer that is not simplified is incorrect");
  bool no_latex = false;
  check->add_flag("--no-latex", no_latex, "Do not echo answers in LaTeX (faster batches)");
  check->add_option("--format", format, "Output format (single answers)")->check(CLI::IsMember({"text", "json"}))->capture_default_str();
  check->add_option("-o,--output", out, "Write to this file instead of standard output");
  with_phase(check);
  answer_opt->needs(unknown_opt);
  unknown_opt->needs(answer_opt);
  batch_opt->excludes(answer_opt);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  if (check->parsed() && answer_opt->count() == 0 && batch_opt->count() == 0) {
    std::cerr << "tackle check: give --unknown and --answer, or --batch\n";
    return 2;
  }
  if (isolate->parsed() && target.empty() && !all) {
    std::cerr << "tackle isolate: give an unknown or --all\n";
    return 2;
  }
  try {
    const tackle::RuleSet rules = tackle::load_rules(rules_dir);
    if (key->parsed()) {
      // Every file is read before anything is written; problems in all of them are reported.
      std::vector<std::unique_ptr<const tackle::Analysis>> analyses;
      std::vector<tackle::Diagnostic> problems;
      for (const auto& f : key_files) {
        try {
          analyses.push_back(tackle::analyze_file(f, rules));
        } catch (const tackle::InputError& e) {
          problems.insert(problems.end(), e.diagnostics().begin(), e.diagnostics().end());
        }
      }
      if (!problems.empty()) throw tackle::InputError(problems);
      // A phased description gives one entry per phase, its variants drawn once for all of
      // them (the phases share the parameters).
      std::vector<tackle::KeyEntry> entries;
      std::vector<std::vector<tackle::Derivation>> per_file;
      for (const auto& a : analyses) per_file.push_back(tackle::explain_phases(*a, tackle::ReportOptions{digits}));
      for (std::size_t i = 0; i < analyses.size(); ++i) {
        std::vector<std::pair<const tackle::Analysis*, const tackle::Derivation*>> parts;
        for (std::size_t k = 0; k < per_file[i].size(); ++k)
          parts.emplace_back(analyses[i]->phases.empty() ? analyses[i].get() : analyses[i]->phases[k].analysis.get(), &per_file[i][k]);
        const auto variants_of = tackle::draw_variants(parts, variants, seed, digits);
        for (std::size_t k = 0; k < per_file[i].size(); ++k) {
          tackle::Derivation& d = per_file[i][k];
          if (!d.phase.empty()) d.title += ": phase " + std::to_string(d.phase_number) + ", " + d.phase;
          entries.push_back({&d, variants_of[k], variants > 0});
        }
      }
      // Variants asked for and none possible anywhere: an input error, not a key without them.
      if (variants > 0 && std::all_of(entries.begin(), entries.end(), [](const auto& e) { return e.variants.empty(); })) {
        std::vector<tackle::Diagnostic> none;
        for (const auto& f : key_files)
          none.push_back({{f, 1, 1}, "variants were asked for, but no parameter has a 'range' to draw them from "
                                     "(expected, for instance, F: {value: 130, unit: N, range: [100, 160]})"});
        throw tackle::InputError(none);
      }
      return emit(tackle::write_key(entries, formats.at(key_format)), out);
    }
    if (isolate->parsed()) {
      const tackle::Description description = tackle::read_description(file);
      std::unique_ptr<const tackle::Analysis> phased;
      if (!description.phases.empty() || !phase.empty()) phased = tackle::analyze(description, rules);
      const tackle::Analysis* picked = nullptr;
      if (phased) {
        std::string problem;
        picked = tackle::pick_phase(*phased, phase, problem);
        if (!picked) {
          std::cerr << "tackle isolate: " << file << ": " << problem << "\n";
          return 2;
        }
      }
      const tackle::Model model = picked ? picked->model : tackle::build_model(description, rules);
      const auto unknowns = tackle::model_unknowns(model);
      std::vector<GiNaC::ex> wanted = unknowns;
      if (!all) {
        const auto parsed = tackle::parse_expression(target, *model.symbols);
        if (!parsed.value || std::find(unknowns.begin(), unknowns.end(), *parsed.value) == unknowns.end()) {
          std::vector<std::string> names;
          for (const auto& u : unknowns) names.push_back(model.symbols->find(u)->name);
          std::cerr << file << ": '" << target << "' is not an unknown of this problem (unknowns: "
                    << tackle::join(names) << ")\n";
          return 1;
        }
        wanted = {*parsed.value};
      }
      const auto candidates = tackle::candidate_equations(model);
      std::vector<tackle::Isolation> found;
      for (const auto& u : wanted) found.push_back(tackle::isolate(model, candidates, u));
      return emit(tackle::write_isolations(model, found, formats.at(format)), out);
    }
    const auto whole = tackle::analyze_file(file, rules);
    // derive and solve tell every phase of a phased description; the other commands take one.
    if ((derive->parsed() || solve->parsed()) && phase.empty() && !whole->phases.empty())
      return emit(tackle::write(tackle::explain_phases(*whole, tackle::ReportOptions{digits}), formats.at(format), derive->parsed()), out);
    std::string phase_problem;
    const tackle::Analysis* analysis = tackle::pick_phase(*whole, phase, phase_problem);
    if (!analysis) {
      std::cerr << "tackle: " << file << ": " << phase_problem << "\n";
      return 2;
    }
    if (sweep->parsed()) {
      tackle::SweepSpec spec;
      if (analysis->model.sweep) spec = tackle::sweep_spec(*analysis->model.sweep);
      if (!vary.empty()) spec.vary = vary;
      if (!fixes.empty()) spec.fix = fixes;
      if (!plot.empty()) spec.plot = split_commas(plot);
      if (spec.vary.empty()) {
        std::cerr << "tackle sweep: give --vary (the description has no 'sweep')\n";
        return 2;
      }
      const tackle::Derivation d = tackle::explain(*analysis);
      const auto result = tackle::run_sweep(*analysis, d, spec, tackle::Location{"--vary/--plot", 0, 0});
      for (const auto& [path, text] : {std::pair{svg_out, tackle::sweep_svg(result)}, std::pair{pgf_out, tackle::sweep_pgfplots(result)}})
        if (!path.empty() && emit(text, path) != 0) return 1;
      return emit(tackle::sweep_csv(result), csv_out);
    }
    if (simulate->parsed()) {
      tackle::SimulationSpec spec;
      if (until > 0) spec.until = until;
      spec.samples = samples;
      if (!sim_plot.empty()) spec.plot = split_commas(sim_plot);
      const auto result = tackle::simulate(*analysis, spec, tackle::Location{"--until/--plot", 0, 0});
      for (const auto& [path, text] : {std::pair{csv_out, tackle::sweep_csv(result.table)}, std::pair{svg_out, tackle::sweep_svg(result.table)},
                                       std::pair{pgf_out, tackle::sweep_pgfplots(result.table)}})
        if (!path.empty() && emit(text, path) != 0) return 1;
      return emit(tackle::simulation_text(result), out);
    }
    if (check->parsed()) {
      tackle::CheckOptions options;
      options.relative_tolerance = tolerance;
      if (sig_figs > 0) options.significant_figures = sig_figs;
      options.require_simplified = require_simplified;
      options.echo_latex = !no_latex;
      options.reveal = reveal;
      const tackle::Checker checker(*analysis, options);
      std::vector<std::pair<std::string, std::string>> set;
      for (const auto& v : set_values) {
        const auto eq = v.find('=');
        if (eq == std::string::npos || eq == 0) {
          std::cerr << "tackle check: --set " << v << ": expected NAME=VALUE\n";
          return 2;
        }
        set.emplace_back(v.substr(0, eq), v.substr(eq + 1));
      }
      std::optional<GiNaC::exmap> values;
      if (!set.empty()) {
        std::string problem;
        values = checker.values_for(set, problem);
        if (!values) {
          std::cerr << "tackle check: --set: " << problem << "\n";
          return 2;
        }
      }
      if (batch_opt->count() > 0) {
        tackle::GradeOptions grade;
        grade.format = results_format == "prairielearn" ? tackle::ResultsFormat::prairielearn
                       : results_format == "jsonl"      ? tackle::ResultsFormat::jsonl
                                                        : tackle::ResultsFormat::gradescope;
        grade.top_level_score = top_level_score;
        grade.set = set;
        for (const auto& p : points_text) {
          const auto eq = p.find('=');
          const std::string number = eq == std::string::npos ? p : p.substr(eq + 1);
          char* end = nullptr;
          const double v = std::strtod(number.c_str(), &end);
          if (number.empty() || *end != '\0' || !(v >= 0) || v > 1e6) {
            std::cerr << "tackle check: --points " << p << ": expected a number of points from 0 to 10^6, or NAME=N\n";
            return 2;
          }
          if (eq == std::string::npos) grade.points = v;
          else grade.points_for[p.substr(0, eq)] = v;
        }
        std::istringstream batch_text;
        if (batch != "-") batch_text.str(tackle::read_text_file(batch));
        // Both outputs go through temporary files and are renamed into place only when the
        // whole batch was graded.
        std::optional<tackle::AtomicOutput> out_file, results_file;
        for (auto& [file, path] : {std::pair{&out_file, &out}, std::pair{&results_file, &results}}) {
          if (path->empty() || *path == "-") continue;
          file->emplace(*path);
          if (!(*file)->ok()) {
            std::cerr << (*file)->error() << "\n";
            return 1;
          }
        }
        std::ostream& sink = out_file ? out_file->stream() : std::cout;
        const auto summary = tackle::check_batch(checker, batch == "-" ? std::cin : batch_text, sink, grade);
        if (results_file) results_file->stream() << summary.results;
        for (auto* file : {&out_file, &results_file})
          if (*file && !(*file)->commit()) {
            std::cerr << (*file)->error() << "\n";
            return 1;
          }
        return 0;
      }
      const auto result = checker.check(unknown, answer, values ? &*values : nullptr);
      return emit(format == "json" ? tackle::result_json(result, answer) : tackle::result_text(result), out);
    }
    const tackle::Derivation d = tackle::explain(*analysis, tackle::ReportOptions{digits});
    return emit(tackle::write(d, formats.at(format), derive->parsed()), out);
  } catch (const tackle::InputError& e) {
    return report_input_error(e);
  } catch (const tackle::InternalError& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tackle: internal error: " << e.what() << "\n";
    return 3;
  }
}

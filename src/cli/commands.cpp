// The command line's commands but check (see commands.hpp).
#include "cli/commands.hpp"

#include <iostream>
#include <memory>

#include "analysis/regimes.hpp"
#include "cli/output.hpp"
#include "expr/parse.hpp"
#include "isolate/isolate.hpp"
#include "motion/simulate.hpp"
#include "report/isolation_report.hpp"
#include "report/key.hpp"
#include "report/sheet.hpp"
#include "report/step_page.hpp"
#include "report/sweep.hpp"
#include "report/writer.hpp"

namespace tackle::cli {

namespace {

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

// A format's name, as --format checked it (report/writer.hpp lists them).
tackle::Format format_of(const std::string& name) {
  const auto f = tackle::format_named(name);
  if (!f) throw tackle::InternalError("no format named '" + name + "'");
  return *f;
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

}  // namespace

const tackle::Analysis* the_phase(const tackle::Analysis& whole, const Options& o) {
  std::string problem;
  const tackle::Analysis* a = tackle::pick_phase(whole, o.phase, problem);
  if (!a) std::cerr << "tackle: " << o.file << ": " << problem << "\n";
  return a;
}

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

int run_page(const Options& o, const tackle::RuleSet& rules) {
  const auto whole = tackle::analyze_file(o.file, rules);
  const tackle::Analysis* analysis = the_phase(*whole, o);
  if (!analysis) return 2;
  return emit(tackle::step_page(tackle::explain(*analysis), analysis->model, o.endpoint), o.out);
}

int run_isolate(const Options& o, const tackle::RuleSet& rules) {
  const tackle::Description description = tackle::read_description(o.file);
  // Phases, and connections decided at the numbers (friction that sticks or slips), are
  // analysed first: the model to search is the phase's, or the regime's that holds.
  std::unique_ptr<const tackle::Analysis> phased;
  if (!description.phases.empty() || !o.phase.empty() || !tackle::decided_connections(description, rules).empty())
    phased = tackle::analyze(description, rules);
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

}  // namespace tackle::cli

// The Python module: `import tackle`. A thin shell over the library, like the command line:
// load a problem, derive it in any format, draw a variant, check one answer or a batch.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <dlfcn.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

#include "grade/batch.hpp"
#include "check/check.hpp"
#include "check/fbd.hpp"
#include "check/steps.hpp"
#include "expr/print.hpp"
#include "pipeline/pipeline.hpp"
#include "python/display.hpp"
#include "report/key.hpp"
#include "report/writer.hpp"
#include "report/step_page.hpp"
#include "ruleset/builtin_rules.hpp"

namespace py = pybind11;

namespace {

// The rules: $TACKLE_RULES, else share/tackle/rules of the prefix this module is installed in
// (PREFIX/lib/python3/dist-packages/tackle*.so), else the library's default (a build tree's).
std::string module_rules_dir() {
  if (const char* env = std::getenv("TACKLE_RULES"); env && *env) return env;
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&module_rules_dir), &info) && info.dli_fname) {
    std::error_code ec;
    const auto installed =
        std::filesystem::path(info.dli_fname).parent_path().parent_path().parent_path().parent_path() /
        "share/tackle/rules";
    if (std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
  return tackle::default_rules_dir();
}

// A problem: one description (or one phase of a phased one), analyzed once, and its checkers,
// each prepared once (on first use) and kept: a Checker's set-up (the references made into
// code, the equations' basis, the points) was 4 to 9 times a check's own cost when it was made
// anew at every call. Thread safety: every method runs with the GIL held (none releases it,
// and nothing here calls back into Python while a checker is at work), so one call at a time
// touches the checkers and GiNaC's reference counts; a Checker's own lazy parts are guarded too.
class Problem {
 public:
  Problem(const std::string& path, const std::string& phase, const std::string& rules_dir)
      : rules_(tackle::load_rules(rules_dir.empty() ? module_rules_dir() : rules_dir, tackle::RuleLoading::when_used,
                                  tackle::builtin_rules())),
        whole_(tackle::analyze_file(path, rules_)) {
    std::string problem;
    analysis_ = tackle::pick_phase(*whole_, phase, problem);
    if (!analysis_) throw py::value_error(path + ": " + std::regex_replace(problem, std::regex("--phase"), "phase="));
    derivation_ = tackle::explain(*analysis_);
  }

  [[nodiscard]] std::string title() const { return derivation_.title; }
  // What a notebook shows (python/display.hpp).
  [[nodiscard]] const tackle::Derivation& derivation() const { return derivation_; }
  [[nodiscard]] const tackle::Model& model() const { return analysis_->model; }

  [[nodiscard]] std::string derive(const std::string& format, bool full) const {
    const auto f = tackle::format_named(format);
    if (!f) {
      const auto names = tackle::format_names();
      throw py::value_error("format '" + format + "' (expected " + tackle::join({names.begin(), names.end() - 1}) +
                            " or " + names.back() + ")");
    }
    return tackle::write(derivation_, *f, full);
  }

  // Each answer: name, status, closed form (text and LaTeX), value and unit when numbers are given.
  [[nodiscard]] py::list answers() const {
    py::list out;
    for (const auto& a : derivation_.answers) {
      py::dict d;
      d["name"] = a.name;
      d["closed_form"] = a.closed_form ? py::object(py::str(tackle::to_text(*a.closed_form))) : py::object(py::none());
      d["latex"] = a.closed_form ? py::object(py::str(tackle::to_latex(*a.closed_form))) : py::object(py::none());
      d["value"] = a.value ? py::object(py::float_(a.value->approx)) : py::object(py::none());
      d["unit"] = a.value ? py::object(py::str(a.value->unit)) : py::object(py::none());
      out.append(d);
    }
    return out;
  }

  // A variant: the parameters with a `range` drawn (the same seed, the same variant), and the
  // answers there; None when no parameter has a range.
  [[nodiscard]] py::object variant(unsigned long long seed, int digits) const {
    const auto drawn = tackle::draw_variants(analysis_->model, derivation_, 1, seed, digits);
    if (drawn.empty()) return py::none();
    py::dict parameters, answers;
    for (const auto& q : drawn[0].parameters)
      parameters[py::str(q.name)] =
          py::dict(py::arg("value") = q.value, py::arg("unit") = q.unit, py::arg("text") = q.text());
    for (const auto& q : drawn[0].answers)
      answers[py::str(q.name)] =
          py::dict(py::arg("value") = q.value, py::arg("unit") = q.unit, py::arg("text") = q.text());
    return py::dict(py::arg("parameters") = parameters, py::arg("answers") = answers);
  }

  // One answer; `params`: the student's own numbers ({"F": 120}, in the stated units).
  [[nodiscard]] py::dict check(const std::string& unknown, const std::string& answer, const py::dict& params,
                               double tolerance, bool reveal) const {
    const auto set = settings(params);  // (Python's str() of each: before a checker is taken)
    const auto checker = checker_for(tolerance, reveal);
    std::optional<GiNaC::exmap> values;
    if (!set.empty()) {
      std::string problem;
      values = checker->values_for(set, problem);
      if (!values) throw py::value_error("params: " + problem);
    }
    const tackle::CheckResult r = checker->check(unknown, answer, values ? &*values : nullptr);
    py::list findings;
    for (const auto& f : r.findings)
      findings.append(py::dict(py::arg("code") = f.code, py::arg("message") = f.message));
    return py::dict(py::arg("unknown") = r.unknown, py::arg("verdict") = tackle::verdict_name(r.verdict),
                    py::arg("score") = r.score, py::arg("summary") = r.summary, py::arg("findings") = findings,
                    py::arg("method") = r.method, py::arg("read_as") = r.echo_text, py::arg("latex") = r.echo_latex);
  }

  // One equation a student wrote: is it one of the derivation's, or does it follow from them?
  [[nodiscard]] py::dict check_equation(const std::string& equation) const {
    const tackle::CheckResult r = checker_for(0.01, false)->check_equation(equation);
    py::list findings, identified, follows;
    for (const auto& f : r.findings)
      findings.append(py::dict(py::arg("code") = f.code, py::arg("message") = f.message));
    for (const auto& n : r.identified_as) identified.append(n);
    for (const auto& n : r.follows_from) follows.append(n);
    return py::dict(py::arg("verdict") = tackle::verdict_name(r.verdict), py::arg("score") = r.score,
                    py::arg("summary") = r.summary, py::arg("findings") = findings, py::arg("method") = r.method,
                    py::arg("read_as") = r.echo_text, py::arg("latex") = r.echo_latex,
                    py::arg("identified_as") = identified, py::arg("follows_from") = follows);
  }

  // A free body diagram the student drew: the YAML (or JSON) of `tackle check --fbd`, or a
  // dict of the same; the grade as `--fbd --format json` gives it, as a dict.
  [[nodiscard]] py::object check_fbd(const py::object& fbd, const std::string& rubric) const {
    const std::string text = py::isinstance<py::str>(fbd)
                                 ? fbd.cast<std::string>()
                                 : py::module_::import("json").attr("dumps")(fbd).cast<std::string>();
    const tackle::StudentFbd student = tackle::read_fbd_file(text, "fbd", analysis_->model);
    const tackle::Rubric r =
        rubric.empty() ? tackle::Rubric{} : tackle::read_rubric(rubric, "rubric", analysis_->model);
    std::vector<tackle::Diagnostic> problems;
    const tackle::FbdGrade g = tackle::check_fbd(analysis_->model, student, r.fbd, problems);
    if (!problems.empty()) throw tackle::InputError(problems);
    return py::module_::import("json").attr("loads")(tackle::fbd_json(g));
  }

  // A worked solution (the YAML of `tackle check --steps`) with an optional rubric (YAML): the
  // grade as `--steps --format json` gives it, as a dict, and the platform's results file.
  // A time_limit (seconds, 0: none): a step not begun within it is not checked (undecided,
  // code time_limit; see grade_solution).
  [[nodiscard]] py::tuple check_solution(const std::string& solution, const std::string& rubric,
                                         const std::string& results_format, double time_limit) const {
    if (!(time_limit >= 0 && time_limit <= 86400))
      throw py::value_error("time_limit must be from 0 to 86400 seconds (0: none)");
    std::optional<std::chrono::steady_clock::time_point> deadline;
    if (time_limit > 0)
      deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                        std::chrono::duration<double>(time_limit));
    const auto checker = checker_for(0.01, false);
    tackle::ResultsFormat format = tackle::ResultsFormat::gradescope;
    if (results_format == "prairielearn")
      format = tackle::ResultsFormat::prairielearn;
    else if (results_format != "gradescope")
      throw py::value_error("results_format '" + results_format + "' (expected gradescope or prairielearn)");
    const auto steps = tackle::read_solution(solution, "solution", analysis_->model);
    const tackle::Rubric r =
        rubric.empty() ? tackle::Rubric{} : tackle::read_rubric(rubric, "rubric", analysis_->model);
    const tackle::SolutionGrade g = tackle::grade_solution(*checker, analysis_->model, steps, r, deadline);
    return py::make_tuple(py::module_::import("json").attr("loads")(tackle::solution_json(g)),
                          tackle::solution_results(g, format));
  }

  // The page to try the step checker (`tackle page`): its form posts to `endpoint` (a path or an
  // http(s) URL; empty: the page's own location). ValueError for an endpoint it cannot use.
  [[nodiscard]] std::string page(const std::string& endpoint) const {
    return tackle::step_page(derivation_, analysis_->model, endpoint);
  }

  // JSON Lines in; (the results a line, the platform's results file) out.
  [[nodiscard]] py::tuple check_batch(const std::string& lines, const std::string& results_format, double points,
                                      const py::dict& params, double tolerance, bool reveal) const {
    const auto checker = checker_for(tolerance, reveal);
    tackle::GradeOptions grade;
    if (results_format == "gradescope")
      grade.format = tackle::ResultsFormat::gradescope;
    else if (results_format == "prairielearn")
      grade.format = tackle::ResultsFormat::prairielearn;
    else if (results_format == "jsonl")
      grade.format = tackle::ResultsFormat::jsonl;
    else
      throw py::value_error("results_format '" + results_format + "' (expected gradescope, prairielearn or jsonl)");
    grade.points = points;
    grade.set = settings(params);
    grade.model = &analysis_->model;
    std::istringstream in(lines);
    std::ostringstream out;
    const tackle::BatchSummary s = tackle::check_batch(*checker, in, out, grade);
    return py::make_tuple(out.str(), s.results);
  }

 private:
  // The checker for these options, made on first use and kept (a few: past them, a checker is
  // made for the call alone). Shared, so that a call holds its own even when Python code run
  // between (a parameter's str()) lets another thread call in.
  std::shared_ptr<const tackle::Checker> checker_for(double tolerance, bool reveal) const {
    const tackle::CheckOptions o = options(tolerance, reveal);
    const auto key = std::make_pair(tolerance, reveal);
    if (const auto found = checkers_.find(key); found != checkers_.end()) return found->second;
    auto made = std::make_shared<const tackle::Checker>(*analysis_, o);
    if (checkers_.size() < max_checkers) checkers_.emplace(key, made);
    return made;
  }
  static tackle::CheckOptions options(double tolerance, bool reveal) {
    if (!(tolerance >= 0 && tolerance <= 1)) throw py::value_error("tolerance must be from 0 to 1");
    tackle::CheckOptions o;
    o.relative_tolerance = tolerance;
    o.reveal = reveal;
    return o;
  }
  static std::vector<std::pair<std::string, std::string>> settings(const py::dict& params) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [k, v] : params) out.emplace_back(py::str(k), py::str(v));
    return out;
  }

  tackle::RuleSet rules_;
  std::unique_ptr<const tackle::Analysis> whole_;
  const tackle::Analysis* analysis_ = nullptr;
  tackle::Derivation derivation_;
  static constexpr std::size_t max_checkers = 8;
  mutable std::map<std::pair<double, bool>, std::shared_ptr<const tackle::Checker>> checkers_;
};

}  // namespace

PYBIND11_MODULE(tackle, m) {
  m.doc() = "tackle: free-body-diagram equations for constrained straight-line motion, solved in closed form";
  m.attr("__version__") = TACKLE_VERSION;
  m.def("rules_dir", &module_rules_dir, "The rules directory a Problem reads by default");
  // A problem in a description is a ValueError carrying every located message, one a line.
  static py::exception<tackle::InputError> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const tackle::InputError& e) {
      std::string text;
      for (const auto& d : e.diagnostics()) text += (text.empty() ? "" : "\n") + tackle::format(d);
      input_error(text.c_str());
    }
  });
  py::class_<Problem>(m, "Problem", "A problem description (YAML), analyzed: derivation, answers, variants, checks")
      .def(py::init<const std::string&, const std::string&, const std::string&>(), py::arg("path"),
           py::arg("phase") = "", py::arg("rules") = "")
      .def_property_readonly("title", &Problem::title)
      .def("derive", &Problem::derive, py::arg("format") = "text", py::arg("full") = true,
           "The derivation (full) or the answers only, as text, latex, markdown or json")
      .def("answers", &Problem::answers, "Each answer: name, closed_form, latex, value, unit")
      .def("variant", &Problem::variant, py::arg("seed"), py::arg("digits") = 6,
           "Parameters drawn from their ranges and the answers there, or None without ranges")
      .def("check", &Problem::check, py::arg("unknown"), py::arg("answer"), py::arg("params") = py::dict(),
           py::arg("tolerance") = 0.01, py::arg("reveal") = false,
           "Check one answer: verdict, score, summary, findings")
      .def("check_equation", &Problem::check_equation, py::arg("equation"),
           "Check an equation the student wrote: verdict, score, summary, findings, identified_as, follows_from")
      .def("check_fbd", &Problem::check_fbd, py::arg("fbd"), py::arg("rubric") = "",
           "Check a free body diagram the student drew (YAML/JSON text or a dict: body, forces, couples): "
           "verdict, summary, each force's status, extras, findings, score")
      .def("check_solution", &Problem::check_solution, py::arg("solution"), py::arg("rubric") = "",
           py::arg("results_format") = "gradescope", py::arg("time_limit") = 0.0,
           "Grade a worked solution (YAML: steps of fbd, equation and answer): (the grade as a dict, the platform's "
           "results file); "
           "with a time_limit (seconds), steps not begun within it are undecided (time_limit)")
      .def("page", &Problem::page, py::arg("endpoint") = "",
           "A self-contained HTML page: the problem and a worked-solution form whose steps it posts to "
           "{endpoint}/step and {endpoint}/solution (the page's own location by default)")
      .def("check_batch", &Problem::check_batch, py::arg("lines"), py::arg("results_format") = "gradescope",
           py::arg("points") = 1.0, py::arg("params") = py::dict(), py::arg("tolerance") = 0.01,
           py::arg("reveal") = false, "Check JSON Lines of answers: (results a line, the platform's results file)");
  // Rich display in notebooks: Problem's HTML and LaTeX, results that show themselves.
  tackle::python::add_display<Problem>(m);
}

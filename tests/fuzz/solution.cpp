// Fuzz target: a student's worked solution (free body diagrams, equations, answers) and a
// rubric, read and graded. The first byte picks the problem; the rest is the solution's YAML
// (a located input error is a normal outcome). Seeds are in seeds/solution/.
#include "common.hpp"

#include <memory>
#include <vector>

#include "check/steps.hpp"
#include "report/verdicts.hpp"

namespace {

struct Problem {
  std::unique_ptr<const tackle::Analysis> analysis;
  std::unique_ptr<const tackle::Checker> checker;
};

const std::vector<Problem>& problems() {
  static const auto list = [] {
    std::vector<Problem> out;
    for (const char* name : {"sample-12.3-two-mass-pulley", "incline-and-hanging-block", "sample-12.8-sign-board",
                             "rotation-wheel-driven-by-a-couple", "two-blocks-joined-by-a-pin"}) {
      Problem p;
      p.analysis =
          tackle::analyze_file(std::string(TACKLE_SOURCE_DIR "/examples/") + name + ".yaml", tackle::fuzz::rules());
      tackle::CheckOptions options;
      options.seed = 1;  // a finding must replay the same way
      p.checker = std::make_unique<const tackle::Checker>(*p.analysis, options);
      out.push_back(std::move(p));
    }
    return out;
  }();
  return list;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const Problem& p = problems()[data[0] % problems().size()];
  const std::string text = tackle::fuzz::text_of(data + 1, size - 1);
  try {
    const auto steps = tackle::read_solution(text, "solution.yaml", p.analysis->model);
    const tackle::SolutionGrade g = tackle::grade_solution(*p.checker, p.analysis->model, steps, tackle::Rubric{});
    (void)tackle::solution_text(g);
    tackle::fuzz::no_internal_verdict(tackle::solution_json(g));
  } catch (const tackle::InputError&) {
  }
  try {
    // The same text as one diagram, and as a rubric.
    const tackle::StudentFbd fbd = tackle::read_fbd_file(text, "fbd.yaml", p.analysis->model);
    std::vector<tackle::Diagnostic> problems;
    const tackle::FbdGrade g = tackle::check_fbd(p.analysis->model, fbd, tackle::FbdRubric{}, problems);
    (void)tackle::fbd_text(g);
    (void)tackle::fbd_json(g);
  } catch (const tackle::InputError&) {
  }
  try {
    (void)tackle::read_rubric(text, "rubric.yaml", p.analysis->model);
  } catch (const tackle::InputError&) {
  }
  return 0;
}

// Fuzz target: a student's answer through the strict parser and the checker. The first
// byte picks the problem, the second the unknown (or an equation, checked against the
// derivation's equations); the rest is the answer as typed. Seeds
// and a dictionary of operators, names, numbers and units are in this folder.
#include "common.hpp"

#include <memory>
#include <vector>

#include "check/check.hpp"

namespace {

const std::string equation = "=";  // not an unknown's name: the text is an equation

struct Problem {
  std::unique_ptr<const tackle::Analysis> analysis;
  std::unique_ptr<const tackle::Checker> checker;
  std::vector<std::string> unknowns;
};

const std::vector<Problem>& problems() {
  static const auto list = [] {
    std::vector<Problem> out;
    for (const char* name : {"sample-12.8-sign-board", "sample-12.7-suitcase", "sample-12.3-two-mass-pulley",
                             "car-braking-us-units", "sample-12.2-pulley-kinematics"}) {
      Problem p;
      p.analysis =
          tackle::analyze_file(std::string(TACKLE_SOURCE_DIR "/examples/") + name + ".yaml", tackle::fuzz::rules());
      // A seed for the points drawn for each check: a finding must replay the same way.
      tackle::CheckOptions options;
      options.seed = 1;
      p.checker = std::make_unique<const tackle::Checker>(*p.analysis, options);
      p.unknowns = p.checker->unknowns();
      p.unknowns.push_back("no_such_unknown");
      p.unknowns.push_back(equation);
      out.push_back(std::move(p));
    }
    return out;
  }();
  return list;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const Problem& p = problems()[data[0] % problems().size()];
  const std::string& unknown = p.unknowns[data[1] % p.unknowns.size()];
  const tackle::CheckResult r = unknown == equation
                                    ? p.checker->check_equation(tackle::fuzz::text_of(data + 2, size - 2))
                                    : p.checker->check(unknown, tackle::fuzz::text_of(data + 2, size - 2));
  for (const auto& f : r.findings) tackle::fuzz::no_internal_verdict(f.code);
  return 0;
}

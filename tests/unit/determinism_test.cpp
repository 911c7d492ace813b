// Determinism inside one process: GiNaC orders terms by hashes made from symbols' serial
// numbers (and addresses). Making symbols before the model shifts every serial number, so
// every hash; each example's reports and isolations must not change with it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "isolate/isolate.hpp"
#include "report/isolation_report.hpp"
#include "../support/helpers.hpp"

using namespace tackle;

namespace {

std::string everything(const std::string& file) {
  const auto a = analyze_file(file, test::rules());
  const auto ds = explain_phases(*a);
  std::string out;
  for (Format f : {Format::text, Format::latex, Format::markdown, Format::json}) out += write(ds, f, true);
  std::vector<const Analysis*> parts{a.get()};
  if (!a->phases.empty()) {
    parts.clear();
    for (const auto& p : a->phases) parts.push_back(p.analysis.get());
  }
  for (const Analysis* part : parts) {
    if (part->impact) continue;  // no balances to isolate
    const auto candidates = candidate_equations(part->model);
    std::vector<Isolation> found;
    for (const auto& u : model_unknowns(part->model)) found.push_back(isolate(part->model, candidates, u));
    out += write_isolations(part->model, found, Format::text);
  }
  return out;
}

}  // namespace

TEST_CASE("Determinism: every example reports the same under shifted hash orders", "[determinism]") {
  const std::vector<std::string> files = test::example_files();
  for (const auto& file : files) {
    SECTION(std::filesystem::path(file).stem().string()) {
      const std::string first = everything(file);
      for (std::size_t shift : {1, 5, 13, 31}) {
        INFO("shift " << shift);
        const std::vector<GiNaC::symbol> dummies(shift);
        CHECK(everything(file) == first);
      }
    }
  }
}

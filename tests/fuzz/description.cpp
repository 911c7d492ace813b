// Fuzz target: a description file through reading, model building, balances, solving and
// the derivation in every format. Seeds: examples/ and tests/data/bad/.
#include "common.hpp"

#include "report/derivation.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto analysis = tackle::analyze_text(tackle::fuzz::text_of(data, size), "fuzz.yaml", tackle::fuzz::rules());
    const auto ds = tackle::explain_phases(*analysis);
    for (auto f : {tackle::Format::text, tackle::Format::latex, tackle::Format::json}) (void)tackle::write(ds, f, true);
  } catch (const tackle::InputError&) {
  }
  return 0;
}

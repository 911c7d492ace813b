// Answer keys: for each problem its title, what is asked, the closed forms and the numbers;
// optionally numeric variants drawn from the parameter ranges the description declares.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "report/derivation.hpp"

namespace tackle {

struct Quantity {
  std::string name;
  std::string number;  // "18.4615"
  std::string unit;    // "N", or empty
  double value = 0.0;  // the same number, for JSON
  [[nodiscard]] std::string text() const { return number + (unit.empty() ? "" : " " + unit); }
};

struct Variant {
  int index = 0;
  std::vector<Quantity> parameters;  // the drawn values, in each parameter's unit
  std::vector<Quantity> answers;
  GiNaC::exmap values;  // the drawn values in SI, by the part's parameter symbols (its figures are drawn at them)
};

/// N variants: every parameter with a `range` drawn from it (a multiple of its `round` step,
/// or of a hundredth of the range), the others kept. The same seed gives the same variants
/// on every platform (std::mt19937_64, no library distribution). A draw that breaks a
/// validity condition, or leaves an answer undefined, is drawn again; InputError when 1000
/// draws cannot give a valid variant. None when no parameter has a range.
[[nodiscard]] std::vector<Variant> draw_variants(const Model& m, const Derivation& d, int count,
                                                 unsigned long long seed, int digits);
/// The same for parts that share parameters (the phases of a phased description): one draw
/// for all, valid only when it is valid in every part; one list of variants per part.
[[nodiscard]] std::vector<std::vector<Variant>> draw_variants(
    const std::vector<std::pair<const Model*, const Derivation*>>& parts, int count, unsigned long long seed,
    int digits);

struct KeyEntry {
  const Derivation* derivation = nullptr;
  std::vector<Variant> variants;
  bool variants_asked = false;  // the key says so when none could be drawn
};

[[nodiscard]] std::string write_key(const std::vector<KeyEntry>& entries, Format f);

}  // namespace tackle

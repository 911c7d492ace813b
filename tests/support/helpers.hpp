// Test helpers: run the chain on inline YAML, collect diagnostics as strings.
#pragma once

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "pipeline/pipeline.hpp"

namespace tackle::test {

inline const RuleSet& rules() {
  static const RuleSet r = load_rules(TACKLE_SOURCE_DIR "/rules");
  return r;
}

// The number of an expression: the definitions, then `also` (time, lambda), then the
// parameters' values put in.
inline double number(const GiNaC::ex& e, const SymbolTable& t, const GiNaC::exmap& also = {}) {
  GiNaC::ex v = e;
  const GiNaC::exmap defs = t.definitions(true);
  for (int depth = 0; depth < 8; ++depth) v = v.subs(defs, GiNaC::subs_options::no_pattern);
  v = v.subs(also, GiNaC::subs_options::no_pattern).subs(t.values(), GiNaC::subs_options::no_pattern);
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(v)).to_double();
}

inline std::unique_ptr<const Analysis> run_text(const std::string& yaml, const std::string& file = "t.yaml") {
  return tackle::analyze_text(yaml, file, rules());
}

/// A massless beam pinned at A, held by a cable from B up to C, turned by a couple M: a
/// problem in symbols only (by hand, moments about A: T_BC = -M/L).
inline const std::string pinned_beam_with_couple = R"(title: couple
axes: [x, y]
parameters: {M: {dimension: moment}, L: {unit: m}}
points: {A: [0, 0], B: [L, 0], C: [L, L]}
bodies: {beam: {mass: 0}}
connections:
  - {type: pin, body: beam, at: A}
  - {type: cable, body: beam, from: B, to: C}
  - {type: couple, on: beam, moment: M}
)";

/// Every example description's path, in order.
inline std::vector<std::string> example_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(TACKLE_SOURCE_DIR "/examples"))
    if (e.path().extension() == ".yaml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

/// An example's text, to vary it in a test.
inline std::string read_example(const std::string& name) {
  return read_text_file(TACKLE_SOURCE_DIR "/examples/" + name);
}

/// An example with one piece of its text replaced (throws when the text is not there, so a
/// test cannot silently run the unchanged example).
inline std::string example_with(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = read_example(name);
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error(name + " has no '" + from + "'");
  return text.replace(at, from.size(), to);
}

/// Every diagnostic the text produces, formatted; empty when it is accepted.
inline std::vector<std::string> errors_of(const std::string& yaml) {
  try {
    (void)run_text(yaml);
  } catch (const InputError& e) {
    std::vector<std::string> out;
    for (const auto& d : e.diagnostics()) out.push_back(format(d));
    return out;
  }
  return {};
}

}  // namespace tackle::test

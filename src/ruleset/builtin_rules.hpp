// The rules compiled into the program: made at build time from rules/*.yaml by
// tackle_embed_rules (src/ruleset/embed_rules.cpp), into the program and the tests only.
#pragma once

#include <span>

#include "ruleset/ruleset.hpp"

namespace tackle {

/// Every rules/*.yaml of the source tree the program was built from, sorted by name.
[[nodiscard]] std::span<const BuiltinRule> builtin_rules();

}  // namespace tackle

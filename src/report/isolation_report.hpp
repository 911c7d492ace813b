#pragma once

#include <string>
#include <vector>

#include "isolate/isolate.hpp"
#include "report/derivation.hpp"

namespace tackle {

/// Text or JSON (`version`, `title`, `isolations`: unknown, found, tried, equation,
/// closed_form, latex, value, unit).
[[nodiscard]] std::string write_isolations(const Model& m, const std::vector<Isolation>& found, Format f);

}  // namespace tackle

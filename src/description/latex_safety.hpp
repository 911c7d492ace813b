// A description's texts that reach LaTeX, HTML and Markdown (titles, statements, TeX names),
// checked before anything is written from them.
#pragma once

#include <string>

#include "core/diagnostics.hpp"
#include "description/description.hpp"

namespace tackle {

/// A title (and a phase's name) on one line; statements and TeX names without a LaTeX command
/// that reads or writes files, runs programs, defines commands or changes how LaTeX reads
/// characters. `source` is the description's text (for the problems' locations).
void check_texts(const std::string& source, const Description& d, Diagnostics& diags);

}  // namespace tackle

// What the command line writes: to standard output (and whether it got there) or to a file
// atomically, and input errors as `file:line:col: message` lines.
#pragma once

#include <functional>
#include <ostream>
#include <string>

#include "core/diagnostics.hpp"

namespace tackle::cli {

/// Says every diagnostic of `e` on standard error, one a line; returns 1 (input error).
int report_input_error(const tackle::InputError& e);

/// Whether everything written to standard output so far reached it; when not, says so once.
bool standard_output_written();

/// `text` to standard output (`out` empty or "-"), or to the file `out` atomically (a failed
/// run leaves no partial output): 0, or 1 when it could not be written.
int emit(const std::string& text, const std::string& out);

/// The same for a document written as it is made (`write` takes the stream).
int emit_to(const std::function<void(std::ostream&)>& write, const std::string& out);

}  // namespace tackle::cli

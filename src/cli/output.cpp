// What the command line writes (see output.hpp).
#include "cli/output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "core/files.hpp"

namespace tackle::cli {

int report_input_error(const tackle::InputError& e) {
  for (const auto& d : e.diagnostics()) std::cerr << tackle::format(d) << "\n";
  return 1;
}

// Whether everything written to standard output so far reached it; when not, says so once
// (`tackle derive FILE > /dev/full` must not exit 0). errno is read right after the flush
// that failed; a write that failed earlier (output past stdio's buffer) may have left no
// reason behind, and then none is given.
bool standard_output_written() {
  static bool said = false;
  errno = 0;
  std::cout.flush();
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && std::cout && !std::ferror(stdout)) return true;
  if (!said)
    std::cerr << "tackle: cannot write to standard output"
              << (err != 0 ? std::string(" (") + std::strerror(err) + ")" : "") << "\n";
  said = true;
  return false;
}

// To standard output, or to the file atomically (a failed run leaves no partial output).
int emit(const std::string& text, const std::string& out) {
  if (out.empty() || out == "-") {
    std::cout << text;
    return standard_output_written() ? 0 : 1;
  }
  std::string error;
  if (tackle::write_file_atomically(out, text, error)) return 0;
  std::cerr << error << "\n";
  return 1;
}

// The same for a document written as it is made (`write` takes the stream): to standard
// output as it goes, or into a temporary file renamed into place when it is complete.
int emit_to(const std::function<void(std::ostream&)>& write, const std::string& out) {
  if (out.empty() || out == "-") {
    write(std::cout);
    return standard_output_written() ? 0 : 1;
  }
  tackle::AtomicOutput file(out);
  if (file.ok()) write(file.stream());
  if (file.commit()) return 0;
  std::cerr << file.error() << "\n";
  return 1;
}

}  // namespace tackle::cli

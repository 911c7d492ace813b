// Files: reading a whole text file with clear errors, and writing outputs atomically (to a
// temporary file beside the target, renamed into place only when everything was written, so
// a failed run never leaves a partial or truncated output).
#pragma once

#include <fstream>
#include <string>

namespace tackle {

/// The whole file; InputError "cannot read the file" or "is a directory (expected a file)".
[[nodiscard]] std::string read_text_file(const std::string& path);

/// An output file written through a temporary file in the same directory; `commit()` renames
/// it into place. Without a successful commit the target is left as it was.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::string path);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();

  /// Whether the temporary file could be made (else `error()` says why).
  [[nodiscard]] bool ok() const { return stream_.is_open(); }
  [[nodiscard]] std::ostream& stream() { return stream_; }
  /// Flushes, closes and renames into place; false (and `error()`) when any step failed.
  bool commit();
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  std::string path_, temp_, error_;
  std::ofstream stream_;
  bool committed_ = false;
};

/// `text` written to `path` atomically; false (and a message on `error`) when it failed.
bool write_file_atomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace tackle

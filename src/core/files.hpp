// Files: reading a whole text file with clear errors and a bound on its size, and writing
// outputs atomically (to a temporary file beside the target, renamed into place only when
// everything was written, so a failed run never leaves a partial or truncated output).
//
// Only a regular file is ever replaced. A device node, a FIFO or a socket (`/dev/null`, a
// terminal, `/dev/stdout` as a pipe) is opened and written as it is: renaming a file over
// `/dev/null` as root would turn it into a regular file for every program on the machine. A
// symbolic link is followed and its target replaced (the link stays a link), with the
// target's mode. Nothing is ever created under /dev or /proc.
#pragma once

#include <cstddef>
#include <istream>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

#include "core/limits.hpp"

namespace tackle {

/// The whole file; InputError "cannot read the file", "is a directory (expected a file)" or
/// "is longer than 16 MiB (expected a description or rule file of at most 16 MiB)".
[[nodiscard]] std::string read_text_file(const std::string& path, std::size_t max_bytes = max_input_file_bytes);

/// A file to read as a stream, never whole (a batch, graded line by line); the same errors
/// as read_text_file's for a file that cannot be opened or is a directory.
[[nodiscard]] std::unique_ptr<std::istream> open_text_file(const std::string& path);

/// A stream buffer over a file descriptor that keeps the first write error's errno (an
/// ofstream forgets why it failed, and "No space left on device" is what a user needs).
class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
  /// The errno of the first failed write, 0 when none failed.
  [[nodiscard]] int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;
  std::streamsize xsputn(const char* s, std::streamsize n) override;

 private:
  bool drain();
  bool write_all(const char* s, std::size_t n);
  int fd_;
  int error_ = 0;
  char buffer_[1 << 16];
};

/// An output file written through a temporary file in the same directory as its (link's)
/// target; `commit()` renames it into place. Without a successful commit the target is left
/// as it was, and the temporary file is removed, also when the process is stopped by SIGINT,
/// SIGTERM or SIGHUP. A target that is not a regular file is written directly.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::string path);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();

  /// Whether the output could be opened (else `error()` says why).
  [[nodiscard]] bool ok() const { return fd_ >= 0; }
  [[nodiscard]] std::ostream& stream() { return stream_; }
  /// Whether writes go straight to the target (a device, a FIFO): not atomic.
  [[nodiscard]] bool direct() const { return temp_.empty(); }
  /// Flushes, closes and renames into place; false (and `error()`) when any step failed.
  bool commit();
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  void fail(int err);
  std::string path_, temp_, error_;
  std::string target_;  // what the temporary file replaces: the path with its links followed
  int fd_ = -1;
  int slot_ = -1;  // in the registry of temporary files removed on a signal
  std::unique_ptr<FdBuffer> buffer_;
  std::ostream stream_{nullptr};
  bool committed_ = false;
};

/// `text` written to `path` atomically; false (and a message on `error`) when it failed.
bool write_file_atomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace tackle

// Diagnostics: every problem a user can cause is reported compiler-style,
// `file:line:col: message`, and all problems of one input are collected before reporting.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tackle {

/// A place in an input file; line and column are 1-based, 0 means "not known".
struct Location {
  std::string file;
  int line = 0;
  int column = 0;

  /// The same file and line, `offset` columns further right (for a position inside a scalar).
  [[nodiscard]] Location shifted(int offset) const;
  friend bool operator==(const Location&, const Location&) = default;
};

struct Diagnostic {
  Location where;
  std::string message;
};

/// `file:line:col: message` (parts that are not known are left out).
[[nodiscard]] std::string format(const Diagnostic& d);

/// Collects problems; stages report everything they find, then throw once.
class Diagnostics {
 public:
  void error(Location where, std::string message);
  [[nodiscard]] bool empty() const { return items_.empty(); }
  [[nodiscard]] const std::vector<Diagnostic>& items() const { return items_; }
  /// Throws InputError with every collected problem, if there is any.
  void throw_if_any() const;

 private:
  std::vector<Diagnostic> items_;
};

/// A problem with the user's input (exit code 1).
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<Diagnostic> diagnostics);
  [[nodiscard]] const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

/// A bug in tackle (exit code 3).
class InternalError : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// The candidate closest to `word` (edit distance, case-insensitive), or "" if none is close.
[[nodiscard]] std::string nearest(std::string_view word, const std::vector<std::string>& candidates);

/// "a, b, c" for messages.
[[nodiscard]] std::string join(const std::vector<std::string>& words, std::string_view sep = ", ");

}  // namespace tackle

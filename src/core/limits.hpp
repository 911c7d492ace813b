// Bounds on anything a user (or a student) can type, enforced before GiNaC sees it.
#pragma once

#include <cstddef>

namespace tackle {

struct ExprLimits {
  std::size_t max_length = 4096;       // characters in one expression
  std::size_t max_tokens = 1024;       // tokens in one expression
  std::size_t max_depth = 64;          // nesting of parentheses, unary signs and powers
  long max_exponent = 64;              // |n| for an integer exponent
  std::size_t max_number_digits = 40;  // digits in one number literal
};

/// The largest file read whole (a description or a rule file); a longer one, or one that
/// never ends (`/dev/zero`), is an input error once this much has been read. The largest
/// example is 6 KB.
inline constexpr std::size_t max_input_file_bytes = std::size_t{16} << 20;  // 16 MiB

/// The longest line of a batch. A line past the checker's own bound (a few answers long) is
/// an `invalid` result; one past this stops the batch as an input error, since a line that
/// never ends (`/dev/zero`) would otherwise be read for ever.
inline constexpr std::size_t max_batch_line_bytes = std::size_t{1} << 20;  // 1 MiB

}  // namespace tackle

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

}  // namespace tackle

// An expression compiled for fast evaluation in doubles: the right-hand side of a numeric
// integration is evaluated millions of times, where substituting into GiNaC would cost
// microseconds each. Postfix code over a small stack; the inputs are given in order.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace tackle {

class Compiled {
 public:
  /// Compiles `e`, whose symbols must all be among `inputs`; nothing (with `problem` set)
  /// for a symbol that is not, or a function it cannot evaluate.
  static std::optional<Compiled> compile(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs,
                                         std::string& problem);
  /// The value at `x` (one double per input, in order).
  [[nodiscard]] double operator()(const double* x) const;

 private:
  enum class Op {
    constant,
    input,
    add,
    mul,
    pow_int,
    pow,
    sin,
    cos,
    tan,
    exp,
    log,
    abs,
    asin,
    acos,
    atan,
    sinh,
    cosh,
    tanh,
    sqrt
  };
  struct Instr {
    Op op;
    double value = 0;  // constant; pow_int: the exponent
    int index = 0;     // input: which; add, mul: how many operands
  };
  std::vector<Instr> code_;
  std::size_t depth_ = 0;  // the stack depth it needs
  bool emit(const GiNaC::ex& e, const std::vector<GiNaC::ex>& inputs, std::string& problem, std::size_t& depth);
};

}  // namespace tackle

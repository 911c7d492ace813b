#include "numeric/compiled.hpp"

#include <cmath>

#include "expr/print.hpp"

namespace tackle {

using namespace GiNaC;

std::optional<Compiled> Compiled::compile(const ex& e, const std::vector<ex>& inputs, std::string& problem) {
  Compiled c;
  std::size_t depth = 0;
  if (!c.emit(e, inputs, problem, depth)) return std::nullopt;
  return c;
}

bool Compiled::emit(const ex& e, const std::vector<ex>& inputs, std::string& problem, std::size_t& depth) {
  auto push = [&](Instr i) {
    code_.push_back(i);
    depth_ = std::max(depth_, depth);
  };
  if (is_a<numeric>(e)) {
    if (!ex_to<numeric>(e).is_real()) {
      problem = "the number " + to_text(e) + " is not real";
      return false;
    }
    ++depth;
    push({Op::constant, ex_to<numeric>(e).to_double(), 0});
    return true;
  }
  if (is_a<symbol>(e)) {
    for (std::size_t i = 0; i < inputs.size(); ++i)
      if (inputs[i].is_equal(e)) {
        ++depth;
        push({Op::input, 0, static_cast<int>(i)});
        return true;
      }
    problem = "it still contains " + to_text(e) + ", which has no value";
    return false;
  }
  if (is_a<constant>(e)) {
    const ex v = evalf(e);
    ++depth;
    push({Op::constant, ex_to<numeric>(v).to_double(), 0});
    return true;
  }
  if (is_a<add>(e) || is_a<mul>(e)) {
    const std::size_t before = depth;
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!emit(e.op(i), inputs, problem, depth)) return false;
    push({is_a<add>(e) ? Op::add : Op::mul, 0, static_cast<int>(e.nops())});
    depth = before + 1;
    return true;
  }
  if (is_a<power>(e)) {
    const ex& x = e.op(1);
    if (is_a<numeric>(x) && ex_to<numeric>(x).is_integer() && abs(ex_to<numeric>(x)) < 64) {
      if (!emit(e.op(0), inputs, problem, depth)) return false;
      push({Op::pow_int, ex_to<numeric>(x).to_double(), 0});
      return true;
    }
    if (x.is_equal(numeric(1, 2))) {
      if (!emit(e.op(0), inputs, problem, depth)) return false;
      push({Op::sqrt, 0, 0});
      return true;
    }
    if (!emit(e.op(0), inputs, problem, depth) || !emit(x, inputs, problem, depth)) return false;
    push({Op::pow, 0, 0});
    --depth;
    return true;
  }
  if (is_a<function>(e) && e.nops() == 1) {
    static const std::pair<const char*, Op> functions[] = {{"sin", Op::sin},   {"cos", Op::cos},   {"tan", Op::tan},
                                                           {"exp", Op::exp},   {"log", Op::log},   {"abs", Op::abs},
                                                           {"asin", Op::asin}, {"acos", Op::acos}, {"atan", Op::atan},
                                                           {"sinh", Op::sinh}, {"cosh", Op::cosh}, {"tanh", Op::tanh}};
    const std::string name = ex_to<function>(e).get_name();
    for (const auto& [n, op] : functions)
      if (name == n) {
        if (!emit(e.op(0), inputs, problem, depth)) return false;
        push({op, 0, 0});
        return true;
      }
  }
  problem = "tackle cannot evaluate " + to_text(e) + " numerically";
  return false;
}

double Compiled::operator()(const double* x) const {
  // Small stacks live on the machine stack; the code was checked when compiled.
  double local[64];
  std::vector<double> heap;
  double* s = local;
  if (depth_ + 1 > 64) {
    heap.resize(depth_ + 1);
    s = heap.data();
  }
  std::size_t top = 0;  // number of values on the stack
  for (const Instr& i : code_) {
    switch (i.op) {
      case Op::constant: s[top++] = i.value; break;
      case Op::input: s[top++] = x[i.index]; break;
      case Op::add: {
        double v = 0;
        for (int k = 0; k < i.index; ++k) v += s[--top];
        s[top++] = v;
        break;
      }
      case Op::mul: {
        double v = 1;
        for (int k = 0; k < i.index; ++k) v *= s[--top];
        s[top++] = v;
        break;
      }
      case Op::pow_int: {
        const double b = s[top - 1];
        const int n = static_cast<int>(i.value);
        double v = 1;
        for (int k = 0; k < std::abs(n); ++k) v *= b;
        s[top - 1] = n < 0 ? 1 / v : v;
        break;
      }
      case Op::pow: {
        const double xp = s[--top];
        s[top - 1] = std::pow(s[top - 1], xp);
        break;
      }
      case Op::sqrt: s[top - 1] = std::sqrt(s[top - 1]); break;
      case Op::sin: s[top - 1] = std::sin(s[top - 1]); break;
      case Op::cos: s[top - 1] = std::cos(s[top - 1]); break;
      case Op::tan: s[top - 1] = std::tan(s[top - 1]); break;
      case Op::exp: s[top - 1] = std::exp(s[top - 1]); break;
      case Op::log: s[top - 1] = std::log(s[top - 1]); break;
      case Op::abs: s[top - 1] = std::fabs(s[top - 1]); break;
      case Op::asin: s[top - 1] = std::asin(s[top - 1]); break;
      case Op::acos: s[top - 1] = std::acos(s[top - 1]); break;
      case Op::atan: s[top - 1] = std::atan(s[top - 1]); break;
      case Op::sinh: s[top - 1] = std::sinh(s[top - 1]); break;
      case Op::cosh: s[top - 1] = std::cosh(s[top - 1]); break;
      case Op::tanh: s[top - 1] = std::tanh(s[top - 1]); break;
    }
  }
  return s[0];
}

}  // namespace tackle

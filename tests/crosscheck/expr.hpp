// The cross-check's own reading of a description's expressions: a small recursive-descent
// compiler from text to a tree, evaluated in any scalar type (double, or the dual numbers
// below for exact first and second derivatives). It shares nothing with tackle's parser or
// GiNaC: the numeric model must not inherit a mistake from the symbolic side.
//
// Grammar (the description's): sum := product (('+'|'-') product)*, product := unary
// (('*'|'/') unary)*, unary := ('+'|'-') unary | power, power := primary ('^' unary)?,
// primary := number | name | name '(' sum ')' | '(' sum ')'. Functions: sqrt abs sin cos tan
// exp log, dot(q) and ddot(q) (names of their own); `pi` is the constant.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace crosscheck {

/// A dual number a + b eps with eps^2 = 0: b carries a directional derivative. Nested
/// (Dual<Dual<double>>) it carries the second derivative along one direction.
inline double value_of(double x) { return x; }
template <class T>
struct Dual;
template <class T>
double value_of(const Dual<T>& x);
template <class T>
struct Dual {
  T a{}, b{};
  Dual() = default;
  Dual(double x) : a(x), b(0.0) {}  // NOLINT: numbers mix with duals
  Dual(T x, T y) : a(x), b(y) {}
};
template <class T>
Dual<T> operator+(const Dual<T>& x, const Dual<T>& y) {
  return {x.a + y.a, x.b + y.b};
}
template <class T>
Dual<T> operator-(const Dual<T>& x, const Dual<T>& y) {
  return {x.a - y.a, x.b - y.b};
}
template <class T>
Dual<T> operator-(const Dual<T>& x) {
  return {-x.a, -x.b};
}
template <class T>
Dual<T> operator*(const Dual<T>& x, const Dual<T>& y) {
  return {x.a * y.a, x.a * y.b + x.b * y.a};
}
template <class T>
Dual<T> operator/(const Dual<T>& x, const Dual<T>& y) {
  return {x.a / y.a, (x.b * y.a - x.a * y.b) / (y.a * y.a)};
}
template <class T>
Dual<T>& operator+=(Dual<T>& x, const Dual<T>& y) {
  return x = x + y;
}
template <class T>
Dual<T>& operator-=(Dual<T>& x, const Dual<T>& y) {
  return x = x - y;
}
template <class T>
Dual<T>& operator*=(Dual<T>& x, const Dual<T>& y) {
  return x = x * y;
}
template <class T>
Dual<T> sqrt(const Dual<T>& x) {
  using std::sqrt;
  T s = sqrt(x.a);
  return {s, x.b / (s * T(2.0))};
}
template <class T>
Dual<T> sin(const Dual<T>& x) {
  using std::sin;
  using std::cos;
  return {sin(x.a), x.b * cos(x.a)};
}
template <class T>
Dual<T> cos(const Dual<T>& x) {
  using std::sin;
  using std::cos;
  return {cos(x.a), -(x.b * sin(x.a))};
}
template <class T>
Dual<T> tan(const Dual<T>& x) {
  using std::cos;
  using std::tan;
  T c = cos(x.a);
  return {tan(x.a), x.b / (c * c)};
}
template <class T>
Dual<T> exp(const Dual<T>& x) {
  using std::exp;
  T e = exp(x.a);
  return {e, x.b * e};
}
template <class T>
Dual<T> log(const Dual<T>& x) {
  using std::log;
  return {log(x.a), x.b / x.a};
}
template <class T>
double value_of(const Dual<T>& x) {
  return value_of(x.a);
}
template <class T>
Dual<T> abs(const Dual<T>& x) {
  return value_of(x) < 0 ? -x : x;
}

using D1 = Dual<double>;
using D2 = Dual<D1>;

/// A compiled expression: a tree over numbers and variable slots.
class Expr {
 public:
  Expr() = default;
  /// Compiles `text`; `slot` maps a name (also `dot(x)`) to its variable index, or -1 when the
  /// name is unknown (an error naming it). Throws std::runtime_error on bad input.
  static Expr compile(const std::string& text, const std::function<int(const std::string&)>& slot);
  static Expr constant(double v);

  template <class S>
  [[nodiscard]] S eval(const std::vector<S>& vars) const {
    return eval_node<S>(root_.get(), vars);
  }
  [[nodiscard]] bool valid() const { return root_ != nullptr; }
  /// Whether the expression reads variable `slot`.
  [[nodiscard]] bool uses(int slot) const;
  /// The size of its terms, for "near 0": sums and differences add their parts' sizes
  /// (|a| + |b|, so that a sum that cancels keeps the size of what cancelled), products and
  /// quotients multiply and divide them, anything else is its value's size.
  [[nodiscard]] double magnitude(const std::vector<double>& vars) const;
  /// Every expression it divides by (a quotient's denominator, the base of a negative power).
  [[nodiscard]] std::vector<Expr> divisors() const;

  struct Node {
    enum Kind { num, var, neg, add, sub, mul, div, pow, ipow, fsqrt, fabs, fsin, fcos, ftan, fexp, flog } kind;
    double value = 0;
    int slot = -1;
    int exponent = 0;
    std::shared_ptr<const Node> l, r;
  };

 private:
  std::shared_ptr<const Node> root_;
  template <class S>
  static S eval_node(const Node* n, const std::vector<S>& v) {
    using std::sqrt;
    using std::sin;
    using std::cos;
    using std::tan;
    using std::exp;
    using std::log;
    using std::abs;
    switch (n->kind) {
      case Node::num: return S(n->value);
      case Node::var: return v[static_cast<std::size_t>(n->slot)];
      case Node::neg: return -eval_node<S>(n->l.get(), v);
      case Node::add: return eval_node<S>(n->l.get(), v) + eval_node<S>(n->r.get(), v);
      case Node::sub: return eval_node<S>(n->l.get(), v) - eval_node<S>(n->r.get(), v);
      case Node::mul: return eval_node<S>(n->l.get(), v) * eval_node<S>(n->r.get(), v);
      case Node::div: return eval_node<S>(n->l.get(), v) / eval_node<S>(n->r.get(), v);
      case Node::ipow: {
        S base = eval_node<S>(n->l.get(), v);
        int e = n->exponent < 0 ? -n->exponent : n->exponent;
        S out(1.0);
        for (int i = 0; i < e; ++i) out = out * base;
        return n->exponent < 0 ? S(1.0) / out : out;
      }
      case Node::pow: return exp(eval_node<S>(n->r.get(), v) * log(eval_node<S>(n->l.get(), v)));
      case Node::fsqrt: return sqrt(eval_node<S>(n->l.get(), v));
      case Node::fabs: return abs(eval_node<S>(n->l.get(), v));
      case Node::fsin: return sin(eval_node<S>(n->l.get(), v));
      case Node::fcos: return cos(eval_node<S>(n->l.get(), v));
      case Node::ftan: return tan(eval_node<S>(n->l.get(), v));
      case Node::fexp: return exp(eval_node<S>(n->l.get(), v));
      case Node::flog: return log(eval_node<S>(n->l.get(), v));
    }
    throw std::logic_error("expression node");
  }
};

/// `text` evaluated with `values` by name (`pi` the number unless named there); nothing when
/// it does not read or names something that is not there, or that `usable` refuses.
[[nodiscard]] std::optional<double> evaluate_text(const std::string& text, const std::map<std::string, double>& values,
                                                  const std::function<bool(const std::string&)>& usable = {});

}  // namespace crosscheck

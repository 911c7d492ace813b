#include "algebra/program.hpp"

#include <cmath>

#include <cln/complex.h>
#include <cln/float.h>
#include <cln/integer.h>
#include <cln/integer_ring.h>
#include <cln/rational.h>
#include <cln/rational_ring.h>
#include <cln/real.h>
#include <cln/real_ring.h>

namespace tackle {

using namespace GiNaC;

namespace {

// Numbers the evaluator keeps working with: at most this many bits in a rational's
// numerator and denominator, or in a float's binary exponent. Past that an answer is not
// decided by numbers (found by fuzzing: 98355^(.3^2.3^5^355.32)^h made CLN build an integer
// of 10^16 digits).
constexpr long max_bits = 8192;

// In CLN's own reals: the evaluator works with them, not with GiNaC's numeric objects.
long bits_of(const cln::cl_R& v) {
  if (cln::zerop(v)) return 0;
  // (What numer().int_length() and denom().int_length() say, without making either.)
  if (cln:: instanceof (v, cln::cl_I_ring)) return std::max<long>(cln::integer_length(cln::the<cln::cl_I>(v)), 1);
  if (cln:: instanceof (v, cln::cl_RA_ring)) {
    const cln::cl_RA& q = cln::the<cln::cl_RA>(v);
    return std::max<long>(cln::integer_length(cln::numerator(q)), cln::integer_length(cln::denominator(q)));
  }
  return std::labs(cln::float_exponent(cln::the<cln::cl_F>(v)));
}

bool integral(const cln::cl_R& v) { return cln:: instanceof (v, cln::cl_I_ring); }

std::optional<cln::cl_R> real_of(const numeric& v) {
  if (!v.is_real()) return std::nullopt;
  return cln::the<cln::cl_R>(v.to_cl_N());
}

bool is_trig(unsigned serial) {
  return serial == sin_SERIAL::serial || serial == cos_SERIAL::serial || serial == tan_SERIAL::serial;
}

}  // namespace

numeric angle_of(const numeric& t) { return numeric(2) * ex_to<numeric>(evalf(atan(t))); }

numeric half_tangent(double angle) {
  const double t = std::tan(angle / 2);
  return numeric(std::llround(t * 1e12), 1000000000000LL);
}

Program::Program(const ex& e, const Sample& layout, const exmap& definitions, const std::vector<bool>& angles) {
  emit(e, layout, definitions, angles, 0);
  for (Node& node : nodes_)
    if (node.op == Op::number) node.approx = cln::double_approx(node.number);
}

std::vector<double> doubles_of(const Sample& point) {
  std::vector<double> out;
  out.reserve(point.size());
  for (const auto& [symbol, value] : point) out.push_back(value.is_real() ? value.to_double() : std::nan(""));
  return out;
}

double Program::approx(const std::vector<double>& point, bool sin_cos_swapped) const {
  if (nodes_.empty()) return std::nan("");
  std::size_t at = 0;
  return run_double(at, point, sin_cos_swapped);
}

// The node at `at` and what follows it, in doubles (NaN for nothing); `at` moves past them
// always (a NaN operand does not stop the walk: the value is NaN anyway).
double Program::run_double(std::size_t& at, const std::vector<double>& point, bool swapped) const {
  const Node& node = nodes_[at++];
  switch (node.op) {
    case Op::number: return node.approx;
    case Op::input: return point[node.index];
    case Op::angle: return 2 * std::atan(point[node.index]);
    case Op::nothing: return std::nan("");
    case Op::add:
    case Op::mul: {
      const bool sum = node.op == Op::add;
      double out = sum ? 0 : 1;
      for (std::size_t i = 0; i < node.n; ++i) {
        const double v = run_double(at, point, swapped);
        out = sum ? out + v : out * v;
      }
      return out;
    }
    case Op::power: {
      const double b = run_double(at, point, swapped), x = run_double(at, point, swapped);
      if (b == 0 && x <= 0) return std::nan("");
      return x == 0.5 ? std::sqrt(b) : std::pow(b, x);
    }
    case Op::function: {
      const double a = run_double(at, point, swapped);
      if (node.serial == abs_SERIAL::serial) return std::fabs(a);
      if (node.serial == csgn_SERIAL::serial) return a > 0 ? 1.0 : a < 0 ? -1.0 : 0.0;
      if (node.serial == exp_SERIAL::serial) return std::exp(a);
      if (node.serial == log_SERIAL::serial) return a > 0 ? std::log(a) : std::nan("");
      if (node.serial == sin_SERIAL::serial) return swapped ? std::cos(a) : std::sin(a);
      if (node.serial == cos_SERIAL::serial) return swapped ? std::sin(a) : std::cos(a);
      if (node.serial == tan_SERIAL::serial) return std::tan(a);
      if (node.serial == asin_SERIAL::serial) return std::asin(a);
      if (node.serial == acos_SERIAL::serial) return std::acos(a);
      if (node.serial == atan_SERIAL::serial) return std::atan(a);
      if (node.serial == sinh_SERIAL::serial) return std::sinh(a);
      if (node.serial == cosh_SERIAL::serial) return std::cosh(a);
      if (node.serial == tanh_SERIAL::serial) return std::tanh(a);
      return std::nan("");  // another function: no screen (the exact evaluation decides)
    }
    case Op::trig: {
      double angle = node.multiple * std::acos(0.0);  // the quarter turns
      for (std::size_t k = 0; k < node.n; ++k) {
        const Node& pair = nodes_[at++];
        angle += static_cast<double>(pair.multiple) * 2 * std::atan(point[pair.index]);
      }
      if (node.serial == sin_SERIAL::serial) return swapped ? std::cos(angle) : std::sin(angle);
      if (node.serial == cos_SERIAL::serial) return swapped ? std::sin(angle) : std::cos(angle);
      return std::tan(angle);
    }
  }
  return std::nan("");
}

void Program::emit(const ex& e, const Sample& layout, const exmap& definitions, const std::vector<bool>& angles,
                   int depth) {
  if (is_exactly<numeric>(e)) {
    if (const auto v = real_of(ex_to<numeric>(e)))
      nodes_.push_back({Op::number, *v});
    else
      nodes_.push_back({Op::nothing, 0});
    return;
  }
  if (is_exactly<constant>(e)) {  // pi in an answer: a float at the current Digits
    if (const ex v = evalf(e); is_exactly<numeric>(v))
      if (const auto r = real_of(ex_to<numeric>(v))) {
        nodes_.push_back({Op::number, *r});
        return;
      }
    nodes_.push_back({Op::nothing, 0});
    return;
  }
  if (is_exactly<symbol>(e)) {
    for (std::size_t i = 0; i < layout.size(); ++i)
      if (layout[i].first.is_equal(e)) {
        nodes_.push_back({i < angles.size() && angles[i] ? Op::angle : Op::input, 0, i});
        return;
      }
    if (const auto d = definitions.find(e); d != definitions.end() && depth < 8)
      emit(d->second, layout, definitions, angles, depth + 1);
    else
      nodes_.push_back({Op::nothing, 0});
    return;
  }
  if (is_exactly<add>(e) || is_exactly<mul>(e)) {
    nodes_.push_back({is_exactly<add>(e) ? Op::add : Op::mul, 0, 0, 0, e.nops()});
    for (std::size_t i = 0; i < e.nops(); ++i) emit(e.op(i), layout, definitions, angles, depth);
    return;
  }
  if (is_exactly<power>(e)) {
    nodes_.push_back({Op::power, 0});
    emit(e.op(0), layout, definitions, angles, depth);
    emit(e.op(1), layout, definitions, angles, depth);
    return;
  }
  if (is_exactly<function>(e) && e.nops() == 1) {
    if (emit_trig(e, layout, angles)) return;
    nodes_.push_back({Op::function, 0, 0, ex_to<function>(e).get_serial()});
    emit(e.op(0), layout, definitions, angles, depth);
    return;
  }
  nodes_.push_back({Op::nothing, 0});
}

// A value while evaluating: exact as a fraction n/d (d > 0) not put in lowest terms (a
// rational's product and sum in CLN take gcds at every step, most of an evaluation's time;
// they are taken here only when a value grows past the bound, and once at the end), or a
// CLN float after a fractional power or a function.
struct Program::Value {
  bool exact = true;
  cln::cl_I n = 0, d = 1;
  cln::cl_R f;

  void set(const cln::cl_R& v) {
    exact = cln:: instanceof (v, cln::cl_RA_ring);
    if (exact) {
      const cln::cl_RA& q = cln::the<cln::cl_RA>(v);
      n = cln::numerator(q);
      d = cln::denominator(q);
    } else {
      f = v;
    }
  }
  [[nodiscard]] cln::cl_R real() const {
    if (!exact) return f;
    if (d == 1) return n;
    return cln::cl_RA(n) / cln::cl_RA(d);
  }
  void reduce() {
    const cln::cl_I g = cln::gcd(n, d);
    if (g != 1) {
      n = cln::exquo(n, g);
      d = cln::exquo(d, g);
    }
  }
  // Past the bound on bits (in lowest terms)?
  bool too_large() {
    if (!exact) return bits_of(f) > max_bits;
    const auto over = [&] { return cln::integer_length(n) > max_bits || cln::integer_length(d) > max_bits; };
    if (!over()) return false;
    reduce();
    return over();
  }
};

std::optional<numeric> Program::operator()(const Sample& point) const {
  if (nodes_.empty()) return std::nullopt;
  try {
    std::size_t at = 0;
    Value v;
    if (run(at, point, v)) return numeric(v.real());
  } catch (const std::bad_alloc&) {
    throw;  // out of memory is the process's (exit 3), not this number's
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// sin, cos or tan of whole multiples of angle inputs plus a multiple of pi/2: a trig node, then
// one angle node per angle (its input, and its multiple). False (nothing emitted) otherwise.
bool Program::emit_trig(const ex& e, const Sample& layout, const std::vector<bool>& angles) {
  const unsigned serial = ex_to<function>(e).get_serial();
  if (!is_trig(serial)) return false;
  const ex arg = e.op(0).expand();
  std::vector<std::pair<std::size_t, long>> multiples;
  numeric of_pi = 0;
  auto term = [&](const ex& t) {
    numeric c = 1;
    ex rest = t;
    if (is_exactly<mul>(t) && t.nops() == 2 && is_exactly<numeric>(t.op(1))) {
      c = ex_to<numeric>(t.op(1));
      rest = t.op(0);
    }
    if (!c.is_integer() && !rest.is_equal(Pi)) return false;
    if (rest.is_equal(Pi)) {
      of_pi += c;
      return true;
    }
    for (std::size_t i = 0; i < layout.size(); ++i)
      if (i < angles.size() && angles[i] && layout[i].first.is_equal(rest)) {
        if (c.int_length() > 16) return false;
        multiples.emplace_back(i, c.to_long());
        return true;
      }
    return false;
  };
  bool ok = true;
  if (is_exactly<add>(arg)) {
    for (const auto& t : arg) ok = ok && term(t);
  } else {
    ok = term(arg);
  }
  const numeric quarters = of_pi * 2;
  if (!ok || multiples.empty() || !quarters.is_integer()) return false;
  nodes_.push_back({Op::trig, 0, 0, serial, multiples.size(), mod(quarters, numeric(4)).to_long()});
  for (const auto& [i, k] : multiples) nodes_.push_back({Op::angle, 0, i, 0, 0, k});
  return true;
}

// The node at `at` and what follows it into `out`; `at` moves past them (false, for nothing,
// leaves it anywhere: the caller gives up too). Exact rationals as long as the operations
// allow; a fractional power or a function is evaluated by GiNaC in CLN floats at the current
// Digits.
bool Program::run(std::size_t& at, const Sample& point, Value& out) const {
  const Node& node = nodes_[at++];
  switch (node.op) {
    case Op::number: out.set(node.number); return true;
    case Op::input: {
      const auto v = real_of(point[node.index].second);
      if (!v) return false;
      out.set(*v);
      return true;
    }
    case Op::angle: {  // the angle itself, not under a sine: 2 atan(t), a float
      const auto t = real_of(point[node.index].second);
      if (!t) return false;
      out.set(cln::the<cln::cl_R>(angle_of(numeric(*t)).to_cl_N()));
      return true;
    }
    case Op::nothing: return false;
    case Op::add:
    case Op::mul: {
      const bool sum = node.op == Op::add;
      out.exact = true;
      out.n = sum ? 0 : 1;
      out.d = 1;
      Value v;
      for (std::size_t i = 0; i < node.n; ++i) {
        if (!run(at, point, v)) return false;
        if (out.exact && v.exact) {
          if (!sum) {
            out.n = out.n * v.n;
            out.d = out.d * v.d;
          } else if (out.d == v.d) {
            out.n = out.n + v.n;
          } else {
            out.n = out.n * v.d + v.n * out.d;
            out.d = out.d * v.d;
          }
        } else if (out.exact || v.exact) {
          // A float and a fraction: the fraction enters as n and d (CLN would reduce it first).
          const Value& q = out.exact ? out : v;
          const cln::cl_R& f = out.exact ? v.f : out.f;
          const cln::cl_R r = sum ? f * q.d + q.n : f * q.n;
          out.set(q.d == 1 ? r : r / q.d);
        } else {
          out.set(sum ? out.f + v.f : out.f * v.f);
        }
        if (out.too_large()) return false;
      }
      return true;
    }
    case Op::power: return run_power(at, point, out);
    case Op::function: return run_function(node, at, point, out);
    case Op::trig: return run_trig(node, at, point, out);
  }
  return false;
}

// A power: exact for a fraction to a whole power, or a perfect power to a fractional one.
bool Program::run_power(std::size_t& at, const Sample& point, Value& out) const {
  Value b, x;
  if (!run(at, point, b) || !run(at, point, x)) return false;
  if (b.exact && x.exact && x.d == 1) {  // a fraction to a whole power (most powers)
    if (cln::integer_length(x.n) > 62) return false;
    const long k = cln::cl_I_to_long(x.n);
    const unsigned long m = static_cast<unsigned long>(k < 0 ? -k : k);
    if (cln::zerop(b.n)) {
      if (k <= 0) return false;  // 0^0, or a division by zero
      out.set(0);
      return true;
    }
    // The result's size in bits is about |k| * log2|base|: bound it before making it.
    const auto bits = [&] {
      return static_cast<double>(m) *
             static_cast<double>(std::max(cln::integer_length(b.n), cln::integer_length(b.d)) + 1);
    };
    if (bits() > max_bits) {
      b.reduce();
      if (bits() > max_bits) return false;
    }
    out.exact = true;
    if (m == 0) {
      out.n = 1;
      out.d = 1;
    } else if (k > 0) {
      out.n = cln::expt_pos(b.n, m);
      out.d = cln::expt_pos(b.d, m);
    } else {
      const bool negative = cln::minusp(b.n);
      out.n = cln::expt_pos(b.d, m);
      out.d = cln::expt_pos(negative ? cln::cl_I(-b.n) : b.n, m);
      if (negative && (m & 1)) out.n = -out.n;
    }
    return true;
  }
  const cln::cl_R base = b.real(), expo = x.real();
  const bool whole = integral(expo);
  if (cln::zerop(base) && !(whole && cln::plusp(expo))) return false;
  if (!whole && cln::minusp(base)) return false;  // complex
  // The result's size in bits is about |expo| * log2|base|: bound it before making it.
  if (bits_of(expo) > 62 || std::fabs(cln::double_approx(expo)) * static_cast<double>(bits_of(base) + 1) > max_bits)
    return false;
  if (whole) {
    out.set(cln::expt(base, cln::the<cln::cl_I>(expo)));
    return true;
  }
  // A rational power of a rational: exact when the base is a perfect power (sqrt(m^2) at a
  // point), else in floats at the current Digits, as evalf() would make it.
  if (cln:: instanceof (base, cln::cl_RA_ring) && cln:: instanceof (expo, cln::cl_RA_ring)) {
    const cln::cl_RA& q = cln::the<cln::cl_RA>(expo);
    cln::cl_RA root;
    if (cln::rootp(cln::the<cln::cl_RA>(base), cln::denominator(q), &root)) {
      out.set(cln::expt(root, cln::numerator(q)));
      return true;
    }
  }
  if (expo == cln::cl_RA(1) / 2) {  // a square root (base > 0 here): sqrt, not exp(log(base)/2)
    out.set(cln::sqrt(cln::cl_float(base, cln::default_float_format)));
    return true;
  }
  const cln::cl_N v = cln::expt(cln::cl_N(cln::cl_float(base, cln::default_float_format)), cln::cl_N(expo));
  if (!cln:: instanceof (v, cln::cl_R_ring)) return false;
  out.set(cln::the<cln::cl_R>(v));
  return true;
}

// abs and csgn exactly; any other function of one argument by GiNaC, in CLN floats.
bool Program::run_function(const Node& node, std::size_t& at, const Sample& point, Value& out) const {
  Value a;
  if (!run(at, point, a)) return false;
  // abs and csgn of a value: exact, and for any size (10^-30 in an argument is not too
  // large to take a sign of).
  if (node.serial == abs_SERIAL::serial || node.serial == csgn_SERIAL::serial) {
    const bool negative = a.exact ? cln::minusp(a.n) : cln::minusp(a.f);
    if (node.serial == csgn_SERIAL::serial) {
      out.set(cln::cl_I(negative ? -1 : (a.exact ? cln::zerop(a.n) : cln::zerop(a.f)) ? 0 : 1));
    } else {
      out = a;
      if (negative && out.exact) out.n = -out.n;
      if (negative && !out.exact) out.f = -out.f;
    }
    return true;
  }
  const cln::cl_R arg = a.real();
  if (bits_of(arg) > 62) return false;  // sin(10^30) says nothing; exp of it is huge
  if (node.serial == exp_SERIAL::serial && std::fabs(cln::double_approx(arg)) > 5000) return false;
  const ex v = evalf(function(node.serial, ex(numeric(arg))));
  if (!is_exactly<numeric>(v)) return false;
  const auto r = real_of(ex_to<numeric>(v));
  if (!r) return false;
  out.set(*r);
  return true;
}

// e^(i arg) exactly: each angle's (1 + i t)^2 / (1 + t^2) to its multiple, times i per
// quarter turn; then its imaginary part (sin), real part (cos) or their quotient (tan).
bool Program::run_trig(const Node& node, std::size_t& at, const Sample& point, Value& out) const {
  if (node.n == 1 && (nodes_[at].multiple == 1 || nodes_[at].multiple == -1)) {
    // One angle, once (most of them): cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2), as a
    // fraction kept unreduced; a quarter turn added takes (cos, sin) to (-sin, cos).
    const Node& angle = nodes_[at++];
    const auto t = real_of(point[angle.index].second);
    if (!t || !cln:: instanceof (*t, cln::cl_RA_ring)) {
      --at;
    } else {
      const cln::cl_RA& q = cln::the<cln::cl_RA>(*t);
      const cln::cl_I n = cln::numerator(q), d = cln::denominator(q), nn = n * n, dd = d * d;
      cln::cl_I sine = 2 * n * d * angle.multiple, cosine = dd - nn;
      const cln::cl_I both = dd + nn;
      for (long k = 0; k < node.multiple; ++k) {
        const cln::cl_I turned = -sine;
        sine = cosine;
        cosine = turned;
      }
      out.exact = true;
      if (node.serial == sin_SERIAL::serial) {
        out.n = sine;
        out.d = both;
      } else if (node.serial == cos_SERIAL::serial) {
        out.n = cosine;
        out.d = both;
      } else {
        if (cln::zerop(cosine)) return false;
        out.n = cln::minusp(cosine) ? cln::cl_I(-sine) : sine;
        out.d = cln::abs(cosine);
      }
      return true;
    }
  }
  cln::cl_N z = 1;
  long bits = 0;
  for (std::size_t k = 0; k < node.n; ++k) {
    const Node& angle = nodes_[at++];
    const auto t = real_of(point[angle.index].second);
    if (!t) return false;
    const long m = angle.multiple < 0 ? -angle.multiple : angle.multiple;
    bits += (2 * m + 1) * (bits_of(*t) + 1);
    if (bits > max_bits) return false;
    cln::cl_N unit = cln::expt(cln::complex(cln::cl_R(1), *t), 2) / (1 + *t * *t);
    if (angle.multiple < 0) unit = cln::conjugate(unit);
    z = z * cln::expt(unit, cln::cl_I(m));
  }
  static const cln::cl_N turns[4] = {1, cln::complex(0, 1), -1, cln::complex(0, -1)};
  z = z * turns[node.multiple];
  const cln::cl_R re = cln::realpart(z), im = cln::imagpart(z);
  if (node.serial == sin_SERIAL::serial)
    out.set(im);
  else if (node.serial == cos_SERIAL::serial)
    out.set(re);
  else if (cln::zerop(re))
    return false;
  else
    out.set(im / re);
  return true;
}

}  // namespace tackle

#include "expr/normal_form.hpp"
#include "expr/rational.hpp"

namespace tackle {

using namespace GiNaC;

NormalForm::NormalForm(const ex& e) {
  const ex nd = numer_denom_remembered(e);
  num = nd.op(0);
  den = nd.op(1);
}

namespace {

// True when an exact number has a pole inside it that exact arithmetic does not see: a
// denominator such as sqrt(20) - 2*sqrt(5) (zero, though GiNaC keeps it unevaluated), or log
// or tan at such a point. evalf() would throw there from inside a new node, which leaks
// (found by fuzzing). Inner parts are checked first, so that evaluating a part never meets a
// pole of its own.
bool has_hidden_pole(const ex& e) {
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_hidden_pole(e.op(i))) return true;
  // Zero, or a sum whose terms cancel to within rounding (relative to their sizes).
  auto near_zero = [](const ex& x) {
    const ex v = evalf(x);
    if (!is_a<numeric>(v)) return false;
    const numeric size = abs(ex_to<numeric>(v));
    if (size.is_zero()) return true;
    if (!is_a<add>(x)) return false;
    numeric terms = 0;
    for (std::size_t i = 0; i < x.nops(); ++i) {
      const ex t = evalf(x.op(i));
      if (!is_a<numeric>(t)) return false;
      terms += abs(ex_to<numeric>(t));
    }
    return size < terms * numeric(1, 1000000000000LL);
  };
  if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_negative()) return near_zero(e.op(0));
  if (is_ex_the_function(e, log)) return near_zero(e.op(0));
  if (is_ex_the_function(e, tan)) return near_zero(cos(e.op(0)));
  return false;
}

}  // namespace

namespace {

// Rational numbers (and symbols, when allowed) under +, * and integer powers only.
bool rational_over(const ex& e, bool symbols) {
  if (is_a<numeric>(e)) return ex_to<numeric>(e).is_rational();
  if (is_a<symbol>(e)) return symbols;
  if (is_a<power>(e)) return e.op(1).info(info_flags::integer) && rational_over(e.op(0), symbols);
  if (is_a<add>(e) || is_a<mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i)
      if (!rational_over(e.op(i), symbols)) return false;
    return true;
  }
  return false;
}

}  // namespace

bool is_rational_number(const ex& e) { return rational_over(e, false); }
bool is_rational_function(const ex& e) { return rational_over(e, true); }

bool has_pole_at(const ex& e, const exmap& values) {
  const ex v = substituted(e, values);
  return has_hidden_pole(v);
}

bool NormalForm::undefined_at(const exmap& values) const { return !denominator_at(values); }

std::optional<ex> NormalForm::denominator_at(const exmap& values) const {
  const ex ds = substituted(den, values);
  // Exact arithmetic decides a rational number; with radicals in it, normal() is costly and
  // not a zero test anyway: the numeric look for a cancelling sum decides.
  const bool rational = is_rational_number(ds);
  const ex d = rational ? normal(ds) : ds;
  if (d.is_zero() || has_hidden_pole(d) || (!rational && has_hidden_pole(1 / d)) ||
      has_hidden_pole(substituted(num, values)))
    return std::nullopt;
  return d;
}

std::optional<ex> NormalForm::at(const exmap& values) const {
  const auto d = denominator_at(values);
  if (!d) return std::nullopt;
  const ex v = normal(substituted(num, values) / *d);
  for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
    if (is_a<symbol>(*it)) return std::nullopt;
  return v;
}

std::optional<double> NormalForm::approx_at(const exmap& values) const {
  const auto d = denominator_at(values);
  if (!d) return std::nullopt;
  const ex v = evalf(substituted(num, values)) / evalf(*d);
  if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nullopt;
  return ex_to<numeric>(v).to_double();
}

}  // namespace tackle

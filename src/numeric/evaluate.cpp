#include "numeric/evaluate.hpp"

#include "expr/rational.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <cln/integer.h>
#include <cln/real.h>

namespace tackle {

using namespace GiNaC;

namespace {

// Exact decimal digits of a terminating rational with at most `max_digits` significant
// digits, or "" when it does not terminate within them.
std::string terminating(const numeric& v, int max_digits) {
  numeric scaled = abs(v);
  int k = 0;
  while (!scaled.is_integer() && k < max_digits) {
    scaled *= 10;
    ++k;
  }
  if (!scaled.is_integer()) return {};
  std::ostringstream os;
  os << scaled;
  std::string s = os.str();
  if (static_cast<int>(s.size()) > std::max(max_digits, k + 1)) return {};
  if (k > 0) {
    while (static_cast<int>(s.size()) <= k) s = "0" + s;
    s.insert(s.size() - k, ".");
  }
  return (v.is_negative() ? "-" : "") + s;
}

// |v| rounded to `digits` significant digits as (digit string, decimal exponent of the first
// digit), computed in exact or CLN float arithmetic at enough precision.
std::pair<std::string, long> significant(const numeric& v, int digits) {
  const long saved = GiNaC::Digits;
  GiNaC::Digits = std::max<long>(saved, digits + 20);
  const numeric a = abs(v);
  // The exponent of the first digit: from the double when it is in range, then corrected.
  long e = static_cast<long>(std::floor(std::log10(a.to_double())));
  auto scaled_by = [&](long exponent) { return ex_to<numeric>(evalf(a * pow(numeric(10), numeric(exponent)))); };
  numeric s = scaled_by(digits - 1 - e);
  const numeric low = pow(numeric(10), numeric(digits - 1)), high = pow(numeric(10), numeric(digits));
  if (s < low) {
    --e;
    s = scaled_by(digits - 1 - e);
  } else if (s >= high) {
    ++e;
    s = scaled_by(digits - 1 - e);
  }
  // Round half up to an integer (CLN: an exact integer, printed in full).
  const cln::cl_I rounded = cln::floor1(cln::the<cln::cl_R>(ex_to<numeric>(evalf(s + numeric(1, 2))).to_cl_N()));
  std::ostringstream os;
  os << numeric(rounded);
  std::string str = os.str();
  if (static_cast<int>(str.size()) > digits) {  // 9.99... rounded up to 10.0...
    ++e;
    str = str.substr(0, digits);
  }
  GiNaC::Digits = saved;
  return {str, e};
}

}  // namespace

std::string decimal_string(const numeric& v, int digits) {
  if (v.is_zero()) return "0";
  if (v.is_rational())
    if (std::string t = terminating(v, std::max(15, digits)); !t.empty()) return t;
  auto [mantissa, e] = significant(v, digits);
  // Plain notation for moderate exponents, else scientific.
  std::string out;
  if (e >= -5 && e < std::max(digits, 15)) {
    if (e >= 0) {
      std::string s = mantissa;
      while (static_cast<long>(s.size()) <= e) s += "0";
      out = s.substr(0, e + 1);
      std::string frac = s.substr(e + 1);
      while (!frac.empty() && frac.back() == '0') frac.pop_back();
      if (!frac.empty()) out += "." + frac;
    } else {
      std::string frac = std::string(-e - 1, '0') + mantissa;
      while (!frac.empty() && frac.back() == '0') frac.pop_back();
      out = "0." + frac;
    }
  } else {
    std::string frac = mantissa.substr(1);
    while (!frac.empty() && frac.back() == '0') frac.pop_back();
    out = mantissa.substr(0, 1) + (frac.empty() ? "" : "." + frac) + "e" + std::to_string(e);
  }
  return (v.is_negative() ? "-" : "") + out;
}

namespace {

// value_at with the rational values already made into a point (and the long sums' values
// there remembered, when given).
std::optional<ex> value_at(const ex& e, const exmap& values, const RationalPoint& point, SumValues* sums = nullptr) {
  // A rational function at rational numbers: computed as a number, without a normal form
  // (normal() of a closed form over 128 bodies' masses is most of a report's time). A pole
  // there may be removable, and roots or functions need more: those go through NormalForm.
  const RationalAt r = sums ? rational_at(e, point, *sums) : rational_at(e, point);
  if (r.kind == RationalAt::Kind::value) return ex(r.value);
  return NormalForm(e).at(values);
}

RationalPoint rational_values(const exmap& values) {
  RationalPoint point;
  for (const auto& [sym, v] : values)
    if (is_a<numeric>(v) && ex_to<numeric>(v).is_rational()) point.emplace(sym, ex_to<numeric>(v));
  return point;
}

std::optional<NumericValue> evaluate_at(const ex& e, const exmap& values, const RationalPoint& point, SumValues* sums,
                                        std::optional<Dimension> dimension, int digits,
                                        const std::optional<Unit>& unit) {
  // A closed form may be undefined at the given numbers (a denominator c - e with c = e):
  // no number then. The denominator is checked first, so that GiNaC does not throw from
  // inside a new object (found by fuzzing: exit 3 for a description with c = e).
  const auto at = value_at(e, values, point, sums);
  if (!at) return std::nullopt;
  const ex v = *at;
  for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
    if (is_a<symbol>(*it)) return std::nullopt;
  if (has_pole_at(v, {})) return std::nullopt;
  NumericValue out;
  out.si = v;
  ex shown = v;
  out.unit = dimension ? si_unit_name(*dimension) : "";
  if (unit) {
    shown = v / unit->to_si;
    out.unit = unit->text;
  }
  const long saved = GiNaC::Digits;
  GiNaC::Digits = std::max<long>(saved, digits + 20);
  const ex f = evalf(shown);
  GiNaC::Digits = saved;
  if (!is_a<numeric>(f) || !ex_to<numeric>(f).is_real()) return std::nullopt;
  out.approx = ex_to<numeric>(f).to_double();
  // The exact value in its lowest terms; with functions at numbers (sin(3/10) of an angle)
  // normal() would treat them as symbols whose order follows GiNaC's hashes, and the form
  // it chose (1/sqrt(x) or sqrt(1/x)) would too: such a value stays as substituted.
  bool functions = false;
  for (const_preorder_iterator it = shown.preorder_begin(); it != shown.preorder_end() && !functions; ++it)
    functions = is_a<function>(*it);
  ex exact_shown;
  if (functions) {
    // Substituted into the closed form as it is (deterministic), not through a normal form.
    ex plain = e;
    for (int depth = 0; depth < 8; ++depth) {
      const ex next = plain.subs(values);
      if (next.is_equal(plain)) break;
      plain = next;
    }
    bool symbols = false;
    for (const_preorder_iterator it = plain.preorder_begin(); it != plain.preorder_end() && !symbols; ++it)
      symbols = is_a<symbol>(*it);
    exact_shown = symbols ? shown : (unit ? plain / unit->to_si : plain);
  } else {
    exact_shown = normal(shown);
  }
  out.exact = exact_shown;
  out.decimal = is_a<numeric>(exact_shown) ? decimal_string(ex_to<numeric>(exact_shown), digits)
                                           : decimal_string(ex_to<numeric>(f), digits);
  return out;
}

}  // namespace

std::optional<ex> value_at(const ex& e, const exmap& values) { return value_at(e, values, rational_values(values)); }

std::optional<NumericValue> evaluate_with(const ex& e, const exmap& values, std::optional<Dimension> dimension,
                                          int digits, const std::optional<Unit>& unit) {
  return evaluate_at(e, values, rational_values(values), nullptr, dimension, digits, unit);
}

std::optional<NumericValue> evaluate(const ex& e, const SymbolTable& symbols, std::optional<Dimension> dimension,
                                     int digits, const std::optional<Unit>& unit) {
  const auto set = symbols.value_set();
  return evaluate_at(e, set->map, set->rational, &set->sums, dimension, digits, unit);
}

}  // namespace tackle

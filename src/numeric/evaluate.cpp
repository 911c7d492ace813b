#include "numeric/evaluate.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace tackle {

using namespace GiNaC;

std::string decimal_string(const numeric& v, int digits) {
  if (v.is_rational()) {
    // A terminating decimal of at most 15 digits is printed exactly.
    numeric scaled = abs(v);
    int k = 0;
    while (!scaled.is_integer() && k < 15) {
      scaled *= 10;
      ++k;
    }
    if (scaled.is_integer()) {
      std::ostringstream os;
      os << scaled;
      std::string s = os.str();
      if (s.size() <= 15) {
        if (k > 0) {
          while (static_cast<int>(s.size()) <= k) s = "0" + s;
          s.insert(s.size() - k, ".");
        }
        return (v.is_negative() ? "-" : "") + s;
      }
    }
  }
  return fmt::format("{:.{}g}", v.to_double(), digits);
}

std::optional<NumericValue> evaluate(const ex& e, const SymbolTable& symbols, std::optional<Dimension> dimension,
                                     int digits) {
  const ex v = normal(e.subs(symbols.values()));
  for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
    if (is_a<symbol>(*it)) return std::nullopt;
  const ex f = evalf(v);
  if (!is_a<numeric>(f) || !ex_to<numeric>(f).is_real()) return std::nullopt;
  NumericValue out;
  out.exact = v;
  out.approx = ex_to<numeric>(f).to_double();
  out.decimal = is_a<numeric>(v) ? decimal_string(ex_to<numeric>(v), digits) : decimal_string(ex_to<numeric>(f), digits);
  out.unit = dimension ? si_unit_name(*dimension) : "";
  return out;
}

}  // namespace tackle

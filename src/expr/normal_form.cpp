#include "expr/normal_form.hpp"

namespace tackle {

using namespace GiNaC;

NormalForm::NormalForm(const ex& e) {
  const ex nd = normal(e).numer_denom();
  num = nd.op(0);
  den = nd.op(1);
}

bool NormalForm::undefined_at(const exmap& values) const { return normal(den.subs(values)).is_zero(); }

std::optional<ex> NormalForm::at(const exmap& values) const {
  const ex d = normal(den.subs(values));
  if (d.is_zero()) return std::nullopt;
  const ex v = normal(num.subs(values) / d);
  for (const_preorder_iterator it = v.preorder_begin(); it != v.preorder_end(); ++it)
    if (is_a<symbol>(*it)) return std::nullopt;
  return v;
}

std::optional<double> NormalForm::approx_at(const exmap& values) const {
  const ex d = normal(den.subs(values));
  if (d.is_zero()) return std::nullopt;
  const ex v = evalf(num.subs(values) / d);
  if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return std::nullopt;
  return ex_to<numeric>(v).to_double();
}

}  // namespace tackle

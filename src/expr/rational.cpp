#include "expr/rational.hpp"

#include <unordered_map>

#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

using Memory = std::unordered_map<ex, ex, ExHash, ex_is_equal>;

}  // namespace

ex numer_denom_remembered(const ex& e) {
  thread_local Memory memory;
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  const ex nd = e.numer_denom();
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, nd);
  return nd;
}

ex normal_remembered(const ex& e) {
  thread_local Memory memory;
  if (is_a<numeric>(e) || is_a<symbol>(e)) return e;
  if (auto it = memory.find(e); it != memory.end()) return it->second;
  const ex n = normal(e);
  if (memory.size() >= 8192) memory.clear();
  memory.emplace(e, n);
  memory.emplace(n, n);
  return n;
}

ex numer_denom_of_normal(const ex& n) {
  ex num = 1, den = 1;
  auto take = [&](const ex& f) {
    if (is_a<numeric>(f)) {
      const numeric& c = ex_to<numeric>(f);
      if (c.is_rational()) {
        num *= c.numer();
        den *= c.denom();
        return;
      }
    } else if (is_a<power>(f) && is_a<numeric>(f.op(1)) && ex_to<numeric>(f.op(1)).is_negative()) {
      den *= pow(f.op(0), -f.op(1));
      return;
    }
    num *= f;
  };
  if (is_a<mul>(n))
    for (std::size_t i = 0; i < n.nops(); ++i) take(n.op(i));
  else
    take(n);
  return lst{num, den};
}

RationalAt rational_at(const ex& e, const RationalPoint& point) {
  using Kind = RationalAt::Kind;
  if (is_a<numeric>(e)) {
    const numeric& c = ex_to<numeric>(e);
    return c.is_rational() ? RationalAt{Kind::value, c} : RationalAt{};
  }
  if (is_a<symbol>(e)) {
    const auto it = point.find(e);
    return it == point.end() ? RationalAt{} : RationalAt{Kind::value, it->second};
  }
  if (is_a<add>(e) || is_a<mul>(e)) {
    const bool sum = is_a<add>(e);
    numeric acc = sum ? 0 : 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const RationalAt t = rational_at(e.op(i), point);
      if (t.kind != Kind::value) return t;
      acc = sum ? acc + t.value : acc * t.value;
    }
    return {Kind::value, acc};
  }
  if (is_a<power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_integer()) {
    const RationalAt b = rational_at(e.op(0), point);
    if (b.kind != Kind::value) return b;
    const numeric& x = ex_to<numeric>(e.op(1));
    if (b.value.is_zero() && x.is_negative()) return {Kind::pole, 0};
    return {Kind::value, pow(b.value, x)};
  }
  return {};
}

bool is_zero_exactly(const ex& e) {
  const ex n = normal(e);
  return n.is_zero() || (has_trig(n) && normal(pythagoras(n, true)).is_zero());
}

}  // namespace tackle

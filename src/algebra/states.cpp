#include "algebra/states.hpp"

#include <chrono>
#include <cmath>

namespace tackle {

using namespace GiNaC;

States::States(std::vector<StateInput> inputs) : inputs_(std::move(inputs)) {
  for (const auto& in : inputs_) {
    layout_.emplace_back(in.symbol, in.base ? *in.base : numeric(1));
    angles_.push_back(in.angle);
  }
}

// Near the base (between half and twice it, in steps of 1/fine of it), else between 1 and 10
// (an angle's t: 1/10 and 1) in steps of 1/fine.
numeric States::value(const StateInput& in, std::mt19937& rng, long fine) const {
  if (in.base) {
    std::uniform_int_distribution<long> spread(fine / 2, 2 * fine);
    return *in.base * numeric(spread(rng), fine);
  }
  // (The fixed points' whole values in tenths, as they have always been drawn.)
  const long step = fine == 1000 ? 10 : fine;
  std::uniform_int_distribution<long> whole(step, 10 * step);
  return numeric(whole(rng), in.angle ? 10 * step : step);
}

Sample States::fixed(int k) const {
  // The k-th of a sequence drawn from one seed (a point's values depend on those before it).
  std::mt19937 rng(12);
  Sample p = layout_;
  for (int j = 0; j <= k; ++j)
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      p[i].second = value(inputs_[i], rng, 1000);
      // (A shift by point: two parameters drawn alike still differ.)
      if (!inputs_[i].base && !inputs_[i].angle) p[i].second = p[i].second + numeric(1, 7 + j);
    }
  return p;
}

Sample States::draw(std::mt19937& rng) const {
  Sample p = layout_;
  for (std::size_t i = 0; i < inputs_.size(); ++i) p[i].second = value(inputs_[i], rng, 1000000);
  return p;
}

std::mt19937 States::generator(const std::optional<std::uint64_t>& seed) {
  std::mt19937 rng;
  if (seed) {
    std::seed_seq seq{static_cast<std::uint32_t>(*seed), static_cast<std::uint32_t>(*seed >> 32)};
    rng.seed(seq);
    return rng;
  }
  try {
    std::random_device device;
    std::seed_seq seq{device(), device(), device(), device()};
    rng.seed(seq);
  } catch (const std::exception&) {  // no entropy source: the clock, still not the student's to know
    const auto now = static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
    std::seed_seq seq{static_cast<std::uint32_t>(now), static_cast<std::uint32_t>(now >> 32)};
    rng.seed(seq);
  }
  return rng;
}

StateInput input_near(const ex& symbol, const std::optional<ex>& value, bool angle) {
  StateInput in{symbol, std::nullopt, angle};
  if (!value) return in;
  const ex f = evalf(*value);
  if (!is_a<numeric>(f) || f.is_zero() || !ex_to<numeric>(f).is_real()) return in;
  const double d = ex_to<numeric>(f).to_double();
  if (angle)
    in.base = half_tangent(d);
  else if (is_a<numeric>(*value) && ex_to<numeric>(*value).is_rational())
    in.base = ex_to<numeric>(*value);
  else
    in.base = numeric(std::llround(d * 1e6), 1000000);
  return in;
}

void angles_in(const ex& e, exset& out) {
  if (is_exactly<symbol>(e) || is_exactly<numeric>(e)) return;
  if (is_exactly<function>(e)) {
    const unsigned s = ex_to<function>(e).get_serial();
    if (s == sin_SERIAL::serial || s == cos_SERIAL::serial || s == tan_SERIAL::serial) {
      for (const_preorder_iterator i = e.op(0).preorder_begin(); i != e.op(0).preorder_end(); ++i)
        if (is_exactly<symbol>(*i)) out.insert(*i);
      return;
    }
  }
  for (std::size_t i = 0; i < e.nops(); ++i) angles_in(e.op(i), out);
}

}  // namespace tackle

// Deciding an answer that agrees with the closed form at the fixed points: proved or refuted
// by GiNaC where it can, else compared at points drawn for the check, on each side of every
// kink (abs(), csgn(), step()).
#include "check/check.hpp"
#include "check/internal.hpp"

#include <algorithm>
#include <set>

#include "expr/rational.hpp"
#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;
using namespace check_detail;

namespace {

// (x^2)^(1/2) is |x| and not x: an even power under a fractional one is a kink, and is
// written as one (|x|^(n r) for (x^n)^r, n even) so that both its sides are looked at.
struct EvenRootsAsAbs : map_function {
  static bool even_root(const ex& e) {
    if (!is_exactly<power>(e) || !is_exactly<power>(e.op(0)) || !is_exactly<numeric>(e.op(1)) ||
        !is_exactly<numeric>(e.op(0).op(1)))
      return false;
    const numeric& r = ex_to<numeric>(e.op(1));
    return ex_to<numeric>(e.op(0).op(1)).is_even() && r.is_rational() && !r.is_integer();
  }
  ex operator()(const ex& e) override {
    const ex m = e.map(*this);
    if (even_root(m)) return pow(abs(m.op(0).op(0)), ex_to<numeric>(m.op(0).op(1)) * ex_to<numeric>(m.op(1)));
    return m;
  }
  // `e` with its even roots as abs(); `e` itself (not rebuilt) when it has none.
  ex rewrite(const ex& e) {
    for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
      if (even_root(*it)) return (*this)(e);
    return e;
  }
};

constexpr std::size_t max_kinks = 4;  // arguments up to their sign: 16 combinations of signs

}  // namespace

Sample Checker::draw_point(std::mt19937& rng) const {
  // Finer than the fixed points (1.5 million values between half and twice each value): an
  // answer built to vanish at some values meets one of them by a chance of its degree over
  // that.
  return states_.draw(rng);
}

const std::vector<Sample>& Checker::FreshPoints::get() {
  if (points_) return *points_;
  Reference::Lazy& lazy = *ref_.lazy;
  const std::lock_guard<std::mutex> lock(lazy.fresh_mutex);
  Reference::Fresh& pool = lazy.fresh;
  const bool seeded = checker_.options_.seed.has_value();
  if (!pool.rng) pool.rng = States::generator(checker_.options_.seed);
  if (pool.uses == 0 || (!seeded && pool.uses >= fresh_renewal)) {
    pool.points.clear();
    pool.values.clear();
    pool.uses = 0;
    // Where the reference is defined (a point on a pole is drawn again) and the model's
    // conditions hold.
    for (int k = 0; k < checker_.options_.points; ++k)
      for (int attempt = 0; attempt < 16; ++attempt) {
        Sample p = checker_.draw_point(*pool.rng);
        if (!checker_.allowed(p)) continue;
        if (const auto v = ref_.program(p)) {
          pool.points.push_back(std::move(p));
          pool.values.push_back(*v);
          break;
        }
      }
  }
  ++pool.uses;
  points_ = pool.points;
  values_ = pool.values;
  return *points_;
}

Checker::Agreement Checker::compare(const ex& answer, const ex& reference, const Program& reference_at,
                                    const Shape& shape, FreshPoints& fresh, const std::function<bool()>& over_budget,
                                    bool& exact_values) const {
  exact_values = false;
  if (answer.is_equal(reference)) return Agreement::proved;  // the closed form as GiNaC writes it
  const double budget = static_cast<double>(options_.exact_size_budget);
  const double size = expanded_size(answer) + shape.size;
  if (shape.rational && rational_function(answer, lengths_)) {
    // Equal as rational functions or not: certain either way. Most equal answers expand to
    // the closed form's own terms over the same denominators; the others are put over one.
    if (size <= budget && (answer.expand() - (shape.expanded ? *shape.expanded : reference.expand())).is_zero())
      return Agreement::proved;
    const auto [n1, d1] = as_fraction(answer);
    const auto [n2, d2] = as_fraction(reference);
    const ex cross = n1 * d2 - n2 * d1;
    if (expanded_size(cross) <= budget && !over_budget())
      return cross.expand().is_zero() ? Agreement::proved : Agreement::refuted;
  } else if (size <= budget && !over_budget() && !has_trig(answer) && !has_trig(reference)) {
    // Zero is a proof; not zero may still be zero by an identity normal() does not know.
    // (Not tried with a sine or a cosine: normal() knows none of their identities, and the
    // points, rational points on the circle for every angle, compare them exactly.)
    try {
      if (normal(answer - reference).is_zero()) return Agreement::proved;
    } catch (const std::bad_alloc&) {
      throw;  // out of memory is the process's (exit 3), not this answer's
    } catch (const std::exception&) {
    }
  }
  const Program answer_at = program(answer);
  const auto& points = fresh.get();
  // (No points, or fewer than asked where the reference is defined: nothing to go on.)
  if (points.empty() || points.size() < static_cast<std::size_t>(options_.points)) return Agreement::unevaluable;
  exact_values = true;
  // (The reference's own closed form: its values came with the points.)
  const bool own = &reference_at == &fresh.reference().program;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Sample& p = points[k];
    if (over_budget()) return Agreement::budget;
    const auto a = answer_at(p);
    const auto b = own ? std::optional<numeric>(fresh.reference_at(k)) : reference_at(p);
    if (!a || !b) return Agreement::unevaluable;
    if (!same(*a, *b)) return Agreement::differs;
    exact_values = exact_values && a->is_rational() && b->is_rational();
  }
  return Agreement::agrees;
}

namespace {

const char* const only_some_values = "the answer agrees with the correct one only for some values of the parameters";
const char* const took_too_long = "the answer took too long to check";
const char* const abs_refused =
    "the answer uses abs(), and tackle could not decide it for every sign of its argument: write it without abs()";

}  // namespace

Checker::Decision Checker::correct_decision(bool proved, bool exact_values) const {
  const std::string count = std::to_string(points_.size() + static_cast<std::size_t>(options_.points));
  if (proved) return Decision{Verdict::correct, "exact", "", "equal to the closed form"};
  if (exact_values)
    return Decision{Verdict::correct, "exact rationals", "",
                    "equal to the closed form (in exact arithmetic at " + count + " random points)"};
  return Decision{
      Verdict::correct, "numeric", "",
      "equal to the closed form at " + count + " random points, to " + std::to_string(options_.digits - 8) + " digits"};
}

Checker::Decision Checker::decide(const Reference& ref, const ex& typed,
                                  const std::function<bool()>& over_budget) const {
  FreshPoints fresh(*this, ref);
  EvenRootsAsAbs as_abs;
  const ex answer = as_abs.rewrite(typed);
  std::vector<ex> kinks;
  kinks_of(answer, kinks);
  for (const auto& k : ref.kinks)
    if (std::none_of(kinks.begin(), kinks.end(), [&](const ex& x) { return x.is_equal(k); })) kinks.push_back(k);
  if (!kinks.empty()) return decide_across_kinks(ref, answer, kinks, fresh, over_budget);
  bool exact_values = false;
  switch (compare(answer, ref.closed_form, ref.program, ref.shape, fresh, over_budget, exact_values)) {
    case Agreement::proved: return correct_decision(true, false);
    case Agreement::agrees: return correct_decision(false, exact_values);
    case Agreement::refuted: return Decision{Verdict::incorrect, "exact", "value", only_some_values};
    case Agreement::differs: return Decision{Verdict::incorrect, "numeric", "value", only_some_values};
    case Agreement::unevaluable:
      return Decision{Verdict::undecided, "numeric", "evaluation",
                      "the answer could not be evaluated at the test values (a division by zero, a negative square "
                      "root, or a number too large to work with?)"};
    case Agreement::budget: break;
  }
  return Decision{Verdict::undecided, "", "budget", took_too_long};
}

// Kinks: each sign of their arguments in turn (abs(x) -> x or -x). Where the answer and the
// reference agree for every sign, the answer is correct on both sides of every kink. A sign
// for which they differ is looked for in the parameters (see differing_side): found, the
// answer is incorrect there; not found (a side no positive values reach, or too narrow a one),
// undecided.
Checker::Decision Checker::decide_across_kinks(const Reference& ref, const ex& answer, const std::vector<ex>& kinks,
                                               FreshPoints& fresh, const std::function<bool()>& over_budget) const {
  const Decision refused{Verdict::undecided, "", "abs", abs_refused};
  // The kinks' arguments, each once up to a constant factor (abs(h - l) and abs(l - h), or
  // abs(mu - 1/10) and abs(10*mu - 1), have one kink).
  std::vector<ex> args;
  std::vector<std::pair<std::size_t, bool>> arg_of;  // per kink: its argument, and whether negated
  for (const auto& k : kinks) {
    std::vector<ex> inner;
    kinks_of(k.op(0), inner);
    if (!inner.empty()) return refused;
    std::size_t j = 0;
    bool negated = false;
    for (; j < args.size(); ++j) {
      if (args[j].is_equal(k.op(0))) break;
      if (const ex ratio = normal(k.op(0) / args[j]); is_exactly<numeric>(ratio) && ex_to<numeric>(ratio).is_real()) {
        negated = ex_to<numeric>(ratio).is_negative();
        break;
      }
    }
    if (j == args.size()) args.push_back(k.op(0));
    arg_of.emplace_back(j, negated);
  }
  if (args.size() > max_kinks) return refused;
  std::vector<std::size_t> differing;  // the signs (bit j set: argument j negative)
  bool all_proved = true, all_exact = true;
  for (std::size_t signs = 0; signs < (std::size_t{1} << args.size()); ++signs) {
    exmap side;
    for (std::size_t i = 0; i < kinks.size(); ++i) {
      const bool negative = (((signs >> arg_of[i].first) & 1) != 0) != arg_of[i].second;
      const ex& arg = kinks[i].op(0);
      const unsigned serial = ex_to<function>(kinks[i]).get_serial();
      side[kinks[i]] = serial == abs_SERIAL::serial    ? (negative ? -arg : arg)
                       : serial == csgn_SERIAL::serial ? ex(negative ? -1 : 1)
                                                       : ex(negative ? 0 : 1);
    }
    const ex a = answer.subs(side), b = ref.closed_form.subs(side);
    bool exact_values = false;
    switch (compare(a, b, program(b), Shape{rational_function(b, lengths_), expanded_size(b), std::nullopt}, fresh,
                    over_budget, exact_values)) {
      case Agreement::proved: break;
      case Agreement::agrees:
        all_proved = false;
        all_exact = all_exact && exact_values;
        break;
      case Agreement::budget: return Decision{Verdict::undecided, "", "budget", took_too_long};
      default: differing.push_back(signs);
    }
  }
  // A sign the model's conditions leave out (abs(N_A) where N_A >= 0 is stated) is no state.
  std::erase_if(differing, [&](std::size_t signs) {
    for (std::size_t j = 0; j < args.size(); ++j)
      if (excluded(args[j], ((signs >> j) & 1) != 0)) return true;
    return false;
  });
  if (differing.empty()) return correct_decision(all_proved, all_exact);
  return differing_side(ref, answer, args, differing, over_budget).value_or(refused);
}

// A state on a side of the kinks where the answer and the reference differ (`differing`: the
// signs of the arguments there), looked for along each parameter of the kinks' arguments from
// each fixed point: values from 2^-64 to 3 * 2^63 times the point's, so both sides of a kink
// within them are met. Found: incorrect; the budget run out: undecided; else nothing.
std::optional<Checker::Decision> Checker::differing_side(const Reference& ref, const ex& answer,
                                                         const std::vector<ex>& args,
                                                         const std::vector<std::size_t>& differing,
                                                         const std::function<bool()>& over_budget) const {
  std::vector<Program> args_at;
  std::set<ex, ex_is_less> used;
  for (const auto& arg : args) {
    args_at.push_back(program(arg));
    for (const auto& s : symbols_in(substituted(arg, lengths_))) used.insert(s);
  }
  const Program answer_at = program(answer);
  for (const Sample& base : points_)
    for (std::size_t i = 0; i < base.size(); ++i) {
      if (!used.count(base[i].first)) continue;
      for (int e = -64; e <= 64; ++e)
        for (const numeric& f : {numeric(2).power(e), numeric(3, 2) * numeric(2).power(e)}) {
          if (over_budget()) return Decision{Verdict::undecided, "", "budget", took_too_long};
          Sample p = base;
          p[i].second = base[i].second * f;
          std::size_t signs = 0;
          bool clear = true;
          for (std::size_t k = 0; k < args_at.size() && clear; ++k) {
            const auto v = args_at[k](p);
            clear = v && !v->is_zero();
            if (clear && v->is_negative()) signs |= std::size_t{1} << k;
          }
          if (!clear || std::find(differing.begin(), differing.end(), signs) == differing.end() || !allowed(p))
            continue;
          const auto a = answer_at(p), b = ref.program(p);
          if (a && b && !same(*a, *b)) return Decision{Verdict::incorrect, "numeric", "value", only_some_values};
        }
    }
  return std::nullopt;
}

}  // namespace tackle

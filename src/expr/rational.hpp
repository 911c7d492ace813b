// Rational functions: normal forms and zero tests, remembered per thread.
#pragma once

#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <ginac/ginac.h>

namespace tackle {

/// normal(e), remembered per thread (the last 8192 expressions): a normal form is met again
/// and again on its way through the solver and the report, and normal() of a rational
/// function of many symbols costs a gcd each time. A normal form is remembered as its own
/// normal form too. What is remembered changes no result: equal input, equal output.
[[nodiscard]] GiNaC::ex normal_remembered(const GiNaC::ex& e);

/// Records `n` as the normal form of `e` (and of itself), for a form found by other means:
/// a fraction built reduced (a numerator over an irreducible denominator it is coprime to),
/// or the factored form of a normal form. normal() is then not asked again for a gcd.
void remember_normal(const GiNaC::ex& e, const GiNaC::ex& n);

/// The numerator and denominator of normal(e) (GiNaC's numer_denom(), which normalizes
/// again each time), remembered the same way.
[[nodiscard]] GiNaC::ex numer_denom_remembered(const GiNaC::ex& e);

/// The numerator and denominator of an expression already in normal form (normal()'s
/// output), read off its structure: factors with a negative exponent and the denominator of
/// the numeric coefficient below, the rest above. No gcd is computed again.
[[nodiscard]] GiNaC::ex numer_denom_of_normal(const GiNaC::ex& n);

/// The exact value of a rational function of symbols at a point (each symbol -> a rational
/// number): `pole` when a denominator vanishes there, `other` when `e` is not a rational
/// function of the point's symbols (a function, a fractional power, a symbol not given).
/// A number is computed, never an expression: cheaper than subs() and normal().
struct RationalAt {
  enum class Kind { value, pole, other } kind = Kind::other;
  GiNaC::numeric value;
};
struct ExHash {
  std::size_t operator()(const GiNaC::ex& x) const { return x.gethash(); }
};
using RationalPoint = std::unordered_map<GiNaC::ex, GiNaC::numeric, ExHash, GiNaC::ex_is_equal>;

/// A memory of values by expression (by hash), for remembered().
template <class Value>
using ExMemory = std::unordered_map<GiNaC::ex, Value, ExHash, GiNaC::ex_is_equal>;

/// The value for `key` in `memory`, else `compute()` put there; past `limit` entries the
/// memory forgets everything. Each caller keeps its memory thread_local; equal keys always
/// give equal values, so what is remembered changes no output.
template <class Value, class Compute>
Value remembered(ExMemory<Value>& memory, const GiNaC::ex& key, std::size_t limit, Compute compute) {
  if (auto it = memory.find(key); it != memory.end()) return it->second;
  Value v = compute();
  if (memory.size() >= limit) memory.clear();
  memory.emplace(key, v);
  return v;
}
[[nodiscard]] RationalAt rational_at(const GiNaC::ex& e, const RationalPoint& point);
/// A sum of more terms than this is long: its value at a point, its sign and its printed
/// terms are worth remembering (a chain's closed forms share m_1 + ... + m_256).
inline constexpr std::size_t long_sum_terms = 16;

/// The values of long sums (more than long_sum_terms terms) at one point, remembered by whoever evaluates
/// many expressions at that point (a chain's 511 closed forms share m_1 + ... + m_256): a
/// sum's value is its value at the point, so the memory changes no result (it forgets
/// everything past 16384 sums). Guarded by its own mutex; it belongs to one point and must
/// be dropped with it.
struct SumValues {
  std::mutex mutex;
  std::unordered_map<GiNaC::ex, GiNaC::numeric, ExHash, GiNaC::ex_is_equal> values;
};
/// rational_at() with the long sums' values looked up in and added to `sums`.
[[nodiscard]] RationalAt rational_at(const GiNaC::ex& e, const RationalPoint& point, SumValues& sums);
/// The same with the values given as an exmap (a symbol whose value is not a number is not
/// given); for a few values looked up once, without making a point.
[[nodiscard]] RationalAt rational_at(const GiNaC::ex& e, const GiNaC::exmap& values);

/// The value drawn for a symbol of this name with this seed: an integer from 1 to 2^40 made
/// from the name (the same in every run and for every expression), so that no pass over an
/// expression is needed to gather its symbols first, and two expressions evaluated with one
/// seed meet at one point.
[[nodiscard]] GiNaC::numeric drawn_value(const std::string& name, std::uint64_t seed);

/// The value of a rational function modulo the prime 2^61 - 1 at a point whose values are
/// drawn from the symbols' names (drawn_value) or given: machine words instead of exact
/// rationals, whose numerators grow with every product. `pole` when a denominator is 0
/// modulo the prime (a pole, or by a chance of its degree over 2^40, the number of values
/// drawn from, one that is not: either way another point is wanted); `other` when `e` is not
/// a rational function of symbols. A value that is not 0 says for certain that the exact
/// value is not 0; a 0 says it is, but for that chance.
struct ModularPoint {
  static constexpr std::uint64_t prime = (std::uint64_t{1} << 61) - 1;
  explicit ModularPoint(std::uint64_t seed) : seed(seed) {}
  std::uint64_t seed;
  std::unordered_map<GiNaC::ex, std::uint64_t, ExHash, GiNaC::ex_is_equal> values;
  // The values of long sums met so far, by node (each kept alive here, so that its address
  // is not taken by another): a chain's 511 values share one denominator object.
  std::unordered_map<const GiNaC::basic*, std::pair<GiNaC::ex, std::uint64_t>> sums;
  /// Sets a symbol's value; the sums remembered are forgotten when it had one already.
  void assign(const GiNaC::ex& s, std::uint64_t v) {
    auto [it, inserted] = values.emplace(s, v);
    if (inserted) return;
    it->second = v;
    sums.clear();
  }
};
struct ModularAt {
  RationalAt::Kind kind = RationalAt::Kind::other;
  std::uint64_t value = 0;
};
[[nodiscard]] ModularAt modular_at(const GiNaC::ex& e, ModularPoint& point);
/// -a and a / b (b not 0) modulo ModularPoint::prime.
[[nodiscard]] std::uint64_t modular_negated(std::uint64_t a);
[[nodiscard]] std::uint64_t modular_quotient(std::uint64_t a, std::uint64_t b);

/// Whether `e` is zero once each substitution is made in turn (the values of one may hold
/// the symbols the next replaces), decided at two points modulo the prime 2^61 - 1 (values
/// drawn from the names with fixed seeds: the same points in every run); each substituted
/// value is evaluated at a point once, then `e`. False when it is not zero at some point
/// (certain), true when it is zero at both (a nonzero one vanishes at a point by chance with
/// a probability of its degree over 2^40), nullopt when some value or `e` is not a rational
/// function of symbols or no point without a pole was found. For expressions too large to
/// expand.
[[nodiscard]] std::optional<bool> zero_at_random_points(const GiNaC::ex& e,
                                                        const std::vector<const GiNaC::exmap*>& substitutions = {});

/// A random exact rational point for the symbols of `e`, drawn in the order of their names.
[[nodiscard]] GiNaC::exmap random_point(const GiNaC::ex& e, std::mt19937& rng);

/// `e` with each node equal to a key of `m` replaced by its value: subs() for a map whose
/// keys hold no wildcards, the same result without pattern matching (GiNaC's subs() tries
/// match() of every key at every node: a chain's 511 solved unknowns put in a closed form
/// cost each of its nodes 511 matches).
[[nodiscard]] GiNaC::ex substituted(const GiNaC::ex& e, const GiNaC::exmap& m);

/// True when `e` is built of symbols and numbers by sums, products and powers of natural
/// exponents: to_polynomial() has nothing to replace (and would copy every node to say so).
[[nodiscard]] bool is_polynomial_in_symbols(const GiNaC::ex& e);

/// The distinct symbols of `e`, in the order first met (GiNaC's order, which is the hash
/// order: not for choosing what is printed).
[[nodiscard]] std::vector<GiNaC::ex> distinct_symbols(const GiNaC::ex& e);
/// The same, only those in `among` (a look-up per symbol met, nothing kept for the others).
[[nodiscard]] std::vector<GiNaC::ex> distinct_symbols_among(
    const GiNaC::ex& e, const std::unordered_set<GiNaC::ex, ExHash, GiNaC::ex_is_equal>& among);

/// The symbols of `e`.
[[nodiscard]] std::set<GiNaC::ex, GiNaC::ex_is_less> symbols_in(const GiNaC::ex& e);

/// The lowest and highest power of each symbol over the terms of an expanded polynomial, read
/// in one pass over its terms (ldegree() and degree() of each symbol would be quadratic in a
/// sum over 256 masses). `low` holds only the symbols in every term.
struct Degrees {
  std::map<GiNaC::ex, int, GiNaC::ex_is_less> low, high;
};
[[nodiscard]] Degrees degrees_of(const GiNaC::ex& expanded);
/// degrees_of(expanded).low alone: each term is asked only for the symbols still common to
/// all terms before it (no map per term; a chain's numerators F m_1 + ... + F m_k).
[[nodiscard]] std::map<GiNaC::ex, int, GiNaC::ex_is_less> low_degrees(const GiNaC::ex& expanded);
/// An expanded polynomial's integer and monomial content c and what is left, p/c expanded,
/// made term by term (expand() of p/c makes each term twice). p/c is exactly what
/// (p/c).expand() gives; c is integer_content() times x^k for each symbol x in every term
/// at its lowest power k.
struct Content {
  GiNaC::ex content, rest;
};
[[nodiscard]] Content content_of(const GiNaC::ex& expanded);

/// A sum of more terms than this is not given to factor(): factoring it takes long and
/// rarely shortens it (see canonical_factors); only its content is taken out.
inline constexpr std::size_t factor_term_limit = 16;

/// content_of(p.expand()) without expanding p, when p is a product of an integer, whole
/// powers of symbols and one expanded sum S of more than `min_terms` terms with integer
/// coefficients, no common factor (the first one positive, as evaluation leaves a sum in a
/// product) and no symbol in every term: the content is |k| x^a y^b ..., the rest S (-S for
/// k < 0). A chain's numerators F*(m_2 + ... + m_256): expanding them and taking F out
/// again was a sixth of solving a chain of 256. Nothing for any other p.
[[nodiscard]] std::optional<Content> content_of_product(const GiNaC::ex& p, std::size_t min_terms);

/// The monomial every one of `terms` holds as a factor, each term read as a product without
/// expanding it: the least whole power of each symbol that is a factor of every term (F in
/// F*(m_1 + m_2) and -m_3*F). Terms that are 0 are skipped; 1 when there is none (a term
/// that is a sum holds no symbol as a factor).
[[nodiscard]] GiNaC::ex common_monomial(const std::vector<GiNaC::ex>& terms);

/// An expanded polynomial of degree 1 in some symbol x that it is not divisible by, whose
/// coefficients of x^1 and x^0 have no common factor: it is irreducible (a factor would be
/// free of x and divide both). m_1 + ... + m_n is; gcd() of the two is far cheaper than
/// factor().
[[nodiscard]] bool linear_and_coprime(const GiNaC::ex& expanded);

/// Whether `v` holds `x`, compared by is_equal (std::find would compare with `==`, which
/// builds a relation and subtracts: a chain's 511 answers spent 0.9 G instructions so).
[[nodiscard]] bool contains(const std::vector<GiNaC::ex>& v, const GiNaC::ex& x);

/// The number of nodes of `e`, counted up to `limit` at most.
[[nodiscard]] std::size_t node_count(const GiNaC::ex& e, std::size_t limit = static_cast<std::size_t>(-1));

/// Zero, exactly: normal() and sin^2 + cos^2 = 1.
[[nodiscard]] bool is_zero_exactly(const GiNaC::ex& e);

}  // namespace tackle

// A strict expression parser over a problem's own names. Every limit (length, tokens,
// nesting, exponent size, number size) is checked before the GiNaC object that would
// exceed it exists. Decimals become exact rationals: `9.81` is 981/100.
//
// Grammar (no implicit multiplication):
//   sum     := product (('+' | '-') product)*
//   product := unary (('*' | '/') unary)*
//   unary   := ('+' | '-') unary | power
//   power   := primary ('^' unary)?            right associative
//   primary := number | name | name '(' args ')' | '(' sum ')'
// `dot(q)` and `ddot(q)` name the rate and acceleration symbols of a coordinate q; `sqrt`,
// `abs`, `sin`, `cos`, `tan`, `exp`, `log` are the functions.
//
// Vectors (for rule templates): `[a, b, c]` is a vector (fewer than three entries are padded
// with zeros), a resolver may give vectors (a point's position), and `unit(v)`, `norm(v)`,
// `cross(u, v)`, `inner(u, v)`, `perp1(v)`, `perp2(v)` (two unit vectors perpendicular to v
// and to each other) work on them. Vectors add, subtract and scale; anything else is an error.
// A vector is a GiNaC 3x1 matrix.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <ginac/ginac.h>

#include "core/limits.hpp"

namespace tackle {

/// Resolves names to expressions: a parameter, a coordinate, `ddot(x_A)`, a local name.
class NameResolver {
 public:
  virtual ~NameResolver() = default;
  [[nodiscard]] virtual std::optional<GiNaC::ex> resolve(std::string_view name) const = 0;
  /// Every name it knows, for "did you mean" suggestions.
  [[nodiscard]] virtual std::vector<std::string> known_names() const = 0;
};

struct ParseProblem {
  int column = 0;  // 0-based offset within the text
  std::string message;
  bool limit = false;  // past one of ExprLimits (too long, too deep, too large a number), not a syntax error
};

struct ParseResult {
  std::optional<GiNaC::ex> value;
  std::vector<ParseProblem> problems;  // empty when value is set
};

[[nodiscard]] ParseResult parse_expression(std::string_view text, const NameResolver& names,
                                           const ExprLimits& limits = {});

/// A relation `lhs OP rhs` with OP one of `>=`, `<=`, `>`, `<`, `=`; used by validity rules and
/// equation answers.
struct ParsedRelation {
  GiNaC::ex lhs, rhs;
  std::string op;
};
struct RelationResult {
  std::optional<ParsedRelation> value;
  std::vector<ParseProblem> problems;
};
[[nodiscard]] RelationResult parse_relation(std::string_view text, const NameResolver& names,
                                            const ExprLimits& limits = {});

/// A resolver that knows no names: for values that must be plain numbers.
[[nodiscard]] const NameResolver& numbers_only();

/// The end of a number literal starting at `start` (digits, an optional fraction, an optional
/// exponent), or `start` when there is none there. Shared by the parser and the answer checker.
[[nodiscard]] std::size_t scan_number(std::string_view text, std::size_t start);

/// True when `e` is a vector (a 3x1 matrix) as the parser makes them.
[[nodiscard]] bool is_vector(const GiNaC::ex& e);
/// A vector from three components.
[[nodiscard]] GiNaC::ex make_vector(const GiNaC::ex& x, const GiNaC::ex& y, const GiNaC::ex& z);

/// True for names the parser accepts as a plain identifier: a letter, then letters, digits, `_`.
[[nodiscard]] bool is_identifier(std::string_view name);

}  // namespace tackle

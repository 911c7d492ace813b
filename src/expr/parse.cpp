#include "expr/parse.hpp"

#include <cctype>
#include <map>

#include "core/diagnostics.hpp"
#include "core/kind.hpp"
#include "core/utf8.hpp"
#include "expr/trig.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

enum class Tok { number, name, op, lparen, rparen, lbracket, rbracket, comma, end };

struct Token {
  Tok kind;
  std::string text;
  int column;
};

bool is_name_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

struct Failure {
  ParseProblem problem;
};

ex cross3(const ex& u, const ex& v) {
  return make_vector(u.op(1) * v.op(2) - u.op(2) * v.op(1), u.op(2) * v.op(0) - u.op(0) * v.op(2),
                     u.op(0) * v.op(1) - u.op(1) * v.op(0));
}

class Parser {
 public:
  Parser(std::string_view text, const NameResolver& names, const ExprLimits& limits)
      : text_(text), names_(names), limits_(limits) {}

  ex parse_all() {
    tokenize();
    ex e = sum();
    if (peek().kind == Tok::rbracket) fail(peek().column, "unexpected ']'");
    if (peek().kind != Tok::end) fail(peek().column, "unexpected '" + peek().text + "'");
    return e;
  }

  // For relations: parse a sum, stop at a relational operator.
  void tokenize_only() { tokenize(); }
  ex sum_only() { return sum(); }
  const Token& peek() const { return tokens_[pos_]; }
  void advance() { ++pos_; }

  [[noreturn]] void fail(int column, std::string message) { throw Failure{{column, std::move(message)}}; }
  [[noreturn]] void fail_limit(int column, std::string message) { throw Failure{{column, std::move(message), true}}; }

 private:
  void tokenize() {
    if (text_.size() > limits_.max_length)
      fail_limit(0, "expression is too long (" + std::to_string(text_.size()) + " characters; at most " +
                        std::to_string(limits_.max_length) + ")");
    std::size_t i = 0;
    while (i < text_.size()) {
      const char c = text_[i];
      const int col = static_cast<int>(i);
      if (c == ' ' || c == '\t') {
        ++i;
        continue;
      }
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && i + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[i + 1])))) {
        const std::size_t j = scan_number(text_, i);
        push(Tok::number, text_.substr(i, j - i), col);
        i = j;
        continue;
      }
      if (is_name_start(c)) {
        std::size_t j = i;
        while (j < text_.size() && is_name_char(text_[j])) ++j;
        push(Tok::name, text_.substr(i, j - i), col);
        i = j;
        continue;
      }
      switch (c) {
        case '+':
        case '-':
        case '*':
        case '/':
        case '^':
          push(Tok::op, text_.substr(i, 1), col);
          ++i;
          continue;
        case '>':
        case '<':
        case '=': {
          std::size_t len = (i + 1 < text_.size() && text_[i + 1] == '=') ? 2 : 1;
          push(Tok::op, text_.substr(i, len), col);
          i += len;
          continue;
        }
        case '(':
          push(Tok::lparen, "(", col);
          ++i;
          continue;
        case '[':
          push(Tok::lbracket, "[", col);
          ++i;
          continue;
        case ']':
          push(Tok::rbracket, "]", col);
          ++i;
          continue;
        case ')':
          push(Tok::rparen, ")", col);
          ++i;
          continue;
        case ',':
          push(Tok::comma, ",", col);
          ++i;
          continue;
        default: break;
      }
      // The whole character (not one byte of it), and a control character escaped.
      fail(col, "unexpected character '" + printable(utf8_char_at(text_, i)) + "'");
    }
    tokens_.push_back({Tok::end, "end of expression", static_cast<int>(text_.size())});
  }

  void push(Tok kind, std::string_view text, int col) {
    if (tokens_.size() >= limits_.max_tokens)
      fail_limit(col, "expression has too many tokens (at most " + std::to_string(limits_.max_tokens) + ")");
    tokens_.push_back({kind, std::string(text), col});
  }

  struct DepthGuard {
    Parser& p;
    DepthGuard(Parser& parser, int column) : p(parser) {
      if (++p.depth_ > p.limits_.max_depth)
        p.fail_limit(column,
                     "expression is nested too deeply (at most " + std::to_string(p.limits_.max_depth) + " levels)");
    }
    ~DepthGuard() { --p.depth_; }
  };

  bool at_op(std::string_view op) const { return peek().kind == Tok::op && peek().text == op; }

  // A sum's terms (and below, a product's factors) are gathered and made into one GiNaC
  // object at the end: each intermediate sum or product would be evaluated (sorted and
  // combined) again. A vector is always the only term or factor.
  ex sum() {
    exvector terms{product()};
    while (at_op("+") || at_op("-")) {
      const bool minus = peek().text == "-";
      const int col = peek().column;
      advance();
      ex rhs = product();
      const bool vector = terms.size() == 1 && is_vector(terms[0]);
      if (vector != is_vector(rhs)) fail(col, "cannot add a vector and a number");
      if (vector)
        terms[0] = combine(terms[0], rhs, minus ? -1 : 1);
      else
        terms.push_back(minus ? -rhs : rhs);
    }
    return terms.size() == 1 ? terms[0] : ex(add(terms));
  }

  static ex combine(const ex& u, const ex& v, int sign) {
    return make_vector(u.op(0) + sign * v.op(0), u.op(1) + sign * v.op(1), u.op(2) + sign * v.op(2));
  }
  static ex scaled(const ex& v, const ex& f) { return make_vector(v.op(0) * f, v.op(1) * f, v.op(2) * f); }

  ex product() {
    exvector factors{unary()};
    const auto value = [&] { return factors.size() == 1 ? factors[0] : ex(mul(factors)); };
    while (true) {
      if (at_op("*") || at_op("/")) {
        const bool divide = peek().text == "/";
        const int col = peek().column;
        advance();
        ex rhs = unary();
        const bool vector = factors.size() == 1 && is_vector(factors[0]);
        if (is_vector(rhs) && (divide || vector))
          fail(col, divide ? "cannot divide by a vector" : "cannot multiply two vectors (use cross or inner)");
        if (divide) {
          if (rhs.is_zero()) fail(col, "division by zero");
          if (vector)
            factors[0] = scaled(factors[0], 1 / rhs);
          else
            factors.push_back(pow(rhs, -1));
        } else if (vector || is_vector(rhs)) {
          factors = {vector ? scaled(factors[0], rhs) : scaled(rhs, value())};
        } else {
          factors.push_back(rhs);
        }
      } else if (peek().kind == Tok::number || peek().kind == Tok::name || peek().kind == Tok::lparen) {
        fail(peek().column, "missing '*' before '" + peek().text + "'");
      } else {
        return value();
      }
    }
  }

  ex unary() {
    if (at_op("-") || at_op("+")) {
      const bool minus = peek().text == "-";
      DepthGuard guard(*this, peek().column);
      advance();
      ex e = unary();
      if (!minus) return e;
      return is_vector(e) ? scaled(e, -1) : -e;
    }
    return power_();
  }

  ex power_() {
    ex base = primary();
    if (!at_op("^")) return base;
    const int col = peek().column;
    DepthGuard guard(*this, col);
    advance();
    ex expo = unary();
    if (is_vector(base) || is_vector(expo)) fail(col, "cannot raise a vector to a power, or to a vector");
    if (is_a<numeric>(expo)) {
      const numeric n = ex_to<numeric>(expo);
      if (!n.is_rational()) fail(col, "exponent must be a rational number");
      if (abs(n.numer()) > limits_.max_exponent || n.denom() > limits_.max_exponent)
        fail_limit(col, "exponent is too large (at most " + std::to_string(limits_.max_exponent) + ")");
      // GiNaC throws for these from inside a new object, and that object then leaks.
      if (base.is_zero() && n.is_zero()) fail(col, "0^0 is undefined");
      if (base.is_zero() && n.is_negative()) fail(col, "division by zero");
      if (is_a<numeric>(base)) {
        // Bound the size of the number the power would make (in bits) before making it.
        const numeric b = ex_to<numeric>(base);
        const long bits = b.is_rational() ? b.numer().int_length() + b.denom().int_length() : 64;
        if (bits * std::abs(n.numer().to_long()) > 4096) fail_limit(col, "number is too large");
      }
    }
    return pow(base, expo);
  }

  ex number(const Token& t) {
    std::size_t digits = 0;
    for (char c : t.text)
      if (std::isdigit(static_cast<unsigned char>(c))) ++digits;
    if (digits > limits_.max_number_digits)
      fail_limit(t.column, "number has too many digits (at most " + std::to_string(limits_.max_number_digits) + ")");
    // A whole number that fits a long (most numbers typed): as it is.
    if (digits == t.text.size() && digits <= 18) return numeric(std::stol(t.text));
    // Exact: mantissa digits over a power of ten, times 10^exponent.
    std::string mant = t.text;
    long exp10 = 0;
    if (auto e = mant.find_first_of("eE"); e != std::string::npos) {
      const std::string es = mant.substr(e + 1);
      mant = mant.substr(0, e);
      if (es.size() > 4) fail_limit(t.column, "number exponent is too large");
      exp10 = std::stol(es);
      if (exp10 > 30 || exp10 < -30) fail_limit(t.column, "number exponent is too large (at most 30)");
    }
    std::string intdigits = mant;
    if (auto dot = mant.find('.'); dot != std::string::npos) {
      intdigits = mant.substr(0, dot) + mant.substr(dot + 1);
      exp10 -= static_cast<long>(mant.size() - dot - 1);
    }
    if (intdigits.empty()) intdigits = "0";
    numeric value(intdigits.c_str());
    return value * GiNaC::pow(numeric(10), numeric(exp10));
  }

  // dot(q) and ddot(q) take the coordinate's bare name: q itself need not be a name the
  // expression may use (an answer may use ddot(y_B) without y_B).
  ex derivative(const Token& name) {
    const Token q = peek();
    if (q.kind != Tok::name)
      fail(q.column, "'" + name.text + "' takes the name of a coordinate, as in " + name.text + "(x_A)");
    advance();
    if (peek().kind != Tok::rparen) fail(peek().column, "expected ')' to close '" + name.text + "('");
    advance();
    const std::string key = name.text + "(" + q.text + ")";
    if (auto r = names_.resolve(key)) return *r;
    fail(name.column, "'" + q.text + "' is not a coordinate, so '" + key + "' is not defined");
  }

  // A call's arguments, each with its first token (for where a problem is), and its ')'.
  struct Arguments {
    std::vector<ex> values;
    std::vector<Token> first_tokens;
  };
  Arguments arguments(const Token& name) {
    Arguments args;
    if (peek().kind != Tok::rparen) {
      while (true) {
        args.first_tokens.push_back(peek());
        args.values.push_back(sum());
        if (peek().kind == Tok::comma) {
          advance();
          continue;
        }
        break;
      }
    }
    if (peek().kind != Tok::rparen) fail(peek().column, "expected ')' to close '" + name.text + "('");
    advance();
    return args;
  }

  void arity(const Token& name, const Arguments& args, std::size_t n) {
    if (args.values.size() != n)
      fail(name.column, "'" + name.text + "' takes " + std::to_string(n) + (n == 1 ? " argument" : " arguments"));
  }

  ex vector_arg(const Token& name, const Arguments& args, std::size_t i) {
    if (!is_vector(args.values[i])) fail(args.first_tokens[i].column, "'" + name.text + "' takes a vector");
    return args.values[i];
  }

  // unit, norm, perp1 and perp2 of a vector.
  ex of_vector(const Token& name, const Arguments& args) {
    const std::string& f = name.text;
    arity(name, args, 1);
    const ex v = vector_arg(name, args, 0);
    // sin^2 + cos^2 = 1 first, so that unit([-sin(theta), cos(theta)]) has no root in it.
    const ex n = sqrt(fewer_trig_terms((v.op(0) * v.op(0) + v.op(1) * v.op(1) + v.op(2) * v.op(2)).expand()));
    if (normal(n).is_zero()) fail(args.first_tokens[0].column, "'" + f + "' of a zero vector");
    if (f == "norm") return n;
    if (f == "unit") return scaled(v, 1 / n);
    // perp1: the unit vector along v x e, e the coordinate axis least aligned with v;
    // perp2 = unit(v) x perp1. Chosen from v's components when they are numbers, else e_z.
    int least = 2;
    if (is_a<numeric>(v.op(0)) && is_a<numeric>(v.op(1)) && is_a<numeric>(v.op(2))) {
      least = 0;
      for (int k = 1; k < 3; ++k)
        if (abs(ex_to<numeric>(v.op(k))) < abs(ex_to<numeric>(v.op(least)))) least = k;
    }
    const ex e = make_vector(least == 0 ? 1 : 0, least == 1 ? 1 : 0, least == 2 ? 1 : 0);
    const ex c = cross3(v, e);
    const ex cn = sqrt(c.op(0) * c.op(0) + c.op(1) * c.op(1) + c.op(2) * c.op(2));
    if (normal(cn).is_zero())
      fail(args.first_tokens[0].column, "'" + f + "' of a vector along the z axis is taken with its numbers given");
    const ex p1 = scaled(c, 1 / cn);
    if (f == "perp1") return p1;
    return cross3(scaled(v, 1 / n), p1);
  }

  // The functions of one number; poles are input errors, found before GiNaC throws from
  // inside a new object (which then leaks): tan at an odd multiple of pi/2, log at 0.
  ex of_number(const Token& name, const Arguments& args) {
    const std::string& f = name.text;
    for (const auto& a : args.values)
      if (is_vector(a)) fail(name.column, "'" + f + "' takes a number, not a vector");
    static const std::map<std::string, ex (*)(const ex&)> plain = {
        {"sqrt", [](const ex& a) { return sqrt(a); }},     {"abs", [](const ex& a) { return ex(abs(a)); }},
        {"sin", [](const ex& a) { return ex(sin(a)); }},   {"cos", [](const ex& a) { return ex(cos(a)); }},
        {"exp", [](const ex& a) { return ex(exp(a)); }},   {"asin", [](const ex& a) { return ex(asin(a)); }},
        {"acos", [](const ex& a) { return ex(acos(a)); }}, {"atan", [](const ex& a) { return ex(atan(a)); }},
        {"sinh", [](const ex& a) { return ex(sinh(a)); }}, {"cosh", [](const ex& a) { return ex(cosh(a)); }}};
    const auto known = plain.find(f);
    if (known == plain.end() && f != "tan" && f != "log")
      fail(name.column, "unknown function '" + f +
                            "' (known: sqrt, abs, sin, cos, tan, asin, acos, atan, sinh, cosh, exp, log, dot, ddot, "
                            "unit, norm, cross, inner, perp1, perp2)");
    if (args.values.size() != 1) fail(name.column, "'" + f + "' takes one argument");
    const ex& a = args.values[0];
    if (known != plain.end()) return known->second(a);
    if (f == "tan") {
      // (Only an argument with pi in it can be one: normal() of every tan's argument was a
      // fifth of reading an answer with a tan.)
      const auto pole = [&] {
        const ex k = normal(a / Pi - numeric(1, 2));
        return is_a<numeric>(k) && ex_to<numeric>(k).is_integer();
      };
      if (a.has(Pi) && pole()) fail(name.column, "tan is undefined at an odd multiple of pi/2");
      return tan(a);
    }
    if (a.is_zero()) fail(name.column, "log is undefined at 0");
    return log(a);
  }

  ex call(const Token& name) {
    DepthGuard guard(*this, name.column);
    advance();  // '('
    if (name.text == "dot" || name.text == "ddot") return derivative(name);
    const Arguments args = arguments(name);
    const std::string& f = name.text;
    if (f == "unit" || f == "norm" || f == "perp1" || f == "perp2") return of_vector(name, args);
    if (f == "cross" || f == "inner") {
      arity(name, args, 2);
      const ex u = vector_arg(name, args, 0), v = vector_arg(name, args, 1);
      if (f == "cross") return cross3(u, v);
      return u.op(0) * v.op(0) + u.op(1) * v.op(1) + u.op(2) * v.op(2);
    }
    return of_number(name, args);
  }

  ex primary() {
    const Token t = peek();
    switch (t.kind) {
      case Tok::number: advance(); return number(t);
      case Tok::name: {
        advance();
        if (peek().kind == Tok::lparen) {
          --pos_;
          const Token name = t;
          advance();
          return call(name);
        }
        if (auto r = names_.resolve(t.text)) return *r;
        if (t.text == "pi") return Pi;  // unless the problem names something pi
        std::string msg = "unknown name '" + t.text + "'";
        const auto known = names_.known_names();
        if (auto near = nearest(t.text, known); !near.empty()) {
          msg += " (did you mean '" + near + "'?)";
        } else {
          std::vector<std::string> plain;  // names a user types, without dot(...) and ddot(...)
          for (const auto& k : known)
            if (k.find('(') == std::string::npos && plain.size() < 12) plain.push_back(k);
          if (!plain.empty()) msg += " (known: " + join(plain) + (plain.size() == 12 ? ", ..." : "") + ")";
        }
        fail(t.column, msg);
      }
      case Tok::lbracket: {
        DepthGuard guard(*this, t.column);
        advance();
        std::vector<ex> items;
        while (peek().kind != Tok::rbracket) {
          const Token first = peek();
          ex item = sum();
          if (is_vector(item)) fail(first.column, "a vector's entries are numbers, not vectors");
          items.push_back(item);
          if (peek().kind == Tok::comma) {
            advance();
            continue;
          }
          if (peek().kind != Tok::rbracket) fail(peek().column, "expected ',' or ']' in a vector");
        }
        if (items.empty() || items.size() > 3) fail(t.column, "a vector has one to three entries");
        advance();
        while (items.size() < 3) items.push_back(0);
        return make_vector(items[0], items[1], items[2]);
      }
      case Tok::lparen: {
        DepthGuard guard(*this, t.column);
        advance();
        ex e = sum();
        if (peek().kind != Tok::rparen)
          fail(peek().column, "expected ')' to close the '(' at column " + std::to_string(t.column + 1));
        advance();
        return e;
      }
      case Tok::end: fail(t.column, "expression ends too early");
      default: fail(t.column, "unexpected '" + t.text + "'");
    }
  }

  std::string_view text_;
  const NameResolver& names_;
  const ExprLimits& limits_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
};

}  // namespace

ParseResult parse_expression(std::string_view text, const NameResolver& names, const ExprLimits& limits) {
  try {
    Parser p(text, names, limits);
    return {p.parse_all(), {}};
  } catch (const Failure& f) {
    return {std::nullopt, {f.problem}};
  } catch (const std::bad_alloc&) {
    throw;  // out of memory is the process's (exit 3), not the expression's
  } catch (const std::exception& e) {
    // GiNaC arithmetic errors (for example 0^0) are input problems too.
    return {std::nullopt, {{0, std::string("cannot evaluate: ") + e.what()}}};
  }
}

RelationResult parse_relation(std::string_view text, const NameResolver& names, const ExprLimits& limits) {
  try {
    Parser p(text, names, limits);
    p.tokenize_only();
    ex lhs = p.sum_only();
    const Token op = p.peek();
    if (op.kind != Tok::op ||
        (op.text != ">=" && op.text != "<=" && op.text != ">" && op.text != "<" && op.text != "=" && op.text != "=="))
      p.fail(op.column, "expected a relation such as 'T >= 0'");
    p.advance();
    ex rhs = p.sum_only();
    if (p.peek().kind != Tok::end) p.fail(p.peek().column, "unexpected '" + p.peek().text + "'");
    return {ParsedRelation{lhs, rhs, op.text == "==" ? "=" : op.text}, {}};
  } catch (const Failure& f) {
    return {std::nullopt, {f.problem}};
  } catch (const std::bad_alloc&) {
    throw;  // out of memory is the process's (exit 3), not the expression's
  } catch (const std::exception& e) {
    return {std::nullopt, {{0, std::string("cannot evaluate: ") + e.what()}}};
  }
}

std::size_t scan_number(std::string_view t, std::size_t start) {
  auto digit = [&](std::size_t k) { return k < t.size() && std::isdigit(static_cast<unsigned char>(t[k])); };
  std::size_t j = start;
  bool digits = false;
  while (digit(j)) ++j, digits = true;
  if (j < t.size() && t[j] == '.') {
    ++j;
    while (digit(j)) ++j, digits = true;
  }
  if (!digits) return start;
  if (j < t.size() && (t[j] == 'e' || t[j] == 'E')) {
    std::size_t k = j + 1;
    if (k < t.size() && (t[k] == '+' || t[k] == '-')) ++k;
    if (digit(k)) {
      while (digit(k)) ++k;
      j = k;
    }
  }
  return j;
}

const NameResolver& numbers_only() {
  struct NoNames : NameResolver {
    std::optional<ex> resolve(std::string_view) const override { return std::nullopt; }
    std::vector<std::string> known_names() const override { return {}; }
  };
  static const NoNames none;
  return none;
}

bool is_vector(const ex& e) {
  return is_exactly<matrix>(e) && ex_to<matrix>(e).rows() == 3 && ex_to<matrix>(e).cols() == 1;
}

ex make_vector(const ex& x, const ex& y, const ex& z) { return matrix(3, 1, lst{x, y, z}); }

bool is_identifier(std::string_view name) {
  if (name.empty() || !is_name_start(name[0])) return false;
  for (char c : name)
    if (!is_name_char(c)) return false;
  return true;
}

}  // namespace tackle

#include "report/break.hpp"

#include <algorithm>
#include <cctype>
#include <optional>

namespace tackle {

namespace {

// The index of the brace that closes the one at `open`, or npos.
std::size_t closing(std::string_view s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      ++i;  // an escaped character (\{, \}) is no brace
      continue;
    }
    if (s[i] == '{') ++depth;
    if (s[i] == '}' && --depth == 0) return i;
  }
  return std::string_view::npos;
}

// A command's name at `i` (just after its backslash): letters, or one other character.
std::string_view command_at(std::string_view s, std::size_t i) {
  std::size_t j = i;
  while (j < s.size() && std::isalpha(static_cast<unsigned char>(s[j]))) ++j;
  if (j == i && j < s.size()) ++j;
  return s.substr(i, j - i);
}

// The next argument at `i` (skipping spaces): a braced group's inside, or one character;
// `i` moves past it.
std::string_view argument(std::string_view s, std::size_t& i) {
  while (i < s.size() && s[i] == ' ') ++i;
  if (i >= s.size()) return {};
  if (s[i] == '{') {
    const std::size_t end = closing(s, i);
    if (end == std::string_view::npos) {
      const std::string_view rest = s.substr(i + 1);
      i = s.size();
      return rest;
    }
    const std::string_view inside = s.substr(i + 1, end - i - 1);
    i = end + 1;
    return inside;
  }
  if (s[i] == '\\') {
    const std::string_view name = command_at(s, i + 1);
    const std::string_view whole = s.substr(i, name.size() + 1);
    i += name.size() + 1;
    return whole;
  }
  return s.substr(i++, 1);
}

// The places of the top-level " + " and " - " (outside braces and \left ... \right).
std::vector<std::size_t> top_level_operators(std::string_view s) {
  std::vector<std::size_t> out;
  int depth = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\') {
      const std::string_view name = command_at(s, i + 1);
      if (name == "left") ++depth;
      if (name == "right") --depth;
      i += name.size();
      if ((name == "left" || name == "right") && i + 1 < s.size()) ++i;  // its delimiter
      continue;
    }
    if (s[i] == '{')
      ++depth;
    else if (s[i] == '}')
      --depth;
    else if (depth == 0 && i > 0 && s[i] == ' ' && i + 2 < s.size() && (s[i + 1] == '+' || s[i + 1] == '-') &&
             s[i + 2] == ' ')
      out.push_back(i);
  }
  return out;
}

// `s` cut at its top-level operators: the first term, then each with its operator in front.
std::vector<std::string> terms_of(std::string_view s) {
  std::vector<std::string> out;
  std::size_t from = 0;
  for (const std::size_t at : top_level_operators(s)) {
    out.emplace_back(s.substr(from, at - from));
    from = at + 1;
  }
  out.emplace_back(s.substr(from));
  return out;
}

// `s` as \frac{num}{den} when it is one fraction as a whole: its numerator and denominator.
std::optional<std::pair<std::string, std::string>> whole_fraction(const std::string& s) {
  if (s.rfind("\\frac{", 0) != 0) return std::nullopt;
  const std::size_t num_close = closing(s, 5);
  if (num_close == std::string::npos || num_close + 1 >= s.size() || s[num_close + 1] != '{' ||
      closing(s, num_close + 1) != s.size() - 1)
    return std::nullopt;
  return std::make_pair(s.substr(6, num_close - 6), s.substr(num_close + 2, s.size() - num_close - 3));
}

// Terms packed into lines of about `width`: `head` before the first, `tail` after the last.
std::vector<std::string> pack(const std::vector<std::string>& terms, double width, const std::string& head,
                              const std::string& tail) {
  std::vector<std::string> lines;
  std::string line = head;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const std::string& term = terms[k];
    if (tex_width(term) > width) {
      // A term too long for a line of its own (a long fraction): broken itself, its
      // operator in front of its first line.
      std::string op, body = term;
      if (k > 0 && body.size() > 2 && (body[0] == '+' || body[0] == '-') && body[1] == ' ')
        op = body.substr(0, 2), body = body.substr(2);
      auto parts = break_tex(body, width);
      if (parts.size() > 1) {
        if (!line.empty() && line != head) lines.push_back(line);
        parts.front() = (line == head ? head : "") + op + parts.front();
        lines.insert(lines.end(), parts.begin(), parts.end() - 1);
        line = parts.back();
        continue;
      }
    }
    if (k > 0 && tex_width(line + " " + term) > width && line != head) {
      lines.push_back(line);
      line = term;
    } else {
      line += (k > 0 ? " " : "") + term;
    }
  }
  lines.push_back(line + tail);
  return lines;
}

}  // namespace

double tex_width(std::string_view s) {
  double w = 0;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (c == '\\') {
      const std::string_view name = command_at(s, i + 1);
      i += name.size() + 1;
      if (name == "frac" || name == "dfrac" || name == "tfrac") {
        const double a = tex_width(argument(s, i)), b = tex_width(argument(s, i));
        w += std::max(a, b) + 0.5;
      } else if (name == "sqrt") {
        w += 1 + tex_width(argument(s, i));
      } else if (name == "mathrm" || name == "text" || name == "operatorname" || name == "mathit" || name == "dot" ||
                 name == "ddot" || name == "boxed" || name == "mathbf") {
        w += tex_width(argument(s, i));
      } else if (name == "left" || name == "right" || name == "bigl" || name == "bigr" || name == "Bigl" ||
                 name == "Bigr") {
        if (i < s.size() && s[i] == '.')
          ++i, w -= 1;
        else if (i < s.size() && s[i] == '\\')
          i += command_at(s, i + 1).size() + 1;
        else
          ++i;
        w += 1;
      } else if (name == "," || name == ";" || name == "!" || name == " ") {
        w += 0.3;
      } else if (name == "quad") {
        w += 2;
      } else if (name == "sin" || name == "cos" || name == "tan" || name == "exp" || name == "log" || name == "ln") {
        w += static_cast<double>(name.size());
      } else {
        w += 1;  // a Greek letter, a symbol
      }
      continue;
    }
    if (c == '^' || c == '_') {
      ++i;
      w += 0.7 * tex_width(argument(s, i));
      continue;
    }
    ++i;
    if (c == '{' || c == '}' || c == ' ') continue;
    w += (c == '+' || c == '-' || c == '=' || c == '<' || c == '>') ? 2 : 1;
  }
  return w;
}

std::vector<std::string> displayed_lines(const std::string& lhs, const std::string& rel, const std::string& rhs,
                                         const std::string& tail, double width) {
  const std::string whole = lhs + " " + rel + " " + rhs + tail;
  if (tex_width(whole) <= width) return {whole};
  if (tex_width(lhs) > 0.6 * width) {
    const auto left = break_tex(lhs, width - 4);
    if (left.size() > 1) {
      std::vector<std::string> lines{"&" + left.front()};
      for (std::size_t k = 1; k < left.size(); ++k) lines.push_back("&\\quad " + left[k]);
      const auto right = break_tex(rhs, width - 8);
      if (right.size() == 1 && tex_width(left.back() + " " + rel + " " + rhs + tail) <= width - 4) {
        lines.back() += " " + rel + " " + rhs + tail;
      } else {
        lines.push_back("&\\qquad " + rel + " " + right.front());
        for (std::size_t k = 1; k < right.size(); ++k) lines.push_back("&\\qquad " + right[k]);
        lines.back() += tail;
      }
      return lines;
    }
  }
  const auto right = break_tex(rhs, std::max(30.0, width - tex_width(lhs) - 3 - tex_width(tail)));
  // A formula that fits without its number, and cannot be broken: the number on a line of
  // its own (a bound's (19.1206 m/s)^2 after a fraction).
  const std::string bare = lhs + " " + rel + " " + rhs;
  if (right.size() == 1 && !tail.empty() && tex_width(bare) <= width) return {lhs + " &" + rel + " " + rhs, "&" + tail};
  if (right.size() == 1) return {whole};
  std::vector<std::string> lines{lhs + " &" + rel + " " + right.front()};
  for (std::size_t k = 1; k < right.size(); ++k) lines.push_back("&\\quad " + right[k]);
  lines.back() += tail;
  return lines;
}

std::string displayed(const std::string& lhs, const std::string& rel, const std::string& rhs, const std::string& tail,
                      double width) {
  const auto lines = displayed_lines(lhs, rel, rhs, tail, width);
  if (lines.size() == 1) return lines.front();
  std::string out = "\\begin{aligned}" + lines.front();
  for (std::size_t k = 1; k < lines.size(); ++k) out += " \\\\ " + lines[k];
  return out + "\\end{aligned}";
}

std::string inline_tex(const std::string& tex) {
  if (tex_width(tex) <= 40) return tex;
  std::string s = tex, sign;
  if (!s.empty() && s[0] == '-') sign = "-", s = s.substr(1);
  if (const auto f = whole_fraction(s)) {
    const auto& [num, den] = *f;
    s = "\\frac{1}{" + den + "} " + (terms_of(num).size() > 1 ? "(" + num + ")" : num);
  }
  s = sign + s;
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\\left(", "("}, {"\\right)", ")"}})
    for (std::size_t at; (at = s.find(from)) != std::string::npos;) s.replace(at, from.size(), to);
  return s;
}

namespace {

// `s` broken inside its longest top-level \left( ... \right) group (a product with a long
// sum in it): `head` and the part before the group on the first line, the part after it and
// `tail` on the last. Nothing when it has no such group with a sum inside.
std::vector<std::string> broken_in_group(const std::string& s, double width, const std::string& head,
                                         const std::string& tail) {
  std::size_t best_open = std::string::npos, best_close = 0, best_length = 0;
  int depth = 0;
  std::vector<std::size_t> opens;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '{') {
      ++depth;
    } else if (s[i] == '}') {
      --depth;
    } else if (s.compare(i, 6, "\\left(") == 0) {
      if (depth == 0) opens.push_back(i);
      ++depth;
      i += 5;
    } else if (s.compare(i, 7, "\\right)") == 0) {
      --depth;
      if (depth == 0 && !opens.empty()) {
        const std::size_t open = opens.back();
        opens.pop_back();
        if (i - open > best_length) best_open = open, best_close = i, best_length = i - open;
      }
      i += 6;
    } else if (s.compare(i, 5, "\\left") == 0) {
      ++depth;
      i += 4;
    } else if (s.compare(i, 6, "\\right") == 0) {
      --depth;
      i += 5;
    }
  }
  if (best_open == std::string::npos) return {};
  const auto terms = terms_of(s.substr(best_open + 6, best_close - best_open - 6));
  if (terms.size() < 2) return {};
  return pack(terms, width, head + s.substr(0, best_open) + "\\bigl(", "\\bigr)" + s.substr(best_close + 7) + tail);
}

// `s` broken at its own + and - when it has them, else inside its longest group; the whole
// of it on one line (with head and tail) when neither.
std::vector<std::string> broken(const std::string& s, double width, const std::string& head, const std::string& tail,
                                bool parenthesize) {
  if (const auto terms = terms_of(s); terms.size() > 1)
    return parenthesize ? pack(terms, width, head + "\\bigl(", "\\bigr)" + tail) : pack(terms, width, head, tail);
  if (auto lines = broken_in_group(s, width, head, tail); !lines.empty()) return lines;
  return {head + s + tail};
}

}  // namespace

std::vector<std::string> break_tex(const std::string& rhs, double width) {
  if (tex_width(rhs) <= width) return {rhs};
  // A sum: broken at its own + and -.
  if (const auto terms = terms_of(rhs); terms.size() > 1) return pack(terms, width, "", "");
  // Else a product or a fraction with a long sum inside.
  std::string sign, s = rhs;
  if (!s.empty() && s[0] == '-') {
    sign = "-";
    s = s.substr(1);
    while (!s.empty() && s[0] == ' ') s = s.substr(1);
  }
  if (const auto f = whole_fraction(s)) {
    const auto& [num, den] = *f;
    // A short denominator goes first, as 1/den; a long one is broken too, after a slash.
    if (tex_width(den) <= 0.5 * width) {
      auto lines = broken(num, width, sign + "\\frac{1}{" + den + "} ", "", true);
      if (lines.size() > 1) return lines;
      return {rhs};
    }
    auto lines = broken(num, width, sign, "", true);
    const auto under = broken(den, width, "\\big/ ", "", true);
    lines.insert(lines.end(), under.begin(), under.end());
    return lines;
  }
  // A root of a long sum: its power 1/2, broken inside its parentheses.
  if (s.rfind("\\sqrt{", 0) == 0 && closing(s, 5) == s.size() - 1) {
    const auto lines = broken(s.substr(6, s.size() - 7), width, sign + "\\bigl(", "\\bigr)^{1/2}", false);
    if (lines.size() > 1) return lines;
  }
  if (auto lines = broken_in_group(s, width, sign, ""); !lines.empty()) return lines;
  return {rhs};
}

}  // namespace tackle

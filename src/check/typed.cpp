// Reading what a student typed: the characters people type (Greek letters, ×, ², √, °) in the
// parser's ASCII, and degrees as radians.
#include "check/internal.hpp"

#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "core/utf8.hpp"

namespace tackle::check_detail {

// An answer as people type it, in the parser's ASCII: Greek letters by name (θ -> theta),
// ·, × and ⋅ -> *, − and – -> -, ÷ -> /, superscript digits -> powers (x² -> x^2, x⁻¹ ->
// x^(-1)), √ -> sqrt, ° -> deg, other spaces -> ' '. `origin` gets, for each byte of the
// result, the character (0-based) of the input it comes from, for columns in messages.
std::string as_typed(std::string_view in, std::vector<int>& origin) {
  static const std::vector<std::pair<std::string_view, std::string_view>> table{
      {"\u00b7", "*"},      {"\u00d7", "*"},       {"\u22c5", "*"},     {"\u2217", "*"},      {"\u2212", "-"},
      {"\u2013", "-"},      {"\u00f7", "/"},       {"\u2215", "/"},     {"\u00a0", " "},      {"\u2009", " "},
      {"\u202f", " "},      {"\u00b0", " deg"},    {"\u03b1", "alpha"}, {"\u03b2", "beta"},   {"\u03b3", "gamma"},
      {"\u03b4", "delta"},  {"\u03b5", "epsilon"}, {"\u03b6", "zeta"},  {"\u03b7", "eta"},    {"\u03b8", "theta"},
      {"\u03d1", "theta"},  {"\u03b9", "iota"},    {"\u03ba", "kappa"}, {"\u03bb", "lambda"}, {"\u03bc", "mu"},
      {"\u00b5", "mu"},     {"\u03bd", "nu"},      {"\u03be", "xi"},    {"\u03c0", "pi"},     {"\u03c1", "rho"},
      {"\u03c3", "sigma"},  {"\u03c4", "tau"},     {"\u03c6", "phi"},   {"\u03d5", "phi"},    {"\u03c7", "chi"},
      {"\u03c8", "psi"},    {"\u03c9", "omega"},   {"\u0393", "Gamma"}, {"\u0394", "Delta"},  {"\u0398", "Theta"},
      {"\u039b", "Lambda"}, {"\u03a3", "Sigma"},   {"\u03a6", "Phi"},   {"\u03a8", "Psi"},    {"\u03a9", "Omega"}};
  static const std::vector<std::string_view> superscripts{"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                                          "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  static const std::string_view super_minus = "\u207b", root = "\u221a";
  std::string out;
  origin.clear();
  auto emit = [&](std::string_view t, int from) {
    out += t;
    origin.insert(origin.end(), t.size(), from);
  };
  auto superscript_at = [&](std::size_t i) -> int {  // the digit, 10 for minus, -1 for none
    for (int d = 0; d < 10; ++d)
      if (in.substr(i, superscripts[d].size()) == superscripts[d]) return d;
    return in.substr(i, super_minus.size()) == super_minus ? 10 : -1;
  };
  auto char_length = [&](std::size_t i) {
    const auto c = static_cast<unsigned char>(in[i]);
    return c < 0x80 ? 1 : c < 0xe0 ? 2 : c < 0xf0 ? 3 : 4;
  };
  int column = 0;
  out.reserve(in.size());
  origin.reserve(in.size() + 1);
  for (std::size_t i = 0; i < in.size();) {
    if (static_cast<unsigned char>(in[i]) < 0x80) {  // ASCII is kept (every entry above starts past it)
      out += in[i++];
      origin.push_back(column++);
      continue;
    }
    if (superscript_at(i) >= 0) {
      // A run of superscripts is one exponent.
      std::string exponent;
      const int from = column;
      while (i < in.size() && superscript_at(i) >= 0) {
        const int d = superscript_at(i);
        exponent += d == 10 ? '-' : static_cast<char>('0' + d);
        i += static_cast<std::size_t>(char_length(i));
        ++column;
      }
      emit(exponent.find('-') == std::string::npos ? "^" + exponent : "^(" + exponent + ")", from);
      continue;
    }
    if (in.substr(i, root.size()) == root) {
      // √3, √x, √(...): sqrt( of what follows (a number or a name; a parenthesis as it is).
      i += root.size();
      const int from = column++;
      if (i < in.size() && in[i] == '(') {
        emit("sqrt", from);
        continue;
      }
      emit("sqrt(", from);
      while (i < in.size() && (std::isalnum(static_cast<unsigned char>(in[i])) || in[i] == '_' || in[i] == '.')) {
        emit(in.substr(i, 1), column++);
        ++i;
      }
      emit(")", column);
      continue;
    }
    bool replaced = false;
    for (const auto& [from, to] : table)
      if (in.substr(i, from.size()) == from) {
        emit(to, column++);
        i += from.size();
        replaced = true;
        break;
      }
    if (replaced) continue;
    const int length = char_length(i);
    emit(in.substr(i, static_cast<std::size_t>(length)), column++);
    i += static_cast<std::size_t>(length);
  }
  origin.push_back(column);  // one past the end
  return out;
}

// `30 deg` -> (30*pi/180): a number followed by deg (not part of a longer name).
std::string degrees_as_radians(const std::string& in, std::vector<int>& origin) {
  std::string out;
  std::vector<int> where;
  for (std::size_t i = 0; i < in.size();) {
    const bool starts_number = (std::isdigit(static_cast<unsigned char>(in[i])) || in[i] == '.') &&
                               (i == 0 || !(std::isalnum(static_cast<unsigned char>(in[i - 1])) || in[i - 1] == '_'));
    if (starts_number) {
      std::size_t j = i;
      while (j < in.size() && (std::isdigit(static_cast<unsigned char>(in[j])) || in[j] == '.')) ++j;
      std::size_t k = j;
      while (k < in.size() && in[k] == ' ') ++k;
      // (A whole answer `30 deg` stays a number with its unit.)
      const bool whole = i == 0 && k + 3 == in.size();
      if (!whole && in.compare(k, 3, "deg") == 0 &&
          (k + 3 == in.size() || !(std::isalnum(static_cast<unsigned char>(in[k + 3])) || in[k + 3] == '_'))) {
        const std::string t = "(" + in.substr(i, j - i) + "*pi/180)";
        out += t;
        where.insert(where.end(), t.size(), origin[i]);
        i = k + 3;
        continue;
      }
    }
    out += in[i];
    where.push_back(origin[i]);
    ++i;
  }
  where.push_back(origin.back());
  origin = where;
  return out;
}

std::string trim(std::string_view s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

}  // namespace tackle::check_detail

#include "core/units.hpp"

#include "core/kind.hpp"
#include "core/utf8.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <vector>

namespace tackle {

using GiNaC::numeric;

namespace {

struct Atom {
  GiNaC::ex to_si;
  Dimension dim;
};

const std::map<std::string, Atom, std::less<>>& atoms() {
  static const std::map<std::string, Atom, std::less<>> table = {
      {"kg", {1, Dimension::mass()}},
      {"g", {numeric(1, 1000), Dimension::mass()}},
      {"t", {1000, Dimension::mass()}},
      {"m", {1, Dimension::length()}},
      {"s", {1, Dimension::time()}},
      {"min", {60, Dimension::time()}},
      {"h", {3600, Dimension::time()}},
      {"N", {1, Dimension::force()}},
      {"J", {1, Dimension::force() * Dimension::length()}},
      {"W", {1, Dimension::force() * Dimension::length() / Dimension::time()}},
      {"Pa", {1, Dimension::force() / Dimension::length().pow(2)}},
      {"Hz", {1, Dimension::time().pow(-1)}},
      {"rad", {1, Dimension::none()}},
      {"deg", {GiNaC::Pi / 180, Dimension::none()}},
      {"rpm", {GiNaC::Pi / 30, Dimension::time().pow(-1)}},  // revolutions per minute: 2 pi rad per 60 s
      {"1", {1, Dimension::none()}},
      // US customary, exact by definition (international foot and avoirdupois pound; the
      // pound-force uses standard gravity 9.80665 m/s^2).
      {"ft", {numeric(3048, 10000), Dimension::length()}},
      {"in", {numeric(254, 10000), Dimension::length()}},
      {"yd", {numeric(9144, 10000), Dimension::length()}},
      {"mi", {numeric(1609344, 1000), Dimension::length()}},
      {"mph", {numeric(1609344, 3600000), Dimension::velocity()}},
      {"lbm", {numeric(45359237, 100000000), Dimension::mass()}},
      {"lbf", {numeric(45359237, 100000000) * numeric(980665, 100000), Dimension::force()}},
      {"kip", {numeric(45359237, 100000) * numeric(980665, 100000), Dimension::force()}},
      {"slug", {numeric(45359237, 100000000) * numeric(980665, 100000) / numeric(3048, 10000), Dimension::mass()}},
      {"pdl", {numeric(45359237, 100000000) * numeric(3048, 10000), Dimension::force()}},
  };
  return table;
}

const std::vector<std::pair<std::string, numeric>>& prefixes() {
  static const std::vector<std::pair<std::string, numeric>> table = {
      {"G", numeric(1000000000)}, {"M", numeric(1000000)},    {"k", numeric(1000)},       {"c", numeric(1, 100)},
      {"m", numeric(1, 1000)},    {"u", numeric(1, 1000000)}, {"µ", numeric(1, 1000000)}, {"n", numeric(1, 1000000000)},
  };
  return table;
}

// SI units take prefixes; kg, min, h, a bare number and the US customary units do not.
bool is_si_atom(std::string_view name) {
  for (const char* s : {"g", "t", "m", "s", "N", "J", "W", "Pa", "Hz", "rad"})
    if (name == s) return true;
  return false;
}

std::optional<Atom> find_atom(std::string_view name) {
  if (auto it = atoms().find(name); it != atoms().end()) return it->second;
  for (const auto& [p, f] : prefixes()) {
    if (name.size() > p.size() && name.substr(0, p.size()) == p) {
      auto it = atoms().find(name.substr(p.size()));
      // Prefixes go on SI units, not on kg, min, h or a bare number.
      if (it != atoms().end() && is_si_atom(it->first)) return Atom{f * it->second.to_si, it->second.dim};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Unit> parse_unit(std::string_view text, std::string& error, int& error_column) {
  Unit u{1, Dimension::none(), std::string(text)};
  std::size_t i = 0;
  int sign = 1;  // +1 after '*' or at start, -1 after '/'
  bool expect_atom = true;
  auto skip_space = [&] {
    while (i < text.size() && text[i] == ' ') ++i;
  };
  skip_space();
  if (i == text.size()) {
    error = "empty unit";
    error_column = 0;
    return std::nullopt;
  }
  while (i < text.size()) {
    skip_space();
    if (expect_atom) {
      const std::size_t start = i;
      while (i < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[i])) || static_cast<unsigned char>(text[i]) >= 0x80))
        ++i;
      if (start == i) {
        error = "expected a unit name";
        error_column = static_cast<int>(start);
        return std::nullopt;
      }
      const std::string_view name = text.substr(start, i - start);
      auto atom = find_atom(name);
      if (!atom) {
        error = "unknown unit '" + printable(name) + "'";
        error_column = static_cast<int>(start);
        return std::nullopt;
      }
      int power = 1;
      if (i < text.size() && text[i] == '^') {
        ++i;
        const std::size_t pstart = i;
        int psign = 1;
        if (i < text.size() && text[i] == '-') {
          psign = -1;
          ++i;
        }
        const std::size_t dstart = i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
        if (dstart == i || i - dstart > 2) {
          error = "expected a small integer exponent";
          error_column = static_cast<int>(pstart);
          return std::nullopt;
        }
        power = psign * std::stoi(std::string(text.substr(dstart, i - dstart)));
      }
      const int p = sign * power;
      u.to_si = u.to_si * GiNaC::pow(atom->to_si, p);
      u.dimension = u.dimension * atom->dim.pow(p);
      expect_atom = false;
    } else {
      if (text[i] == '*' || text[i] == '.') {
        sign = 1;
      } else if (text[i] == '/') {
        sign = -1;
      } else {
        error = "unexpected '" + printable(utf8_char_at(text, i)) + "' in unit";
        error_column = static_cast<int>(i);
        return std::nullopt;
      }
      ++i;
      expect_atom = true;
    }
    skip_space();
  }
  if (expect_atom) {
    error = "unit ends after an operator";
    error_column = static_cast<int>(text.size());
    return std::nullopt;
  }
  return u;
}

namespace {

// Named dimensions: what a message calls them, the `dimension:` key, and the SI unit printed.
struct Named {
  Dimension dimension;
  const char* description;
  const char* key;
  const char* si_unit;
};

const std::vector<Named>& named_dimensions() {
  static const std::vector<Named> table = {
      {Dimension::none(), "dimensionless", "dimensionless", ""},
      {Dimension::mass(), "mass", "mass", "kg"},
      {Dimension::length(), "length", "length", "m"},
      {Dimension::time(), "time", "time", "s"},
      {Dimension::force(), "force", "force", "N"},
      {Dimension::velocity(), "velocity", "velocity", "m/s"},
      {Dimension::acceleration(), "acceleration", "acceleration", "m/s^2"},
      {Dimension::force() / Dimension::length(), "stiffness (force per length)", "stiffness", "N/m"},
      {Dimension::force() / Dimension::velocity(), "damping coefficient (force per velocity)", "damping", "N*s/m"},
      {Dimension::force() * Dimension::length(), "moment (or energy)", "moment", "N*m"},
      {Dimension::force() * Dimension::length(), "energy", "energy", "J"},
      {Dimension::force() * Dimension::length() / Dimension::time(), "power", "power", "W"},
      {Dimension::force() * Dimension::time(), "impulse (or momentum)", "impulse", "N*s"},
      {Dimension{{0, 0, -1}}, "angular velocity (or frequency)", "angular_velocity", "rad/s"},
      {Dimension{{0, 0, -2}}, "angular acceleration", "angular_acceleration", "rad/s^2"},
      {Dimension::mass() * Dimension::length() * Dimension::length(), "moment of inertia", "inertia", "kg*m^2"},
  };
  return table;
}

// "mass^a length^b time^c" or "kg^a*m^b*s^c" for a dimension without a name.
std::string compose(const Dimension& d, const char* const base[3], const char* sep) {
  std::string s;
  for (int i = 0; i < 3; ++i) {
    if (d.exp[i] == 0) continue;
    if (!s.empty()) s += sep;
    s += base[i];
    if (d.exp[i] != 1) s += "^" + std::to_string(d.exp[i]);
  }
  return s;
}

}  // namespace

std::string Dimension::describe() const {
  for (const auto& n : named_dimensions())
    if (n.dimension == *this) return n.description;
  static const char* const base[] = {"mass", "length", "time"};
  return compose(*this, base, " ");
}

std::optional<Dimension> Dimension::from_name(std::string_view name) {
  for (const auto& n : named_dimensions())
    if (name == n.key) return n.dimension;
  return std::nullopt;
}

std::string si_unit_name(const Dimension& d) {
  for (const auto& n : named_dimensions())
    if (n.dimension == d) return n.si_unit;
  static const char* const base[] = {"kg", "m", "s"};
  return compose(d, base, "*");
}

const Unit& joule() {
  static const Unit j = [] {
    std::string error;
    int column = 0;
    return *parse_unit("J", error, column);
  }();
  return j;
}

std::string unit_latex(std::string_view unit_text) {
  if (unit_text == "deg") return "{}^{\\circ}";  // 30^{\circ}, as a book sets an angle
  std::string out = "\\mathrm{";
  for (std::size_t i = 0; i < unit_text.size(); ++i) {
    const char c = unit_text[i];
    if (c == '^') {
      std::size_t j = i + 1;
      std::string e;
      if (j < unit_text.size() && unit_text[j] == '-') e += unit_text[j++];
      while (j < unit_text.size() && std::isdigit(static_cast<unsigned char>(unit_text[j]))) e += unit_text[j++];
      out += "^{" + e + "}";
      i = j - 1;
    } else if (c == '*' || c == '.') {
      out += "\\,";
    } else {
      out += c;
    }
  }
  return out + "}";
}

std::string with_article(const std::string& noun) {
  if (noun == "dimensionless") return "a pure number";
  const bool vowel = !noun.empty() && std::string("aeiou").find(noun[0]) != std::string::npos;
  return (vowel ? "an " : "a ") + noun;
}

std::optional<Dimension> dimension_of(const GiNaC::ex& e, const DimensionLookup& lookup, std::string& problem) {
  using namespace GiNaC;
  // Class by class-info (is_a<> is a dynamic_cast: a check spent a tenth of its time there).
  if (is_exactly<numeric>(e) || is_exactly<GiNaC::constant>(e)) return Dimension::none();
  if (is_exactly<symbol>(e)) return lookup.dimension_of(ex_to<symbol>(e));
  // A sum's terms and a product's factors are all looked at, and what is said does not depend
  // on their order (GiNaC's order follows hashes of addresses, which differ between runs): the
  // first problem in text order, else the two dimensions first in name order.
  const auto parts = [&](std::vector<Dimension>& dims) {
    std::optional<std::string> first_problem;
    bool unknown = false;
    for (const auto& part : e) {
      std::string p;
      if (auto d = dimension_of(part, lookup, p))
        dims.push_back(*d);
      else if (p.empty())
        unknown = true;
      else if (!first_problem || p < *first_problem)
        first_problem = p;
    }
    if (first_problem) problem = *first_problem;
    return !first_problem && !unknown;
  };
  if (is_exactly<add>(e)) {
    std::vector<Dimension> dims;
    if (!parts(dims)) return std::nullopt;
    if (std::all_of(dims.begin(), dims.end(), [&](const Dimension& d) { return d == dims.front(); }))
      return dims.front();
    std::vector<std::string> names;
    for (std::size_t i = 0; i < dims.size(); ++i)  // each distinct dimension once
      if (std::none_of(dims.begin(), dims.begin() + static_cast<std::ptrdiff_t>(i),
                       [&](const Dimension& x) { return x == dims[i]; }))
        names.push_back(dims[i].describe());
    std::sort(names.begin(), names.end());
    problem = "adds " + with_article(names[0]) + " to " + with_article(names[1]);
    return std::nullopt;
  }
  if (is_exactly<mul>(e)) {
    std::vector<Dimension> dims;
    if (!parts(dims)) return std::nullopt;
    Dimension total;
    for (const auto& d : dims) total = total * d;
    return total;
  }
  if (is_exactly<power>(e)) {
    auto base = dimension_of(e.op(0), lookup, problem);
    if (!base) return std::nullopt;
    const ex expo = e.op(1);
    if (base->exp == Dimension::none().exp) return Dimension::none();
    if (is_exactly<numeric>(expo)) {
      const numeric n = ex_to<numeric>(expo);
      if (n.is_integer()) return base->pow(n.to_int());
      if (n.is_rational()) {
        const int den = n.denom().to_int();
        Dimension r;
        for (int i = 0; i < 3; ++i) {
          if ((base->exp[i] * n.numer().to_int()) % den != 0) {
            problem = "takes a fractional power of a " + base->describe();
            return std::nullopt;
          }
          r.exp[i] = base->exp[i] * n.numer().to_int() / den;
        }
        return r;
      }
    }
    problem = "raises " + with_article(base->describe()) + " to a non-numeric power";
    return std::nullopt;
  }
  if (is_a<function>(e)) {
    // sin, cos, tan, exp, log...: arguments must be dimensionless; abs keeps the dimension.
    const std::string name = ex_to<function>(e).get_name();
    auto arg = dimension_of(e.op(0), lookup, problem);
    if (!arg) return std::nullopt;
    if (name == "abs") return arg;
    if (!(*arg == Dimension::none())) {
      problem = "takes " + name + " of " + with_article(arg->describe());
      return std::nullopt;
    }
    return Dimension::none();
  }
  problem = "has a term whose dimension tackle cannot tell";
  return std::nullopt;
}

}  // namespace tackle

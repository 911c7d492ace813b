// The helpers every stage shares: claiming names, parsing, checking dimensions, reading
// vectors and reporting unknown names.
#include "model/builder/context.hpp"

#include "core/units.hpp"
#include "expr/print.hpp"
#include "expr/rational.hpp"

namespace tackle::build {

using namespace GiNaC;

bool BuildContext::claim_in(std::map<std::string, Location>& names_in_use, const Text& name, const std::string& what) {
  if (!is_identifier(name.text)) {
    diags.error(name.at,
                what + " name '" + name.text + "' is not a valid name (expected a letter, then letters, digits or _)");
    return false;
  }
  if (auto it = names_in_use.find(name.text); it != names_in_use.end() && it->second.line == 0 && name.text == "t") {
    diags.error(name.at, "'t' is time (expected another name for this " + what + ")");
    return false;
  } else if (it != names_in_use.end()) {
    diags.error(name.at,
                "duplicate name '" + name.text + "' (first defined at line " + std::to_string(it->second.line) + ")");
    return false;
  }
  names_in_use[name.text] = name.at;
  return true;
}

std::optional<ex> BuildContext::parse(const Text& t, const NameResolver& names, const std::string& what) {
  auto r = parse_expression(t.text, names);
  for (const auto& p : r.problems) diags.error(t.at.shifted(p.column), what + ": " + p.message);
  return r.value;
}

std::optional<ex> BuildContext::number_in_parameters(const Text& t, const std::string& what,
                                                     std::optional<Dimension> expected) {
  const auto v = parse(t, *table, what);
  if (!v) return std::nullopt;
  for (const ex& x : distinct_symbols(*v)) {
    const SymbolInfo* s = table->find(x);
    if (s && s->role == SymbolRole::parameter) continue;
    diags.error(t.at, what + ": '" + to_text(x) +
                          "' is not a parameter (expected a number or an expression in the parameters)");
    return std::nullopt;
  }
  if (expected && !is_a<numeric>(*v)) check_dimension(*v, *expected, t.at, what);
  const ex at = substituted(*v, table->values());
  if (const auto missing = distinct_symbols(at); !missing.empty()) {
    diags.error(t.at, what + ": '" + to_text(missing.front()) +
                          "' has no value (expected a number, or parameters with values)");
    return std::nullopt;
  }
  return at;
}

void BuildContext::check_dimension(const ex& e, const Dimension& expected, const Location& at,
                                   const std::string& what) {
  std::string problem;
  auto dim = dimension_of(e, *table, problem);
  if (!dim) {
    if (!problem.empty()) diags.error(at, what + " " + problem + " (expected a " + expected.describe() + ")");
    return;
  }
  if (!(*dim == expected))
    diags.error(
        at, what + " is " + with_article(dim->describe()) + " (expected " + with_article(expected.describe()) + ")");
}

std::optional<Vec> BuildContext::vector(const VectorDesc& v, const NameResolver& names, const std::string& what,
                                        std::optional<Dimension> expected) {
  if (static_cast<int>(v.items.size()) != m.dims()) {
    diags.error(v.at, what + " has " + std::to_string(v.items.size()) + (v.items.size() == 1 ? " entry" : " entries") +
                          " (expected " + std::to_string(m.dims()) + ", one per axis: " + join(m.axes) + ")");
    return std::nullopt;
  }
  Vec out = zero_vec();
  bool ok = true;
  for (std::size_t i = 0; i < v.items.size(); ++i) {
    auto e = parse(v.items[i], names, what);
    if (!e) {
      ok = false;
      continue;
    }
    if (is_vector(*e)) {
      diags.error(v.items[i].at, what + ": an entry is a vector (expected a number)");
      ok = false;
      continue;
    }
    if (expected && !is_a<numeric>(*e)) check_dimension(*e, *expected, v.items[i].at, what);
    out[i] = *e;
  }
  if (!ok) return std::nullopt;
  return out;
}

std::vector<std::string> BuildContext::body_names() const {
  std::vector<std::string> n;
  for (const auto& b : m.bodies) n.push_back(b.name);
  return n;
}
std::vector<std::string> BuildContext::point_names() const {
  std::vector<std::string> n;
  for (const auto& p : m.points) n.push_back(p.name);
  return n;
}

void BuildContext::unknown_name(const Text& t, const std::string& kind, const std::vector<std::string>& known) {
  std::string msg = "unknown " + kind + " '" + t.text + "'";
  if (auto near = nearest(t.text, known); !near.empty())
    msg += " (did you mean '" + near + "'?)";
  else if (!known.empty())
    msg += " (known: " + join(known) + ")";
  diags.error(t.at, msg);
}

const GiNaC::exmap& BuildContext::coordinates_at_zero() {
  if (coordinates_at_zero_bodies_ != m.coordinates.size() || coordinates_at_zero_.empty()) {
    coordinates_at_zero_.clear();
    for (const auto& c : m.coordinates) coordinates_at_zero_[c.q] = 0;
    coordinates_at_zero_bodies_ = m.coordinates.size();
  }
  return coordinates_at_zero_;
}

}  // namespace tackle::build

#include "description/yaml_reader.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

#include "core/utf8.hpp"

namespace tackle::yaml {

Location where(const YAML::Node& n, const std::string& file) {
  const YAML::Mark m = n.Mark();
  if (m.line < 0) return {file, 0, 0};
  // A quoted scalar's mark is its opening quote (yaml-cpp tags quoted scalars "!"); columns
  // inside it count from the first character after the quote.
  const int quote = (n.IsScalar() && n.Tag() == "!") ? 1 : 0;
  return {file, m.line + 1, m.column + 1 + quote};
}

YAML::Node load(const std::string& text, const std::string& file, Diagnostics& diags) {
  if (const auto bad = invalid_utf8_at(text)) {
    const auto line_start = text.rfind('\n', *bad == 0 ? 0 : *bad - 1);
    const std::size_t col = line_start == std::string::npos || *bad == 0 ? *bad + 1 : *bad - line_start;
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(*bad), '\n'));
    diags.error({file, line, static_cast<int>(col)},
                fmt::format("invalid UTF-8 byte 0x{:02X} (expected UTF-8 text)", static_cast<unsigned char>(text[*bad])));
    return YAML::Node();
  }
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    diags.error({file, e.mark.line + 1, e.mark.column + 1}, "invalid YAML: " + e.msg);
  }
  return YAML::Node();
}

std::string kind_name(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map: return "a mapping";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Scalar: return "a scalar";
    default: return "nothing";
  }
}

bool is_list(const YAML::Node& n, const std::string& what, const std::string& file, Diagnostics& diags) {
  if (n.IsSequence()) return true;
  diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a list)");
  return false;
}

bool check_map(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what,
               const std::string& file, Diagnostics& diags) {
  if (!map.IsMap()) {
    diags.error(where(map, file), what + " is " + kind_name(map) + " (expected a mapping)");
    return false;
  }
  std::set<std::string> seen;
  for (const auto& kv : map) {
    if (!kv.first.IsScalar()) {
      diags.error(where(kv.first, file), "a key in " + what + " is " + kind_name(kv.first) + " (expected a name)");
      continue;
    }
    const std::string key = kv.first.Scalar();
    if (!seen.insert(key).second) {
      diags.error(where(kv.first, file), "duplicate key '" + key + "' in " + what);
      continue;
    }
    bool ok = false;
    for (const auto& a : allowed) ok = ok || a == key;
    if (!ok) {
      std::string msg = "unknown key '" + key + "' in " + what;
      if (auto near = nearest(key, allowed); !near.empty())
        msg += " (did you mean '" + near + "'?)";
      else
        msg += " (expected one of: " + join(allowed) + ")";
      diags.error(where(kv.first, file), msg);
    }
  }
  return true;
}

void check_unique_keys(const YAML::Node& map, const std::string& what, const std::string& file, Diagnostics& diags) {
  std::set<std::string> seen;
  for (const auto& kv : map)
    if (kv.first.IsScalar() && !seen.insert(kv.first.Scalar()).second)
      diags.error(where(kv.first, file), "duplicate key '" + kv.first.Scalar() + "' in " + what);
}

std::optional<Text> scalar(const YAML::Node& n, const std::string& what, const std::string& file,
                           Diagnostics& diags) {
  if (!n.IsScalar()) {
    diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a scalar)");
    return std::nullopt;
  }
  return Text{n.Scalar(), where(n, file)};
}

std::optional<std::vector<Text>> scalar_list(const YAML::Node& n, const std::string& what,
                                             const std::string& file, Diagnostics& diags) {
  std::vector<Text> out;
  if (n.IsScalar()) {
    out.push_back({n.Scalar(), where(n, file)});
    return out;
  }
  if (!n.IsSequence()) {
    diags.error(where(n, file), what + " is " + kind_name(n) + " (expected a list of names)");
    return std::nullopt;
  }
  bool ok = true;
  for (const auto& item : n) {
    if (auto t = scalar(item, "an item of " + what, file, diags))
      out.push_back(*t);
    else
      ok = false;
  }
  if (!ok) return std::nullopt;
  return out;
}

}  // namespace tackle::yaml

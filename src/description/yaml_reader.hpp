// Small helpers over yaml-cpp for located, schema-checked reading (shared by the description
// and rule readers).
#pragma once

#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/diagnostics.hpp"
#include "description/description.hpp"

namespace tackle::yaml {

/// Location of a node (yaml-cpp marks are 0-based).
Location where(const YAML::Node& n, const std::string& file);

/// Loads a YAML document; a syntax error is reported as a located diagnostic and a null node
/// is returned.
YAML::Node load(const std::string& text, const std::string& file, Diagnostics& diags);

/// Checks the keys of a map: unknown keys (with the nearest allowed key suggested) and
/// duplicate keys are reported. Returns false when the node is not a map.
/// True for a sequence; otherwise reports "WHAT is a mapping (expected a list)".
bool is_list(const YAML::Node& n, const std::string& what, const std::string& file, Diagnostics& diags);

bool check_map(const YAML::Node& map, const std::vector<std::string>& allowed, const std::string& what,
               const std::string& file, Diagnostics& diags);

/// Reports keys that occur twice in a map (yaml-cpp keeps both).
void check_unique_keys(const YAML::Node& map, const std::string& what, const std::string& file, Diagnostics& diags);

/// A scalar as located text; reports and returns nullopt when the node is not a scalar.
std::optional<Text> scalar(const YAML::Node& n, const std::string& what, const std::string& file,
                           Diagnostics& diags);

/// A scalar or a list of scalars.
std::optional<std::vector<Text>> scalar_list(const YAML::Node& n, const std::string& what,
                                             const std::string& file, Diagnostics& diags);

/// "a mapping", "a list", "a scalar" for messages.
std::string kind_name(const YAML::Node& n);

}  // namespace tackle::yaml

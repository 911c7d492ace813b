// How a person orders indexed names (m_2 before m_10): the printer's sums and factors are
// sorted by it.
#pragma once

#include <string>

namespace tackle {

/// Keys compared with their digit runs as numbers (m_2 before m_10), the way a person orders
/// indexed names; otherwise as strings.
[[nodiscard]] bool natural_less(const std::string& a, const std::string& b);

}  // namespace tackle

// TeX for plain prose: the characters TeX treats specially, escaped. Shared by the writers.
#pragma once

#include <string>

namespace tackle {

[[nodiscard]] std::string tex_escape(const std::string& s);

}  // namespace tackle

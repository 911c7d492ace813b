// The {name} placeholders of a problem's statement: a brace that opens right after a letter,
// a digit, '_' or '^' is LaTeX's (\ddot{x}, x_{A}) and stays as it is.
#pragma once

#include <cctype>
#include <string_view>
#include <vector>

namespace tackle {

struct Placeholder {
  std::size_t open = 0, close = 0;  // the positions of '{' and '}'
  std::string_view name;
};

[[nodiscard]] inline std::vector<Placeholder> placeholders(std::string_view text) {
  std::vector<Placeholder> out;
  for (std::size_t open = text.find('{'); open != std::string_view::npos; open = text.find('{', open + 1)) {
    if (open > 0) {
      const auto before = static_cast<unsigned char>(text[open - 1]);
      if (std::isalnum(before) || before == '_' || before == '^' || before == '{') continue;
    }
    const std::size_t close = text.find('}', open);
    if (close == std::string_view::npos) break;
    out.push_back({open, close, text.substr(open + 1, close - open - 1)});
  }
  return out;
}

}  // namespace tackle

// UTF-8 validation: descriptions, rules and answers are text; a byte that is not valid UTF-8
// is reported where it stands, before any reader or JSON writer sees it.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace tackle {

/// The offset of the first byte that does not begin a valid UTF-8 sequence (overlong forms,
/// surrogates and code points above U+10FFFF are invalid), or nothing when all is valid.
[[nodiscard]] inline std::optional<std::size_t> invalid_utf8_at(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t n = 0;
    unsigned long cp = 0, min = 0;
    if ((c & 0xE0) == 0xC0) n = 1, cp = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0) n = 2, cp = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0) n = 3, cp = c & 0x07, min = 0x10000;
    else return i;
    if (i + n >= s.size()) return i;  // a sequence cut short by the end
    for (std::size_t k = 1; k <= n; ++k) {
      const auto d = static_cast<unsigned char>(s[i + k]);
      if ((d & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (d & 0x3F);
    }
    if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
    i += n + 1;
  }
  return std::nullopt;
}

}  // namespace tackle

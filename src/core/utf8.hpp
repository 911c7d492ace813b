// UTF-8 validation: descriptions, rules and answers are text; a byte that is not valid UTF-8
// is reported where it stands, before any reader or JSON writer sees it.
#pragma once

#include <cstddef>
#include <cstdio>
#include <optional>
#include <string>
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
    if ((c & 0xE0) == 0xC0)
      n = 1, cp = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0)
      n = 2, cp = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0)
      n = 3, cp = c & 0x07, min = 0x10000;
    else
      return i;
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

/// The bytes of the one character at `i`: a whole UTF-8 sequence when one starts there, else
/// the one byte.
[[nodiscard]] inline std::string_view utf8_char_at(std::string_view s, std::size_t i) {
  const auto c = static_cast<unsigned char>(s[i]);
  const std::size_t n = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 1;
  if (n > 1 && invalid_utf8_at(s.substr(i, n)) == std::nullopt) return s.substr(i, n);
  return s.substr(i, 1);
}

/// Text from input made safe to echo in a message: whole UTF-8 characters as they are;
/// control characters (C0, DEL, C1), invisible format characters that reorder or hide text
/// (bidirectional overrides, zero-width spaces, line separators, the byte order mark) and
/// bytes that are not UTF-8 escaped (`\x07`, `\u202E`, `\xE9`).
[[nodiscard]] inline std::string printable(std::string_view s) {
  std::string out;
  char buf[16];
  for (std::size_t i = 0; i < s.size();) {
    const std::string_view ch = utf8_char_at(s, i);
    const auto c = static_cast<unsigned char>(s[i]);
    i += ch.size();
    if (ch.size() == 1) {
      if (c >= 0x20 && c < 0x7F) {
        out += static_cast<char>(c);
      } else {
        std::snprintf(buf, sizeof buf, "\\x%02X", c);
        out += buf;
      }
      continue;
    }
    unsigned long cp = ch.size() == 2 ? c & 0x1Fu : ch.size() == 3 ? c & 0x0Fu : c & 0x07u;
    for (std::size_t k = 1; k < ch.size(); ++k) cp = (cp << 6) | (static_cast<unsigned char>(ch[k]) & 0x3Fu);
    const bool hidden = (cp >= 0x80 && cp <= 0x9F) || (cp >= 0x200B && cp <= 0x200F) ||
                        (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069) || cp == 0xFEFF;
    if (hidden) {
      std::snprintf(buf, sizeof buf, "\\u%04lX", cp);
      out += buf;
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace tackle

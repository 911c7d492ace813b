#include "core/diagnostics.hpp"

#include <algorithm>
#include <cctype>

namespace tackle {

Location Location::shifted(int offset) const {
  Location l = *this;
  if (l.column > 0) l.column += offset;
  return l;
}

std::string format(const Diagnostic& d) {
  std::string out;
  if (!d.where.file.empty()) out += d.where.file + ":";
  if (d.where.line > 0) {
    out += std::to_string(d.where.line) + ":";
    if (d.where.column > 0) out += std::to_string(d.where.column) + ":";
  }
  if (!out.empty()) out += " ";
  return out + d.message;
}

void Diagnostics::error(Location where, std::string message) {
  items_.push_back({std::move(where), std::move(message)});
}

void Diagnostics::throw_if_any() const {
  if (!items_.empty()) throw InputError(items_);
}

static std::string summary(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const auto& d : ds) s += format(d) + "\n";
  return s;
}

InputError::InputError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error(summary(diagnostics)), diagnostics_(std::move(diagnostics)) {}

static std::size_t distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same =
          std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearest(std::string_view word, const std::vector<std::string>& candidates) {
  // By kind first: a bare letter that names a kind of quantity, T for the tension T_s, m for
  // m_A, is meant as the name that letter starts (not t, time, one case away).
  if (!word.empty() && word.find('_') == std::string_view::npos)
    for (const auto& c : candidates)
      if (c.size() > word.size() + 1 && c.compare(0, word.size(), word) == 0 && c[word.size()] == '_') return c;
  std::string best;
  std::size_t best_d = 0;
  for (const auto& c : candidates) {
    const std::size_t d = distance(word, c);
    if (best.empty() || d < best_d) {
      best = c;
      best_d = d;
    }
  }
  // Close enough to be a plausible typo: at most a third of the longer word (so one- and
  // two-letter names are suggested only when they differ in case).
  const std::size_t limit = std::max(word.size(), best.size()) / 3;
  return (!best.empty() && best_d <= limit) ? best : std::string{};
}

std::string join(const std::vector<std::string>& words, std::string_view sep) {
  std::string s;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i) s += sep;
    s += words[i];
  }
  return s;
}

}  // namespace tackle

// One interface for every output format. A format is one class in one file
// (src/report/writers/<format>.cpp) that writes each kind of document it has: a derivation
// (derive, solve), the phases of a phased description, an answer key, problem sheets, the
// isolations. The documents themselves are narrated elsewhere (Derivation, KeyEntry,
// SheetEntry, Isolation): writers only format them.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "isolate/isolate.hpp"
#include "report/derivation.hpp"
#include "report/key.hpp"
#include "report/sheet.hpp"

namespace tackle {

class Writer {
 public:
  virtual ~Writer() = default;
  [[nodiscard]] virtual const char* name() const = 0;
  /// `full`: the whole derivation; otherwise the answers only (`tackle solve`).
  [[nodiscard]] virtual std::string derivation(const Derivation& d, bool full) const = 0;
  /// A phased description's phases, one after the other, as one document.
  [[nodiscard]] virtual std::string phases(const std::vector<Derivation>& ds, bool full) const = 0;
  /// The same two documents written to `out` as they are made: a format whose document is
  /// long (a chain's answers: 88 MB for 2048 blocks) writes it piece by piece, never holding
  /// it whole. By default the text made whole, then written.
  virtual void derivation_to(std::ostream& out, const Derivation& d, bool full) const { out << derivation(d, full); }
  virtual void phases_to(std::ostream& out, const std::vector<Derivation>& ds, bool full) const {
    out << phases(ds, full);
  }
  // Documents a format may not have (the command line offers only those it has; asking a
  // format for another is a bug, reported as an internal error).
  [[nodiscard]] virtual std::string key(const std::vector<KeyEntry>& entries) const;
  [[nodiscard]] virtual std::string sheet(const std::vector<SheetEntry>& entries, bool figures) const;
  [[nodiscard]] virtual std::string isolations(const Model& m, const std::vector<Isolation>& found) const;
};

/// Every format with its writer, in the order the help lists them (writers/formats.cpp): a new
/// format is its writer's file, its Format and its line there.
[[nodiscard]] const std::vector<std::pair<Format, const Writer*>>& all_formats();
[[nodiscard]] const Writer& writer_for(Format f);
/// The format whose writer has this name (text, latex, markdown, json, html), or none.
[[nodiscard]] std::optional<Format> format_named(std::string_view name);
/// The formats' names, in the order of all_formats().
[[nodiscard]] std::vector<std::string> format_names();

}  // namespace tackle

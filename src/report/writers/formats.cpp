// The formats by name: each format's writer, in the order the help lists them. A new format
// is its writer's file (writers/<format>.cpp), its Format, and its line here.
#include <algorithm>
#include <stdexcept>

#include "report/writer.hpp"

namespace tackle {

const Writer& text_writer();
const Writer& latex_writer();
const Writer& markdown_writer();
const Writer& json_writer();
const Writer& html_writer();

const std::vector<std::pair<Format, const Writer*>>& all_formats() {
  static const std::vector<std::pair<Format, const Writer*>> all{{Format::text, &text_writer()},
                                                                 {Format::latex, &latex_writer()},
                                                                 {Format::markdown, &markdown_writer()},
                                                                 {Format::json, &json_writer()},
                                                                 {Format::html, &html_writer()}};
  return all;
}

const Writer& writer_for(Format f) {
  for (const auto& [format, writer] : all_formats())
    if (format == f) return *writer;
  throw std::logic_error("no writer for this format");
}

std::optional<Format> format_named(std::string_view name) {
  for (const auto& [format, writer] : all_formats())
    if (name == writer->name()) return format;
  return std::nullopt;
}

std::vector<std::string> format_names() {
  std::vector<std::string> names;
  for (const auto& [format, writer] : all_formats()) names.emplace_back(writer->name());
  return names;
}

}  // namespace tackle

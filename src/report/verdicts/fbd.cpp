// A graded free body diagram written: text and JSON.
#include <fmt/format.h>

#include "core/utf8.hpp"
#include "report/verdicts.hpp"

namespace tackle {

std::string fbd_text(const FbdGrade& g) {
  std::string out = fmt::format("free body diagram of {}: {}: {}\n", g.of, verdict_name(g.verdict), g.summary);
  for (const auto& f : g.forces) {
    std::string status = f.status == "drawn"             ? "drawn"
                         : f.status == "wrong_direction" ? "drawn the wrong way"
                         : f.status == "wrong_point"     ? "drawn at the wrong point"
                         : f.status == "off_line"        ? "drawn off its line"
                         : f.status == "zero"            ? "nothing at this position (not needed)"
                                                         : "missing";
    std::vector<std::string> names;
    for (const auto& n : f.drawn_as) names.push_back(n.empty() ? "(no name)" : n);
    if (!names.empty()) status += " as your " + join(names);
    out += fmt::format("  {}{}: {}\n", f.phrase,
                       f.label.empty() || f.phrase.find(" part)") != std::string::npos ? "" : " (" + f.label + ")",
                       status);
  }
  for (const auto& e : g.extras) out += "  extra: " + e.message + "\n";
  if (g.verdict == Verdict::correct || g.verdict == Verdict::incorrect)
    out += fmt::format("score: {:g} of {:g}\n", g.score, g.max_score);
  return out;
}

std::string fbd_json(const FbdGrade& g) {
  std::string out = "{\n  \"version\": 1,\n  \"of\": " + json_quoted(g.of) +
                    ",\n  \"verdict\": " + json_quoted(verdict_name(g.verdict)) +
                    ",\n  \"summary\": " + json_quoted(g.summary) + ",\n  \"forces\": [";
  for (std::size_t i = 0; i < g.forces.size(); ++i) {
    const auto& f = g.forces[i];
    std::string names = "[";
    for (std::size_t k = 0; k < f.drawn_as.size(); ++k) names += (k ? ", " : "") + json_quoted(f.drawn_as[k]);
    out += fmt::format(
        "{}\n    {{\"source\": {}, \"phrase\": {}, \"label\": {}, \"status\": {}, \"drawn_as\": {}], \"weight\": {}, "
        "\"score\": {}}}",
        i ? "," : "", json_quoted(f.source), json_quoted(f.phrase), json_quoted(f.label), json_quoted(f.status), names,
        json_number(f.weight), json_number(f.score));
  }
  out += g.forces.empty() ? "],\n" : "\n  ],\n";
  out += "  \"extras\": [";
  for (std::size_t i = 0; i < g.extras.size(); ++i)
    out += fmt::format("{}\n    {{\"name\": {}, \"code\": {}, \"message\": {}}}", i ? "," : "",
                       json_quoted(g.extras[i].name), json_quoted(g.extras[i].code), json_quoted(g.extras[i].message));
  out += g.extras.empty() ? "],\n" : "\n  ],\n";
  out += "  \"findings\": [";
  for (std::size_t i = 0; i < g.findings.size(); ++i)
    out += fmt::format("{}\n    {{\"code\": {}, \"message\": {}}}", i ? "," : "", json_quoted(g.findings[i].code),
                       json_quoted(g.findings[i].message));
  out += g.findings.empty() ? "],\n" : "\n  ],\n";
  out += "  \"score\": " + json_number(g.score) + ",\n  \"max_score\": " + json_number(g.max_score) + "\n}\n";
  return out;
}

}  // namespace tackle

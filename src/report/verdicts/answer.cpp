// A checked answer's or equation's verdict written: a batch's JSON line, a JSON object, text;
// and the JSON pieces every verdict writer uses (a quoted string, a number, a platform's test).
#include <cmath>
#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/utf8.hpp"
#include "report/verdicts.hpp"

namespace tackle {

namespace {

nlohmann::ordered_json to_json(const CheckResult& r, const std::string& answer, const std::string& id) {
  nlohmann::ordered_json j;
  if (!id.empty()) j["id"] = id;
  j["unknown"] = r.unknown;
  j["answer"] = answer;
  j["verdict"] = verdict_name(r.verdict);
  j["score"] = r.score;
  j["summary"] = r.summary;
  j["findings"] = nlohmann::ordered_json::array();
  for (const auto& f : r.findings) j["findings"].push_back({{"code", f.code}, {"message", f.message}});
  j["method"] = r.method;
  j["read_as"] = r.echo_text;
  j["latex"] = r.echo_latex;
  if (r.equation) {
    j["identified_as"] = r.identified_as;
    j["follows_from"] = r.follows_from;
  }
  return j;
}

// `s` as a JSON string, as nlohmann's dump writes it (UTF-8 as it is, control characters
// escaped), appended to `out`; a batch writes thousands of lines, and building a JSON object
// for each was a sixth of a check.
void append_quoted(std::string& out, std::string_view s) {
  if (invalid_utf8_at(s)) {  // (bytes that are not UTF-8: replaced, as the library does it)
    out += nlohmann::json(std::string(s)).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    return;
  }
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20)
          out += fmt::format("\\u{:04x}", c);
        else
          out += ch;
    }
  }
  out += '"';
}

// A number as nlohmann's dump writes a double: the shortest form that reads back, with ".0"
// when it is whole.
void append_number(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  const std::string n = fmt::format("{}", v);
  out += n;
  if (n.find_first_of(".eE") == std::string::npos) out += ".0";
}

}  // namespace

std::string json_quoted(std::string_view s) {
  std::string out;
  append_quoted(out, s);
  return out;
}

std::string json_number(double v) {
  std::string out;
  append_number(out, v);
  return out;
}

std::string platform_test(ResultsFormat format, const std::string& name, double score, double max, bool passed,
                          const std::string& output) {
  if (format == ResultsFormat::gradescope)
    return "{\"name\":" + json_quoted(name) + ",\"score\":" + json_number(score) +
           ",\"max_score\":" + json_number(max) + ",\"status\":\"" + (passed ? "passed" : "failed") +
           "\",\"output\":" + json_quoted(output) + ",\"visibility\":\"visible\"}";
  return "{\"name\":" + json_quoted(name) + ",\"points\":" + json_number(score) +
         ",\"max_points\":" + json_number(max) + ",\"message\":" + json_quoted(output) + "}";
}

std::string result_line(const CheckResult& r, const std::string& answer, const std::string& id) {
  std::string out;
  out.reserve(256 + answer.size() + r.summary.size() + r.echo_text.size() + r.echo_latex.size());
  out += '{';
  if (!id.empty()) {
    out += "\"id\":";
    append_quoted(out, id);
    out += ',';
  }
  out += "\"unknown\":";
  append_quoted(out, r.unknown);
  out += ",\"answer\":";
  append_quoted(out, answer);
  out += ",\"verdict\":";
  append_quoted(out, verdict_name(r.verdict));
  out += ",\"score\":";
  append_number(out, r.score);
  out += ",\"summary\":";
  append_quoted(out, r.summary);
  out += ",\"findings\":[";
  for (std::size_t k = 0; k < r.findings.size(); ++k) {
    out += k ? ",{\"code\":" : "{\"code\":";
    append_quoted(out, r.findings[k].code);
    out += ",\"message\":";
    append_quoted(out, r.findings[k].message);
    out += '}';
  }
  out += "],\"method\":";
  append_quoted(out, r.method);
  out += ",\"read_as\":";
  append_quoted(out, r.echo_text);
  out += ",\"latex\":";
  append_quoted(out, r.echo_latex);
  if (r.equation)
    for (const auto& [name, list] :
         {std::pair{"identified_as", &r.identified_as}, std::pair{"follows_from", &r.follows_from}}) {
      out += std::string(",\"") + name + "\":[";
      for (std::size_t k = 0; k < list->size(); ++k) {
        if (k) out += ',';
        append_quoted(out, (*list)[k]);
      }
      out += ']';
    }
  out += '}';
  return out;
}

std::string result_json(const CheckResult& r, const std::string& answer, const std::string& id) {
  const nlohmann::ordered_json j = to_json(r, answer, id);
  nlohmann::ordered_json out;
  out["version"] = 1;
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "version") out[it.key()] = it.value();
  return out.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

std::string result_text(const CheckResult& r) {
  std::string out = verdict_name(r.verdict) + ": " + r.summary + "\n";
  if (!r.echo_text.empty()) out += "  read as: " + r.echo_text + "\n";
  for (const auto& f : r.findings)
    if (f.message != r.summary) out += "  also: " + f.message + "\n";
  if (r.equation && r.verdict == Verdict::correct && r.follows_from.size() > 1)
    out += "  follows from: " + join(r.follows_from) + "\n";
  return out;
}

}  // namespace tackle

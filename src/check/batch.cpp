#include "check/batch.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/fbd.hpp"

#include "core/diagnostics.hpp"
#include "core/files.hpp"
#include "core/limits.hpp"
#include "core/utf8.hpp"

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
        if (c < 0x20) out += fmt::format("\\u{:04x}", c);
        else out += ch;
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
    return "{\"name\":" + json_quoted(name) + ",\"score\":" + json_number(score) + ",\"max_score\":" + json_number(max) +
           ",\"status\":\"" + (passed ? "passed" : "failed") + "\",\"output\":" + json_quoted(output) + ",\"visibility\":\"visible\"}";
  return "{\"name\":" + json_quoted(name) + ",\"points\":" + json_number(score) + ",\"max_points\":" + json_number(max) +
         ",\"message\":" + json_quoted(output) + "}";
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
    for (const auto& [name, list] : {std::pair{"identified_as", &r.identified_as}, std::pair{"follows_from", &r.follows_from}}) {
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

namespace {

// One line of `in` into `line` (without its newline); false at the end of the input. A line
// past max_batch_line_bytes is an input error as soon as that many bytes were read: a line
// that never ends (`/dev/zero`) must not be read for ever, nor into memory.
bool read_line(std::istream& in, std::string& line, std::size_t number, const std::string& source) {
  line.clear();
  std::streambuf* buffer = in.rdbuf();
  using traits = std::char_traits<char>;
  for (;;) {
    const traits::int_type c = buffer->sbumpc();
    if (traits::eq_int_type(c, traits::eof())) {
      in.setstate(std::ios::eofbit);
      return !line.empty();
    }
    if (c == '\n') return true;
    if (line.size() == max_batch_line_bytes)
      throw InputError({{{source, static_cast<int>(number), 0},
                         "the line is longer than " + std::to_string(max_batch_line_bytes >> 20) +
                             " MiB (expected JSON Lines: one object with id, unknown and answer per line)"}});
    line.push_back(traits::to_char_type(c));
  }
}

}  // namespace

BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, std::ostream& results,
                         const GradeOptions& options) {
  using J = nlohmann::ordered_json;
  const auto dump = [](const J& j) { return j.dump(-1, ' ', false, J::error_handler_t::replace); };
  BatchSummary s;
  // The results file is written as the lines are graded; its totals come last (JSON does
  // not order the fields of an object).
  const bool platform = options.format != ResultsFormat::jsonl;
  // PrairieLearn's tests wait in a temporary file (memory stays bounded): a result that is
  // not gradable must not tell which of the other answers were right, and that is known only
  // at the end.
  const bool spooled = options.format == ResultsFormat::prairielearn;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> spool(spooled ? std::tmpfile() : nullptr, &std::fclose);
  if (spooled && !spool) throw InternalError("cannot make a temporary file for the PrairieLearn tests");
  std::unique_ptr<FdBuffer> spool_buffer(spooled ? new FdBuffer(fileno(spool.get())) : nullptr);
  std::ostream spool_stream(spool_buffer.get());
  std::ostream& tests = spooled ? spool_stream : results;
  if (platform) results << "{\n";
  if (platform && !spooled) results << "  \"tests\": [";
  std::vector<std::string> format_errors;  // the first max_format_errors
  std::string line;
  std::size_t physical = 0;  // the line's number in the file, blank lines counted
  while (out && read_line(in, line, ++physical, options.source)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    ++s.lines;
    std::string id = "line " + std::to_string(s.lines), unknown, answer;
    bool equation = false;
    std::optional<std::string> fbd;  // a free body diagram's JSON
    std::vector<std::pair<std::string, std::string>> params = options.set;
    CheckResult r;
    std::string problem;
    GradedLine graded;
    graded.line = physical;
    // Whose answer and which question, for the gradebook.
    const auto read_who = [&](const nlohmann::json& j) {
      graded.object = true;
      if (j.contains("student") && (j["student"].is_string() || j["student"].is_number()))
        graded.student = j["student"].is_string() ? j["student"].get<std::string>() : j["student"].dump();
      if (j.contains("id")) graded.id = j["id"].is_string() ? j["id"].get<std::string>() : j["id"].dump(-1, ' ', false, J::error_handler_t::replace);
    };
    // Bounded before parsing: a submission line is at most a few answers long.
    if (line.size() > 4 * checker.options().limits.max_length + 1024) {
      problem = "the line is too long (" + std::to_string(line.size()) + " characters)";
      // Still the student's: read for whom it is (the line is at most max_batch_line_bytes).
      if (options.graded) {
        try {
          const auto j = nlohmann::json::parse(line);
          if (j.is_object()) read_who(j);
        } catch (const std::bad_alloc&) {
          throw;
        } catch (const std::exception&) {
        }
      }
    } else {
      try {
        const auto j = nlohmann::json::parse(line);
        if (!j.is_object()) throw std::runtime_error("not an object");
        read_who(j);
        if (graded.id) id = *graded.id;
        if (j.contains("fbd")) {
          // A free body diagram, as `check --fbd` reads it (JSON is YAML).
          if (!j["fbd"].is_object()) problem = "\"fbd\" is not an object (expected {\"body\": ..., \"forces\": [...]})";
          else fbd = j["fbd"].dump(-1, ' ', false, J::error_handler_t::replace);
          if (j.contains("answer") || j.contains("equation")) problem = "a line has one of \"fbd\", \"equation\" and \"answer\"";
          if (fbd) answer = *fbd;
        } else if (j.contains("equation")) {
          // A step of a worked solution: an equation, checked against the derivation's.
          if (!j["equation"].is_string()) problem = "\"equation\" is not a string";
          else answer = j["equation"].get<std::string>();
          if (j.contains("answer")) problem = "a line has an \"equation\" or an \"answer\", not both";
          equation = true;
        } else {
          if (!j.contains("unknown") || !j["unknown"].is_string()) problem = "no \"unknown\" (a string)";
          else unknown = j["unknown"].get<std::string>();
          if (!j.contains("answer")) problem = "no \"answer\"";
          else answer = j["answer"].is_string() ? j["answer"].get<std::string>() : j["answer"].dump(-1, ' ', false, J::error_handler_t::replace);
        }
        if (j.contains("params")) {
          if (!j["params"].is_object()) {
            problem = "\"params\" is not an object of parameter values";
          } else {
            for (auto it = j["params"].begin(); it != j["params"].end(); ++it)
              params.emplace_back(it.key(), it.value().is_string() ? it.value().get<std::string>()
                                                                    : it.value().dump(-1, ' ', false, J::error_handler_t::replace));
          }
        }
      } catch (const std::bad_alloc&) {
        throw;  // out of memory is the process's (exit 3), not this line's
      } catch (const std::exception&) {
        problem = "not a JSON object with id, unknown and answer";
      }
    }
    std::optional<GiNaC::exmap> values;
    if (problem.empty() && !params.empty()) {
      std::string why;
      values = checker.values_for(params, why);
      if (!values) problem = "params: " + why;
    }
    if (!problem.empty()) {
      r.unknown = unknown;
      r.verdict = Verdict::invalid;
      r.summary = "line " + std::to_string(s.lines) + ": " + problem;
      r.findings.push_back({"not_an_answer", r.summary});
    } else if (fbd) {
      if (!options.model) {
        r.verdict = Verdict::invalid;
        r.summary = "line " + std::to_string(s.lines) + ": free body diagrams are not checked here";
        r.findings.push_back({"not_an_answer", r.summary});
      } else {
        try {
          const StudentFbd student = read_fbd_file(*fbd, "fbd", *options.model);
          std::vector<Diagnostic> problems;
          r = checked_fbd(*options.model, student, FbdRubric{}, problems);
          if (!problems.empty()) r.summary = problems.front().message;
          unknown = r.unknown;  // the test's name: "free body diagram of B"
        } catch (const InputError& e) {
          r.verdict = Verdict::invalid;
          r.summary = "line " + std::to_string(s.lines) + ": " + (e.diagnostics().empty() ? std::string("not a free body diagram") : e.diagnostics().front().message);
          r.findings.push_back({"not_an_answer", r.summary});
        }
      }
    } else if (equation) {
      r = checker.check_equation(answer);
    } else {
      r = checker.check(unknown, answer, values ? &*values : nullptr);
    }
    if (r.verdict == Verdict::correct) ++s.correct;
    const std::string name = id + (unknown.empty() ? "" : ": " + unknown);
    const std::string feedback = verdict_name(r.verdict) + ": " + r.summary;
    if (r.verdict == Verdict::invalid) {
      ++s.invalid;
      // A line without an id is named by its place, which its problem already says: once.
      const std::string place = "line " + std::to_string(s.lines) + ": ";
      const bool named_by_place = id + ": " == place;
      if (format_errors.size() < max_format_errors)
        format_errors.push_back(name + ": " + (named_by_place && r.summary.rfind(place, 0) == 0 ? r.summary.substr(place.size()) : r.summary));
    }
    const auto own = options.points_for.find(unknown);
    const double max_points = own != options.points_for.end() ? own->second : options.points;
    const double points = r.score * max_points;
    s.points += points;
    s.max_points += max_points;
    if (options.graded) {
      graded.points = points;
      graded.max_points = max_points;
      graded.verdict = r.verdict;
      options.graded(graded);
    }
    const std::string result = result_line(r, answer, id);
    out << result << "\n";
    if (options.format == ResultsFormat::jsonl) results << result << "\n";
    if (platform)
      tests << (s.lines == 1 ? "\n    " : ",\n    ") << platform_test(options.format, name, points, max_points, r.verdict == Verdict::correct, feedback);
  }
  if (!platform) return s;
  if (spooled && s.invalid == 0) {
    // Gradable: the tests, copied from the temporary file.
    tests.flush();
    if (spool_buffer->error() != 0 || std::fseek(spool.get(), 0, SEEK_SET) != 0)
      throw InternalError("cannot read back the temporary file of the PrairieLearn tests");
    results << "  \"tests\": [";
    char chunk[1 << 16];
    for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, spool.get())) > 0;) results.write(chunk, static_cast<std::streamsize>(n));
  }
  if (!spooled || s.invalid == 0) results << (s.lines == 0 ? "],\n" : "\n  ],\n");
  const std::string said = std::to_string(s.correct) + " of " + std::to_string(s.lines) + " answers correct";
  J totals;
  if (options.format == ResultsFormat::gradescope) {
    if (options.top_level_score) totals["score"] = s.points;
    totals["output"] = said;
  } else {
    // An answer that cannot be graded as typed: not gradable, so no attempt is charged.
    totals["gradable"] = s.invalid == 0;
    if (s.invalid == 0) {
      totals["score"] = s.max_points > 0 ? s.points / s.max_points : 0.0;
    } else {
      if (s.invalid > format_errors.size())
        format_errors.push_back("and " + std::to_string(s.invalid - format_errors.size()) + " more");
      totals["format_errors"] = format_errors;
    }
    totals["message"] = s.invalid == 0 ? said : std::to_string(s.invalid) + " of " + std::to_string(s.lines) +
                                                   " answers cannot be graded as typed: fix them and submit again";
  }
  // The totals' fields, indented as the rest, after the tests.
  std::size_t k = 0;
  for (auto it = totals.begin(); it != totals.end(); ++it, ++k)
    results << "  " << dump(it.key()) << ": " << dump(it.value()) << (k + 1 < totals.size() ? ",\n" : "\n");
  results << "}\n";
  return s;
}

BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, const GradeOptions& options) {
  std::ostringstream results;
  BatchSummary s = check_batch(checker, in, out, results, options);
  s.results = results.str();
  return s;
}

}  // namespace tackle

#include "check/batch.hpp"

#include <nlohmann/json.hpp>

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
  return j;
}

}  // namespace

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
  return out;
}

BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, const GradeOptions& options) {
  using J = nlohmann::ordered_json;
  BatchSummary s;
  J tests = J::array(), jsonl = J::array();
  std::vector<std::string> format_errors;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    ++s.lines;
    std::string id = "line " + std::to_string(s.lines), unknown, answer;
    std::vector<std::pair<std::string, std::string>> params = options.set;
    CheckResult r;
    std::string problem;
    // Bounded before parsing: a submission line is at most a few answers long.
    if (line.size() > 4 * checker.options().limits.max_length + 1024) {
      problem = "the line is too long (" + std::to_string(line.size()) + " characters)";
    } else {
      try {
        const auto j = nlohmann::json::parse(line);
        if (!j.is_object()) throw std::runtime_error("not an object");
        if (j.contains("id")) id = j["id"].is_string() ? j["id"].get<std::string>() : j["id"].dump(-1, ' ', false, J::error_handler_t::replace);
        if (!j.contains("unknown") || !j["unknown"].is_string()) problem = "no \"unknown\" (a string)";
        else unknown = j["unknown"].get<std::string>();
        if (!j.contains("answer")) problem = "no \"answer\"";
        else answer = j["answer"].is_string() ? j["answer"].get<std::string>() : j["answer"].dump(-1, ' ', false, J::error_handler_t::replace);
        if (j.contains("params")) {
          if (!j["params"].is_object()) {
            problem = "\"params\" is not an object of parameter values";
          } else {
            for (auto it = j["params"].begin(); it != j["params"].end(); ++it)
              params.emplace_back(it.key(), it.value().is_string() ? it.value().get<std::string>()
                                                                    : it.value().dump(-1, ' ', false, J::error_handler_t::replace));
          }
        }
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
      format_errors.push_back(name + ": " + (named_by_place && r.summary.rfind(place, 0) == 0 ? r.summary.substr(place.size()) : r.summary));
    }
    const auto own = options.points_for.find(unknown);
    const double max_points = own != options.points_for.end() ? own->second : options.points;
    const double points = r.score * max_points;
    s.points += points;
    s.max_points += max_points;
    const J result = to_json(r, answer, id);
    out << result.dump(-1, ' ', false, J::error_handler_t::replace) << "\n";
    if (options.format == ResultsFormat::jsonl) jsonl.push_back(result);
    if (options.format == ResultsFormat::gradescope)
      tests.push_back({{"name", name}, {"score", points}, {"max_score", max_points},
                       {"status", r.verdict == Verdict::correct ? "passed" : "failed"}, {"output", feedback}, {"visibility", "visible"}});
    if (options.format == ResultsFormat::prairielearn)
      tests.push_back({{"name", name}, {"points", points}, {"max_points", max_points}, {"message", feedback}});
  }
  const std::string said = std::to_string(s.correct) + " of " + std::to_string(s.lines) + " answers correct";
  J results;
  switch (options.format) {
    case ResultsFormat::gradescope: {
      if (options.top_level_score) results["score"] = s.points;
      results["output"] = said;
      results["tests"] = tests;
      break;
    }
    case ResultsFormat::prairielearn: {
      // An answer that cannot be graded as typed: not gradable, so no attempt is charged.
      results["gradable"] = s.invalid == 0;
      if (s.invalid == 0) results["score"] = s.max_points > 0 ? s.points / s.max_points : 0.0;
      else results["format_errors"] = format_errors;
      results["message"] = s.invalid == 0 ? said : std::to_string(s.invalid) + " of " + std::to_string(s.lines) +
                                                       " answers cannot be graded as typed: fix them and submit again";
      // Not gradable, no attempt charged: the tests would tell which of the other answers are
      // right, and the student could submit again with only the wrong ones changed.
      if (s.invalid == 0) results["tests"] = tests;
      break;
    }
    case ResultsFormat::jsonl: {
      for (const auto& x : jsonl) s.results += x.dump(-1, ' ', false, J::error_handler_t::replace) + "\n";
      return s;
    }
  }
  s.results = results.dump(2, ' ', false, J::error_handler_t::replace) + "\n";
  return s;
}

}  // namespace tackle

#include "grade/batch.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <sstream>

#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "check/fbd.hpp"

#include "core/diagnostics.hpp"
#include "core/files.hpp"
#include "core/limits.hpp"
#include "core/utf8.hpp"

namespace tackle {

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

namespace {

// A line of the batch as read: its text, its place among the answers and in the file.
struct PendingLine {
  std::string text;
  std::size_t number = 0;    // among the lines that are not blank, from 1
  std::size_t physical = 0;  // in the file, blank lines counted
};

// A line once graded: what the results say of it (its JSON result line made already).
struct LineOutcome {
  Verdict verdict = Verdict::invalid;
  double score = 0;
  std::string summary, unknown, id, result;
  GradedLine graded;
};

// What a line is: its id, the question and the answer (or why it is not one).
struct ReadLine {
  std::string id, unknown, answer, problem;
  bool equation = false;
  std::optional<std::string> fbd;  // a free body diagram's JSON
  std::vector<std::pair<std::string, std::string>> params;
};

ReadLine read_answer_line(const std::string& line, std::size_t number, const Checker& checker,
                          const GradeOptions& options, GradedLine& graded) {
  using J = nlohmann::ordered_json;
  ReadLine l;
  l.id = "line " + std::to_string(number);
  l.params = options.set;
  // Whose answer and which question, for the gradebook.
  const auto read_who = [&](const nlohmann::json& j) {
    graded.object = true;
    if (j.contains("student") && (j["student"].is_string() || j["student"].is_number()))
      graded.student = j["student"].is_string() ? j["student"].get<std::string>() : j["student"].dump();
    if (j.contains("id"))
      graded.id =
          j["id"].is_string() ? j["id"].get<std::string>() : j["id"].dump(-1, ' ', false, J::error_handler_t::replace);
  };
  // Bounded before parsing: a submission line is at most a few answers long.
  if (line.size() > 4 * checker.options().limits.max_length + 1024) {
    l.problem = "the line is too long (" + std::to_string(line.size()) + " characters)";
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
    return l;
  }
  try {
    const auto j = nlohmann::json::parse(line);
    if (!j.is_object()) throw std::runtime_error("not an object");
    read_who(j);
    if (graded.id) l.id = *graded.id;
    if (j.contains("fbd")) {
      // A free body diagram, as `check --fbd` reads it (JSON is YAML).
      if (!j["fbd"].is_object())
        l.problem = "\"fbd\" is not an object (expected {\"body\": ..., \"forces\": [...]})";
      else
        l.fbd = j["fbd"].dump(-1, ' ', false, J::error_handler_t::replace);
      if (j.contains("answer") || j.contains("equation"))
        l.problem = "a line has one of \"fbd\", \"equation\" and \"answer\"";
      if (l.fbd) l.answer = *l.fbd;
    } else if (j.contains("equation")) {
      // A step of a worked solution: an equation, checked against the derivation's.
      if (!j["equation"].is_string())
        l.problem = "\"equation\" is not a string";
      else
        l.answer = j["equation"].get<std::string>();
      if (j.contains("answer")) l.problem = "a line has an \"equation\" or an \"answer\", not both";
      l.equation = true;
    } else {
      if (!j.contains("unknown") || !j["unknown"].is_string())
        l.problem = "no \"unknown\" (a string)";
      else
        l.unknown = j["unknown"].get<std::string>();
      if (!j.contains("answer"))
        l.problem = "no \"answer\"";
      else
        l.answer = j["answer"].is_string() ? j["answer"].get<std::string>()
                                           : j["answer"].dump(-1, ' ', false, J::error_handler_t::replace);
    }
    if (j.contains("params")) {
      if (!j["params"].is_object()) {
        l.problem = "\"params\" is not an object of parameter values";
      } else {
        for (auto it = j["params"].begin(); it != j["params"].end(); ++it)
          l.params.emplace_back(it.key(), it.value().is_string()
                                              ? it.value().get<std::string>()
                                              : it.value().dump(-1, ' ', false, J::error_handler_t::replace));
      }
    }
  } catch (const std::bad_alloc&) {
    throw;  // out of memory is the process's (exit 3), not this line's
  } catch (const std::exception&) {
    l.problem = "not a JSON object with id, unknown and answer";
  }
  return l;
}

CheckResult not_an_answer(std::size_t number, const std::string& problem) {
  CheckResult r;
  r.verdict = Verdict::invalid;
  r.summary = "line " + std::to_string(number) + ": " + problem;
  r.findings.push_back({"not_an_answer", r.summary});
  return r;
}

CheckResult checked_diagram(const std::string& fbd, std::size_t number, const GradeOptions& options) {
  if (!options.model) return not_an_answer(number, "free body diagrams are not checked here");
  try {
    const StudentFbd student = read_fbd_file(fbd, "fbd", *options.model);
    std::vector<Diagnostic> problems;
    CheckResult r = checked_fbd(*options.model, student, FbdRubric{}, problems);
    if (!problems.empty()) r.summary = problems.front().message;
    return r;
  } catch (const InputError& e) {
    return not_an_answer(
        number, e.diagnostics().empty() ? std::string("not a free body diagram") : e.diagnostics().front().message);
  }
}

LineOutcome grade_line(const Checker& checker, const PendingLine& p, const GradeOptions& options) {
  LineOutcome o;
  o.graded.line = p.physical;
  ReadLine l = read_answer_line(p.text, p.number, checker, options, o.graded);
  std::optional<GiNaC::exmap> values;
  if (l.problem.empty() && !l.params.empty()) {
    std::string why;
    values = checker.values_for(l.params, why);
    if (!values) l.problem = "params: " + why;
  }
  CheckResult r;
  if (!l.problem.empty()) {
    r = not_an_answer(p.number, l.problem);
    r.unknown = l.unknown;
  } else if (l.fbd) {
    r = checked_diagram(*l.fbd, p.number, options);
    if (options.model) l.unknown = r.unknown;  // the test's name: "free body diagram of B"
  } else if (l.equation) {
    r = checker.check_equation(l.answer);
  } else {
    r = checker.check(l.unknown, l.answer, values ? &*values : nullptr);
  }
  o.verdict = r.verdict;
  o.score = r.score;
  o.summary = r.summary;
  o.unknown = l.unknown;
  o.id = l.id;
  o.result = result_line(r, l.answer, l.id);
  return o;
}

// A graded line through a file between processes: exact, whatever bytes its texts hold.
void put(std::FILE* f, const std::string& text) {
  const std::uint64_t n = text.size();
  std::fwrite(&n, sizeof n, 1, f);
  std::fwrite(text.data(), 1, text.size(), f);
}
template <class T>
void put_raw(std::FILE* f, const T& v) {
  std::fwrite(&v, sizeof v, 1, f);
}
void put(std::FILE* f, const LineOutcome& o) {
  put_raw(f, o.verdict);
  put_raw(f, o.score);
  for (const std::string* t : {&o.summary, &o.unknown, &o.id, &o.result}) put(f, *t);
  put_raw(f, o.graded.line);
  put_raw(f, o.graded.object);
  for (const auto* t : {&o.graded.student, &o.graded.id}) {
    put_raw(f, t->has_value());
    if (*t) put(f, **t);
  }
}
bool get(std::FILE* f, std::string& text) {
  std::uint64_t n = 0;
  if (std::fread(&n, sizeof n, 1, f) != 1 || n > max_batch_line_bytes * 8) return false;
  text.resize(n);
  return std::fread(text.data(), 1, n, f) == n;
}
template <class T>
bool get_raw(std::FILE* f, T& v) {
  return std::fread(&v, sizeof v, 1, f) == 1;
}
bool get(std::FILE* f, LineOutcome& o) {
  bool ok = get_raw(f, o.verdict) && get_raw(f, o.score);
  for (std::string* t : {&o.summary, &o.unknown, &o.id, &o.result}) ok = ok && get(f, *t);
  ok = ok && get_raw(f, o.graded.line) && get_raw(f, o.graded.object);
  for (auto* t : {&o.graded.student, &o.graded.id}) {
    bool has = false;
    ok = ok && get_raw(f, has);
    if (ok && has) ok = get(f, t->emplace());
  }
  return ok;
}

// Lines [from, to) of `block` graded in a child process, into a temporary file; the child's
// id, or -1 where it could not be started (the caller grades them itself).
struct Child {
  pid_t pid = -1;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, &std::fclose};
  std::size_t from = 0, to = 0;
};

Child start_child(const Checker& checker, const std::vector<PendingLine>& block, std::size_t from, std::size_t to,
                  const GradeOptions& options) {
  Child c;
  c.from = from;
  c.to = to;
  c.file.reset(std::tmpfile());
  if (!c.file) return c;
  std::fflush(nullptr);  // (nothing buffered is written twice)
  c.pid = fork();
  if (c.pid != 0) return c;
  // The child: grades its lines, writes them, and ends without running any exit handler or
  // flushing any stream it shares with its parent.
  int status = 0;
  try {
    for (std::size_t i = from; i < to; ++i) put(c.file.get(), grade_line(checker, block[i], options));
    if (std::fflush(c.file.get()) != 0) status = 3;
  } catch (...) {
    status = 3;
  }
  _exit(status);
}

std::vector<LineOutcome> finish_child(Child& c) {
  int status = 0;
  while (waitpid(c.pid, &status, 0) < 0)
    if (errno != EINTR) throw InternalError("cannot wait for a grading process");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InternalError("a grading process ended with " + (WIFEXITED(status)
                                                               ? "status " + std::to_string(WEXITSTATUS(status))
                                                               : "signal " + std::to_string(WTERMSIG(status))));
  std::rewind(c.file.get());
  std::vector<LineOutcome> out(c.to - c.from);
  for (auto& o : out)
    if (!get(c.file.get(), o)) throw InternalError("cannot read back a grading process's results");
  return out;
}

// A block of lines graded by `jobs` processes (this one and jobs - 1 children), each a run of
// consecutive lines; in the block's order.
std::vector<LineOutcome> grade_block(const Checker& checker, const std::vector<PendingLine>& block, int jobs,
                                     const GradeOptions& options) {
  const std::size_t n = block.size(), parts = std::min<std::size_t>(static_cast<std::size_t>(std::max(jobs, 1)), n);
  std::vector<LineOutcome> out(n);
  std::vector<Child> children;
  for (std::size_t k = 1; k < parts; ++k)
    children.push_back(start_child(checker, block, k * n / parts, (k + 1) * n / parts, options));
  const auto here = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) out[i] = grade_line(checker, block[i], options);
  };
  here(0, parts == 0 ? 0 : n / parts);
  for (Child& c : children) {
    if (c.pid < 0) {
      here(c.from, c.to);
      continue;
    }
    auto graded = finish_child(c);
    std::move(graded.begin(), graded.end(), out.begin() + static_cast<std::ptrdiff_t>(c.from));
  }
  return out;
}

// The outputs of a batch, written as its lines are graded: the result lines, and the
// platform's results file (its tests as they come, its totals at the end).
class BatchWriter {
 public:
  BatchWriter(std::ostream& out, std::ostream& results, const GradeOptions& options)
      : out_(out),
        results_(results),
        options_(options),
        platform_(options.format != ResultsFormat::jsonl),
        spooled_(options.format == ResultsFormat::prairielearn),
        spool_(spooled_ ? std::tmpfile() : nullptr, &std::fclose) {
    // PrairieLearn's tests wait in a temporary file (memory stays bounded): a result that is
    // not gradable must not tell which of the other answers were right, and that is known
    // only at the end.
    if (spooled_ && !spool_) throw InternalError("cannot make a temporary file for the PrairieLearn tests");
    spool_buffer_.reset(spooled_ ? new FdBuffer(fileno(spool_.get())) : nullptr);
    spool_stream_.rdbuf(spool_buffer_.get());
    if (platform_) results_ << "{\n";
    if (platform_ && !spooled_) results_ << "  \"tests\": [";
  }
  void line(LineOutcome& o, std::size_t number);
  BatchSummary finish();

 private:
  std::ostream& out_;
  std::ostream& results_;
  const GradeOptions& options_;
  const bool platform_, spooled_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> spool_;
  std::unique_ptr<FdBuffer> spool_buffer_;
  std::ostream spool_stream_{nullptr};
  std::vector<std::string> format_errors_;  // the first max_format_errors
  BatchSummary s_;
  std::ostream& tests() { return spooled_ ? spool_stream_ : results_; }
};

void BatchWriter::line(LineOutcome& o, std::size_t number) {
  s_.lines = number;
  if (o.verdict == Verdict::correct) ++s_.correct;
  const std::string name = o.id + (o.unknown.empty() ? "" : ": " + o.unknown);
  const std::string feedback = verdict_name(o.verdict) + ": " + o.summary;
  if (o.verdict == Verdict::invalid) {
    ++s_.invalid;
    // A line without an id is named by its place, which its problem already says: once.
    const std::string place = "line " + std::to_string(number) + ": ";
    const bool named_by_place = o.id + ": " == place;
    if (format_errors_.size() < max_format_errors)
      format_errors_.push_back(
          name + ": " +
          (named_by_place && o.summary.rfind(place, 0) == 0 ? o.summary.substr(place.size()) : o.summary));
  }
  const auto own = options_.points_for.find(o.unknown);
  const double max_points = own != options_.points_for.end() ? own->second : options_.points;
  const double points = o.score * max_points;
  s_.points += points;
  s_.max_points += max_points;
  if (options_.graded) {
    o.graded.points = points;
    o.graded.max_points = max_points;
    o.graded.verdict = o.verdict;
    options_.graded(o.graded);
  }
  out_ << o.result << "\n";
  if (options_.format == ResultsFormat::jsonl) results_ << o.result << "\n";
  if (platform_)
    tests() << (number == 1 ? "\n    " : ",\n    ")
            << platform_test(options_.format, name, points, max_points, o.verdict == Verdict::correct, feedback);
}

BatchSummary BatchWriter::finish() {
  using J = nlohmann::ordered_json;
  const auto dump = [](const J& j) { return j.dump(-1, ' ', false, J::error_handler_t::replace); };
  if (!platform_) return s_;
  if (spooled_ && s_.invalid == 0) {
    // Gradable: the tests, copied from the temporary file.
    spool_stream_.flush();
    if (spool_buffer_->error() != 0 || std::fseek(spool_.get(), 0, SEEK_SET) != 0)
      throw InternalError("cannot read back the temporary file of the PrairieLearn tests");
    results_ << "  \"tests\": [";
    char chunk[1 << 16];
    for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, spool_.get())) > 0;)
      results_.write(chunk, static_cast<std::streamsize>(n));
  }
  if (!spooled_ || s_.invalid == 0) results_ << (s_.lines == 0 ? "],\n" : "\n  ],\n");
  const std::string said = std::to_string(s_.correct) + " of " + std::to_string(s_.lines) + " answers correct";
  J totals;
  if (options_.format == ResultsFormat::gradescope) {
    if (options_.top_level_score) totals["score"] = s_.points;
    totals["output"] = said;
  } else {
    // An answer that cannot be graded as typed: not gradable, so no attempt is charged.
    totals["gradable"] = s_.invalid == 0;
    if (s_.invalid == 0) {
      totals["score"] = s_.max_points > 0 ? s_.points / s_.max_points : 0.0;
    } else {
      if (s_.invalid > format_errors_.size())
        format_errors_.push_back("and " + std::to_string(s_.invalid - format_errors_.size()) + " more");
      totals["format_errors"] = format_errors_;
    }
    totals["message"] = s_.invalid == 0 ? said
                                        : std::to_string(s_.invalid) + " of " + std::to_string(s_.lines) +
                                              " answers cannot be graded as typed: fix them and submit again";
  }
  // The totals' fields, indented as the rest, after the tests.
  std::size_t k = 0;
  for (auto it = totals.begin(); it != totals.end(); ++it, ++k)
    results_ << "  " << dump(it.key()) << ": " << dump(it.value()) << (k + 1 < totals.size() ? ",\n" : "\n");
  results_ << "}\n";
  return s_;
}

}  // namespace

BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, std::ostream& results,
                         const GradeOptions& options) {
  BatchWriter writer(out, results, options);
  // One line at a time; with several jobs, blocks of lines graded side by side.
  const int jobs = std::max(options.jobs, 1);
  const std::size_t block_size = jobs == 1 ? 1 : block_lines_per_job * static_cast<std::size_t>(jobs);
  std::vector<PendingLine> block;
  const auto grade = [&] {
    std::vector<LineOutcome> graded = grade_block(checker, block, jobs, options);
    for (std::size_t i = 0; i < graded.size(); ++i) writer.line(graded[i], block[i].number);
    block.clear();
  };
  std::string line;
  std::size_t physical = 0, number = 0;  // the line's number in the file (blank lines counted), and among answers
  try {
    while (out && read_line(in, line, ++physical, options.source)) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      block.push_back({line, ++number, physical});
      if (block.size() == block_size) grade();
    }
  } catch (const InputError&) {
    grade();  // (the lines before a line too long to read are graded and written)
    throw;
  }
  grade();
  return writer.finish();
}

BatchSummary check_batch(const Checker& checker, std::istream& in, std::ostream& out, const GradeOptions& options) {
  std::ostringstream results;
  BatchSummary s = check_batch(checker, in, out, results, options);
  s.results = results.str();
  return s;
}

}  // namespace tackle

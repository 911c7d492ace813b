#include "crosscheck/oracle.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "check/check.hpp"
#include "crosscheck/compare.hpp"
#include "crosscheck/diagram.hpp"
#include "crosscheck/variants.hpp"
#include "crosscheck/worlds.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

namespace {

using Rng = std::mt19937_64;

// A description the oracle writes items for: tackle's analysis and checker of it, and what
// the items are made from.
struct Source {
  std::string name;   // the example's file name, or generated-SEED
  std::string group;  // the example's file name, or "generated FAMILY"
  tackle::Description d;
  std::shared_ptr<const tackle::Analysis> analysis;
  std::shared_ptr<const tackle::Checker> checker;
  std::shared_ptr<const Variants> variants;
  Definitions definitions;  // tackle's turning strands' lengths, as text
};

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// tackle's names for the turning strands' lengths, with their definitions as text.
Definitions definitions_of(const tackle::Analysis& a) {
  Definitions out;
  for (const auto& s : a.model.symbols->all())
    if (s->geometric && s->definition) out.emplace_back(s->name, tackle::to_text(*s->definition));
  return out;
}

// A source, or why the oracle cannot use the description.
std::optional<Source> load(const std::string& text, const std::string& name, const std::string& group,
                           const tackle::RuleSet& rules, std::uint64_t seed, std::string& why) {
  Source s{name, group, {}, nullptr, nullptr, nullptr, {}};
  try {
    s.d = tackle::parse_description(text, name);
    Rng rng(seed);
    const Model probe(s.d, rng);  // (throws Unsupported for what the model cannot express)
    s.analysis = tackle::analyze_text(text, name, rules);
  } catch (const Unsupported& e) {
    why = std::string("the model cannot express it: ") + e.what();
    return std::nullopt;
  } catch (const std::exception& e) {
    why = std::string("tackle refuses it: ") + e.what();
    return std::nullopt;
  }
  if (s.analysis->solution.status == tackle::Solution::Status::inconsistent) {
    why = "tackle finds its equations inconsistent";
    return std::nullopt;
  }
  tackle::CheckOptions co;
  co.seed = seed;
  s.checker = std::make_shared<const tackle::Checker>(*s.analysis, co);
  s.variants = std::make_shared<const Variants>(*s.analysis);
  s.definitions = definitions_of(*s.analysis);
  return s;
}

std::vector<Source> load_examples(const std::string& dir, const tackle::RuleSet& rules, std::uint64_t seed) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<Source> out;
  for (const auto& f : files) {
    std::string why;
    const std::string name = f.filename().string();
    if (auto s = load(read(f), name, name, rules, seed, why))
      out.push_back(std::move(*s));
    else
      std::cout << fmt::format("not used  {}: {}\n", name, why);
  }
  return out;
}

// What the model decides and what tackle said about one item.
struct Item {
  Variant v;
  Judgement j;
  std::optional<tackle::CheckResult> r;
  std::string error;  // an exception from tackle's checker
};

struct Comparison {
  enum Kind { agree, disagree, undecided, skipped } kind = agree;
  std::string why;
};

Comparison compare_verdict(const Item& it) {
  using tackle::Verdict;
  if (!it.error.empty()) return {Comparison::disagree, "tackle threw: " + it.error};
  if (it.j.truth == Truth::unknown) return {Comparison::skipped, it.j.why};
  if (it.j.tautology)  // (docs/checking.md: `trivial`, incorrect by design)
    return {Comparison::skipped,
            "a tautology (holds whatever the state): tackle says " + tackle::verdict_name(it.r->verdict)};
  const tackle::CheckResult& r = *it.r;
  const bool holds = it.j.truth == Truth::holds;
  if (r.verdict != Verdict::correct && r.summary.empty() && r.findings.empty())
    return {Comparison::disagree, "tackle says nothing (" + tackle::verdict_name(r.verdict) + " without a reason)"};
  if (r.verdict == Verdict::correct)
    return holds ? Comparison{} : Comparison{Comparison::disagree, "false, and tackle says correct"};
  if (r.verdict == Verdict::incorrect)
    return holds ? Comparison{Comparison::disagree, "true, and tackle says incorrect"} : Comparison{};
  if (r.verdict == Verdict::undecided)
    return holds ? Comparison{Comparison::undecided, r.summary}
                 : Comparison{Comparison::disagree, "false, and tackle leaves it undecided"};
  return {Comparison::disagree, std::string(holds ? "true" : "false") + ", and tackle says invalid"};
}

struct Counts {
  long items = 0, holds = 0, fails = 0, disagreements = 0, undecided = 0, skipped = 0, meant_otherwise = 0;
};

class Tally {
 public:
  Tally(std::string noun, int shown) : noun_(std::move(noun)), shown_(shown) {}

  void add(const Source& s, const Item& it, const Comparison& c) {
    for (Counts* k : {&total_, &families_[it.v.family], &groups_[s.group]}) count(*k, it, c);
    if (c.kind == Comparison::skipped) ++skip_reasons_[reason_kind(c.why)];
    if (c.kind == Comparison::undecided) ++undecided_reasons_[c.why];
    if (c.kind == Comparison::disagree) {
      ++disagree_reasons_[c.why + (it.r && !it.r->findings.empty() ? " (" + it.r->findings.front().code + ")" : "")];
      show(s, it, c);
    } else if (it.j.tautology && std::getenv("CROSSCHECK_DEBUG"))
      std::cout << fmt::format("TAUTOLOGY  {} [{}] {}\n", s.name, it.v.family, it.v.text);
    else if (it.v.meant != (it.j.truth == Truth::holds) && it.j.truth != Truth::unknown &&
             std::getenv("CROSSCHECK_DEBUG"))
      std::cout << fmt::format("NOT AS MEANT  {} [{}] {}\n          {}\n", s.name, it.v.family, it.j.why, it.v.text);
  }

  long print(long written) const {
    std::cout << fmt::format("\n{:<22} {:>7} {:>7} {:>7} {:>9} {:>9} {:>8} {:>8}\n", "family", noun_, "true", "false",
                             "disagree", "undecided", "skipped", "not as meant");
    for (const auto& [f, k] : families_) row(f, k);
    row("all", total_);
    std::cout << fmt::format("\n{:<52} {:>7} {:>9}\n", "source", noun_, "disagree");
    for (const auto& [g, k] : groups_) std::cout << fmt::format("{:<52} {:>7} {:>9}\n", g, k.items, k.disagreements);
    if (!disagree_reasons_.empty()) std::cout << "\ndisagreements (tackle's finding):\n";
    for (const auto& [why, n] : disagree_reasons_) std::cout << fmt::format("  {:>6}  {}\n", n, why);
    if (!skip_reasons_.empty()) std::cout << "\nnot decided by the model (skipped):\n";
    for (const auto& [why, n] : skip_reasons_) std::cout << fmt::format("  {:>6}  {}\n", n, why);
    if (!undecided_reasons_.empty()) std::cout << "\ntrue, and left undecided by tackle (allowed, counted):\n";
    for (const auto& [why, n] : undecided_reasons_) std::cout << fmt::format("  {:>6}  {}\n", n, why);
    std::cout << fmt::format(
        "\n{} {}: {} decided by the model ({} true, {} false), {} skipped, {} true and undecided by tackle\n", written,
        noun_, total_.holds + total_.fails, total_.holds, total_.fails, total_.skipped, total_.undecided);
    std::cout << fmt::format("{} {}, {} disagreements\n", written, noun_, total_.disagreements);
    return total_.disagreements;
  }

 private:
  std::string noun_;
  int shown_;
  Counts total_;
  std::map<std::string, Counts> families_, groups_;
  std::map<std::string, long> skip_reasons_, undecided_reasons_, disagree_reasons_;
  std::map<std::string, int> shown_of_;

  static void count(Counts& k, const Item& it, const Comparison& c) {
    ++k.items;
    if (it.j.truth == Truth::holds) ++k.holds;
    if (it.j.truth == Truth::fails) ++k.fails;
    if (it.j.truth != Truth::unknown && (it.j.truth == Truth::holds) != it.v.meant) ++k.meant_otherwise;
    if (c.kind == Comparison::disagree) ++k.disagreements;
    if (c.kind == Comparison::undecided) ++k.undecided;
    if (c.kind == Comparison::skipped) ++k.skipped;
  }
  // A skip's reason without its particulars (the quantity, the numbers).
  static std::string reason_kind(const std::string& why) {
    for (const char* k : {"the model has no value for", "the model has no quantity", "undetermined",
                          "too close to call", "cannot read"})
      if (why.find(k) != std::string::npos)
        return k == std::string("undetermined") ? "the model leaves a quantity undetermined" : k;
    return why;
  }
  void row(const std::string& name, const Counts& k) const {
    std::cout << fmt::format("{:<22} {:>7} {:>7} {:>7} {:>9} {:>9} {:>8} {:>8}\n", name, k.items, k.holds, k.fails,
                             k.disagreements, k.undecided, k.skipped, k.meant_otherwise);
  }
  void show(const Source& s, const Item& it, const Comparison& c) {
    int& n = shown_of_[s.group + " " + it.v.family];
    if (shown_ > 0 && n++ >= shown_) return;
    std::cout << fmt::format("DISAGREE  {} [{}] {}{}\n", s.name, it.v.family, c.why,
                             it.r && !it.r->summary.empty() ? ": " + it.r->summary : "");
    std::string text = it.v.text;  // (a diagram's YAML: each line indented)
    for (std::size_t at = text.find('\n'); at != std::string::npos && at + 1 < text.size();
         at = text.find('\n', at + 1))
      text.insert(at + 1, "          ");
    std::cout << fmt::format("          {}{}\n", it.v.unknown.empty() ? "" : it.v.unknown + " = ", text);
    if (it.j.truth == Truth::fails) std::cout << fmt::format("          (model: {})\n", it.j.why);
  }
};

// One kind of item: how it is made, decided by the model and checked by tackle.
struct ItemKind {
  std::string noun;
  std::function<std::optional<Variant>(const Source&, Rng&)> make;
  std::function<Judgement(const Source&, const Variant&, const std::vector<World>&)> judge;
  std::function<tackle::CheckResult(const Source&, const Variant&)> check;
};

ItemKind item_kind(OracleOptions::Kind k) {
  switch (k) {
    case OracleOptions::Kind::answers:
      return {"answers", [](const Source& s, Rng& rng) { return s.variants->answer(rng); },
              [](const Source&, const Variant& v, const std::vector<World>& w) {
                return judge_answer(v.unknown, v.text, w);
              },
              [](const Source& s, const Variant& v) { return s.checker->check(v.unknown, v.text); }};
    case OracleOptions::Kind::fbds:
      return {"diagrams", [](const Source& s, Rng& rng) { return make_diagram(s.d, rng); },
              [](const Source&, const Variant& v, const std::vector<World>&) { return judge_diagram(*v.diagram); },
              [](const Source& s, const Variant& v) { return check_diagram(*s.analysis, v.text); }};
    case OracleOptions::Kind::equations:
    default:
      return {"equations", [](const Source& s, Rng& rng) { return s.variants->equation(rng); },
              [](const Source&, const Variant& v, const std::vector<World>& w) { return judge_equation(v.text, w); },
              [](const Source& s, const Variant& v) { return s.checker->check_equation(v.text); }};
  }
}

Item decide_and_check(const ItemKind& kind, const Source& s, Variant v, const std::vector<World>& worlds, bool silent) {
  Item it{std::move(v), {}, std::nullopt, ""};
  it.j = kind.judge(s, it.v, worlds);
  try {
    it.r = silent ? tackle::CheckResult{} : kind.check(s, it.v);
  } catch (const std::exception& e) {
    it.error = e.what();
  }
  return it;
}

// The next generated mechanism the oracle can use (motion left out: not needed).
std::optional<Source> next_generated(std::uint64_t& seed, const tackle::RuleSet& rules) {
  for (int tries = 0; tries < 20; ++tries) {
    const std::uint64_t s = seed++;
    std::string kind;
    std::string text = generate(s, &kind);
    if (text.find("\nmotion:\n") != std::string::npos) text.erase(text.find("\nmotion:\n") + 1);
    std::string why;
    if (auto src = load(text, fmt::format("generated-{}", s), "generated " + kind, rules, s, why)) return src;
  }
  return std::nullopt;
}

}  // namespace

long run_oracle(const OracleOptions& o, const tackle::RuleSet& rules) {
  const ItemKind kind = item_kind(o.kind);
  Rng rng(o.seed);
  std::vector<Source> examples = o.examples.empty() ? std::vector<Source>{} : load_examples(o.examples, rules, o.seed);
  Tally tally(kind.noun, o.shown);
  std::uint64_t generated_seed = o.seed * 1000003ULL;
  long written = 0, idle = 0;
  for (long visit = 0; written < o.count && idle < 100; ++visit) {
    std::optional<Source> fresh;
    const Source* s = nullptr;
    if (visit % 2 == 0 && !examples.empty())
      s = &examples[static_cast<std::size_t>(visit / 2) % examples.size()];
    else if ((fresh = next_generated(generated_seed, rules)))
      s = &*fresh;
    if (!s) break;
    std::vector<World> worlds;
    try {
      worlds = make_worlds(s->d, rng, WorldOptions{}, s->definitions);
    } catch (const std::exception&) {
      ++idle;
      continue;
    }
    const long before = written;
    for (int k = 0; k < o.per_visit && written < o.count; ++k) {
      auto v = kind.make(*s, rng);
      if (!v) break;
      ++written;
      const Item it = decide_and_check(kind, *s, std::move(*v), worlds, o.silent);
      tally.add(*s, it, compare_verdict(it));
    }
    idle = written == before ? idle + 1 : 0;
  }
  return tally.print(written);
}

int explain_one(const std::string& file, const std::string& text, const std::string& unknown,
                const tackle::RuleSet& rules, std::uint64_t seed) {
  std::string why;
  const auto s = load(read(file), file, file, rules, seed, why);
  if (!s) {
    std::cout << "not used: " << why << "\n";
    return 2;
  }
  Rng rng(seed);
  const auto worlds = make_worlds(s->d, rng, WorldOptions{}, s->definitions);
  for (const auto& w : worlds) {
    std::cout << fmt::format("world (draw {}):", w.draw);
    for (const auto& [k, v] : w.values) std::cout << fmt::format(" {}={:.6g}{}", k, v, w.free.count(k) ? "(free)" : "");
    std::cout << "\n";
  }
  const Judgement j = unknown.empty() ? judge_equation(text, worlds) : judge_answer(unknown, text, worlds);
  std::cout << fmt::format("the model: {} ({}; worst relative residual {:.3g})\n",
                           j.truth == Truth::holds   ? "holds"
                           : j.truth == Truth::fails ? "fails"
                                                     : "cannot decide",
                           j.why, j.worst);
  const tackle::CheckResult r = unknown.empty() ? s->checker->check_equation(text) : s->checker->check(unknown, text);
  std::cout << fmt::format("tackle: {}: {}\n", tackle::verdict_name(r.verdict), r.summary);
  return 0;
}

}  // namespace crosscheck

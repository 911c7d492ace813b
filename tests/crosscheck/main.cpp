// tackle_crosscheck: the independent numeric model against tackle's closed forms.
//   tackle_crosscheck examples DIR [PERTURB]    every DIR/*.yaml (skipped ones with the reason)
//   tackle_crosscheck generated N [SEED] [--family NAME] [--motion-every K] [--quiet] [PERTURB]
//                                               N random mechanisms from SEED
//   PERTURB (a deliberately wrong model, which must disagree): --perturb-masses X (the
//   model's masses times 1 + X), --perturb-inertia X (its moments of inertia times 1 + X),
//   --perturb-winding (its strings wound on drums wind the other way); or a deliberately
//   wrong tackle: --perturb-drop-answer (its first answer asked for left out),
//   --perturb-invert-condition (its first validity condition inverted)
//   tackle_crosscheck files FILE...             description files (the regressions); a file
//                                               named expected-disagreement-* must disagree
//   tackle_crosscheck print SEED                the mechanism SEED generates, as YAML
//   tackle_crosscheck equations|answers|fbds N [SEED] [--examples DIR] [--all] [--perturb-silent]
//                                               the oracle of verdicts (oracle.hpp): N students'
//                                               equations, answers or free body diagrams over
//                                               DIR's examples and generated mechanisms, each
//                                               decided by the model and checked by tackle
//                                               (--perturb-silent: tackle's verdicts left empty,
//                                               so that every item must disagree)
//   tackle_crosscheck explain FILE EQUATION [UNKNOWN]
//                                               one equation (an answer for UNKNOWN): the
//                                               model's values, its truth, tackle's verdict
// Exit status 1 when anything disagrees (beyond 1e-9 relative) or tackle refuses a
// generated mechanism.
#include <algorithm>
#include <cstdlib>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "crosscheck/compare.hpp"
#include "crosscheck/oracle.hpp"
#include "ruleset/ruleset.hpp"

namespace {

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void print_disagreements(const crosscheck::Outcome& o, std::size_t limit = 4) {
  for (std::size_t i = 0; i < o.disagreements.size() && i < limit; ++i) {
    const auto& d = o.disagreements[i];
    std::cout << fmt::format("    {}: tackle {:.15g}, model {:.15g}  at {}\n", d.quantity, d.tackle, d.model, d.state);
  }
  if (o.disagreements.size() > limit) std::cout << fmt::format("    ... and {} more\n", o.disagreements.size() - limit);
}

int usage() {
  std::cerr << "usage: tackle_crosscheck examples DIR [PERTURB] | generated N [SEED] [--family NAME] [--motion-every "
               "K] [--quiet] [PERTURB] | files FILE... | print SEED\n"
               "       | equations|answers|fbds N [SEED] [--examples DIR] [--all] [--perturb-silent] | explain FILE "
               "EQUATION [UNKNOWN]\n"
               "  PERTURB: --perturb-masses X | --perturb-inertia X | --perturb-winding | --perturb-drop-answer | "
               "--perturb-invert-condition\n";
  return 2;
}

// Reads a perturbation option at argv[i] (advancing i past its value); false when it is none.
bool perturbation(int argc, char** argv, int& i, crosscheck::Options& o) {
  const std::string a = argv[i];
  if (a == "--perturb-masses" && i + 1 < argc)
    o.perturb = std::stod(argv[++i]);
  else if (a == "--perturb-inertia" && i + 1 < argc)
    o.perturb_inertia = std::stod(argv[++i]);
  else if (a == "--perturb-winding")
    o.perturb_winding = true;
  else if (a == "--perturb-drop-answer")
    o.perturb_drop_answer = true;
  else if (a == "--perturb-invert-condition")
    o.perturb_invert_condition = true;
  else
    return false;
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  const tackle::RuleSet rules = tackle::load_rules(tackle::default_rules_dir());
  const auto started = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };

  if ((mode == "equations" || mode == "answers" || mode == "fbds") && argc >= 3) {
    crosscheck::OracleOptions o;
    o.kind = mode == "equations" ? crosscheck::OracleOptions::Kind::equations
             : mode == "answers" ? crosscheck::OracleOptions::Kind::answers
                                 : crosscheck::OracleOptions::Kind::fbds;
    o.count = std::stol(argv[2]);
    for (int i = 3; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--examples" && i + 1 < argc)
        o.examples = argv[++i];
      else if (a == "--all")
        o.shown = 0;
      else if (a == "--perturb-silent")
        o.silent = true;
      else
        o.seed = std::stoull(a);
    }
    const long disagreements = crosscheck::run_oracle(o, rules);
    std::cout << fmt::format("({:.1f} s)\n", elapsed());
    return disagreements ? 1 : 0;
  }
  if (mode == "explain" && (argc == 4 || argc == 5))
    return crosscheck::explain_one(argv[2], argv[3], argc == 5 ? argv[4] : "", rules,
                                   std::getenv("CROSSCHECK_SEED") ? std::stoull(std::getenv("CROSSCHECK_SEED")) : 1);
  if (mode == "print" && argc == 3) {
    std::cout << crosscheck::generate(std::stoull(argv[2]));
    return 0;
  }
  if (mode == "examples" && argc >= 3) {
    crosscheck::Options base;
    for (int i = 3; i < argc; ++i)
      if (!perturbation(argc, argv, i, base)) return usage();
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(argv[2]))
      if (e.path().extension() == ".yaml") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    int agree = 0, skipped = 0, refused = 0, disagree = 0, compared = 0;
    for (const auto& f : files) {
      crosscheck::Options o = base;
      o.states = 6;
      const auto out = crosscheck::compare(read(f), f.filename().string(), rules, o);
      const std::string name = f.filename().string();
      switch (out.kind) {
        case crosscheck::Outcome::Kind::agree:
          ++agree;
          compared += out.compared;
          std::cout << fmt::format(
              "agree     {} ({} states, {} values{}{})\n", name, out.states, out.compared,
              out.not_determined ? fmt::format(", {} left free by the model", out.not_determined) : "",
              out.motion_points
                  ? fmt::format(", motion: {} points, max error {:.2g}", out.motion_points, out.motion_error)
                  : "");
          if (!out.motion_note.empty()) std::cout << "          motion: " << out.motion_note << "\n";
          if (!out.motion_event.empty())
            std::cout << "          the motion's first event: " << out.motion_event << "\n";
          for (const auto& note : out.not_compared) std::cout << "          not compared: " << note << "\n";
          break;
        case crosscheck::Outcome::Kind::skipped:
          ++skipped;
          std::cout << fmt::format("skipped   {}: {}\n", name, out.reason);
          break;
        case crosscheck::Outcome::Kind::tackle_refused:
          ++refused;
          std::cout << fmt::format("refused   {}: {}\n", name, out.reason);
          break;
        case crosscheck::Outcome::Kind::disagree:
          ++disagree;
          std::cout << fmt::format("DISAGREE  {}\n", name);
          print_disagreements(out);
          break;
      }
    }
    std::cout << fmt::format(
        "{} examples: {} agree ({} values compared), {} skipped, {} not solved by tackle, {} disagree ({:.1f} s)\n",
        files.size(), agree, compared, skipped, refused, disagree, elapsed());
    return disagree ? 1 : 0;
  }
  if (mode == "generated" && argc >= 3) {
    const long n = std::stol(argv[2]);
    std::uint64_t seed = 1;
    int motion_every = 1;
    bool quiet = false;
    std::string family;  // with --family NAME, only that family's mechanisms (n of them)
    crosscheck::Options base;
    for (int i = 3; i < argc; ++i) {
      const std::string a = argv[i];
      if (a == "--motion-every" && i + 1 < argc)
        motion_every = std::stoi(argv[++i]);
      else if (a == "--family" && i + 1 < argc)
        family = argv[++i];
      else if (perturbation(argc, argv, i, base))
        continue;
      else if (a == "--quiet")
        quiet = true;
      else
        seed = std::stoull(a);
    }
    long disagree = 0, refused = 0, skipped = 0, compared = 0, motions = 0, free_values = 0;
    std::map<std::string, long> kinds;
    for (long i = 0, made = 0; made < n; ++i) {
      const std::uint64_t s = seed * 1000003ULL + static_cast<std::uint64_t>(i);
      std::string kind;
      std::string text = crosscheck::generate(s, &kind);
      if (!family.empty() && kind != family) {
        if (i > 1000 * (made + 1)) {
          std::cerr << fmt::format("tackle_crosscheck: no family named '{}'\n", family);
          return 2;
        }
        continue;
      }
      ++made;
      ++kinds[kind];
      crosscheck::Options o = base;
      o.seed = s;
      o.states = 3;
      o.motion = motion_every > 0 && (made - 1) % motion_every == 0;
      // (without the motion compared, its section goes: tackle's motion stage is not needed)
      if (!o.motion && text.find("\nmotion:\n") != std::string::npos) text.erase(text.find("\nmotion:\n") + 1);
      const double before = elapsed();
      const auto out = crosscheck::compare(text, fmt::format("generated-{}.yaml", s), rules, o);
      if (elapsed() - before > 1.0)
        std::cout << fmt::format("slow      mechanism {} ({}): {:.1f} s\n", s, kind, elapsed() - before);
      compared += out.compared;
      free_values += out.not_determined;
      if (out.motion_points) ++motions;
      if (out.kind == crosscheck::Outcome::Kind::disagree) {
        ++disagree;
        std::cout << fmt::format("DISAGREE  mechanism {} ({}); tackle_crosscheck print {} shows it\n", s, kind, s);
        print_disagreements(out);
      } else if (out.kind == crosscheck::Outcome::Kind::tackle_refused) {
        ++refused;
        std::cout << fmt::format("REFUSED   mechanism {} ({}): {}\n", s, kind, out.reason);
      } else if (out.kind == crosscheck::Outcome::Kind::skipped) {
        ++skipped;
        std::cout << fmt::format("SKIPPED   mechanism {} ({}): {}\n", s, kind, out.reason);
      } else if (!quiet) {
        std::cout << fmt::format("agree     mechanism {} ({}): {} values{}{}\n", s, kind, out.compared,
                                 out.motion_points ? fmt::format(", motion max error {:.2g}", out.motion_error) : "",
                                 out.motion_note.empty() ? "" : "; motion: " + out.motion_note);
      }
    }
    std::string families;
    for (const auto& [k, c] : kinds) families += fmt::format("{}{} {}", families.empty() ? "" : ", ", c, k);
    std::cout << fmt::format("families: {}\n", families);
    std::cout << fmt::format(
        "{} values compared, {} left free by the model, {} motions compared over 1 s, {} refused by tackle, {} skipped "
        "({:.1f} s)\n",
        compared, free_values, motions, refused, skipped, elapsed());
    std::cout << fmt::format("{} mechanisms, {} disagreements\n", n, disagree);
    return disagree || refused || skipped ? 1 : 0;
  }
  if (mode == "files" && argc >= 3) {
    int failures = 0;
    for (int i = 2; i < argc; ++i) {
      const std::filesystem::path f = argv[i];
      const bool expected = f.filename().string().rfind("expected-disagreement-", 0) == 0;
      crosscheck::Options o;
      o.states = 6;
      const auto out = crosscheck::compare(read(f), f.filename().string(), rules, o);
      const bool disagrees = out.kind == crosscheck::Outcome::Kind::disagree;
      const bool ok = expected ? disagrees : out.kind == crosscheck::Outcome::Kind::agree;
      if (!ok) ++failures;
      std::cout << fmt::format(
          "{}  {}: {}{}\n", ok ? "ok  " : "FAIL", f.filename().string(),
          disagrees                                      ? "disagrees"
          : out.kind == crosscheck::Outcome::Kind::agree ? "agrees" + (out.reason.empty() ? "" : ": " + out.reason)
                                                         : "not compared: " + out.reason,
          expected ? (disagrees ? " (a known disagreement: tackle's bug, still there)"
                                : " (expected a disagreement: rename the file once tackle is fixed)")
                   : "");
      if (disagrees) print_disagreements(out);
      if (!out.motion_note.empty()) std::cout << "      motion: " << out.motion_note << "\n";
    }
    return failures ? 1 : 0;
  }
  return usage();
}

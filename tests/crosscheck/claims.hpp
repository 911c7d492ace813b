// What tackle says beyond the closed forms of its unknowns (issue 41, item 3): an answer for
// every quantity the description asks for, the conditions under which its solution holds
// (each with whether it holds at the given numbers and whether it always holds), and the slip
// speed of a sliding contact on a turning body (which way its friction acts). Copied out of
// tackle's analysis, so that a mistake can be planted in them (the tests that the comparison
// catches one), then compared with the model at each state.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "crosscheck/compare.hpp"
#include "crosscheck/model.hpp"
#include "pipeline/pipeline.hpp"

namespace crosscheck {

struct Claims {
  struct Asked {
    std::string name;                 // as the description asks it (`find`)
    std::optional<std::string> expr;  // a quantity defined from the unknowns (F/ddot(x_B)), as text
    bool answered = false;            // tackle gives a closed form for it
    GiNaC::ex value;                  // that closed form
    std::string status;               // why not, when it gives none
  };
  std::vector<Asked> asked;
  struct Condition {
    std::string source, op;
    std::string lhs, rhs;          // as the rule states it (T >= 0), in tackle's names
    std::set<std::string> forces;  // the unknowns it is about
    GiNaC::ex value;               // with the solution put in: `value op 0`
    std::optional<bool> holds;     // at the given numbers
    std::optional<bool> always;    // for every positive value of the parameters
  };
  std::vector<Condition> conditions;
  std::vector<std::pair<std::string, GiNaC::ex>> slips;  // a sliding contact's label, its slip speed
  std::set<std::string> solved;                          // the unknowns tackle determines
};

/// tackle's claims about a description it solved.
[[nodiscard]] Claims claims_of(const tackle::Analysis& a, const tackle::Description& d);
/// The deliberate mistakes of `o` planted in them: the first answer asked for left out, the
/// first condition inverted.
void plant(Claims& c, const Options& o);

/// One state, as the comparison sees it: tackle's expressions evaluated there, the model's
/// instant and its values (parameters, coordinates, rates, solved quantities).
struct ClaimState {
  const State* state = nullptr;
  const Instant* instant = nullptr;
  std::map<std::string, double> values;
  std::function<std::optional<double>(const GiNaC::ex&)> tackle_value;
  double force_scale = 1, accel_scale = 1;
  bool base = false;  // the layout at the given numbers: where a stated `holds` applies
  std::string where;
};

/// Compares the claims with the model at one state; disagreements and what could not be
/// compared (`notes`, each once) are added to `out`.
void compare_claims(const Claims& c, const Model& m, const ClaimState& s, Outcome& out, std::set<std::string>& notes);

}  // namespace crosscheck

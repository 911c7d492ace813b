// Numeric integration of the equations of motion (Boost.Odeint, Dormand-Prince 5(4) with
// dense output), for any motion the description asks for, linear or not: the state is the
// motion's coordinates and rates, the right-hand side their solved accelerations compiled to
// doubles. Events: a validity condition that stops holding (a string going slack, a contact
// lost) ends the run there, since the model no longer holds; so does a rate changing sign
// where a rule assumed the direction of motion (sliding friction).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/analysis.hpp"
#include "numeric/plot.hpp"

namespace tackle {

struct SimulationSpec {
  std::optional<double> until;    // seconds (default: the description's 'until')
  std::vector<std::string> plot;  // expressions in the answers, coordinates, rates, parameters and t
  int samples = 201;              // rows of the table, evenly spaced in time
  double tolerance = 1e-10;       // relative and absolute error per step
  double time_limit = 10;         // seconds of computing before giving up
};

struct SimulationEvent {
  double t = 0;
  std::string what;   // "contact c: the contact pushes no longer"
  bool ends = false;  // the run ends here
};

struct Simulation {
  SweepResult table;  // t and the plotted quantities, for the sweep writers
  std::vector<SimulationEvent> events;
  double reached = 0;     // the time the run reached
  bool complete = false;  // it reached 'until' with the model holding throughout
  std::string stopped;    // why it ended early, in words
  std::size_t steps = 0;  // accepted integration steps
  // What the run does not watch (source, why): a strand whose length needs a starting value
  // 'initial' does not give. "The model holds throughout" is said only without these.
  std::vector<std::pair<std::string, std::string>> not_followed;
};

/// Runs the motion; problems with the spec (a plot name it does not know, no 'until') are
/// located InputErrors (`where` names the option or the description key).
[[nodiscard]] Simulation simulate(const Analysis& a, const SimulationSpec& spec, const Location& where);

}  // namespace tackle

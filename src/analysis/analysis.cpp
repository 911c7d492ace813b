#include "analysis/analysis.hpp"

#include "analysis/regimes.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "solve/bounds.hpp"

#include <algorithm>

namespace tackle {

using namespace GiNaC;

namespace {

// Motion in time, after the instant; a motion that cannot be followed is an input error at
// the description's 'motion'.
void follow_motion(Analysis& a) {
  a.motion = analyze_motion(a.model, a.system, a.solution);
  if (a.motion && !a.motion->problem.empty())
    throw InputError({{a.motion->problem_at.value_or(a.model.motion->at), a.motion->problem}});
}

}  // namespace

namespace {

void sort_by_place(std::vector<Diagnostic>& all) {
  std::stable_sort(all.begin(), all.end(), [](const Diagnostic& x, const Diagnostic& y) {
    return std::pair(x.where.line, x.where.column) < std::pair(y.where.line, y.where.column);
  });
}

// Balances that contradict each other are a description that cannot be right (exit 1), never
// a derivation: the conflicting equations named, at the first body they balance, with what
// could supply what is missing.
InputError contradiction(const Model& m, const EquationSystem& s, const Solution& sol) {
  Location at{m.file, 0, 0};
  std::string expected;
  for (const auto& label : sol.conflicts) {
    const auto e =
        std::find_if(s.equations.begin(), s.equations.end(), [&](const Equation& x) { return x.label == label; });
    if (e == s.equations.end() || e->bodies.empty() || e->system) continue;
    const Body& b = m.bodies[static_cast<std::size_t>(e->bodies.front())];
    if (at.line == 0) at = b.at;
    if (!expected.empty()) continue;
    if (e->kind == Equation::Kind::amb && b.angle.is_zero())
      expected = "body '" + b.name +
                 "' does not turn (it has no angle), so the moments on it must cancel: a second contact, "
                 "its forces through its center of mass, or an angle and a shape or inertia to turn with";
    else if (e->kind == Equation::Kind::amb && b.inertia.is_zero())
      expected = "body '" + b.name +
                 "' has no shape or inertia to turn with, so the moments on it must cancel: a second contact, "
                 "its forces through its center of mass, or a shape or inertia";
    else if (e->kind == Equation::Kind::lmb && b.mass.is_zero())
      expected = "body '" + b.name +
                 "' has no mass, so the forces on it must cancel: a support, a string or a contact that "
                 "balances them, or a mass";
  }
  if (expected.empty())
    expected = "a support or a contact that balances the forces, or a coordinate that lets the body move that way";
  // (One equation alone: it reads 0 = a term that is not zero, a force or a moment.)
  std::string alone = "a term that is not zero";
  if (sol.conflicts.size() == 1)
    if (const auto e = std::find_if(s.equations.begin(), s.equations.end(),
                                    [&](const Equation& x) { return x.label == sol.conflicts.front(); });
        e != s.equations.end())
      alone = e->kind == Equation::Kind::lmb   ? "a force that is not zero"
              : e->kind == Equation::Kind::amb ? "a moment that is not zero"
                                               : alone;
  const std::string which = sol.conflicts.size() == 1
                                ? sol.conflicts.front() + " reads 0 = " + alone
                                : join(std::vector<std::string>(sol.conflicts.begin(), sol.conflicts.end() - 1)) +
                                      " and " + sol.conflicts.back() + " contradict each other";
  return InputError({{at, "the balances cannot all hold: " + which + " (expected " + expected + ")"}});
}

// One description (or one phase): model, balances, solve, power, the interval's end or the
// impact, motion. `prior` are the reading problems, reported with the model's.
std::unique_ptr<Analysis> analyze_one(const Description& d, const RuleSet& rules, std::vector<Diagnostic> prior) {
  auto a = std::make_unique<Analysis>();
  try {
    a->model = build_model(d, rules);
  } catch (const InputError& e) {
    prior.insert(prior.end(), e.diagnostics().begin(), e.diagnostics().end());
  }
  if (!prior.empty()) {
    sort_by_place(prior);
    throw InputError(prior);
  }
  if (a->model.impact) {
    a->power.reason = "the rates jump at an impact (its check is the energy, above)";
    a->impact = analyze_impact(a->model);
    return a;
  }
  a->system = build_equations(a->model);
  if (auto problems = check_dimensions(a->model, a->system); !problems.empty()) throw InputError(problems);
  a->solution = solve(a->model, a->system);
  if (a->solution.status == Solution::Status::inconsistent) throw contradiction(a->model, a->system, a->solution);
  a->power = check_power(a->model, a->system, a->solution);
  if (a->model.interval) {
    a->interval_end = interval_end(a->model, a->solution);
    if (!a->interval_end->problem.empty())
      throw InputError({{a->model.interval->at, "'interval': " + a->interval_end->problem}});
  }
  follow_motion(*a);
  return a;
}

// A description with connections decided at the numbers: each in its first regime, then the
// next where that one's validity fails (analysis/regimes). Others: as they are.
std::unique_ptr<Analysis> analyze_decided(const Description& d, const RuleSet& rules, std::vector<Diagnostic> prior) {
  const std::vector<std::size_t> which = decided_connections(d, rules);
  if (which.empty()) return analyze_one(d, rules, std::move(prior));
  std::vector<std::size_t> regime(which.size(), 0);
  std::vector<bool> turn(which.size(), false);
  // (Decided without the motion: its coordinates are those of the regime chosen, which may
  // have more degrees of freedom than the first.)
  Description first = with_regimes(d, rules, which, regime, turn);
  const bool motion = first.motion.has_value();
  first.motion.reset();
  std::unique_ptr<Analysis> a = analyze_one(first, rules, prior);
  std::vector<RegimeChoice> choices;
  bool changed = false;
  for (std::size_t k = 0; k < which.size(); ++k) {
    bool t = false;
    choices.push_back(decide_regime(*a, d, rules, which[k], t));
    if (choices.back().chosen != choices.back().first) {
      regime[k] = 1;
      turn[k] = t;
      changed = true;
    }
  }
  if (changed || motion) {
    a = analyze_one(with_regimes(d, rules, which, regime, turn), rules, std::move(prior));
    for (std::size_t k = 0; k < which.size(); ++k) choices[k].connection = a->model.connections.at(which[k]).label;
  }
  a->regimes = std::move(choices);
  return a;
}

// The phases in order, each carrying its end state into the next as defined parameters (the
// closed forms printed and read back in the next phase's names, which share the parameters).
std::unique_ptr<Analysis> analyze_phases(const Description& d, const RuleSet& rules, std::vector<Diagnostic> prior) {
  auto top = std::make_unique<Analysis>();
  top->model.title = d.title.text;
  top->model.file = d.file;
  std::vector<ParameterDesc> carried;
  for (const auto& ph : d.phases) {
    Description pd = ph.d;
    pd.parameters.insert(pd.parameters.begin() + static_cast<std::ptrdiff_t>(d.parameters.size()), carried.begin(),
                         carried.end());
    std::unique_ptr<Analysis> a;
    try {
      a = analyze_decided(pd, rules, {});
    } catch (const InputError& e) {
      // Later phases need what this one carries: the chain stops here.
      prior.insert(prior.end(), e.diagnostics().begin(), e.diagnostics().end());
      break;
    }
    Phase phase{ph.name.text, ph.at, nullptr, {}};
    const SymbolTable& table = *a->model.symbols;
    const exmap state = end_state(a->model, a->solution, a->interval_end, a->impact);
    bool ok = true;
    for (const auto& [name, value] : ph.carry) {
      const auto parsed = parse_expression(value.text, table);
      if (!parsed.value) {
        for (const auto& p : parsed.problems)
          prior.push_back({value.at.shifted(p.column), "'carry' of phase '" + ph.name.text + "': " + p.message});
        ok = false;
        continue;
      }
      ex at_end = parsed.value->subs(state);
      std::vector<std::string> missing;
      for (const auto& sym : table.all())
        if (sym->role != SymbolRole::parameter && at_end.has(sym->sym)) missing.push_back(sym->name);
      if (!missing.empty()) {
        std::vector<std::string> known;
        for (const auto& [k, v] : state) known.push_back(to_text(k));
        std::sort(known.begin(), known.end());
        prior.push_back({value.at, "'carry' of phase '" + ph.name.text + "': " + join(missing) +
                                       " is not known at the end of the phase (known there: " +
                                       (known.empty() ? std::string("nothing but the parameters") : join(known)) +
                                       ")"});
        ok = false;
        continue;
      }
      at_end = simplest(at_end);
      ParameterDesc p;
      p.name = name;
      p.define = Text{to_text(at_end), value.at};
      p.positive = false;
      carried.push_back(p);
      phase.carried.emplace_back(name.text, at_end);
    }
    phase.analysis = std::move(a);
    top->phases.push_back(std::move(phase));
    if (!ok) break;
  }
  if (!prior.empty()) {
    sort_by_place(prior);
    throw InputError(prior);
  }
  return top;
}

}  // namespace

std::unique_ptr<const Analysis> analyze(const Description& d, const RuleSet& rules) {
  if (!d.phases.empty()) return analyze_phases(d, rules, {});
  return analyze_decided(d, rules, {});
}

std::unique_ptr<const Analysis> analyze_text(const std::string& text, const std::string& file, const RuleSet& rules) {
  DescriptionRead read = read_description_text(text, file);
  if (!read.usable) throw InputError(read.problems);
  if (!read.description.phases.empty()) {
    // Reading problems first: a phase's model is not built on a phase that could not be read.
    if (!read.problems.empty()) {
      sort_by_place(read.problems);
      throw InputError(read.problems);
    }
    return analyze_phases(read.description, rules, {});
  }
  return analyze_decided(read.description, rules, read.problems);
}

const Analysis* pick_phase(const Analysis& a, const std::string& name, std::string& message) {
  std::vector<std::string> names;
  for (const auto& p : a.phases) names.push_back(p.name);
  if (a.phases.empty()) {
    if (!name.empty()) message = "--phase " + name + ": the description has no phases";
    return message.empty() ? &a : nullptr;
  }
  for (const auto& p : a.phases)
    if (p.name == name) return p.analysis.get();
  message = (name.empty() ? std::string("the description has phases") : "there is no phase '" + name + "'") +
            " (expected --phase with one of: " + join(names) + ")";
  return nullptr;
}

std::unique_ptr<const Analysis> analyze_file(const std::string& path, const RuleSet& rules) {
  return analyze_text(read_text_file(path), path, rules);
}

}  // namespace tackle

#include "analysis/analysis.hpp"

#include "analysis/regimes.hpp"
#include "analysis/runs.hpp"
#include "expr/parse.hpp"
#include "expr/print.hpp"
#include "solve/bounds.hpp"

#include <algorithm>
#include <cmath>
#include <map>

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

// The runs (analysis/runs.hpp): a sweep of the closed forms, and the described motion and sweep.

namespace {

// Answers by their closed forms, parameters by their symbols.
class SweepNames : public NameResolver {
 public:
  SweepNames(const SymbolTable& table, const std::vector<Answer>& answers) : table_(table) {
    for (const auto& a : answers)
      if (a.closed_form) answers_[a.name] = *a.closed_form;
  }
  std::optional<ex> resolve(std::string_view name) const override {
    if (auto it = answers_.find(std::string(name)); it != answers_.end()) return it->second;
    if (const SymbolInfo* s = table_.find(name); s && s->role == SymbolRole::parameter) return s->sym;
    return std::nullopt;
  }
  std::vector<std::string> known_names() const override {
    std::vector<std::string> out;
    for (const auto& [k, v] : answers_) out.push_back(k);
    for (const auto& s : table_.all())
      if (s->role == SymbolRole::parameter) out.push_back(s->name);
    return out;
  }

 private:
  const SymbolTable& table_;
  std::map<std::string, ex> answers_;
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// One point of a sweep: where it is on the axis and in the varied parameter, each curve's
// value there, whether every condition holds.
struct SweepPoint {
  double x, varied;
  std::vector<std::optional<double>> y;
  bool valid, boundary = false, inserted = false;
};

// The steps of a sweep and what they share: the spec read (its problems collected, thrown
// where each part of it has been read), the curves and conditions in normal form, the points
// sampled, and the result they fill.
struct Sweep {
  const SymbolTable& table;
  const std::vector<Answer>& answers;
  const std::vector<ConditionReport>& conditions;
  const SweepSpec& spec;
  const Location& where;
  Diagnostics diags;
  SweepResult r;
  std::vector<std::string> parts;  // the range's start, end and count, as written
  const SymbolInfo* x = nullptr;   // the varied parameter
  std::optional<numeric> start, end, count;
  exmap base;  // the parameters' values, with the fixed ones
  std::vector<ex> curves;
  std::optional<NormalForm> against;  // the horizontal axis, when it is an expression
  std::vector<NormalForm> curve_forms, condition_forms;
  std::vector<SweepPoint> points;

  // A number as written, or a problem.
  std::optional<numeric> number(const std::string& text, const std::string& what) {
    auto parsed = parse_expression(text, numbers_only());
    if (!parsed.value || !is_a<numeric>(*parsed.value)) {
      diags.error(where, what + " '" + text + "' is not a number");
      return std::nullopt;
    }
    return ex_to<numeric>(*parsed.value);
  }

  // A parameter with a value of its own (not a defined one), or a problem naming those there are.
  const SymbolInfo* parameter(const std::string& name, const std::string& what) {
    const SymbolInfo* s = table.find(name);
    if (!s || s->role != SymbolRole::parameter || s->definition) {
      std::vector<std::string> known;
      for (const auto& p : table.all())
        if (p->role == SymbolRole::parameter && !p->definition) known.push_back(p->name);
      diags.error(where, what + " names '" + name + "', which is not a parameter (parameters: " + join(known) + ")");
      return nullptr;
    }
    return s;
  }

  // The range to vary, name=start:end:count; a range not of that shape is thrown at once.
  void read_range() {
    const auto eq = spec.vary.find('=');
    if (eq != std::string::npos) {
      std::string rest = spec.vary.substr(eq + 1);
      for (std::size_t p; (p = rest.find(':')) != std::string::npos; rest = rest.substr(p + 1))
        parts.push_back(rest.substr(0, p));
      parts.push_back(rest);
    }
    if (eq == std::string::npos || parts.size() != 3) {
      diags.error(where, "'" + spec.vary + "' is not a range to vary (expected name=start:end:count, e.g. h=0:2:41)");
      diags.throw_if_any();
    }
    x = parameter(trim(spec.vary.substr(0, eq)), "the range to vary");
    start = number(parts[0], "the start");
    end = number(parts[1], "the end");
    count = number(parts[2], "the count");
    if (count && (!count->is_integer() || *count < 2 || *count > 100000))
      diags.error(where, "the count '" + parts[2] + "' is not a whole number from 2 to 100000");
  }

  // The parameters' values, with those the spec fixes (in their units).
  void read_fixed() {
    base = table.values();
    for (const auto& f : spec.fix) {
      const auto e2 = f.find('=');
      if (e2 == std::string::npos) {
        diags.error(where, "'" + f + "' is not a fixed value (expected name=value, e.g. l=1)");
        continue;
      }
      const SymbolInfo* s = parameter(trim(f.substr(0, e2)), "'" + f + "'");
      const auto v = number(trim(f.substr(e2 + 1)), "the value");
      if (s && v) base[s->sym] = *v * s->unit_to_si;
    }
  }

  // The expressions to plot, in the answers and parameters, with their legends; the spec's
  // problems so far are thrown here.
  void read_curves() {
    SweepNames names(table, answers);
    for (const auto& p : spec.plot) {
      auto parsed = parse_expression(p, names);
      if (!parsed.value) {
        diags.error(where, "plot '" + p + "': " + parsed.problems.front().message);
        continue;
      }
      curves.push_back(*parsed.value);
      r.names.push_back(trim(p));
      // For the legend: the expression as written, answers as their own symbols (N_{A} - N_{B}).
      auto shown = parse_expression(p, table);
      r.latex.push_back(to_latex(shown.value ? *shown.value : fold_definitions(*parsed.value, table)));
    }
    if (spec.plot.empty()) diags.error(where, "nothing to plot (expected a list such as N_A,N_B,N_A-N_B)");
    diags.throw_if_any();
  }

  // Each curve's unit, one for the y axis when every curve has the same dimension; the
  // horizontal axis the varied parameter's.
  void choose_units() {
    std::optional<Dimension> common;
    bool same = true;
    for (const auto& c : curves) {
      std::string problem;
      auto dim = dimension_of(c, table, problem);
      r.units.push_back(dim ? si_unit_name(*dim) : "");
      if (!dim || (common && !(*common == *dim)))
        same = false;
      else
        common = dim;
    }
    if (same && common) r.y_unit = si_unit_name(*common);
    r.x_name = x->name;
    r.x_unit = x->unit;
    r.x_latex = x->tex;
  }

  // Against an expression in the parameters (figure 12.28 plots against h/l): its value at
  // each point, in SI (or a pure number); its problems are thrown here.
  void read_against() {
    if (spec.against.empty()) return;
    auto parsed = parse_expression(spec.against, table);
    std::string problem;
    if (!parsed.value) {
      diags.error(where, "against '" + spec.against + "': " + parsed.problems.front().message);
    } else if (!parsed.value->has(x->sym)) {
      diags.error(where, "against '" + trim(spec.against) + "' does not change with " + x->name +
                             " (expected an expression in it, e.g. " + x->name + "/l)");
    } else if (auto dim = dimension_of(*parsed.value, table, problem); !dim) {
      diags.error(where, "against '" + trim(spec.against) + "': " + problem);
    } else {
      for (const auto& s : table.all())
        if (s->role != SymbolRole::parameter && parsed.value->has(s->sym))
          diags.error(where, "against '" + trim(spec.against) + "' uses '" + s->name + "', which is not a parameter");
      against.emplace(*parsed.value);
      name_axis(*parsed.value, *dim);
    }
    diags.throw_if_any();
  }

  // The horizontal axis named by the expression `along`, the varied parameter kept beside it.
  void name_axis(const ex& along, const Dimension& dim) {
    r.varied_name = r.x_name;
    r.varied_unit = r.x_unit;
    r.x_name = trim(spec.against);
    r.x_unit = dim.exp == Dimension::none().exp ? "" : si_unit_name(dim);
    // Inline, as an axis is labelled: h/l, not a built-up fraction.
    const ex nd = numer_denom(along);
    auto part = [](const ex& e) { return is_a<add>(e) ? "\\left(" + to_latex(e) + "\\right)" : to_latex(e); };
    r.x_latex = nd.op(1).is_equal(1) ? to_latex(along) : part(nd.op(0)) + "/" + part(nd.op(1));
  }

  // Each curve's and condition's normal form once; each point only substitutes into it.
  void make_forms() {
    r.y.assign(curves.size(), {});
    for (const auto& c : curves) curve_forms.emplace_back(c);
    for (const auto& cond : conditions) condition_forms.emplace_back(cond.simplified);
  }

  // The values at one point of the varied parameter: the definitions (undefined points, a
  // denominator that vanishes there, have no value: a gap in the curve).
  exmap values_at(const numeric& xv) const {
    exmap values = base;
    values[x->sym] = xv * x->unit_to_si;
    for (const auto& s : table.all())
      if (s->definition)
        if (auto v = value_at(*s->definition, values)) values[s->sym] = *v;
    return values;
  }

  // Every validity condition holds: exact at rational points (N_A is exactly 0 at h/l = 1),
  // else a high-precision float; undefined there: not valid. With roots in it (a tilted
  // normal), a double: normal() of radicals is slow and no exact zero test anyway.
  bool holds(const exmap& values, bool exact) const {
    for (std::size_t k = 0; k < conditions.size(); ++k) {
      const auto& cond = conditions[k];
      if (!exact || !is_rational_number(substituted(condition_forms[k].num, values)) ||
          !is_rational_number(substituted(condition_forms[k].den, values))) {
        const auto a = condition_forms[k].approx_at(values);
        if (!a || !relation_holds(numeric(*a), cond.op)) return false;
        continue;
      }
      const auto at = condition_forms[k].at(values);
      ex v = at ? *at : ex(0);
      if (!is_a<numeric>(v)) v = evalf(v);
      if (!at || !is_a<numeric>(v) || !ex_to<numeric>(v).is_real() || !relation_holds(ex_to<numeric>(v), cond.op))
        return false;
    }
    return true;
  }

  // The point at a value of the varied parameter.
  SweepPoint point(const numeric& xv, bool exact) const {
    const exmap values = values_at(xv);
    SweepPoint p{against ? against->approx_at(values).value_or(std::nan("")) : xv.to_double(),
                 xv.to_double(),
                 {},
                 holds(values, exact)};
    for (const auto& f : curve_forms) p.y.push_back(f.approx_at(values));
    return p;
  }

  // The i-th of the evenly spaced samples.
  numeric sample(int i) const { return *start + (*end - *start) * numeric(i, count->to_int() - 1); }

  // The samples, with the bound between two of them where the validity changes.
  void sample_all() {
    const int n = count->to_int();
    for (int i = 0; i < n; ++i) {
      SweepPoint p = point(sample(i), true);
      if (i > 0 && p.valid != points.back().valid) mark_bound(i, p);
      points.push_back(std::move(p));
    }
  }

  // Where the validity changes between sample i - 1 and sample i (`p`), the bound between the
  // two, found by bisection: the dashed part begins where the condition fails, not at the next
  // sample. A sample is marked when the bound falls on it, else a point is put in between.
  void mark_bound(int i, SweepPoint& p) {
    const bool from = points.back().valid;
    const double a = sample(i - 1).to_double(), b = sample(i).to_double();
    double lo = a, hi = b;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      (holds(values_at(numeric(mid)), false) == from ? lo : hi) = mid;
    }
    const double at = from ? lo : hi;  // on the valid side
    const double tol = 1e-9 * std::abs(b - a);
    if (std::abs(at - a) <= tol) {
      points.back().boundary = true;
    } else if (std::abs(at - b) <= tol) {
      p.boundary = true;
    } else {
      SweepPoint q = point(numeric(at), false);
      q.valid = q.boundary = q.inserted = true;
      points.push_back(std::move(q));
    }
  }

  // The points into the result's columns.
  void fill_result() {
    const bool any_boundary = std::any_of(points.begin(), points.end(), [](const SweepPoint& p) { return p.boundary; });
    for (const SweepPoint& p : points) {
      r.x.push_back(p.x);
      if (against) r.varied.push_back(p.varied);
      for (std::size_t c = 0; c < curves.size(); ++c) r.y[c].push_back(p.y[c]);
      r.valid.push_back(p.valid);
      if (any_boundary) r.boundary.push_back(p.boundary), r.inserted.push_back(p.inserted);
    }
  }

  // Where the axis' expression is undefined, no curve has a point; undefined everywhere, a problem.
  void drop_undefined() {
    bool any = false;
    for (std::size_t i = 0; i < r.x.size(); ++i) {
      if (std::isfinite(r.x[i]))
        any = true;
      else
        for (auto& c : r.y) c[i].reset();
    }
    if (!any) {
      diags.error(where, "against '" + trim(spec.against) + "' is undefined over the whole range");
      diags.throw_if_any();
    }
  }
};

}  // namespace

SweepSpec sweep_spec(const SweepDesc& s) {
  SweepSpec spec;
  spec.vary = s.vary.text;
  for (const auto& f : s.fix) spec.fix.push_back(f.text);
  for (const auto& p : s.plot) spec.plot.push_back(p.text);
  if (s.against) spec.against = s.against->text;
  return spec;
}

SweepResult evaluate_sweep(const Model& m, const std::vector<Answer>& answers,
                           const std::vector<ConditionReport>& conditions, const SweepSpec& spec,
                           const Location& where) {
  Sweep s{*m.symbols, answers, conditions, spec, where};
  s.r.title = m.title;
  s.read_range();
  s.read_fixed();
  s.read_curves();
  s.choose_units();
  s.read_against();
  s.make_forms();
  s.sample_all();
  s.fill_result();
  s.drop_undefined();
  return std::move(s.r);
}

DescribedRuns run_described(const Analysis& a, const Answers& answers) {
  DescribedRuns runs;
  if (a.motion && a.model.motion->until) {
    // A figure, not a command: a second of computing at most (a hostile 'until' must not
    // hold a report up; `tackle simulate` allows 10 s).
    SimulationSpec spec;
    spec.time_limit = 1;
    runs.motion = simulate(a, spec, a.model.motion->at);
  }
  if (a.model.sweep)
    runs.sweep =
        evaluate_sweep(a.model, answers.answers, answers.conditions, sweep_spec(*a.model.sweep), a.model.sweep->at);
  return runs;
}

}  // namespace tackle

// Grading a student's free body diagram against the model's own (check/fbd.hpp): tackle's forces
// as entries (each with its point, its line, its sense where the model knows it, and its kind),
// the student's arrows matched to them by point, line and kind (an assignment problem), then
// the grade of each force, of the couples, and of the arrows left over.
#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include "check/equation.hpp"
#include "check/fbd.hpp"
#include "algebra/assignment.hpp"
#include "expr/print.hpp"
#include "model/forces.hpp"
#include "numeric/layout.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

constexpr double pi = 3.14159265358979323846;

using Triple = std::array<double, 3>;

double dot3(const Triple& a, const Triple& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Triple& a) { return std::sqrt(dot3(a, a)); }
Triple minus3(const Triple& a, const Triple& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Triple cross3(const Triple& a, const Triple& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

std::string bodies_phrase(const std::vector<std::string>& names) {
  if (names.empty()) return "no body";
  if (names.size() == 1) return names.front();
  std::vector<std::string> head(names.begin(), names.end() - 1);
  return "the system of " + join(head) + " and " + names.back();
}

// One force of tackle's diagram the student should draw.
struct Entry {
  std::size_t load = 0;
  std::optional<Triple> at;
  std::string at_name;
  std::vector<Triple> lines;  // one direction per part (a free force: several); empty: any
  bool fixed = false;         // its sense is known (the first line's)
  bool free = false;          // a force of unknown direction (a pin's): any arrow in the span of its lines
  bool zero = false;          // nothing at the sketch's position
  bool couple = false;
  int couple_sense = 0;
  bool point_matters = false;      // its point sets its moment about its body's center of mass
  std::string kind;                // weight, tension, spring, damper, applied or support
  std::string key;                 // its load's force_key (a carried force: its connection)
  std::vector<std::string> names;  // its unknowns' names (the first: for a student who used the same)
};

// What grading one diagram shares.
struct Diagram {
  const Model& m;
  const StudentFbd& fbd;
  const FbdRubric& rubric;
  std::vector<int> bodies;
  std::set<ex, ex_is_less> defaulted;  // parameters without a value, taken as 1
  exmap values;                        // the numbers the sketch shows
  std::vector<std::optional<Triple>> arrow_at;
  std::vector<std::string> arrow_kind;  // said, or settled for identical arrows; empty: any kind
  std::set<std::string> internal;
  std::set<ex, ex_is_less> unknowns, positive;
  std::vector<Entry> entries;
  double cos_tol = 1, sin_tol = 0;

  Diagram(const Model& model, const StudentFbd& f, const FbdRubric& r) : m(model), fbd(f), rubric(r) {}
  [[nodiscard]] std::optional<double> num(const ex& e) const { return real_at(e, values); }
  [[nodiscard]] std::optional<Triple> position(const Vec& v) const {
    return point_at(
        m, [&](const ex& e) { return num(e); }, v);
  }
};

// The kind of force a load is, as a student names it: from the connection it comes from (the
// sketch's drawing of it), the weight from gravity.
std::string kind_of(const Model& m, const LoadOrigin& origin) {
  if (origin.kind == LoadOrigin::Kind::weight) return "weight";
  for (const auto& d : m.drawings) {
    if (d.label != origin.connection) continue;
    if (d.as == "line") return "tension";
    if (d.as == "spring" || d.as == "damper") return d.as;
    if (d.as == "arrow" || d.as == "couple") return "applied";
    return "support";
  }
  return origin.rule == "unknown_force" ? "applied" : "support";
}

// Where the problem's names stand: the diagram's bodies, each arrow's point; problems with them.
std::vector<Diagnostic> place_names(Diagram& d, FbdGrade& g) {
  std::vector<std::string> body_names, point_names;
  for (const auto& b : d.m.bodies) body_names.push_back(b.name);
  for (const auto& p : d.m.points) point_names.push_back(p.name);
  std::vector<Diagnostic> problems = fbd_name_problems(d.m, d.fbd);
  if (d.fbd.bodies.empty())
    problems.insert(
        problems.begin(),
        {d.fbd.where, "the free body diagram has no 'body' (expected body: NAME, or bodies: [A, B] for a system)"});
  for (const auto& name : d.fbd.bodies)
    if (auto it = std::find(body_names.begin(), body_names.end(), name); it != body_names.end())
      d.bodies.push_back(static_cast<int>(it - body_names.begin()));
  g.of = bodies_phrase(d.fbd.bodies);
  d.values = layout_numbers(d.m, {}, &d.defaulted);
  d.arrow_at.resize(d.fbd.forces.size());
  for (std::size_t i = 0; i < d.fbd.forces.size(); ++i) {
    const std::string& at = d.fbd.forces[i].at;
    if (at.empty()) continue;
    if (auto p = std::find(point_names.begin(), point_names.end(), at); p != point_names.end()) {
      d.arrow_at[i] = d.position(d.m.points[static_cast<std::size_t>(p - point_names.begin())].position);
    } else if (auto b = std::find(body_names.begin(), body_names.end(), at); b != body_names.end()) {
      const Body& body = d.m.bodies[static_cast<std::size_t>(b - body_names.begin())];
      if (body.has_cm) d.arrow_at[i] = d.position(body.cm);
    }
  }
  for (const auto& f : d.fbd.forces) d.arrow_kind.push_back(f.kind);
  return problems;
}

// The line of a force that is nothing at the sketch's position (a spring at its natural length):
// its components are a vanishing size times a direction, so their ratios keep the direction.
std::optional<Triple> zero_line(const Diagram& d, const Vec& c) {
  const auto ref = std::find_if(c.begin(), c.end(), [](const ex& x) { return !x.is_zero(); });
  if (ref == c.end()) return std::nullopt;
  Triple u{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    if (c[k].is_zero()) continue;
    const auto r = d.num(normal(c[k] / *ref));
    if (!r) return std::nullopt;
    u[k] = *r;
  }
  if (norm3(u) < 1e-12) return std::nullopt;
  return u;
}

// Where a load acts: its point, or (a load on a 1-D body, which says none) the body itself.
void place_at(const Diagram& d, const Load& l, Entry& e) {
  e.at_name = l.at_name;
  if (l.at) {
    e.at = d.position(*l.at);
    return;
  }
  if (l.body < 0) return;
  const Body& b = d.m.bodies[static_cast<std::size_t>(l.body)];
  if (!b.has_cm) return;
  e.at = d.position(b.cm);
  e.at_name = b.name;
}

// Whether where the force acts sets its moment about its body's center of mass (2-D and 3-D):
// its line, or one of its possible lines, passes off the center.
bool point_matters(const Diagram& d, const Load& l, const Entry& e) {
  if (d.m.dims() < 2 || !e.at || l.body < 0) return false;
  const Body& b = d.m.bodies[static_cast<std::size_t>(l.body)];
  const auto cm = b.has_cm ? d.position(b.cm) : std::nullopt;
  if (!cm) return false;
  const Triple r = minus3(*e.at, *cm);
  const double far = 1e-9 * std::max(1.0, norm3(*cm));
  if (norm3(r) <= far) return false;
  if (e.free || e.lines.empty()) return true;
  return std::any_of(e.lines.begin(), e.lines.end(),
                     [&](const Triple& line) { return norm3(cross3(r, line)) > far * norm3(line); });
}

// One part of a load as an entry (and its force in `g`); `undecided_by` names a force whose
// direction cannot be had in numbers. False when the part is left out.
bool part_entry(Diagram& d, const Load& l, const ForcePart& p, Entry& e, FbdGrade::Force& f,
                std::string& undecided_by) {
  ex all = p.key;
  for (int k = 0; k < d.m.dims(); ++k) all += p.coefficients[k];
  const auto uses_defaulted = [&](const ex& x) {
    return std::any_of(d.defaulted.begin(), d.defaulted.end(), [&](const ex& s) { return x.has(s); });
  };
  if (uses_defaulted(all) && undecided_by.empty()) undecided_by = force_phrase(l.origin);
  if (!p.unknown.is_zero()) {
    const auto key = d.num(p.key);
    e.lines.push_back(p.numbers);
    if (key && *key < 0)
      for (auto& x : e.lines.back()) x = -x;
    e.zero = key && *key == 0;  // mu N with mu = 0: no friction in the sketch
    e.fixed = key && *key != 0 && d.positive.count(p.unknown);
    e.names = {to_text(p.unknown)};
    f.label = p.key.is_equal(1) ? to_text(p.unknown) : to_text(p.key) + "*" + to_text(p.unknown);
    return true;
  }
  const auto n = d.position(p.coefficients);
  if (!n) {
    if (undecided_by.empty()) undecided_by = force_phrase(l.origin);
    return false;
  }
  e.zero = norm3(*n) < 1e-12;
  if (!e.zero)
    e.lines.push_back(*n);
  else if (const auto line = zero_line(d, p.coefficients))
    e.lines.push_back(*line);  // either sense
  // Known at the sketch's position (a spring's stretch there, a given force at t = 0), so is
  // its sense: pulling or pushing as its value says.
  e.fixed = !e.zero;
  // Its label where it lies along one axis: its size, as a figure writes it (m_B g).
  int along = -1, count = 0;
  for (int k = 0; k < d.m.dims(); ++k)
    if (!p.coefficients[k].is_zero()) {
      along = k;
      ++count;
    }
  if (count == 1) f.label = to_text(!e.zero && (*n)[along] < 0 ? -p.coefficients[along] : p.coefficients[along]);
  return true;
}

// A force with two or more unknowns of either sign along independent lines (a pin's O_x, O_y):
// its direction is not known, and one arrow, or one per line, stands for it. Else a load drawn
// as several arrows (N and mu N): each says which part it is.
void merge_parts(std::vector<Entry>& of_load, std::vector<FbdGrade::Force>& forces) {
  std::size_t unknown_parts = 0;
  bool any_fixed = false;
  for (const auto& e : of_load) {
    unknown_parts += e.names.empty() ? 0 : 1;
    any_fixed = any_fixed || e.fixed;
  }
  if (unknown_parts >= 2 && unknown_parts == of_load.size() && !any_fixed) {
    Entry merged = of_load.front();
    merged.free = true;
    std::vector<std::string> labels;
    for (std::size_t k = 0; k < of_load.size(); ++k) {
      if (k) {
        merged.lines.push_back(of_load[k].lines.front());
        merged.names.push_back(of_load[k].names.front());
      }
      labels.push_back(forces[forces.size() - of_load.size() + k].label);
    }
    forces.resize(forces.size() - of_load.size() + 1);
    forces.back().label = join(labels);
    of_load = {merged};
  } else if (of_load.size() > 1) {
    for (std::size_t k = 0; k < of_load.size(); ++k) {
      auto& f = forces[forces.size() - of_load.size() + k];
      if (!f.label.empty()) f.phrase += " (its " + f.label + " part)";
    }
  }
}

// A 2-D load's couple as an entry: its sense where the model knows it.
void couple_entry(Diagram& d, FbdGrade& g, std::size_t li, std::string& undecided_by) {
  const Load& l = d.m.loads[li];
  Entry e;
  e.load = li;
  e.at_name = l.at_name;
  e.couple = true;
  e.key = force_key(l.origin);
  e.kind = kind_of(d.m, l.origin);
  FbdGrade::Force f{l.source(), couple_phrase(l.origin), to_text(l.couple[2]), "missing", {}, 1, 0};
  if (const auto v = d.num(l.couple[2])) {  // its value at the sketch's position
    const bool has_unknown =
        std::any_of(d.unknowns.begin(), d.unknowns.end(), [&](const ex& u) { return l.couple[2].has(u); });
    if (!has_unknown) {
      e.couple_sense = *v > 0 ? 1 : *v < 0 ? -1 : 0;
      e.zero = *v == 0;  // nothing in the sketch (a couple of 0)
    }
  }
  if (std::any_of(d.defaulted.begin(), d.defaulted.end(), [&](const ex& s) { return l.couple[2].has(s); }) &&
      undecided_by.empty())
    undecided_by = f.phrase;
  d.entries.push_back(e);
  g.forces.push_back(f);
}

// The connection a constraint comes from, by its label without its axis ("same motion carried
// (x)"), when no load comes from it: two bodies said to move together (same_motion) ask for no
// force between them, yet one carries the other. Empty for every other constraint.
std::string forceless_connection(const Model& m, const Constraint& c) {
  std::string key = c.label;
  if (const auto open = key.rfind(" ("); open != std::string::npos && key.back() == ')') key.erase(open);
  const bool loaded = std::any_of(m.loads.begin(), m.loads.end(), [&](const Load& l) {
    return l.origin.kind != LoadOrigin::Kind::weight && l.origin.connection == key;
  });
  return loaded ? "" : key;
}

// The other body a constraint keeps body `b`'s center at a constant offset from, along an axis
// (x_K - x_T = const); -1 for none.
int carrier_of(const Model& m, const Constraint& c, std::size_t b) {
  for (std::size_t o = 0; o < m.bodies.size(); ++o)
    for (int k = 0; o != b && k < m.dims(); ++k) {
      const ex offset = (m.bodies[b].cm[k] - m.bodies[o].cm[k]).expand();
      if (!offset.is_zero() && ((offset - c.quantity).expand().is_zero() || (offset + c.quantity).expand().is_zero()))
        return static_cast<int>(o);
    }
  return -1;
}

// The force of a body that carries one of the diagram's (or is carried by it) where the model
// has none: at the body's center, along any direction (in 1-D, either sense), an unknown the
// balances of the system do not need.
void carried_entries(Diagram& d, FbdGrade& g) {
  std::set<std::pair<std::string, int>> made;
  for (const Constraint& c : d.m.constraints) {
    const std::string key = forceless_connection(d.m, c);
    for (const int b : d.bodies) {
      const Body& body = d.m.bodies[static_cast<std::size_t>(b)];
      const int o = key.empty() || !body.has_cm ? -1 : carrier_of(d.m, c, static_cast<std::size_t>(b));
      if (o < 0 || std::find(d.bodies.begin(), d.bodies.end(), o) != d.bodies.end() || !made.insert({key, b}).second)
        continue;
      Entry e;
      e.at = d.position(body.cm);
      e.at_name = body.name;
      e.kind = "support";
      e.key = key;
      for (int k = 0; k < d.m.dims(); ++k)
        e.lines.push_back(Triple{k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, k == 2 ? 1.0 : 0.0});
      e.free = d.m.dims() > 1;
      d.entries.push_back(e);
      const std::string phrase =
          "the force of " + d.m.bodies[static_cast<std::size_t>(o)].name + " on " + body.name + " (" + key + ")";
      g.forces.push_back({key, phrase, "", "missing", {}, 1, 0});
    }
  }
}

// Tackle's own diagram: one entry per force the student should draw; what makes it undecided.
std::string own_diagram(Diagram& d, FbdGrade& g) {
  d.unknowns = {d.m.candidates.begin(), d.m.candidates.end()};
  for (const auto& c : d.m.conditions) {  // unknowns a condition keeps from being negative (T >= 0, N >= 0)
    if (c.op == ">=" || c.op == ">")
      d.positive.insert((c.lhs - c.rhs).expand());
    else if (c.op == "<=" || c.op == "<")
      d.positive.insert((c.rhs - c.lhs).expand());
  }
  d.internal = internal_forces(d.m, d.bodies);
  std::string undecided_by;
  for (std::size_t li = 0; li < d.m.loads.size(); ++li) {
    const Load& l = d.m.loads[li];
    if (std::find(d.bodies.begin(), d.bodies.end(), l.body) == d.bodies.end() || d.internal.count(force_key(l.origin)))
      continue;
    std::vector<Entry> of_load;
    for (const ForcePart& p : split_force(d.m, l.force, d.unknowns, [&](const ex& e) { return d.num(e); })) {
      Entry e;
      e.load = li;
      place_at(d, l, e);
      e.key = force_key(l.origin);
      e.kind = kind_of(d.m, l.origin);
      FbdGrade::Force f{l.source(), force_phrase(l.origin), "", "missing", {}, 1, 0};
      if (!part_entry(d, l, p, e, f, undecided_by)) continue;
      of_load.push_back(e);
      g.forces.push_back(f);
    }
    merge_parts(of_load, g.forces);
    for (auto& e : of_load) e.point_matters = point_matters(d, l, e);
    d.entries.insert(d.entries.end(), of_load.begin(), of_load.end());
    if (d.m.dims() == 3 && !is_zero_vec(l.couple) && undecided_by.empty())
      undecided_by = "the couple of the " + l.source();
    if (d.m.dims() == 2 && !l.couple[2].is_zero()) couple_entry(d, g, li, undecided_by);
  }
  carried_entries(d, g);
  return undecided_by;
}

// Each force's weight: the rubric's for its source, its source's key, or one of its unknowns.
void weigh(const Diagram& d, FbdGrade& g) {
  const auto& w = d.rubric.weights;
  for (std::size_t k = 0; k < d.entries.size(); ++k) {
    auto& f = g.forces[k];
    if (auto it = w.find(f.source); it != w.end())
      f.weight = it->second;
    else if (auto it2 = w.find(d.entries[k].key); it2 != w.end())
      f.weight = it2->second;
    else
      for (const auto& n : d.entries[k].names)
        if (auto it3 = w.find(n); it3 != w.end()) {
          f.weight = it3->second;
          break;
        }
    if (d.entries[k].zero) f.status = "zero";
  }
}

// How an arrow fits an entry: none at all; else the better the higher.
enum Fit { none = 0, off_line = 1, wrong_point = 2, wrong_direction = 3, good = 4 };

bool same_point(const Diagram& d, std::size_t i, const Entry& e) {
  if (d.fbd.forces[i].at.empty() || (!e.at && e.at_name.empty())) return true;
  if (d.arrow_at[i] && e.at) return norm3(minus3(*d.arrow_at[i], *e.at)) <= 1e-9 * std::max(1.0, norm3(*e.at));
  return d.fbd.forces[i].at == e.at_name;
}

// Whether `v` lies in the span of `lines`, within the tolerance: the part of it outside the
// span (Gram-Schmidt) is small against it.
bool in_span(const Diagram& d, const Triple& v, const std::vector<Triple>& lines) {
  std::vector<Triple> basis;
  for (const auto& l : lines) {
    Triple u = l;
    for (const auto& b : basis) {
      const double c = dot3(u, b);
      for (int k = 0; k < 3; ++k) u[k] -= c * b[k];
    }
    if (const double n = norm3(u); n > 1e-9) basis.push_back({u[0] / n, u[1] / n, u[2] / n});
  }
  Triple r = v;
  for (const auto& b : basis) {
    const double c = dot3(r, b);
    for (int k = 0; k < 3; ++k) r[k] -= c * b[k];
  }
  return norm3(r) <= norm3(v) * d.sin_tol + 1e-12;
}

Fit direction_fit(const Diagram& d, std::size_t i, const Entry& e) {
  const auto& dir = d.fbd.forces[i].direction;
  if (e.couple) return none;
  if (e.free || e.lines.empty()) return !dir || e.lines.empty() || in_span(d, *dir, e.lines) ? good : none;
  if (!dir) return e.zero ? good : wrong_direction;  // its line is known
  const double c = dot3(*dir, e.lines.front()) / (norm3(*dir) * norm3(e.lines.front()));
  if (c >= d.cos_tol) return good;
  if (-c >= d.cos_tol) return e.fixed ? wrong_direction : good;
  return none;
}

Fit fit(const Diagram& d, std::size_t i, const Entry& e) {
  if (!d.arrow_kind[i].empty() && d.arrow_kind[i] != e.kind) return none;
  const Fit dir = direction_fit(d, i, e);
  const bool said = !d.fbd.forces[i].at.empty();
  // At the force's own point (said), along no line it has: the force, drawn off its line.
  if (dir == none) return !e.couple && said && same_point(d, i, e) ? off_line : none;
  if (!same_point(d, i, e)) return dir == good ? wrong_point : none;
  // Not said where, for a force whose point sets its moment: as drawn at the wrong point.
  if (!said && e.point_matters && dir == good) return wrong_point;
  return dir;
}

// Tackle's name for a force: its (first) unknown's, else its label.
std::string label_of(const Diagram& d, const FbdGrade& g, std::size_t k) {
  return d.entries[k].names.empty() ? g.forces[k].label : d.entries[k].names.front();
}

// What a fit is worth to the matching: a good fit over a force drawn the wrong way over one at
// the wrong point; a force of known line over a pin's, which takes any line; a force that is
// nothing in the sketch least (any arrow might be taken for it); the student's name for
// tackle's symbol only to break ties (a student may call a tension F).
double fit_value(const Diagram& d, const FbdGrade& g, std::size_t i, std::size_t k) {
  const Fit f = fit(d, i, d.entries[k]);
  if (f == none) return 0;
  double base = f == good ? 10 : f == wrong_direction ? 6 : f == wrong_point ? 5 : 4;
  if (d.entries[k].zero)
    base /= 4;
  else if (d.entries[k].free && f == good)
    base -= 0.5;
  const std::string& name = d.fbd.forces[i].name;
  return base + (!name.empty() && name == label_of(d, g, k) ? 1 : 0);
}

struct Matching {
  std::vector<int> entry_of, arrow_of;
  std::vector<Fit> fitted;
  std::vector<std::vector<std::size_t>> more;  // further arrows for a free force, one per line
  double total = 0;
};

// The best assignment of arrows to forces, the arrows `held` (where given) and the force `taken`
// (where given) left out of it: a force's components chosen already.
Matching match_once(const Diagram& d, const FbdGrade& g, const std::vector<std::size_t>& held = {},
                    std::optional<std::size_t> taken = {}) {
  const std::size_t na = d.fbd.forces.size(), ne = d.entries.size();
  std::vector<std::vector<double>> value(na, std::vector<double>(ne, 0));
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t k = 0; k < ne; ++k)
      if (k != taken && std::find(held.begin(), held.end(), i) == held.end()) value[i][k] = fit_value(d, g, i, k);
  Matching mt{best_assignment(value, ne), std::vector<int>(ne, -1), std::vector<Fit>(ne, none),
              std::vector<std::vector<std::size_t>>(ne), 0};
  for (std::size_t i = 0; i < na; ++i) {
    if (mt.entry_of[i] < 0) continue;
    const auto k = static_cast<std::size_t>(mt.entry_of[i]);
    mt.arrow_of[k] = static_cast<int>(i);
    mt.fitted[k] = fit(d, i, d.entries[k]);
    mt.total += value[i][k];
  }
  return mt;
}

// Arrows drawn alike (the same name, point and direction, no kind said) stand for forces of one
// kind: two weights drawn at a pin are a weight twice, never a weight and the pin's force.
// Whether two arrows are drawn at one point (as said) and the same way.
bool drawn_alike(const Diagram& d, std::size_t i, std::size_t j) {
  const StudentForce &a = d.fbd.forces[i], &b = d.fbd.forces[j];
  if (a.at != b.at) return false;
  if (!a.direction || !b.direction) return !a.direction && !b.direction;
  return dot3(*a.direction, *b.direction) >= d.cos_tol * norm3(*a.direction) * norm3(*b.direction);
}

std::vector<std::vector<std::size_t>> alike_groups(const Diagram& d) {
  std::vector<std::vector<std::size_t>> groups;
  auto alike = [&](std::size_t i, std::size_t j) {
    const StudentForce &a = d.fbd.forces[i], &b = d.fbd.forces[j];
    return !a.name.empty() && a.name == b.name && a.kind.empty() && b.kind.empty() && drawn_alike(d, i, j);
  };
  std::vector<char> placed(d.fbd.forces.size(), 0);
  for (std::size_t i = 0; i < d.fbd.forces.size(); ++i) {
    if (placed[i]) continue;
    std::vector<std::size_t> group{i};
    for (std::size_t j = i + 1; j < d.fbd.forces.size(); ++j)
      if (!placed[j] && alike(i, j)) {
        group.push_back(j);
        placed[j] = 1;
      }
    if (group.size() > 1) groups.push_back(group);
  }
  return groups;
}

// The matching that fits best in all, each group of arrows drawn alike held to one kind (the
// kind that fits best, tried in turn where the first matching gave the group several).
Matching match(Diagram& d, const FbdGrade& g) {
  Matching best = match_once(d, g);
  for (const auto& group : alike_groups(d)) {
    std::vector<std::string> kinds;
    for (const std::size_t i : group)
      if (best.entry_of[i] >= 0) {
        const std::string& k = d.entries[static_cast<std::size_t>(best.entry_of[i])].kind;
        if (std::find(kinds.begin(), kinds.end(), k) == kinds.end()) kinds.push_back(k);
      }
    if (kinds.size() < 2) continue;
    std::optional<Matching> chosen;
    std::string chosen_kind;
    for (const auto& kind : kinds) {
      for (const std::size_t i : group) d.arrow_kind[i] = kind;
      Matching mt = match_once(d, g);
      if (!chosen || mt.total > chosen->total) {
        chosen = std::move(mt);
        chosen_kind = kind;
      }
    }
    for (const std::size_t i : group) d.arrow_kind[i] = chosen_kind;
    best = std::move(*chosen);
  }
  return best;
}

// A force of unknown direction may be drawn as one arrow per line of its span, the arrows at one
// point (said alike: a second weight drawn at the body's center is no component of the pin's
// force drawn at the pin, even where the two points are one).
void more_lines(const Diagram& d, const FbdGrade& g, Matching& mt) {
  const std::size_t na = d.fbd.forces.size(), ne = d.entries.size();
  for (std::size_t i = 0; i < na; ++i) {
    if (mt.entry_of[i] >= 0 || !d.fbd.forces[i].direction) continue;
    for (std::size_t k = 0; k < ne; ++k) {
      const Entry& en = d.entries[k];
      if (!en.free || mt.fitted[k] != good || 1 + mt.more[k].size() >= en.lines.size() || fit(d, i, en) != good)
        continue;
      const StudentForce& drawn_first = d.fbd.forces[static_cast<std::size_t>(mt.arrow_of[k])];
      const auto& first = drawn_first.direction;
      if (!first || drawn_first.at != d.fbd.forces[i].at)
        continue;  // drawn as one force of unknown direction already, or elsewhere
      std::vector<Triple> drawn{*first};
      for (auto j : mt.more[k]) drawn.push_back(*d.fbd.forces[j].direction);
      if (in_span(d, *d.fbd.forces[i].direction, drawn)) continue;  // not a new line
      mt.more[k].push_back(i);
      mt.entry_of[i] = static_cast<int>(k);
      mt.total += fit_value(d, g, i, k);
      break;
    }
  }
}

// A force of unknown direction (its entry) and a group of arrows that may stand for it
// together, as its components.
using Group = std::pair<std::size_t, std::vector<std::size_t>>;

// The groups for force `k`: two or more arrows (one per line of its span at most), each fitting
// it with a direction, drawn at one point (as said), each off the span of the ones before it;
// added to `out` while it holds fewer than `cap` (a drawing of many arrows at one pin).
void component_groups(const Diagram& d, std::size_t k, std::size_t cap, std::vector<Group>& out) {
  const Entry& en = d.entries[k];
  std::vector<std::size_t> fitting;
  for (std::size_t i = 0; i < d.fbd.forces.size(); ++i)
    if (d.fbd.forces[i].direction && fit(d, i, en) == good) fitting.push_back(i);
  std::vector<std::size_t> group;
  std::vector<Triple> lines;
  const std::function<void(std::size_t)> grow = [&](std::size_t from) {
    if (out.size() >= cap) return;
    if (group.size() >= 2) out.push_back({k, group});
    for (std::size_t j = from; j < fitting.size() && group.size() < en.lines.size(); ++j) {
      const StudentForce& a = d.fbd.forces[fitting[j]];
      if ((!group.empty() && a.at != d.fbd.forces[group.front()].at) || in_span(d, *a.direction, lines)) continue;
      group.push_back(fitting[j]);
      lines.push_back(*a.direction);
      grow(j + 1);
      group.pop_back();
      lines.pop_back();
    }
  };
  grow(0);
}

// The matching that fits best in all, each force of unknown direction drawn as one arrow (with
// the further lines drawn at its point after it) or as a group of components chosen first: of
// two arrows along x at a weld, one may be its component and the other a given force there.
Matching best_matching(Diagram& d, const FbdGrade& g) {
  Matching best = match(d, g);
  more_lines(d, g, best);
  std::vector<Group> groups;
  for (std::size_t k = 0; k < d.entries.size(); ++k)
    if (d.entries[k].free) component_groups(d, k, 256, groups);
  for (const auto& [k, group] : groups) {
    Matching mt = match_once(d, g, group, k);
    mt.arrow_of[k] = static_cast<int>(group.front());
    mt.fitted[k] = good;
    mt.more[k].assign(group.begin() + 1, group.end());
    for (const std::size_t i : group) {
      mt.entry_of[i] = static_cast<int>(k);
      mt.total += fit_value(d, g, i, k);
    }
    more_lines(d, g, mt);
    if (mt.total > best.total + 1e-9) best = std::move(mt);
  }
  return best;
}

std::string said(const Diagram& d, std::size_t i) {
  return d.fbd.forces[i].name.empty() ? std::string("an arrow") : "your " + d.fbd.forces[i].name;
}

// The grade of each of tackle's forces (couples apart); what is drawn wrong.
void grade_forces(const Diagram& d, const Matching& mt, FbdGrade& g, std::vector<Finding>& wrong) {
  for (std::size_t k = 0; k < d.entries.size(); ++k) {
    auto& f = g.forces[k];
    if (mt.arrow_of[k] < 0) {
      if (d.entries[k].zero) f.score = f.weight;  // nothing there: not needed, its share
      continue;
    }
    const auto i = static_cast<std::size_t>(mt.arrow_of[k]);
    f.drawn_as.push_back(d.fbd.forces[i].name);
    for (auto j : mt.more[k]) f.drawn_as.push_back(d.fbd.forces[j].name);
    const std::string who = said(d, i) + " stands for " + f.phrase;
    switch (mt.fitted[k]) {
      case good:
        f.status = "drawn";
        f.score = f.weight;
        break;
      case wrong_point:
        f.status = "wrong_point";
        f.score = f.weight * d.rubric.wrong_point;
        wrong.push_back({"wrong_point", d.fbd.forces[i].at.empty()
                                            ? who + ", but is drawn at no point (where it acts sets its moment)"
                                            : who + ", which does not act at " + d.fbd.forces[i].at});
        break;
      default:
        f.status = mt.fitted[k] == off_line ? "off_line" : "wrong_direction";
        f.score = f.weight * d.rubric.wrong_direction;
        wrong.push_back({"force_direction", !d.fbd.forces[i].direction
                                                ? who + ", whose line is known: draw it along that line"
                                            : mt.fitted[k] == off_line ? who + ", but is not along its line"
                                                                       : who + ", which points the other way"});
        break;
    }
  }
}

// Couples: by their sense; each couple of the student stands for one of tackle's.
void grade_couples(const Diagram& d, const Matching& mt, FbdGrade& g, std::vector<Finding>& wrong,
                   std::vector<Finding>& extra) {
  for (const StudentCouple& sc : d.fbd.couples) {
    std::optional<std::size_t> best;
    bool right = false;
    for (std::size_t k = 0; k < d.entries.size(); ++k) {
      const bool taken = g.forces[k].status != "missing" && g.forces[k].status != "zero";
      if (!d.entries[k].couple || mt.arrow_of[k] >= 0 || taken) continue;
      const bool ok = d.entries[k].couple_sense == 0 || sc.sense == d.entries[k].couple_sense;
      if (!best || (ok && !right)) {
        best = k;
        right = ok;
      }
    }
    if (!best) {
      extra.push_back({"extra_force", (sc.name.empty() ? std::string("a couple") : "your couple " + sc.name) +
                                          ": no couple acts on " + g.of});
      g.extras.push_back({sc.name, "extra_force", extra.back().message});
      continue;
    }
    auto& f = g.forces[*best];
    f.drawn_as.push_back(sc.name);
    f.status = right ? "drawn" : "wrong_direction";
    f.score = f.weight * (right ? 1 : d.rubric.wrong_direction);
    if (!right)
      wrong.push_back(
          {"force_direction", "your couple " + sc.name + " stands for " + f.phrase + ", which turns the other way"});
  }
}

// Why an arrow left over is there, where it can be said: a force drawn twice (its name, or its
// kind, is that of the arrow standing for it, or it is drawn like that arrow), a force on another
// body, a force internal to the system; else it is one of no force here.
Finding extra_finding(const Diagram& d, const Matching& mt, const FbdGrade& g, std::size_t i) {
  const StudentForce& a = d.fbd.forces[i];
  for (std::size_t k = 0; k < d.entries.size(); ++k) {
    if (mt.arrow_of[k] < 0 || d.entries[k].zero || fit(d, i, d.entries[k]) != good) continue;
    const auto j = static_cast<std::size_t>(mt.arrow_of[k]);
    const bool same = a.name == d.fbd.forces[j].name || a.name == label_of(d, g, k) || !d.arrow_kind[i].empty() ||
                      drawn_alike(d, i, j);
    if (same) return {"extra_force", said(d, i) + " counts " + g.forces[k].phrase + " once too often"};
  }
  for (std::size_t li = 0; li < d.m.loads.size(); ++li) {
    const Load& l = d.m.loads[li];
    const bool ours = std::find(d.bodies.begin(), d.bodies.end(), l.body) != d.bodies.end();
    if (ours && !d.internal.count(force_key(l.origin))) continue;
    Entry e;
    e.load = li;
    place_at(d, l, e);
    for (const ForcePart& p : split_force(d.m, l.force, d.unknowns, [&](const ex& x) { return d.num(x); }))
      if (!p.unknown.is_zero())
        e.lines.push_back(p.numbers);
      else if (auto n = d.position(p.coefficients))
        e.lines.push_back(*n);
    if (e.lines.empty() || a.at.empty() || !same_point(d, i, e) || (a.direction && !in_span(d, *a.direction, e.lines)))
      continue;
    if (ours)
      return {"internal_force", said(d, i) + " is " + force_phrase(l.origin) + ", which is internal to " + g.of +
                                    " (its forces on the system's bodies cancel)"};
    return {"other_body", said(d, i) + " is " + force_phrase(l.origin) + ", which acts on " +
                              d.m.bodies[static_cast<std::size_t>(l.body)].name + ", not on " + g.of};
  }
  return {"extra_force",
          said(d, i) + " is not one of the forces on " + g.of + (a.at.empty() ? std::string("") : " at " + a.at)};
}

void conclude(const Diagram& d, FbdGrade& g, std::vector<Finding> missing, const std::vector<Finding>& wrong,
              const std::vector<Finding>& extra) {
  g.findings = std::move(missing);
  g.findings.insert(g.findings.end(), wrong.begin(), wrong.end());
  g.findings.insert(g.findings.end(), extra.begin(), extra.end());
  for (const auto& f : g.forces) {
    g.max_score += f.weight;
    g.score += f.score;
  }
  g.score = std::max(0.0, g.score - d.rubric.extra * static_cast<double>(g.extras.size()));
  if (g.findings.empty()) {
    g.verdict = Verdict::correct;
    g.summary = "every force on " + g.of + " is drawn, each along its line and at its point";
  } else {
    g.verdict = Verdict::incorrect;
    g.summary = g.findings.front().message;
  }
}

}  // namespace

FbdGrade check_fbd(const Model& m, const StudentFbd& fbd, const FbdRubric& rubric, std::vector<Diagnostic>& problems) {
  FbdGrade g;
  Diagram d(m, fbd, rubric);
  problems = place_names(d, g);
  if (!problems.empty()) {
    g.verdict = Verdict::invalid;
    g.summary = problems.front().message;
    g.findings.push_back({"unknown_name", g.summary});
    return g;
  }
  if (const std::string undecided_by = own_diagram(d, g); !undecided_by.empty()) {
    g.verdict = Verdict::undecided;
    g.summary = undecided_by.rfind("the couple of", 0) == 0
                    ? undecided_by + " is a couple in space, which a drawn diagram is not checked for"
                    : "the direction of " + undecided_by +
                          " depends on a parameter without a value, so a drawing cannot be compared with it";
    g.findings.push_back({"evaluation", g.summary});
    return g;
  }
  weigh(d, g);
  d.cos_tol = std::cos(rubric.tolerance * pi / 180);
  d.sin_tol = std::sin(rubric.tolerance * pi / 180);
  const Matching mt = best_matching(d, g);
  std::vector<Finding> missing, wrong, extra;
  grade_forces(d, mt, g, wrong);
  grade_couples(d, mt, g, wrong, extra);
  for (std::size_t i = 0; i < fbd.forces.size(); ++i) {
    if (mt.entry_of[i] >= 0) continue;
    extra.push_back(extra_finding(d, mt, g, i));
    g.extras.push_back({fbd.forces[i].name, extra.back().code, extra.back().message});
  }
  for (const auto& f : g.forces)
    if (f.status == "missing") missing.push_back({"missing_force", f.phrase + " is missing"});
  conclude(d, g, std::move(missing), wrong, extra);
  return g;
}

}  // namespace tackle

#include "check/fbd.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include <fmt/format.h>

#include "check/batch.hpp"
#include "check/equation.hpp"
#include "expr/print.hpp"
#include "model/forces.hpp"
#include "numeric/layout.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// At most this many arrows and couples in one diagram: a diagram is a drawing, not a batch.
constexpr std::size_t max_arrows = 60;
constexpr double pi = 3.14159265358979323846;

using Triple = std::array<double, 3>;

double dot3(const Triple& a, const Triple& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm3(const Triple& a) { return std::sqrt(dot3(a, a)); }

std::optional<double> number_of(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || std::fabs(v) > 1e6) return std::nullopt;
  return v;
}

// The names a message offers: at most a dozen of them.
std::string some(const std::vector<std::string>& names) {
  std::vector<std::string> first(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(names.size(), 12)));
  return join(first) + (names.size() > 12 ? ", ..." : "");
}

std::string bodies_phrase(const std::vector<std::string>& names) {
  if (names.empty()) return "no body";
  if (names.size() == 1) return names.front();
  std::vector<std::string> head(names.begin(), names.end() - 1);
  return "the system of " + join(head) + " and " + names.back();
}

StudentFbd read_fbd_data(const yaml::Node& node, int dims, const std::string& file, Diagnostics& diags);

void in_file_order(std::vector<Diagnostic>& problems) {
  std::stable_sort(problems.begin(), problems.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::pair(a.where.line, a.where.column) < std::pair(b.where.line, b.where.column);
  });
}

}  // namespace

StudentFbd read_fbd(const yaml::Node& node, const Model& m, const std::string& file, Diagnostics& out) {
  const int dims = m.dims();
  // The data's problems and the names' together, in the file's order.
  Diagnostics diags;
  StudentFbd fbd = read_fbd_data(node, dims, file, diags);
  std::vector<Diagnostic> all = diags.items();
  for (auto& d : fbd_name_problems(m, fbd)) all.push_back(std::move(d));
  in_file_order(all);
  for (auto& d : all) out.error(std::move(d.where), std::move(d.message));
  return fbd;
}

namespace {

StudentFbd read_fbd_data(const yaml::Node& node, int dims, const std::string& file, Diagnostics& diags) {
  StudentFbd fbd;
  fbd.where = yaml::where(node, file);
  if (!yaml::check_map(node, {"body", "bodies", "forces", "couples"}, "the free body diagram", file, diags)) return fbd;
  if (node["body"] && node["bodies"]) {
    diags.error(yaml::where(node["bodies"], file), "a free body diagram has 'body' or 'bodies', not both");
  } else if (node["body"]) {
    if (auto t = yaml::scalar(node["body"], "'body'", file, diags)) {
      fbd.bodies.push_back(t->text);
      fbd.body_where.push_back(yaml::where(node["body"], file));
    }
  } else if (node["bodies"]) {
    if (yaml::is_list(node["bodies"], "'bodies'", file, diags))
      for (const yaml::Node b : node["bodies"])
        if (auto t = yaml::scalar(b, "a body", file, diags)) {
          if (std::find(fbd.bodies.begin(), fbd.bodies.end(), t->text) != fbd.bodies.end())
            diags.error(yaml::where(b, file), "body '" + t->text + "' is named twice");
          fbd.bodies.push_back(t->text);
          fbd.body_where.push_back(yaml::where(b, file));
        }
    if (fbd.bodies.empty() && node["bodies"].is_sequence()) diags.error(yaml::where(node["bodies"], file), "'bodies' is empty (expected the system's bodies)");
  } else {
    diags.error(fbd.where, "the free body diagram has no 'body' (expected body: NAME, or bodies: [A, B] for a system)");
  }
  std::size_t count = 0;
  if (const yaml::Node forces = node["forces"]; forces && yaml::is_list(forces, "'forces'", file, diags)) {
    count += forces.size();
    for (const yaml::Node item : forces) {
      if (!yaml::check_map(item, {"name", "at", "direction", "angle"}, "a force", file, diags)) continue;
      StudentForce f;
      f.where = yaml::where(item, file);
      if (item["name"]) {
        if (auto t = yaml::scalar(item["name"], "'name'", file, diags)) f.name = t->text;
      }
      if (item["at"]) {
        if (auto t = yaml::scalar(item["at"], "'at'", file, diags)) {
          f.at = t->text;
          f.at_where = yaml::where(item["at"], file);
        }
      }
      const yaml::Node dir = item["direction"], angle = item["angle"];
      if (dir && angle) {
        diags.error(yaml::where(angle, file), "a force has 'direction' or 'angle', not both");
      } else if (angle) {
        if (dims != 2) {
          diags.error(yaml::where(angle, file), "'angle' is for a plane problem (expected 'direction' with " + std::to_string(dims) + " number" + (dims == 1 ? "" : "s") + ")");
        } else if (auto t = yaml::scalar(angle, "'angle'", file, diags)) {
          if (auto v = number_of(t->text)) f.direction = Triple{std::cos(*v * pi / 180), std::sin(*v * pi / 180), 0};
          else diags.error(yaml::where(angle, file), "'angle' is not a number (expected degrees from the " + std::string("first axis, counterclockwise)"));
        }
      } else if (dir && dir.is_scalar() && dir.text() == "any") {
        // no direction: the student does not know it (a pin's force)
      } else if (dir && dir.is_sequence()) {
        if (dir.size() != static_cast<std::size_t>(dims)) {
          diags.error(yaml::where(dir, file), "'direction' has " + std::to_string(dir.size()) + " number" + (dir.size() == 1 ? "" : "s") +
                                                  " (expected " + std::to_string(dims) + ", one per axis)");
        } else {
          Triple d{0, 0, 0};
          bool ok = true;
          for (std::size_t k = 0; k < dir.size(); ++k) {
            const auto t = yaml::scalar(dir[k], "a direction's number", file, diags);
            if (!t) {
              ok = false;
              continue;
            }
            if (auto v = number_of(t->text)) d[k] = *v;
            else {
              diags.error(yaml::where(dir[k], file), "'" + t->text + "' is not a number (expected a number from -10^6 to 10^6)");
              ok = false;
            }
          }
          if (ok && norm3(d) < 1e-12) diags.error(yaml::where(dir, file), "'direction' is zero (expected a direction along the force)");
          else if (ok) f.direction = d;
        }
      } else {
        diags.error(dir ? yaml::where(dir, file) : f.where,
                    "a force needs its 'direction' (expected a list of " + std::to_string(dims) + " number" + (dims == 1 ? "" : "s") +
                        (dims == 2 ? ", 'angle' in degrees," : ",") + " or 'any')");
      }
      fbd.forces.push_back(std::move(f));
    }
  }
  if (const yaml::Node couples = node["couples"]; couples && yaml::is_list(couples, "'couples'", file, diags)) {
    count += couples.size();
    if (dims != 2 && couples.size() > 0) diags.error(yaml::where(couples, file), "'couples' are for a plane problem (this one has " + std::to_string(dims) + (dims == 1 ? " axis)" : " axes)"));
    for (const yaml::Node item : couples) {
      if (!yaml::check_map(item, {"name", "sense"}, "a couple", file, diags)) continue;
      StudentCouple c;
      c.where = yaml::where(item, file);
      if (item["name"]) {
        if (auto t = yaml::scalar(item["name"], "'name'", file, diags)) c.name = t->text;
      }
      if (!item["sense"]) {
        diags.error(c.where, "a couple needs its 'sense' (expected counterclockwise, clockwise or any)");
      } else if (auto t = yaml::scalar(item["sense"], "'sense'", file, diags)) {
        if (t->text == "counterclockwise") c.sense = 1;
        else if (t->text == "clockwise") c.sense = -1;
        else if (t->text != "any") diags.error(yaml::where(item["sense"], file), "'" + t->text + "' is not a sense (expected counterclockwise, clockwise or any)");
      }
      fbd.couples.push_back(std::move(c));
    }
  }
  if (count > max_arrows)
    diags.error(fbd.where, "the free body diagram has " + std::to_string(count) + " forces and couples (at most " + std::to_string(max_arrows) + ")");
  return fbd;
}

}  // namespace

std::vector<Diagnostic> fbd_name_problems(const Model& m, const StudentFbd& fbd) {
  std::vector<Diagnostic> problems;
  std::vector<std::string> body_names, names;
  for (const auto& b : m.bodies) body_names.push_back(b.name);
  for (const auto& p : m.points) names.push_back(p.name);
  for (const auto& b : m.bodies)
    if (b.has_cm && std::find(names.begin(), names.end(), b.name) == names.end()) names.push_back(b.name);
  for (std::size_t i = 0; i < fbd.bodies.size(); ++i)
    if (std::find(body_names.begin(), body_names.end(), fbd.bodies[i]) == body_names.end())
      problems.push_back({fbd.body_where[i], "'" + fbd.bodies[i] + "' is not a body of the problem (expected one of: " + some(body_names) + ")"});
  for (const auto& f : fbd.forces)
    if (!f.at.empty() && std::find(names.begin(), names.end(), f.at) == names.end())
      problems.push_back({f.at_where, "'" + f.at + "' is not a point or body of the problem (expected one of: " + some(names) + ")"});
  // In the file's order.
  in_file_order(problems);
  return problems;
}

StudentFbd read_fbd_file(const std::string& text, const std::string& file, const Model& m) {
  Diagnostics diags;
  const yaml::Document doc = yaml::load(text, file, diags);
  diags.throw_if_any();
  StudentFbd fbd = read_fbd(doc.root(), m, file, diags);
  diags.throw_if_any();
  return fbd;
}

FbdRubric read_fbd_rubric(const yaml::Node& node, const std::string& file, Diagnostics& diags) {
  FbdRubric r;
  if (!yaml::check_map(node, {"wrong_direction", "wrong_point", "extra", "tolerance", "weights"}, "'fbd'", file, diags)) return r;
  auto read = [&](const yaml::Node& n, const std::string& what, double high, double& into) {
    const auto t = yaml::scalar(n, what, file, diags);
    if (!t) return;
    const auto v = number_of(t->text);
    if (!v || *v < 0 || *v > high) diags.error(yaml::where(n, file), what + " is not a number from 0 to " + fmt::format("{:g}", high));
    else into = *v;
  };
  for (const auto& [key, field, high] : {std::tuple{"wrong_direction", &r.wrong_direction, 1.0}, std::tuple{"wrong_point", &r.wrong_point, 1.0},
                                         std::tuple{"extra", &r.extra, 1000.0}, std::tuple{"tolerance", &r.tolerance, 45.0}})
    if (node[key]) read(node[key], std::string("'") + key + "'", high, *field);
  if (const yaml::Node w = node["weights"]) {
    if (!w.is_map()) diags.error(yaml::where(w, file), "'weights' is " + yaml::kind_name(w) + " (expected a mapping from a force's source or unknown to its points)");
    else
      for (const auto& e : w) {
        double v = 1;
        read(e.second, "the weight of '" + e.first.text() + "'", 1000.0, v);
        r.weights[e.first.text()] = v;
        r.weight_where[e.first.text()] = yaml::where(e.first, file);
      }
  }
  return r;
}

std::vector<Diagnostic> fbd_rubric_problems(const Model& m, const FbdRubric& r) {
  // What a weight may name: each force's unknowns, its source, or its source's key (a strand
  // without its end: "string s: strand pB-C"), which the message offers.
  std::vector<std::string> names;
  auto add = [&](const std::string& n) {
    if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  };
  for (const Load& l : m.loads)
    for (const ex& u : m.candidates)
      if (std::any_of(l.force.begin(), l.force.end(), [&](const ex& c) { return c.has(u); }) ||
          std::any_of(l.couple.begin(), l.couple.end(), [&](const ex& c) { return c.has(u); }))
        add(to_text(u));
  for (const Load& l : m.loads) add(force_key(l.source));
  auto a_source = [&](const std::string& name) {
    return std::any_of(m.loads.begin(), m.loads.end(), [&](const Load& l) { return l.source == name; });
  };
  std::vector<Diagnostic> problems;
  for (const auto& [name, where] : r.weight_where)
    if (std::find(names.begin(), names.end(), name) == names.end() && !a_source(name))
      problems.push_back({where, "'" + name + "' names no force of the problem (expected a force's unknown or source: " + some(names) + ")"});
  in_file_order(problems);
  return problems;
}

FbdGrade check_fbd(const Model& m, const StudentFbd& fbd, const FbdRubric& rubric, std::vector<Diagnostic>& problems) {
  FbdGrade g;
  const int dims = m.dims();
  std::vector<std::string> body_names, point_names;
  for (const auto& b : m.bodies) body_names.push_back(b.name);
  for (const auto& p : m.points) point_names.push_back(p.name);
  problems = fbd_name_problems(m, fbd);
  if (fbd.bodies.empty()) problems.insert(problems.begin(), {fbd.where, "the free body diagram has no 'body' (expected body: NAME, or bodies: [A, B] for a system)"});
  std::vector<int> bodies;
  for (const auto& name : fbd.bodies)
    if (auto it = std::find(body_names.begin(), body_names.end(), name); it != body_names.end()) bodies.push_back(static_cast<int>(it - body_names.begin()));
  g.of = bodies_phrase(fbd.bodies);

  // The numbers the sketch shows: the parameters' values, the layout's positions.
  std::set<ex, ex_is_less> defaulted;
  const exmap values = layout_numbers(m, {}, &defaulted);
  auto num = [&](const ex& e) { return real_at(e, values); };
  auto position = [&](const Vec& v) { return point_at(m, num, v); };
  // A student's `at`: a point, or a body (its center of mass).
  std::vector<std::optional<Triple>> arrow_at(fbd.forces.size());
  for (std::size_t i = 0; i < fbd.forces.size(); ++i) {
    const std::string& at = fbd.forces[i].at;
    if (at.empty()) continue;
    if (auto p = std::find(point_names.begin(), point_names.end(), at); p != point_names.end()) {
      arrow_at[i] = position(m.points[static_cast<std::size_t>(p - point_names.begin())].position);
    } else if (auto b = std::find(body_names.begin(), body_names.end(), at); b != body_names.end() && m.bodies[static_cast<std::size_t>(b - body_names.begin())].has_cm) {
      arrow_at[i] = position(m.bodies[static_cast<std::size_t>(b - body_names.begin())].cm);
    }
  }
  if (!problems.empty()) {
    g.verdict = Verdict::invalid;
    g.summary = problems.front().message;
    g.findings.push_back({"unknown_name", g.summary});
    return g;
  }

  // Tackle's own diagram: one entry per force the student should draw.
  const std::set<ex, ex_is_less> unknowns(m.candidates.begin(), m.candidates.end());
  std::set<ex, ex_is_less> positive;  // unknowns a condition keeps from being negative (T >= 0, N >= 0)
  for (const auto& c : m.conditions) {
    if (c.op == ">=" || c.op == ">") positive.insert((c.lhs - c.rhs).expand());
    else if (c.op == "<=" || c.op == "<") positive.insert((c.rhs - c.lhs).expand());
  }
  auto state_free = [&](const ex& e) {
    for (const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it)
      if (is_a<symbol>(*it)) {
        const SymbolInfo* info = m.symbols->find(*it);
        if (!info || (info->role != SymbolRole::parameter && info->role != SymbolRole::defined)) return false;
      }
    return true;
  };
  auto uses_defaulted = [&](const ex& e) {
    for (const auto& s : defaulted)
      if (e.has(s)) return true;
    return false;
  };
  struct Entry {
    std::size_t load = 0;
    std::optional<Triple> at;
    std::string at_name;
    std::vector<Triple> lines;  // one direction per part (a free force: several)
    bool fixed = false;         // its sense is known (the first line's)
    bool free = false;          // a force of unknown direction (a pin's): any arrow in the span of its lines
    bool zero = false;          // nothing at the sketch's position
    bool couple = false;
    int couple_sense = 0;
    std::string name;  // its unknown's name, for a student who used the same one
  };
  std::vector<Entry> entries;
  const std::set<std::string> internal = internal_forces(m, bodies);
  std::string undecided_by;
  for (std::size_t li = 0; li < m.loads.size(); ++li) {
    const Load& l = m.loads[li];
    if (std::find(bodies.begin(), bodies.end(), l.body) == bodies.end() || internal.count(force_key(l.source))) continue;
    std::optional<Triple> at;
    if (l.at) at = position(*l.at);
    const std::vector<ForcePart> parts = split_force(m, l.force, unknowns, num);
    std::vector<Entry> of_load;
    for (const ForcePart& p : parts) {
      Entry e{li, at, l.at_name, {}, false, false, false, false, 0, ""};
      FbdGrade::Force f{l.source, force_phrase(l.source), "", "missing", {}, 1, 0};
      ex all = p.key;
      for (int k = 0; k < dims; ++k) all += p.coefficients[k];
      if (uses_defaulted(all) && undecided_by.empty()) undecided_by = force_phrase(l.source);
      if (!p.unknown.is_zero()) {
        const auto key = num(p.key);
        e.lines.push_back(p.numbers);
        if (key && *key < 0)
          for (auto& x : e.lines.back()) x = -x;
        e.fixed = key && *key != 0 && positive.count(p.unknown);
        e.name = to_text(p.unknown);
        f.label = p.key.is_equal(1) ? to_text(p.unknown) : to_text(p.key) + "*" + to_text(p.unknown);
      } else {
        const auto n = position(p.coefficients);
        if (!n) {
          if (undecided_by.empty()) undecided_by = force_phrase(l.source);
          continue;
        }
        e.lines.push_back(*n);
        e.zero = norm3(*n) < 1e-12;
        e.fixed = state_free(all);
        // Its label where it lies along one axis: its size, as a figure writes it (m_B g).
        int along = -1, count = 0;
        for (int k = 0; k < dims; ++k)
          if (!p.coefficients[k].is_zero()) {
            along = k;
            ++count;
          }
        if (count == 1) f.label = to_text((*n)[along] < 0 ? -p.coefficients[along] : p.coefficients[along]);
      }
      of_load.push_back(e);
      g.forces.push_back(f);
    }
    // A force with two or more unknowns of either sign along independent lines (a pin's O_x,
    // O_y): its direction is not known, and one arrow, or one per line, stands for it.
    std::size_t unknown_parts = 0;
    bool any_fixed = false;
    for (const auto& e : of_load) {
      unknown_parts += e.name.empty() ? 0 : 1;
      any_fixed = any_fixed || e.fixed;
    }
    if (unknown_parts >= 2 && unknown_parts == of_load.size() && !any_fixed) {
      Entry merged = of_load.front();
      merged.free = true;
      std::vector<std::string> labels;
      for (std::size_t k = 0; k < of_load.size(); ++k) {
        if (k) merged.lines.push_back(of_load[k].lines.front());
        labels.push_back(g.forces[g.forces.size() - of_load.size() + k].label);
      }
      g.forces.resize(g.forces.size() - of_load.size() + 1);
      g.forces.back().label = join(labels);
      of_load = {merged};
    } else if (of_load.size() > 1) {
      // One load in several arrows (N and mu N): each says which part it is.
      for (std::size_t k = 0; k < of_load.size(); ++k) {
        auto& f = g.forces[g.forces.size() - of_load.size() + k];
        if (!f.label.empty()) f.phrase += " (its " + f.label + " part)";
      }
    }
    entries.insert(entries.end(), of_load.begin(), of_load.end());
    if (dims == 3 && !is_zero_vec(l.couple) && undecided_by.empty()) undecided_by = "the couple of the " + l.source;
    if (dims == 2 && !l.couple[2].is_zero()) {
      Entry e{li, at, l.at_name, {}, false, false, false, true, 0, ""};
      FbdGrade::Force f{l.source, l.source.rfind("couple", 0) == 0 ? "the " + l.source : "the couple of the " + l.source, to_text(l.couple[2]), "missing", {}, 1, 0};
      if (const auto v = num(l.couple[2]); v && state_free(l.couple[2])) {
        bool has_unknown = false;
        for (const auto& u : unknowns) has_unknown = has_unknown || l.couple[2].has(u);
        if (!has_unknown) e.couple_sense = *v > 0 ? 1 : *v < 0 ? -1 : 0;
      }
      if (uses_defaulted(l.couple[2]) && undecided_by.empty()) undecided_by = f.phrase;
      entries.push_back(e);
      g.forces.push_back(f);
    }
  }
  if (!undecided_by.empty()) {
    g.verdict = Verdict::undecided;
    g.summary = undecided_by.rfind("the couple of", 0) == 0
                    ? undecided_by + " is a couple in space, which a drawn diagram is not checked for"
                    : "the direction of " + undecided_by + " depends on a parameter without a value, so a drawing cannot be compared with it";
    g.findings.push_back({"evaluation", g.summary});
    return g;
  }
  for (std::size_t k = 0; k < entries.size(); ++k) {
    auto& f = g.forces[k];
    if (auto w = rubric.weights.find(f.source); w != rubric.weights.end()) f.weight = w->second;
    else if (auto w2 = rubric.weights.find(force_key(f.source)); w2 != rubric.weights.end()) f.weight = w2->second;
    else if (auto w3 = rubric.weights.find(entries[k].name); !entries[k].name.empty() && w3 != rubric.weights.end()) f.weight = w3->second;
    if (entries[k].zero) f.status = "zero";
  }

  // How an arrow fits an entry: 0 not at all; else the better the higher.
  const double cos_tol = std::cos(rubric.tolerance * pi / 180);
  auto same_point = [&](std::size_t i, const Entry& e) {
    if (fbd.forces[i].at.empty() || (!e.at && e.at_name.empty())) return true;
    if (arrow_at[i] && e.at) {
      Triple d{(*arrow_at[i])[0] - (*e.at)[0], (*arrow_at[i])[1] - (*e.at)[1], (*arrow_at[i])[2] - (*e.at)[2]};
      return norm3(d) <= 1e-9 * std::max(1.0, norm3(*e.at));
    }
    return fbd.forces[i].at == e.at_name;
  };
  auto in_span = [&](const Triple& d, const std::vector<Triple>& lines) {
    // The part of d outside the lines' span (Gram-Schmidt), small against d.
    std::vector<Triple> basis;
    for (const auto& l : lines) {
      Triple v = l;
      for (const auto& b : basis) {
        const double c = dot3(v, b);
        for (int k = 0; k < 3; ++k) v[k] -= c * b[k];
      }
      if (const double n = norm3(v); n > 1e-9)
        basis.push_back({v[0] / n, v[1] / n, v[2] / n});
    }
    Triple r = d;
    for (const auto& b : basis) {
      const double c = dot3(r, b);
      for (int k = 0; k < 3; ++k) r[k] -= c * b[k];
    }
    return norm3(r) <= norm3(d) * std::sin(rubric.tolerance * pi / 180) + 1e-12;
  };
  enum Fit { none = 0, off_line = 1, wrong_point = 2, wrong_direction = 3, good = 4 };
  auto direction_fit = [&](std::size_t i, const Entry& e) -> Fit {
    const auto& d = fbd.forces[i].direction;
    if (e.couple) return none;
    if (e.zero) return good;
    if (e.free) return !d || in_span(*d, e.lines) ? good : none;
    if (!d) return wrong_direction;  // its line is known
    const double c = dot3(*d, e.lines.front()) / (norm3(*d) * norm3(e.lines.front()));
    if (c >= cos_tol) return good;
    if (-c >= cos_tol) return e.fixed ? wrong_direction : good;
    return none;
  };
  auto fit = [&](std::size_t i, const Entry& e) -> Fit {
    const Fit d = direction_fit(i, e);
    // At the force's own point (said), along no line it has: the force, drawn off its line.
    if (d == none) return !e.couple && !e.zero && !fbd.forces[i].at.empty() && same_point(i, e) ? off_line : none;
    if (!same_point(i, e)) return d == good ? wrong_point : none;
    return d;
  };

  // The matching that fits best in all (Hungarian method on at most 60 x 60): a good fit over
  // a force drawn the wrong way over one at the wrong point, and the student's name for
  // tackle's symbol only to break ties (a student may call a tension F).
  const std::size_t na = fbd.forces.size(), ne = entries.size();
  std::vector<int> entry_of(na, -1), arrow_of(ne, -1);
  std::vector<Fit> fitted(ne, none);
  auto label_of = [&](std::size_t e) { return entries[e].name.empty() ? g.forces[e].label : entries[e].name; };
  auto value = [&](std::size_t i, std::size_t e) -> double {
    const Fit f = fit(i, entries[e]);
    if (f == none) return 0;
    const double base = f == good ? 10 : f == wrong_direction ? 6 : f == wrong_point ? 5 : 4;
    return base + (!fbd.forces[i].name.empty() && fbd.forces[i].name == label_of(e) ? 1 : 0);
  };
  if (na > 0 && ne > 0) {
    const std::size_t n = std::max(na, ne);
    // u, v: potentials; p[j]: the row matched to column j (1-based, 0: none).
    std::vector<double> u(n + 1, 0), v(n + 1, 0);
    std::vector<std::size_t> p(n + 1, 0), way(n + 1, 0);
    auto cost = [&](std::size_t i, std::size_t j) { return i < na && j < ne ? -value(i, j) : 0.0; };
    for (std::size_t i = 1; i <= n; ++i) {
      p[0] = i;
      std::size_t j0 = 0;
      std::vector<double> minv(n + 1, 1e300);
      std::vector<char> used(n + 1, 0);
      do {
        used[j0] = 1;
        const std::size_t i0 = p[j0];
        double delta = 1e300;
        std::size_t j1 = 0;
        for (std::size_t j = 1; j <= n; ++j) {
          if (used[j]) continue;
          const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
          if (cur < minv[j]) {
            minv[j] = cur;
            way[j] = j0;
          }
          if (minv[j] < delta) {
            delta = minv[j];
            j1 = j;
          }
        }
        for (std::size_t j = 0; j <= n; ++j) {
          if (used[j]) {
            u[p[j]] += delta;
            v[j] -= delta;
          } else {
            minv[j] -= delta;
          }
        }
        j0 = j1;
      } while (p[j0] != 0);
      do {
        const std::size_t j1 = way[j0];
        p[j0] = p[j1];
        j0 = j1;
      } while (j0 != 0);
    }
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t i = p[j] - 1, e = j - 1;
      if (p[j] == 0 || i >= na || e >= ne || value(i, e) <= 0) continue;
      entry_of[i] = static_cast<int>(e);
      arrow_of[e] = static_cast<int>(i);
      fitted[e] = fit(i, entries[e]);
    }
  }
  // A force of unknown direction may be drawn as one arrow per line of its span.
  std::vector<std::vector<std::size_t>> more(ne);
  for (std::size_t i = 0; i < na; ++i) {
    if (entry_of[i] >= 0 || !fbd.forces[i].direction) continue;
    for (std::size_t e = 0; e < ne; ++e) {
      const Entry& en = entries[e];
      if (!en.free || fitted[e] != good || 1 + more[e].size() >= en.lines.size() || fit(i, en) != good) continue;
      const auto& first = fbd.forces[static_cast<std::size_t>(arrow_of[e])].direction;
      if (!first) continue;  // drawn as one force of unknown direction already
      std::vector<Triple> drawn{*first};
      for (auto j : more[e]) drawn.push_back(*fbd.forces[j].direction);
      if (in_span(*fbd.forces[i].direction, drawn)) continue;  // not a new line
      more[e].push_back(i);
      entry_of[i] = static_cast<int>(e);
      break;
    }
  }

  // The grade of each of tackle's forces.
  auto said = [&](std::size_t i) { return fbd.forces[i].name.empty() ? std::string("an arrow") : "your " + fbd.forces[i].name; };
  std::vector<Finding> missing, wrong, extra;
  for (std::size_t e = 0; e < ne; ++e) {
    auto& f = g.forces[e];
    if (arrow_of[e] < 0) {
      if (!entries[e].zero) missing.push_back({"missing_force", f.phrase + " is missing"});
      continue;
    }
    const std::size_t i = static_cast<std::size_t>(arrow_of[e]);
    f.drawn_as.push_back(fbd.forces[i].name);
    for (auto j : more[e]) f.drawn_as.push_back(fbd.forces[j].name);
    switch (fitted[e]) {
      case good:
        f.status = "drawn";
        f.score = f.weight;
        break;
      case wrong_point:
        f.status = "wrong_point";
        f.score = f.weight * rubric.wrong_point;
        wrong.push_back({"wrong_point", said(i) + " stands for " + f.phrase + ", which does not act at " + fbd.forces[i].at});
        break;
      default:
        f.status = fitted[e] == off_line ? "off_line" : "wrong_direction";
        f.score = f.weight * rubric.wrong_direction;
        wrong.push_back({"force_direction", !fbd.forces[i].direction ? said(i) + " stands for " + f.phrase + ", whose line is known: draw it along that line"
                                            : fitted[e] == off_line  ? said(i) + " stands for " + f.phrase + ", but is not along its line"
                                                                     : said(i) + " stands for " + f.phrase + ", which points the other way"});
        break;
    }
    if (entries[e].zero) f.score = 0;
  }
  // Couples: by their sense.
  for (std::size_t c = 0; c < fbd.couples.size(); ++c) {
    const StudentCouple& sc = fbd.couples[c];
    std::optional<std::size_t> best;
    bool right = false;
    for (std::size_t e = 0; e < ne; ++e) {
      if (!entries[e].couple || arrow_of[e] >= 0 || g.forces[e].status != "missing") continue;
      const bool ok = entries[e].couple_sense == 0 || sc.sense == entries[e].couple_sense;
      if (!best || (ok && !right)) {
        best = e;
        right = ok;
      }
    }
    if (!best) {
      extra.push_back({"extra_force", (sc.name.empty() ? std::string("a couple") : "your couple " + sc.name) + ": no couple acts on " + g.of});
      g.extras.push_back({sc.name, "extra_force", extra.back().message});
      continue;
    }
    auto& f = g.forces[*best];
    f.drawn_as.push_back(sc.name);
    // Found missing above (no arrow stands for a couple): taken back.
    missing.erase(std::remove_if(missing.begin(), missing.end(), [&](const Finding& x) { return x.message == f.phrase + " is missing"; }), missing.end());
    if (right) {
      f.status = "drawn";
      f.score = f.weight;
    } else {
      f.status = "wrong_direction";
      f.score = f.weight * rubric.wrong_direction;
      wrong.push_back({"force_direction", "your couple " + sc.name + " stands for " + f.phrase + ", which turns the other way"});
    }
  }
  // Every arrow left: an extra force, and why where it can be said.
  for (std::size_t i = 0; i < na; ++i) {
    if (entry_of[i] >= 0) continue;
    std::string code = "extra_force", message;
    // Drawn twice: the same name as the arrow already standing for a force that fits as well.
    for (std::size_t e = 0; e < ne && message.empty(); ++e)
      if (fit(i, entries[e]) == good && !entries[e].zero && arrow_of[e] >= 0 &&
          (fbd.forces[i].name == fbd.forces[static_cast<std::size_t>(arrow_of[e])].name || fbd.forces[i].name == label_of(e)))
        message = said(i) + " counts " + g.forces[e].phrase + " once too often";
    for (std::size_t li = 0; li < m.loads.size() && message.empty(); ++li) {
      const Load& l = m.loads[li];
      const bool ours = std::find(bodies.begin(), bodies.end(), l.body) != bodies.end();
      if (ours && !internal.count(force_key(l.source))) continue;
      Entry e{li, l.at ? position(*l.at) : std::nullopt, l.at_name, {}, false, true, false, false, 0, ""};
      for (const ForcePart& p : split_force(m, l.force, unknowns, num))
        if (!p.unknown.is_zero()) e.lines.push_back(p.numbers);
        else if (auto n = position(p.coefficients)) e.lines.push_back(*n);
      if (e.lines.empty() || fbd.forces[i].at.empty() || !same_point(i, e) || (fbd.forces[i].direction && !in_span(*fbd.forces[i].direction, e.lines)))
        continue;
      if (ours) {
        code = "internal_force";
        message = said(i) + " is " + force_phrase(l.source) + ", which is internal to " + g.of + " (its forces on the system's bodies cancel)";
      } else {
        code = "other_body";
        message = said(i) + " is " + force_phrase(l.source) + ", which acts on " + m.bodies[static_cast<std::size_t>(l.body)].name + ", not on " + g.of;
      }
    }
    if (message.empty())
      message = said(i) + " is not one of the forces on " + g.of + (fbd.forces[i].at.empty() ? std::string("") : " at " + fbd.forces[i].at);
    extra.push_back({code, message});
    g.extras.push_back({fbd.forces[i].name, code, message});
  }

  g.findings = missing;
  g.findings.insert(g.findings.end(), wrong.begin(), wrong.end());
  g.findings.insert(g.findings.end(), extra.begin(), extra.end());
  for (const auto& f : g.forces) {
    if (f.status == "zero") continue;
    g.max_score += f.weight;
    g.score += f.score;
  }
  g.score = std::max(0.0, g.score - rubric.extra * static_cast<double>(g.extras.size()));
  if (g.findings.empty()) {
    g.verdict = Verdict::correct;
    g.summary = "every force on " + g.of + " is drawn, each along its line and at its point";
  } else {
    g.verdict = Verdict::incorrect;
    g.summary = g.findings.front().message;
  }
  return g;
}

CheckResult fbd_result(const FbdGrade& g) {
  CheckResult r;
  r.unknown = "free body diagram of " + g.of;
  r.verdict = g.verdict;
  r.summary = g.summary;
  r.findings = g.findings;
  r.method = g.verdict == Verdict::invalid || g.verdict == Verdict::undecided ? "" : "fbd";
  r.score = g.max_score > 0 ? g.score / g.max_score : (g.verdict == Verdict::correct ? 1.0 : 0.0);
  return r;
}

std::string fbd_text(const FbdGrade& g) {
  std::string out = fmt::format("free body diagram of {}: {}: {}\n", g.of, verdict_name(g.verdict), g.summary);
  for (const auto& f : g.forces) {
    std::string status = f.status == "drawn" ? "drawn" : f.status == "wrong_direction" ? "drawn the wrong way" : f.status == "wrong_point" ? "drawn at the wrong point"
                         : f.status == "off_line"                                    ? "drawn off its line"
                         : f.status == "zero"                                        ? "nothing at this position (not needed)"
                                                                                     : "missing";
    std::vector<std::string> names;
    for (const auto& n : f.drawn_as) names.push_back(n.empty() ? "(no name)" : n);
    if (!names.empty()) status += " as your " + join(names);
    out += fmt::format("  {}{}: {}\n", f.phrase, f.label.empty() || f.phrase.find(" part)") != std::string::npos ? "" : " (" + f.label + ")", status);
  }
  for (const auto& e : g.extras) out += "  extra: " + e.message + "\n";
  if (g.verdict == Verdict::correct || g.verdict == Verdict::incorrect) out += fmt::format("score: {:g} of {:g}\n", g.score, g.max_score);
  return out;
}

std::string fbd_json(const FbdGrade& g) {
  std::string out = "{\n  \"version\": 1,\n  \"of\": " + json_quoted(g.of) + ",\n  \"verdict\": " + json_quoted(verdict_name(g.verdict)) +
                    ",\n  \"summary\": " + json_quoted(g.summary) + ",\n  \"forces\": [";
  for (std::size_t i = 0; i < g.forces.size(); ++i) {
    const auto& f = g.forces[i];
    std::string names = "[";
    for (std::size_t k = 0; k < f.drawn_as.size(); ++k) names += (k ? ", " : "") + json_quoted(f.drawn_as[k]);
    out += fmt::format("{}\n    {{\"source\": {}, \"phrase\": {}, \"label\": {}, \"status\": {}, \"drawn_as\": {}], \"weight\": {}, \"score\": {}}}", i ? "," : "",
                       json_quoted(f.source), json_quoted(f.phrase), json_quoted(f.label), json_quoted(f.status), names, json_number(f.weight),
                       json_number(f.score));
  }
  out += g.forces.empty() ? "],\n" : "\n  ],\n";
  out += "  \"extras\": [";
  for (std::size_t i = 0; i < g.extras.size(); ++i)
    out += fmt::format("{}\n    {{\"name\": {}, \"code\": {}, \"message\": {}}}", i ? "," : "", json_quoted(g.extras[i].name), json_quoted(g.extras[i].code),
                       json_quoted(g.extras[i].message));
  out += g.extras.empty() ? "],\n" : "\n  ],\n";
  out += "  \"findings\": [";
  for (std::size_t i = 0; i < g.findings.size(); ++i)
    out += fmt::format("{}\n    {{\"code\": {}, \"message\": {}}}", i ? "," : "", json_quoted(g.findings[i].code), json_quoted(g.findings[i].message));
  out += g.findings.empty() ? "],\n" : "\n  ],\n";
  out += "  \"score\": " + json_number(g.score) + ",\n  \"max_score\": " + json_number(g.max_score) + "\n}\n";
  return out;
}

}  // namespace tackle

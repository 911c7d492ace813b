#include "check/fbd.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

#include <fmt/format.h>

#include "expr/print.hpp"
#include "model/forces.hpp"

namespace tackle {

using namespace GiNaC;

namespace {

// At most this many arrows and couples in one diagram: a diagram is a drawing, not a batch.
constexpr std::size_t max_arrows = 60;
constexpr double pi = 3.14159265358979323846;

using Triple = std::array<double, 3>;

double norm3(const Triple& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

std::optional<double> number_of(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v) || std::fabs(v) > 1e6) return std::nullopt;
  return v;
}

// The names a message offers: at most a dozen of them.
std::string some(const std::vector<std::string>& names) {
  std::vector<std::string> first(names.begin(),
                                 names.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(names.size(), 12)));
  return join(first) + (names.size() > 12 ? ", ..." : "");
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

// An arrow's `kind`: what sort of force the student means it for.
std::string read_kind(const yaml::Node& node, const std::string& file, Diagnostics& diags) {
  static const std::vector<std::string> kinds{"weight", "tension", "spring", "damper", "applied", "support"};
  const auto t = yaml::scalar(node, "'kind'", file, diags);
  if (!t) return "";
  if (std::find(kinds.begin(), kinds.end(), t->text) != kinds.end()) return t->text;
  diags.error(
      yaml::where(node, file),
      "'" + t->text + "' is not a kind of force (expected weight, tension, spring, damper, applied or support)");
  return "";
}

// The diagram's body, or a system's bodies.
void read_bodies(const yaml::Node& node, StudentFbd& fbd, const std::string& file, Diagnostics& diags) {
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
    if (fbd.bodies.empty() && node["bodies"].is_sequence())
      diags.error(yaml::where(node["bodies"], file), "'bodies' is empty (expected the system's bodies)");
  } else {
    diags.error(fbd.where, "the free body diagram has no 'body' (expected body: NAME, or bodies: [A, B] for a system)");
  }
}

// A force's direction: a list of numbers, an angle in degrees (in the plane), or any.
void read_direction(const yaml::Node& item, StudentForce& f, int dims, const std::string& file, Diagnostics& diags) {
  const yaml::Node dir = item["direction"], angle = item["angle"];
  if (dir && angle) {
    diags.error(yaml::where(angle, file), "a force has 'direction' or 'angle', not both");
  } else if (angle) {
    if (dims != 2) {
      diags.error(yaml::where(angle, file), "'angle' is for a plane problem (expected 'direction' with " +
                                                std::to_string(dims) + " number" + (dims == 1 ? "" : "s") + ")");
    } else if (auto t = yaml::scalar(angle, "'angle'", file, diags)) {
      if (auto v = number_of(t->text))
        f.direction = Triple{std::cos(*v * pi / 180), std::sin(*v * pi / 180), 0};
      else
        diags.error(yaml::where(angle, file), "'angle' is not a number (expected degrees from the " +
                                                  std::string("first axis, counterclockwise)"));
    }
  } else if (dir && dir.is_scalar() && dir.text() == "any") {
    // no direction: the student does not know it (a pin's force)
  } else if (dir && dir.is_sequence()) {
    if (dir.size() != static_cast<std::size_t>(dims)) {
      diags.error(yaml::where(dir, file), "'direction' has " + std::to_string(dir.size()) + " number" +
                                              (dir.size() == 1 ? "" : "s") + " (expected " + std::to_string(dims) +
                                              ", one per axis)");
    } else {
      Triple d{0, 0, 0};
      bool ok = true;
      for (std::size_t k = 0; k < dir.size(); ++k) {
        const auto t = yaml::scalar(dir[k], "a direction's number", file, diags);
        if (!t) {
          ok = false;
          continue;
        }
        if (auto v = number_of(t->text))
          d[k] = *v;
        else {
          diags.error(yaml::where(dir[k], file),
                      "'" + t->text + "' is not a number (expected a number from -10^6 to 10^6)");
          ok = false;
        }
      }
      if (ok && norm3(d) < 1e-12)
        diags.error(yaml::where(dir, file), "'direction' is zero (expected a direction along the force)");
      else if (ok)
        f.direction = d;
    }
  } else {
    diags.error(dir ? yaml::where(dir, file) : f.where, "a force needs its 'direction' (expected a list of " +
                                                            std::to_string(dims) + " number" + (dims == 1 ? "" : "s") +
                                                            (dims == 2 ? ", 'angle' in degrees," : ",") + " or 'any')");
  }
}

// One arrow: its name, kind, point and direction.
StudentForce read_force(const yaml::Node& item, int dims, const std::string& file, Diagnostics& diags) {
  StudentForce f;
  f.where = yaml::where(item, file);
  if (item["name"]) {
    if (auto t = yaml::scalar(item["name"], "'name'", file, diags)) f.name = t->text;
  }
  if (item["kind"]) f.kind = read_kind(item["kind"], file, diags);
  if (item["at"]) {
    if (auto t = yaml::scalar(item["at"], "'at'", file, diags)) {
      f.at = t->text;
      f.at_where = yaml::where(item["at"], file);
    }
  }
  read_direction(item, f, dims, file, diags);
  return f;
}

// One couple: its name and sense.
StudentCouple read_couple(const yaml::Node& item, const std::string& file, Diagnostics& diags) {
  StudentCouple c;
  c.where = yaml::where(item, file);
  if (item["name"]) {
    if (auto t = yaml::scalar(item["name"], "'name'", file, diags)) c.name = t->text;
  }
  if (!item["sense"]) {
    diags.error(c.where, "a couple needs its 'sense' (expected counterclockwise, clockwise or any)");
  } else if (auto t = yaml::scalar(item["sense"], "'sense'", file, diags)) {
    if (t->text == "counterclockwise")
      c.sense = 1;
    else if (t->text == "clockwise")
      c.sense = -1;
    else if (t->text != "any")
      diags.error(yaml::where(item["sense"], file),
                  "'" + t->text + "' is not a sense (expected counterclockwise, clockwise or any)");
  }
  return c;
}

StudentFbd read_fbd_data(const yaml::Node& node, int dims, const std::string& file, Diagnostics& diags) {
  StudentFbd fbd;
  fbd.where = yaml::where(node, file);
  if (!yaml::check_map(node, {"body", "bodies", "forces", "couples"}, "the free body diagram", file, diags)) return fbd;
  read_bodies(node, fbd, file, diags);
  std::size_t count = 0;
  if (const yaml::Node forces = node["forces"]; forces && yaml::is_list(forces, "'forces'", file, diags)) {
    count += forces.size();
    for (const yaml::Node item : forces) {
      if (!yaml::check_map(item, {"name", "at", "direction", "angle", "kind"}, "a force", file, diags)) continue;
      fbd.forces.push_back(read_force(item, dims, file, diags));
    }
  }
  if (const yaml::Node couples = node["couples"]; couples && yaml::is_list(couples, "'couples'", file, diags)) {
    count += couples.size();
    if (dims != 2 && couples.size() > 0)
      diags.error(yaml::where(couples, file), "'couples' are for a plane problem (this one has " +
                                                  std::to_string(dims) + (dims == 1 ? " axis)" : " axes)"));
    for (const yaml::Node item : couples) {
      if (!yaml::check_map(item, {"name", "sense"}, "a couple", file, diags)) continue;
      fbd.couples.push_back(read_couple(item, file, diags));
    }
  }
  if (count > max_arrows)
    diags.error(fbd.where, "the free body diagram has " + std::to_string(count) + " forces and couples (at most " +
                               std::to_string(max_arrows) + ")");
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
      problems.push_back({fbd.body_where[i], "'" + fbd.bodies[i] + "' is not a body of the problem (expected one of: " +
                                                 some(body_names) + ")"});
  for (const auto& f : fbd.forces)
    if (!f.at.empty() && std::find(names.begin(), names.end(), f.at) == names.end())
      problems.push_back(
          {f.at_where, "'" + f.at + "' is not a point or body of the problem (expected one of: " + some(names) + ")"});
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
  if (!yaml::check_map(node, {"wrong_direction", "wrong_point", "extra", "tolerance", "weights"}, "'fbd'", file, diags))
    return r;
  auto read = [&](const yaml::Node& n, const std::string& what, double high, double& into) {
    const auto t = yaml::scalar(n, what, file, diags);
    if (!t) return;
    const auto v = number_of(t->text);
    if (!v || *v < 0 || *v > high)
      diags.error(yaml::where(n, file), what + " is not a number from 0 to " + fmt::format("{:g}", high));
    else
      into = *v;
  };
  for (const auto& [key, field, high] :
       {std::tuple{"wrong_direction", &r.wrong_direction, 1.0}, std::tuple{"wrong_point", &r.wrong_point, 1.0},
        std::tuple{"extra", &r.extra, 1000.0}, std::tuple{"tolerance", &r.tolerance, 45.0}})
    if (node[key]) read(node[key], std::string("'") + key + "'", high, *field);
  if (const yaml::Node w = node["weights"]) {
    if (!w.is_map())
      diags.error(yaml::where(w, file), "'weights' is " + yaml::kind_name(w) +
                                            " (expected a mapping from a force's source or unknown to its points)");
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
  for (const Load& l : m.loads) add(force_key(l.origin));
  auto a_source = [&](const std::string& name) {
    return std::any_of(m.loads.begin(), m.loads.end(), [&](const Load& l) { return l.source() == name; });
  };
  std::vector<Diagnostic> problems;
  for (const auto& [name, where] : r.weight_where)
    if (std::find(names.begin(), names.end(), name) == names.end() && !a_source(name))
      problems.push_back(
          {where,
           "'" + name + "' names no force of the problem (expected a force's unknown or source: " + some(names) + ")"});
  in_file_order(problems);
  return problems;
}

CheckResult checked_fbd(const Model& m, const StudentFbd& fbd, const FbdRubric& rubric,
                        std::vector<Diagnostic>& problems) {
  try {
    return fbd_result(check_fbd(m, fbd, rubric, problems));
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const InputError&) {
    throw;  // the caller's to report, located
  } catch (const std::exception& e) {
    CheckResult r;
    r.unknown = "free body diagram of " + join(fbd.bodies);
    return r.conclude(Verdict::undecided, "internal",
                      std::string("tackle failed while checking this diagram (an internal error: ") + e.what() +
                          "), so it is left undecided");
  }
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

}  // namespace tackle

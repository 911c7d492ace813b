#include "crosscheck/diagram.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include <fmt/format.h>

#include "check/fbd.hpp"

namespace crosscheck {

namespace {

using Rng = std::mt19937_64;

std::size_t pick(Rng& rng, std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); }
bool coin(Rng& rng) { return pick(rng, 2) == 0; }

// An arrow's length carries nothing: a direction times a length from 0.5 to 3.
Eigen::VectorXd drawn(const Eigen::VectorXd& v, Rng& rng) {
  return v * std::uniform_real_distribution<double>(0.5, 3.0)(rng);
}

// The model's force as a student who knows it draws it: at its point, along its line (its own
// sense where that is known, either sense otherwise), a force of unknown direction as `any`
// or along a direction it may take, a couple with its sense (`any` where unknown).
Arrow arrow_for(const BodyForce& f, std::size_t index, Rng& rng) {
  Arrow a{fmt::format("F{}", index + 1), f.at, std::nullopt, f.couple, f.turn, static_cast<int>(index)};
  if (f.couple) return a;
  if (f.lines.size() > 1) {
    if (coin(rng)) return a;  // any
    Eigen::VectorXd d = Eigen::VectorXd::Zero(f.lines.front().size());
    for (const auto& l : f.lines) d += std::uniform_real_distribution<double>(-1.0, 1.0)(rng) * l;
    if (d.norm() > 1e-3) a.direction = drawn(d.normalized(), rng);
    return a;
  }
  a.direction = drawn((f.sense || coin(rng) ? 1.0 : -1.0) * f.lines.front(), rng);
  return a;
}

// The direction turned by `deg` degrees towards a direction across it (in 1-D: none).
std::optional<Eigen::VectorXd> tilted(const Eigen::VectorXd& v, double deg) {
  if (v.size() < 2) return std::nullopt;
  Eigen::Index k = 0;
  v.cwiseAbs().minCoeff(&k);
  Eigen::VectorXd w = Eigen::VectorXd::Unit(v.size(), k);
  w = (w - v * v.dot(w) / v.squaredNorm()).normalized();
  const double a = deg * std::numbers::pi / 180;
  return Eigen::VectorXd(std::cos(a) * v + std::sin(a) * v.norm() * w);
}

std::string yaml_of(const Diagram& g) {
  std::string forces, couples;
  for (const auto& a : g.arrows) {
    if (a.couple) {
      couples += fmt::format("  - {{name: {}, sense: {}}}\n", a.name,
                             a.sense > 0   ? "counterclockwise"
                             : a.sense < 0 ? "clockwise"
                                           : "any");
      continue;
    }
    std::string dir = "any";
    if (a.direction) {
      dir = "[";
      for (int i = 0; i < a.direction->size(); ++i) dir += fmt::format("{}{:.12g}", i ? ", " : "", (*a.direction)(i));
      dir += "]";
    }
    forces += fmt::format("  - {{name: {}, at: {}, direction: {}}}\n", a.name, a.at, dir);
  }
  return "body: " + g.body + "\n" + (forces.empty() ? "forces: []\n" : "forces:\n" + forces) +
         (couples.empty() ? "" : "couples:\n" + couples);
}

// The families: how a diagram is made from the right arrows (nothing: it does not apply).
using Change = std::function<bool(Diagram&, const Model&, const State&, Rng&)>;

bool dropped(Diagram& g, const Model&, const State&, Rng& rng) {
  if (g.arrows.empty()) return false;
  g.arrows.erase(g.arrows.begin() + static_cast<std::ptrdiff_t>(pick(rng, g.arrows.size())));
  return true;
}

// One arrow changed by `change` (which says whether it could), tried from a random one on.
bool one_arrow(Diagram& g, Rng& rng, const std::function<bool(Arrow&, const BodyForce&)>& change) {
  if (g.arrows.empty()) return false;
  const std::size_t start = pick(rng, g.arrows.size());
  for (std::size_t k = 0; k < g.arrows.size(); ++k) {
    const std::size_t i = (start + k) % g.arrows.size();
    if (g.arrows[i].force >= 0 && change(g.arrows[i], g.forces[static_cast<std::size_t>(g.arrows[i].force)]))
      return true;
  }
  return false;
}

bool turned(Diagram& g, const Model&, const State&, Rng& rng) {
  return one_arrow(g, rng, [](Arrow& a, const BodyForce& f) {
    if (a.couple ? f.turn == 0 : !a.direction || !f.sense) return false;
    if (a.couple)
      a.sense = -a.sense;
    else
      a.direction = -*a.direction;
    return true;
  });
}

bool tilted_arrow(Diagram& g, const Model&, const State&, Rng& rng) {
  return one_arrow(g, rng, [](Arrow& a, const BodyForce& f) {
    if (a.couple || !a.direction || f.lines.size() > 1) return false;
    const auto t = tilted(*a.direction, 30);
    if (!t) return false;
    a.direction = *t;
    return true;
  });
}

bool moved(Diagram& g, const Model&, const State&, Rng& rng) {
  return one_arrow(g, rng, [&](Arrow& a, const BodyForce&) {
    if (a.couple) return false;
    std::vector<std::string> elsewhere;
    for (const auto& [name, p] : g.positions)
      if ((p - g.positions.at(a.at)).norm() > 1e-6) elsewhere.push_back(name);
    if (elsewhere.empty()) return false;
    a.at = elsewhere[pick(rng, elsewhere.size())];
    return true;
  });
}

bool extra_weight(Diagram& g, const Model&, const State&, Rng&) {
  for (const auto& f : g.forces)
    if (f.what == "gravity") {
      g.arrows.push_back({"W2", f.at, f.lines.front(), false, 0, -1});
      return true;
    }
  return false;
}

// A force on another body (the other end of a strand, the other side of a joint) drawn here.
bool extra_force(Diagram& g, const Model& m, const State& s, Rng& rng) {
  const auto bodies = m.body_names();
  const std::string other = bodies[pick(rng, bodies.size())];
  if (other == g.body) return false;
  const auto theirs = m.forces_on(other, s);
  if (theirs.empty()) return false;
  const BodyForce& f = theirs[pick(rng, theirs.size())];
  if (f.zero || f.couple || f.what == "gravity") return false;
  Arrow a = arrow_for(f, 0, rng);
  a.name = "X";
  a.force = -1;
  g.arrows.push_back(a);
  return true;
}

bool right(Diagram&, const Model&, const State&, Rng&) { return true; }

struct Family {
  const char* name;
  bool meant;
  Change change;
};
const Family families[] = {{"right", true, right},
                           {"right", true, right},
                           {"dropped", false, dropped},
                           {"turned", false, turned},
                           {"tilted", false, tilted_arrow},
                           {"moved", false, moved},
                           {"extra-weight", false, extra_weight},
                           {"extra-force", false, extra_force}};

// Whether an arrow stands for a force: at its point, along its line (in its sense where that
// is known), within 5 degrees.
bool fits(const Arrow& a, const BodyForce& f, const Diagram& g) {
  if (a.couple || f.couple)
    return a.couple && f.couple && (f.turn == 0 || a.sense == 0 ? f.turn == 0 : a.sense == f.turn);
  if ((g.positions.at(a.at) - g.positions.at(f.at)).norm() > 1e-9 * (1 + g.positions.at(f.at).norm())) return false;
  const double cos_tol = std::cos(5 * std::numbers::pi / 180);
  if (!a.direction) return f.lines.size() > 1;
  const Eigen::VectorXd d = a.direction->normalized();
  if (f.lines.size() > 1) {
    Eigen::MatrixXd L(d.size(), static_cast<Eigen::Index>(f.lines.size()));
    for (std::size_t k = 0; k < f.lines.size(); ++k) L.col(static_cast<Eigen::Index>(k)) = f.lines[k];
    const Eigen::VectorXd r = d - L * L.completeOrthogonalDecomposition().solve(d);
    return r.norm() <= std::sin(5 * std::numbers::pi / 180);
  }
  const double c = d.dot(f.lines.front());
  return c >= cos_tol || (!(f.sense && !f.zero) && -c >= cos_tol);
}

// Which rows a matching in `fit` (augmenting paths) leaves without a column; rows with
// `needed` false are not matched at all.
std::vector<std::size_t> unmatched_rows(const std::vector<std::vector<bool>>& fit, std::size_t columns,
                                        const std::vector<bool>& needed) {
  std::vector<int> row_of(columns, -1);
  const std::function<bool(std::size_t, std::vector<bool>&)> augment = [&](std::size_t i, std::vector<bool>& seen) {
    for (std::size_t j = 0; j < columns; ++j) {
      if (!fit[i][j] || seen[j]) continue;
      seen[j] = true;
      if (row_of[j] < 0 || augment(static_cast<std::size_t>(row_of[j]), seen)) {
        row_of[j] = static_cast<int>(i);
        return true;
      }
    }
    return false;
  };
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < fit.size(); ++i) {
    std::vector<bool> seen(columns, false);
    if (needed[i] && !augment(i, seen)) out.push_back(i);
  }
  return out;
}

// Whether `arrows` can stand together for the force of unknown direction `f` as its components
// (docs/checking.md: one arrow per component along independent lines): two or more, at most
// one per line of its span, each fitting it with a direction, drawn at one point (as said), each
// more than 5 degrees off the span of the ones before it.
bool components(const Diagram& g, const BodyForce& f, const std::vector<std::size_t>& arrows) {
  if (arrows.size() < 2 || arrows.size() > f.lines.size()) return false;
  std::vector<Eigen::VectorXd> basis;
  for (const std::size_t i : arrows) {
    const Arrow& a = g.arrows[i];
    if (!a.direction || a.at != g.arrows[arrows.front()].at || !fits(a, f, g)) return false;
    Eigen::VectorXd r = a.direction->normalized();
    for (const auto& b : basis) r -= r.dot(b) * b;
    if (r.norm() <= std::sin(5 * std::numbers::pi / 180)) return false;
    basis.push_back(r.normalized());
  }
  return true;
}

// The first arrow no force takes and the first force no arrow stands for, of those `in` (an
// arrow's or force's flag), or nothing: a matching one for one.
std::pair<std::optional<std::size_t>, std::optional<std::size_t>> left_over(const Diagram& g,
                                                                            const std::vector<bool>& arrow_in,
                                                                            const std::vector<bool>& force_in) {
  // Right when one matching of arrows to forces takes in every arrow and every force that is
  // not zero (a zero force may be drawn or not). Such a matching exists exactly when one takes
  // in every arrow and one every such force (Mendelsohn-Dulmage): each is found alone.
  const std::size_t na = g.arrows.size(), nf = g.forces.size();
  std::vector<std::vector<bool>> by_arrow(na, std::vector<bool>(nf, false)), by_force(nf, std::vector<bool>(na, false));
  for (std::size_t i = 0; i < na; ++i)
    for (std::size_t j = 0; j < nf; ++j)
      by_arrow[i][j] = by_force[j][i] = arrow_in[i] && force_in[j] && fits(g.arrows[i], g.forces[j], g);
  std::vector<bool> drawn(nf);
  for (std::size_t j = 0; j < nf; ++j) drawn[j] = force_in[j] && !g.forces[j].zero;
  const auto extra = unmatched_rows(by_arrow, nf, arrow_in);
  const auto missing = unmatched_rows(by_force, na, drawn);
  return {extra.empty() ? std::nullopt : std::optional(extra.front()),
          missing.empty() ? std::nullopt : std::optional(missing.front())};
}

// Whether the diagram is right with each force of unknown direction from `from` on drawn as one
// arrow or as its components (every group of arrows tried).
bool right_with_components(const Diagram& g, std::size_t from, std::vector<bool>& arrow_in,
                           std::vector<bool>& force_in) {
  if (from == g.forces.size()) {
    const auto [extra, missing] = left_over(g, arrow_in, force_in);
    return !extra && !missing;
  }
  if (right_with_components(g, from + 1, arrow_in, force_in)) return true;
  const BodyForce& f = g.forces[from];
  if (f.couple || f.lines.size() < 2) return false;
  const std::size_t na = g.arrows.size();
  for (std::size_t mask = 1; na < 16 && mask < (std::size_t{1} << na); ++mask) {
    std::vector<std::size_t> group;
    for (std::size_t i = 0; i < na; ++i)
      if ((mask >> i) & 1) group.push_back(i);
    if (std::any_of(group.begin(), group.end(), [&](std::size_t i) { return !arrow_in[i]; }) ||
        !components(g, f, group))
      continue;
    for (const std::size_t i : group) arrow_in[i] = false;
    force_in[from] = false;
    const bool right = right_with_components(g, from + 1, arrow_in, force_in);
    for (const std::size_t i : group) arrow_in[i] = true;
    force_in[from] = true;
    if (right) return true;
  }
  return false;
}

}  // namespace

std::optional<Variant> make_diagram(const tackle::Description& d, Rng& rng) {
  try {
    const Model m(d, rng);
    State s = m.base_state();
    if (m.has_massless())
      if (auto settled = m.random_state(rng, 0.0)) s = *settled;
    const auto bodies = m.body_names();
    auto g = std::make_shared<Diagram>();
    g->body = bodies[pick(rng, bodies.size())];
    g->forces = m.forces_on(g->body, s);
    for (const auto& name : bodies) g->positions[name] = *m.named_position(name, s);
    for (const auto& p : d.points) g->positions[p.name.text] = *m.named_position(p.name.text, s);
    for (std::size_t k = 0; k < g->forces.size(); ++k)
      if (!g->forces[k].zero) g->arrows.push_back(arrow_for(g->forces[k], k, rng));
    const Family& f = families[pick(rng, std::size(families))];
    if (!f.change(*g, m, s, rng)) return std::nullopt;
    return Variant{yaml_of(*g), f.name, f.meant, "", g};
  } catch (const Unsupported&) {
    return std::nullopt;
  }
}

Judgement judge_diagram(const Diagram& g) {
  std::vector<bool> arrow_in(g.arrows.size(), true), force_in(g.forces.size(), true);
  if (right_with_components(g, 0, arrow_in, force_in)) return {Truth::holds, "", 0};
  // Wrong: said as the one-for-one matching finds it.
  const auto [extra, missing] = left_over(g, arrow_in, force_in);
  if (extra) return {Truth::fails, "arrow " + g.arrows[*extra].name + " is no force on " + g.body, 1};
  const BodyForce& f = g.forces[missing.value_or(0)];
  return {Truth::fails, "the force of " + f.what + " at " + f.at + " is not drawn", 1};
}

tackle::CheckResult check_diagram(const tackle::Analysis& a, const std::string& yaml) {
  try {
    const tackle::StudentFbd fbd = tackle::read_fbd_file(yaml, "diagram.yaml", a.model);
    std::vector<tackle::Diagnostic> problems;
    return tackle::fbd_result(tackle::check_fbd(a.model, fbd, tackle::FbdRubric{}, problems));
  } catch (const tackle::InputError& e) {
    tackle::CheckResult r;
    r.conclude(tackle::Verdict::invalid, "input", e.what());
    return r;
  }
}

}  // namespace crosscheck

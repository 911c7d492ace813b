#include "crosscheck/model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "core/units.hpp"  // input reading only: each unit's factor to SI

namespace crosscheck {

namespace {

double unit_factor(const std::string& text) {
  std::string error;
  int column = 0;
  auto u = tackle::parse_unit(text, error, column);
  if (!u) throw Unsupported("unit '" + text + "': " + error);
  const GiNaC::ex x = u->to_si.evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(x)) throw Unsupported("unit '" + text + "' has no numeric factor");
  return GiNaC::ex_to<GiNaC::numeric>(x).to_double();
}

const tackle::ArgDesc& need(const tackle::ConnectionDesc& c, const std::string& key) {
  const tackle::ArgDesc* a = c.arg(key);
  if (!a || a->items.empty()) throw Unsupported("a '" + c.type.text + "' connection without '" + key + "'");
  return *a;
}
std::string need_text(const tackle::ConnectionDesc& c, const std::string& key) { return need(c, key).items[0].text; }
std::optional<std::string> opt_text(const tackle::ConnectionDesc& c, const std::string& key) {
  const tackle::ArgDesc* a = c.arg(key);
  if (!a || a->items.empty()) return std::nullopt;
  return a->items[0].text;
}

D2 seed(double x, double first, double second_dir) { return D2(D1(x, first), D1(second_dir, 0.0)); }

// A vector of the plane turned by `a` (counterclockwise); other dimensions unchanged.
Eigen::VectorXd rotated(const Eigen::VectorXd& v, double a) {
  if (v.size() != 2 || a == 0) return v;
  Eigen::VectorXd r(2);
  r << std::cos(a) * v(0) - std::sin(a) * v(1), std::sin(a) * v(0) + std::cos(a) * v(1);
  return r;
}

Eigen::MatrixXd pinv_solve_matrix(const Eigen::MatrixXd& A) {
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(A);
  cod.setThreshold(1e-12);
  return cod.pseudoInverse();
}

int rank_of(const Eigen::MatrixXd& A, double tolerance = 1e-9) {
  if (A.rows() == 0) return 0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A);
  const auto& s = svd.singularValues();
  if (s.size() == 0 || s(0) == 0) return 0;
  int r = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s(i) > tolerance * s(0)) ++r;
  return r;
}

}  // namespace

int Model::slot(const std::string& name) const {
  auto it = slots_.find(name);
  return it == slots_.end() ? -1 : it->second;
}

Expr Model::compile_any(const tackle::Text& t) const {
  try {
    Expr e = Expr::compile(t.text, [this](const std::string& n) { return slot(n); });
    return e;
  } catch (const std::runtime_error& e) {
    throw Unsupported(e.what());
  }
}

Expr Model::compile(const tackle::Text& t) const {
  Expr e = compile_any(t);
  // (the steady rate has no value of its own: solve() finds it from a body's acceleration)
  if (steady_slot_ >= 0 && e.uses(steady_slot_))
    throw Unsupported("the steady rate '" + slot_names_[static_cast<std::size_t>(steady_slot_)] +
                      "' outside a body's given acceleration");
  return e;
}

double Model::number(const tackle::Text& t) const {
  Expr e = compile(t);
  std::vector<double> vars(slot_names_.size(), 0.0);
  for (const auto& [n, v] : params_) vars[static_cast<std::size_t>(slot(n))] = v;
  for (const auto& [n, v] : base_coord_)
    if (slot(n) >= 0) vars[static_cast<std::size_t>(slot(n))] = v;
  return e.eval(vars);
}

Model::Model(const tackle::Description& d, std::mt19937_64& rng, const Perturbation& perturb) {
  if (!d.phases.empty()) throw Unsupported("phases (each phase is a problem of its own)");
  if (d.impact) throw Unsupported("an impact (momentum balance over an instant, no forces)");
  if (d.interval) throw Unsupported("an interval of constant acceleration (averaged forces)");
  dims_ = d.axes.empty() ? 1 : static_cast<int>(d.axes.size());
  for (const auto& b : d.bodies)
    if (b.angle && dims_ != 2) throw Unsupported("a body that turns outside the plane (body '" + b.name.text + "')");
  const int n = dims_;

  // Parameters, in SI: values times their unit's factor; defined ones from their expression;
  // those without a value drawn at random (the same values go into tackle's closed forms).
  std::uniform_real_distribution<double> draw(0.5, 2.0);
  for (const auto& p : d.parameters) {
    double v = 0;
    if (p.define) {
      v = number(*p.define);
    } else if (p.value) {
      v = number(*p.value) * (p.unit ? unit_factor(p.unit->text) : 1.0);
    } else {
      v = draw(rng);
      if (p.unit && unit_factor(p.unit->text) != 1.0 && p.unit->text == "deg") v = v * 0.4;
    }
    params_[p.name.text] = v;
    slots_[p.name.text] = static_cast<int>(slot_names_.size());
    slot_names_.push_back(p.name.text);
  }
  // A steady motion at an unknown rate (`steady: {rate: omega}`): the rate is a name of its
  // own, with no value; only a body's given acceleration may use it (see solve_steady).
  if (d.steady && !d.steady->rate.text.empty()) {
    if (d.motion) throw Unsupported("a steady motion at an unknown rate with a motion in time");
    if (slots_.count(d.steady->rate.text)) throw Unsupported("a steady rate named as a parameter");
    steady_slot_ = static_cast<int>(slot_names_.size());
    slots_[d.steady->rate.text] = steady_slot_;
    slot_names_.push_back(d.steady->rate.text);
  }
  first_coord_slot_ = static_cast<int>(slot_names_.size());
  for (const auto& b : d.bodies) {
    for (const auto* c : {&b.position, &b.angle}) {
      if (!*c) continue;
      for (const std::string& s : {(*c)->text, "dot(" + (*c)->text + ")"}) {
        slots_[s] = static_cast<int>(slot_names_.size());
        slot_names_.push_back(s);
      }
    }
  }
  if (!slots_.count("t")) {
    slots_["t"] = static_cast<int>(slot_names_.size());
    slot_names_.push_back("t");
  }

  // The layout: given values first, then the layout's.
  for (const auto& [name, value] : d.layout) base_coord_[name.text] = number(value);
  for (const auto& g : d.given) {
    if (!g.value) continue;
    const double v = number(*g.value) * (g.unit ? unit_factor(g.unit->text) : 1.0);
    const std::string& nm = g.name.text;
    if (nm.rfind("dot(", 0) == 0)
      base_rate_[nm] = v;
    else if (nm.rfind("ddot(", 0) == 0)
      given_accel_[nm] = v;
    else
      base_coord_[nm] = v;
    // a coordinate or rate given in the parameters (theta: theta_0, dot(theta): v/L): tackle
    // answers at that value only, so the states keep it
    const Expr e = compile(*g.value);
    bool in_parameters = false;
    for (int k = 0; k < first_coord_slot_; ++k) in_parameters = in_parameters || e.uses(k);
    if (in_parameters && nm.rfind("ddot(", 0) != 0) pinned_[nm] = v;
  }
  // A problem of kinematics only: no body has a mass, so no balance is written, and the
  // constraints alone give the accelerations from the given ones.
  kinematic_ = !d.bodies.empty();
  for (const auto& bd : d.bodies) kinematic_ = kinematic_ && !bd.mass;
  for (const auto& g : d.given) {
    if (g.name.text.rfind("ddot(", 0) != 0) continue;
    if (!kinematic_) throw Unsupported("a given acceleration (" + g.name.text + ") of a body with a balance");
    if (!given_accel_.count(g.name.text)) given_accel_[g.name.text] = draw(rng) - 1.25;
  }

  if (steady_slot_ >= 0 && kinematic_) throw Unsupported("a steady motion of bodies without mass");

  // Bodies.
  auto eval_vec = [&](const std::vector<Expr>& es, const std::vector<double>& vars) {
    Eigen::VectorXd r(n);
    for (int i = 0; i < n; ++i) r(i) = es[static_cast<std::size_t>(i)].eval(vars);
    return r;
  };
  auto base_vars = [&]() {
    std::vector<double> vars(slot_names_.size(), 0.0);
    for (const auto& [nm, v] : params_) vars[static_cast<std::size_t>(slot(nm))] = v;
    for (const auto& [nm, v] : base_coord_)
      if (slot(nm) >= 0) vars[static_cast<std::size_t>(slot(nm))] = v;
    return vars;
  };
  const int t_slot = slot("t");
  for (const auto& bd : d.bodies) {
    Body b;
    b.name = bd.name.text;
    if (!bd.mass && !kinematic_)
      throw Unsupported("body '" + b.name +
                        "' has no mass (kinematics only: no balance is written for it) beside bodies that have one");
    b.mass = bd.mass ? number(*bd.mass) * (1 + perturb.masses) : 0.0;
    b.massive = b.mass != 0;
    if (b.mass < 0) throw Unsupported("a negative mass");
    if (bd.angle) {
      // A turning body: its rotation is tackle's angle; its inertia about the center given or
      // from its shape and (the model's) mass.
      b.angle = bd.angle->text;
      if (!base_coord_.count(b.angle)) base_coord_[b.angle] = 0.0;
      b.angle0 = base_coord_[b.angle];
      if (bd.acceleration || bd.accel_along) throw Unsupported("a turning body with a given acceleration");
      if (bd.inertia) {
        b.inertia = number(*bd.inertia);
      } else if (bd.shape_kind) {
        const std::string k = bd.shape_kind->text;
        std::vector<double> size;
        if (bd.shape_size)
          for (const auto& t : bd.shape_size->items) size.push_back(number(t));
        auto need_size = [&](std::size_t c) {
          if (size.size() != c) throw Unsupported("shape '" + k + "' with " + std::to_string(size.size()) + " sizes");
        };
        if (k == "disk") {
          need_size(1);
          b.inertia = b.mass * size[0] * size[0] / 2;
        } else if (k == "ring") {
          need_size(1);
          b.inertia = b.mass * size[0] * size[0];
        } else if (k == "rod") {
          need_size(1);
          b.inertia = b.mass * size[0] * size[0] / 12;
        } else if (k == "sphere") {
          need_size(1);
          b.inertia = 2 * b.mass * size[0] * size[0] / 5;
        } else if (k == "box") {
          need_size(2);
          b.inertia = b.mass * (size[0] * size[0] + size[1] * size[1]) / 12;
        } else if (k == "point")
          b.inertia = 0;
        else
          throw Unsupported("shape '" + k + "'");
      }
      b.inertia *= 1 + perturb.inertia;
      if (b.inertia < 0) throw Unsupported("a negative moment of inertia");
    }
    if (n == 1) {
      b.kind = Body::line;
      b.coord = bd.position->text;
      b.a = Eigen::VectorXd::Zero(1);
      b.b = Eigen::VectorXd::Ones(1);
    } else if (bd.position) {
      if (!bd.center_of_mass) throw Unsupported("a body with a position and no center of mass");
      b.kind = Body::line;
      b.coord = bd.position->text;
      std::vector<Expr> cm;
      for (const auto& it : bd.center_of_mass->items) cm.push_back(compile(it));
      const int own = slot(b.coord);
      for (const auto& e : cm) {
        for (int s = first_coord_slot_; s < static_cast<int>(slot_names_.size()); ++s)
          if (s != own && e.uses(s))
            throw Unsupported("the center of mass of '" + b.name + "' depends on '" +
                              slot_names_[static_cast<std::size_t>(s)] + "'");
      }
      auto at = [&](double s) {
        auto vars = base_vars();
        vars[static_cast<std::size_t>(own)] = s;
        return eval_vec(cm, vars);
      };
      b.a = at(0);
      b.b = at(1) - at(0);
      const Eigen::VectorXd bend = at(2.3) - b.a - 2.3 * b.b;
      if (bend.norm() > 1e-12 * (1 + b.a.norm() + b.b.norm()))
        throw Unsupported("the center of mass of '" + b.name + "' moves on a curve, not a line");
    } else {
      if (!bd.center_of_mass) throw Unsupported("body '" + b.name + "' has no center of mass");
      std::vector<Expr> cm;
      for (const auto& it : bd.center_of_mass->items) cm.push_back(compile(it));
      if (static_cast<int>(cm.size()) != n) throw Unsupported("a center of mass of the wrong size");
      b.cm0 = eval_vec(cm, base_vars());
      if (bd.angle) {
        // its center where tackle writes it, in its angle (and other coordinates): a guide
        // holds it there, and its force must come out 0
        b.kind = Body::turning;
        for (const auto& e : cm) {
          for (int s = first_coord_slot_; s < t_slot; ++s)
            if (e.uses(s) && slot_names_[static_cast<std::size_t>(s)].rfind("dot(", 0) == 0)
              throw Unsupported("the center of mass of '" + b.name + "' depends on a rate");
          if (e.uses(t_slot)) uses_time_ = true;
        }
        b.cm_expr = cm;
      } else if (bd.acceleration) {
        b.kind = Body::driven;
        std::vector<Expr> acc;
        for (const auto& it : bd.acceleration->items) {
          acc.push_back(compile_any(it));
          if (acc.back().uses(t_slot)) throw Unsupported("a given acceleration that changes in time");
        }
        b.frame_accel = eval_vec(acc, base_vars());  // (with the steady rate at 0)
        if (steady_slot_ >= 0) {
          // a0 + s w, s the rate squared: linear in s, or the model cannot find s
          auto at = [&](double sq) {
            auto vars = base_vars();
            vars[static_cast<std::size_t>(steady_slot_)] = std::sqrt(sq);
            return eval_vec(acc, vars);
          };
          const Eigen::VectorXd w = at(1) - b.frame_accel;
          if (w.norm() > 0) {
            const Eigen::VectorXd bend = at(2.3) - b.frame_accel - 2.3 * w;
            if (bend.norm() > 1e-12 * (1 + b.frame_accel.norm() + w.norm()))
              throw Unsupported("a given acceleration that is not linear in the steady rate squared");
            if (steady_) throw Unsupported("the steady rate in the accelerations of two bodies");
            Steady st;
            st.body = static_cast<int>(bodies_.size());
            st.a0 = b.frame_accel;
            st.w = w;
            st.squared = d.steady->rate.text + "^2";
            st.rate = d.steady->rate.text;
            st.period = d.steady->period ? d.steady->period->text : "tau";
            steady_ = st;
          }
        }
      } else if (bd.accel_along) {
        b.kind = Body::along;
        std::vector<Expr> dir;
        for (const auto& it : bd.accel_along->items) dir.push_back(compile(it));
        b.b = eval_vec(dir, base_vars()).normalized();
        b.a = b.cm0;
        b.coord = bd.accel_name ? bd.accel_name->text : "a_" + b.name;
      } else {
        b.kind = Body::still;
      }
    }
    if (b.kind == Body::line) {
      auto it = base_coord_.find(b.coord);
      const double s0 = it == base_coord_.end() ? 0.0 : it->second;
      base_coord_[b.coord] = s0;
      b.cm0 = b.a + s0 * b.b;
    }
    if (b.kind != Body::driven) b.frame_accel = Eigen::VectorXd::Zero(n);
    has_massless_ = has_massless_ || !b.massive;
    bodies_.push_back(b);
  }
  if (steady_slot_ >= 0 && !steady_) throw Unsupported("a steady rate that no body's acceleration uses");
  if (steady_) requirements_.push_back({Requirement::real, steady_->squared, "", 0, -1, "the steady rate is real"});
  int next = 0;
  for (auto& b : bodies_) {
    b.q0 = next;
    next += n;
  }
  for (auto& b : bodies_) {
    if ((b.massive || !b.angle.empty()) && n > 1) {
      b.nr = n == 2 ? 1 : 3;
      b.r0 = next;
      next += b.nr;
    }
  }
  ndof_ = next;
  std::map<std::string, int> body_index;
  for (std::size_t i = 0; i < bodies_.size(); ++i) body_index[bodies_[i].name] = static_cast<int>(i);

  // Points: a body is a point (its center); a point on a body at its offset; a fixed point.
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    PointRef p;
    p.name = bodies_[i].name;
    p.body = static_cast<int>(i);
    p.offset = Eigen::VectorXd::Zero(n);
    points_[bodies_[i].name] = p;
  }
  for (const auto& pd : d.points) {
    PointRef p;
    p.name = pd.name.text;
    if (pd.on) {
      auto it = body_index.find(pd.on->text);
      if (it == body_index.end()) throw Unsupported("point on an unknown body");
      p.body = it->second;
      p.turns = pd.turns;
      p.offset = Eigen::VectorXd::Zero(n);
      if (pd.offset) {
        std::vector<Expr> off;
        for (const auto& t : pd.offset->items) off.push_back(compile(t));
        p.offset = eval_vec(off, base_vars());
      }
    } else if (pd.at) {
      for (const auto& t : pd.at->items) {
        p.ground.push_back(compile(t));
        if (p.ground.back().uses(t_slot)) uses_time_ = true;
        for (int s = first_coord_slot_; s < t_slot; ++s)
          if (p.ground.back().uses(s)) throw Unsupported("a fixed point that depends on a coordinate");
      }
      p.frame_accel = Eigen::VectorXd::Zero(n);
    } else {
      throw Unsupported("a point with neither a position nor a body");
    }
    points_[pd.name.text] = p;
  }

  // Gravity.
  gravity_ = Eigen::VectorXd::Zero(n);
  if (d.gravity) {
    std::vector<Expr> g;
    for (const auto& t : d.gravity->items) g.push_back(compile(t));
    gravity_ = eval_vec(g, base_vars());
  } else if (d.gravity_magnitude) {
    const double g = number(*d.gravity_magnitude);
    const double tilt = d.gravity_tilt ? number(*d.gravity_tilt) : 0.0;
    gravity_(0) = -g * std::sin(tilt);
    if (n > 1) gravity_(1) = -g * std::cos(tilt);
  }

  // Connections.
  auto unit_vec = [&](const tackle::ConnectionDesc& c, const std::string& key) {
    const auto& a = need(c, key);
    std::vector<Expr> es;
    for (const auto& t : a.items) es.push_back(compile(t));
    if (static_cast<int>(es.size()) != n) throw Unsupported("a vector of the wrong size");
    Eigen::VectorXd v = eval_vec(es, base_vars());
    if (v.norm() == 0) throw Unsupported("a zero direction");
    return Eigen::VectorXd(v.normalized());
  };
  auto body_of = [&](const tackle::ConnectionDesc& c, const std::string& key) {
    auto it = body_index.find(need_text(c, key));
    if (it == body_index.end()) throw Unsupported("unknown body");
    return it->second;
  };
  auto path_of = [&](const tackle::ConnectionDesc& c, const std::string& key) {
    std::vector<PointRef> pts;
    for (const auto& t : need(c, key).items) pts.push_back(point(t.text, -1));
    return pts;
  };
  auto ground_copy = [&](const PointRef& material_point, int body) {
    // The ground point where a material point of `body` is at the layout (moving with the
    // body's frame when its acceleration is given).
    PointRef g;
    const Eigen::VectorXd p0 = layout_position(material_point);
    for (int i = 0; i < n; ++i) g.ground.push_back(Expr::constant(p0(i)));
    g.frame_accel = bodies_[static_cast<std::size_t>(body)].frame_accel;
    g.frame_body = body;
    return g;
  };
  auto add_project = [&](const std::string& name, const PointRef& p, int body, const Eigen::VectorXd& dir) {
    Constraint c;
    c.kind = Constraint::project;
    c.name = name;
    c.points = {p, ground_copy(p, body)};
    c.dir = dir;
    cons_.push_back(c);
    return &cons_.back();
  };
  const char* xyz[] = {"x", "y", "z"};
  auto add_pin = [&](const std::string& at, const PointRef& p, int body) {
    for (int i = 0; i < n; ++i) add_project(at + "_" + xyz[i], p, body, Eigen::VectorXd::Unit(n, i));
  };
  auto add_rotation = [&](const std::string& name, int body, int other, int axis) {
    const Body& b = bodies_[static_cast<std::size_t>(body)];
    if (b.r0 < 0) throw Unsupported("a couple on a massless body");
    Constraint c;
    c.kind = Constraint::rotation;
    c.name = name;
    c.body = body;
    c.other = other;
    c.dir = Eigen::VectorXd::Constant(1, axis);
    cons_.push_back(c);
  };
  // What a connection adds is labelled after it ("sliding at A": its type, then its name or
  // the point it acts at), for the diagrams.
  auto label_made = [&](const std::string& label, std::size_t cons_from, std::size_t elements_from,
                        std::size_t loads_from) {
    for (std::size_t k = cons_from; k < cons_.size(); ++k) cons_[k].label = label;
    for (std::size_t k = elements_from; k < elements_.size(); ++k) elements_[k].label = label;
    for (std::size_t k = loads_from; k < loads_.size(); ++k) loads_[k].label = label;
  };
  // A contact that grips: it pushes, and its friction stays within mu N (mu when given); in
  // 3-D its friction has two components in the tangent plane (F_<at>1, F_<at>2), and the cone
  // bounds their resultant.
  auto grips = [&](const std::string& at, const tackle::ConnectionDesc& c, const std::string& what,
                   bool plane = false) {
    requirements_.push_back({Requirement::pushes, "N_" + at, "", 0, -1, what + " pushes"});
    if (opt_text(c, "mu"))
      requirements_.push_back({Requirement::cone, plane ? "F_" + at + "1" : "F_" + at, "N_" + at,
                               number(c.arg("mu")->items[0]), -1, what + " grips (|F| <= mu N)",
                               plane ? "F_" + at + "2" : ""});
  };
  // Friction between two moving bodies, decided at the layout once the model is whole: sticking
  // (as built) while its friction stays within mu_s N, else sliding (decide_contacts).
  struct Undecided {
    std::string normal, friction;
    double mu_k = 0;
    Eigen::VectorXd tangent;
  };
  std::vector<Undecided> undecided;
  for (const auto& c : d.connections) {
    const std::string& type = c.type.text;
    const std::string cname = c.name ? c.name->text : "";
    // (what this connection adds is labelled after it, for diagrams: see the loop's end)
    const std::size_t cons_before = cons_.size(), elements_before = elements_.size(), loads_before = loads_.size();
    if (type == "force") {
      Load l;
      l.body = body_of(c, "on");
      l.at = opt_text(c, "at") ? material(*opt_text(c, "at"), l.body) : material(need_text(c, "on"), l.body);
      for (const auto& t : need(c, "force").items) {
        l.force.push_back(compile(t));
        if (l.force.back().uses(t_slot)) uses_time_ = true;
      }
      if (static_cast<int>(l.force.size()) != n) throw Unsupported("a force of the wrong size");
      loads_.push_back(l);
    } else if (type == "couple") {
      Load l;
      l.body = body_of(c, "on");
      l.at = material(need_text(c, "on"), l.body);
      for (int i = 0; i < n; ++i) l.force.push_back(Expr::constant(0));
      for (const auto& t : need(c, "moment").items) l.couple.push_back(compile(t));
      if (bodies_[static_cast<std::size_t>(l.body)].r0 < 0) throw Unsupported("a couple on a massless body");
      loads_.push_back(l);
    } else if (type == "string") {
      Constraint s;
      s.name = opt_text(c, "tension") ? *opt_text(c, "tension") : "T_" + cname;
      s.g_sign = -1;
      requirements_.push_back({Requirement::pulls, s.name, "", 0, -1, "string " + cname + " pulls"});
      if (c.arg("path")) {
        s.kind = Constraint::path;
        s.points = path_of(c, "path");
        s.winds = windings(s.points, perturb.winding ? -1.0 : 1.0);
      } else {
        s.kind = Constraint::length_expr;
        s.length = compile(need(c, "length").items[0]);
      }
      cons_.push_back(s);
    } else if (type == "pulley") {
      // a point the strings bend at; with a radius, the wrapped length is constant (tackle
      // checks that no strand at it turns), so it adds nothing to the length
    } else if (type == "spring" || type == "elastic_cord") {
      Element e;
      e.kind = Element::spring;
      e.points = path_of(c, "path");
      e.winds = windings(e.points, perturb.winding ? -1.0 : 1.0);
      e.k = number(need(c, "k").items[0]);
      if (type == "elastic_cord")
        requirements_.push_back(
            {Requirement::taut, "", "", 0, static_cast<int>(elements_.size()), "elastic cord " + cname + " is taut"});
      if (c.arg("rest_length")) {
        e.rest = number(need(c, "rest_length").items[0]);
      } else {
        e.stretch = true;
        e.stretch_value = number(need(c, "stretch").items[0]);
      }
      elements_.push_back(e);
    } else if (type == "damper") {
      Element e;
      e.kind = Element::damper;
      e.points = path_of(c, "path");
      e.winds = windings(e.points, perturb.winding ? -1.0 : 1.0);
      e.c = number(need(c, "c").items[0]);
      elements_.push_back(e);
    } else if (type == "contact" || type == "link") {
      Constraint s;
      s.kind = Constraint::path;
      s.points = path_of(c, "between");
      const bool contact = type == "contact";
      s.name = opt_text(c, "force") ? *opt_text(c, "force") : (contact ? "N_" : "T_") + cname;
      s.g_sign = contact ? 1 : -1;
      if (contact) requirements_.push_back({Requirement::pushes, s.name, "", 0, -1, "contact " + cname + " pushes"});
      cons_.push_back(s);
    } else if (type == "fixed") {
      const int b = body_of(c, "body");
      add_project("R_" + need_text(c, "body"), material(need_text(c, "body"), b), b, Eigen::VectorXd::Ones(1));
    } else if (type == "roller" || type == "free_wheel" || type == "sliding" || type == "skidding_wheel") {
      const int b = body_of(c, "body");
      const std::string at = need_text(c, "at");
      Constraint* k = add_project("N_" + at, material(at, b), b, unit_vec(c, "normal"));
      requirements_.push_back({Requirement::pushes, "N_" + at, "", 0, -1, "the " + type + " at " + at + " pushes"});
      if (type == "sliding" || type == "skidding_wheel") {
        k->mu = number(need(c, "mu").items[0]);
        k->sliding = unit_vec(c, "sliding");
      }
    } else if (type == "driven_wheel" && bodies_[static_cast<std::size_t>(body_of(c, "body"))].kind == Body::driven) {
      // the traction is what makes the body follow its given acceleration: its point keeps
      // up with the body's frame along the rolling direction
      const int b = body_of(c, "body");
      const std::string at = need_text(c, "at");
      add_project("N_" + at, material(at, b), b, unit_vec(c, "normal"));
      add_project("F_" + at, material(at, b), b, unit_vec(c, "rolling"));
      grips(at, c, "the driven wheel at " + at);
    } else if (type == "rolling") {
      // no slip: the body's material point at the contact C has no velocity along the
      // tangent, v_cm . t + omega (z x (C - cm)) . t = 0, and the center keeps its distance
      // along the normal (the same with n); N_C along n and F_C along t act on the body at C
      const int b = body_of(c, "body");
      const Body& bb = bodies_[static_cast<std::size_t>(b)];
      if (bb.r0 < 0 || n != 2) throw Unsupported("rolling of a body that cannot turn");
      const std::string at = need_text(c, "at");
      const Eigen::VectorXd arm = layout_position(point(at, b)) - bb.cm0;  // C - cm, the ground's directions
      PointRef contact;  // the geometric contact point, the center's plus C - cm
      contact.name = at;
      contact.body = b;
      contact.offset = arm;
      contact.turns = false;
      const std::pair<std::string, std::string> rows[] = {{"N_" + at, "normal"}, {"F_" + at, "tangent"}};
      for (const auto& [name, key] : rows) {
        Constraint k;
        k.kind = Constraint::roll;
        k.name = name;
        k.body = b;
        k.points = {contact};
        k.dir = unit_vec(c, key);
        k.arm = -arm(1) * k.dir(0) + arm(0) * k.dir(1);
        cons_.push_back(k);
      }
      grips(at, c, "the rolling contact at " + at);
    } else if (type == "sticking") {
      // The contact's material point does not move along the normal nor, in 2-D, along the
      // tangent; in 3-D not anywhere in the tangent plane: two rows, along the tangent t
      // (F_<at>1) and along n x t (F_<at>2), the two directions spanning the plane that the
      // description's normal and tangent give (its friction may point anywhere in it).
      const int b = body_of(c, "body");
      const std::string at = need_text(c, "at");
      const Eigen::VectorXd normal = unit_vec(c, "normal"), tangent = unit_vec(c, "tangent");
      add_project("N_" + at, material(at, b), b, normal);
      if (dims_ == 3) {
        if (std::abs(normal.dot(tangent)) > 1e-9)
          throw Unsupported("a sticking contact whose tangent is not at right angles to its normal (at " + at + ")");
        const Eigen::Vector3d across =
            Eigen::Vector3d(normal(0), normal(1), normal(2)).cross(Eigen::Vector3d(tangent(0), tangent(1), tangent(2)));
        add_project("F_" + at + "1", material(at, b), b, tangent);
        add_project("F_" + at + "2", material(at, b), b, Eigen::VectorXd(across));
      } else {
        add_project("F_" + at, material(at, b), b, tangent);
      }
      grips(at, c, "the sticking contact at " + at, dims_ == 3);
    } else if (type == "sticking_between" || type == "sliding_between" || type == "friction_between") {
      // Two bodies that touch (stacked blocks): the model keeps their centers' relative
      // position along the normal (N_<at>: the first is pushed along n, the other along -n) and,
      // while they stick, along the tangent (F_<at>, the same way); sliding, kinetic friction
      // mu N on the first against its slip relative to the other, and the opposite on the other.
      // Point masses: the contact's force acts through each body's center (a block that could
      // tip, a contact away from the centers, is not modelled).
      const int b = body_of(c, "body"), o = body_of(c, "other");
      const std::string at = need_text(c, "at"), first = need_text(c, "body"), other = need_text(c, "other");
      if (at != first && at != other)
        throw Unsupported("a contact between two bodies away from their centers ('" + at + "')");
      for (int k : {b, o})
        if (!bodies_[static_cast<std::size_t>(k)].angle.empty())
          throw Unsupported("a contact between two bodies, one of them turning");
      auto relative = [&](const std::string& name, const Eigen::VectorXd& dir) {
        Constraint k;
        k.kind = Constraint::relative;
        k.name = name;
        k.points = {material(first, b), material(other, o)};
        k.points[0].name = k.points[1].name = at;  // (where the description says it acts)
        k.dir = dir;
        cons_.push_back(k);
      };
      const std::string what = "the contact between " + first + " and " + other + " at " + at;
      relative("N_" + at, unit_vec(c, "normal"));
      requirements_.push_back({Requirement::pushes, "N_" + at, "", 0, -1, what + " pushes"});
      if (type == "sliding_between") {
        cons_.back().mu = number(need(c, "mu").items[0]);
        cons_.back().sliding = unit_vec(c, "sliding");
      } else {
        const double mu = number(need(c, type == "friction_between" ? "mu_s" : "mu").items[0]);
        relative("F_" + at, unit_vec(c, "tangent"));
        requirements_.push_back({Requirement::cone, "F_" + at, "N_" + at, mu, -1, what + " grips (|F| <= mu N)"});
        if (type == "friction_between")
          undecided.push_back({"N_" + at, "F_" + at, number(need(c, "mu_k").items[0]), unit_vec(c, "tangent")});
      }
    } else if (type == "collar") {
      const int b = body_of(c, "body");
      const std::string at = need_text(c, "at");
      add_project(opt_text(c, "force") ? *opt_text(c, "force") : "P_" + at, material(at, b), b, unit_vec(c, "across"));
      add_project(opt_text(c, "force_too") ? *opt_text(c, "force_too") : "Q_" + at, material(at, b), b,
                  unit_vec(c, "across_too"));
    } else if (type == "pin" || type == "ball_and_socket" || type == "hinge" || type == "fixed_support" ||
               type == "weld") {
      const int b = body_of(c, "body");
      const std::string at = need_text(c, "at");
      add_pin(at, material(at, b), b);
      if (type == "fixed_support") add_rotation("M_" + at, b, -1, 0);
      if (type == "weld")
        for (int i = 0; i < 3; ++i) add_rotation("M_" + at + xyz[i], b, -1, i);
    } else if (type == "rod" || type == "cable") {
      const int b = body_of(c, "body");
      const std::string from = need_text(c, "from"), to = need_text(c, "to");
      Constraint s;
      s.kind = Constraint::path;
      s.name = "T_" + from + to;
      s.g_sign = -1;
      if (type == "cable")
        requirements_.push_back({Requirement::pulls, s.name, "", 0, -1, "cable from " + from + " pulls"});
      const PointRef pf = material(from, b);
      PointRef pt = point(to, -1);
      if (pt.body >= 0) throw Unsupported("a rod or cable to a moving point");
      pt.frame_accel = bodies_[static_cast<std::size_t>(b)].frame_accel;
      pt.frame_body = b;
      s.points = {pf, pt};
      cons_.push_back(s);
    } else if (type == "pin_joint" || type == "ball_joint" || type == "weld_joint" || type == "slider_joint" ||
               type == "same_motion") {
      const int b = body_of(c, "body"), o = body_of(c, "other");
      const std::string at = type == "same_motion" ? need_text(c, "body") : need_text(c, "at");
      const PointRef pa = material(at, b), pb = material(at, o);
      auto relative = [&](const std::string& name, const Eigen::VectorXd& dir) {
        Constraint k;
        k.kind = Constraint::relative;
        k.name = name;
        k.points = {pa, pb};
        k.dir = dir;
        cons_.push_back(k);
      };
      if (type == "slider_joint") {
        // across the slide, which turns with `other`; the point slides along it, so the
        // reaction on `other` acts where the point is now, not at a point of `other`
        Constraint k;
        k.kind = Constraint::slide;
        k.name = "N_" + at;
        k.points = {pa};
        k.other = o;
        k.dir = unit_vec(c, "normal");
        cons_.push_back(k);
      } else {
        for (int i = 0; i < n; ++i)
          relative(type == "same_motion" ? "" : at + "_" + xyz[i], Eigen::VectorXd::Unit(n, i));
      }
      if (type == "weld_joint" || type == "slider_joint") add_rotation("M_" + at, b, o, 0);
    } else {
      throw Unsupported("connection type '" + type + "' (" +
                        (type == "unknown_force" || type == "driven_wheel"
                             ? "an unknown force that no constraint determines, "
                               "on a body whose acceleration is not given"
                             : "not in the model") +
                        ")");
    }
    label_made(type + (cname.empty() ? "" : " " + cname), cons_before, elements_before, loads_before);
  }

  // Guides: what tackle's bodies do without a connection saying so. A body with a
  // coordinate moves on its line, an accelerating one along its direction, a driven one
  // with its given acceleration, any other one stays still; no body with a mass rotates.
  for (std::size_t i = 0; i < bodies_.size(); ++i) {
    const Body& b = bodies_[i];
    std::vector<Eigen::VectorXd> across;
    if (b.kind == Body::turning) {
      for (int k = 0; k < n; ++k) {
        Constraint c;
        c.kind = Constraint::guide_curve;
        c.guide = true;
        c.name = "guide on " + b.name + " to its center as written (" + xyz[k] + ")";
        c.body = static_cast<int>(i);
        c.dir = Eigen::VectorXd::Unit(n, k);
        cons_.push_back(c);
      }
    } else if (b.kind == Body::line || b.kind == Body::along) {
      Eigen::MatrixXd basis = Eigen::MatrixXd::Identity(n, n);
      const Eigen::VectorXd u = b.b.normalized();
      for (int k = 0; k < n; ++k) {
        Eigen::VectorXd e = basis.col(k) - u * u.dot(basis.col(k));
        for (const auto& a : across) e -= a * a.dot(e);
        if (e.norm() > 1e-6) across.push_back(e.normalized());
      }
    } else {
      // a body in steady motion: its first guide along the part of its acceleration that the
      // unknown rate gives (solve_steady finds the rate that makes that guide's force 0)
      const bool steady = steady_ && steady_->body == static_cast<int>(i);
      if (steady) across.push_back(steady_->w.normalized());
      for (int k = 0; k < n; ++k) {
        Eigen::VectorXd e = Eigen::VectorXd::Unit(n, k);
        for (const auto& a : across) e -= a * a.dot(e);
        if (e.norm() > 1e-6) across.push_back(e.normalized());
      }
      if (steady) steady_->guide = static_cast<int>(cons_.size());
    }
    for (std::size_t k = 0; k < across.size(); ++k) {
      Constraint c;
      c.kind = Constraint::guide_line;
      c.guide = true;
      c.name = "guide on " + b.name + " across its motion (" + std::to_string(k + 1) + ")";
      if (steady_ && steady_->guide == static_cast<int>(cons_.size()))
        c.name = "guide on " + b.name + " along its acceleration at the steady rate";
      c.body = static_cast<int>(i);
      c.dir = across[k];
      cons_.push_back(c);
    }
    for (int k = 0; k < (b.angle.empty() ? b.nr : 0); ++k) {
      Constraint c;
      c.kind = Constraint::rotation;
      c.guide = true;
      c.name = "guide couple on " + b.name + " (" + xyz[b.nr == 1 ? 2 : k] + ")";
      c.body = static_cast<int>(i);
      c.other = -1;
      c.dir = Eigen::VectorXd::Constant(1, k);
      cons_.push_back(c);
    }
  }

  // Each constraint's value at the layout is the constant it keeps.
  State s0;
  s0.q = Eigen::VectorXd::Zero(ndof_);
  s0.v = Eigen::VectorXd::Zero(ndof_);
  for (const auto& b : bodies_) {
    s0.q.segment(b.q0, n) = b.cm0;
    if (b.r0 >= 0) s0.q(b.r0) = b.angle0;
  }
  std::vector<D2> q(static_cast<std::size_t>(ndof_));
  for (int i = 0; i < ndof_; ++i) q[static_cast<std::size_t>(i)] = D2(s0.q(i));
  for (auto& c : cons_) {
    if (c.kind == Constraint::guide_line) {
      const Body& b = bodies_[static_cast<std::size_t>(c.body)];
      c.constant = c.dir.dot(b.kind == Body::line ? b.a : b.cm0);
    } else {
      c.constant = value(c, q, D2(0.0)).a.a;
    }
  }

  // Every coordinate of tackle's at 0 (a spring's origin length): lines at their `a`, angles
  // 0, turning bodies' centers where they are written then.
  origin_q_ = Eigen::VectorXd::Zero(ndof_);
  {
    std::vector<double> vars(slot_names_.size(), 0.0);
    for (const auto& [nm, v] : params_) vars[static_cast<std::size_t>(slot(nm))] = v;
    for (const auto& b : bodies_) {
      const Eigen::VectorXd c = b.kind == Body::line      ? b.a
                                : b.kind == Body::turning ? eval_vec(b.cm_expr, vars)
                                                          : b.cm0;
      origin_q_.segment(b.q0, n) = c;
    }
  }

  // Friction between two moving bodies, decided at the layout: they stick while the friction
  // sticking needs is within mu_s N (and they press on each other); else they slip, the first
  // body the way in which its slip relative to the other then grows (kinetic friction mu_k N
  // against it): of the two ways, the one whose relative acceleration is not against it.
  for (const auto& u : undecided) {
    const Instant inst = solve(base_state());
    const Quantity* f = inst.find(u.friction);
    const Quantity* nn = inst.find(u.normal);
    const auto cone = std::find_if(requirements_.begin(), requirements_.end(), [&](const Requirement& r) {
      return r.kind == Requirement::cone && r.force == u.friction;
    });
    if (!f || !nn || !f->determined || !nn->determined || cone == requirements_.end())
      throw Unsupported("friction between two bodies whose forces the model does not determine");
    if (nn->value >= 0 && std::abs(f->value) <= cone->mu * nn->value) continue;  // they stick
    requirements_.erase(cone);
    cons_.erase(std::find_if(cons_.begin(), cons_.end(), [&](const Constraint& c) { return c.name == u.friction; }));
    Constraint& k = *std::find_if(cons_.begin(), cons_.end(), [&](const Constraint& c) { return c.name == u.normal; });
    k.mu = u.mu_k;
    const Body& first = bodies_[static_cast<std::size_t>(k.points[0].body)];
    const Body& other = bodies_[static_cast<std::size_t>(k.points[1].body)];
    double way = 0;
    for (double sign : {1.0, -1.0}) {
      k.sliding = sign * u.tangent;
      const auto acc = accelerations(base_state());
      if (acc && k.sliding.dot(acc->segment(first.q0, n) - acc->segment(other.q0, n)) >= 0) {
        way = sign;
        break;
      }
    }
    if (way == 0) throw Unsupported("friction between two bodies that slip neither way");
    k.sliding = way * u.tangent;
  }
}

Eigen::VectorXd Model::layout_position(const PointRef& p) const {
  const int n = dims_;
  Eigen::VectorXd p0(n);
  if (p.body >= 0) {
    const Body& b = bodies_[static_cast<std::size_t>(p.body)];
    p0 = b.cm0 + (p.turns ? rotated(p.offset, b.angle0) : p.offset);
  } else {
    std::vector<double> vars(slot_names_.size(), 0.0);
    for (const auto& [nm, v] : params_) vars[static_cast<std::size_t>(slot(nm))] = v;
    for (const auto& [nm, v] : base_coord_)
      if (slot(nm) >= 0) vars[static_cast<std::size_t>(slot(nm))] = v;
    for (int i = 0; i < n; ++i) p0(i) = p.ground[static_cast<std::size_t>(i)].eval(vars);
  }
  return p0;
}

std::vector<Model::Constraint::Winding> Model::windings(const std::vector<PointRef>& pts, double sign) const {
  // A path's end at a point of a turning body that keeps the ground's directions is where
  // the strand leaves the drum it is wound on.
  std::vector<Constraint::Winding> out;
  auto wound = [&](const PointRef& p) {
    return p.body >= 0 && !p.turns && !bodies_[static_cast<std::size_t>(p.body)].angle.empty();
  };
  for (std::size_t k = 0; k < pts.size(); ++k) {
    if (!wound(pts[k])) continue;
    if (pts.size() < 2 || (k != 0 && k + 1 != pts.size()))
      throw Unsupported("a strand over a turning body in the middle of its path");
    Constraint::Winding w;
    w.end = k;
    w.next = k == 0 ? 1 : k - 1;
    w.body = pts[k].body;
    w.sign = sign;
    out.push_back(w);
  }
  return out;
}

Model::PointRef Model::point(const std::string& name, int) const {
  auto it = points_.find(name);
  if (it == points_.end()) throw Unsupported("unknown point '" + name + "'");
  return it->second;
}

Model::PointRef Model::material(const std::string& name, int body) const {
  // The material point of `body` at the point's place at the layout.
  // (in the body's frame: its offset at the layout turned back by the body's angle there)
  PointRef p = point(name, body);
  if (p.body == body) return p;
  const Eigen::VectorXd p0 = layout_position(p);
  const Body& b = bodies_[static_cast<std::size_t>(body)];
  PointRef m;
  m.name = name;
  m.body = body;
  m.offset = rotated(p0 - b.cm0, -b.angle0);
  return m;
}

template <class S>
std::vector<S> Model::variables(const std::vector<S>& q, const Eigen::VectorXd& v, const S& t) const {
  std::vector<S> vars(slot_names_.size(), S(0.0));
  for (const auto& [nm, val] : params_) vars[static_cast<std::size_t>(slot(nm))] = S(val);
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    const double bb = b.b.squaredNorm();
    S s(0.0);
    double rate = 0;
    for (int i = 0; i < dims_; ++i) {
      s = s + (q[static_cast<std::size_t>(b.q0 + i)] - S(b.a(i))) * S(b.b(i) / bb);
      if (v.size() > 0) rate += v(b.q0 + i) * b.b(i) / bb;
    }
    vars[static_cast<std::size_t>(slot(b.coord))] = s;
    vars[static_cast<std::size_t>(slot("dot(" + b.coord + ")"))] = S(rate);
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    vars[static_cast<std::size_t>(slot(b.angle))] = q[static_cast<std::size_t>(b.r0)];
    vars[static_cast<std::size_t>(slot("dot(" + b.angle + ")"))] = S(v.size() > 0 ? v(b.r0) : 0.0);
  }
  vars[static_cast<std::size_t>(slot("t"))] = t;
  return vars;
}

template <class S>
std::vector<S> Model::position(const PointRef& p, const std::vector<S>& q, const std::vector<S>& vars,
                               const S& t) const {
  const int n = dims_;
  std::vector<S> r(static_cast<std::size_t>(n), S(0.0));
  if (p.body >= 0) {
    const Body& b = bodies_[static_cast<std::size_t>(p.body)];
    for (int i = 0; i < n; ++i) r[static_cast<std::size_t>(i)] = q[static_cast<std::size_t>(b.q0 + i)] + S(p.offset(i));
    if (b.r0 >= 0 && p.turns) {
      if (n == 2) {
        // center + Rot(rotation) offset
        using std::sin;
        using std::cos;
        const S th = q[static_cast<std::size_t>(b.r0)];
        const S c = cos(th), sn = sin(th);
        r[0] = q[static_cast<std::size_t>(b.q0)] + c * S(p.offset(0)) - sn * S(p.offset(1));
        r[1] = q[static_cast<std::size_t>(b.q0 + 1)] + sn * S(p.offset(0)) + c * S(p.offset(1));
      } else {
        // Small rotations about the center (exact at rotation 0 with no angular velocity, the
        // only states tackle describes in 3-D): r += phi x offset.
        const S a = q[static_cast<std::size_t>(b.r0)], bq = q[static_cast<std::size_t>(b.r0 + 1)],
                c = q[static_cast<std::size_t>(b.r0 + 2)];
        r[0] = r[0] + bq * S(p.offset(2)) - c * S(p.offset(1));
        r[1] = r[1] + c * S(p.offset(0)) - a * S(p.offset(2));
        r[2] = r[2] + a * S(p.offset(1)) - bq * S(p.offset(0));
      }
    }
  } else {
    for (int i = 0; i < n; ++i) {
      r[static_cast<std::size_t>(i)] = p.ground[static_cast<std::size_t>(i)].eval(vars);
      if (p.frame_accel.size() > 0 && p.frame_accel(i) != 0)
        r[static_cast<std::size_t>(i)] = r[static_cast<std::size_t>(i)] + S(0.5 * p.frame_accel(i)) * t * t;
    }
  }
  return r;
}

template <class S>
S Model::path_length(const std::vector<PointRef>& pts, const std::vector<S>& q, const S& t) const {
  const auto vars = variables(q, Eigen::VectorXd(), t);
  S total(0.0);
  std::vector<S> prev = position(pts[0], q, vars, t);
  for (std::size_t k = 1; k < pts.size(); ++k) {
    std::vector<S> cur = position(pts[k], q, vars, t);
    using std::sqrt;
    using std::abs;
    if (dims_ == 1) {
      total = total + abs(cur[0] - prev[0]);
    } else {
      S sq(0.0);
      for (int i = 0; i < dims_; ++i)
        sq = sq + (cur[static_cast<std::size_t>(i)] - prev[static_cast<std::size_t>(i)]) *
                      (cur[static_cast<std::size_t>(i)] - prev[static_cast<std::size_t>(i)]);
      total = total + sqrt(sq);
    }
    prev = cur;
  }
  return total;
}

template <class S>
S Model::winding_arm(const Constraint::Winding& w, const std::vector<PointRef>& pts, const std::vector<S>& q,
                     const S& t) const {
  // s = d . (z x offset): d the unit vector from the neighbouring point into the end, offset
  // the end's (the ground's directions) from the drum's center. The string's material point
  // at the rim moves with the rim, v_cm + omega z x offset, the end itself with v_cm: the
  // string runs onto the drum at omega s, and the free length plus what is wound is constant.
  using std::sqrt;
  const auto vars = variables(q, Eigen::VectorXd(), t);
  const auto a = position(pts[w.end], q, vars, t), b = position(pts[w.next], q, vars, t);
  const S dx = a[0] - b[0], dy = a[1] - b[1];
  const S len = sqrt(dx * dx + dy * dy);
  const Eigen::VectorXd& o = pts[w.end].offset;
  return S(w.sign) * (dx * S(-o(1)) + dy * S(o(0))) / len;
}

Model::Derivs Model::length_derivs(const std::vector<PointRef>& pts, const std::vector<Constraint::Winding>& winds,
                                   const State& s) const {
  Derivs d = derivs([&](const std::vector<D2>& q, const D2& t) { return path_length(pts, q, t); }, s);
  for (const auto& w : winds) {
    // the wound length's rate is s omega (s from the strand's direction now): in J, s at
    // the rotation; in gamma, ds/dt omega
    const int r = bodies_[static_cast<std::size_t>(w.body)].r0;
    const Derivs a = derivs([&](const std::vector<D2>& q, const D2& t) { return winding_arm(w, pts, q, t); }, s);
    d.value += a.value * s.q(r);
    d.grad(r) += a.value;
    d.dd += (a.grad.dot(s.v) + a.dt) * s.v(r);
  }
  return d;
}

Model::Derivs Model::cons_derivs(const Constraint& c, const State& s) const {
  if (c.kind == Constraint::path && !c.winds.empty()) return length_derivs(c.points, c.winds, s);
  return derivs([&](const std::vector<D2>& q, const D2& t) { return value(c, q, t); }, s);
}

template <class S>
S Model::value(const Constraint& c, const std::vector<S>& q, const S& t) const {
  switch (c.kind) {
    case Constraint::path: {
      S out = path_length(c.points, q, t);
      for (const auto& w : c.winds)
        out = out + winding_arm(w, c.points, q, t) *
                        q[static_cast<std::size_t>(bodies_[static_cast<std::size_t>(w.body)].r0)];
      return out;
    }
    case Constraint::roll: {
      const Body& b = bodies_[static_cast<std::size_t>(c.body)];
      S out = S(c.arm) * q[static_cast<std::size_t>(b.r0)];
      for (int i = 0; i < dims_; ++i) out = out + q[static_cast<std::size_t>(b.q0 + i)] * S(c.dir(i));
      return out;
    }
    case Constraint::guide_curve: {
      const Body& b = bodies_[static_cast<std::size_t>(c.body)];
      const int i = c.dir(0) != 0 ? 0 : 1;
      const auto vars = variables(q, Eigen::VectorXd(), t);
      return q[static_cast<std::size_t>(b.q0 + i)] - b.cm_expr[static_cast<std::size_t>(i)].eval(vars);
    }
    case Constraint::length_expr: return c.length.eval(variables(q, Eigen::VectorXd(), t));
    case Constraint::project:
    case Constraint::relative: {
      const auto vars = variables(q, Eigen::VectorXd(), t);
      const auto a = position(c.points[0], q, vars, t), b = position(c.points[1], q, vars, t);
      S out(0.0);
      for (int i = 0; i < dims_; ++i)
        out = out + (a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(i)]) * S(c.dir(i));
      return out;
    }
    case Constraint::slide: {
      const auto vars = variables(q, Eigen::VectorXd(), t);
      const auto p = position(c.points[0], q, vars, t);
      const Body& o = bodies_[static_cast<std::size_t>(c.other)];
      std::vector<S> n(static_cast<std::size_t>(dims_));
      for (int i = 0; i < dims_; ++i) n[static_cast<std::size_t>(i)] = S(c.dir(i));
      if (o.r0 >= 0 && dims_ == 2) {
        using std::sin;
        using std::cos;
        const S th = q[static_cast<std::size_t>(o.r0)] - S(o.angle0);
        n[0] = cos(th) * S(c.dir(0)) - sin(th) * S(c.dir(1));
        n[1] = sin(th) * S(c.dir(0)) + cos(th) * S(c.dir(1));
      }
      S out(0.0);
      for (int i = 0; i < dims_; ++i)
        out = out +
              n[static_cast<std::size_t>(i)] * (p[static_cast<std::size_t>(i)] - q[static_cast<std::size_t>(o.q0 + i)]);
      return out;
    }
    case Constraint::rotation: {
      const int axis = static_cast<int>(c.dir(0));
      S out = q[static_cast<std::size_t>(bodies_[static_cast<std::size_t>(c.body)].r0 + axis)];
      if (c.other >= 0) {
        const Body& o = bodies_[static_cast<std::size_t>(c.other)];
        if (o.r0 < 0) throw Unsupported("a couple on a massless body");
        out = out - q[static_cast<std::size_t>(o.r0 + axis)];
      }
      return out;
    }
    case Constraint::guide_line: {
      const Body& b = bodies_[static_cast<std::size_t>(c.body)];
      S out(0.0);
      for (int i = 0; i < dims_; ++i) {
        S target(0.0);
        if (b.kind == Body::driven) target = S(0.5 * b.frame_accel(i)) * t * t;
        out = out + (q[static_cast<std::size_t>(b.q0 + i)] - target) * S(c.dir(i));
      }
      return out;
    }
  }
  throw std::logic_error("constraint kind");
}

template <class F>
Model::Derivs Model::derivs(const F& f, const State& s) const {
  Derivs d;
  const std::size_t n = static_cast<std::size_t>(ndof_);
  std::vector<D2> q(n);
  d.grad = Eigen::VectorXd::Zero(ndof_);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) q[j] = D2(s.q(static_cast<Eigen::Index>(j)));
    q[i] = seed(s.q(static_cast<Eigen::Index>(i)), 1.0, 0.0);
    d.grad(static_cast<Eigen::Index>(i)) = f(q, D2(s.t)).a.b;
  }
  for (std::size_t j = 0; j < n; ++j) q[j] = D2(s.q(static_cast<Eigen::Index>(j)));
  d.dt = f(q, seed(s.t, 1.0, 0.0)).a.b;
  for (std::size_t j = 0; j < n; ++j) {
    const double vj = s.v(static_cast<Eigen::Index>(j));
    q[j] = D2(D1(s.q(static_cast<Eigen::Index>(j)), vj), D1(vj, 0.0));
  }
  const D2 r = f(q, D2(D1(s.t, 1.0), D1(1.0, 0.0)));
  d.value = r.a.a;
  d.dd = r.b.b;
  return d;
}

Eigen::VectorXd Model::generalized(const PointRef& p, const Eigen::VectorXd& force, const State& s) const {
  // a force on the body's material point at p: on its center, and its moment about it
  Eigen::VectorXd g = Eigen::VectorXd::Zero(ndof_);
  if (p.body < 0) return g;
  const Body& b = bodies_[static_cast<std::size_t>(p.body)];
  g.segment(b.q0, dims_) = force;
  if (b.r0 >= 0) {
    const Eigen::VectorXd o = dims_ == 2 && p.turns ? rotated(p.offset, s.q(b.r0)) : p.offset;
    if (dims_ == 2) {
      g(b.r0) = o(0) * force(1) - o(1) * force(0);
    } else {
      g(b.r0) = o(1) * force(2) - o(2) * force(1);
      g(b.r0 + 1) = o(2) * force(0) - o(0) * force(2);
      g(b.r0 + 2) = o(0) * force(1) - o(1) * force(0);
    }
  }
  return g;
}

double Model::element_tension(const Element& e, const State& s) const {
  const auto L = length_derivs(e.points, e.winds, s);
  if (e.kind == Element::damper) return e.c * (L.grad.dot(s.v) + L.dt);
  double rest = e.rest;
  if (e.stretch) {
    // origin length: every coordinate of tackle's at 0 (angles too: nothing wound)
    std::vector<D2> q0(static_cast<std::size_t>(ndof_), D2(0.0));
    for (int i = 0; i < ndof_; ++i) q0[static_cast<std::size_t>(i)] = D2(origin_q_(i));
    rest = path_length(e.points, q0, D2(s.t)).a.a - e.stretch_value;
  }
  return e.k * (L.value - rest);
}

Eigen::VectorXd Model::point_position(const PointRef& p, const State& s) const {
  const std::vector<double> q(s.q.data(), s.q.data() + s.q.size());
  const auto r = position(p, q, variables(q, s.v, s.t), s.t);
  return Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size()));
}

std::vector<double> Model::numbers_at(const State& s) const {
  const std::vector<double> q(s.q.data(), s.q.data() + s.q.size());
  return variables(q, s.v, s.t);
}

std::optional<Eigen::VectorXd> Model::named_position(const std::string& name, const State& s) const {
  auto it = points_.find(name);
  if (it == points_.end()) return std::nullopt;
  return point_position(it->second, s);
}

std::vector<std::string> Model::body_names() const {
  std::vector<std::string> out;
  for (const auto& b : bodies_) out.push_back(b.name);
  return out;
}

std::vector<Margin> Model::margins(const State& s, const Instant& inst) const {
  std::vector<Margin> out;
  for (const auto& r : requirements_) {
    Margin m{&r, 0, true};
    const Quantity* f = inst.find(r.force);
    const Quantity* n = r.kind == Requirement::cone ? inst.find(r.normal) : nullptr;
    const Quantity* f2 =
        r.force_too.empty() ? nullptr : inst.find(r.force_too);  // (3-D: the friction's second component)
    if (r.kind == Requirement::taut) {
      m.value = element_tension(elements_[static_cast<std::size_t>(r.element)], s);
    } else if (!f || (r.kind == Requirement::cone && !n) || (!r.force_too.empty() && !f2)) {
      m.determined = false;
    } else {
      m.value = r.kind == Requirement::cone ? r.mu * n->value - std::hypot(f->value, f2 ? f2->value : 0.0) : f->value;
      m.determined = f->determined && (!n || n->determined) && (!f2 || f2->determined);
    }
    out.push_back(m);
  }
  return out;
}

Eigen::VectorXd Model::velocity(const PointRef& p, const State& s) const {
  std::vector<D1> q(static_cast<std::size_t>(ndof_));
  for (int i = 0; i < ndof_; ++i) q[static_cast<std::size_t>(i)] = D1(s.q(i), s.v(i));
  const auto vars = variables(q, Eigen::VectorXd(), D1(s.t, 1.0));
  const auto r = position(p, q, vars, D1(s.t, 1.0));
  Eigen::VectorXd v(dims_);
  for (int i = 0; i < dims_; ++i) v(i) = r[static_cast<std::size_t>(i)].b;
  return v;
}

std::optional<double> Model::slip_speed(const std::string& normal, const State& s) const {
  for (const auto& c : cons_) {
    if (c.name != normal || c.mu == 0) continue;
    // the body's material point there (a contact point that keeps the ground's directions,
    // where a wheel touches, is where the material point now is)
    PointRef p = c.points[0];
    if (!p.turns && p.body >= 0 && dims_ == 2 && bodies_[static_cast<std::size_t>(p.body)].r0 >= 0) {
      p.offset = rotated(p.offset, -s.q(bodies_[static_cast<std::size_t>(p.body)].r0));
      p.turns = true;
    }
    // (between two bodies: the first's slip relative to the other)
    if (c.kind == Constraint::relative) return c.sliding.dot(velocity(p, s) - velocity(c.points[1], s));
    return c.sliding.dot(velocity(p, s));
  }
  return std::nullopt;
}

std::vector<std::pair<std::string, double>> Model::watched(const State& s) const {
  State p = s;
  project(p, false);
  std::vector<std::pair<std::string, double>> out;
  for (const auto& mg : margins(p, solve(p)))
    out.emplace_back(mg.requirement->what, mg.determined ? mg.value : std::numeric_limits<double>::quiet_NaN());
  for (const auto& c : cons_)
    if (c.mu != 0)
      out.emplace_back("the slip at " + c.name.substr(2) + " (its friction turns)", *slip_speed(c.name, p));
  return out;
}

Model::Kkt Model::system(const State& s, const std::vector<int>* only) const {
  const int n = ndof_;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd mass = Eigen::VectorXd::Zero(n);
  for (const auto& b : bodies_) {
    for (int i = 0; i < dims_; ++i) {
      mass(b.q0 + i) = b.mass;
      f(b.q0 + i) += b.mass * gravity_(i);
    }
    for (int k = 0; k < b.nr; ++k)
      mass(b.r0 + k) = b.angle.empty() ? b.mass : b.inertia;  // (without an angle: any positive inertia, held at 0)
  }
  std::vector<double> vars(slot_names_.size());
  {
    std::vector<double> qd(s.q.data(), s.q.data() + s.q.size());
    vars = variables(qd, s.v, s.t);
  }
  for (const auto& l : loads_) {
    Eigen::VectorXd F(dims_);
    for (int i = 0; i < dims_; ++i) F(i) = l.force[static_cast<std::size_t>(i)].eval(vars);
    f += generalized(l.at, F, s);
    if (!l.couple.empty()) {
      const Body& b = bodies_[static_cast<std::size_t>(l.body)];
      for (int k = 0; k < b.nr; ++k) f(b.r0 + k) += l.couple[static_cast<std::size_t>(b.nr == 1 ? 0 : k)].eval(vars);
    }
  }
  for (const auto& e : elements_) f -= element_tension(e, s) * length_derivs(e.points, e.winds, s).grad;

  // Constraints: every rule's; a guide only where the rules leave that motion free.
  std::vector<Derivs> rows;
  std::vector<int> kept;
  Eigen::MatrixXd J(0, n);
  int rank = 0;
  for (std::size_t k = 0; k < cons_.size(); ++k) {
    const Constraint& c = cons_[k];
    Derivs dv = cons_derivs(c, s);
    if (c.guide) {
      Eigen::MatrixXd J2(J.rows() + 1, n);
      J2 << J, dv.grad.transpose();
      const int r2 = rank_of(J2);
      if (only ? std::find(only->begin(), only->end(), static_cast<int>(k)) == only->end() : r2 == rank) continue;
      rank = r2;
      J = J2;
    } else {
      Eigen::MatrixXd J2(J.rows() + 1, n);
      J2 << J, dv.grad.transpose();
      J = J2;
      rank = rank_of(J);
    }
    rows.push_back(dv);
    kept.push_back(static_cast<int>(k));
  }
  const int m = static_cast<int>(kept.size());
  Kkt out;
  out.K = Eigen::MatrixXd::Zero(n + m, n + m);
  out.rhs = Eigen::VectorXd::Zero(n + m);
  out.K.topLeftCorner(n, n) = mass.asDiagonal();
  out.rhs.head(n) = f;
  for (int j = 0; j < m; ++j) {
    const Constraint& c = cons_[static_cast<std::size_t>(kept[static_cast<std::size_t>(j)])];
    Eigen::VectorXd g = c.g_sign * rows[static_cast<std::size_t>(j)].grad;
    if (c.mu != 0) {
      // sliding: the contact's force is N (n - mu s) at its point
      g += generalized(c.points[0], -c.mu * c.sliding, s);
      // (between two bodies, the opposite on the other)
      if (c.kind == Constraint::relative) g -= generalized(c.points[1], -c.mu * c.sliding, s);
    }
    out.K.block(0, n + j, n, 1) = -g;
    out.K.block(n + j, 0, 1, n) = rows[static_cast<std::size_t>(j)].grad.transpose();
    out.rhs(n + j) = -rows[static_cast<std::size_t>(j)].dd;
  }
  out.kept = kept;
  return out;
}

Eigen::VectorXd Model::along_line(const Body& b, const Eigen::MatrixXd& nulls) const {
  // a body's acceleration along its line (or direction): its part of each free direction
  const double bb = b.kind == Body::line ? b.b.squaredNorm() : 1.0;
  return (b.b.transpose() * nulls.middleRows(b.q0, dims_)).transpose() / bb;
}

Instant Model::solve_kinematics(const State& s) const {
  // J a = -gamma with the given accelerations put in: the others by least squares, each
  // compared where the constraints determine it.
  const Kkt k = system(s);
  const int n = ndof_, m = static_cast<int>(k.kept.size());
  Eigen::MatrixXd J = k.K.bottomLeftCorner(m, n);
  Eigen::VectorXd rhs = k.rhs.tail(m);
  std::vector<bool> given(static_cast<std::size_t>(n), false);
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    auto it = given_accel_.find("ddot(" + b.coord + ")");
    if (it == given_accel_.end()) continue;
    // the body's acceleration along its line is given, and the guides hold it across
    for (int i = 0; i < dims_; ++i) {
      const double ai = b.b(i) * it->second;
      rhs -= J.col(b.q0 + i) * ai;
      J.col(b.q0 + i).setZero();
      given[static_cast<std::size_t>(b.q0 + i)] = true;
    }
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    auto it = given_accel_.find("ddot(" + b.angle + ")");
    if (it == given_accel_.end()) continue;
    rhs -= J.col(b.r0) * it->second;
    J.col(b.r0).setZero();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
  svd.setThreshold(1e-11);
  const Eigen::VectorXd x = svd.solve(rhs);
  Instant out;
  out.residual = (J * x - rhs).norm() / std::max(1.0, rhs.norm());
  const int rank = static_cast<int>(svd.rank());
  const Eigen::MatrixXd nulls = svd.matrixV().rightCols(n - rank);
  out.free_directions = static_cast<int>(nulls.cols());
  for (const auto& b : bodies_) {
    if (b.kind != Body::line || given_accel_.count("ddot(" + b.coord + ")")) continue;
    Quantity qn;
    qn.name = "ddot(" + b.coord + ")";
    qn.value = b.b.dot(x.segment(b.q0, dims_)) / b.b.squaredNorm();
    for (int i = 0; i < dims_; ++i)
      qn.determined = qn.determined && (b.b(i) == 0 || nulls.cols() == 0 || nulls.row(b.q0 + i).norm() < 1e-7);
    qn.free = along_line(b, nulls);
    out.quantities.push_back(qn);
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty() || given_accel_.count("ddot(" + b.angle + ")")) continue;
    Quantity qn;
    qn.name = "ddot(" + b.angle + ")";
    qn.value = x(b.r0);
    qn.determined = nulls.cols() == 0 || nulls.row(b.r0).norm() < 1e-7;
    qn.free = nulls.row(b.r0).transpose();
    out.quantities.push_back(qn);
  }
  return out;
}

Instant Model::solve(const State& s) const { return steady_ ? solve_steady(s) : solve_fixed(s); }

void Model::set_steady(double squared) {
  Body& b = bodies_[static_cast<std::size_t>(steady_->body)];
  b.frame_accel = steady_->a0 + squared * steady_->w;
  auto follow = [&](PointRef& p) {
    if (p.frame_body == steady_->body) p.frame_accel = b.frame_accel;
  };
  for (auto& c : cons_)
    for (auto& p : c.points) follow(p);
  for (auto& e : elements_)
    for (auto& p : e.points) follow(p);
  for (auto& l : loads_) follow(l.at);
  for (auto& [name, p] : points_) follow(p);
}

Instant Model::solve_steady(const State& s) const {
  // The body's acceleration is a0 + s w, s the rate squared, unknown. At t = 0 the frame's
  // acceleration enters only the constraints' second derivatives (the right-hand side), so
  // everything solved is affine in s, the force of the guide along w too: tackle's model has
  // no such force, and s is where it vanishes.
  if (uses_time_) throw Unsupported("a steady motion at an unknown rate in a model that depends on time");
  Model at0 = *this, at1 = *this;
  at0.set_steady(0);
  at1.set_steady(1);
  const Instant i0 = at0.solve_fixed(s), i1 = at1.solve_fixed(s);
  const std::string guide = "guide: " + cons_[static_cast<std::size_t>(steady_->guide)].name;
  const Quantity *g0 = i0.find(guide), *g1 = i1.find(guide);
  const double slope = g0 && g1 ? g1->value - g0->value : 0.0;
  if (!g0 || !g1 || !g0->determined || !g1->determined ||
      std::abs(slope) <= 1e-12 * std::max({1.0, std::abs(g0->value), std::abs(g1->value)})) {
    // (the balances do not fix the rate: along w something else holds the body)
    Instant out = i0;
    out.quantities.push_back({steady_->squared, 0, false, false, {}});
    return out;
  }
  const double squared = -g0->value / slope;
  Model at = *this;
  at.set_steady(squared);
  Instant out = at.solve_fixed(s);
  out.quantities.push_back({steady_->squared, squared, true, false, {}});
  if (squared > 0) {
    out.quantities.push_back({steady_->rate, std::sqrt(squared), true, false, {}});
    out.quantities.push_back({steady_->period, 2 * std::numbers::pi / std::sqrt(squared), true, false, {}});
  }
  return out;
}

Instant Model::solve_fixed(const State& s) const {
  if (kinematic_) return solve_kinematics(s);
  const Kkt k = system(s);
  const int n = ndof_;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(k.K, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  const double smax = sv.size() ? sv(0) : 0.0;
  int rank = 0;
  for (int i = 0; i < sv.size(); ++i)
    if (sv(i) > 1e-11 * smax) ++rank;
  svd.setThreshold(1e-11);
  const Eigen::VectorXd x = svd.solve(k.rhs);
  Instant out;
  const double scale = std::max(1.0, k.rhs.norm());
  out.residual = (k.K * x - k.rhs).norm() / scale;
  out.rank_deficiency = static_cast<int>(k.K.rows()) - rank;
  const Eigen::MatrixXd nulls = svd.matrixV().rightCols(k.K.cols() - rank);
  auto determined = [&](int i) { return nulls.rows() == 0 || nulls.cols() == 0 || nulls.row(i).norm() < 1e-7; };
  out.free_directions = static_cast<int>(nulls.cols());
  for (const auto& b : bodies_) {
    if (b.kind != Body::line && b.kind != Body::along) continue;
    Quantity qn;
    qn.name = b.kind == Body::line ? "ddot(" + b.coord + ")" : b.coord;
    qn.value = b.b.dot(x.segment(b.q0, dims_)) / (b.kind == Body::line ? b.b.squaredNorm() : 1.0);
    for (int i = 0; i < dims_; ++i) qn.determined = qn.determined && (b.b(i) == 0 || determined(b.q0 + i));
    qn.free = along_line(b, nulls);
    out.quantities.push_back(qn);
  }
  for (const auto& b : bodies_) {
    for (int r = 0; r < b.nr; ++r) {
      Quantity qn;
      qn.name = b.angle.empty() ? "guide: angular acceleration of " + b.name : "ddot(" + b.angle + ")";
      qn.value = x(b.r0 + r);
      qn.determined = determined(b.r0 + r);
      qn.free = nulls.row(b.r0 + r).transpose();
      out.quantities.push_back(qn);
    }
  }
  for (std::size_t j = 0; j < k.kept.size(); ++j) {
    const Constraint& c = cons_[static_cast<std::size_t>(k.kept[j])];
    if (c.name.empty()) continue;
    Quantity qn;
    qn.name = c.guide ? "guide: " + c.name : c.name;
    qn.value = x(n + static_cast<int>(j));
    qn.determined = determined(n + static_cast<int>(j));
    qn.free = nulls.row(n + static_cast<int>(j)).transpose();
    qn.force = true;
    out.quantities.push_back(qn);
  }
  return out;
}

std::optional<Eigen::VectorXd> Model::accelerations(const State& s) const {
  // An integrator's intermediate states are off the constraints by a little; a guide that
  // the rules make redundant on them (a pinned body's center as written in its angle) is
  // not quite redundant there, and keeping it makes the system singular. The guides are
  // chosen at the state projected onto the constraints.
  std::vector<int> kept;
  const bool curved =
      std::any_of(bodies_.begin(), bodies_.end(), [](const Body& b) { return b.kind == Body::turning; });
  if (curved) {
    State p = s;
    project(p, false);
    kept = system(p).kept;
  }
  const Kkt k = system(s, curved ? &kept : nullptr);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(k.K);
  cod.setThreshold(1e-11);
  if (cod.rank() < k.K.rows()) return std::nullopt;
  return Eigen::VectorXd(cod.solve(k.rhs).head(ndof_));
}

void Model::project(State& s, bool rates_only, const std::vector<bool>* frozen_q,
                    const std::vector<bool>* frozen_v) const {
  const int n = ndof_;
  auto jac = [&](Eigen::VectorXd& phi, Eigen::VectorXd& phit) {
    Eigen::MatrixXd J(static_cast<Eigen::Index>(cons_.size()), n);
    phi.resize(static_cast<Eigen::Index>(cons_.size()));
    phit.resize(static_cast<Eigen::Index>(cons_.size()));
    for (std::size_t k = 0; k < cons_.size(); ++k) {
      const Constraint& c = cons_[k];
      const Derivs dv = cons_derivs(c, s);
      J.row(static_cast<Eigen::Index>(k)) = dv.grad.transpose();
      phi(static_cast<Eigen::Index>(k)) = dv.value - c.constant;
      phit(static_cast<Eigen::Index>(k)) = dv.dt;
    }
    return J;
  };
  auto freeze = [&](Eigen::MatrixXd J, const std::vector<bool>* frozen) {
    if (frozen)
      for (int i = 0; i < n; ++i)
        if ((*frozen)[static_cast<std::size_t>(i)]) J.col(i).setZero();
    return J;
  };
  Eigen::VectorXd phi, phit;
  if (!rates_only) {
    for (int it = 0; it < 60; ++it) {
      Eigen::MatrixXd J = jac(phi, phit);
      if (phi.norm() < 1e-13 * (1 + s.q.norm())) break;
      s.q -= pinv_solve_matrix(freeze(J, frozen_q)) * phi;
    }
  }
  Eigen::MatrixXd J = jac(phi, phit);
  s.v -= pinv_solve_matrix(freeze(J, frozen_v)) * (J * s.v + phit);
}

bool Model::settle_massless(State& s) const {
  // A massless body's position (and rate) is where its force balance holds: Gauss-Newton on
  // the massless bodies' coordinates and rates, making the whole system consistent.
  std::vector<int> idx;
  for (const auto& b : bodies_)
    if (!b.massive && b.kind == Body::line)
      for (int i = 0; i < dims_; ++i) idx.push_back(b.q0 + i);
  if (idx.empty()) return true;
  const int u = static_cast<int>(idx.size());
  auto residual = [&](const State& st) {
    const Kkt k = system(st);
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(k.K);
    cod.setThreshold(1e-11);
    const Eigen::VectorXd x = cod.solve(k.rhs);
    Eigen::VectorXd inconsistency = k.K * x - k.rhs;
    // and the constraints themselves, positions and rates
    std::vector<double> extra;
    for (const auto& c : cons_) {
      const Derivs dv = cons_derivs(c, st);
      extra.push_back(dv.value - c.constant);
      extra.push_back(dv.grad.dot(st.v) + dv.dt);
    }
    Eigen::VectorXd r(inconsistency.size() + static_cast<Eigen::Index>(extra.size()));
    r << inconsistency, Eigen::Map<Eigen::VectorXd>(extra.data(), static_cast<Eigen::Index>(extra.size()));
    return r;
  };
  for (int it = 0; it < 40; ++it) {
    const Eigen::VectorXd r0 = residual(s);
    if (r0.norm() < 1e-11 * (1 + s.q.norm() + s.v.norm())) return true;
    Eigen::MatrixXd Jr(r0.size(), 2 * u);
    for (int j = 0; j < 2 * u; ++j) {
      State p = s;
      const double h = 1e-7;
      if (j < u)
        p.q(idx[static_cast<std::size_t>(j)]) += h;
      else
        p.v(idx[static_cast<std::size_t>(j - u)]) += h;
      Jr.col(j) = (residual(p) - r0) / h;
    }
    const Eigen::VectorXd step = pinv_solve_matrix(Jr) * r0;
    for (int j = 0; j < u; ++j) {
      s.q(idx[static_cast<std::size_t>(j)]) -= step(j);
      s.v(idx[static_cast<std::size_t>(j)]) -= step(u + j);
    }
  }
  const Eigen::VectorXd r = residual(s);
  return r.norm() < 1e-9 * (1 + s.q.norm() + s.v.norm());
}

State Model::base_state() const {
  State s;
  s.q = Eigen::VectorXd::Zero(ndof_);
  s.v = Eigen::VectorXd::Zero(ndof_);
  for (const auto& b : bodies_) {
    s.q.segment(b.q0, dims_) = b.cm0;
    if (b.kind == Body::line) {
      auto it = base_rate_.find("dot(" + b.coord + ")");
      if (it != base_rate_.end()) s.v.segment(b.q0, dims_) = b.b * it->second;
    }
    if (!b.angle.empty()) {
      s.q(b.r0) = b.angle0;
      auto it = base_rate_.find("dot(" + b.angle + ")");
      if (it != base_rate_.end()) s.v(b.r0) = it->second;
    }
  }
  place_turning(s);
  project(s, false);
  return s;
}

void Model::place_turning(State& s) const {
  // each turning body's center (and its rate) where it is written in the coordinates
  std::vector<D1> q(static_cast<std::size_t>(ndof_));
  for (int i = 0; i < ndof_; ++i) q[static_cast<std::size_t>(i)] = D1(s.q(i), s.v(i));
  const auto vars = variables(q, Eigen::VectorXd(), D1(s.t, 1.0));
  for (const auto& b : bodies_) {
    if (b.kind != Body::turning) continue;
    for (int i = 0; i < dims_; ++i) {
      const D1 c = b.cm_expr[static_cast<std::size_t>(i)].eval(vars);
      s.q(b.q0 + i) = c.a;
      s.v(b.q0 + i) = c.b;
    }
  }
}

std::optional<State> Model::random_state(std::mt19937_64& rng, double spread) const {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  State s = base_state();
  // (a value given in the parameters stays: the draws are made all the same, so that the
  // other values drawn do not depend on it)
  auto kept = [&](const std::string& name) { return pinned_.count(name) != 0; };
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    const double dq = spread * u(rng), dv = u(rng);
    if (!kept(b.coord)) s.q.segment(b.q0, dims_) += b.b * dq;
    if (!kept("dot(" + b.coord + ")")) s.v.segment(b.q0, dims_) = b.b * dv;
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    const double dq = spread * u(rng), dv = u(rng);
    if (!kept(b.angle)) s.q(b.r0) += dq;
    if (!kept("dot(" + b.angle + ")")) s.v(b.r0) = dv;
  }
  if (uses_time_) s.t = 0.5 * (1 + u(rng));
  place_turning(s);
  project(s, false);
  // (the projection may land on the mirror image of a straight strand, two blocks that
  // changed places: no state of the mechanism described)
  if (!strands_keep_direction(s, base_state())) return std::nullopt;
  if (has_massless_ && !settle_massless(s)) return std::nullopt;
  // the state must keep every constraint
  for (const auto& c : cons_) {
    const Derivs dv = cons_derivs(c, s);
    if (std::abs(dv.value - c.constant) > 1e-9 * (1 + std::abs(c.constant))) return std::nullopt;
    if (std::abs(dv.grad.dot(s.v) + dv.dt) > 1e-9 * (1 + s.v.norm())) return std::nullopt;
  }
  // nor may the projection have moved a value given in the parameters
  if (!pinned_.empty()) {
    const auto vals = values_at(s);
    for (const auto& [name, v] : pinned_) {
      auto it = vals.find(name);
      if (it != vals.end() && std::abs(it->second - v) > 1e-9 * (1 + std::abs(v))) return std::nullopt;
    }
  }
  return s;
}

std::optional<State> Model::state_from(const std::map<std::string, double>& coords,
                                       const std::map<std::string, double>& rates, double t) const {
  State s = base_state();
  s.t = t;
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    auto c = coords.find(b.coord);
    if (c != coords.end()) s.q.segment(b.q0, dims_) = b.a + b.b * c->second;
    auto r = rates.find("dot(" + b.coord + ")");
    s.v.segment(b.q0, dims_) = b.b * (r != rates.end() ? r->second : 0.0);
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    auto c = coords.find(b.angle);
    if (c != coords.end()) s.q(b.r0) = c->second;
    auto r = rates.find("dot(" + b.angle + ")");
    s.v(b.r0) = r != rates.end() ? r->second : 0.0;
  }
  place_turning(s);
  // project moving only the bodies whose values were not given
  std::vector<bool> fq(static_cast<std::size_t>(ndof_), false), fv(static_cast<std::size_t>(ndof_), false);
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    for (int i = 0; i < dims_; ++i) {
      // only along the body's line: across it the guides hold it anyway
      if (coords.count(b.coord)) fq[static_cast<std::size_t>(b.q0 + i)] = b.b(i) != 0;
      if (rates.count("dot(" + b.coord + ")")) fv[static_cast<std::size_t>(b.q0 + i)] = b.b(i) != 0;
    }
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    if (coords.count(b.angle)) fq[static_cast<std::size_t>(b.r0)] = true;
    if (rates.count("dot(" + b.angle + ")")) fv[static_cast<std::size_t>(b.r0)] = true;
  }
  project(s, false, &fq, &fv);
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    const double bb = b.b.squaredNorm();
    if (coords.count(b.coord)) {
      const double got = b.b.dot(s.q.segment(b.q0, dims_) - b.a) / bb;
      if (std::abs(got - coords.at(b.coord)) > 1e-9 * (1 + std::abs(coords.at(b.coord)))) return std::nullopt;
    }
    if (rates.count("dot(" + b.coord + ")")) {
      const double got = b.b.dot(s.v.segment(b.q0, dims_)) / bb;
      if (std::abs(got - rates.at("dot(" + b.coord + ")")) > 1e-9 * (1 + std::abs(got))) return std::nullopt;
    }
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    if (coords.count(b.angle) && std::abs(s.q(b.r0) - coords.at(b.angle)) > 1e-9 * (1 + std::abs(coords.at(b.angle))))
      return std::nullopt;
    if (rates.count("dot(" + b.angle + ")") &&
        std::abs(s.v(b.r0) - rates.at("dot(" + b.angle + ")")) > 1e-9 * (1 + std::abs(s.v(b.r0))))
      return std::nullopt;
  }
  if (has_massless_ && !settle_massless(s)) return std::nullopt;
  return s;
}

std::vector<Eigen::VectorXd> Model::strand_vectors(const State& s) const {
  std::vector<Eigen::VectorXd> out;
  const std::vector<double> q(s.q.data(), s.q.data() + s.q.size());
  const auto vars = variables(q, Eigen::VectorXd(), s.t);
  auto add = [&](const std::vector<PointRef>& pts) {
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const auto a = position(pts[k], q, vars, s.t), b = position(pts[k - 1], q, vars, s.t);
      Eigen::VectorXd v(dims_);
      for (int i = 0; i < dims_; ++i) v(i) = a[static_cast<std::size_t>(i)] - b[static_cast<std::size_t>(i)];
      out.push_back(v);
    }
  };
  for (const auto& c : cons_)
    if (c.kind == Constraint::path) add(c.points);
  for (const auto& e : elements_) add(e.points);
  return out;
}

bool same_directions(const std::vector<Eigen::VectorXd>& now, const std::vector<Eigen::VectorXd>& then) {
  // A strand that keeps its direction and now points the other way went through zero length
  // (a strand that turns may point anywhere).
  for (std::size_t k = 0; k < now.size() && k < then.size(); ++k) {
    const double dot = now[k].dot(then[k]), norms = now[k].norm() * then[k].norm();
    if (norms == 0) continue;
    if (dot < 0 && std::abs(std::abs(dot) - norms) < 1e-9 * norms) return false;
  }
  return true;
}

bool Model::strands_keep_direction(const State& s, const State& ref) const {
  return same_directions(strand_vectors(s), strand_vectors(ref));
}

std::map<std::string, double> Model::coordinates_at(const State& s) const {
  std::map<std::string, double> out;
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    out[b.coord] = b.b.dot(s.q.segment(b.q0, dims_) - b.a) / b.b.squaredNorm();
  }
  for (const auto& b : bodies_)
    if (!b.angle.empty()) out[b.angle] = s.q(b.r0);
  return out;
}

std::map<std::string, double> Model::values_at(const State& s) const {
  std::map<std::string, double> out = params_;
  for (const auto& b : bodies_) {
    if (b.kind != Body::line) continue;
    const double bb = b.b.squaredNorm();
    out[b.coord] = b.b.dot(s.q.segment(b.q0, dims_) - b.a) / bb;
    out["dot(" + b.coord + ")"] = b.b.dot(s.v.segment(b.q0, dims_)) / bb;
  }
  for (const auto& b : bodies_) {
    if (b.angle.empty()) continue;
    out[b.angle] = s.q(b.r0);
    out["dot(" + b.angle + ")"] = s.v(b.r0);
  }
  out["t"] = s.t;
  for (const auto& [name, v] : given_accel_) out[name] = v;
  return out;
}

}  // namespace crosscheck

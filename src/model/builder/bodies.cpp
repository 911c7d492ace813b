// The bodies (each one a point too) with their coordinates, accelerations and masses; the
// named points; the layout that tells strand directions.
#include "model/builder/stages.hpp"

#include <algorithm>
#include <functional>

#include "expr/normal_form.hpp"
#include "expr/print.hpp"

namespace tackle::build {

using namespace GiNaC;

namespace {

// `draw: {shape, size}`: the shape the free body diagram gives a body, its sizes lengths that
// are positive with the given values.
// The lengths of a `draw:`'s size, each positive with the given values (`numbers`: those
// values); none where one is not.
std::optional<std::vector<ex>> drawn_lengths(BuildContext& ctx, const VectorDesc& items, const std::string& what,
                                             std::vector<double>& numbers) {
  std::vector<ex> size;
  const exmap values = ctx.table->values();
  for (const auto& t : items.items) {
    auto v = ctx.parse(t, *ctx.table, what);
    if (!v) return std::nullopt;
    ctx.check_dimension(*v, Dimension::length(), t.at, what);
    const ex x = v->subs(values).evalf();
    if (!is_a<numeric>(x) || !ex_to<numeric>(x).is_real() || ex_to<numeric>(x) <= 0) {
      ctx.diags.error(t.at, what + ": size '" + t.text + "' is not a positive length with the given values");
      return std::nullopt;
    }
    size.push_back(*v);
    numbers.push_back(ex_to<numeric>(x).to_double());
  }
  return size;
}

void draw_override(BuildContext& ctx, const BodyDesc& b, Body& body) {
  const std::string what = "'draw' of body '" + body.name + "'";
  const std::string& shape = b.draw_shape->text;
  const std::size_t n = shape == "rectangle" || shape == "wedge" || shape == "spool" ? 2 : shape == "circle" ? 1 : 0;
  if (n == 0) {
    ctx.diags.error(b.draw_shape->at, what + " has shape '" + shape + "' (expected rectangle, circle, spool or wedge)");
    return;
  }
  if (b.draw_face && (shape != "wedge" || (b.draw_face->text != "left" && b.draw_face->text != "right"))) {
    ctx.diags.error(b.draw_face->at, what + " has face '" + b.draw_face->text + "' (expected " +
                                         (shape == "wedge" ? "left or right" : "no 'face': only a wedge has one") +
                                         ")");
    return;
  }
  const std::string sizes = shape == "wedge"   ? "[base, height]"
                            : shape == "spool" ? "[diameter, hub diameter]"
                            : n == 2           ? "[width, height]"
                                               : "[diameter]";
  if (!b.draw_size) {
    ctx.diags.error(b.draw_shape->at, what + " has no 'size' (expected " + sizes + ")");
    return;
  }
  if (b.draw_size->items.size() != n) {
    ctx.diags.error(b.draw_size->at, what + ": 'size' has " + std::to_string(b.draw_size->items.size()) +
                                         " entries (expected " + std::to_string(n) + ": " + sizes + ")");
    return;
  }
  std::vector<double> numbers;
  auto size = drawn_lengths(ctx, *b.draw_size, what, numbers);
  if (!size) return;
  if (shape == "spool" && numbers[1] >= numbers[0]) {
    const auto& items = b.draw_size->items;
    ctx.diags.error(items[1].at, what + ": the hub's diameter '" + items[1].text + "' is not less than the spool's '" +
                                     items[0].text + "' (expected a hub inside the spool)");
    return;
  }
  body.drawn_shape = shape;
  body.drawn_size = std::move(*size);
  body.drawn_face_left = b.draw_face && b.draw_face->text == "left";
}

// The moment of inertia about the center of mass (about the plane's normal): given, or
// from a shape and the mass, by the book's formulas. Without either a body is a point.
void inertia(BuildContext& ctx, const BodyDesc& b, Body& body) {
  const std::string what = "body '" + body.name + "'";
  if (!b.inertia && !b.shape_kind) return;
  const Location at = b.inertia ? b.inertia->at : b.shape_kind->at;
  if (ctx.m.dims() != 2) {
    ctx.diags.error(at, what + ": a moment of inertia is for 2-D problems (a body turns in the plane)");
    return;
  }
  if (b.inertia && b.shape_kind) {
    ctx.diags.error(at, what + " has both 'inertia' and 'shape' (the shape gives the moment of inertia; give one)");
    return;
  }
  const Dimension mass_length_squared = Dimension::mass() * Dimension::length() * Dimension::length();
  if (b.inertia) {
    if (auto I = ctx.parse(*b.inertia, *ctx.table, "'inertia' of " + what)) {
      ctx.check_dimension(*I, mass_length_squared, b.inertia->at, "'inertia' of " + what);
      body.inertia = *I;
    }
    return;
  }
  // shape: kind and its sizes, I = k m (sizes)
  struct Shape {
    const char* kind;
    std::size_t sizes;
    std::function<ex(const std::vector<ex>&)> inertia;  // per unit mass
  };
  static const std::vector<Shape> shapes = {
      {"point", 0, [](const std::vector<ex>&) { return ex(0); }},
      {"disk", 1, [](const std::vector<ex>& r) { return pow(r[0], 2) / 2; }},
      {"ring", 1, [](const std::vector<ex>& r) { return pow(r[0], 2); }},
      {"rod", 1, [](const std::vector<ex>& l) { return pow(l[0], 2) / 12; }},
      {"sphere", 1, [](const std::vector<ex>& r) { return 2 * pow(r[0], 2) / 5; }},
      {"box", 2, [](const std::vector<ex>& s) { return (pow(s[0], 2) + pow(s[1], 2)) / 12; }},
  };
  const auto shape =
      std::find_if(shapes.begin(), shapes.end(), [&](const Shape& x) { return b.shape_kind->text == x.kind; });
  if (shape == shapes.end()) {
    ctx.diags.error(b.shape_kind->at, "unknown shape '" + b.shape_kind->text + "' of " + what +
                                          " (expected one of: point, disk, ring, rod, sphere, box)");
    return;
  }
  const std::size_t given = b.shape_size ? b.shape_size->items.size() : 0;
  if (given != shape->sizes) {
    ctx.diags.error(b.shape_kind->at, "shape '" + b.shape_kind->text + "' of " + what + " has " +
                                          std::to_string(given) + (given == 1 ? " size" : " sizes") + " (expected " +
                                          std::to_string(shape->sizes) + (shape->sizes == 1 ? " length" : " lengths") +
                                          ")");
    return;
  }
  std::vector<ex> sizes;
  for (std::size_t i = 0; i < given; ++i) {
    auto v = ctx.parse(b.shape_size->items[i], *ctx.table, "size of the shape of " + what);
    if (!v) return;
    if (!is_a<numeric>(*v))
      ctx.check_dimension(*v, Dimension::length(), b.shape_size->items[i].at, "size of the shape of " + what);
    sizes.push_back(*v);
  }
  body.inertia = body.mass * shape->inertia(sizes);
  // Drawn as it is (unless 'draw' says otherwise): a disk, ring or sphere as a circle, a rod
  // as a bar along the body, a box as a rectangle; both turn with the body.
  if (body.drawn_shape.empty()) {
    const std::string kind = shape->kind;
    if (kind == "disk" || kind == "ring" || kind == "sphere") {
      body.drawn_shape = "circle";
      body.drawn_size = {2 * sizes[0]};
    } else if (kind == "rod") {
      body.drawn_shape = "rod";
      body.drawn_size = {sizes[0]};
    } else if (kind == "box") {
      body.drawn_shape = "rectangle";
      body.drawn_size = sizes;
    }
  }
}

// The steps of reading the bodies and what they share: the number of axes and the unknown
// accelerations (they come first among the unknowns).
struct BodiesReader {
  BuildContext& ctx;
  const bool one_d;
  std::vector<ex> accelerations;

  explicit BodiesReader(BuildContext& context) : ctx(context), one_d(context.m.dims() == 1) {}

  // The translation coordinate `position` names, with its rate and acceleration, a length,
  // of the body about to be added.
  Coordinate position_coordinate(const Text& position) {
    const std::string q = position.text;
    Coordinate c;
    c.q = ctx.table->add(q, std::nullopt, SymbolRole::coordinate, Dimension::length(), false, position.at).sym;
    c.rate =
        ctx.table->add("dot(" + q + ")", std::nullopt, SymbolRole::rate, Dimension::velocity(), false, position.at).sym;
    c.accel = ctx.table
                  ->add("ddot(" + q + ")", std::nullopt, SymbolRole::acceleration, Dimension::acceleration(), false,
                        position.at)
                  .sym;
    c.body = static_cast<int>(ctx.m.bodies.size());
    c.kind = Coordinate::Kind::translation;
    return c;
  }

  // In 1-D: 'position' names the coordinate, which is the center of mass; the keys for 2-D and
  // 3-D are refused.
  void read_1d(const BodyDesc& b, Body& body) {
    if (!b.position)
      ctx.diags.error(b.at, "body '" + body.name + "' has no 'position' (expected the name of its coordinate, e.g. x_" +
                                body.name + ")");
    for (const auto* v : {&b.center_of_mass, &b.acceleration})
      if (*v)
        ctx.diags.error((*v)->at, "body '" + body.name +
                                      "': 'center_of_mass' and 'acceleration' are for 2-D and 3-D problems (in 1-D, "
                                      "'position' names the coordinate)");
    if (b.accel_along)
      ctx.diags.error(b.accel_along->at, "body '" + body.name + "': 'acceleration' is for 2-D and 3-D problems");
    if (b.angle)
      ctx.diags.error(b.angle->at, "body '" + body.name + "': 'angle' is for 2-D problems (a body turns in the plane)");
    if (b.position && ctx.claim(*b.position, "coordinate")) {
      const Coordinate q = position_coordinate(*b.position);
      body.cm = {q.q, 0, 0};
      body.has_cm = true;
      accelerations.push_back(q.accel);
      ctx.m.coordinates.push_back(q);
    }
  }

  // In 2-D and 3-D, a coordinate: the center of mass is written in it, and the acceleration
  // follows (twice differentiated in time).
  std::optional<Coordinate> read_position(const BodyDesc& b, const Body& body) {
    if (!b.position) return std::nullopt;
    if (!b.center_of_mass)
      ctx.diags.error(b.position->at,
                      "body '" + body.name +
                          "' has a 'position' but no 'center_of_mass' (expected its center of mass written in " +
                          b.position->text + ")");
    if (b.acceleration || b.accel_along)
      ctx.diags.error(
          b.position->at,
          "body '" + body.name +
              "' has both 'position' and 'acceleration' (its acceleration follows from its position; give one)");
    if (!ctx.claim(*b.position, "coordinate")) return std::nullopt;
    return position_coordinate(*b.position);
  }

  // An angle: the body turns in the plane (its center of mass may be written in the angle
  // too: a pendulum's bob, a bar pinned at one end). Its coordinate into `own`.
  void read_angle(const BodyDesc& b, Body& body, std::vector<Coordinate>& own) {
    if (!b.angle) return;
    if (ctx.m.dims() != 2) {
      ctx.diags.error(b.angle->at, "body '" + body.name + "': 'angle' is for 2-D problems (a body turns in the plane)");
    } else if (b.acceleration || b.accel_along) {
      ctx.diags.error(
          b.angle->at,
          "body '" + body.name +
              "' has both 'angle' and 'acceleration' (its acceleration follows from its coordinates; give one)");
    } else if (ctx.claim(*b.angle, "coordinate")) {
      const std::string q = b.angle->text;
      const Dimension per_second{{0, 0, -1}}, per_second_squared{{0, 0, -2}};
      body.angle = ctx.table->add(q, std::nullopt, SymbolRole::coordinate, Dimension::none(), false, b.angle->at).sym;
      const ex rate =
          ctx.table->add("dot(" + q + ")", std::nullopt, SymbolRole::rate, per_second, false, b.angle->at).sym;
      const ex accel =
          ctx.table
              ->add("ddot(" + q + ")", std::nullopt, SymbolRole::acceleration, per_second_squared, false, b.angle->at)
              .sym;
      own.push_back({body.angle, rate, accel, static_cast<int>(ctx.m.bodies.size()), Coordinate::Kind::rotation});
    }
  }

  // The center of mass, needed with an angle; written in the body's coordinate when it has one.
  void read_center_of_mass(const BodyDesc& b, Body& body, const std::vector<Coordinate>& own) {
    if (b.center_of_mass) {
      if (auto cm = ctx.vector(*b.center_of_mass, *ctx.table, "'center_of_mass' of body '" + body.name + "'",
                               Dimension::length())) {
        body.cm = *cm;
        body.has_cm = true;
      }
    } else if (!own.empty()) {
      ctx.diags.error(b.angle->at, "body '" + body.name +
                                       "' has an 'angle' but no 'center_of_mass' (expected its center of mass, "
                                       "fixed or written in its coordinates)");
    }
  }

  // A center of mass that does not depend on the body's coordinate is reported.
  void check_written_in_position(const BodyDesc& b, const Body& body, const std::optional<Coordinate>& position) {
    if (position && body.has_cm) {
      bool depends = false;
      for (const auto& c : body.cm) depends = depends || c.has(position->q);
      if (!depends)
        ctx.diags.error(b.center_of_mass->at, "'center_of_mass' of body '" + body.name +
                                                  "' does not depend on its coordinate '" + b.position->text +
                                                  "' (expected it written in " + b.position->text + ")");
    }
  }

  // The acceleration given instead of a position: a vector, or a direction of motion `along`
  // with an unknown magnitude.
  void read_acceleration(const BodyDesc& b, Body& body) {
    // (a position with an acceleration too is reported above; the position wins)
    if (b.acceleration && !b.position) {
      if (auto a = ctx.vector(*b.acceleration, *ctx.table, "'acceleration' of body '" + body.name + "'",
                              Dimension::acceleration()))
        body.given_acceleration = *a;
    } else if (b.accel_along && !b.position) {
      auto dir = ctx.vector(*b.accel_along, *ctx.table, "'along' of the acceleration of body '" + body.name + "'",
                            std::nullopt);
      const Text name = b.accel_name ? *b.accel_name : Text{"a_" + body.name, b.accel_along->at};
      if (dir && is_zero_vec(*dir)) {
        ctx.diags.error(b.accel_along->at, "the direction of motion of body '" + body.name + "' is a zero vector");
      } else if (dir && ctx.claim(name, "acceleration")) {
        const SymbolInfo& a =
            ctx.table->add(name.text, std::nullopt, SymbolRole::unknown, Dimension::acceleration(), false, name.at);
        body.along_unknown = a.sym;
        body.given_acceleration = a.sym * unit(*dir);
        accelerations.push_back(a.sym);
      }
    }
  }

  // In 2-D and 3-D: the position and angle, the center of mass, or the acceleration as
  // given; the body's coordinates listed (its acceleration follows from them:
  // kinematics::acceleration).
  void read_2d(const BodyDesc& b, Body& body) {
    const std::optional<Coordinate> position = read_position(b, body);
    std::vector<Coordinate> own;  // this body's coordinates
    read_angle(b, body, own);
    read_center_of_mass(b, body, own);
    if (position) own.insert(own.begin(), *position);
    check_written_in_position(b, body, position);
    if (!own.empty() && body.has_cm)
      for (const auto& c : own) accelerations.push_back(c.accel);
    ctx.m.coordinates.insert(ctx.m.coordinates.end(), own.begin(), own.end());
    read_acceleration(b, body);
  }

  // The body into the model, a point too (at its center of mass).
  void add(Body& body) {
    ctx.body_index[body.name] = static_cast<int>(ctx.m.bodies.size());
    ctx.point_index[body.name] = static_cast<int>(ctx.m.points.size());
    Point self;
    self.name = body.name;
    self.position = body.cm;
    self.body = static_cast<int>(ctx.m.bodies.size());
    self.at = body.at;
    ctx.m.points.push_back(self);
    ctx.m.bodies.push_back(body);
  }

  // A body as described, when its name is free.
  void read(const BodyDesc& b) {
    if (!ctx.claim_place(b.name, "body")) return;
    Body body;
    body.name = b.name.text;
    body.at = b.name.at;
    if (one_d)
      read_1d(b, body);
    else
      read_2d(b, body);
    add(body);
  }

  // A body's mass: a mass, positive at the parameters' values, or 0 for a massless body; a
  // body with mass needs a center of mass in 2-D and 3-D.
  void read_mass(const BodyDesc& b, Body& body) {
    if (auto mass = ctx.parse(*b.mass, *ctx.table, "mass of body '" + body.name + "'")) {
      body.mass = *mass;
      body.has_mass = true;
      if (!mass->is_zero()) {
        ctx.check_dimension(*mass, Dimension::mass(), b.mass->at, "mass of body '" + body.name + "'");
        // A mass that is zero (or negative) at the parameters' values: its balance would be
        // divided by zero. A massless body is written 'mass: 0', and its balance fixes it.
        const ex exact = mass->subs(ctx.table->values());
        const ex at = evalf(exact);
        if (is_a<numeric>(at) && ex_to<numeric>(at).is_real() && !ex_to<numeric>(at).is_positive())
          ctx.diags.error(
              b.mass->at,
              "mass of body '" + body.name + "' is " + to_text(*mass) + ", which is " + to_text(exact) +
                  " at the parameters' values (expected a positive mass; a body without mass is written 'mass: 0')");
      }
      if (!one_d && !mass->is_zero() && !body.has_cm)
        ctx.diags.error(b.at, "body '" + body.name +
                                  "' has no 'center_of_mass' (needed for its weight and its angular momentum balance)");
    }
  }

  // Masses after every coordinate exists (a mass may not depend on them, but the message
  // for a misused name is clearer this way); the drawn shape and the moment of inertia.
  void masses() {
    for (std::size_t i = 0; i < ctx.d.bodies.size(); ++i) {
      const auto& b = ctx.d.bodies[i];
      auto it = ctx.body_index.find(b.name.text);
      if (it == ctx.body_index.end()) continue;
      Body& body = ctx.m.bodies[it->second];
      if (b.draw_shape) draw_override(ctx, b, body);
      if (!b.mass) continue;
      read_mass(b, body);
      inertia(ctx, b, body);
    }
  }
};

}  // namespace

void bodies(BuildContext& ctx) {
  BodiesReader r(ctx);
  for (const auto& b : ctx.d.bodies) r.read(b);
  ctx.m.candidates.insert(ctx.m.candidates.begin(), r.accelerations.begin(), r.accelerations.end());
  r.masses();
}

void points(BuildContext& ctx) {
  for (const auto& p : ctx.d.points) {
    if (!ctx.claim_place(p.name, "point")) continue;
    Point pt;
    pt.name = p.name.text;
    pt.at = p.name.at;
    if (p.at) {
      if (auto pos = ctx.vector(*p.at, *ctx.table, "position of point '" + pt.name + "'", Dimension::length())) {
        // Undefined at the given values: reported, and the point is left at the origin so
        // that nothing later evaluates the pole.
        const exmap values = ctx.table->values();
        bool defined = true;
        for (int k = 0; k < 3; ++k)
          if (NormalForm((*pos)[k]).undefined_at(values)) {
            ctx.diags.error(p.at->at, "position of point '" + pt.name + "' is undefined at the given values (" +
                                          to_text((*pos)[k]) + " divides by zero there)");
            defined = false;
          }
        if (defined) pt.position = *pos;
      }
    } else if (p.on) {
      auto it = ctx.body_index.find(p.on->text);
      if (it == ctx.body_index.end()) {
        ctx.unknown_name(*p.on, "body", ctx.body_names());
        continue;
      }
      pt.body = it->second;
      pt.position = ctx.m.bodies[pt.body].cm;
      if (p.offset) {
        if (auto off = ctx.vector(*p.offset, *ctx.table, "offset of point '" + pt.name + "'", Dimension::length())) {
          // In the body's frame: it turns with the body's angle (0: as written), unless it
          // keeps the ground's directions.
          const ex& a = ctx.m.bodies[pt.body].angle;
          pt.offset = *off;
          pt.turns = p.turns;
          if (!p.turns && a.is_zero())
            ctx.diags.error(*p.turns_at, "point '" + pt.name + "' has 'turns: false', but body '" +
                                             ctx.m.bodies[pt.body].name +
                                             "' does not turn (expected a body with an 'angle')");
          if (!a.is_zero() && p.turns)
            *off = Vec{cos(a) * (*off)[0] - sin(a) * (*off)[1], sin(a) * (*off)[0] + cos(a) * (*off)[1], (*off)[2]};
          for (int i = 0; i < 3; ++i) pt.position[i] += (*off)[i];
        }
      }
    }
    ctx.point_index[pt.name] = static_cast<int>(ctx.m.points.size());
    ctx.m.points.push_back(pt);
  }
}

void read_layout(BuildContext& ctx) {
  ctx.layout = ctx.table->values();
  for (const auto& [name, value] : ctx.d.layout) {
    const SymbolInfo* s = ctx.table->find(name.text);
    if (!s || (s->role != SymbolRole::coordinate && s->role != SymbolRole::parameter)) {
      std::vector<std::string> known;
      for (const auto& sym : ctx.table->all())
        if (sym->role == SymbolRole::coordinate || sym->role == SymbolRole::parameter) known.push_back(sym->name);
      std::string msg = "'layout' names '" + name.text + "', which is not a coordinate or a parameter";
      if (auto near = nearest(name.text, known); !near.empty()) msg += " (did you mean '" + near + "'?)";
      ctx.diags.error(name.at, msg);
      continue;
    }
    auto v = ctx.number_in_parameters(value, "layout value of '" + name.text + "'", s->dimension);
    if (v && is_a<numeric>(evalf(*v))) ctx.layout[s->sym] = *v;
  }
  // A coordinate given with a value is at that value in the layout, unless the layout says
  // otherwise (its problems are reported with the other given quantities).
  for (const auto& g : ctx.d.given) {
    const SymbolInfo* s = g.value ? ctx.table->find(g.name.text) : nullptr;
    if (!s || s->role != SymbolRole::coordinate || ctx.layout.count(s->sym)) continue;
    Diagnostics later;
    if (auto v = given_value(g, *s, *ctx.table, later)) {
      const ex at = substituted(*v, ctx.table->values());  // v/R: a number once R has its value
      if (is_a<numeric>(evalf(at))) ctx.layout[s->sym] = at;
    }
  }
  // The instant is t = 0 for telling directions (a support that moves with time).
  if (is_a<symbol>(ctx.m.time)) ctx.layout[ctx.m.time] = 0;
  ctx.m.layout = ctx.layout;
}

}  // namespace tackle::build

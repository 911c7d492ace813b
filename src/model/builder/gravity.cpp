// Gravity: its vector (given, or a magnitude and a tilt of the axes) and each massive body's
// weight.
#include "model/builder/stages.hpp"

namespace tackle::build {

using namespace GiNaC;

void gravity(BuildContext& ctx) {
  std::optional<Vec> g;
  if (ctx.d.gravity) {
    g = ctx.vector(*ctx.d.gravity, *ctx.table, "'gravity'", Dimension::acceleration());
  } else if (ctx.d.gravity_magnitude && ctx.d.gravity_tilt) {
    // Axes tilted by `tilt`: gravity is -g sin(tilt) along the first axis (up the slope) and
    // -g cos(tilt) along the second (across it, upwards).
    auto magnitude = ctx.parse(*ctx.d.gravity_magnitude, *ctx.table, "'magnitude' of 'gravity'");
    auto tilt = ctx.parse(*ctx.d.gravity_tilt, *ctx.table, "'tilt' of 'gravity'");
    if (magnitude && !is_a<numeric>(*magnitude))
      ctx.check_dimension(*magnitude, Dimension::acceleration(), ctx.d.gravity_magnitude->at,
                          "'magnitude' of 'gravity'");
    if (tilt && !is_a<numeric>(*tilt))
      ctx.check_dimension(*tilt, Dimension::none(), ctx.d.gravity_tilt->at, "'tilt' of 'gravity'");
    if (magnitude && tilt)
      g = Vec{-*magnitude * sin(*tilt), ctx.m.dims() > 1 ? ex(-*magnitude * cos(*tilt)) : ex(0), 0};
  }
  if (!g) return;
  ctx.m.gravity = *g;
  for (std::size_t i = 0; i < ctx.m.bodies.size(); ++i) {
    const Body& b = ctx.m.bodies[i];
    if (!b.has_mass || b.mass.is_zero()) continue;
    Load weight;
    weight.body = static_cast<int>(i);
    weight.force = b.mass * *g;
    if (b.has_cm) {
      weight.at = b.cm;
      weight.at_name = "the center of mass of " + b.name;
    }
    weight.origin = weight_origin(b.name);
    ctx.m.loads.push_back(weight);
  }
}

}  // namespace tackle::build

#include "media/frames.hpp"

#include <algorithm>
#include <cmath>

#include "tasks/drawn_points.hpp"

namespace media {

render::BodyPoints bodyPointsOf(const sim::Model& model) {
  const tasks::DrawnPoints drawn = tasks::drawnPointsOf(model);
  render::BodyPoints points;
  points.top = drawn.top;
  points.bottom = drawn.bottom;
  points.spacing = drawn.spacing;
  points.radius = drawn.radius;
  points.footprint_half = drawn.footprint_half;
  return points;
}

render::FrameInput frameOf(const sim::Telemetry& t) {
  render::FrameInput f;
  f.position_world = t.x_world;
  f.orientation = t.orientation;
  f.t = t.t;
  f.spin = t.spin;
  return f;
}

render::Framing framingOf(const sim::Telemetry& start, const render::BodyPoints& points) {
  render::Framing framing;
  framing.center = start.x_world.cast<float>();
  framing.radius = 1.25f * render::reachOf(points);
  return framing;
}

}  // namespace media

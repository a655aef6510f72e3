#include "media/frames.hpp"

#include <algorithm>
#include <cmath>

#include "sim/rollout.hpp"
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

render::Framing framingOfRun(const sim::Model& model, const render::BodyPoints& points,
                             const std::function<bool()>& cancelled,
                             const std::function<void(double)>& reached) {
  sim::Rollout run(model);
  const sim::Telemetry start = run.sampleAt(0);
  const render::Framing near = framingOf(start, points);
  Eigen::Vector2d low = start.x_world.head<2>(), high = low;
  double wander = 0;  // m: the CM's largest distance from where it started, across the floor
  sim::sampleRun(run, 100, [&](const sim::Telemetry& s) {
    if (cancelled && cancelled()) run.requestStop();
    if (reached) reached(s.t);
    low = low.cwiseMin(s.x_world.head<2>());
    high = high.cwiseMax(s.x_world.head<2>());
    wander = std::max(wander, (s.x_world - start.x_world).head<2>().norm());
  });
  const float reach = render::reachOf(points);
  if (wander <= 0.25 * reach) return near;  // the quarter's margin holds it: as before
  render::Framing framing;
  framing.center = Eigen::Vector3f(0.5f * static_cast<float>(low.x() + high.x()),
                                   0.5f * static_cast<float>(low.y() + high.y()),
                                   static_cast<float>(start.x_world.z()));
  framing.radius = 1.1f * reach + 0.5f * static_cast<float>((high - low).norm());
  return framing;
}

}  // namespace media

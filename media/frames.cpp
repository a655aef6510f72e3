#include "media/frames.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sim/rollout.hpp"
#include "sim/tessellate.hpp"
#include "tasks/body_mesh.hpp"
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

rb::Result<render::BodyTriangles> bodyTrianglesOf(const tasks::LoadedScene& loaded,
                                                  render::Surface surface) {
  render::BodyTriangles triangles;
  if (surface != render::Surface::Triangles) return triangles;
  auto mesh = tasks::drawnMesh(loaded);
  if (!mesh) return mesh.error();
  triangles.vertices.reserve(mesh.value().vertices.size());
  for (const Eigen::Vector3d& v : mesh.value().vertices)
    triangles.vertices.push_back(v.cast<float>());
  triangles.faces = std::move(mesh.value().faces);
  return triangles;
}

render::FrameInput frameOf(const sim::Telemetry& t) {
  render::FrameInput f;
  f.position_world = t.x_world;
  f.orientation = t.orientation;
  f.t = t.t;
  f.spin = t.spin;
  return f;
}

render::Framing framingOf(const sim::Telemetry& start, const render::BodyPoints& points,
                          float frame) {
  render::Framing framing;
  framing.center = start.x_world.cast<float>();
  // A body as long as the frame reaches half of it from its middle (its height and its points'
  // radius aside: within 2 % for the shipped bodies), so that a frame of the body's own
  // length draws it as the body's own framing does.
  framing.radius = 1.25f * (frame > 0 ? 0.5f * frame : render::reachOf(points));
  return framing;
}

RunFraming framingOfRun(const sim::Model& model, const render::BodyPoints& points, float frame,
                        const std::function<bool()>& cancelled,
                        const std::function<void(double)>& reached) {
  sim::Rollout run(model);
  const sim::Telemetry start = run.sampleAt(0);
  const render::Framing near = framingOf(start, points, frame);
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
  const float path = 0.5f * static_cast<float>((high - low).norm());
  RunFraming result;
  result.framing = near;
  result.reversals = run.reversals();
  const bool wanders = wander > 0.25 * reach;  // past the quarter's margin
  if (wanders) {
    result.framing.center = Eigen::Vector3f(0.5f * static_cast<float>(low.x() + high.x()),
                                            0.5f * static_cast<float>(low.y() + high.y()),
                                            static_cast<float>(start.x_world.z()));
    if (frame <= 0) result.framing.radius = 1.1f * reach + path;
  }
  if (frame > 0) {
    // The views show 1.1 times the sphere (camera.cpp): the body is whole where its reach about
    // the path's middle (or its start) stays within that.
    const float held = reach + (wanders ? path : static_cast<float>(wander));
    result.body_leaves = held > 1.1f * result.framing.radius;
    result.needs = 2 * held / (1.1f * 1.25f);
  }
  return result;
}

std::optional<std::string> leavesNote(const RunFraming& framing, const render::BodyPoints& points,
                                      render::View view, float frame, double length_unit,
                                      const std::string& named) {
  if (frame <= 0) return std::nullopt;
  // The follow view keeps 1.1 times half the frame about the body's middle (camera.cpp), the
  // body moving with it.
  const float reach = render::reachOf(points);
  const bool follow = view == render::View::Follow;
  const bool leaves = follow ? reach > 1.1f * 0.5f * frame : framing.body_leaves;
  if (!leaves) return std::nullopt;
  const double needs = (follow ? 2 * reach / 1.1f : framing.needs) / length_unit;
  char text[300];
  std::snprintf(text, sizeof text,
                "the body goes out of the picture: %s %.3g is less than this run needs in the %s "
                "view (%.3g, in the file's unit)",
                named.c_str(), frame / length_unit, std::string(rb::nameOf(view)).c_str(), needs);
  return text;
}

}  // namespace media

#include "tasks/player_data.hpp"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "tasks/analysis.hpp"

namespace tasks {
namespace {

// A JSON array of numbers at `digits` significant digits: the page's data, compact (nlohmann
// writes 17 digits, which would triple the size for precision no eye sees).
template <typename F>
void appendArray(std::string& out, const char* name, std::size_t n, int digits, F value) {
  out.append("\"").append(name).append("\":[");
  char text[40];
  for (std::size_t i = 0; i < n; ++i) {
    std::snprintf(text, sizeof text, "%.*g", digits, value(i) + 0.0);
    out.append(i ? "," : "").append(text);
  }
  out.append("],");
}

}  // namespace

std::vector<Pose> thinPoses(const std::vector<Pose>& poses) {
  if (poses.size() < 3) return poses;
  const double span = poses.back().t - poses.front().t;
  const double rate = (poses.size() - 1) / std::max(span, 1e-12);
  const std::size_t k =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(rate / kPlayerRate - 1e-9)));
  std::vector<Pose> out;
  for (std::size_t i = 0; i < poses.size(); i += k) out.push_back(poses[i]);
  if (out.back().t != poses.back().t) out.push_back(poses.back());
  return out;
}

double playerFrame(const scene::Loaded& scene, const sim::Model& model) {
  if (!(scene.video.frame > 0) || !std::isfinite(scene.video.frame)) return 0;
  const double frame = scene.video.frame * model.length_unit;
  return frameFits(frame, *model.body) ? frame : 0;
}

std::string playerScript(const PlayerRun& run) {
  std::string data = "{";
  data += "\"id\":" + nlohmann::json(run.id).dump() + ",";
  data += "\"title\":" + nlohmann::json(run.title).dump() + ",";
  const DrawnPoints& p = run.points;
  // Points: x, y, z of each in turn, µm precision.
  appendArray(data, "top", 3 * p.top.size(), 6, [&](std::size_t i) { return p.top[i / 3][i % 3]; });
  appendArray(data, "bottom", 3 * p.bottom.size(), 6,
              [&](std::size_t i) { return p.bottom[i / 3][i % 3]; });
  char text[160];
  std::snprintf(text, sizeof text, "\"radius\":%.6g,\"reach\":%.6g,\"frame\":%.6g,", p.radius,
                reachOf(p), run.frame);
  data += text;
  const auto& q = run.poses;
  // Times to the µs over runs up to 1000 s; positions to 0.1 µm; the quaternion to 1e-9.
  appendArray(data, "t", q.size(), 9, [&](std::size_t i) { return q[i].t; });
  appendArray(data, "x", q.size(), 7, [&](std::size_t i) { return q[i].x; });
  appendArray(data, "y", q.size(), 7, [&](std::size_t i) { return q[i].y; });
  appendArray(data, "z", q.size(), 7, [&](std::size_t i) { return q[i].z; });
  appendArray(data, "qw", q.size(), 10, [&](std::size_t i) { return q[i].qw; });
  appendArray(data, "qx", q.size(), 10, [&](std::size_t i) { return q[i].qx; });
  appendArray(data, "qy", q.size(), 10, [&](std::size_t i) { return q[i].qy; });
  appendArray(data, "qz", q.size(), 10, [&](std::size_t i) { return q[i].qz; });
  appendArray(data, "spin", q.size(), 7, [&](std::size_t i) { return q[i].spin; });
  appendArray(data, "reversals", run.reversals.size(), 9,
              [&](std::size_t i) { return run.reversals[i]; });
  data.back() = '}';
  return "(window.RATTLEBACK_RUNS = window.RATTLEBACK_RUNS || {})[" +
         nlohmann::json(run.id).dump() + "] = " + data + ";\n";
}

}  // namespace tasks

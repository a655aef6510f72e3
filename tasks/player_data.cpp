#include "tasks/player_data.hpp"

#include <Eigen/Geometry>
#include <algorithm>
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

// The indices kept with every k-th pose, and the last.
std::vector<std::size_t> everyKth(std::size_t n, std::size_t k) {
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < n; i += k) kept.push_back(i);
  if (kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

// Whether the player's replay of the poses `kept` (player.js: applyTime, cubic) follows every
// pose between them within kPlayerAttitudeDeg and kPlayerSpin.
bool replays(const std::vector<Pose>& poses, const std::vector<std::size_t>& kept) {
  auto quaternion = [&](std::size_t i) {
    const Pose& p = poses[i];
    return Eigen::Quaterniond(p.qw, p.qx, p.qy, p.qz).normalized();
  };
  // The spin's slope at kept pose m: central differences of the kept poses (one-sided at ends).
  auto slope = [&](std::size_t m) {
    const std::size_t lo = kept[m == 0 ? 0 : m - 1], hi = kept[std::min(m + 1, kept.size() - 1)];
    return (poses[hi].spin - poses[lo].spin) / (poses[hi].t - poses[lo].t);
  };
  const double attitude = kPlayerAttitudeDeg * M_PI / 180;
  for (std::size_t m = 0; m + 1 < kept.size(); ++m) {
    const std::size_t a = kept[m], b = kept[m + 1];
    const double h = poses[b].t - poses[a].t;
    const Eigen::Quaterniond qa = quaternion(a), qb = quaternion(b);
    const double sa = slope(m) * h, sb = slope(m + 1) * h;
    for (std::size_t i = a + 1; i < b; ++i) {
      const double u = (poses[i].t - poses[a].t) / h, u2 = u * u, u3 = u2 * u;
      if (qa.slerp(u, qb).angularDistance(quaternion(i)) > attitude) return false;
      const double spin = (2 * u3 - 3 * u2 + 1) * poses[a].spin + (u3 - 2 * u2 + u) * sa +
                          (3 * u2 - 2 * u3) * poses[b].spin + (u3 - u2) * sb;
      if (std::abs(spin - poses[i].spin) > kPlayerSpin) return false;
    }
  }
  return true;
}

}  // namespace

std::vector<Pose> thinPoses(const std::vector<Pose>& poses) {
  if (poses.size() < 3) return poses;
  const double span = poses.back().t - poses.front().t;
  const double rate = (poses.size() - 1) / std::max(span, 1e-12);
  std::size_t k =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(rate / kPlayerRate - 1e-9)));
  std::vector<std::size_t> kept = everyKth(poses.size(), k);
  while (k > 1 && !replays(poses, kept)) kept = everyKth(poses.size(), --k);
  std::vector<Pose> out;
  for (std::size_t i : kept) out.push_back(poses[i]);
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

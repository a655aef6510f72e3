#include "tasks/player_data.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "render/views.hpp"
#include "tasks/analysis.hpp"
#include "tasks/simulate.hpp"
#include "util/names.hpp"

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

// The views' cameras, in the renderer's order (render/views.hpp): "views":[{"name":"oblique",
// "projection":"perspective","toward_eye":[…],"up":[…],"elevation_deg":0,…},…].
std::string viewsJson() {
  // A float as the decimal it was written as (0.55f, not 0.550000011920929).
  auto decimal = [](float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", value);
    return std::strtod(text, nullptr);
  };
  auto vector = [&](const std::array<float, 3>& v) {
    return nlohmann::json{decimal(v[0]), decimal(v[1]), decimal(v[2])};
  };
  nlohmann::json views = nlohmann::json::array();
  for (const render::ViewPreset& p : render::kViewPresets)
    views.push_back({{"name", rb::nameOf(p.view)},
                     {"projection", rb::nameOf(p.projection)},
                     {"toward_eye", vector(p.toward_eye)},
                     {"up", vector(p.up)},
                     {"elevation_deg", decimal(p.elevation_deg)},
                     {"fov_deg", decimal(p.fov_deg)},
                     {"margin", decimal(p.margin)},
                     {"eye_r", decimal(p.eye_r)},
                     {"near_r", decimal(p.near_r)},
                     {"far_r", decimal(p.far_r)}});
  return "\"views\":" + views.dump() + ",";
}

}  // namespace

std::vector<Pose> posesOf(const std::vector<sim::Telemetry>& samples) {
  std::vector<Pose> poses;
  poses.reserve(samples.size());
  for (const sim::Telemetry& s : samples) {
    const Eigen::Quaterniond q = attitude(s);
    poses.push_back(
        {s.t, s.x_world.x(), s.x_world.y(), s.x_world.z(), q.w(), q.x(), q.y(), q.z(), s.spin});
  }
  return poses;
}

PlayerRun playerRunOf(const std::string& id, const sim::Model& model, double frame,
                      std::vector<Pose> poses, std::vector<double> reversals) {
  PlayerRun run;
  run.id = id;
  run.title = id;
  run.points = drawnPointsOf(model);
  run.frame = frame;
  run.poses = thinPoses(poses);
  run.reversals = std::move(reversals);
  return run;
}

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
  data += viewsJson();
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

#include "tasks/player_data.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "sim/analysis.hpp"
#include "sim/integrator.hpp"
#include "tasks/analysis.hpp"
#include "tasks/body_mesh.hpp"
#include "tasks/run_json.hpp"
#include "tasks/simulate.hpp"
#include "util/names.hpp"
#include "util/picture.hpp"

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

// A run's series (t, x, y, z, qw, qx, qy, qz, spin) and its reversals: "name":[…], each.
void appendPoses(std::string& data, const std::vector<Pose>& q,
                 const std::vector<double>& reversals) {
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
  appendArray(data, "reversals", reversals.size(), 9, [&](std::size_t i) { return reversals[i]; });
}

// A body drawn as triangles: "vertices":[x, y, z, …] at the points' µm precision, each
// once, and "faces":[i, j, k, …], three vertex indices each (a third of what each face's corners
// written out would take).
void appendTriangles(std::string& data, const sim::TriangleMesh& mesh) {
  const auto& v = mesh.vertices;
  const auto& f = mesh.faces;
  appendArray(data, "vertices", 3 * v.size(), 6, [&](std::size_t i) { return v[i / 3][i % 3]; });
  // Indices print whole at %.9g up to 10^9 (kPlayerMostFaces keeps them far below).
  appendArray(data, "faces", 3 * f.size(), 9, [&](std::size_t i) { return f[i / 3][i % 3]; });
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

// The views' cameras, in the renderer's order (util/picture.hpp): "views":[{"name":"oblique",
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

Pose poseOf(const sim::Telemetry& s) {
  const Eigen::Quaterniond q = attitude(s);
  return {s.t, s.x_world.x(), s.x_world.y(), s.x_world.z(), q.w(), q.x(), q.y(), q.z(), s.spin};
}

// The model a run ran: its scene's `model` with what a command's options or Python's keywords
// put in over the scene (spin, duration, integrator, step or tolerance: tasks::SceneOption's that
// reach the model), as the run's sidecar records them in `run_model`; none unless the model so
// made is the one the sidecar records (modelJson), whole: another body, or a sidecar of another
// version, is not this run's. (A teacher's `simulate --duration 3` is the run's other way at
// 3 s, not the scene file's 8 s.)
std::optional<sim::Model> modelOfRun(const sim::Model& model, const nlohmann::json& run_model) {
  if (!run_model.is_object()) return std::nullopt;
  auto number = [&](const nlohmann::json& j) -> std::optional<double> {
    if (!j.is_number()) return std::nullopt;
    return j.get<double>();
  };
  const auto duration = number(run_model.value("duration_s", nlohmann::json()));
  const auto spin =
      number(run_model.value("initial", nlohmann::json::object()).value("spin", nlohmann::json()));
  const auto integrator =
      rb::parseName<sim::Integrator>(run_model.value("integrator", std::string()));
  if (!duration || !spin || !integrator) return std::nullopt;
  sim::Model ran = model;
  ran.duration = *duration;
  ran.initial.spin = *spin;
  ran.integrator = *integrator;
  // One of the two, the other 0, as sim/compile.cpp makes a model.
  const auto tolerance = number(run_model.value("tolerance", nlohmann::json()));
  const auto dt = number(run_model.value("dt_s", nlohmann::json()));
  ran.tolerance = sim::isAdaptive(*integrator) ? tolerance.value_or(0) : 0;
  ran.dt = sim::isAdaptive(*integrator) ? 0 : dt.value_or(0);
  if (modelJson(ran) != run_model) return std::nullopt;
  return ran;
}

}  // namespace

std::vector<Pose> posesOf(const std::vector<sim::Telemetry>& samples) {
  std::vector<Pose> poses;
  poses.reserve(samples.size());
  for (const sim::Telemetry& s : samples) poses.push_back(poseOf(s));
  return poses;
}

PlayerSurface playerSurfaceOf(const LoadedScene& loaded) {
  PlayerSurface surface;
  if (rb::parseName<render::Surface>(loaded.scene.video.surface) != render::Surface::Triangles)
    return surface;
  auto mesh = drawnMesh(loaded);
  // A scene that loads has a mesh (bodyMesh fails only on keys that loading checks); were it
  // not so, the points still show the body, and the title says why they are drawn.
  if (!mesh) {
    surface.note = "drawn as points: " + mesh.error().text();
    return surface;
  }
  const std::size_t faces = mesh.value().faces.size();
  if (faces > kPlayerMostFaces) {
    surface.note = "drawn as points: its surface has " + std::to_string(faces) +
                   " triangles, more than the player draws (" + std::to_string(kPlayerMostFaces) +
                   ")";
    return surface;
  }
  surface.triangles = std::move(mesh).value();
  return surface;
}

PlayerRun playerRunOf(const std::string& id, const sim::Model& model, double frame,
                      std::vector<Pose> poses, std::vector<double> reversals,
                      PlayerSurface surface) {
  PlayerRun run;
  run.id = id;
  run.title = surface.note.empty() ? id : id + " (" + surface.note + ")";
  run.points = drawnPointsOf(model);
  run.triangles = std::move(surface.triangles);
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

std::optional<SpunRun> otherSpinOf(const sim::Model& model, const nlohmann::json& run_model,
                                   double rate) {
  const std::optional<sim::Model> ran = modelOfRun(model, run_model);
  if (!ran) return std::nullopt;
  const double spin = ran->initial.spin;
  if (spin == 0 || !std::isfinite(spin)) return std::nullopt;
  // A body that prefers neither way shows nothing the other way that this run does not.
  if (sim::preferredDirection(*ran, std::abs(spin)) == sim::Direction::None) return std::nullopt;
  sim::Model other = *ran;
  other.initial.spin = -spin;
  SimulateOptions options;
  // The run's own rate, as its CSV was sampled, within kDefaultRate … 2000 a second: thinPoses
  // keeps what the replay needs of 500 a second (a CSV at 20 a second would replay coarsely),
  // and above 2000 keeps the same for far more work and memory (1e7 Hz is allowed).
  options.rate =
      checkRate(rate, ran->duration) ? std::clamp(rate, kDefaultRate, 2000.0) : kDefaultRate;
  // Poses as the samples come (a pose is a fraction of a sample: a long run's samples kept
  // whole would take hundreds of MB).
  std::vector<Pose> poses;
  options.each = [&](const sim::Telemetry& s) { poses.push_back(poseOf(s)); };
  const SimulateResult result = simulate(other, options);
  if (poses.size() < 2) return std::nullopt;
  return SpunRun{-spin, thinPoses(poses), result.summary.reversals};
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
  if (!run.triangles.faces.empty()) appendTriangles(data, run.triangles);
  char text[160];
  std::snprintf(text, sizeof text, "\"radius\":%.6g,\"reach\":%.6g,\"frame\":%.6g,", p.radius,
                reachOf(p), run.frame);
  data += text;
  data += viewsJson();
  appendPoses(data, run.poses, run.reversals);
  if (run.other) {
    std::snprintf(text, sizeof text, "\"spun\":%.9g,\"other\":{\"spun\":%.9g,",
                  -run.other->spun + 0.0, run.other->spun);
    data += text;
    appendPoses(data, run.other->poses, run.other->reversals);
    data.back() = '}';
    data += ',';
  }
  data.back() = '}';
  return "(window.RATTLEBACK_RUNS = window.RATTLEBACK_RUNS || {})[" +
         nlohmann::json(run.id).dump() + "] = " + data + ";\n";
}

}  // namespace tasks

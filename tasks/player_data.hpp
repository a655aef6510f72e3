// The report page's 3D player reads each run from a classic script beside index.html (a page
// opened from disk may not fetch() or import modules), which this writes:
//
//   (window.RATTLEBACK_RUNS = window.RATTLEBACK_RUNS || {})["ID"] = {…};
//
// holding the drawn points (body frame about the CM, m), for a scene whose video.surface is
// triangles also its surface ("vertices": x, y, z each, about the CM, m; "faces": three vertex
// indices each, wound outwards; the player then draws them, not the points), the fixed views'
// framing, the views' cameras (the renderer's own table, util/picture.hpp), and the run's poses: t,
// x, y, z (CM, world, m), qw, qx, qy, qz (body to world, scalar first) and the spin n (rad/s), at
// most kPlayerRate samples per simulated second. A run spun one way may carry the same body spun
// the other way ("spun": the run's initial spin, rad/s; "other": {spun, t, x, …, spin, reversals},
// the same series), which the player offers beside it (otherSpinOf).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "sim/mesh.hpp"
#include "sim/model.hpp"
#include "sim/telemetry.hpp"
#include "tasks/drawn_points.hpp"
#include "tasks/scene_args.hpp"

namespace tasks {

/// The fewest poses per simulated second the player gets (thinPoses gives it more where the
/// run needs them): 14 a period of the default body's pitch (7 Hz).
constexpr double kPlayerRate = 100;
/// How closely the player's replay (slerp of the attitude, a cubic of the spin between poses,
/// player/src/player.js) must follow every sample of the run's telemetry that thinPoses drops:
/// the attitude within 0.1° (half a pixel at the tip of a 20 cm body 560 px long, from above),
/// the spin within 0.005 rad/s (half the read-out's last digit).
constexpr double kPlayerAttitudeDeg = 0.1;
constexpr double kPlayerSpin = 0.005;

struct Pose {
  double t = 0;                           ///< s
  double x = 0, y = 0, z = 0;             ///< CM, world, m
  double qw = 1, qx = 0, qy = 0, qz = 0;  ///< body to world
  double spin = 0;                        ///< n, rad/s
};

/// The same body spun the other way, beside a run (otherSpinOf).
struct SpunRun {
  double spun = 0;                ///< rad/s: its initial spin (model.initial.spin)
  std::vector<Pose> poses;        ///< thinned (thinPoses)
  std::vector<double> reversals;  ///< s
};

/// The most faces the player is given of a body drawn as triangles: 200,000 (the default
/// body's 24,192 make 0.8 MB of data; a scan of millions would make a page of hundreds of MB,
/// and a software-WebGL frame of seconds). Above it the player draws the points, and its title
/// says why.
constexpr std::size_t kPlayerMostFaces = 200000;

/// The body's surface as the player draws it.
struct PlayerSurface {
  /// About the CM, m (tasks::drawnMesh): a scene whose video.surface is triangles, as its
  /// stills and videos draw it; none: the points are drawn.
  sim::TriangleMesh triangles;
  /// Why a triangles scene's body is drawn as points (too many faces), for its title; else
  /// empty.
  std::string note;
};

/// The surface of a scene's body as the player draws it (PlayerSurface).
PlayerSurface playerSurfaceOf(const LoadedScene& loaded);

struct PlayerRun {
  std::string id;     ///< the key in window.RATTLEBACK_RUNS (the scene's stem)
  std::string title;  ///< shown above the player
  DrawnPoints points;
  sim::TriangleMesh triangles;    ///< none: the points are drawn (PlayerSurface)
  std::vector<Pose> poses;        ///< in time order
  std::vector<double> reversals;  ///< s
  /// m: the length of body the views are framed for (the scene's video.frame), as stills and
  /// videos frame it; 0: the body's own.
  double frame = 0;
  /// The body spun the other way, where the player offers both (otherSpinOf; this run's spin
  /// is then -other->spun); none: the player shows this run alone, and its data says no more.
  std::optional<SpunRun> other;
};

/// A scene's video.frame in metres, as the player takes it: 0 where it is not given, or where
/// it is not within 1/10 … 50 times the body's length (which `still` and `render` refuse).
double playerFrame(const scene::Loaded& scene, const sim::Model& model);
/// The same as the manifest lists it for a still or video (OutputEntry::frame_m): none for 0.
inline std::optional<double> listedFrame(const scene::Loaded& scene, const sim::Model& model) {
  const double frame = playerFrame(scene, model);
  return frame > 0 ? std::optional<double>(frame) : std::nullopt;
}

/// Every k-th pose, and the last: the largest k that leaves at least kPlayerRate poses a second
/// and replays every pose dropped within kPlayerAttitudeDeg and kPlayerSpin. (At 100 a second
/// Kane & Levinson's body, whose n swings with its 17 Hz pitch, was replayed 0.8° and 0.5 rad/s
/// off, and read +0.04 rad/s at its reversal: all of its 500 a second are kept.)
std::vector<Pose> thinPoses(const std::vector<Pose>& poses);

/// The poses of a run's samples (tasks::attitude's quaternion).
std::vector<Pose> posesOf(const std::vector<sim::Telemetry>& samples);

/// The player's run, as the report and Python both make it: titled by its id (and the surface's
/// note), the body's drawn points and `surface`'s triangles, `frame` (m; 0: the body's own), the
/// poses thinned (thinPoses), the reversals (s).
PlayerRun playerRunOf(const std::string& id, const sim::Model& model, double frame,
                      std::vector<Pose> poses, std::vector<double> reversals,
                      PlayerSurface surface = {});

/// The body spun the other way, for the player to show beside a run of a scene whose model is
/// `model`: the run's model (`run_model`, its sidecar's "model": the scene's with the spin,
/// duration, integrator and step or tolerance a command's options or Python's keywords gave)
/// with its initial spin negated (as render --both spins it), run here by tasks::simulate at
/// `rate` samples a second (the run's; within 500 … 2000) and thinned. None where the
/// run's model is not the scene's so made (another body; a sidecar of another version), where
/// the run's spin is 0, or where the body prefers neither direction at it
/// (sim::preferredDirection). 10–30 ms for the default scene's 8 s (2 busy cores).
std::optional<SpunRun> otherSpinOf(const sim::Model& model, const nlohmann::json& run_model,
                                   double rate);

/// The script's text, with the views' cameras.
std::string playerScript(const PlayerRun& run);

}  // namespace tasks

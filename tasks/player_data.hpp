// The report page's 3D player reads each run from a classic script beside index.html (a page
// opened from disk may not fetch() or import modules), which this writes:
//
//   (window.RATTLEBACK_RUNS = window.RATTLEBACK_RUNS || {})["ID"] = {…};
//
// holding the drawn points (body frame about the CM, m), the fixed views' framing, and the
// run's poses: t, x, y, z (CM, world, m), qw, qx, qy, qz (body to world, scalar first) and the
// spin n (rad/s), at most kPlayerRate samples per simulated second.
#pragma once

#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "sim/model.hpp"
#include "tasks/drawn_points.hpp"

namespace tasks {

/// Poses per simulated second the player gets: at 100 Hz the body's fastest rocking (the
/// default body's pitch, 7 Hz) has 14 poses a period, and slerp between them is within 2.5 %
/// of its amplitude; an 8 s run's poses take about 80 kB.
constexpr double kPlayerRate = 100;

struct Pose {
  double t = 0;                           ///< s
  double x = 0, y = 0, z = 0;             ///< CM, world, m
  double qw = 1, qx = 0, qy = 0, qz = 0;  ///< body to world
  double spin = 0;                        ///< n, rad/s
};

struct PlayerRun {
  std::string id;     ///< the key in window.RATTLEBACK_RUNS (the scene's stem)
  std::string title;  ///< shown above the player
  DrawnPoints points;
  std::vector<Pose> poses;        ///< in time order
  std::vector<double> reversals;  ///< s
  /// m: the length of body the views are framed for (the scene's video.frame), as stills and
  /// videos frame it; 0: the body's own.
  double frame = 0;
};

/// A scene's video.frame in metres, as the player takes it: 0 where it is not given, or where
/// it is not within 1/10 … 50 times the body's length (which `still` and `render` refuse).
double playerFrame(const scene::Loaded& scene, const sim::Model& model);

/// Every k-th pose so that at most kPlayerRate remain per simulated second, and the last.
std::vector<Pose> thinPoses(const std::vector<Pose>& poses);

/// The script's text.
std::string playerScript(const PlayerRun& run);

}  // namespace tasks

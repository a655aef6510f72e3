// The scene a run was simulated from, loaded again to replay the run in the report's player:
// the scene file its sidecar names, with the values the run put in over it, when that file
// still describes the run.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "sim/model.hpp"
#include "tasks/player_data.hpp"
#include "tasks/report/sidecars.hpp"

namespace tasks::report {

/// The model of a run's scene, or why there is none to replay it on: `why` completes "SCENE …"
/// for the line `report` prints ("has changed since this run was simulated: …"), empty where
/// there is nothing to say (no scene named: the page then has no player, as for a run made from
/// a string).
struct RunModel {
  std::optional<sim::Model> model;
  std::string scene;  ///< the scene file's path, where one was found
  std::string why;
  double frame = 0;  ///< m: the scene's video.frame for the player (playerFrame)
  /// The body as the scene's video.surface draws it (playerSurfaceOf), or as `drawn_surface`
  /// says where that is given (how the scene's videos were drawn: render --surface).
  PlayerSurface surface;
};

/// The model of the scene a telemetry sidecar names (from here, then from `dir`), with the
/// values the run put in over it (scene_values: --set, Python's with_values), when that scene
/// can be read and still describes the run.
RunModel runModelOf(const RunRecord& run, const fs::path& dir,
                    const std::string& drawn_surface = "");

/// Whether the scene file the run names (found as runModelOf finds it) has been edited since
/// the run: its content's fingerprint is not the one simulate wrote. False where either is not
/// known.
bool sceneEditedSince(const RunRecord& run, const fs::path& dir);

}  // namespace tasks::report

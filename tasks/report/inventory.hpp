// The report's inventory of a folder: which files belong to which scene (by the folder's
// manifest, tasks/manifest.hpp, else by their names), which are sweeps, and the rest.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "tasks/report/sidecars.hpp"

namespace tasks::report {

namespace fs = std::filesystem;

/// The suffixes a scene's files have when named as scripts/run.sh names them.
inline constexpr const char* kVideoSuffixes[] = {"-preferred.mp4", "-reversed.mp4", "-ccw.mp4",
                                                 "-cw.mp4",        "-both.mp4",     ".mp4"};
/// First frames of the reversed and preferred videos, used as their posters.
inline constexpr const char* kPosterSuffixes[] = {"-reversed.png", "-preferred.png", "-ccw.png",
                                                  "-cw.png"};
inline constexpr const char* kStillSuffixes[] = {"-oblique.png", "-above.png", "-front.png",
                                                 "-side.png", "-follow.png"};
inline constexpr const char* kPlotSuffixes[] = {"-spin.png", "-energy.png", "-tilt.png",
                                                "-normal.png"};
inline constexpr const char* kDataSuffixes[] = {".csv.json", "-analysis.json", "-analysis.txt",
                                                ".csv"};

/// What the manifest says of a video, where it gives the video's spin.
struct ManifestVideo {
  double spin = 0;  ///< rad/s, as rendered
  /// The video's own run, where the manifest says (manifest.hpp: simulated_s, first_reversal_s):
  /// its command "render".
  std::optional<RunRecord> run;
};

/// The files of one scene (by the name before a known suffix), found in DIR.
struct SceneFiles {
  std::map<std::string, std::string> by_suffix;  ///< suffix → file name
  /// Videos and stills the manifest lists beyond one per slot (a scene rendered at several
  /// sizes, stills at other times): shown too, not dropped.
  std::vector<std::string> more_videos, more_stills;
  /// Telemetry the manifest lists beside the scene's main run (".csv": the scene's own
  /// <scene>.csv, else the first by name), in name order: each listed with what it measured.
  std::vector<std::string> more_runs;
  /// Stills' captions from the manifest (file name → "oblique view, t = 1 s, spun −4 rad/s").
  std::map<std::string, std::string> captions;
  /// The scene each file was made from, as the manifest says (tasks::madeFrom), where it says.
  std::map<std::string, std::string> made_from;
  /// Each video the manifest lists with its spin: file name → what the manifest says of it.
  std::map<std::string, ManifestVideo> manifest_videos;
  bool has(const std::string& suffix) const { return by_suffix.count(suffix) > 0; }
  const std::string& at(const std::string& suffix) const { return by_suffix.at(suffix); }
};

/// A sweep's table, its sidecar and heatmaps.
struct SweepFiles {
  std::string name, csv;
  nlohmann::json meta;  ///< the table's sidecar (sweep's NAME.csv.json)
  std::vector<std::string> images;
  std::vector<std::string> parts;  ///< the shard tables merged into it, found in the folder
};

/// The files of a folder, placed: by scene, the sweeps, and the rest.
struct Folder {
  std::map<std::string, SceneFiles> scenes;
  /// The scenes in the order the manifest first names them: the order the job made them in
  /// (the main job's default scene before the printed one), where `scenes` is by name.
  std::vector<std::string> listed;
  std::vector<SweepFiles> sweeps;
  std::vector<std::string> others;
  bool empty() const { return scenes.empty() && sweeps.empty() && others.empty(); }
};

/// The folder's files, placed.
Folder inventoryOf(const fs::path& dir);

}  // namespace tasks::report

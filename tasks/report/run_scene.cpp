#include "tasks/report/run_scene.hpp"

#include <cmath>

#include "scene/loader.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"

namespace tasks::report {
namespace {

constexpr const char* kChanged =
    "has changed since this run was simulated: no 3D player for it (simulate it again to "
    "replay it)";

// The scene file a telemetry sidecar names: its absolute path, else as given (from here, then
// from the folder).
std::optional<std::string> sceneOf(const RunRecord& run, const fs::path& dir) {
  std::error_code ec;
  for (const Text* named : {&run.scene_path, &run.scene}) {
    const std::string path = stringOr(*named, "");
    if (path.empty()) continue;
    if (fs::is_regular_file(path, ec)) return path;
    if (fs::is_regular_file(dir / path, ec)) return (dir / path).string();
  }
  return std::nullopt;
}

// Whether the scene file no longer describes the run its sidecar recorded: its content's
// fingerprint differs from the one simulate wrote, or, in a sidecar older than that key, the
// body's mass does, the only body parameter such a sidecar records (a relative 1e-9: the same
// file gives the same mass to the last digit). Without either, the scene is taken as it is. The
// player would otherwise draw the body as it is now, moving as the old one did.
bool sceneChangedSince(const RunRecord& run, const std::string& scene_path,
                       const sim::Model& model) {
  if (run.scene_fingerprint) return *run.scene_fingerprint != sceneFingerprint(scene_path);
  if (!run.mass_kg) return false;
  return std::abs(*run.mass_kg - model.body->mass) > 1e-9 * std::abs(model.body->mass);
}

// The values the run put in over its scene; none where one is not a key and a text (not a
// sidecar of ours).
std::optional<std::vector<scene::KeyValue>> keyValuesOf(const RunRecord& run) {
  std::vector<scene::KeyValue> values;
  for (const auto& [key, value] : run.scene_values) {
    if (!key || !value) return std::nullopt;
    values.push_back({*key, *value});
  }
  return values;
}

// The scene at `out.scene` loaded with the run's values, where it still describes the run.
void loadRunScene(const RunRecord& run, RunModel& out, const std::string& drawn_surface) {
  const auto values = keyValuesOf(run);
  if (!values) return;
  const auto text = scene::readSceneFile(out.scene);
  if (!text) return;
  // Its content first: an edited scene has changed, whether or not it still loads.
  if (run.scene_fingerprint && *run.scene_fingerprint != sceneFingerprint(out.scene)) {
    out.why = kChanged;
    return;
  }
  // The same content that no longer loads: this rattleback reads it otherwise than the one
  // that ran it (a key since renamed, a check since added); its own error line says how. (A
  // sidecar from before the fingerprint cannot tell that from an edit.)
  auto loaded = scene::loadWithValues(text.value(), out.scene, *values, "scene_values");
  auto model = loaded ? scene::loadModel(loaded.value()) : rb::Result<sim::Model>(loaded.error());
  if (!model) {
    out.why = std::string(run.scene_fingerprint ? "no longer loads in this rattleback ("
                                                : "no longer loads (") +
              model.error().text() +
              "): no 3D player for it (mend the scene and simulate it again to replay it)";
    return;
  }
  if (sceneChangedSince(run, out.scene, model.value())) {
    out.why = kChanged;
    return;
  }
  out.frame = playerFrame(loaded.value(), model.value());
  if (!drawn_surface.empty()) loaded.value().video.surface = drawn_surface;
  out.surface = playerSurfaceOf(LoadedScene{std::move(loaded).value(), model.value()});
  out.model = std::move(model).value();
}

}  // namespace

bool sceneEditedSince(const RunRecord& run, const fs::path& dir) {
  const auto scene = sceneOf(run, dir);
  return scene && run.scene_fingerprint && *run.scene_fingerprint != sceneFingerprint(*scene);
}

RunModel runModelOf(const RunRecord& run, const fs::path& dir, const std::string& drawn_surface) {
  if (run.command != "simulate") return {};
  // A scene made from text (Python's from_yaml, from_dict; scene_path null) has no file to replay
  // the run on: a file of its name here is another scene, and there is nothing to say.
  if (run.from_text) return {};
  const auto scene_path = sceneOf(run, dir);
  // A scene read from a file when it ran (it has a fingerprint) that is not there now: moved or
  // removed (a run made from a string has none, and nothing to say).
  if (!scene_path) {
    if (!run.scene_fingerprint) return {};
    return {std::nullopt, stringOr(run.scene_path, ""),
            "is not there any more: no 3D player for it (simulate it again to replay it)"};
  }
  RunModel out{std::nullopt, *scene_path, ""};
  loadRunScene(run, out, drawn_surface);
  return out;
}

}  // namespace tasks::report

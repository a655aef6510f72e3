// Loading a scene with command-line overrides: an override replaces the scene's key before
// compile(), and an error in it is named by its option ("--dt: simulation.dt …").
#pragma once

#include <array>
#include <optional>
#include <string>

#include "scene/loader.hpp"
#include "sim/model.hpp"
#include "tasks/scene_options.hpp"
#include "util/result.hpp"

namespace tasks {

/// A scene file as loaded (with the overrides applied) and its compiled run.
struct LoadedScene {
  scene::Loaded scene;
  sim::Model model;
};

/// Where a scene or sweep file is: `path` itself, or, for a relative path that is not here, the
/// installed copy under the assets folder (share/rattleback/scenes, …/sweeps), so that
/// `rattleback still scenes/rattleback.yaml` and bench's defaults work from any folder. A path
/// that starts with ./ or ../ is this folder's only.
std::string findShipped(const std::string& path);

/// The compiled scene, or the one line to print.
rb::Result<LoadedScene> loadScene(const std::string& path, const Overrides& o);
/// The same for a scene already loaded (from a string, or with values put in).
rb::Result<LoadedScene> applyOverrides(scene::Loaded scene, const Overrides& o);

/// For --verbose: one line on stderr with the body, contact, integrator and step.
void describeModel(const sim::Model& model, const std::string& scene);

/// Parses "1280x720"; false when malformed.
bool parseSize(const std::string& text, std::array<int, 2>& size);

}  // namespace tasks

#include <filesystem>

#include "app/commands.hpp"
#include "scene/loader.hpp"
#include "tasks/scene_args.hpp"

namespace app {

void record(const std::vector<tasks::OutputEntry>& entries) {
  if (auto ok = tasks::recordOutputs(entries); !ok)
    tell(Tone::Note, "the outputs are written but not listed in their folder's " +
                         std::string(tasks::kManifestName) + " (" + ok.error().text() +
                         "); rattleback report places them by their names");
}

std::string sceneName(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

std::string sceneWithValues(const std::string& path, const tasks::Overrides& overrides) {
  if (overrides.values.empty()) return path;
  return path + " with " + scene::valuesSaid(overrides.values, "=");
}

// Said with -q too: the run is of another file than the one named (a pipeline's deleted scene
// of a shipped one's name would run the shipped one with nothing said).
void noteShipped(const std::string& given) {
  const std::string file = tasks::findShipped(given);
  if (file != given)
    tell(Tone::Note, "no " + given + " in this folder; running the shipped one, " + file + " (./" +
                         given + " names this folder's only)");
}

}  // namespace app

#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "tasks/scene_args.hpp"

namespace app {

void record(const std::vector<tasks::OutputEntry>& entries) {
  if (auto ok = tasks::recordOutputs(entries); !ok)
    std::cerr << "note: the outputs are written but not listed in their folder's "
              << tasks::kManifestName << " (" << ok.error().text()
              << "); rattleback report places them by their names\n";
}

std::string sceneName(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

// Said with -q too: the run is of another file than the one named (a CI maintainer's trial: a
// pipeline's deleted scene of a shipped one's name ran the shipped one with nothing said).
void noteShipped(const std::string& given) {
  const std::string file = tasks::findShipped(given);
  if (file != given)
    std::cerr << "note: no " << given << " in this folder; running the shipped one, " << file
              << " (./" << given << " names this folder's only)\n";
}

}  // namespace app

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

void noteShipped(const std::string& given, bool quiet) {
  if (quiet) return;
  const std::string file = tasks::findShipped(given);
  if (file != given)
    std::cerr << "note: no " << given << " in this folder; running the shipped one, " << file
              << "\n";
}

}  // namespace app

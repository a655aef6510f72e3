#include <filesystem>
#include <iostream>

#include "app/commands.hpp"

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

}  // namespace app

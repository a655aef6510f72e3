#include "tasks/manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "tasks/output.hpp"
#include "util/names.hpp"

namespace tasks {
namespace {

namespace fs = std::filesystem;

nlohmann::json toJson(const OutputEntry& e) {
  nlohmann::json j;
  j["file"] = fs::path(e.file).filename().string();
  j["kind"] = std::string(rb::nameOf(e.kind));
  j["scene"] = e.scene;
  j["role"] = e.role;
  j["spin"] = e.spin ? nlohmann::json(*e.spin) : nlohmann::json(nullptr);
  j["t"] = e.t ? nlohmann::json(*e.t) : nlohmann::json(nullptr);
  if (!e.made_from.empty()) j["made_from"] = e.made_from;
  if (e.frame_m) j["frame_m"] = *e.frame_m;
  if (!e.view.empty()) j["view"] = e.view;
  if (!e.surface.empty()) j["surface"] = e.surface;
  if (e.simulated_s) {
    j["simulated_s"] = *e.simulated_s;
    j["first_reversal_s"] =
        e.first_reversal_s ? nlohmann::json(*e.first_reversal_s) : nlohmann::json(nullptr);
    j["reversals_s"] = e.reversals_s;
    j["final_spin"] = e.final_spin ? nlohmann::json(*e.final_spin) : nlohmann::json(nullptr);
  }
  return j;
}

std::optional<OutputEntry> fromJson(const nlohmann::json& j) {
  if (!j.is_object() || !j.contains("file") || !j["file"].is_string()) return std::nullopt;
  const auto kind = rb::parseName<OutputKind>(j.value("kind", ""));
  if (!kind) return std::nullopt;
  OutputEntry e;
  e.file = j["file"].get<std::string>();
  e.kind = *kind;
  e.scene = j.value("scene", "");
  e.role = j.value("role", "");
  if (j.contains("spin") && j["spin"].is_number()) e.spin = j["spin"].get<double>();
  if (j.contains("t") && j["t"].is_number()) e.t = j["t"].get<double>();
  if (j.contains("made_from") && j["made_from"].is_string())
    e.made_from = j["made_from"].get<std::string>();
  if (j.contains("frame_m") && j["frame_m"].is_number()) e.frame_m = j["frame_m"].get<double>();
  if (j.contains("view") && j["view"].is_string()) e.view = j["view"].get<std::string>();
  if (j.contains("surface") && j["surface"].is_string())
    e.surface = j["surface"].get<std::string>();
  if (j.contains("simulated_s") && j["simulated_s"].is_number()) {
    e.simulated_s = j["simulated_s"].get<double>();
    if (j.contains("first_reversal_s") && j["first_reversal_s"].is_number())
      e.first_reversal_s = j["first_reversal_s"].get<double>();
    if (j.contains("reversals_s") && j["reversals_s"].is_array())
      for (const nlohmann::json& t : j["reversals_s"])
        if (t.is_number()) e.reversals_s.push_back(t.get<double>());
    if (j.contains("final_spin") && j["final_spin"].is_number())
      e.final_spin = j["final_spin"].get<double>();
  }
  return e;
}

// Holds an exclusive lock on the folder itself while alive: flock(2) on the folder's own
// descriptor leaves no file behind. Where a folder cannot be locked so (NFS refuses an
// exclusive lock on a descriptor not open for writing), DIR/.rattleback-manifest.lock.
class Lock {
 public:
  explicit Lock(const fs::path& dir)
      : fd_(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)) {
    if (fd_ >= 0 && ::flock(fd_, LOCK_EX) == 0) return;
    if (fd_ >= 0) ::close(fd_);
    fd_ = ::open((dir / ".rattleback-manifest.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ >= 0) ::flock(fd_, LOCK_EX);
  }
  ~Lock() {
    if (fd_ >= 0) ::close(fd_);  // releases the lock
  }
  Lock(const Lock&) = delete;
  Lock& operator=(const Lock&) = delete;

 private:
  int fd_;
};

rb::Status recordInFolder(const fs::path& dir, const std::vector<OutputEntry>& entries) {
  Lock lock(dir);
  std::map<std::string, nlohmann::json> by_file;
  std::vector<std::string> order;
  for (const OutputEntry& e : readManifest(dir.string())) {
    order.push_back(e.file);
    by_file[e.file] = toJson(e);
  }
  for (const OutputEntry& e : entries) {
    const std::string name = fs::path(e.file).filename().string();
    if (!by_file.count(name)) order.push_back(name);
    by_file[name] = toJson(e);
  }
  nlohmann::json outputs = nlohmann::json::array();
  for (const std::string& name : order) outputs.push_back(by_file[name]);
  auto out = AtomicOutput::open((dir / kManifestName).string());
  if (!out) return out.error();
  out->stream()
      << nlohmann::json{{"program", "rattleback " RATTLEBACK_VERSION}, {"outputs", outputs}}.dump(1)
      << "\n";
  return out->commit();
}

}  // namespace

rb::Status recordOutputs(const std::vector<OutputEntry>& entries) {
  std::map<fs::path, std::vector<OutputEntry>> by_folder;
  for (const OutputEntry& e : entries) {
    // Only files: a table sent to standard output or a device has no folder to record it in.
    if (rb::outputPlace(e.file).temporary.empty()) continue;
    fs::path dir = fs::path(e.file).parent_path();
    by_folder[dir.empty() ? fs::path(".") : dir].push_back(e);
  }
  for (const auto& [dir, list] : by_folder)
    if (auto ok = recordInFolder(dir, list); !ok) return ok;
  return {};
}

std::vector<OutputEntry> readManifest(const std::string& dir) {
  std::ifstream in(fs::path(dir) / kManifestName);
  if (!in) return {};
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  std::vector<OutputEntry> entries;
  if (j.is_discarded() || !j.is_object() || !j.contains("outputs") || !j["outputs"].is_array())
    return entries;
  for (const auto& e : j["outputs"])
    if (auto entry = fromJson(e)) entries.push_back(*entry);
  return entries;
}

}  // namespace tasks

#include "tasks/report/player_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

#include "tasks/manifest.hpp"
#include "tasks/output.hpp"
#include "tasks/player_data.hpp"
#include "tasks/report/run_scene.hpp"
#include "tasks/report/sidecars.hpp"
#include "tasks/simulate.hpp"
#include "util/assets.hpp"

namespace tasks::report {
namespace {

// The telemetry columns a pose is made of, in Pose's order.
constexpr const char* kPoseColumns[] = {"t", "x", "y", "z", "qw", "qx", "qy", "qz", "spin"};

// Where each of kPoseColumns is in a CSV's header line; none where one is missing.
std::optional<std::vector<int>> poseColumnsOf(const std::string& header) {
  std::vector<int> index(std::size(kPoseColumns), -1);
  std::stringstream head(header);
  std::string name;
  for (int i = 0; std::getline(head, name, ','); ++i)
    for (std::size_t w = 0; w < std::size(kPoseColumns); ++w)
      if (name == kPoseColumns[w]) index[w] = i;
  if (std::count(index.begin(), index.end(), -1) > 0) return std::nullopt;
  return index;
}

// A CSV line's numbers (the telemetry has no quoted fields), read as strtod reads them.
void numbersOf(const std::string& line, std::vector<double>& fields) {
  fields.clear();
  for (const char* p = line.c_str(); *p;) {
    char* end = nullptr;
    fields.push_back(std::strtod(p, &end));
    p = std::strchr(end, ',');
    if (!p) break;
    ++p;
  }
}

// The poses of a telemetry CSV (found by the header); none for a CSV without them (written
// before the attitude was).
std::vector<Pose> posesOf(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return {};
  const auto index = poseColumnsOf(line);
  if (!index) return {};
  std::vector<Pose> poses;
  std::vector<double> fields;
  while (std::getline(in, line)) {
    numbersOf(line, fields);
    auto at = [&](std::size_t w) {
      return static_cast<std::size_t>((*index)[w]) < fields.size() ? fields[(*index)[w]] : NAN;
    };
    poses.push_back({at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), at(8)});
  }
  return poses;
}

// How a scene's videos (else its stills) were drawn, where the manifest says: the players are
// framed and drawn as the pictures beside them (--frame, --surface), not each filled with its own
// body as its scene file says.
struct Drawn {
  std::optional<double> frame;
  std::string surface;
};

// DIR/<id>.player.js for a scene with telemetry: its poses, reversals and drawn points, and
// the body spun the other way where the player offers it (otherSpinOf); None (the page then has
// no player for it) when the CSV, its sidecar or its scene cannot be read; an error when the
// file cannot be written.
rb::Result<PlayerRuns> writePlayerData(const fs::path& dir, const std::string& id,
                                       const SceneFiles& f, const Drawn& drawn,
                                       std::vector<std::string>& notes) {
  if (!f.has(".csv") || !f.has(".csv.json")) return PlayerRuns::None;
  const std::optional<RunRecord> sidecar = readRunRecord(dir / f.at(".csv.json"));
  if (!sidecar || sidecar->command != "simulate") return PlayerRuns::None;
  RunModel found = runModelOf(*sidecar, dir, drawn.surface);
  if (!found.model) {
    if (!found.why.empty())
      notes.push_back((dir / f.at(".csv")).string() + ": " + found.scene + " " + found.why);
    // The data an earlier report wrote for this run would replay it on another body.
    std::error_code ec;
    fs::remove(dir / (id + ".player.js"), ec);
    return PlayerRuns::None;
  }
  std::vector<Pose> poses = posesOf(dir / f.at(".csv"));
  if (poses.size() < 2) return PlayerRuns::None;
  std::vector<double> reversals;
  for (const Number& r : sidecar->reversals_s)
    if (r) reversals.push_back(*r);
  // Framed and drawn as the scene's videos and stills were (--frame, --surface), else as its
  // video.frame and video.surface say.
  PlayerRun run = playerRunOf(id, *found.model, drawn.frame.value_or(found.frame), std::move(poses),
                              std::move(reversals), std::move(found.surface));
  // Beside it, the body spun the other way, simulated here: a body spun the way it prefers
  // shows no reversal, and its teacher wants to show it reverse. Whether or not --both's videos
  // are in the folder: the player is where the reversal is replayed and stepped through, and it
  // costs a few ms here, where the videos cost minutes.
  if (const std::optional<nlohmann::json> sidecar_json = readJson(dir / f.at(".csv.json")))
    run.other = otherSpinOf(*found.model, field(*sidecar_json, "model"),
                            sidecar->rate_hz.value_or(kDefaultRate));
  auto out = AtomicOutput::open((dir / (id + ".player.js")).string());
  if (!out) return out.error();
  out->stream() << playerScript(run);
  if (auto e = out->commit(); !e) return e.error();
  return run.other ? PlayerRuns::BothSpins : PlayerRuns::One;
}

// The bundle copied beside the page; false when the build made none (no node and npm), an
// error when it cannot be written (a full disk, a file-size limit: the page would otherwise
// stand without its players, and nothing said).
rb::Result<bool> copyPlayerBundle(const fs::path& dir) {
  std::ifstream in(fs::path(rb::assetsDir()) / "player" / kPlayerBundle, std::ios::binary);
  if (!in) return false;
  auto out = AtomicOutput::open((dir / kPlayerBundle).string());
  if (!out) return out.error();
  // Read whole, then written: `<< rdbuf()` stops quietly at a failed write once it has written
  // anything (no failbit), and a bundle cut at a file-size limit would stand as whole.
  const std::string bundle((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  out->stream().write(bundle.data(), static_cast<std::streamsize>(bundle.size()));
  if (auto e = out->commit(); !e) return e.error();
  return true;
}

// How each scene's videos, else its stills, were drawn (the first listed of each that says).
std::map<std::string, Drawn> drawnAs(const fs::path& dir) {
  std::map<std::string, Drawn> drawn;
  const std::vector<OutputEntry> listed = readManifest(dir.string());
  for (const OutputKind kind : {OutputKind::Video, OutputKind::Still})
    for (const OutputEntry& e : listed) {
      if (e.kind != kind) continue;
      Drawn& d = drawn[e.scene];
      if (e.frame_m && !d.frame) d.frame = e.frame_m;
      if (!e.surface.empty() && d.surface.empty()) d.surface = e.surface;
    }
  return drawn;
}

}  // namespace

rb::Result<std::vector<PlayerPlace>> writePlayers(const fs::path& dir, const Folder& folder,
                                                  std::vector<std::string>& notes) {
  std::vector<PlayerPlace> players;
  const rb::Result<bool> bundle = copyPlayerBundle(dir);
  if (!bundle) return bundle.error();
  if (!bundle.value()) return players;
  const auto drawn = drawnAs(dir);
  for (const auto& [name, files] : folder.scenes) {
    const auto as = drawn.find(name);
    const rb::Result<PlayerRuns> data =
        writePlayerData(dir, name, files, as == drawn.end() ? Drawn{} : as->second, notes);
    if (!data) return data.error();
    if (data.value() != PlayerRuns::None) players.push_back({name, data.value()});
  }
  std::error_code ec;
  if (players.empty()) fs::remove(dir / kPlayerBundle, ec);  // nothing to play
  return players;
}

}  // namespace tasks::report

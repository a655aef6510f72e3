#include "tasks/report/inventory.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <set>

#include "tasks/manifest.hpp"
#include "tasks/report/captions.hpp"
#include "tasks/report/html.hpp"
#include "tasks/report/sidecars.hpp"

namespace tasks::report {
namespace {

// A manifest's videos, by scene and spin: which stills are their posters.
struct ListedVideo {
  std::string role;
  std::string view;  // "" when the manifest does not say
};
struct ListedSpins {
  std::map<std::string, std::map<double, ListedVideo>> paired;  // scene → spin → video
  std::map<std::string, std::map<double, std::string>> single;  // scene → lone videos' views
};

// The first video of a scene and spin is the one whose slot a poster fills (placeEntry keeps a
// slot's first; later ones are shown beside it, without posters): a second `render --both` of
// the scene from above must not make a still from above the first one's poster.
ListedSpins spinsOf(const std::vector<OutputEntry>& entries) {
  ListedSpins spins;
  for (const OutputEntry& e : entries) {
    if (e.kind != OutputKind::Video || !e.spin) continue;
    if (e.role == "single")
      spins.single[e.scene].try_emplace(*e.spin, e.view);
    else if (e.role != "both")
      spins.paired[e.scene].try_emplace(*e.spin, ListedVideo{e.role, e.view});
  }
  return spins;
}

// A still is a video's poster when it shows the video's first frame: at t = 0, spun as the video
// is, from the video's view (a poster from above over a video from the side jumps at play).
bool posterOf(const OutputEntry& still, const std::string& video_view) {
  return still.t && *still.t == 0 && still.spin && (video_view.empty() || video_view == still.role);
}

// What is placed as the manifest lists it, and what is left to place by name.
struct Listing {
  std::map<std::string, std::vector<std::string>> runs;  // scene → its telemetry
  std::set<std::string> placed;
};

// The slot of the page a manifest entry fills: the suffix a file of that role has when named
// as scripts/run.sh names it. Videos' spins say which stills are their posters.
std::optional<std::string> slotOf(const OutputEntry& e,
                                  const std::map<double, ListedVideo>& video_spins) {
  switch (e.kind) {
    case OutputKind::Video:
      if (e.role == "preferred" || e.role == "reversed" || e.role == "ccw" || e.role == "cw" ||
          e.role == "both")
        return "-" + e.role + ".mp4";
      return ".mp4";
    case OutputKind::Still:
      if (e.spin && video_spins.count(*e.spin) && posterOf(e, video_spins.at(*e.spin).view))
        return "-" + video_spins.at(*e.spin).role + ".png";
      return "-" + e.role + ".png";
    case OutputKind::Plot:
      return "-" + e.role + ".png";
    case OutputKind::Telemetry:
      return ".csv";
    case OutputKind::Analysis:
      return e.role == "json" ? "-analysis.json" : "-analysis.txt";
    default:
      return std::nullopt;
  }
}

// A video's own run as the manifest lists it (its spin, length and first reversal).
RunRecord videoRunOf(const OutputEntry& e) {
  RunRecord run;
  run.command = "render";
  run.initial_spin = e.spin;
  run.simulated_s = e.simulated_s;
  run.first_reversal_s = e.first_reversal_s;
  for (double t : e.reversals_s) run.reversals_s.push_back(t);
  run.final_spin = e.final_spin;
  return run;
}

// What the manifest says of a file beside its slot: a still's caption, a video's spin, the
// scene it was made from.
void noteListed(const OutputEntry& e, Folder& folder) {
  if (e.kind == OutputKind::Still) folder.scenes[e.scene].captions[e.file] = stillCaption(e);
  if (e.kind == OutputKind::Video && e.spin) {
    ManifestVideo& video = folder.scenes[e.scene].manifest_videos[e.file];
    video.spin = *e.spin;
    if (e.simulated_s) video.run = videoRunOf(e);
  }
  if (!e.made_from.empty()) folder.scenes[e.scene].made_from[e.file] = e.made_from;
}

// A file the manifest lists in its scene's slot (the slot's first keeps it; later videos and
// stills are shown beside it), the bench's with the other files; telemetry is kept for
// placeRuns.
void placeEntry(const fs::path& dir, const OutputEntry& e, ListedSpins& spins, Folder& folder,
                Listing& listing) {
  std::error_code ec;
  if (e.kind == OutputKind::Telemetry) {
    listing.runs[e.scene].push_back(e.file);
    listing.placed.insert(e.file);
    if (fs::is_regular_file(dir / (e.file + ".json"), ec)) listing.placed.insert(e.file + ".json");
    return;
  }
  // A lone video's poster.
  if (e.kind == OutputKind::Still && e.spin && spins.single[e.scene].count(*e.spin) &&
      posterOf(e, spins.single[e.scene].at(*e.spin))) {
    SceneFiles& f = folder.scenes[e.scene];
    if (!f.has("-single.png")) f.by_suffix["-single.png"] = e.file;
  }
  if (e.kind == OutputKind::Bench || e.kind == OutputKind::BenchPlot) {
    folder.others.push_back(e.file);
  } else if (e.kind == OutputKind::Sweep || e.kind == OutputKind::SweepPlot) {
    return;  // sweeps are found by their sidecars, their plots by name (takeSweeps)
  } else if (auto slot = slotOf(e, spins.paired[e.scene])) {
    SceneFiles& f = folder.scenes[e.scene];
    const bool media = e.kind == OutputKind::Video || e.kind == OutputKind::Still;
    if (media && f.has(*slot) && f.at(*slot) != e.file)
      (e.kind == OutputKind::Video ? f.more_videos : f.more_stills).push_back(e.file);
    else
      f.by_suffix[*slot] = e.file;
  }
  listing.placed.insert(e.file);
}

// Each scene's main run is its own <scene>.csv, else the first by name (not the last
// written); the others are listed beside it.
void placeRuns(const fs::path& dir, std::map<std::string, std::vector<std::string>>& runs,
               Folder& folder) {
  std::error_code ec;
  for (auto& [scene, files] : runs) {
    std::sort(files.begin(), files.end());
    // The page reads a CSV's rows: arrays (.npz, .h5) are listed beside it, never the main run.
    auto main = std::find(files.begin(), files.end(), scene + ".csv");
    if (main == files.end())
      main = std::find_if(files.begin(), files.end(),
                          [](const std::string& file) { return endsWith(file, ".csv"); });
    SceneFiles& f = folder.scenes[scene];
    if (main == files.end()) {
      f.more_runs.insert(f.more_runs.end(), files.begin(), files.end());
      continue;
    }
    f.by_suffix[".csv"] = *main;
    if (fs::is_regular_file(dir / (*main + ".json"), ec))
      f.by_suffix[".csv.json"] = *main + ".json";
    // The figures shown are the main run's (simulate names them after its table: anna.csv's
    // anna-spin.png), not another run's of the same scene listed after it.
    const std::string stem = fs::path(*main).stem().string();
    for (const char* suffix : kPlotSuffixes)
      if (fs::is_regular_file(dir / (stem + suffix), ec)) f.by_suffix[suffix] = stem + suffix;
    for (const std::string& file : files)
      if (file != *main) f.more_runs.push_back(file);
  }
}

// Places the files the manifest lists; returns the names it placed.
std::set<std::string> placeListed(const fs::path& dir, Folder& folder) {
  const std::vector<OutputEntry> entries = readManifest(dir.string());
  ListedSpins spins = spinsOf(entries);
  Listing listing;
  std::error_code ec;
  for (const OutputEntry& e : entries) {
    if (!fs::is_regular_file(dir / e.file, ec)) continue;  // since removed
    if (std::find(folder.listed.begin(), folder.listed.end(), e.scene) == folder.listed.end())
      folder.listed.push_back(e.scene);
    noteListed(e, folder);
    placeEntry(dir, e, spins, folder, listing);
  }
  placeRuns(dir, listing.runs, folder);
  return listing.placed;
}

// The files the manifest does not list, placed by their names: the scene is the name before a
// known suffix.
void placeByName(const fs::path& dir, const std::set<std::string>& placed, Folder& folder) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  // Longer suffixes first (-preferred.mp4 before .mp4, .csv.json before .csv).
  std::vector<std::string> suffixes;
  for (const char* s : kVideoSuffixes) suffixes.push_back(s);
  for (const char* s : kDataSuffixes) suffixes.push_back(s);
  for (const char* s : kPosterSuffixes) suffixes.push_back(s);
  for (const char* s : kStillSuffixes) suffixes.push_back(s);
  for (const char* s : kPlotSuffixes) suffixes.push_back(s);
  for (const std::string& name : names) {
    if (name.empty() || name[0] == '.' || name == "index.html" || name == kManifestName ||
        placed.count(name))
      continue;
    bool claimed = false;
    for (const std::string& suffix : suffixes)
      if (!claimed && endsWith(name, suffix)) {
        SceneFiles& f = folder.scenes[name.substr(0, name.size() - suffix.size())];
        f.by_suffix[suffix] = name;
        // A lone <scene>.mp4 takes <scene>-oblique.png, when the manifest names no poster.
        if (suffix == "-oblique.png" && !f.has("-single.png")) f.by_suffix["-single.png"] = name;
        claimed = true;
      }
    if (!claimed && (endsWith(name, ".png") || endsWith(name, ".csv")))
      folder.others.push_back(name);
  }
}

// A shard's table whose merged table is in the folder (its sidecar lists the shard in
// `merged_from`) is a part of that sweep, not a sweep of its own: it is listed under it. A shard
// not merged yet stays a section of its own, which says it is one.
void attachShards(std::vector<SweepFiles>& sweeps) {
  for (auto it = sweeps.begin(); it != sweeps.end();) {
    SweepFiles* whole = nullptr;
    if (field(it->meta, "shard").is_object())
      for (SweepFiles& merged : sweeps) {
        const nlohmann::json& from = field(merged.meta, "merged_from");
        if (&merged == &*it || !from.is_array() ||
            field(merged.meta, "sweep") != field(it->meta, "sweep"))
          continue;
        for (const nlohmann::json& f : from)
          if (f.is_string() && fs::path(f.get<std::string>()).filename() == it->csv)
            whole = &merged;
      }
    if (!whole) {
      ++it;
      continue;
    }
    whole->parts.push_back(it->csv);
    whole->images.insert(whole->images.end(), it->images.begin(), it->images.end());
    it = sweeps.erase(it);
  }
  for (SweepFiles& sweep : sweeps) std::sort(sweep.parts.begin(), sweep.parts.end());
}

// A sweep's table (its sidecar says so), with its heatmaps NAME.png and NAME-*.png, taken out of
// the scenes and the other files.
void takeSweeps(const fs::path& dir, Folder& folder) {
  auto& scenes = folder.scenes;
  auto& others = folder.others;
  for (auto it = scenes.begin(); it != scenes.end();) {
    std::optional<nlohmann::json> meta;
    if (it->second.has(".csv.json")) meta = readJson(dir / it->second.at(".csv.json"));
    if (!(it->second.has(".csv") && meta && field(*meta, "command") == "sweep")) {
      ++it;
      continue;
    }
    SweepFiles sweep{it->first, it->second.at(".csv"), *meta, {}, {}};
    for (auto o = others.begin(); o != others.end();) {
      const bool mine =
          endsWith(*o, ".png") && (*o == it->first + ".png" || o->rfind(it->first + "-", 0) == 0);
      if (mine) sweep.images.push_back(*o);
      o = mine ? others.erase(o) : o + 1;
    }
    folder.sweeps.push_back(std::move(sweep));
    it = scenes.erase(it);
  }
}

// A CSV of its own (bench.csv) is no scene: it goes with the other files.
void releaseLoneTables(Folder& folder) {
  auto& scenes = folder.scenes;
  auto& others = folder.others;
  for (auto it = scenes.begin(); it != scenes.end();) {
    const bool lone_csv = it->second.by_suffix.size() == 1 && it->second.has(".csv");
    if (lone_csv) {
      others.push_back(it->second.at(".csv"));
      others.insert(others.end(), it->second.more_runs.begin(), it->second.more_runs.end());
    }
    it = lone_csv ? scenes.erase(it) : std::next(it);
  }
  std::sort(others.begin(), others.end());
  others.erase(std::unique(others.begin(), others.end()), others.end());
}

}  // namespace

Folder inventoryOf(const fs::path& dir) {
  Folder folder;
  placeByName(dir, placeListed(dir, folder), folder);
  takeSweeps(dir, folder);
  attachShards(folder.sweeps);
  releaseLoneTables(folder);
  return folder;
}

}  // namespace tasks::report

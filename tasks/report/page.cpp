// The report page: DIR/index.html, its style, and the order of its sections (scenes with videos
// first, then the rest, the sweeps, the other files), with the players' scripts last.
#include "tasks/report/page.hpp"

#include <algorithm>

#include "tasks/output.hpp"
#include "tasks/report/html.hpp"
#include "tasks/report/inventory.hpp"
#include "tasks/report/player_files.hpp"
#include "tasks/report/scene_section.hpp"
#include "tasks/report/sweep_section.hpp"
#include "util/assets.hpp"
#include "util/output_place.hpp"

namespace tasks {
namespace report {
namespace {

const char* kStyle = R"(
body{font-family:"DejaVu Sans",sans-serif;max-width:1300px;margin:1em auto;padding:0 1em;color:#222}
h1{margin-bottom:0}section{border-top:1px solid #ccc;margin-top:1.5em}
.pair{display:flex;gap:1em;flex-wrap:wrap}.pair figure{flex:1 1 500px;margin:0}
video,img{max-width:100%;height:auto;background:#eee}figure{margin:0 0 1em}
.grid{display:grid;grid-template-columns:repeat(auto-fill,minmax(300px,1fr));gap:.7em}
.grid figure{margin:0}figcaption{font-size:.9em;color:#444}
.grid.wide{grid-template-columns:repeat(auto-fill,minmax(min(100%,620px),1fr))}
table{border-collapse:collapse;margin:1em 0}
td,th{border:1px solid #ccc;padding:.4em .8em;vertical-align:top;text-align:left}
.warning{color:#9a3412;font-weight:bold}
img.thumb{display:block;width:360px;margin:.4em 0}
)";

void writeOthers(std::ostream& out, const std::vector<std::string>& others) {
  if (others.empty()) return;
  out << "<section id=\"other\"><h2>Benchmarks and other figures</h2><div class=\"grid\">\n";
  for (const std::string& name : others) {
    if (endsWith(name, ".png"))
      writeFigure(out, name, "");
    else
      out << "<p><a href=\"" << url(name) << "\">" << escape(name) << "</a></p>\n";
  }
  out << "</div></section>\n";
}

// Where the page's reader finds the documentation: the installed pages (share/doc/rattleback
// beside share/rattleback) when this program is installed (an installed report's page would
// otherwise point to a source tree that is not there), else the source's.
std::string documentationWhere() {
  const std::string installed = rb::docsDir();
  if (!installed.empty())
    return "<code>" + escape(installed) +
           "/</code> where rattleback is installed (<code>getting-started.md</code> first)";
  return "<code>docs/</code> in rattleback's source (<code>docs/getting-started.md</code> first; "
         "<code>bash scripts/docs.sh</code> builds it as a site)";
}

// Scenes with videos first, then the rest; each group in the order the manifest names them (the
// order the job made them), then the scenes it does not name, by name.
std::vector<std::string> sceneOrder(const Folder& folder) {
  std::vector<std::string> names = folder.listed;
  for (const auto& [name, files] : folder.scenes)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  auto hasVideo = [&](const std::string& name) {
    const auto found = folder.scenes.find(name);
    if (found == folder.scenes.end()) return false;  // a name the manifest gave a sweep or bench
    const SceneFiles& files = found->second;
    return files.has("-reversed.mp4") || files.has("-preferred.mp4") || files.has("-ccw.mp4") ||
           files.has("-cw.mp4") || files.has(".mp4");
  };
  std::vector<std::string> order;
  for (const bool videos : {true, false})
    for (const std::string& name : names)
      if (folder.scenes.count(name) && hasVideo(name) == videos) order.push_back(name);
  return order;
}

void writePage(std::ostream& out, const fs::path& dir, const Folder& folder,
               const std::vector<PlayerPlace>& players) {
  out << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
         "<meta name=\"viewport\" content=\"width=device-width\">"
         "<title>rattleback: results</title><style>"
      << kStyle << kVideoStyle << "</style></head><body>\n<h1>rattleback: results</h1>\n"
      << "<p>What the runs left in this folder, by scene. Made by rattleback " RATTLEBACK_VERSION
         " (<code>rattleback report</code>). What each figure means: the documentation, "
      << documentationWhere() << ".</p>\n";
  for (const std::string& name : sceneOrder(folder)) {
    const auto player = std::find_if(players.begin(), players.end(),
                                     [&](const PlayerPlace& p) { return p.id == name; });
    writeScene(out, dir, name, folder.scenes.at(name),
               player == players.end() ? PlayerRuns::None : player->runs);
  }
  for (const SweepFiles& sweep : folder.sweeps) writeSweep(out, sweep);
  writeOthers(out, folder.others);
  // Classic scripts (a page opened from disk may not import modules or fetch): each run's
  // data, then the player, which finds every .rb-player.
  for (const PlayerPlace& player : players)
    out << "<script src=\"" << url(player.id + ".player.js") << "\"></script>\n";
  if (!players.empty()) out << "<script src=\"" << url(kPlayerBundle) << "\"></script>\n";
  out << "<script>" << kVideoScript << "</script>\n</body></html>\n";
}

}  // namespace
}  // namespace report

rb::Result<ReportPage> writeReport(const std::string& folder_path) {
  namespace fs = std::filesystem;
  const fs::path dir = folder_path;
  std::error_code ec;
  // A name that is not there is said as such, not as "not a folder".
  if (!fs::is_directory(dir, ec))
    return rb::Error{"", folder_path +
                             (fs::exists(dir, ec) ? ": not a folder" : ": no such folder") +
                             " (give the folder the runs wrote into, e.g. out)"};
  // `report` takes a folder, not -o: the way out of a folder it cannot write in says so.
  const rb::OutputNamedBy naming("rattleback report", "a folder");
  const report::Folder folder = report::inventoryOf(dir);
  // The page's place first: a folder where no file can be made is said as the page's (the
  // player's files would otherwise be the first to fail).
  const std::string path = (dir / "index.html").string();
  auto opened = AtomicOutput::open(path);
  if (!opened) return opened.error();
  std::vector<std::string> notes;
  const auto players = report::writePlayers(dir, folder, notes);
  if (!players) return players.error();
  report::writePage(opened->stream(), dir, folder, players.value());
  if (auto e = opened->commit(); !e) return e.error();
  return ReportPage{path, folder.empty(), notes};
}

}  // namespace tasks

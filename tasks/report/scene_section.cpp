#include "tasks/report/scene_section.hpp"

#include <iterator>
#include <optional>
#include <set>
#include <vector>

#include "tasks/analysis.hpp"
#include "tasks/report/captions.hpp"
#include "tasks/report/html.hpp"
#include "tasks/report/run_scene.hpp"
#include "tasks/report/sidecars.hpp"
#include "tasks/report/videos.hpp"

namespace tasks::report {
namespace {

// The scene files a run and the main run were made from, where they differ: runs are grouped
// by their scene file's stem, so a run of another file of the same name (week1/top.yaml and
// week2/top.yaml into one folder) says which file it ran, or it reads as a variant of the main
// run's scene.
std::string anotherFileNote(const std::optional<RunRecord>& run,
                            const std::optional<RunRecord>& main) {
  if (!run || !main) return "";
  const std::string main_file = stringOr(main->scene_path, "");
  const std::string file = stringOr(run->scene_path, "");
  if (main_file.empty() || file.empty() || file == main_file) return "";
  return "<b>another file</b>: <code>" + escape(stringOr(run->scene, file)) +
         "</code> (the main run's: <code>" + escape(stringOr(main->scene, main_file)) +
         "</code>)<br>";
}

// A run's own figures (simulate --plot names them after its table), where they are: the spin's
// shown, the others linked, so that none listed in the manifest is missing from the page.
std::string figuresOf(const fs::path& dir, const std::string& csv) {
  std::string thumb, links;
  std::error_code ec;
  const std::string stem = fs::path(csv).stem().string();
  for (const std::string suffix : kPlotSuffixes) {
    const std::string png = stem + suffix;
    if (!fs::is_regular_file(dir / png, ec)) continue;
    if (suffix == "-spin.png")
      thumb = "<br><img class=\"thumb\" src=\"" + url(png) + "\" alt=\"" +
              escape(stem + ": spin n against time") + "\">";
    links += std::string(links.empty() ? "figures: " : ", ") + "<a href=\"" + url(png) + "\">" +
             escape(suffix.substr(1, suffix.size() - 5)) + "</a>";
  }
  return thumb + (links.empty() ? "" : "<br>" + links);
}

// The scene's other runs (SceneFiles::more_runs), each a row: its CSV and what it measured.
void writeMoreRuns(std::ostream& out, const fs::path& dir, const SceneFiles& f) {
  if (f.more_runs.empty()) return;
  std::optional<RunRecord> main;
  if (f.has(".csv")) main = readRunRecord(dir / (f.at(".csv") + ".json"));
  out << "<h3>Other runs</h3><table><tr><th>telemetry</th><th>measured (simulate)</th></tr>\n";
  for (const std::string& csv : f.more_runs) {
    const std::optional<RunRecord> run = readRunRecord(dir / (csv + ".json"));
    out << "<tr><td><a href=\"" << url(csv) << "\">" << escape(csv) << "</a></td><td>"
        << anotherFileNote(run, main) << (run ? measuredOf(*run) : "–") << figuresOf(dir, csv)
        << "</td></tr>\n";
  }
  out << "</table>\n";
}

// The main run and the other runs of the same scene file and values (another file's, or one
// with other values, is another body), the main one first.
std::vector<RunRecord> runsOfTheScene(const fs::path& dir, const SceneFiles& f,
                                      const std::optional<RunRecord>& main) {
  std::vector<RunRecord> runs;
  if (main) runs.push_back(*main);
  for (const std::string& csv : f.more_runs) {
    std::optional<RunRecord> run = readRunRecord(dir / (csv + ".json"));
    if (run && (!main || (run->scene_fingerprint == main->scene_fingerprint &&
                          run->scene_values == main->scene_values)))
      runs.push_back(std::move(*run));
  }
  return runs;
}

// Theory (analyze --json) beside what the run measured (simulate's sidecar).
void writeAnalysis(std::ostream& out, const SceneFiles& f,
                   const std::optional<nlohmann::json>& theory,
                   const std::optional<RunRecord>& run) {
  // An analysis as text alone (analyze -o NAME.txt, listed in the manifest) is linked, not
  // dropped: its scene's section would be empty.
  const std::string full_analysis =
      f.has("-analysis.txt") ? "<a href=\"" + url(f.at("-analysis.txt")) + "\">full analysis</a>"
                             : "";
  if (!theory && !run && !f.has(".csv")) {
    if (!full_analysis.empty()) out << "<p>" << full_analysis << "</p>\n";
    return;
  }
  out << "<table><tr><th>predicted (linearised and averaged rolling model)</th><th>measured "
         "(simulate)</th></tr>"
         "<tr><td>";
  if (theory) out << predictedOf(*theory) << (full_analysis.empty() ? "" : "<br>");
  out << full_analysis;
  out << "</td><td>";
  if (run) out << measuredOf(*run);
  if (f.has(".csv"))
    out << (run ? "<br>" : "") << "<a href=\"" << url(f.at(".csv")) << "\">telemetry (CSV)</a>";
  out << "</td></tr></table>\n";
}

template <std::size_t N>
void writeImages(std::ostream& out, const SceneFiles& f, const char* const (&suffixes)[N],
                 const char* heading, const std::vector<std::string>& more = {}) {
  std::vector<std::string> files;
  for (const char* suffix : suffixes)
    if (f.has(suffix)) files.push_back(f.at(suffix));
  files.insert(files.end(), more.begin(), more.end());
  if (files.empty()) return;
  out << "<h3>" << heading << "</h3><div class=\"grid\">\n";
  for (const std::string& file : files) {
    const auto listed = f.captions.find(file);
    writeFigure(out, file, listed != f.captions.end() ? listed->second : plotCaption(file));
  }
  out << "</div>\n";
}

// The videos, stills, figures and analyses shown for a scene that were made from another
// version of it than its run (the file edited since, or other values put in), named above
// them: old videos and stills would otherwise stand beside the new run's numbers, with nothing
// said.
void writeOtherVersions(std::ostream& out, const fs::path& dir, const SceneFiles& f,
                        const std::optional<RunRecord>& run) {
  const std::string run_made_from = run ? run->made_from : "";
  if (run_made_from.empty()) return;
  std::set<std::string> shown(f.more_videos.begin(), f.more_videos.end());
  shown.insert(f.more_stills.begin(), f.more_stills.end());
  for (const auto& [suffix, file] : f.by_suffix)
    if (suffix != ".csv" && suffix != ".csv.json") shown.insert(file);
  std::vector<std::string> other;
  for (const std::string& file : shown)
    if (const auto it = f.made_from.find(file);
        it != f.made_from.end() && it->second != run_made_from)
      other.push_back(file);
  if (other.empty()) return;
  out << "<p class=\"warning\">⚠ Made from another version of this scene than the run measured "
         "here (its file edited since, or other values put in), so their pictures and numbers "
         "may not match the run's: ";
  for (std::size_t i = 0; i < other.size(); ++i)
    out << (i ? ", " : "") << "<code>" << escape(other[i]) << "</code>";
  // Which is behind: where the scene file has been edited since the run, the run is (a
  // teacher who simulated before an edit and rendered after it was told to make the new
  // videos again).
  if (sceneEditedSince(*run, dir))
    out << ". The scene file has been edited since the run was simulated: simulate it again to "
           "measure the scene as it is now (or make these again from the version the run "
           "used).</p>\n";
  else
    out << ". Make them again from the scene and values the run used.</p>\n";
}

// The theory of the run's own scene (its file, the values put in over it) at the run's spin,
// as analyze --json would write it, whenever the run's scene can be had: the folder's
// analyze --json may be of another body or spin (a --set run beside the base scene's analysis
// would show the base's forecast), or there may be none (simulate and render alone). The
// folder's analysis stands in only for a run whose scene cannot be had.
std::optional<nlohmann::json> theoryOf(const fs::path& dir, const SceneFiles& f,
                                       const std::optional<RunRecord>& run) {
  if (run)
    if (const std::optional<sim::Model> model = runModelOf(*run, dir).model)
      return analysisJson(*model, analysisSpin(*model, run->model_spin));
  if (f.has("-analysis.json")) return readJson(dir / f.at("-analysis.json"));
  return std::nullopt;
}

// The player's place, with the averaged theory's forecast first reversal for its n(t) plot
// (player/README.md: data-forecast; the player marks it when it applies).
// With both spins, the page says so and names the key that switches them (S): the player's
// buttons say it too, but the page's paragraph is where its keys are looked up.
void writePlayerPlace(std::ostream& out, const std::string& name,
                      const std::optional<nlohmann::json>& theory, PlayerRuns runs) {
  std::string forecast;
  if (theory && field(*theory, "predicted_first_reversal").is_object())
    forecast =
        " data-forecast=\"" + escape(field(*theory, "predicted_first_reversal").dump()) + "\"";
  const bool both = runs == PlayerRuns::BothSpins;
  out << "<h3>Turn it around</h3><p>"
      << (both ? "The run replayed in 3D, and the same body spun the other way (simulated for "
                 "this page): the buttons beside the picture switch between them, each saying "
                 "what its run did. Drag to orbit, scroll to zoom. "
               : "The run replayed in 3D: drag to orbit, scroll to zoom. ")
      << "Keys: <kbd>space</kbd> plays and pauses, <kbd>←</kbd> <kbd>→</kbd> step, "
         "<kbd>R</kbd> the next reversal, "
      << (both ? "<kbd>S</kbd> the other spin, " : "")
      << "<kbd>F</kbd> full screen, <kbd>P</kbd> present (full "
         "screen, large read-outs, for a classroom), <kbd>Esc</kbd> leaves either. The arrow "
         "around the body turns as it does: orange counter-clockwise, green clockwise.</p>"
         "<div class=\"rb-player\" data-run=\""
      << escape(name) << "\"" << forecast << "></div>\n";
}

}  // namespace

void writeScene(std::ostream& out, const fs::path& dir, const std::string& name,
                const SceneFiles& f, PlayerRuns player) {
  out << "<section id=\"" << escape(name) << "\"><h2>" << escape(name) << "</h2>\n";
  std::optional<RunRecord> run;
  if (f.has(".csv.json")) run = readRunRecord(dir / f.at(".csv.json"));
  const std::optional<nlohmann::json> theory = theoryOf(dir, f, run);
  writeOtherVersions(out, dir, f, run);
  writeVideos(out, f, theory, runsOfTheScene(dir, f, run));
  if (player != PlayerRuns::None) writePlayerPlace(out, name, theory, player);
  writeAnalysis(out, f, theory, run);
  writeMoreRuns(out, dir, f);
  for (const std::string& file : f.more_videos)
    writeVideoFigure(out, file, "", "metadata", escape(file));
  writeImages(out, f, kStillSuffixes, "Stills", f.more_stills);
  writeImages(out, f, kPlotSuffixes, "Against time");
  out << "</section>\n";
}

}  // namespace tasks::report

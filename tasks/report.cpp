#include "tasks/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "tasks/analysis.hpp"
#include "tasks/drawn_points.hpp"
#include "tasks/manifest.hpp"
#include "tasks/output.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"
#include "util/assets.hpp"
#include "util/format.hpp"
#include "util/output_place.hpp"

namespace tasks {
namespace {

namespace fs = std::filesystem;

const char* kVideoSuffixes[] = {"-preferred.mp4", "-reversed.mp4", "-ccw.mp4",
                                "-cw.mp4",        "-both.mp4",     ".mp4"};
// First frames of the reversed and preferred videos, used as their posters.
const char* kPosterSuffixes[] = {"-reversed.png", "-preferred.png", "-ccw.png", "-cw.png"};
const char* kStillSuffixes[] = {"-oblique.png", "-above.png", "-front.png", "-side.png",
                                "-follow.png"};
const char* kPlotSuffixes[] = {"-spin.png", "-energy.png", "-tilt.png", "-normal.png"};
const char* kDataSuffixes[] = {".csv.json", "-analysis.json", "-analysis.txt", ".csv"};

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// A file's name as an attribute's URL (href, src, poster): percent-encoded, then escaped. Its
// visible text (a caption, a heading) stays as escape() alone writes it.
std::string url(const std::string& file) {
  return escape(urlPath(file));
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// The files of one scene (by the name before a known suffix), found in DIR.
struct SceneFiles {
  std::map<std::string, std::string> by_suffix;  // suffix → file name
  // Videos and stills the manifest lists beyond one per slot (a scene rendered at several
  // sizes, stills at other times): shown too, not dropped.
  std::vector<std::string> more_videos, more_stills;
  // Telemetry the manifest lists beside the scene's main run (".csv": the scene's own
  // <scene>.csv, else the first by name), in name order: each listed with what it measured.
  std::vector<std::string> more_runs;
  // Stills' captions from the manifest (file name → "oblique view, t = 1 s, spun −4 rad/s").
  std::map<std::string, std::string> captions;
  // The scene each file was made from, as the manifest says (tasks::madeFrom), where it says.
  std::map<std::string, std::string> made_from;
  // Each video's spin, rad/s, as the manifest says, where it says.
  std::map<std::string, double> video_spins;
  bool has(const std::string& suffix) const { return by_suffix.count(suffix) > 0; }
  const std::string& at(const std::string& suffix) const { return by_suffix.at(suffix); }
};

std::optional<nlohmann::json> readJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

// j[key] when j is an object that holds it, else null: a hand-edited or foreign file then
// shows "–" in the page instead of stopping the report.
const nlohmann::json& field(const nlohmann::json& j, const char* key) {
  static const nlohmann::json none;
  if (!j.is_object()) return none;
  const auto it = j.find(key);
  return it == j.end() ? none : *it;
}

// j as text when it is a string, else `otherwise`.
std::string stringOr(const nlohmann::json& j, const std::string& otherwise) {
  return j.is_string() ? j.get<std::string>() : otherwise;
}

std::string number(const nlohmann::json& j, const char* format) {
  if (!j.is_number()) return "–";
  char text[64];
  std::snprintf(text, sizeof text, format, j.get<double>());
  return text;
}

std::string spinWords(double spin) {
  return spin > 0 ? "counter-clockwise" : spin < 0 ? "clockwise" : "no spin";
}

// Whether a run (simulate's sidecar's result) reversed, and when: every reversal, as the
// player's n(t) plot counts them (a new user's long run said only its first of 4), the first
// kReversalsNamed of more. A sidecar without the list gives its first.
std::string reversalOf(const nlohmann::json& result) {
  constexpr std::size_t kReversalsNamed = 4;
  std::vector<std::string> times;
  const nlohmann::json& all = field(result, "reversals_s");
  if (all.is_array())
    for (const nlohmann::json& t : all) times.push_back(number(t, "%.3f"));
  if (times.empty() && field(result, "first_reversal_s").is_number())
    times.push_back(number(field(result, "first_reversal_s"), "%.3f"));
  if (times.empty()) return "no reversal in " + number(field(result, "simulated_s"), "%g") + " s";
  if (times.size() == 1) return "<b>reversed at " + times[0] + " s</b>";
  const std::size_t named = std::min(times.size(), kReversalsNamed);
  std::string text = "<b>reversed " + std::to_string(times.size()) + " times</b>, ";
  text += named < times.size() ? "the first " + std::to_string(named) + " at " : "at ";
  for (std::size_t i = 0; i < named; ++i)
    text += times[i] + (i + 2 < named ? ", " : i + 2 == named ? " and " : " s");
  return text;
}

// A mode at rest (analyze's "frequencies_hz"): its frequency, or how fast it grows where it
// topples instead ("growth_rates_at_rest").
std::string restModeOf(const nlohmann::json& theory, const char* mode) {
  const nlohmann::json& hz = field(field(theory, "frequencies_hz"), mode);
  const nlohmann::json& growth = field(field(theory, "growth_rates_at_rest"), mode);
  if (hz.is_null() && growth.is_number())
    return "<b>unstable</b> (grows at " + number(growth, "%.3g") + " /s)";
  return number(hz, "%.2f") + " Hz";
}

// The first reversal the averaged theory predicts (analyze's "predicted_first_reversal").
std::string forecastOf(const nlohmann::json& theory) {
  const nlohmann::json& f = field(theory, "predicted_first_reversal");
  if (!f.is_object()) return "";
  std::string text = "<br>first reversal (averaged theory): ";
  if (field(f, "applies") == false) return text + "none: the body cannot stand";
  const std::string measures = " (n²ρ/g " + number(field(f, "spin_parameter"), "%.2g") +
                               ", rocking / spin energy " +
                               number(field(f, "energy_ratio"), "%.2g") + ")";
  if (field(f, "range") == "outside") return text + "outside its range" + measures;
  if (!field(f, "time_s").is_number())
    return text + "none within " + number(field(f, "within_s"), "%g") + " s" + measures;
  return text + "<b>" + number(field(f, "time_s"), "%.2f") + " s</b>" + measures +
         (field(f, "range") == "within"
              ? ", within its range: within about 1.5 %"
              : std::string(", beyond its range: ") + kBeyondRangeError + " in the runs measured");
}

// The run's estimated errors (simulate --check, its sidecar's "check"); empty without one.
std::string checkOf(const nlohmann::json& check) {
  if (!check.is_object()) return "";
  std::string text = "<br>estimated error (<code>--check</code>, against " +
                     escape(stringOr(field(check, "setting"), "a tighter run")) + "): ";
  const nlohmann::json& errors = field(check, "reversal_errors_s");
  if (errors.is_array() && !errors.empty()) {
    text += errors[0].is_number()
                ? "first reversal ±" + number(std::abs(errors[0].get<double>()), "%.2g") + " s, "
                : "first reversal <b>not converged</b> (the tighter run has none), ";
  }
  const nlohmann::json& spin = field(check, "spin_error_rad_s");
  return text + "n(t) ±" + (spin.is_number() ? number(std::abs(spin.get<double>()), "%.2g") : "–") +
         " rad/s";
}

// What simulate measured (its sidecar's result), when its run was spun counter-clockwise
// (`ccw`) or clockwise as a video was; empty otherwise.
std::string measuredAs(const std::optional<nlohmann::json>& run, bool ccw) {
  if (!run) return "";
  const nlohmann::json& r = field(*run, "result");
  const nlohmann::json& spin = field(r, "initial_spin");
  if (!spin.is_number() || spin == 0 || (spin > 0) != ccw) return "";
  return "<br>measured (<code>simulate</code>, " + number(spin, "%+.3g") +
         " rad/s): " + reversalOf(r);
}

// What the theory predicts of a spin the preferred way: by the definition of preferred, that
// its rocking grows more slowly, if at all; not that it never reverses ("keeps turning" sat under
// a video of deep dents that reversed at 4.5 s, as their forecast said: a teacher's trial).
constexpr const char* kPreferredWay =
    "the theory predicts its rocking grows more slowly this way, if at all, so it turns longer "
    "before any reversal";

// The videos, each captioned with what the theory predicts for its direction and, where
// simulate's run was spun the same way, what that run did: the theory is linear and holds
// near upright, and a body that loses no energy can reverse both ways, so the page never says
// what the videos show without a run that measured it.
void writeVideos(std::ostream& out, const SceneFiles& f,
                 const std::optional<nlohmann::json>& theory,
                 const std::optional<nlohmann::json>& run) {
  // A video's poster is its own first frame (NAME-reversed.png for NAME-reversed.mp4, as the
  // main job renders with `still --spin`), when the run left one; otherwise the browser shows
  // the video's first frame once loaded.
  auto video = [&](const std::string& file, const std::string& poster_suffix,
                   const std::string& caption) {
    const std::string poster = f.has(poster_suffix) ? f.at(poster_suffix) : "";
    out << "<figure><video src=\"" << url(file) << "\" muted loop playsinline controls "
        << "preload=\"auto\"" << (poster.empty() ? "" : " poster=\"" + url(poster) + "\"")
        << "></video><figcaption>" << caption << "</figcaption></figure>\n";
  };
  // The preferred direction as analyze found it (render --both names its videos the same way).
  std::optional<bool> ccw_preferred;
  if (theory) {
    const nlohmann::json& preferred = field(*theory, "preferred");
    if (preferred == "ccw" || preferred == "cw") ccw_preferred = preferred == "ccw";
  }
  auto measured = [&](bool preferred) {
    return ccw_preferred ? measuredAs(run, preferred == *ccw_preferred) : std::string();
  };
  // Which way and how fast a video was spun, as the manifest says: " (clockwise, −5 rad/s)".
  // A video's spin as the manifest lists it: none where it does not (or says 0).
  auto spinOf = [&](const std::string& file) -> std::optional<double> {
    const auto spin = f.video_spins.find(file);
    if (spin == f.video_spins.end() || spin->second == 0) return std::nullopt;
    return spin->second;
  };
  auto rads = [](double spin) { return number(spin, "%+.3g") + " rad/s"; };
  auto spun = [&](const std::string& file) {
    const auto spin = spinOf(file);
    return spin ? " (" + spinWords(*spin) + ", " + rads(*spin) + ")" : std::string();
  };
  if (f.has("-reversed.mp4") || f.has("-preferred.mp4")) {
    out << "<div class=\"pair\">\n";
    if (f.has("-reversed.mp4"))
      video(f.at("-reversed.mp4"), "-reversed.png",
            "Spun the <b>reversing</b> way" + spun(f.at("-reversed.mp4")) +
                ": the theory predicts it rocks, stops and spins back" + measured(false));
    if (f.has("-preferred.mp4"))
      video(f.at("-preferred.mp4"), "-preferred.png",
            "Spun the <b>preferred</b> way" + spun(f.at("-preferred.mp4")) + ": " + kPreferredWay +
                measured(true));
    out << "</div>\n";
  }
  // A body with no preferred direction: its videos are named by their spins.
  if (f.has("-ccw.mp4") || f.has("-cw.mp4")) {
    out << "<div class=\"pair\">\n";
    for (const auto& [suffix, ccw] : {std::pair{"-cw", false}, std::pair{"-ccw", true}})
      if (f.has(std::string(suffix) + ".mp4"))
        video(f.at(std::string(suffix) + ".mp4"), std::string(suffix) + ".png",
              std::string("Spun <b>") + (ccw ? "counter-clockwise" : "clockwise") +
                  "</b>: the theory prefers neither direction" + measuredAs(run, ccw));
    out << "</div>\n";
  }
  // A video alone: its spin, which way, what the theory predicts that way and what a run spun
  // so measured ("The scene as rendered" said none of these; a teacher's trial).
  if (f.has(".mp4")) {
    std::string caption = "The scene as rendered";
    if (const auto spin = spinOf(f.at(".mp4"))) {
      const bool ccw = *spin > 0;
      caption = "Spun <b>" + spinWords(*spin) + "</b> (" + rads(*spin) + ")";
      if (ccw_preferred)
        caption += ": " + std::string(ccw == *ccw_preferred
                                          ? kPreferredWay
                                          : "the theory predicts it rocks, stops and spins back");
      caption += measuredAs(run, ccw);
    }
    video(f.at(".mp4"), "-single.png", caption);
  }
  if (f.has("-both.mp4"))
    out << "<p><a href=\"" << url(f.at("-both.mp4"))
        << "\">Both side by side in one video</a></p>\n";
}

// What a run measured (simulate's sidecar): its spin, reversal, final spin, energy and check.
std::string measuredOf(const nlohmann::json& run) {
  const nlohmann::json& r = field(run, "result");
  const nlohmann::json& spin = field(r, "initial_spin");
  std::ostringstream out;
  // The values put in over the scene file (--set, with_values), which make this run's body:
  // a class's variants of one scene each said only the scene's name.
  const nlohmann::json& values = field(run, "scene_values");
  if (values.is_array() && !values.empty()) {
    out << "values put in: ";
    for (std::size_t i = 0; i < values.size(); ++i)
      out << (i ? ", " : "") << "<code>"
          << escape(stringOr(field(values[i], "key"), "?") + " = " +
                    stringOr(field(values[i], "value"), "?"))
          << "</code>";
    out << "<br>";
  }
  // How long, and how often sampled: runs of one scene told apart by these said the same (a
  // researcher's 10 s run at 10 kHz beside the 8 s one; a researcher's trial).
  const nlohmann::json& simulated = field(r, "simulated_s");
  const nlohmann::json& rate = field(run, "rate_hz");
  out << "spun " << number(spin, "%+.3g") << " rad/s ("
      << spinWords(spin.is_number() ? spin.get<double>() : 0.0) << ")"
      << (simulated.is_number() ? ", " + number(simulated, "%.4g") + " s" : std::string())
      << (rate.is_number() ? " at " + number(rate, "%.4g") + " samples/s" : std::string()) << "<br>"
      << reversalOf(r) << "<br>final spin " << number(field(r, "final_spin"), "%+.3f")
      << " rad/s<br>energy " << number(field(field(r, "energy_j"), "initial"), "%.4g") << " J → "
      << number(field(field(r, "energy_j"), "final"), "%.4g") << " J";
  // What simulate's summary warned of, where the page is read without it (a teacher's trial:
  // a step too large showed as "no reversal in 5 s" with nothing said).
  const nlohmann::json& warnings = field(r, "warnings");
  if (warnings.is_array())
    for (const nlohmann::json& w : warnings)
      out << "<br><span class=\"warning\">⚠ " << escape(stringOr(field(w, "text"), "?"))
          << "</span>";
  out << checkOf(field(run, "check"));
  return out.str();
}

// The scene's other runs (SceneFiles::more_runs), each a row: its CSV and what it measured.
// Runs are grouped by their scene file's stem: a run of another file of the same name (a
// course's week1/top.yaml and week2/top.yaml into one folder) says which file it ran, where
// the main run's sidecar names another (a CI maintainer's trial: it read as a variant of the
// main run's scene).
void writeMoreRuns(std::ostream& out, const fs::path& dir, const SceneFiles& f) {
  if (f.more_runs.empty()) return;
  std::string main_file, main_named;  // its path, and its name as given
  if (f.has(".csv"))
    if (const auto main = readJson(dir / (f.at(".csv") + ".json"))) {
      main_file = stringOr(field(*main, "scene_path"), "");
      main_named = stringOr(field(*main, "scene"), main_file);
    }
  out << "<h3>Other runs</h3><table><tr><th>telemetry</th><th>measured (simulate)</th></tr>\n";
  for (const std::string& csv : f.more_runs) {
    const std::optional<nlohmann::json> run = readJson(dir / (csv + ".json"));
    std::string file_note;
    if (run && !main_file.empty()) {
      const std::string file = stringOr(field(*run, "scene_path"), "");
      if (!file.empty() && file != main_file)
        file_note = "<b>another file</b>: <code>" + escape(stringOr(field(*run, "scene"), file)) +
                    "</code> (the main run's: <code>" + escape(main_named) + "</code>)<br>";
    }
    // Its own figures (simulate --plot names them after its table), where they are: the spin's
    // shown, the others linked (a teacher's trial: a run spun the other way was a row of text,
    // its four figures listed in the manifest and nowhere on the page).
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
    const std::string figures = thumb + (links.empty() ? "" : "<br>" + links);
    out << "<tr><td><a href=\"" << url(csv) << "\">" << escape(csv) << "</a></td><td>" << file_note
        << (run ? measuredOf(*run) : "–") << figures << "</td></tr>\n";
  }
  out << "</table>\n";
}

// Theory (analyze --json) beside what the run measured (simulate's sidecar).
void writeAnalysis(std::ostream& out, const SceneFiles& f,
                   const std::optional<nlohmann::json>& theory,
                   const std::optional<nlohmann::json>& run) {
  // An analysis as text alone (analyze -o NAME.txt, listed in the manifest) is linked, not
  // dropped: its scene's section was empty.
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
  if (theory) {
    const nlohmann::json& t = *theory;
    const nlohmann::json& preferred = field(t, "preferred");
    const bool topples = preferred.is_null() && field(t, "rest_stable") == false;
    out << "preferred direction: <b>"
        << (preferred == "ccw"    ? "counter-clockwise"
            : preferred == "cw"   ? "clockwise"
            : preferred == "none" ? "none"
            : topples             ? "none: the body cannot stand"
                                  : "–")
        << "</b><br>growth rates at n = " << number(field(t, "spin"), "%+g") << " rad/s: roll "
        << number(field(field(t, "growth_rates"), "roll"), "%+.3f") << " /s, pitch "
        << number(field(field(t, "growth_rates"), "pitch"), "%+.3f")
        << " /s<br>rocking at rest: roll " << restModeOf(t, "roll") << ", pitch "
        << restModeOf(t, "pitch") << "<br>misalignment "
        << number(field(t, "misalignment_deg"), "%+.2f") << "°; "
        << (field(t, "rest_stable") == true    ? "stands upright"
            : field(t, "rest_stable") == false ? "<b>cannot stand upright</b>"
                                               : "upright: –")
        << forecastOf(t);
    if (!full_analysis.empty()) out << "<br>";
  }
  out << full_analysis;
  out << "</td><td>";
  if (run) out << measuredOf(*run);
  if (f.has(".csv"))
    out << (run ? "<br>" : "") << "<a href=\"" << url(f.at(".csv")) << "\">telemetry (CSV)</a>";
  out << "</td></tr></table>\n";
}

// A number for a caption: %g, with U+2212 for its minus sign as the plots' tic labels have.
std::string shown(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text[0] == '-' ? "\u2212" + std::string(text + 1) : text;
}

// What a still shows, from its manifest entry: "oblique view, t = 1 s, spun −4 rad/s".
std::string stillCaption(const OutputEntry& e) {
  std::string caption = (e.role.empty() ? std::string("a") : e.role) + " view";
  if (e.t) caption += ", t = " + shown(*e.t) + " s";
  if (e.spin) caption += *e.spin == 0 ? ", not spun" : ", spun " + shown(*e.spin) + " rad/s";
  return caption;
}

// What a plot against time shows, by its suffix; else "" (the file's name is shown).
std::string plotCaption(const std::string& file) {
  const std::pair<const char*, const char*> plots[] = {
      {"-spin.png", "spin n against time"},
      {"-energy.png", "energy against time"},
      {"-tilt.png", "tilt against time"},
      {"-normal.png", "normal force against time"}};
  for (const auto& [suffix, caption] : plots)
    if (endsWith(file, suffix)) return caption;
  return "";
}

// An image linked to itself, captioned (its file name when there is no caption), with the
// caption as its alt text: a bare file name told a reader nothing of what the still shows.
void writeFigure(std::ostream& out, const std::string& file, const std::string& caption,
                 const char* loading = "eager") {
  const std::string text = caption.empty() ? file : caption;
  out << "<figure><a href=\"" << url(file) << "\"><img src=\"" << url(file) << "\" alt=\""
      << escape(text) << "\" loading=\"" << loading << "\"></a><figcaption>" << escape(text)
      << (caption.empty() ? "" : " (<a href=\"" + url(file) + "\">" + escape(file) + "</a>)")
      << "</figcaption></figure>\n";
}

void writeImages(std::ostream& out, const SceneFiles& f, const char* const* suffixes,
                 std::size_t count, const char* heading,
                 const std::vector<std::string>& more = {}) {
  std::vector<std::string> files;
  for (std::size_t i = 0; i < count; ++i)
    if (f.has(suffixes[i])) files.push_back(f.at(suffixes[i]));
  files.insert(files.end(), more.begin(), more.end());
  if (files.empty()) return;
  out << "<h3>" << heading << "</h3><div class=\"grid\">\n";
  for (const std::string& file : files) {
    const auto listed = f.captions.find(file);
    writeFigure(out, file, listed != f.captions.end() ? listed->second : plotCaption(file));
  }
  out << "</div>\n";
}

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

// The files of a folder, placed: by scene, the sweeps, and the rest.
struct SweepFiles {
  std::string name, csv;
  nlohmann::json meta;
  std::vector<std::string> images;
  std::vector<std::string> parts;  ///< the shard tables merged into it, found in the folder
};
struct Folder {
  std::map<std::string, SceneFiles> scenes;
  std::vector<SweepFiles> sweeps;
  std::vector<std::string> others;
};

// The slot of the page a manifest entry fills: the suffix a file of that role has when named
// as scripts/run.sh names it. Videos' spins say which stills are their posters.
std::optional<std::string> slotOf(const OutputEntry& e,
                                  const std::map<double, std::string>& video_spins) {
  switch (e.kind) {
    case OutputKind::Video:
      if (e.role == "preferred" || e.role == "reversed" || e.role == "ccw" || e.role == "cw" ||
          e.role == "both")
        return "-" + e.role + ".mp4";
      return ".mp4";
    case OutputKind::Still:
      if (e.t && *e.t == 0 && e.spin && video_spins.count(*e.spin))
        return "-" + video_spins.at(*e.spin) + ".png";
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

// Places the files the manifest lists; returns the names it placed.
std::set<std::string> placeListed(const fs::path& dir, Folder& folder) {
  const std::vector<OutputEntry> entries = readManifest(dir.string());
  std::map<std::string, std::map<double, std::string>> video_spins;  // scene → spin → role
  for (const OutputEntry& e : entries)
    if (e.kind == OutputKind::Video && e.spin && e.role != "both" && e.role != "single")
      video_spins[e.scene][*e.spin] = e.role;
  std::map<std::string, std::set<double>> single_spins;  // scene → spins of lone videos
  for (const OutputEntry& e : entries)
    if (e.kind == OutputKind::Video && e.spin && e.role == "single")
      single_spins[e.scene].insert(*e.spin);
  std::map<std::string, std::vector<std::string>> runs;  // scene → its telemetry
  std::set<std::string> placed;
  std::error_code ec;
  for (const OutputEntry& e : entries) {
    if (!fs::is_regular_file(dir / e.file, ec)) continue;  // since removed
    if (e.kind == OutputKind::Still) folder.scenes[e.scene].captions[e.file] = stillCaption(e);
    if (e.kind == OutputKind::Video && e.spin) folder.scenes[e.scene].video_spins[e.file] = *e.spin;
    if (!e.made_from.empty()) folder.scenes[e.scene].made_from[e.file] = e.made_from;
    if (e.kind == OutputKind::Telemetry) {
      runs[e.scene].push_back(e.file);
      placed.insert(e.file);
      if (fs::is_regular_file(dir / (e.file + ".json"), ec)) placed.insert(e.file + ".json");
      continue;
    }
    // A lone video's poster: a still at t = 0 spun as it was (whatever its view).
    if (e.kind == OutputKind::Still && e.t && *e.t == 0 && e.spin &&
        single_spins[e.scene].count(*e.spin)) {
      SceneFiles& f = folder.scenes[e.scene];
      if (!f.has("-single.png")) f.by_suffix["-single.png"] = e.file;
    }
    if (e.kind == OutputKind::Bench || e.kind == OutputKind::BenchPlot) {
      folder.others.push_back(e.file);
    } else if (e.kind == OutputKind::Sweep || e.kind == OutputKind::SweepPlot) {
      continue;  // sweeps are found by their sidecars, their plots by name (below)
    } else if (auto slot = slotOf(e, video_spins[e.scene])) {
      SceneFiles& f = folder.scenes[e.scene];
      const bool media = e.kind == OutputKind::Video || e.kind == OutputKind::Still;
      if (media && f.has(*slot) && f.at(*slot) != e.file) {  // the slot's first keeps it
        (e.kind == OutputKind::Video ? f.more_videos : f.more_stills).push_back(e.file);
        placed.insert(e.file);
        continue;
      }
      f.by_suffix[*slot] = e.file;
    }
    placed.insert(e.file);
  }
  // Each scene's main run is its own <scene>.csv, else the first by name (not the last
  // written); the others are listed beside it.
  for (auto& [scene, files] : runs) {
    std::sort(files.begin(), files.end());
    auto main = std::find(files.begin(), files.end(), scene + ".csv");
    if (main == files.end()) main = files.begin();
    SceneFiles& f = folder.scenes[scene];
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
  return placed;
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

// A sweep's table (its sidecar says so), with its heatmaps NAME.png and NAME-*.png; a CSV of its
// own (bench.csv) is no scene: it goes with the other files.
void separateSweeps(const fs::path& dir, Folder& folder) {
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
  attachShards(folder.sweeps);
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

// The player's bundle, in the assets (player/CMakeLists.txt), copied beside the page.
constexpr const char* kPlayerBundle = "rattleback-player.js";

// The scene file a telemetry sidecar names: its absolute path, else as given (from here, then
// from the folder).
std::optional<std::string> sceneOf(const nlohmann::json& sidecar, const fs::path& dir) {
  std::error_code ec;
  for (const char* key : {"scene_path", "scene"}) {
    const std::string path = stringOr(field(sidecar, key), "");
    if (path.empty()) continue;
    if (fs::is_regular_file(path, ec)) return path;
    if (fs::is_regular_file(dir / path, ec)) return (dir / path).string();
  }
  return std::nullopt;
}

// The poses of a telemetry CSV (the columns t, x, y, z, qw … qz, spin, found by the header);
// none for a CSV without them (written before the attitude was).
std::vector<Pose> posesOf(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return {};
  const char* wanted[] = {"t", "x", "y", "z", "qw", "qx", "qy", "qz", "spin"};
  std::vector<int> index(std::size(wanted), -1);
  std::stringstream head(line);
  std::string name;
  for (int i = 0; std::getline(head, name, ','); ++i)
    for (std::size_t w = 0; w < std::size(wanted); ++w)
      if (name == wanted[w]) index[w] = i;
  if (std::count(index.begin(), index.end(), -1) > 0) return {};
  std::vector<Pose> poses;
  std::vector<double> fields;
  while (std::getline(in, line)) {
    fields.clear();
    for (const char* p = line.c_str(); *p;) {
      char* end = nullptr;
      fields.push_back(std::strtod(p, &end));
      p = std::strchr(end, ',');
      if (!p) break;
      ++p;
    }
    auto at = [&](std::size_t w) {
      return static_cast<std::size_t>(index[w]) < fields.size() ? fields[index[w]] : NAN;
    };
    poses.push_back({at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), at(8)});
  }
  return poses;
}

// Whether the scene file no longer describes the run its sidecar recorded: its content's
// fingerprint differs from the one simulate wrote, or, in a sidecar older than that key, the
// body's mass does, the only body parameter such a sidecar records (a relative 1e-9: the same
// file gives the same mass to the last digit). Without either, the scene is taken as it is. The
// player would otherwise draw the body as it is now, moving as the old one did.
bool sceneChangedSince(const nlohmann::json& sidecar, const std::string& scene_path,
                       const sim::Model& model) {
  const nlohmann::json& fingerprint = field(sidecar, "scene_fingerprint");
  if (fingerprint.is_string()) return fingerprint != sceneFingerprint(scene_path);
  const nlohmann::json& mass = field(field(sidecar, "model"), "mass_kg");
  if (!mass.is_number()) return false;
  return std::abs(mass.get<double>() - model.body->mass) > 1e-9 * std::abs(model.body->mass);
}

// The model of a run's scene, or why there is none to replay it on: `why` completes "SCENE …"
// for the line `report` prints ("has changed since this run was simulated: …"), empty where there
// is nothing to say (no scene named: the page then has no player, as for a run made from a
// string).
struct RunModel {
  std::optional<sim::Model> model;
  std::string scene;  ///< the scene file's path, where one was found
  std::string why;
  double frame = 0;  ///< m: the scene's video.frame for the player (playerFrame)
};

// The model of the scene a telemetry sidecar names, with the values the run put in over it
// (scene_values: --set, Python's with_values), when that scene can be read and still describes
// the run (sceneChangedSince).
RunModel runModelOf(const nlohmann::json& sidecar, const fs::path& dir) {
  if (field(sidecar, "command") != "simulate") return {};
  // A scene made from text (Python's from_yaml, from_dict; scene_path null) has no file to replay
  // the run on: a file of its name here is another scene, and there is nothing to say.
  if (sidecar.contains("scene_path") && sidecar["scene_path"].is_null()) return {};
  const auto scene_path = sceneOf(sidecar, dir);
  // A scene read from a file when it ran (it has a fingerprint) that is not there now: moved or
  // removed (a run made from a string has none, and nothing to say).
  if (!scene_path) {
    if (!field(sidecar, "scene_fingerprint").is_string()) return {};
    return {std::nullopt, stringOr(field(sidecar, "scene_path"), ""),
            "is not there any more: no 3D player for it (simulate it again to replay it)"};
  }
  RunModel out{std::nullopt, *scene_path, ""};
  std::vector<scene::KeyValue> values;
  const nlohmann::json& put = field(sidecar, "scene_values");
  if (put.is_array())
    for (const nlohmann::json& kv : put) {
      const nlohmann::json &key = field(kv, "key"), &value = field(kv, "value");
      if (!key.is_string() || !value.is_string()) return out;  // not a sidecar of ours
      values.push_back({key.get<std::string>(), value.get<std::string>()});
    }
  const auto text = scene::readSceneFile(*scene_path);
  if (!text) return out;
  const std::string changed =
      "has changed since this run was simulated: no 3D player for it (simulate it again to "
      "replay it)";
  // Its content first: an edited scene has changed, whether or not it still loads.
  const nlohmann::json& fingerprint = field(sidecar, "scene_fingerprint");
  if (fingerprint.is_string() && fingerprint != sceneFingerprint(*scene_path)) {
    out.why = changed;
    return out;
  }
  // The same content that no longer loads: this rattleback reads it otherwise than the one
  // that ran it (a key since renamed, a check since added); its own error line says how. (A
  // sidecar from before the fingerprint cannot tell that from an edit.)
  auto loaded = scene::loadWithValues(text.value(), *scene_path, values, "scene_values");
  auto model = loaded ? scene::loadModel(loaded.value()) : rb::Result<sim::Model>(loaded.error());
  if (!model) {
    out.why = std::string(fingerprint.is_string() ? "no longer loads in this rattleback ("
                                                  : "no longer loads (") +
              model.error().text() +
              "): no 3D player for it (mend the scene and simulate it again to replay it)";
    return out;
  }
  if (sceneChangedSince(sidecar, *scene_path, model.value())) {
    out.why = changed;
    return out;
  }
  out.frame = playerFrame(loaded.value(), model.value());
  out.model = std::move(model).value();
  return out;
}

// DIR/<id>.player.js for a scene with telemetry: its poses, reversals and drawn points; false
// (the page then has no player for it) when the CSV, its sidecar or its scene cannot be read;
// an error when the file cannot be written.
rb::Result<bool> writePlayerData(const fs::path& dir, const std::string& id, const SceneFiles& f,
                                 std::optional<double> drawn_frame,
                                 std::vector<std::string>& notes) {
  if (!f.has(".csv") || !f.has(".csv.json")) return false;
  const std::optional<nlohmann::json> sidecar = readJson(dir / f.at(".csv.json"));
  if (!sidecar || field(*sidecar, "command") != "simulate") return false;
  const RunModel found = runModelOf(*sidecar, dir);
  const std::optional<sim::Model>& model = found.model;
  if (!model) {
    if (!found.why.empty())
      notes.push_back((dir / f.at(".csv")).string() + ": " + found.scene + " " + found.why);
    // The data an earlier report wrote for this run would replay it on another body.
    std::error_code ec;
    fs::remove(dir / (id + ".player.js"), ec);
    return false;
  }
  PlayerRun run;
  run.id = id;
  run.title = id;
  run.points = drawnPointsOf(*model);
  // Framed as the scene's videos and stills were drawn (--frame), else as its video.frame says.
  run.frame = drawn_frame.value_or(found.frame);
  run.poses = thinPoses(posesOf(dir / f.at(".csv")));
  if (run.poses.size() < 2) return false;
  const nlohmann::json& reversals = field(field(*sidecar, "result"), "reversals_s");
  if (reversals.is_array())
    for (const auto& r : reversals)
      if (r.is_number()) run.reversals.push_back(r.get<double>());
  auto out = AtomicOutput::open((dir / (id + ".player.js")).string());
  if (!out) return out.error();
  out->stream() << playerScript(run);
  if (auto e = out->commit(); !e) return e.error();
  return true;
}

// The bundle copied beside the page; false when the build made none (no node and npm), an
// error when it cannot be written (a full disk, a file-size limit: the page was written without
// its players, and nothing said; a teacher's trial).
rb::Result<bool> copyPlayerBundle(const fs::path& dir) {
  std::ifstream in(fs::path(rb::assetsDir()) / "player" / kPlayerBundle, std::ios::binary);
  if (!in) return false;
  auto out = AtomicOutput::open((dir / kPlayerBundle).string());
  if (!out) return out.error();
  // Read whole, then written: `<< rdbuf()` stops quietly at a failed write once it has written
  // anything (no failbit), and a bundle cut at a file-size limit stood as whole.
  const std::string bundle((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  out->stream().write(bundle.data(), static_cast<std::streamsize>(bundle.size()));
  if (auto e = out->commit(); !e) return e.error();
  return true;
}

// The videos, stills, figures and analyses shown for a scene that were made from another
// version of it than its run (the file edited since, or other values put in), named above
// them: a teacher edited a scene and ran simulate again, and the page showed the old videos
// and stills beside the new run's numbers, with nothing said.
void writeOtherVersions(std::ostream& out, const SceneFiles& f,
                        const std::optional<nlohmann::json>& run) {
  const std::string run_made_from = run ? madeFrom(*run) : "";
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
  out << ". Make them again from the scene and values the run used.</p>\n";
}

void writeScene(std::ostream& out, const fs::path& dir, const std::string& name,
                const SceneFiles& f, bool player) {
  out << "<section id=\"" << escape(name) << "\"><h2>" << escape(name) << "</h2>\n";
  std::optional<nlohmann::json> theory, run;
  if (f.has("-analysis.json")) theory = readJson(dir / f.at("-analysis.json"));
  if (f.has(".csv.json")) run = readJson(dir / f.at(".csv.json"));
  // The theory of the run's own scene (its file, the values put in over it) at the run's spin,
  // as analyze --json would write it, whenever the run's scene can be had: the folder's
  // analyze --json may be of another body or spin (a student's --set run beside the base
  // scene's analysis was shown the base's forecast, 2.12 s, beside its own 1.689 s), or there
  // may be none (a user who ran simulate and render), which left the predicted column empty.
  // The folder's analysis stands in only for a run whose scene cannot be had.
  if (run)
    if (const std::optional<sim::Model> model = runModelOf(*run, dir).model) {
      const nlohmann::json& spin = field(field(field(*run, "model"), "initial"), "spin");
      theory = analysisJson(
          *model, analysisSpin(
                      *model, spin.is_number() ? std::optional(spin.get<double>()) : std::nullopt));
    }
  writeOtherVersions(out, f, run);
  writeVideos(out, f, theory, run);
  if (player) {
    // The averaged theory's forecast first reversal, for the player's n(t) plot
    // (player/README.md: data-forecast; the player marks it when it applies).
    std::string forecast;
    if (theory && field(*theory, "predicted_first_reversal").is_object())
      forecast =
          " data-forecast=\"" + escape(field(*theory, "predicted_first_reversal").dump()) + "\"";
    out << "<h3>Turn it around</h3><p>The run replayed in 3D: drag to orbit, scroll to zoom, "
           "space plays and pauses, arrows step.</p><div class=\"rb-player\" data-run=\""
        << escape(name) << "\"" << forecast << "></div>\n";
  }
  writeAnalysis(out, f, theory, run);
  writeMoreRuns(out, dir, f);
  for (const std::string& file : f.more_videos)
    out << "<figure><video src=\"" << url(file) << "\" muted loop playsinline controls "
        << "preload=\"metadata\"></video><figcaption>" << escape(file)
        << "</figcaption></figure>\n";
  writeImages(out, f, kStillSuffixes, std::size(kStillSuffixes), "Stills", f.more_stills);
  writeImages(out, f, kPlotSuffixes, std::size(kPlotSuffixes), "Against time");
  out << "</section>\n";
}

// The base scene as the sweep file names it, not as the machine that ran it resolved it (an
// absolute path of that machine); a sidecar from before `base_as_written` has only that.
std::string baseAsNamed(const nlohmann::json& meta) {
  const std::string written = stringOr(field(meta, "base_as_written"), "");
  return written.empty() ? stringOr(field(meta, "base"), "?") : written;
}

// The sweep's runs: the product of its axes' sizes.
long long sweepRows(const nlohmann::json& meta) {
  long long rows = 1;
  const nlohmann::json& axes = field(meta, "axes");
  for (std::size_t i = 0; axes.is_array() && i < axes.size(); ++i) {
    const nlohmann::json& values = field(axes[i], "values");
    rows *= values.is_array() ? static_cast<long long>(values.size()) : 0;
  }
  return rows;
}

void writeSweep(std::ostream& out, const SweepFiles& sweep) {
  const nlohmann::json& shard = field(sweep.meta, "shard");
  out << "<section id=\"sweep-" << escape(sweep.name) << "\"><h2>Sweep: " << escape(sweep.name)
      << "</h2>\n<p>" << number(field(sweep.meta, "rows"), "%g")
      << (field(sweep.meta, "rows") == 1 ? " run of " : " runs of ");
  if (shard.is_object())
    out << "the sweep's " << sweepRows(sweep.meta) << " (shard "
        << number(field(shard, "index"), "%g") << " of " << number(field(shard, "count"), "%g")
        << ", not merged here) of ";
  const std::string sweep_file = stringOr(field(sweep.meta, "sweep"), "");
  out << "<code>" << escape(baseAsNamed(sweep.meta)) << "</code>"
      << (sweep_file.empty() ? std::string()
                             : " (the base scene of <code>" +
                                   escape(fs::path(sweep_file).filename().string()) + "</code>)")
      << " over ";
  const nlohmann::json& axes = field(sweep.meta, "axes");
  for (std::size_t i = 0; axes.is_array() && i < axes.size(); ++i) {
    const nlohmann::json& values = field(axes[i], "values");
    out << (i ? " × " : "") << "<code>" << escape(stringOr(field(axes[i], "key"), "?"))
        << "</code> ("
        << rb::counted(values.is_array() ? static_cast<long long>(values.size()) : 0, "value")
        << ")";
  }
  out << ": <a href=\"" << url(sweep.csv) << "\">the table (CSV)</a>";
  if (!sweep.parts.empty()) {
    out << "; merged from " << sweep.parts.size() << " shard"
        << (sweep.parts.size() == 1 ? "" : "s") << ":";
    for (const std::string& part : sweep.parts)
      out << " <a href=\"" << url(part) << "\">" << escape(part) << "</a>";
  }
  // Heatmaps wider than the stills' grid (900 px drawn: at 300 their labels could not be read;
  // a researcher's trial).
  out << "</p><div class=\"grid wide\">\n";
  for (const std::string& image : sweep.images) writeFigure(out, image, "");
  out << "</div></section>\n";
}

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
// beside share/rattleback) when this program is installed (a CI maintainer's trial: the page of
// an installed report pointed to the source's docs/), else the source's.
std::string documentationWhere() {
  const std::string installed = rb::docsDir();
  if (!installed.empty())
    return "<code>" + escape(installed) +
           "/</code> where rattleback is installed (<code>getting-started.md</code> first)";
  return "<code>docs/</code> in rattleback's source (<code>docs/getting-started.md</code> first; "
         "<code>bash scripts/docs.sh</code> builds it as a site)";
}

void writePage(std::ostream& out, const fs::path& dir, const Folder& folder,
               const std::vector<std::string>& players) {
  out << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
         "<meta name=\"viewport\" content=\"width=device-width\">"
         "<title>rattleback: results</title><style>"
      << kStyle << "</style></head><body>\n<h1>rattleback: results</h1>\n"
      << "<p>What the runs left in this folder, by scene. Made by rattleback " RATTLEBACK_VERSION
         " (<code>rattleback report</code>). What each figure means: the documentation, "
      << documentationWhere() << ".</p>\n";
  // Scenes with videos first, then the rest, each in name order.
  std::vector<std::string> order;
  for (const auto& [name, files] : folder.scenes)
    if (files.has("-reversed.mp4") || files.has("-preferred.mp4") || files.has("-ccw.mp4") ||
        files.has("-cw.mp4") || files.has(".mp4"))
      order.push_back(name);
  for (const auto& [name, files] : folder.scenes)
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  for (const std::string& name : order)
    writeScene(out, dir, name, folder.scenes.at(name),
               std::find(players.begin(), players.end(), name) != players.end());
  for (const SweepFiles& sweep : folder.sweeps) writeSweep(out, sweep);
  writeOthers(out, folder.others);
  // Classic scripts (a page opened from disk may not import modules or fetch): each run's
  // data, then the player, which finds every .rb-player.
  for (const std::string& id : players)
    out << "<script src=\"" << url(id + ".player.js") << "\"></script>\n";
  if (!players.empty()) out << "<script src=\"" << url(kPlayerBundle) << "\"></script>\n";
  out << "</body></html>\n";
}

}  // namespace

std::string urlPath(const std::string& name) {
  const char* hex = "0123456789ABCDEF";
  std::string out;
  for (const unsigned char c : name) {
    const bool kept = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (kept)
      out += static_cast<char>(c);
    else
      out += {'%', hex[c >> 4], hex[c & 15]};
  }
  return out;
}

rb::Result<ReportPage> writeReport(const std::string& folder_path) {
  const fs::path dir = folder_path;
  std::error_code ec;
  // A name that is not there is said as such ("not a folder" read as if it were a file; a
  // teacher's trial).
  if (!fs::is_directory(dir, ec))
    return rb::Error{"", folder_path +
                             (fs::exists(dir, ec) ? ": not a folder" : ": no such folder") +
                             " (give the folder the runs wrote into, e.g. out)"};
  // `report` takes a folder, not -o: the way out of a folder it cannot write in says so.
  const rb::OutputNamedBy naming("rattleback report", "a folder");
  Folder folder;
  placeByName(dir, placeListed(dir, folder), folder);
  separateSweeps(dir, folder);
  // The page's place first: a folder where no file can be made is said as the page's (the
  // player's files would otherwise be the first to fail).
  const std::string path = (dir / "index.html").string();
  auto opened = AtomicOutput::open(path);
  if (!opened) return opened.error();
  std::vector<std::string> players, notes;
  const rb::Result<bool> bundle = copyPlayerBundle(dir);
  if (!bundle) return bundle.error();
  if (bundle.value()) {
    // The frame each scene's videos (else stills) were drawn at, where one was asked for (a
    // teacher's trial: videos drawn with --frame at one scale beside players that each filled
    // their picture with their own body).
    std::map<std::string, std::optional<double>> drawn;
    const std::vector<OutputEntry> listed = readManifest(dir.string());
    for (const OutputKind kind : {OutputKind::Video, OutputKind::Still})
      for (const OutputEntry& e : listed)
        if (e.kind == kind && e.frame_m && !drawn.count(e.scene)) drawn[e.scene] = e.frame_m;
    for (const auto& [name, files] : folder.scenes) {
      const auto frame = drawn.find(name);
      const rb::Result<bool> data = writePlayerData(
          dir, name, files, frame == drawn.end() ? std::nullopt : frame->second, notes);
      if (!data) return data.error();
      if (data.value()) players.push_back(name);
    }
    if (players.empty()) fs::remove(dir / kPlayerBundle, ec);  // nothing to play
  }
  writePage(opened->stream(), dir, folder, players);
  if (auto e = opened->commit(); !e) return e.error();
  return ReportPage{path, folder.scenes.empty() && folder.sweeps.empty() && folder.others.empty(),
                    notes};
}

}  // namespace tasks

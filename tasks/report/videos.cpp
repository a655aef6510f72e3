#include "tasks/report/videos.hpp"

#include <string>

#include "tasks/report/captions.hpp"
#include "tasks/report/html.hpp"

namespace tasks::report {
namespace {

constexpr const char* kReversingWay = "the theory predicts it rocks, stops and spins back";

// The videos of one scene and what their captions draw on.
struct Videos {
  std::ostream& out;
  const SceneFiles& f;
  const std::vector<RunRecord>& runs;
  std::optional<bool> ccw_preferred;  ///< the preferred direction as analyze found it
  bool either_way = false;            ///< analyze predicts a reversal the preferred way too

  // What the manifest says of the video `file`, where it gives its spin; else null.
  const ManifestVideo* listedAs(const std::string& file) const {
    const auto listed = f.manifest_videos.find(file);
    return listed == f.manifest_videos.end() ? nullptr : &listed->second;
  }

  // The first run spun counter-clockwise (`ccw`) or clockwise: a teacher who simulated both
  // ways under two names found the reversing video's caption without its run's result.
  std::optional<RunRecord> runSpun(bool ccw) const {
    for (const RunRecord& r : runs)
      if (r.initial_spin && *r.initial_spin != 0 && (*r.initial_spin > 0) == ccw) return r;
    return std::nullopt;
  }

  // The run spun `ccw` or not, else the run `file` (a video spun that way) showed as the
  // manifest lists it: a teacher who kept telemetry of one spin only found the other video's
  // caption without its reversal.
  std::optional<RunRecord> runFor(const std::string& file, bool ccw) const {
    if (auto run = runSpun(ccw)) return run;
    const ManifestVideo* listed = listedAs(file);
    return listed ? listed->run : std::nullopt;
  }

  // A video's poster is its own first frame (NAME-reversed.png for NAME-reversed.mp4, as the
  // main job renders with `still --spin`), when the run left one; otherwise the browser shows
  // the video's first frame once loaded.
  void video(const std::string& file, const std::string& poster_suffix,
             const std::string& caption) const {
    writeVideoFigure(out, file, f.has(poster_suffix) ? f.at(poster_suffix) : "", "auto", caption);
  }

  const char* preferredWay() const { return either_way ? kPreferredWayEitherWay : kPreferredWay; }

  // What the run measured, where it was spun the way (`preferred` or not) `file` was.
  std::string measured(const std::string& file, bool preferred) const {
    if (!ccw_preferred) return "";
    const bool ccw = preferred == *ccw_preferred;
    return measuredAs(runFor(file, ccw), ccw, preferred, either_way);
  }

  // A video's spin as the manifest lists it: none where it does not (or says 0).
  std::optional<double> spinOf(const std::string& file) const {
    const ManifestVideo* listed = listedAs(file);
    if (!listed || listed->spin == 0) return std::nullopt;
    return listed->spin;
  }

  static std::string rads(double spin) { return number(spin, "%+.3g") + " rad/s"; }

  // Which way and how fast a video was spun, as the manifest says: " (clockwise, −5 rad/s)".
  std::string spun(const std::string& file) const {
    const auto spin = spinOf(file);
    return spin ? " (" + spinWords(*spin) + ", " + rads(*spin) + ")" : std::string();
  }

  // render --both's pair, named by the preferred direction.
  void byWay() const {
    if (!f.has("-reversed.mp4") && !f.has("-preferred.mp4")) return;
    out << "<div class=\"pair\">\n";
    // Where the theory finds the rocking grows either way, both ways reverse: the one it does
    // not prefer is named as that, not as "the reversing way".
    if (f.has("-reversed.mp4"))
      video(f.at("-reversed.mp4"), "-reversed.png",
            std::string(either_way ? "Spun <b>against</b> its preferred way"
                                   : "Spun the <b>reversing</b> way") +
                spun(f.at("-reversed.mp4")) + ": " + kReversingWay +
                measured(f.at("-reversed.mp4"), false));
    if (f.has("-preferred.mp4"))
      video(f.at("-preferred.mp4"), "-preferred.png",
            "Spun the <b>preferred</b> way" + spun(f.at("-preferred.mp4")) + ": " + preferredWay() +
                measured(f.at("-preferred.mp4"), true));
    out << "</div>\n";
  }

  // A body with no preferred direction: its videos are named by their spins.
  void bySpin() const {
    if (!f.has("-ccw.mp4") && !f.has("-cw.mp4")) return;
    out << "<div class=\"pair\">\n";
    for (const auto& [suffix, ccw] : {std::pair{"-cw", false}, std::pair{"-ccw", true}})
      if (f.has(std::string(suffix) + ".mp4"))
        video(f.at(std::string(suffix) + ".mp4"), std::string(suffix) + ".png",
              std::string("Spun <b>") + (ccw ? "counter-clockwise" : "clockwise") +
                  "</b>: the theory prefers neither direction" +
                  measuredAs(runFor(f.at(std::string(suffix) + ".mp4"), ccw), ccw));
    out << "</div>\n";
  }

  // A video alone: its spin, which way, what the theory predicts that way and what a run spun
  // so measured.
  void alone() const {
    if (!f.has(".mp4")) return;
    std::string caption = "The scene as rendered";
    if (const auto spin = spinOf(f.at(".mp4"))) {
      const bool ccw = *spin > 0;
      caption = "Spun <b>" + spinWords(*spin) + "</b> (" + rads(*spin) + ")";
      if (ccw_preferred)
        caption += ": " + std::string(ccw == *ccw_preferred ? preferredWay() : kReversingWay);
      caption += measuredAs(
          runFor(f.at(".mp4"), ccw), ccw,
          ccw_preferred ? std::optional<bool>(ccw == *ccw_preferred) : std::nullopt, either_way);
    }
    video(f.at(".mp4"), "-single.png", caption);
  }
};

}  // namespace

void writeVideos(std::ostream& out, const SceneFiles& f,
                 const std::optional<nlohmann::json>& theory, const std::vector<RunRecord>& runs) {
  Videos videos{out, f, runs, std::nullopt};
  // The preferred direction as analyze found it (render --both names its videos the same way).
  if (theory) {
    const nlohmann::json& preferred = field(*theory, "preferred");
    if (preferred == "ccw" || preferred == "cw") videos.ccw_preferred = preferred == "ccw";
    videos.either_way = field(*theory, "grows_either_way") == true;
  }
  videos.byWay();
  videos.bySpin();
  videos.alone();
  if (f.has("-both.mp4"))
    out << "<p><a href=\"" << url(f.at("-both.mp4"))
        << "\">Both side by side in one video</a></p>\n";
}

}  // namespace tasks::report

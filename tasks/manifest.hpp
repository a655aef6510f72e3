// What the commands wrote into a folder, typed: each output file with what it is, the scene it
// came from and its role, kept in FOLDER/rattleback-manifest.json. The report reads it to place
// each file on the page (files it does not list, written by hand or by an older version, are
// placed by their names' suffixes).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "util/names.hpp"
#include "util/result.hpp"

namespace tasks {

enum class OutputKind {
  Telemetry,
  Plot,
  Video,
  Still,
  Analysis,
  Sweep,
  SweepPlot,
  Bench,
  BenchPlot
};

struct OutputEntry {
  std::string file;  ///< path as written; the manifest keeps its name within its folder
  OutputKind kind = OutputKind::Telemetry;
  std::string scene;  ///< the scene's (or sweep's) name: its file's stem
  /// Video: preferred, reversed, both or single; still: the view; plot: what it shows (spin,
  /// energy, tilt, normal); analysis: json or text.
  std::string role;
  std::optional<double> spin;  ///< rad/s, of the run shown (videos, stills)
  std::optional<double> t;     ///< s, of a still
  /// The scene it was made from (tasks::madeFrom: its content and the values put in), so that
  /// the report can tell a video or figure of an earlier version of the scene from one of the
  /// run it shows; "" when not known.
  std::string made_from = {};
  /// m: the length of body a still or video was framed for (video.frame, --frame); none where
  /// it was framed for its own. The report's player of the scene frames its views the same.
  std::optional<double> frame_m = {};
  /// A video's view (oblique, above, …): a still is its poster only when drawn from the same
  /// view. "" when not known (a manifest written before videos had it).
  std::string view = {};
  /// A video's run (one spun way; not a side-by-side): how long it ran, s, and its first
  /// reversal the rule counts, none where it did not reverse. The report captions the video
  /// with them where no telemetry of that spin was kept. Unknown (none for both) in a manifest
  /// written before videos had them.
  std::optional<double> simulated_s = {};
  std::optional<double> first_reversal_s = {};
  /// The same run's every reversal, s, and its spin n at the end, rad/s: what the caption says
  /// the run did (reversed three times, ending clockwise). Unknown in an older manifest.
  std::vector<double> reversals_s = {};
  std::optional<double> final_spin = {};
  /// How a video or still drew the body (video.surface: points, triangles, with --surface): the
  /// report's player of the scene draws it the same. "" when not known (an older manifest).
  std::string surface = {};
};

inline constexpr const char* kManifestName = "rattleback-manifest.json";

/// Adds the entries to the manifest of each one's folder (replacing any entry for the same
/// file), under a lock so that commands running side by side keep each other's entries.
rb::Status recordOutputs(const std::vector<OutputEntry>& entries);

/// The manifest of `dir`: its entries, their `file` a name within `dir`; none when absent or
/// unreadable.
std::vector<OutputEntry> readManifest(const std::string& dir);

}  // namespace tasks

namespace rb {
template <>
struct NameTable<tasks::OutputKind> {
  static constexpr std::array<std::pair<tasks::OutputKind, std::string_view>, 9> entries{{
      {tasks::OutputKind::Telemetry, "telemetry"},
      {tasks::OutputKind::Plot, "plot"},
      {tasks::OutputKind::Video, "video"},
      {tasks::OutputKind::Still, "still"},
      {tasks::OutputKind::Analysis, "analysis"},
      {tasks::OutputKind::Sweep, "sweep"},
      {tasks::OutputKind::SweepPlot, "sweep_plot"},
      {tasks::OutputKind::Bench, "bench"},
      {tasks::OutputKind::BenchPlot, "bench_plot"},
  }};
};
}  // namespace rb

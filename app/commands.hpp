// The subcommands of `rattleback`. Each returns the process exit status.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "app/tell.hpp"
#include "render/image_io.hpp"
#include "sim/tessellate.hpp"
#include "tasks/manifest.hpp"
#include "tasks/outcome.hpp"
#include "tasks/scene_args.hpp"

namespace app {

using tasks::describeModel;
using tasks::loadScene;
using tasks::Overrides;
using tasks::parseSize;

/// Exit statuses (docs/commands.md "Exit codes").
enum Exit : int {
  kOk = 0,
  kBadInput = 2,  ///< the scene, an option or an output path is unusable; nothing written
  kDiverged = 3,  ///< the run stopped itself (NaN, energy, rim); its partial output was removed
  kMachine = 4,   ///< the machine failed (rb::Error::machine): no OpenGL, a full disk; nothing kept
  // 130 / 143: interrupted by SIGINT / SIGTERM (app/interrupt.hpp)
};

/// Prints the error's one line on standard error; returns kBadInput, or kMachine for an error of
/// the machine. The one place a command's bad input is reported.
int fail(const rb::Error& error);
inline int fail(const rb::Status& status) {
  return fail(status.error());
}
template <typename T>
int fail(const rb::Result<T>& result) {
  return fail(result.error());
}

/// Lists what a command wrote in its folder's manifest (a note on stderr when it cannot).
void record(const std::vector<tasks::OutputEntry>& entries);
/// A scene's (or sweep's) name in the manifest: its file's stem.
std::string sceneName(const std::string& path);
/// The scene as a summary's `scene` line names it: its path, and the --set values put into it
/// ("hull.yaml with body.mesh.file=hull-5.stl"), so that runs of one file with other values
/// say which they were.
std::string sceneWithValues(const std::string& path, const tasks::Overrides& overrides);
/// Says on standard error (with -q too) when `given` is not in this folder and the shipped copy
/// of that name runs instead (tasks::findShipped): a deleted or misnamed scene of the user's
/// would otherwise run the shipped one in silence.
void noteShipped(const std::string& given);

/// --set's KEY=VALUE entries, split at their first '=', put into `o.values` in order.
rb::Status putSettings(const std::vector<std::string>& entries, Overrides& o);

struct SimulateArgs {
  std::string scene;
  std::string output;  ///< CSV path; empty: out/<scene name>.csv
  std::optional<double> rate;
  Overrides overrides;           ///< --duration, --spin, --dt, --tolerance, --integrator
  std::vector<std::string> set;  ///< KEY=VALUE: a scene key's value (YAML), before the options
  std::string plot_dir;          ///< non-empty: write the four figures (PNG) there
  bool check = false;            ///< also estimate the run's error (tasks/check.hpp)
  bool quiet = false;
  bool verbose = false;
};
int simulateCommand(const SimulateArgs& args);
/// The line of a run that stopped before its output: why, that `what` (telemetry, video, still)
/// was not written, what the run had found by then, and the value of `option` (--duration, or a
/// still's --t) that ends the run before the stop; `why` follows the stop's own words.
std::string stoppedLine(const std::string& scene, const tasks::Outcome& outcome,
                        const std::string& what, const std::string& option,
                        const std::string& why = "");
/// Says each of the body's own warnings (tasks::bodyWarnings) before a stopped run's line, and
/// gives the words that line ends with to point to them ("" when there are none).
std::string saidOddBody(const sim::Model& model);

struct AnalyzeArgs {
  std::string scene;
  bool json = false;
  std::string output;          ///< a file to write instead of standard output
  std::optional<double> spin;  ///< rad/s for the growth rates; default the scene's (or 5)
  bool quiet = false;          ///< accepted as every command's -q; analyze prints nothing else
  Overrides overrides;         ///< --set's values, and --duration (the forecast's reach)
};
int analyzeCommand(const AnalyzeArgs& args);

struct RenderArgs {
  std::string scene;
  std::string output;  ///< .mp4 path; empty: out/<scene>.mp4
  Overrides overrides;
  bool both = false;  ///< also the reversed spin and a side-by-side video
  int crf = 20;
  std::string preset = "veryfast";
  std::string backend = "auto";            ///< auto | egl | osmesa
  std::string backend_from = "--backend";  ///< where `backend` came from, for its error
  bool quiet = false;
  bool verbose = false;
};
int renderCommand(const RenderArgs& args);

struct StillArgs {
  std::string scene;
  std::string output;  ///< .png path; empty: out/<scene>-<view>.png
  Overrides overrides;
  std::string t = "0";          ///< s, or a moment of the run: reversal, first_reversal, end
  std::string t_named = "--t";  ///< as typed, for its errors: --t or --time
  bool no_readouts = false;
  bool transparent = false;      ///< PNG with alpha: no floor, no background, no read-outs
  std::string backend = "auto";  ///< auto | egl | osmesa
  std::string backend_from = "--backend";  ///< where `backend` came from, for its error
  bool quiet = false;
  bool verbose = false;
};
int stillCommand(const StillArgs& args);

struct BenchArgs {
  std::vector<std::string> scenes;  ///< empty: scenes/rattleback.yaml, scenes/seed-flip-ccw.yaml
  std::string csv;                  ///< empty: out/bench.csv
  std::string plot;                 ///< empty: out/bench.png
  double duration = 3;              ///< simulated seconds per run
  int repeats = 3;                  ///< timed runs per rung
  int rungs = 5;                    ///< steps in each ladder of halvings
  std::vector<std::string> models, integrators;  ///< empty: all that apply
  std::vector<double> tolerances;  ///< the adaptive ladder; empty: 1e-4, 1e-5, … 1e-10
  bool quiet = false;
};
/// Speed against error: prints a table, writes CSV and a log–log plot.
int benchCommand(const BenchArgs& args);

/// The units export writes (--units): each by name, with the metres it stands for and the
/// units.length that reads the file back. The option's choices and help are made from it.
struct ExportUnit {
  const char* name;
  double metres;
  const char* length;
};
inline constexpr std::array<ExportUnit, 3> kExportUnits{
    {{"mm", 1e-3, "0.001"}, {"cm", 1e-2, "0.01"}, {"m", 1.0, "1"}}};

struct ExportArgs {
  std::string scene;
  std::string output;                    ///< .stl path; empty: out/<scene name>.stl
  std::string units = "mm";              ///< one of kExportUnits: the numbers the file holds
  int segments = sim::kDefaultSegments;  ///< around the body (sim/tessellate.hpp)
  Overrides overrides;                   ///< --set's values
  bool quiet = false;
};
/// Writes the scene's body as a binary STL, closed and wound outwards.
int exportCommand(const ExportArgs& args);

struct ReportArgs {
  std::string dir;  ///< the folder the runs wrote into; index.html is written there
  bool quiet = false;
};
/// Writes DIR/index.html from what the runs left in DIR.
int reportCommand(const ReportArgs& args);

struct CompareArgs {
  std::string actual, expected;
  // (render::Tolerance's defaults, which snapshot suites and Python share)
  int channel_tolerance = render::Tolerance{}.channel;  ///< 0–255 per channel
  double pixel_fraction = render::Tolerance{}.pixels;   ///< of the pixels may differ beyond it
  int square = render::Tolerance{}.square;  ///< a square this side all beyond it differs; 0 off
  std::string diff;                         ///< where to write a diff image when they differ
  bool quiet = false;                       ///< no verdict line: the exit status says it
};
/// Exit 0 when the images match within the tolerance, 1 when they differ.
int compareCommand(const CompareArgs& args);

struct SnapshotArgs {
  std::string file;     ///< the suite file (YAML): goldens, defaults, cases
  bool update = false;  ///< write the goldens that differ or are missing instead of failing
  std::string report;   ///< the failure report's folder; empty: snapshot-report beside the file
  int jobs = 0;         ///< threads; 0: all cores
  bool quiet = false;
  std::string junit;  ///< JUnit XML of every case's verdict, for a CI's test view; empty: none
};
/// Draws each case of a snapshot suite and compares it with its golden: exit 0 all match, 1 any
/// differs or has no golden (a report written), 2 a bad suite, 3 a run stopped, 4 the machine.
int snapshotCommand(const SnapshotArgs& args);

struct SweepArgs {
  std::string file;    ///< the sweep file (YAML)
  std::string output;  ///< CSV; empty: out/<sweep>.csv (with --shard: …-shard-I-of-N.csv)
  int jobs = 0;        ///< threads; 0: all cores
  std::string shard;   ///< "I/N": rows I, I+N, … only
  std::string plot;    ///< heatmap PNG of --metric over the first two axes
  std::string metric = "first_reversal_s";
  std::string emit;           ///< "slurm" | "parallel": print a job script instead of running
  std::optional<int> shards;  ///< with --emit: how many shards (refused without it)
  bool resume = false;        ///< continue from the rows an interrupted run kept
  bool quiet = false;
};
/// Runs every scene of a sweep (the product of its axes) on a pool of threads; one CSV row each.
int sweepCommand(const SweepArgs& args);

struct SweepMergeArgs {
  std::string output;
  std::vector<std::string> shards;
  std::string plot;  ///< heatmap PNG of --metric over the first two axes
  std::string metric = "first_reversal_s";
  bool quiet = false;
};
/// Recombines the shard tables of one sweep in the sweep's order.
int sweepMergeCommand(const SweepMergeArgs& args);

}  // namespace app

#include "app/cli.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string_view>

#include "app/suggest.hpp"
#include "media/presets.hpp"
#include "render/frame.hpp"
#include "scene/snapshot.hpp"
#include "sim/model.hpp"
#include "sim/tessellate.hpp"
#include "tasks/still_time.hpp"
#include "tasks/sweep.hpp"
#include "util/assets.hpp"

namespace app {
namespace {

// An enum's names as --help lists them, "a | b | c", from the table the parser uses.
template <typename E>
std::string names() {
  std::string out;
  for (const auto& [value, name] : rb::NameTable<E>::entries)
    out.append(out.empty() ? "" : " | ").append(name);
  return out;
}

// The options every scene command shares: the scene, and the run's overrides.
void sceneOption(CLI::App& c, std::string& scene) {
  c.add_option("scene", scene, "Scene file (YAML)")->required();
}

// An option that sets a scene key (tasks::sceneOptions: its name, its key, its help), into
// `o`; `help` replaces the table's words where this command uses it otherwise. A size is kept
// as typed and read once the line is parsed (Cli::parse), so its error is ours, not CLI11's.
CLI::Option* keyOption(CLI::App& c, Overrides& o, tasks::SceneOption option,
                       const std::string& help = "") {
  const tasks::SceneOptionRow& row = tasks::rowOf(option);
  const std::string flag = std::string("--") + row.name;
  const std::string said = help.empty() ? std::string(row.help) : help;
  if (row.kind == tasks::OptionKind::Number)
    return c.add_option_function<double>(
        flag, [&o, option](double value) { o.set(option, value); }, said);
  return c.add_option_function<std::string>(
      flag, [&o, option](const std::string& text) { o.set(option, text); }, said);
}

void stepOptions(CLI::App& c, Overrides& o) {
  keyOption(c, o, tasks::SceneOption::Dt);
  keyOption(c, o, tasks::SceneOption::Tolerance);
}

// --set, which simulate, analyze, render and still take alike: a run made with it can be
// analysed, drawn and filmed with the same values.
void setOption(CLI::App& c, std::vector<std::string>& entries) {
  c.add_option("--set", entries,
               "Set a scene key (dotted, e.g. contact.model=smooth or body.dents.at[0]=0.8; the "
               "value in YAML); one a --set, repeatable; a key an option above also sets is "
               "refused")
      // One value a --set: a vector option takes every word after it by default, so `--set
      // initial.spin=3 mine.yaml` took the scene as a second value and said "scene is required".
      ->allow_extra_args(false)
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

void defineSimulate(CLI::App& c, Cli& cli) {
  SimulateArgs& s = cli.simulate_args;
  sceneOption(c, s.scene);
  c.add_option("-o,--output", s.output,
               "telemetry file: CSV (default out/<scene>.csv; - for standard output), or arrays by "
               "the name: .npz (NumPy), .h5 (HDF5)");
  keyOption(c, s.overrides, tasks::SceneOption::Duration);
  keyOption(c, s.overrides, tasks::SceneOption::Spin);
  stepOptions(c, s.overrides);
  keyOption(c, s.overrides, tasks::SceneOption::Integrator, names<sim::Integrator>());
  setOption(c, s.set);
  c.add_option("--rate", s.rate,
               "Telemetry samples per simulated second, at exact times (default 500)");
  c.add_option("--plot", s.plot_dir,
               "Folder for the figures: energy, spin, tilt and height, normal force (PNG)");
  c.add_flag("--check", s.check,
             "Also run at half the step (or a hundredth of the tolerance) and report the "
             "estimated error of each reversal time and of n(t)");
  c.add_flag("-q,--quiet", s.quiet, "No summary and no progress bar");
  c.add_flag("-v,--verbose", s.verbose, "Also describe the model before running");
}

void defineAnalyze(CLI::App& c, Cli& cli) {
  sceneOption(c, cli.analyze_args.scene);
  c.add_flag("--json", cli.analyze_args.json, "Print JSON");
  c.add_option("-o,--output", cli.analyze_args.output,
               "Write to this file (whole or not at all) instead of standard output");
  c.add_option(
      "--spin", cli.analyze_args.spin,
      "Spin for the growth rates, eigenvalues and forecast, rad/s (default: the scene's, else 5)");
  keyOption(c, cli.analyze_args.overrides, tasks::SceneOption::Duration,
            "How far the forecast looks, s (default: the scene's simulation.duration)");
  setOption(c, cli.analyze_set);
  // Every other command has -q; a script that gives it to all of them works here too.
  c.add_flag("-q,--quiet", cli.analyze_args.quiet,
             "Nothing but the analysis (analyze prints nothing else: taken as the other commands "
             "take it)");
}

// The backend's default can come from the environment (CI runs the render tests on both).
void backendOption(CLI::App& c, std::string& backend, std::string& from, const char* help) {
  if (const char* env = std::getenv("RATTLEBACK_BACKEND"); env && *env) {
    backend = env;
    from = "RATTLEBACK_BACKEND (the environment)";
  }
  c.add_option("--backend", backend, help)->each([&from](const std::string&) {
    from = "--backend";
  });
}

// The video's options, which a still takes too (they change a frame's inset). A still takes
// --fps and --playback as well, so that one line of options serves `render` and `still`, but
// does not list them: they change nothing in a single frame.
void videoOptions(CLI::App& c, Overrides& o, bool video) {
  keyOption(c, o, tasks::SceneOption::View, names<render::View>());
  keyOption(c, o, tasks::SceneOption::Surface,
            names<render::Surface>() +
                ": the body's surface points, or its closed surface as shaded triangles; red "
                "where it faces up, blue where it faces down (default: the scene's "
                "video.surface, or points)");
  keyOption(c, o, tasks::SceneOption::Size);
  keyOption(c, o, tasks::SceneOption::Frame);
  CLI::Option* fps = keyOption(c, o, tasks::SceneOption::Fps);
  keyOption(c, o, tasks::SceneOption::Duration, "Simulated time, s (the inset's time axis)");
  CLI::Option* playback = keyOption(c, o, tasks::SceneOption::Playback);
  if (!video) {
    fps->group("");
    playback->group("");
  }
  keyOption(c, o, tasks::SceneOption::Spin);
  stepOptions(c, o);
}

void defineRender(CLI::App& c, Cli& cli) {
  RenderArgs& r = cli.render_args;
  sceneOption(c, r.scene);
  c.add_option("-o,--output", r.output,
               "Video file (default out/<scene>.mp4; with --both the base name)");
  videoOptions(c, r.overrides, true);
  setOption(c, cli.render_set);
  c.add_option("--crf", r.crf, "x264 quality 1–51, lower is better (default 20)");
  c.add_option("--preset", r.preset, media::presetNames() + " (x264's; default veryfast)");
  backendOption(c, r.backend, r.backend_from,
                "OpenGL through egl (a GPU, or Mesa's llvmpipe without a display), osmesa, or "
                "auto: EGL when it starts, else OSMesa (default: $RATTLEBACK_BACKEND, or auto)");
  c.add_flag("--both", r.both,
             "Also the reversed spin, named …-preferred.mp4 and …-reversed.mp4 (…-ccw.mp4 and "
             "…-cw.mp4 for a body with no preferred direction), and a side-by-side …-both.mp4: "
             "the spin against the body's preferred way on the left; larger text");
  c.add_flag("-q,--quiet", r.quiet, "No summary and no progress bar");
  c.add_flag("-v,--verbose", r.verbose,
             "Also describe the model and the OpenGL in use (backend, vendor, renderer)");
}

void defineStill(CLI::App& c, Cli& cli) {
  StillArgs& st = cli.still_args;
  sceneOption(c, st.scene);
  c.add_option("-o,--output", st.output, "PNG file (default out/<scene>-<view>.png)");
  c.add_option("--t,--time", st.t,
               "Simulated time of the frame, s (default 0), or " + rb::choices<tasks::NamedTime>() +
                   ": the first reversal the rule counts (docs/physics.md P7), or the run's end")
      ->type_name("S");
  videoOptions(c, st.overrides, false);
  setOption(c, cli.still_set);
  c.add_flag("--no-readouts", st.no_readouts, "No time, spin, inset plot or floor scale");
  c.add_flag("--transparent", st.transparent,
             "PNG with alpha for figures and slides: the body and its shadow over nothing (no "
             "floor, background or read-outs)");
  backendOption(c, st.backend, st.backend_from,
                (names<render::Backend>() + ": as for render").c_str());
  c.add_flag("-q,--quiet", st.quiet, "Do not print the file name");
  c.add_flag("-v,--verbose", st.verbose, "Also name the OpenGL in use (backend, vendor, renderer)");
}

void defineCompare(CLI::App& c, Cli& cli) {
  CompareArgs& a = cli.compare_args;
  c.add_option("actual", a.actual, "PNG")->required();
  c.add_option("expected", a.expected, "PNG")->required();
  c.add_option("--tolerance", a.channel_tolerance,
               "Largest difference per channel (0–255) that still counts as equal (default 2)");
  c.add_option("--pixels", a.pixel_fraction,
               "Fraction of pixels allowed beyond the tolerance (default 0.002)");
  c.add_option("--square", a.square,
               "Differing whatever --pixels allows: a square of this many pixels a side that all "
               "differ beyond the tolerance (a changed thing, not scattered edges; default 4, 0 "
               "off)");
  c.add_option("--diff", a.diff, "Write a diff image here when they differ");
  c.add_flag("-q,--quiet", a.quiet,
             "Print nothing: the exit status says same (0) or different (1)");
}

// The keys of a suite file, from the reader's own table (scene::snapshotKeys).
std::string snapshotKeysHelp() {
  std::string out =
      "Suite file keys (YAML; view, size, backend, tolerance, pixels and square at "
      "the top are every case's defaults):\n";
  for (const scene::SnapshotKey& k : scene::snapshotKeys()) {
    const char* where = k.where == scene::SnapshotWhere::Top    ? "suite"
                        : k.where == scene::SnapshotWhere::Case ? "case "
                                                                : "both ";
    out +=
        "  " + std::string(where) + "  " + std::string(k.name) + ": " + std::string(k.help) + "\n";
  }
  // A pipeline branches on these (docs/commands.md, "rattleback snapshot").
  return out +
         "Exit status: 0 every case matches (--update: the goldens written); 1 a case differs or "
         "has no golden; 2 bad input (the suite, a case's scene, a golden that is not a PNG, an "
         "option, a report folder that cannot be made); 3 a case's run stopped; 4 the machine "
         "failed (no OpenGL, a full disk); 130 interrupted (Ctrl-C), 143 terminated\n";
}

// -j: a pool of 1 … 1024 threads, 0 for all cores (tasks/job_pool.cpp), as sweep checks it.
CLI::Validator jobsCheck() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        int jobs = -1;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), jobs);
        if (error == std::errc() && end == value.data() + value.size() && jobs >= 0 && jobs <= 1024)
          return {};
        return "threads must be 1 … 1024 (0 or none: all cores), not " + value;
      },
      "");
}

void defineSnapshot(CLI::App& c, Cli& cli) {
  SnapshotArgs& s = cli.snapshot_args;
  c.add_option("suite", s.file, "Snapshot suite file (YAML): goldens, defaults, cases")->required();
  c.add_flag("--update", s.update,
             "Write the goldens that differ or are missing (those that match are left alone)");
  c.add_option("--report", s.report,
               "Folder for the HTML report of what differs (default snapshot-report beside the "
               "suite file)");
  c.add_option("-j,--jobs", s.jobs, "Threads (default: all cores)")->check(jobsCheck());
  c.add_option("--junit", s.junit,
               "JUnit XML of every case's verdict (FILE.xml), for a CI's test view; written "
               "whatever the verdicts (a suite that cannot run: one error), not when interrupted");
  c.add_flag("-q,--quiet", s.quiet, "No verdicts and no progress bar: the exit status says it");
}

void defineBench(CLI::App& c, Cli& cli) {
  BenchArgs& b = cli.bench_args;
  c.add_option("scenes", b.scenes,
               "Scene files (default scenes/rattleback.yaml scenes/seed-flip-ccw.yaml)");
  c.add_option("-o,--output", b.csv, "CSV table (default out/bench.csv)");
  c.add_option("--plot", b.plot, "Error-against-cost plot, PNG (default out/bench.png)");
  c.add_option("--duration", b.duration, "Simulated seconds per run (default 3)");
  c.add_option("--repeats", b.repeats, "Timed runs per step (default 3)");
  c.add_option("--rungs", b.rungs,
               "Rungs of each ladder: halvings of the step, and for dopri5 decades of the "
               "tolerance from 1e-4 (default 5)");
  c.add_option("--models", b.models, names<sim::ContactModel>() + " (default: all that apply)")
      ->delimiter(',');
  c.add_option("--integrators", b.integrators,
               names<sim::Integrator>() +
                   " (default all but dop853; dopri5 and dop853 run the tolerance ladder)")
      ->delimiter(',');
  c.add_option("--tolerances", b.tolerances,
               "Tolerance ladder for dopri5 (default: --rungs decades from 1e-4)")
      ->delimiter(',');
  c.add_flag("-q,--quiet", b.quiet, "No table on stdout");
}

void defineMerge(CLI::App& c, Cli& cli) {
  SweepMergeArgs& m = cli.merge_args;
  c.add_option("output", m.output, "Merged CSV table")->required();
  c.add_option("shards", m.shards, "The shards' CSV tables")->required();
  c.add_option("--plot", m.plot,
               "Heatmap (PNG) of --metric over the first two axes of more than one value");
  c.add_option(
      "--metric", m.metric,
      "Column to plot: " + rb::choices<tasks::SweepMetric>(", ") + " (default first_reversal_s)");
  c.add_flag("-q,--quiet", m.quiet, "No summary");
}

void defineSweep(CLI::App& c, Cli& cli) {
  SweepArgs& w = cli.sweep_args;
  c.add_option("sweep", w.file, "Sweep file (YAML): base scene, vary, duration");
  c.add_option("-o,--output", w.output,
               "CSV table (default out/<sweep>.csv; with --shard out/<sweep>.shard-I-of-N.csv)");
  c.add_option("-j,--jobs", w.jobs, "Threads (default: all cores)");
  c.add_option("--shard", w.shard, "I/N: run only rows I, I+N, I+2N, … (merge the shards after)");
  c.add_option("--plot", w.plot,
               "Heatmap (PNG) of --metric over the first two axes of more than one value");
  c.add_option(
      "--metric", w.metric,
      "Column to plot: " + rb::choices<tasks::SweepMetric>(", ") + " (default first_reversal_s)");
  c.add_option("--emit", w.emit,
               "Print a job script instead of running: " + names<tasks::JobScript>() +
                   " (an sbatch job array and its merge, or command lines for GNU parallel)");
  c.add_option("--shards", w.shards, "With --emit: how many shards");
  c.add_flag("--resume", w.resume, "Continue an interrupted sweep from the rows it kept");
  c.add_flag("-q,--quiet", w.quiet, "No summary and no progress bar");
  cli.merge =
      c.add_subcommand("merge", "Recombine the shard tables of one sweep, in the sweep's order");
  defineMerge(*cli.merge, cli);
}

void defineExport(CLI::App& c, Cli& cli) {
  ExportArgs& e = cli.export_args;
  sceneOption(c, e.scene);
  c.add_option("-o,--output", e.output, "Binary STL file (default out/<scene>.stl)");
  std::vector<std::string> names;
  std::string listed, lengths;
  for (std::size_t i = 0; i < kExportUnits.size(); ++i) {
    const char* joiner = i == 0 ? "" : i + 1 == kExportUnits.size() ? " or " : ", ";
    names.emplace_back(kExportUnits[i].name);
    listed += joiner + names.back();
    lengths += joiner + std::string(kExportUnits[i].length);
  }
  c.add_option("--units", e.units,
               "The file's unit: " + listed +
                   " (default mm, what slicers assume). Read it back with units.length " + lengths)
      ->check(CLI::IsMember(names));
  c.add_option(
       "--segments", e.segments,
       "Segments around the body: finer is smoother and larger (default " +
           std::to_string(sim::kDefaultSegments) +
           ": 24,192 triangles, 1.2 MB, mass properties within 1e-3 of the body's; the error "
           "falls as 1/segments²)")
      ->check(CLI::Range(sim::kMinSegments, sim::kMaxSegments));
  setOption(c, cli.export_set);
  c.add_flag("-q,--quiet", e.quiet, "Print nothing");
}

void defineReport(CLI::App& c, Cli& cli) {
  c.add_option("dir", cli.report_args.dir, "Folder the runs wrote into (e.g. out)")->required();
  c.add_flag("-q,--quiet", cli.report_args.quiet, "Do not print the page's path");
}

int runSweep(Cli& cli) {
  return *cli.merge ? sweepMergeCommand(cli.merge_args) : sweepCommand(cli.sweep_args);
}

}  // namespace

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> table = {
      {"simulate", "Run a scene; write CSV telemetry and print a summary", false, defineSimulate,
       [](Cli& c) { return simulateCommand(c.simulate_args); }},
      {"analyze",
       "Mass properties, rest stability, frequencies, growth rates, preferred direction, forecast "
       "first reversal",
       false, defineAnalyze, [](Cli& c) { return analyzeCommand(c.analyze_args); }},
      {"render", "Render a scene to an MP4 video (H.264)", true, defineRender, runRender},
      {"still", "Render one frame of a scene to a PNG", true, defineStill, runStill},
      {"compare", "Compare two PNG images within a tolerance (exit 0 same, 1 different)", true,
       defineCompare, runCompare},
      {"snapshot",
       "Compare stills with golden images, from a suite file (exit 0 all match, 1 any differs); "
       "--update writes them",
       true, defineSnapshot, runSnapshot},
      {"bench", "Speed against error: each contact model × integrator × step against a reference",
       false, defineBench, [](Cli& c) { return benchCommand(c.bench_args); }},
      {"sweep",
       "Run every scene of a sweep file (the product of its axes) on all cores; one CSV row each",
       false, defineSweep, runSweep},
      {"export",
       "Write the scene's body as a binary STL (closed, wound outwards) to print or to read "
       "back as a mesh body",
       false, defineExport, [](Cli& c) { return exportCommand(c.export_args); }},
      {"report", "Write DIR/index.html: the videos, stills, plots and analysis found in DIR", false,
       defineReport, [](Cli& c) { return reportCommand(c.report_args); }},
  };
  return table;
}

namespace {

// --help's last line: where the documentation is. An installed program's pages are in
// <prefix>/share/doc/rattleback (found relative to the program, as the prefix may move); a
// program run from its build tree points to the source's docs/.
std::string documentation() {
  const char* more = " rattleback COMMAND --help for a command's options.";
  if (const std::string docs = rb::docsDir(); !docs.empty())
    return "Documentation: " + docs + "/ (getting-started.md first)." + more;
  return std::string(
             "Documentation: docs/ in the source (docs/getting-started.md first; bash "
             "scripts/docs.sh builds it as a site into site/).") +
         more;
}

}  // namespace

Cli::Cli(std::string_view first_argument) {
  // The usage lines say "rattleback", not the path the program was started by (CLI11 takes
  // argv[0] where the app has no name: "Usage: /usr/lib/…/bin/rattleback simulate …").
  app.name("rattleback");
  app.set_version_flag("--version", "rattleback " RATTLEBACK_VERSION);
  app.require_subcommand(1);
  // Where the line names a command first, only that one is defined: CLI11 makes every option's
  // strings and checks, and all eleven commands' took a millisecond and more of each start.
  // Anything else (--help, --version, a typo) gets them all, for its help or its suggestion.
  const auto& all = commands();
  const bool named = std::any_of(
      all.begin(), all.end(), [&](const CommandSpec& spec) { return first_argument == spec.name; });
  for (const CommandSpec& spec : all)
    if (!named || first_argument == spec.name)
      spec.define(*app.add_subcommand(spec.name, spec.summary), *this);
}

namespace {

// Every command's help ends with where the documentation is (CLI11 gives a subcommand its
// parent's footer when it is made; these are set later, so each is set here), snapshot's with
// its suite file's keys.
void setFooters(CLI::App& app, const std::string& documentation) {
  app.footer(documentation);
  for (CLI::App* command : app.get_subcommands(std::function<bool(CLI::App*)>()))
    setFooters(*command, documentation);
}

}  // namespace

// Made only when help is printed: finding the documentation folder looks at several paths, a
// twentieth of the program's start-up when it was done at every start.
void Cli::addFooters() {
  setFooters(app, documentation());
  for (CLI::App* command : app.get_subcommands(std::function<bool(CLI::App*)>()))
    if (command->get_name() == "snapshot") command->footer(snapshotKeysHelp());
}

std::optional<int> Cli::parse(int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    addFooters();
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    addFooters();
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    tell(Tone::Error, "rattleback: " + explainParseError(app, argc, argv, e.what()));
    return kBadInput;
  }
  for (auto [entries, target] : {std::pair{&render_set, &render_args.overrides},
                                 std::pair{&still_set, &still_args.overrides},
                                 std::pair{&analyze_set, &analyze_args.overrides},
                                 std::pair{&export_set, &export_args.overrides}})
    if (auto ok = putSettings(*entries, *target); !ok) {
      tell(Tone::Error, ok.error().text());
      return kBadInput;
    }
  for (Overrides* o : {&render_args.overrides, &still_args.overrides}) {
    const auto size = o->given.find(tasks::SceneOption::Size);
    if (size == o->given.end()) continue;
    if (!parseSize(size->second.name, size->second.size)) {
      tell(Tone::Error,
           "--size: expected WIDTHxHEIGHT such as 1280x720, not '" + size->second.name + "'");
      return kBadInput;
    }
  }
  // still's --t is also --time: its errors name the one typed (CLI11 does not say which).
  if (std::string_view(chosen().name) == "still")  // (commands not named are not defined)
    for (int i = 1; i < argc && std::string_view(argv[i]) != "--"; ++i) {
      const std::string_view arg = argv[i];
      if (arg == "--time" || arg.starts_with("--time=")) still_args.t_named = "--time";
      if (arg == "--t" || arg.starts_with("--t=")) still_args.t_named = "--t";
    }
  return std::nullopt;
}

const CommandSpec& Cli::chosen() const {
  const std::string name = app.get_subcommands().front()->get_name();
  for (const CommandSpec& spec : commands())
    if (name == spec.name) return spec;
  return commands().front();
}

int Cli::run() {
  const CommandSpec& spec = chosen();
  return spec.run ? spec.run(*this) : kBadInput;
}

int runGuarded(Cli& cli) {
  // A write beyond the shell's file-size limit (ulimit -f) fails with "File too large" and is
  // handled as every failed write is (exit 4, its temporary file removed, an existing output
  // kept), instead of SIGXFSZ ending the process with its part files left behind (exit 153 and
  // a .NAME.part-PID beside the video). Python ignores it likewise.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    const int status = cli.run();
    // What went to standard output (analyze's text, --emit's script) reached it, or the command
    // failed: `analyze > /dev/full` and `sweep --emit parallel >&-` would exit 0 having written
    // nothing, so that `… | parallel` on a full disk "succeeded".
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0;
    const int error = errno;
    if (status == kOk && (!flushed || std::ferror(stdout) || !std::cout)) {
      tell(Tone::Error,
           std::string("rattleback: ") + cli.chosen().name + ": cannot write standard output" +
               (error ? std::string(" (") + std::strerror(error) + ")" : std::string()));
      return kMachine;
    }
    return status;
  } catch (const std::bad_alloc&) {
    tell(Tone::Error, std::string("rattleback: ") + cli.chosen().name + ": out of memory");
  } catch (const std::exception& e) {
    tell(Tone::Error, std::string("rattleback: ") + cli.chosen().name +
                          ": internal error: " + e.what() +
                          " (a fault of rattleback's: please report it with the command)");
  }
  return kMachine;
}

}  // namespace app

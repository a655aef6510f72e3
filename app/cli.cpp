#include "app/cli.hpp"

#include <array>
#include <cstdlib>
#include <iostream>

#include "app/suggest.hpp"

namespace app {

Cli::Cli() {
  app.set_version_flag("--version", "rattleback " RATTLEBACK_VERSION);
  app.require_subcommand(1);

  SimulateArgs& s = simulate_args;
  simulate = app.add_subcommand("simulate", "Run a scene; write CSV telemetry and print a summary");
  simulate->add_option("scene", s.scene, "Scene file (YAML)")->required();
  simulate->add_option("-o,--output", s.output,
                       "CSV telemetry file (default out/<scene>.csv; - for standard output)");
  simulate->add_option("--duration", s.duration, "Simulated time, s (overrides the scene)");
  simulate->add_option("--spin", s.spin, "Initial spin, rad/s (overrides the scene)");
  simulate->add_option("--dt", s.dt, "Fixed time step, s (overrides the scene's dt or tolerance)");
  simulate->add_option("--tolerance", s.tolerance,
                       "Adaptive steps (dopri5) to this error per step (overrides the scene's dt or tolerance)");
  simulate->add_option("--integrator", s.integrator, "euler | symplectic | rk4 | dopri5");
  simulate->add_option("--rate", s.rate,
                       "Telemetry samples per simulated second, at exact times (default 500)");
  simulate->add_option("--plot", s.plot_dir,
                       "Folder for the figures: energy, spin, tilt and height, normal force (PNG)");
  simulate->add_flag("-q,--quiet", s.quiet, "No summary and no progress bar");
  simulate->add_flag("-v,--verbose", s.verbose, "Also describe the model before running");

  analyze = app.add_subcommand(
      "analyze", "Mass properties, rest stability, frequencies, growth rates, preferred direction");
  analyze->add_option("scene", analyze_args.scene, "Scene file (YAML)")->required();
  analyze->add_flag("--json", analyze_args.json, "Print JSON");
  analyze->add_option("--spin", analyze_args.spin,
                      "Spin for the growth rates and eigenvalues, rad/s (default: the scene's)");

  RenderArgs& r = render_args;
  // The backend's default can come from the environment (CI runs the render tests on both).
  if (const char* backend = std::getenv("RATTLEBACK_BACKEND"); backend && *backend) {
    render_args.backend = still_args.backend = backend;
    render_args.backend_from = still_args.backend_from = "RATTLEBACK_BACKEND (the environment)";
  }
  render = app.add_subcommand("render", "Render a scene to an MP4 video (H.264)");
  render->add_option("scene", r.scene, "Scene file (YAML)")->required();
  render->add_option("-o,--output", r.output,
                     "Video file (default out/<scene>.mp4; with --both the base name)");
  render->add_option("--view", r.overrides.view, "oblique | above | front | side | follow");
  render->add_option("--size", render_size, "Frame size WxH, e.g. 1280x720");
  render->add_option("--fps", r.overrides.fps,
                     "Frames per second, a whole number 1–240 (default: the scene's video.fps, or 30)");
  render->add_option("--duration", r.overrides.duration, "Simulated time, s");
  render->add_option("--playback", r.overrides.playback,
                     "Playback speed: simulated seconds per video second (0.5 = slow motion)");
  render->add_option("--spin", r.overrides.spin, "Initial spin, rad/s (overrides the scene)");
  render->add_option("--dt", r.overrides.dt, "Fixed time step, s");
  render->add_option("--tolerance", r.overrides.tolerance, "Adaptive steps to this error per step");
  render->add_option("--crf", r.crf, "x264 quality 1–51, lower is better (default 20)");
  render->add_option("--preset", r.preset, "x264 preset (default veryfast)");
  render->add_option("--backend", r.backend,
                     "OpenGL through egl (a GPU, or Mesa's llvmpipe without a display), osmesa, or "
                     "auto: EGL when it starts, else OSMesa (default: $RATTLEBACK_BACKEND, or auto)")
      ->each([&r](const std::string&) { r.backend_from = "--backend"; });
  render->add_flag("--both", r.both,
                   "Also the reversed spin, named …-preferred.mp4 and …-reversed.mp4, and a "
                   "side-by-side …-both.mp4");
  render->add_flag("-q,--quiet", r.quiet, "No summary and no progress bar");
  render->add_flag("-v,--verbose", r.verbose,
                   "Also describe the model and the OpenGL in use (backend, vendor, renderer)");

  StillArgs& st = still_args;
  still = app.add_subcommand("still", "Render one frame of a scene to a PNG");
  still->add_option("scene", st.scene, "Scene file (YAML)")->required();
  still->add_option("-o,--output", st.output, "PNG file (default out/<scene>-<view>.png)");
  still->add_option("--view", st.overrides.view, "oblique | above | front | side | follow");
  still->add_option("--t,--time", st.t, "Simulated time of the frame, s (default 0)");
  still->add_option("--size", still_size, "Image size WxH, e.g. 1280x720");
  // The video's options that change a frame's inset (its time axis and the frames its curve
  // runs through), so that `still --t` gives a frame of a video rendered with them.
  still->add_option("--duration", st.overrides.duration,
                    "Simulated time of the run, s: the inset's time axis (as render --duration)");
  still->add_option("--fps", st.overrides.fps, "Frames per second of the video (as render --fps)");
  still->add_option("--playback", st.overrides.playback,
                    "Playback speed of the video (as render --playback)");
  still->add_option("--spin", st.overrides.spin, "Initial spin, rad/s (overrides the scene)");
  still->add_option("--dt", st.overrides.dt, "Fixed time step, s");
  still->add_option("--tolerance", st.overrides.tolerance, "Adaptive steps to this error per step");
  still->add_flag("--no-readouts", st.no_readouts, "No time, spin or inset plot");
  still->add_flag("--transparent", st.transparent,
                  "PNG with alpha for figures and slides: the body and its shadow over nothing (no "
                  "floor, background or read-outs)");
  still->add_option("--backend", st.backend, "auto (default) | egl | osmesa: as for render")
      ->each([&st](const std::string&) { st.backend_from = "--backend"; });
  still->add_flag("-q,--quiet", st.quiet, "Do not print the file name");
  still->add_flag("-v,--verbose", st.verbose, "Also name the OpenGL in use (backend, vendor, renderer)");

  CompareArgs& c = compare_args;
  compare = app.add_subcommand(
      "compare", "Compare two PNG images within a tolerance (exit 0 same, 1 different)");
  compare->add_option("actual", c.actual, "PNG")->required();
  compare->add_option("expected", c.expected, "PNG")->required();
  compare->add_option("--tolerance", c.channel_tolerance,
                      "Largest difference per channel (0–255) that still counts as equal (default 2)");
  compare->add_option("--pixels", c.pixel_fraction,
                      "Fraction of pixels allowed beyond the tolerance (default 0.002)");
  compare->add_option("--diff", c.diff, "Write a diff image here when they differ");
  compare->add_flag("-q,--quiet", c.quiet, "Print nothing: the exit status says same (0) or different (1)");

  BenchArgs& b = bench_args;
  bench = app.add_subcommand(
      "bench", "Speed against error: each contact model × integrator × step against a reference");
  bench->add_option("scenes", b.scenes,
                    "Scene files (default scenes/rattleback.yaml scenes/seed-reversed.yaml)");
  bench->add_option("-o,--output", b.csv, "CSV table (default out/bench.csv)");
  bench->add_option("--plot", b.plot, "Error-against-cost plot, PNG (default out/bench.png)");
  bench->add_option("--duration", b.duration, "Simulated seconds per run (default 3)");
  bench->add_option("--repeats", b.repeats, "Timed runs per step (default 3)");
  bench->add_option("--rungs", b.rungs, "Steps in each ladder of halvings (default 5)");
  bench->add_option("--models", b.models, "points smooth rolling auto (default: all that apply)")
      ->delimiter(',');
  bench->add_option("--integrators", b.integrators,
                    "euler symplectic rk4 dopri5 (default all; dopri5 runs the tolerance ladder)")
      ->delimiter(',');
  bench->add_option("--tolerances", b.tolerances,
                    "Tolerance ladder for dopri5 (default 1e-4,1e-5,…,1e-10)")
      ->delimiter(',');
  bench->add_flag("-q,--quiet", b.quiet, "No table on stdout");

  SweepArgs& w = sweep_args;
  sweep = app.add_subcommand(
      "sweep", "Run every scene of a sweep file (the product of its axes) on all cores; one CSV row each");
  sweep->add_option("sweep", w.file, "Sweep file (YAML): base scene, vary, duration");
  sweep->add_option("-o,--output", w.output,
                    "CSV table (default out/<sweep>.csv; with --shard out/<sweep>.shard-I-of-N.csv)");
  sweep->add_option("-j,--jobs", w.jobs, "Threads (default: all cores)");
  sweep->add_option("--shard", w.shard, "I/N: run only rows I, I+N, I+2N, … (merge the shards after)");
  sweep->add_option("--plot", w.plot, "Heatmap (PNG) of --metric over the first two axes");
  sweep->add_option("--metric", w.metric,
                    "Column to plot: first_reversal_s (default), reversals, final_spin, "
                    "max_tilt_deg, energy_lost, wall_s");
  sweep->add_option("--emit", w.emit,
                    "Print a job script instead of running: slurm (an sbatch job array and its "
                    "merge) or parallel (command lines for GNU parallel)");
  sweep->add_option("--shards", w.shards, "With --emit: how many shards");
  sweep->add_flag("--resume", w.resume, "Continue an interrupted sweep from the rows it kept");
  sweep->add_flag("-q,--quiet", w.quiet, "No summary and no progress bar");
  merge = sweep->add_subcommand(
      "merge", "Recombine the shard tables of one sweep, in the sweep's order");
  merge->add_option("output", merge_args.output, "Merged CSV table")->required();
  merge->add_option("shards", merge_args.shards, "The shards' CSV tables")->required();
  merge->add_option("--plot", merge_args.plot, "Heatmap (PNG) of --metric over the first two axes");
  merge->add_option("--metric", merge_args.metric, "Column to plot (default first_reversal_s)");
  merge->add_flag("-q,--quiet", merge_args.quiet, "No summary");

  report = app.add_subcommand(
      "report", "Write DIR/index.html: the videos, stills, plots and analysis found in DIR");
  report->add_option("dir", report_args.dir, "Folder the runs wrote into (e.g. out)")->required();
  report->add_flag("-q,--quiet", report_args.quiet, "Do not print the page's path");
}

std::optional<int> Cli::parse(int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rattleback: " << explainParseError(app, argc, argv, e.what()) << "\n";
    return kBadInput;
  }
  for (auto [text, target] : {std::pair{&render_size, &render_args.overrides.size},
                              std::pair{&still_size, &still_args.overrides.size}}) {
    if (text->empty()) continue;
    std::array<int, 2> size;
    if (!parseSize(*text, size)) {
      std::cerr << "--size: expected WIDTHxHEIGHT such as 1280x720, not '" << *text << "'\n";
      return kBadInput;
    }
    *target = size;
  }
  return std::nullopt;
}

bool Cli::draws() const { return *render || *still || *compare; }

int Cli::runLight() {
  if (*simulate) return simulateCommand(simulate_args);
  if (*analyze) return analyzeCommand(analyze_args);
  if (*bench) return benchCommand(bench_args);
  if (*report) return reportCommand(report_args);
  if (*merge) return sweepMergeCommand(merge_args);
  if (*sweep) return sweepCommand(sweep_args);
  return kBadInput;
}

}  // namespace app

// rattleback: simulate a rattleback and report what it does.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.hpp"
#include "app/suggest.hpp"

int main(int argc, char** argv) {
  CLI::App cli{"rattleback: simulate the rattleback (celt) that spins back"};
  cli.set_version_flag("--version", "rattleback " RATTLEBACK_VERSION);
  cli.require_subcommand(1);

  app::SimulateArgs sim_args;
  CLI::App* simulate = cli.add_subcommand(
      "simulate", "Run a scene; write CSV telemetry and print a summary");
  simulate->add_option("scene", sim_args.scene, "Scene file (YAML)")->required();
  simulate->add_option("-o,--output", sim_args.output,
                       "CSV telemetry file (default out/<scene>.csv)");
  simulate->add_option("--duration", sim_args.duration, "Simulated time, s (overrides the scene)");
  simulate->add_option("--dt", sim_args.dt, "Fixed time step, s (overrides the scene's dt or tolerance)");
  simulate->add_option("--tolerance", sim_args.tolerance,
                       "Adaptive steps (dopri5) to this error per step (overrides the scene's dt or tolerance)");
  simulate->add_option("--integrator", sim_args.integrator, "euler | symplectic | rk4 | dopri5");
  simulate->add_option("--rate", sim_args.rate,
                       "Telemetry samples per simulated second, at exact times (default 500)");
  simulate->add_option("--plot", sim_args.plot_dir,
                       "Folder for the figures: energy, spin, tilt and height, normal force (PNG)");
  simulate->add_flag("-q,--quiet", sim_args.quiet, "No summary and no progress bar");
  simulate->add_flag("-v,--verbose", sim_args.verbose, "Also describe the model before running");

  app::AnalyzeArgs analyze_args;
  CLI::App* analyze = cli.add_subcommand(
      "analyze", "Mass properties, rest stability, frequencies, growth rates, preferred direction");
  analyze->add_option("scene", analyze_args.scene, "Scene file (YAML)")->required();
  analyze->add_flag("--json", analyze_args.json, "Print JSON");
  analyze->add_option("--spin", analyze_args.spin,
                      "Spin for the growth rates and eigenvalues, rad/s (default: the scene's)");

  app::RenderArgs render_args;
  std::string render_size, still_size;
  CLI::App* render = cli.add_subcommand("render", "Render a scene to an MP4 video (H.264)");
  render->add_option("scene", render_args.scene, "Scene file (YAML)")->required();
  render->add_option("-o,--output", render_args.output,
                     "Video file (default out/<scene>.mp4; with --both the base name)");
  render->add_option("--view", render_args.overrides.view, "oblique | above | front | side | follow");
  render->add_option("--size", render_size, "Frame size WxH, e.g. 1280x720");
  render->add_option("--fps", render_args.overrides.fps, "Frames per second");
  render->add_option("--duration", render_args.overrides.duration, "Simulated time, s");
  render->add_option("--playback", render_args.overrides.playback,
                     "Playback speed: simulated seconds per video second (0.5 = slow motion)");
  render->add_option("--spin", render_args.overrides.spin, "Initial spin, rad/s (overrides the scene)");
  render->add_option("--dt", render_args.overrides.dt, "Fixed time step, s");
  render->add_option("--tolerance", render_args.overrides.tolerance, "Adaptive steps to this error per step");
  render->add_option("--crf", render_args.crf, "x264 quality 1–51, lower is better (default 20)");
  render->add_option("--preset", render_args.preset, "x264 preset (default veryfast)");
  render->add_flag("--both", render_args.both,
                   "Also the reversed spin, named …-preferred.mp4 and …-reversed.mp4, and a "
                   "side-by-side …-both.mp4");
  render->add_flag("-q,--quiet", render_args.quiet, "No summary and no progress bar");
  render->add_flag("-v,--verbose", render_args.verbose, "Also describe the model before running");

  app::StillArgs still_args;
  CLI::App* still = cli.add_subcommand("still", "Render one frame of a scene to a PNG");
  still->add_option("scene", still_args.scene, "Scene file (YAML)")->required();
  still->add_option("-o,--output", still_args.output, "PNG file (default out/<scene>-<view>.png)");
  still->add_option("--view", still_args.overrides.view, "oblique | above | front | side | follow");
  still->add_option("--t", still_args.t, "Simulated time of the frame, s (default 0)");
  still->add_option("--size", still_size, "Image size WxH, e.g. 1280x720");
  still->add_option("--spin", still_args.overrides.spin, "Initial spin, rad/s (overrides the scene)");
  still->add_option("--dt", still_args.overrides.dt, "Fixed time step, s");
  still->add_option("--tolerance", still_args.overrides.tolerance, "Adaptive steps to this error per step");
  still->add_flag("--no-readouts", still_args.no_readouts, "No time, spin or inset plot");
  still->add_flag("-q,--quiet", still_args.quiet, "Do not print the file name");

  app::CompareArgs compare_args;
  CLI::App* compare = cli.add_subcommand(
      "compare", "Compare two PNG images within a tolerance (exit 0 same, 1 different)");
  compare->add_option("actual", compare_args.actual, "PNG")->required();
  compare->add_option("expected", compare_args.expected, "PNG")->required();
  compare->add_option("--tolerance", compare_args.channel_tolerance,
                      "Largest difference per channel (0–255) that still counts as equal (default 2)");
  compare->add_option("--pixels", compare_args.pixel_fraction,
                      "Fraction of pixels allowed beyond the tolerance (default 0.002)");
  compare->add_option("--diff", compare_args.diff, "Write a diff image here when they differ");

  app::BenchArgs bench_args;
  CLI::App* bench = cli.add_subcommand(
      "bench", "Speed against error: each contact model × integrator × step against a reference");
  bench->add_option("scenes", bench_args.scenes,
                    "Scene files (default scenes/rattleback.yaml scenes/seed-reversed.yaml)");
  bench->add_option("-o,--output", bench_args.csv, "CSV table (default out/bench.csv)");
  bench->add_option("--plot", bench_args.plot, "Error-against-cost plot, PNG (default out/bench.png)");
  bench->add_option("--duration", bench_args.duration, "Simulated seconds per run (default 3)");
  bench->add_option("--repeats", bench_args.repeats, "Timed runs per step (default 3)");
  bench->add_option("--rungs", bench_args.rungs, "Steps in each ladder of halvings (default 5)");
  bench->add_option("--models", bench_args.models, "points smooth rolling (default: all that apply)")
      ->delimiter(',');
  bench->add_option("--integrators", bench_args.integrators,
                    "euler symplectic rk4 dopri5 (default all; dopri5 runs the tolerance ladder)")
      ->delimiter(',');
  bench->add_option("--tolerances", bench_args.tolerances,
                    "Tolerance ladder for dopri5 (default 1e-4,1e-5,…,1e-10)")
      ->delimiter(',');
  bench->add_flag("-q,--quiet", bench_args.quiet, "No table on stdout");

  app::ReportArgs report_args;
  CLI::App* report = cli.add_subcommand(
      "report", "Write DIR/index.html: the videos, stills, plots and analysis found in DIR");
  report->add_option("dir", report_args.dir, "Folder the runs wrote into (e.g. out)")->required();
  report->add_flag("-q,--quiet", report_args.quiet, "Do not print the page's path");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rattleback: " << app::explainParseError(cli, argc, argv, e.what()) << "\n";
    return app::kBadInput;
  }
  if (*simulate) return app::simulateCommand(sim_args);
  if (*analyze) return app::analyzeCommand(analyze_args);
  if (*bench) return app::benchCommand(bench_args);
  if (*report) return app::reportCommand(report_args);
  for (auto [text, target] : {std::pair{&render_size, &render_args.overrides.size},
                              std::pair{&still_size, &still_args.overrides.size}}) {
    if (text->empty()) continue;
    std::array<int, 2> size;
    if (!app::parseSize(*text, size)) {
      std::cerr << "--size: expected WIDTHxHEIGHT such as 1280x720, not '" << *text << "'\n";
      return app::kBadInput;
    }
    *target = size;
  }
  if (*render) return app::renderCommand(render_args);
  if (*still) return app::stillCommand(still_args);
  if (*compare) return app::compareCommand(compare_args);
  return app::kBadInput;
}

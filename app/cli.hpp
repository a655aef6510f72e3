// The command line of `rattleback`, defined once (a table of commands, app/cli.cpp) and read by
// both programs behind it: the light `rattleback` (simulate, analyze, bench, report, sweep) and
// `rattleback-render` (render, still, compare, snapshot), which the first runs in its own place
// (exec) for the commands that draw — so the commands that only simulate never load OSMesa/EGL (and
// LLVM behind them) or libav.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "app/commands.hpp"

namespace app {

struct Cli;

/// One command: its name and summary, its options, and what runs it. A command is added here
/// only (commands()); `run` is null in the program that does not link it (the drawing commands
/// in `rattleback`, which hands them to rattleback-render).
struct CommandSpec {
  const char* name;
  const char* summary;
  bool draws;  ///< needs OpenGL or libav: run by rattleback-render
  void (*define)(CLI::App& command, Cli& cli);
  int (*run)(Cli& cli);
};

/// Every command, in --help's order.
const std::vector<CommandSpec>& commands();

struct Cli {
  /// `first_argument`: the command line's first word (argv[1]); where it names a command, only
  /// that command is defined.
  explicit Cli(std::string_view first_argument = {});
  /// Every command's help footer (the documentation's place; snapshot's suite keys).
  void addFooters();
  Cli(const Cli&) = delete;
  Cli& operator=(const Cli&) = delete;

  CLI::App app{"rattleback: simulate the rattleback (celt) that spins back"};
  SimulateArgs simulate_args;
  AnalyzeArgs analyze_args;
  RenderArgs render_args;
  StillArgs still_args;
  CompareArgs compare_args;
  SnapshotArgs snapshot_args;
  BenchArgs bench_args;
  ReportArgs report_args;
  ExportArgs export_args;
  SweepArgs sweep_args;
  SweepMergeArgs merge_args;
  std::vector<std::string> render_set, still_set, analyze_set, export_set;  ///< --set, by parse()
  CLI::App* merge = nullptr;                                                ///< `sweep merge`

  /// Reads argv. Returns the exit status when that ends the program (--help, --version, a
  /// command-line error, already printed); nothing when a command is to run.
  std::optional<int> parse(int argc, char** argv);
  /// The command chosen (after parse).
  const CommandSpec& chosen() const;
  /// Runs the chosen command; kBadInput when this program does not link it.
  int run();
};

/// cli.run(), with an exception that escapes a command (memory run out, a fault of ours) said in
/// one line and exit status kMachine, instead of an abort.
int runGuarded(Cli& cli);

// The drawing commands' runners: defined in rattleback-render (app/video.cpp, app/snapshot.cpp),
// absent (null, weak) in rattleback.
[[gnu::weak]] int runRender(Cli& cli);
[[gnu::weak]] int runStill(Cli& cli);
[[gnu::weak]] int runCompare(Cli& cli);
[[gnu::weak]] int runSnapshot(Cli& cli);  ///< app/snapshot.cpp

}  // namespace app

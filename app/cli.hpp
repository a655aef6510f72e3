// The command line of `rattleback`, defined once and read by both programs behind it: the
// light `rattleback` (simulate, analyze, bench, report, sweep) and `rattleback-render` (render,
// still, compare), which the first runs in its own place (exec) for the commands that draw —
// so the commands that only simulate never load OSMesa/EGL (and LLVM behind them) or libav.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "app/commands.hpp"

namespace app {

struct Cli {
  Cli();
  Cli(const Cli&) = delete;
  Cli& operator=(const Cli&) = delete;

  CLI::App app{"rattleback: simulate the rattleback (celt) that spins back"};
  SimulateArgs simulate_args;
  AnalyzeArgs analyze_args;
  RenderArgs render_args;
  StillArgs still_args;
  CompareArgs compare_args;
  BenchArgs bench_args;
  ReportArgs report_args;
  SweepArgs sweep_args;
  SweepMergeArgs merge_args;
  std::string render_size, still_size;

  CLI::App* simulate = nullptr;
  CLI::App* analyze = nullptr;
  CLI::App* render = nullptr;
  CLI::App* still = nullptr;
  CLI::App* compare = nullptr;
  CLI::App* bench = nullptr;
  CLI::App* report = nullptr;
  CLI::App* sweep = nullptr;
  CLI::App* merge = nullptr;

  /// Reads argv. Returns the exit status when that ends the program (--help, --version, a
  /// command-line error, already printed); nothing when a command is to run.
  std::optional<int> parse(int argc, char** argv);
  /// True when the chosen command draws (render, still, compare): rattleback-render runs it.
  bool draws() const;
  /// Runs the chosen command that does not draw.
  int runLight();
};

}  // namespace app

// The subcommands of `rattleback`. Each returns the process exit status.
#pragma once

#include <optional>
#include <string>

namespace app {

/// Exit statuses (README "Exit codes").
enum Exit : int {
  kOk = 0,
  kBadInput = 2,  ///< the scene, an option or an output path is unusable; nothing written
  kDiverged = 3,  ///< the run produced NaN or inf; its partial output was removed
};

struct SimulateArgs {
  std::string scene;
  std::string output;  ///< CSV path; empty: out/<scene name>.csv
  std::optional<double> duration, dt, rate;
  std::optional<std::string> integrator;
  bool quiet = false;
};
int simulateCommand(const SimulateArgs& args);

struct AnalyzeArgs {
  std::string scene;
  bool json = false;
};
int analyzeCommand(const AnalyzeArgs& args);

}  // namespace app

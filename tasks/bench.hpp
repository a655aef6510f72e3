// `bench`'s measurements (docs/commands.md "rattleback bench"): for each contact model × integrator
// × step of a ladder of halvings (or tolerances for dopri5), a scene runs `repeats` times; the cost
// is the median wall time per simulated second, and the errors are measured against a reference:
// the same model with rk4 at a step 16× below the ladder's finest, and the rolling model's
// reference where the body has a smooth surface. A conservative variant (no friction, no dampers,
// no drag) gives the energy drift.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/model.hpp"
#include "sim/spec.hpp"
#include "util/result.hpp"

namespace tasks {

/// One rung of a ladder and what it measured.
/// How a rung of the bench went.
enum class BenchStatus {
  Ok,       ///< measured
  Failed,   ///< refused, or stopped by itself (message says why)
  Skipped,  ///< not run: the rung before ran over the budget of one run
};

struct BenchRow {
  std::string scene;
  sim::ContactModel model = sim::ContactModel::Points;
  sim::Integrator integrator = sim::Integrator::Rk4;
  double dt = 0;           ///< fixed step, s (NaN for adaptive rows)
  double tolerance = NAN;  ///< adaptive rows
  std::int64_t steps = 0, rejected = 0;
  std::optional<double> switches;  ///< auto rows: changes of contact model
  BenchStatus status = BenchStatus::Ok;
  std::string message;  ///< for Failed and Skipped: why, in full (the CSV's status)
  std::string brief;    ///< the same in a few words (the printed table)
  double cost_median = NAN, cost_min = NAN, cost_max = NAN, us_per_step = NAN;
  /// Wall time of the rung's run as a whole process (`rattleback simulate` with the rung's
  /// settings: start-up, loading, the run and its telemetry), s, median of the repeats.
  std::optional<double> process_s;
  std::optional<double> reversal, reversal_error, reversal_error_rolling;
  std::optional<double> spin_error, spin_error_rolling, energy_drift;
};

/// A scene to bench: its spec and the body compiled once for every run.
struct BenchScene {
  std::string name;  ///< the file's name
  std::string path;  ///< where it was read
  sim::SceneSpec spec;
  std::shared_ptr<const sim::Body> body;
};
rb::Result<BenchScene> loadBenchScene(const std::string& path);

struct BenchOptions {
  double duration = 3;  ///< simulated seconds per run
  int repeats = 3;
  int rungs = 5;
  std::vector<std::string> models;               ///< empty: all that apply
  std::vector<std::string> integrators;          ///< empty: all
  std::vector<double> tolerances;                ///< empty: 1e-4 … 1e-10
  std::function<bool()> cancelled;               ///< asked before each rung (may be empty)
  std::function<void(const BenchRow&)> row;      ///< each row as it is measured
  std::function<void(const std::string&)> note;  ///< a line worth saying (may be empty)
  /// Runs the program with these arguments as a process of its own and returns its wall time,
  /// s, or nothing when it failed (may be empty: no process column).
  std::function<std::optional<double>(const std::vector<std::string>&)> process;
};

/// The arguments of `rattleback simulate` that run `spec` (the scene file with the bench's
/// changes put in by --set) for `duration` s, sampled as the bench samples, writing nothing.
std::vector<std::string> processArguments(const BenchScene& scene, const sim::SceneSpec& spec,
                                          double duration);

/// Checks the options: known models and integrators, tolerances within 1e-14 … 0.1, duration
/// > 0, repeats ≥ 1, rungs 1 … 12.
rb::Status checkBenchOptions(const BenchOptions& options);

/// Measures every rung for one scene, appending to `rows`; false when cancelled.
bool benchScene(const BenchScene& scene, const BenchOptions& options, std::vector<BenchRow>& rows);

/// The CSV's header line and one row (with their newlines).
std::string benchCsvHeader();
std::string benchCsvLine(const BenchRow& r);

}  // namespace tasks

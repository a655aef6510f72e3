// A sweep's result columns, declared once: each one's name, unit and meaning, how its field is
// written from a row, and for the metrics (what a heatmap can show) the enum, the words a
// figure's title uses and the number a row gives. The CSV writer, the sidecar, the plots, the
// merge and Python's columns all loop over this table, so a new metric is one row here and one
// entry of SweepMetric's name table.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/watchdog.hpp"
#include "tasks/analysis.hpp"
#include "tasks/table.hpp"
#include "util/names.hpp"

namespace tasks {

enum class RowStatus {
  Ok,       ///< ran to its end
  Stopped,  ///< stopped by itself (stop says why, message in the run's words)
  Refused,  ///< its scene was refused (message: the loader's line)
};

/// One run of a sweep and what it found.
struct SweepRow {
  std::int64_t row = 0;             ///< index in the sweep's order (first axis slowest)
  std::vector<std::string> values;  ///< each axis's value, as put into the scene
  RowStatus status = RowStatus::Ok;
  std::string message;                     ///< for Stopped and Refused: why, in words
  std::optional<sim::StopReason> stop;     ///< for Stopped, when the run said why
  std::optional<double> first_reversal_s;  ///< s
  std::optional<std::int64_t> reversals;   ///< none when refused
  std::optional<double> final_spin;        ///< rad/s, when it reached its end
  std::optional<double> max_tilt_deg;      ///< degrees over the steps (also a stopped run's)
  std::optional<double> energy_lost;       ///< fraction of the initial energy, at the end
  std::optional<double> forecast_s;        ///< s: the averaged theory's first reversal (analyze's)
  std::optional<ForecastNote> forecast_note;  ///< why forecast_s is, or is not, a time
  std::optional<bool> exports;  ///< whether `export` writes the row's body: its dents within it
  double wall_s = 0;            ///< wall-clock time of the run, s
};

/// The result columns with a number, which a figure can show (`--metric`, Python's `metric=`).
enum class SweepMetric { FirstReversal, Reversals, FinalSpin, MaxTilt, EnergyLost, Wall, Forecast };

/// How far a run must go before a column is known (docs/commands.md "Columns: only what the
/// table needs"): a sweep that lists its columns stops each run at the furthest its columns need.
enum class ColumnNeeds {
  Nothing,        ///< known from the scene, or of the run however far it went: no step more
  FirstReversal,  ///< until the reversal rule confirms the first reversal, or the run's end
  WholeRun,       ///< the whole duration (what happens at the end, or anywhere in the run)
};

/// What a row works out beside its run, for the columns that ask for it.
enum class RowExtra {
  None,
  Forecast,  ///< the averaged theory's forecast (tasks/forecast.hpp), from the scene alone
  Exports,   ///< whether `export` writes the body as a solid, once per body
};

/// A result column of the table: after the row index and the axes' values.
struct SweepResultColumn {
  Column column;  ///< name, unit and meaning (the sidecar's)
  /// The field as the CSV writes it (before csvField's quoting): "" for none.
  std::string (*text)(const SweepRow&) = nullptr;
  /// For a metric: which, its value at a row (NaN for none) and its words for a title.
  std::optional<SweepMetric> metric;
  double (*value)(const SweepRow&) = nullptr;
  const char* words = nullptr;
  ColumnNeeds needs = ColumnNeeds::WholeRun;
  /// In the table of a sweep that lists no columns (forecast_s is only there when asked for:
  /// without `columns:` the table is as it was).
  bool by_default = true;
  /// A whole number (a count): its value() is one, or NaN where a row has none. Python's
  /// to_pandas gives it pandas' nullable integers.
  bool whole = false;
  RowExtra extra = RowExtra::None;
};

/// The result columns of a table, in its order.
using SweepColumns = std::vector<const SweepResultColumn*>;

/// Whether any of `columns` asks for `extra`.
bool asksFor(const SweepColumns& columns, RowExtra extra);

/// Every result column, in the table's order.
std::span<const SweepResultColumn> sweepResultTable();
/// The metric's column.
const SweepResultColumn& columnOf(SweepMetric metric);
/// A metric at a row: only a run that went as far as its columns need has a value to show (NaN
/// otherwise).
double metricOf(const SweepRow& row, SweepMetric metric);
/// The column of this name, or none.
const SweepResultColumn* findSweepColumn(std::string_view name);
/// The names of every column, in the table's order (for a message's list and a did-you-mean).
std::vector<std::string> sweepColumnNames();
/// How far the runs of a table of these columns must go: the furthest any of them needs.
ColumnNeeds needsOf(const SweepColumns& columns);

}  // namespace tasks

namespace rb {
template <>
struct NameTable<tasks::RowStatus> {
  static constexpr std::array<std::pair<tasks::RowStatus, std::string_view>, 3> entries{{
      {tasks::RowStatus::Ok, "ok"},
      {tasks::RowStatus::Stopped, "stopped"},
      {tasks::RowStatus::Refused, "refused"},
  }};
};
// The names are the columns' (the table's header).
template <>
struct NameTable<tasks::SweepMetric> {
  static constexpr std::array<std::pair<tasks::SweepMetric, std::string_view>, 7> entries{{
      {tasks::SweepMetric::FirstReversal, "first_reversal_s"},
      {tasks::SweepMetric::Reversals, "reversals"},
      {tasks::SweepMetric::FinalSpin, "final_spin"},
      {tasks::SweepMetric::MaxTilt, "max_tilt_deg"},
      {tasks::SweepMetric::EnergyLost, "energy_lost"},
      {tasks::SweepMetric::Wall, "wall_s"},
      {tasks::SweepMetric::Forecast, "forecast_s"},
  }};
};
}  // namespace rb

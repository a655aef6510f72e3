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
#include <vector>

#include "sim/watchdog.hpp"
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
  double wall_s = 0;                       ///< wall-clock time of the run, s
};

/// The result columns with a number, which a figure can show (`--metric`, Python's `metric=`).
enum class SweepMetric { FirstReversal, Reversals, FinalSpin, MaxTilt, EnergyLost, Wall };

/// A result column of the table: after the row index and the axes' values.
struct SweepResultColumn {
  Column column;  ///< name, unit and meaning (the sidecar's)
  /// The field as the CSV writes it (before csvField's quoting): "" for none.
  std::string (*text)(const SweepRow&) = nullptr;
  /// For a metric: which, its value at a row (NaN for none) and its words for a title.
  std::optional<SweepMetric> metric;
  double (*value)(const SweepRow&) = nullptr;
  const char* words = nullptr;
};

/// Every result column, in the table's order.
std::span<const SweepResultColumn> sweepResultTable();
/// The metric's column.
const SweepResultColumn& columnOf(SweepMetric metric);
/// A metric at a row: only a run that reached its end has a value to show (NaN otherwise).
double metricOf(const SweepRow& row, SweepMetric metric);

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
  static constexpr std::array<std::pair<tasks::SweepMetric, std::string_view>, 6> entries{{
      {tasks::SweepMetric::FirstReversal, "first_reversal_s"},
      {tasks::SweepMetric::Reversals, "reversals"},
      {tasks::SweepMetric::FinalSpin, "final_spin"},
      {tasks::SweepMetric::MaxTilt, "max_tilt_deg"},
      {tasks::SweepMetric::EnergyLost, "energy_lost"},
      {tasks::SweepMetric::Wall, "wall_s"},
  }};
};
}  // namespace rb

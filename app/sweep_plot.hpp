// A sweep's table read back and drawn (app/sweep_plot.cpp): what `sweep --plot` and
// `sweep merge --plot` share.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tasks/sweep_columns.hpp"
#include "util/result.hpp"

namespace app {

struct Table {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> axis_values;  // [axis][value]
  std::vector<double> values;    // the metric of each row in row order; NaN where none
  double length_unit = 0;        // m per file length unit of the base scene; 0: not known
  std::vector<double> forecast;  // forecast_s of each row, drawn beside first_reversal_s; or none
};

/// Splits one CSV line (RFC 4180 quoting); nullopt when its quotes do not close.
std::optional<std::vector<std::string>> splitCsv(const std::string& line);
/// The metric --metric names (metricProblem has said when it names none).
tasks::SweepMetric metricNamed(const std::string& name);
/// Why --metric names no metric, or nothing.
rb::Status metricProblem(const std::string& name);
/// The field of `name` in a line of a table of these result columns, or none.
std::optional<std::string> fieldOf(const std::vector<std::string>& fields, std::size_t axes,
                                   const tasks::SweepColumns& columns, std::string_view name);
/// The metric of a line's fields (none where the run was not ok), or of the line itself.
double metricOf(const std::vector<std::string>& fields, std::size_t axes,
                const tasks::SweepColumns& columns, tasks::SweepMetric metric);
double metricOf(const std::string& line, std::size_t axes, const tasks::SweepColumns& columns,
                tasks::SweepMetric metric);
/// Each line's forecast_s where the table has it and the plot is of first_reversal_s; else none.
std::vector<double> forecastsOf(const std::vector<std::string>& lines, std::size_t axes,
                                const tasks::SweepColumns& columns, tasks::SweepMetric metric);
/// Why --metric cannot be plotted from a table of these columns, or nothing.
rb::Status metricListed(const std::string& name, const tasks::SweepColumns& columns);
/// Draws `metric` over the table: a heatmap of the first two axes of more than one value, or a
/// line plot of the one such axis (docs/commands.md "rattleback sweep", --plot).
rb::Status plotTable(const std::string& png, tasks::SweepMetric metric_id, const std::string& title,
                     const Table& table);

}  // namespace app

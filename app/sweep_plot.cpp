// A sweep's table read back and drawn: the fields of its lines, the metric of each row, and its
// line plot or heatmap (gnuplot, app/plot.hpp), for `sweep --plot` and `sweep merge --plot`.
#include "app/sweep_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "app/plot.hpp"
#include "scene/keys.hpp"

namespace app {

// An axis's label: the key or column with its unit, "initial.spin [rad/s]", as the run's plots
// label theirs ("spin n [rad/s]"). A scene key's unit is the schema's; lengths in the file's unit
// ("file units") and dimensionless values go bare (the sweep's plots said "initial.spin" and
// "first_reversal_s" with no units).
std::string sweepLabel(const std::string& name, double length_unit) {
  const std::string unit = tasks::sweepColumnUnit(name);
  if (unit == "file units") {
    // The dents sweep's heatmap said "body.dents.at[0]" with no unit.
    if (!(length_unit > 0)) return name;
    for (const auto& [metres, symbol] :
         {std::pair{1.0, "m"}, {0.1, "dm"}, {0.01, "cm"}, {0.001, "mm"}, {0.0254, "in"}})
      if (length_unit == metres) return name + " [" + symbol + "]";
    return name + " [" + rb::show(length_unit) + " m]";
  }
  return unit.empty() ? name : name + " [" + unit + "]";
}

// Splits one CSV line (RFC 4180 quoting); nullopt when its quotes do not close.
std::optional<std::vector<std::string>> splitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        fields.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        fields.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) return std::nullopt;
  return fields;
}

// The metric --metric names (metricProblem has said when it names none).
tasks::SweepMetric metricNamed(const std::string& name) {
  return rb::parseName<tasks::SweepMetric>(name).value_or(tasks::SweepMetric::FirstReversal);
}

// Why --metric names no metric, or nothing.
rb::Status metricProblem(const std::string& name) {
  if (rb::parseName<tasks::SweepMetric>(name)) return {};
  const auto nearest = rb::nearestWord(name, rb::namesOf<tasks::SweepMetric>());
  return rb::Status::fail("--metric: '" + name + "' is not a column to plot" +
                          (nearest ? "; did you mean " + *nearest + "?" : std::string()) +
                          " (one of " + rb::choices<tasks::SweepMetric>(", ") + ")");
}

// The field of `name` in a line of a table of these result columns, or none.
std::optional<std::string> fieldOf(const std::vector<std::string>& fields, std::size_t axes,
                                   const tasks::SweepColumns& columns, std::string_view name) {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i]->column.name == name)
      return 1 + axes + i < fields.size() ? std::optional(fields[1 + axes + i]) : std::nullopt;
  return std::nullopt;
}

// The metric from a line of a shard's table (the merge reads the files the shards wrote): none
// where the run was not ok (a table without the status column: where the field is empty).
double metricOf(const std::vector<std::string>& fields, std::size_t axes,
                const tasks::SweepColumns& columns, tasks::SweepMetric metric) {
  const auto value = fieldOf(fields, axes, columns, rb::nameOf(metric));
  const auto status = fieldOf(fields, axes, columns, "status");
  if (!value || value->empty() || (status && *status != "ok")) return std::nan("");
  return std::strtod(value->c_str(), nullptr);
}
double metricOf(const std::string& line, std::size_t axes, const tasks::SweepColumns& columns,
                tasks::SweepMetric metric) {
  const auto fields = splitCsv(line);
  return fields ? metricOf(*fields, axes, columns, metric) : std::nan("");
}

// Each line's forecast_s, to draw beside its first reversal (the theory against the runs: what a
// lab plots), where the table has it and the plot is of first_reversal_s; else none. The
// theory's figure is the scene's, whatever became of its run: drawn for a run that stopped too.
std::vector<double> forecastsOf(const std::vector<std::string>& lines, std::size_t axes,
                                const tasks::SweepColumns& columns, tasks::SweepMetric metric) {
  std::vector<double> f;
  const auto forecast = rb::nameOf(tasks::SweepMetric::Forecast);
  if (metric != tasks::SweepMetric::FirstReversal ||
      std::none_of(columns.begin(), columns.end(),
                   [&](const tasks::SweepResultColumn* c) { return c->column.name == forecast; }))
    return f;
  for (const std::string& line : lines) {
    const auto fields = splitCsv(line);
    const auto value = fields ? fieldOf(*fields, axes, columns, forecast) : std::nullopt;
    f.push_back(value && !value->empty() ? std::strtod(value->c_str(), nullptr) : std::nan(""));
  }
  return f;
}

// Why --metric cannot be plotted from a table of these columns, or nothing.
rb::Status metricListed(const std::string& name, const tasks::SweepColumns& columns) {
  for (const tasks::SweepResultColumn* c : columns)
    if (c->column.name == name) return {};
  std::string listed;
  for (const tasks::SweepResultColumn* c : columns)
    listed += (listed.empty() ? "" : ", ") + std::string(c->column.name);
  return rb::Status::fail("--metric " + name + ": the sweep's columns: does not list it (" +
                          listed + "); add it there to plot it");
}

namespace {

// The metric along one axis (the line plot of plotTable): the figure titled `title`, its panel
// `named`; the axis's values are the table's rows `stride` apart.
rb::Status plotLine(const std::string& png, tasks::SweepMetric metric_id, const std::string& title,
                    const std::string& named, const Table& table, std::size_t x,
                    std::int64_t stride) {
  const std::string metric(rb::nameOf(metric_id));
  Panel panel;
  panel.title = named;
  panel.x_label = sweepLabel(table.keys[x], table.length_unit);
  panel.y_label = sweepLabel(metric);
  Series series;
  series.title = metric;
  std::vector<double> xs;
  for (std::size_t i = 0; i < table.axis_values[x].size(); ++i) {
    xs.push_back(std::strtod(table.axis_values[x][i].c_str(), nullptr));
    const auto row = static_cast<std::size_t>(static_cast<std::int64_t>(i) * stride);
    series.points.emplace_back(xs.back(), table.values[row]);
  }
  panel.log_x = logarithmicAxis(xs);
  // Every value of the axis spanned, and a missing point said (the runs that did not reverse
  // would otherwise vanish from the axis: spins −8 … 8 drawn as −8 … −1).
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  if (*lo < *hi) panel.x_range = std::pair{*lo, *hi};
  if (std::any_of(series.points.begin(), series.points.end(),
                  [](const auto& p) { return !std::isfinite(p.second); }))
    panel.note = "no point: no value (" +
                 std::string(metric == "first_reversal_s" ? "no reversal, or " : "") +
                 "run stopped or refused)";
  panel.series.push_back(series);
  if (!table.forecast.empty()) {
    Series theory;
    theory.title = "forecast_s (averaged theory)";
    theory.color = "#009e73";  // Okabe and Ito's bluish green, beside gnuplot's first purple
    theory.dash = 2;
    theory.point_type = 6;  // an open circle
    for (std::size_t i = 0; i < xs.size(); ++i)
      theory.points.emplace_back(
          xs[i], table.forecast[static_cast<std::size_t>(static_cast<std::int64_t>(i) * stride)]);
    if (std::any_of(theory.points.begin(), theory.points.end(),
                    [](const auto& p) { return !std::isfinite(p.second); }))
      panel.note += std::string(panel.note.empty() ? "" : "; ") +
                    "forecast_s: none where the theory gives none (forecast_note says why)";
    panel.series.push_back(theory);
  }
  return plotPng(png, title, {panel}, 900, 500);
}

}  // namespace

// Draws `metric` over the first two axes of more than one value (a heatmap), or the one such
// axis (a line plot); every other axis at its first value, said in the title. An axis of one
// value is never a heatmap's side: gnuplot leaves an image one cell tall grey, which reads as
// "no value" where every run had one.
rb::Status plotTable(const std::string& png, tasks::SweepMetric metric_id, const std::string& title,
                     const Table& table) {
  const std::string metric(rb::nameOf(metric_id));
  const std::size_t axes = table.keys.size();
  // Row index of coordinates (i0, i1, 0, 0, …).
  std::vector<std::int64_t> stride(axes, 1);
  for (std::size_t i = axes; i-- > 1;)
    stride[i - 1] = stride[i] * static_cast<std::int64_t>(table.axis_values[i].size());
  std::vector<std::size_t> drawn;
  for (std::size_t i = 0; i < axes && drawn.size() < 2; ++i)
    if (table.axis_values[i].size() > 1) drawn.push_back(i);
  if (drawn.empty()) drawn.push_back(0);  // one run: a point
  std::string fixed;
  for (std::size_t i = 0; i < axes; ++i)
    if (std::find(drawn.begin(), drawn.end(), i) == drawn.end())
      fixed += (fixed.empty() ? "" : ", ") + table.keys[i] + " = " + table.axis_values[i][0];
  // The metric in words in the title (the figure's story), its column's name on the axis.
  const std::string named =
      tasks::columnOf(metric_id).words + (fixed.empty() ? "" : " (" + fixed + ")");
  const auto at = [&](std::size_t axis, std::size_t i) {
    return static_cast<std::size_t>(static_cast<std::int64_t>(i) * stride[axis]);
  };
  if (drawn.size() == 1)
    return plotLine(png, metric_id, title + ": " + named, named, table, drawn[0], stride[drawn[0]]);
  const std::size_t x = drawn[0], y = drawn[1];
  Heatmap map;
  map.title = title + ": " + named;
  map.x_label = sweepLabel(table.keys[x], table.length_unit);
  map.y_label = sweepLabel(table.keys[y], table.length_unit);
  map.value_label = sweepLabel(metric);
  map.x_values = table.axis_values[x];
  map.y_values = table.axis_values[y];
  for (std::size_t ix = 0; ix < map.x_values.size(); ++ix)
    for (std::size_t iy = 0; iy < map.y_values.size(); ++iy)
      map.values.push_back(table.values[at(x, ix) + at(y, iy)]);
  map.note = "grey: no value (" +
             std::string(metric == "first_reversal_s" ? "no reversal, or " : "") +
             "run stopped or refused)";
  return heatmapPng(png, map, 900, 600);
}

}  // namespace app

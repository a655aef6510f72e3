#include "tasks/sweep_columns.hpp"

#include <algorithm>
#include <cmath>

namespace tasks {
namespace {

double orNan(const std::optional<double>& v) {
  return v.value_or(std::nan(""));
}

using M = SweepMetric;
using Row = SweepRow;

// The columns after the varied keys. `status` is a word to group by; why a run stopped is
// `stop_reason` (a code) and `message` (its words); wall_s last of the default columns, the one
// that varies between runs of the same sweep. What each needs of a run: status and its reasons
// say how the run went as far as it was taken, wall_s what that took; first_reversal_s is known
// once the reversal rule has confirmed it (sim/reversals.hpp: nothing after undoes it); the
// count, the final spin, the largest tilt and the energy lost can change until the end;
// forecast_s is the theory's, from the scene alone.
const SweepResultColumn kResults[] = {
    {{"status", "", "ok | stopped | refused"},
     [](const Row& r) { return std::string(rb::nameOf(r.status)); },
     std::nullopt,
     nullptr,
     nullptr,
     ColumnNeeds::Nothing},
    {{"stop_reason", "",
      "for a stopped run, why as a code: non_finite | energy_gain | on_rim (empty otherwise)"},
     [](const Row& r) { return r.stop ? std::string(rb::nameOf(*r.stop)) : std::string(); },
     std::nullopt,
     nullptr,
     nullptr,
     ColumnNeeds::Nothing},
    {{"first_reversal_s", "s", "first spin reversal (as simulate), empty when none"},
     [](const Row& r) { return number(r.first_reversal_s); },
     M::FirstReversal,
     [](const Row& r) { return orNan(r.first_reversal_s); },
     "time of the first reversal",
     ColumnNeeds::FirstReversal},
    {{"reversals", "", "count of spin reversals (as simulate)"},
     [](const Row& r) { return r.reversals ? std::to_string(*r.reversals) : std::string(); },
     M::Reversals,
     [](const Row& r) { return r.reversals ? static_cast<double>(*r.reversals) : std::nan(""); },
     "number of reversals",
     ColumnNeeds::WholeRun,
     /*by_default=*/true,
     /*whole=*/true},
    {{"final_spin", "rad/s", "n = w.z at the end of the run"},
     [](const Row& r) { return number(r.final_spin); },
     M::FinalSpin,
     [](const Row& r) { return orNan(r.final_spin); },
     "spin at the end"},
    {{"max_tilt_deg", "deg",
      "largest tilt of the body axis over the steps (to the stop, if it stopped)"},
     [](const Row& r) { return number(r.max_tilt_deg); },
     M::MaxTilt,
     [](const Row& r) { return orNan(r.max_tilt_deg); },
     "largest tilt"},
    {{"energy_lost", "", "fraction of the initial energy lost by the end"},
     [](const Row& r) { return number(r.energy_lost); },
     M::EnergyLost,
     [](const Row& r) { return orNan(r.energy_lost); },
     "share of the energy lost"},
    {{"message", "",
      "for a stopped or refused run, why in words (the run's or the scene loader's line)"},
     [](const Row& r) { return r.message; },
     std::nullopt,
     nullptr,
     nullptr,
     ColumnNeeds::Nothing},
    // A measurement: microseconds, no more.
    {{"wall_s", "s", "wall-clock time of the run (the only column that varies between runs)"},
     [](const Row& r) { return fixed(r.wall_s, 6); },
     M::Wall,
     [](const Row& r) { return r.wall_s; },
     "wall time of each run",
     ColumnNeeds::Nothing},
    // Only where listed: the table without `columns:` is as it was.
    {{"forecast_s", "s",
      "first reversal forecast by the averaged theory (as analyze), empty when it forecasts "
      "none or the scene is outside its range"},
     [](const Row& r) { return number(r.forecast_s); },
     M::Forecast,
     [](const Row& r) { return orNan(r.forecast_s); },
     "forecast first reversal",
     ColumnNeeds::Nothing,
     /*by_default=*/false,
     /*whole=*/false,
     RowExtra::Forecast},
    // Why forecast_s is empty where it is: a word to group by, as status is.
    {{"forecast_note", "",
      "why forecast_s is or is not a time: within | beyond (the theory's range) | none_in_run | "
      "outside_range | not_spun | cannot_stand | no_theory"},
     [](const Row& r) {
       return r.forecast_note ? std::string(rb::nameOf(*r.forecast_note)) : std::string();
     },
     std::nullopt,
     nullptr,
     nullptr,
     ColumnNeeds::Nothing,
     /*by_default=*/false,
     /*whole=*/false,
     RowExtra::Forecast},
    // Whether the body prints: a maker's sweep over the dents keeps the rows that export.
    {{"exports", "",
      "whether export writes the row's body as a solid: yes | no (a dent cuts through its "
      "bottom or its rim)"},
     [](const Row& r) {
       return r.exports ? std::string(*r.exports ? "yes" : "no") : std::string();
     },
     std::nullopt,
     nullptr,
     nullptr,
     ColumnNeeds::Nothing,
     /*by_default=*/false,
     /*whole=*/false,
     RowExtra::Exports},
};

}  // namespace

std::span<const SweepResultColumn> sweepResultTable() {
  return kResults;
}

const SweepResultColumn& columnOf(SweepMetric metric) {
  for (const SweepResultColumn& c : kResults)
    if (c.metric == metric) return c;
  return kResults[0];  // (every metric has its row: the sweep tests look up each)
}

double metricOf(const SweepRow& row, SweepMetric metric) {
  if (row.status != RowStatus::Ok) return std::nan("");
  return columnOf(metric).value(row);
}

bool asksFor(const SweepColumns& columns, RowExtra extra) {
  return std::any_of(columns.begin(), columns.end(),
                     [&](const SweepResultColumn* c) { return c->extra == extra; });
}

const SweepResultColumn* findSweepColumn(std::string_view name) {
  for (const SweepResultColumn& c : kResults)
    if (name == c.column.name) return &c;
  return nullptr;
}

std::vector<std::string> sweepColumnNames() {
  std::vector<std::string> names;
  for (const SweepResultColumn& c : kResults) names.emplace_back(c.column.name);
  return names;
}

ColumnNeeds needsOf(const SweepColumns& columns) {
  ColumnNeeds needs = ColumnNeeds::Nothing;
  for (const SweepResultColumn* c : columns) needs = std::max(needs, c->needs);
  return needs;
}

}  // namespace tasks

#include "tasks/sweep.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

#include "scene/key_path.hpp"
#include "scene/keys.hpp"
#include "sim/compile.hpp"
#include "sim/rollout.hpp"
#include "sim/tessellate.hpp"
#include "tasks/analysis.hpp"
#include "tasks/job_pool.hpp"
#include "tasks/output.hpp"
#include "util/assets.hpp"
#include "util/nearest.hpp"

namespace tasks {
namespace {

// The default table's result columns' names, units and meanings.
const std::vector<Column>& resultColumns() {
  static const std::vector<Column> columns = [] {
    std::vector<Column> out;
    for (const SweepResultColumn& c : sweepResultTable())
      if (c.by_default) out.push_back(c.column);
    return out;
  }();
  return columns;
}

std::vector<Column> namesOf(const SweepColumns& columns) {
  std::vector<Column> out;
  for (const SweepResultColumn* c : columns) out.push_back(c->column);
  return out;
}

// Takes the run as far as its columns need: to its end; until the reversal rule has confirmed
// the first reversal (sim/reversals.hpp: a reversal once counted stays, so the value is the one
// the whole run gives: the same steps, fed to the same rule); or not at all. False when it
// stopped before (a divergence or a stop request).
bool advanceAsNeeded(sim::Rollout& rollout, ColumnNeeds needs) {
  const double end = rollout.endTime();
  switch (needs) {
    case ColumnNeeds::WholeRun:
      return rollout.advanceTo(end);
    case ColumnNeeds::FirstReversal:
      return rollout.advanceToReversal(end);
    case ColumnNeeds::Nothing:
      break;
  }
  return true;
}

double since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The compiled bodies of a sweep, one per body group, compiled by the first run that needs it
// and released when the last run of this call that uses it is done.
class Bodies {
 public:
  using Compiled = rb::Result<std::shared_ptr<const sim::Body>>;

  Bodies(const scene::Sweep& sweep, const std::vector<std::int64_t>& rows)
      : sweep_(sweep), slots_(static_cast<std::size_t>(sweep.bodyGroups())) {
    for (std::int64_t row : rows) ++slots_[static_cast<std::size_t>(sweep.bodyGroup(row))].uses;
  }

  Compiled get(std::int64_t row, const sim::SceneSpec& spec) {
    Slot& slot = slots_[static_cast<std::size_t>(sweep_.bodyGroup(row))];
    std::call_once(slot.once, [&] { slot.body.emplace(sim::compileBody(spec)); });
    return *slot.body;
  }

  // Whether `export` writes the row's body as a solid (at export's default number of segments):
  // a property of the body, so worked out once for its group.
  bool exports(std::int64_t row, const sim::Body& body) {
    Slot& slot = slots_[static_cast<std::size_t>(sweep_.bodyGroup(row))];
    std::call_once(slot.exports_once, [&] {
      slot.exports = sim::dentsLieWithin(body.surface, body.dents, sim::kDefaultSegments);
    });
    return slot.exports;
  }

  void release(std::int64_t row) {
    Slot& slot = slots_[static_cast<std::size_t>(sweep_.bodyGroup(row))];
    if (--slot.uses == 0) slot.body.reset();
  }

 private:
  struct Slot {
    std::once_flag once, exports_once;
    std::optional<Compiled> body;
    bool exports = false;
    std::atomic<std::int64_t> uses{0};
  };
  const scene::Sweep& sweep_;
  std::vector<Slot> slots_;
};

// What a row computes: how far its run goes, and whether the theory's forecast is asked for.
struct RowWork {
  ColumnNeeds needs = ColumnNeeds::WholeRun;
  bool forecast = false;
  bool exports = false;
};

// One run of the sweep, or nothing when it was stopped on request.
std::optional<SweepRow> runRow(const scene::Sweep& sweep, const scene::SweepScenes& scenes,
                               Bodies& bodies, std::int64_t index, std::stop_token stop,
                               const RowWork& work) {
  const auto start = std::chrono::steady_clock::now();
  SweepRow row;
  row.row = index;
  const std::vector<int> at = sweep.coordinates(index);
  for (std::size_t i = 0; i < sweep.axes.size(); ++i)
    row.values.push_back(sweep.axes[i].values[at[i]]);
  auto refused = [&](const std::string& why) {
    row.status = RowStatus::Refused;
    row.message = why;
    row.wall_s = since(start);
    return row;
  };
  auto loaded = scenes.scene(index);
  if (!loaded) return refused(loaded.error().text());
  auto body = bodies.get(index, loaded->spec);
  struct Release {
    Bodies& bodies;
    std::int64_t row;
    ~Release() { bodies.release(row); }
  } release{bodies, index};
  if (!body) return refused(scene::describe(loaded.value(), body.error()));
  auto model = sim::compileRun(loaded->spec, body.value());
  if (!model) return refused(scene::describe(loaded.value(), model.error()));

  if (work.exports) row.exports = bodies.exports(index, *model->body);
  if (work.forecast) {
    const Forecast forecast = forecastReversal(model.value());
    row.forecast_s = forecast.time;
    row.forecast_note = forecast.note;
  }
  sim::Rollout rollout(std::move(model).value());
  rollout.stopWith(stop);
  const double end = rollout.endTime();
  const bool went = advanceAsNeeded(rollout, work.needs);
  const sim::RunSummary& run = rollout.summary();
  if (run.stop_requested) return std::nullopt;
  // The first reversal as far as the run went; the rest only of a whole run (a run stopped
  // early leaves them empty, not as they stood when it stopped).
  row.first_reversal_s = run.first_reversal_s;
  if (work.needs == ColumnNeeds::WholeRun) {
    row.reversals = static_cast<std::int64_t>(run.reversals.size());
    // A stopped run's largest tilt too: how far it went over is often why it stopped.
    row.max_tilt_deg = run.max_tilt_deg;
  }
  if (went && work.needs == ColumnNeeds::WholeRun) {
    const sim::Telemetry last = rollout.sampleAt(end);
    row.final_spin = last.spin;
    row.energy_lost = (run.first.energy - last.energy) / std::abs(run.first.energy);
  } else if (!went) {
    row.status = RowStatus::Stopped;
    row.message = run.divergence.value_or("the run did not reach its end");
    if (run.stop) row.stop = run.stop->reason;
  }
  row.wall_s = since(start);
  return row;
}

}  // namespace

std::vector<std::string> sweepNotes(const scene::Sweep& sweep, const scene::SweepScenes& scenes) {
  std::vector<std::string> notes;
  for (const scene::SweepAxis& axis : sweep.axes)
    if (axis.key == "contact.model") return notes;
  const auto first = scenes.scene(0);
  if (!first || first->spec.contact.model != "rolling") return notes;
  const std::string physics = rb::docPage("physics.md");
  for (const scene::SweepAxis& axis : sweep.axes) {
    if (axis.key == "contact.friction")
      notes.push_back(axis.place + ": " + axis.key +
                      " does not change a rolling run, which never slips (" + physics +
                      " P4.5): the rows along it are alike. contact.model: auto lets the body "
                      "slip; a rolling run's sidecar gives the friction it needed "
                      "(friction_needed)");
    else if (axis.key.starts_with("contact.") && axis.key != "contact.air_drag")
      notes.push_back(axis.place + ": " + axis.key + " is not used by a rolling run (" + physics +
                      " P4.5): the rows along it are alike; contact.model: auto uses it where "
                      "the body slides");
  }
  return notes;
}

std::span<const Column> sweepResultColumns() {
  return resultColumns();
}

namespace {

// The columns a sweep lists, each one of the table's: an unknown name is said where it is
// listed, with the nearest column's and the list of them.
rb::Status checkColumns(const scene::Sweep& sweep) {
  const std::vector<std::string> names = sweepColumnNames();
  for (const scene::SweepColumnName& c : sweep.columns) {
    if (findSweepColumn(c.name)) continue;
    std::string known;
    for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
    const std::optional<std::string> nearest = rb::nearestWord(c.name, names);
    const std::string at =
        c.where.line > 0 ? c.where.file + ":" + std::to_string(c.where.line) : c.where.file;
    // A file's line names the key ("sw.yaml:4: columns: …"); an argument is the key itself
    // (Python's "argument columns: …").
    const std::string label = c.where.line > 0 ? at + ": columns: " : at + ": ";
    rb::Error e{"", label + c.name + " is not a column of the table" +
                        (nearest ? "; did you mean " + *nearest + "?" : "") +
                        " (the columns: " + known + ")"};
    e.where = c.where;
    return e;
  }
  return {};
}

rb::Result<scene::Sweep> checked(rb::Result<scene::Sweep> sweep) {
  if (!sweep) return sweep;
  if (auto ok = checkColumns(sweep.value()); !ok) return ok.error();
  return sweep;
}

}  // namespace

rb::Result<scene::Sweep> loadSweep(const std::string& path) {
  return checked(scene::loadSweep(path));
}

rb::Result<scene::Sweep> loadSweepText(const std::string& yaml, const std::string& name,
                                       const scene::SweepBase& base) {
  return checked(scene::loadSweepText(yaml, name, base));
}

rb::Status setColumns(scene::Sweep& sweep, const std::vector<std::string>& names,
                      const std::string& named) {
  const rb::Error::Where where{named, 0, "columns"};
  auto refused = [&](const std::string& why) {
    rb::Error e{"", named + ": " + why};
    e.where = where;
    return e;
  };
  if (names.empty()) return refused("give at least one column, e.g. [\"first_reversal_s\"]");
  sweep.columns.clear();
  for (const std::string& name : names) {
    for (const scene::SweepColumnName& c : sweep.columns)
      if (c.name == name) return refused(name + " is listed twice");
    sweep.columns.push_back({name, where});
  }
  return checkColumns(sweep);
}

SweepColumns tableColumns(const scene::Sweep& sweep) {
  SweepColumns out;
  if (sweep.columns.empty()) {
    for (const SweepResultColumn& c : sweepResultTable())
      if (c.by_default) out.push_back(&c);
    return out;
  }
  for (const scene::SweepColumnName& c : sweep.columns)
    if (const SweepResultColumn* column = findSweepColumn(c.name)) out.push_back(column);
  return out;
}

SweepColumns columnsNamed(const std::vector<std::string>& names) {
  SweepColumns out;
  for (const std::string& name : names)
    if (const SweepResultColumn* column = findSweepColumn(name)) out.push_back(column);
  return out;
}

std::string sweepColumnUnit(const std::string& name) {
  for (const Column& c : resultColumns())
    if (name == c.name) return c.unit;
  const scene::Key* key = scene::findKey(scene::withoutIndex(name));
  return key ? std::string(key->unit) : "";
}

std::string sweepHeader(const std::vector<std::string>& keys, const SweepColumns& columns) {
  std::string line = "row";
  // (Appended piece by piece: `"," + string` trips a false -Wrestrict of GCC 12.)
  for (const std::string& key : keys) line.append(",").append(csvField(key));
  return line + "," + csvHeader(namesOf(columns));
}

std::string sweepRowPrefix(const scene::Sweep& sweep, std::int64_t row) {
  std::string line = std::to_string(row);
  const std::vector<int> at = sweep.coordinates(row);
  for (std::size_t i = 0; i < sweep.axes.size(); ++i)
    line.append(",").append(csvField(sweep.axes[i].values[at[i]]));
  return line + ",";
}

std::string sweepLine(const SweepRow& row, const SweepColumns& columns) {
  std::string line = std::to_string(row.row);
  for (const std::string& v : row.values) line.append(",").append(csvField(v));
  for (const SweepResultColumn* c : columns) line.append(",").append(csvField(c->text(row)));
  return line;
}

nlohmann::json sweepColumnsJson(const std::vector<std::string>& keys, const SweepColumns& results) {
  nlohmann::json columns = nlohmann::json::array();
  columns.push_back({{"name", "row"},
                     {"unit", ""},
                     {"meaning", "index of the run in the sweep's order (first axis slowest)"}});
  // An axis's unit is its scene key's (the schema's: lengths in the file's unit).
  for (const std::string& key : keys) {
    const scene::Key* k = scene::findKey(scene::withoutIndex(key));
    columns.push_back({{"name", key},
                       {"unit", sweepColumnUnit(key)},
                       {"meaning", "the value put into the scene" +
                                       (k ? ": " + std::string(k->doc) : std::string())}});
  }
  for (const auto& c : columnsJson(namesOf(results))) columns.push_back(c);
  return columns;
}

nlohmann::json sweepAxesJson(const scene::Sweep& sweep) {
  nlohmann::json axes = nlohmann::json::array();
  for (const auto& axis : sweep.axes) axes.push_back({{"key", axis.key}, {"values", axis.values}});
  return axes;
}

namespace {

// A row that threw is a stopped row, with its values and the exception's words.
SweepRow thrownRow(const scene::Sweep& sweep, std::int64_t index, const std::exception& e) {
  SweepRow row;
  row.row = index;
  const std::vector<int> at = sweep.coordinates(index);
  for (std::size_t a = 0; a < sweep.axes.size(); ++a)
    row.values.push_back(sweep.axes[a].values[at[a]]);
  row.status = RowStatus::Stopped;
  row.message = e.what();
  return row;
}

}  // namespace

SweepRun runSweep(const scene::Sweep& sweep, const scene::SweepScenes& scenes,
                  const std::vector<std::int64_t>& rows, const SweepOptions& options) {
  SweepRun out;
  Bodies bodies(sweep, rows);
  const SweepColumns columns = tableColumns(sweep);
  RowWork work;
  work.needs = needsOf(columns);
  work.forecast = asksFor(columns, RowExtra::Forecast);
  work.exports = asksFor(columns, RowExtra::Exports);
  std::vector<std::optional<SweepRow>> results(rows.size());
  std::mutex finished_mutex;
  const auto start = std::chrono::steady_clock::now();
  const PoolRun pool = runJobs(
      rows.size(), options.jobs,
      [&](std::size_t i, std::stop_token stop) {
        std::optional<SweepRow> row;
        try {
          row = runRow(sweep, scenes, bodies, rows[i], stop, work);
        } catch (const std::exception& e) {
          row = thrownRow(sweep, rows[i], e);
        }
        if (!row) return false;
        if (options.finished) {
          std::lock_guard lock(finished_mutex);
          options.finished(*row);
        }
        results[i] = std::move(row);
        return true;
      },
      options.cancelled, options.progress);
  out.threads = pool.threads;
  out.wall_s = since(start);
  out.interrupted = pool.interrupted;
  for (auto& r : results)
    if (r) out.rows.push_back(std::move(*r));
  return out;
}

rb::Status writeSweepTable(const std::string& output, const std::vector<std::string>& keys,
                           const SweepColumns& columns, const std::vector<std::string>& lines,
                           nlohmann::json sidecar) {
  if (auto made = makeParentFolder(output); !made) return made;
  auto csv = AtomicOutput::open(output);
  if (!csv) return csv.error();
  auto meta = AtomicOutput::open(output + ".json");
  if (!meta) return meta.error();
  csv->stream() << sweepHeader(keys, columns) << "\n";
  for (const std::string& line : lines) csv->stream() << line << "\n";
  sidecar["columns"] = sweepColumnsJson(keys, columns);
  meta->stream() << sidecar.dump(2) << "\n";
  if (auto e = csv->commit(); !e) return e;
  return meta->commit();
}

}  // namespace tasks

// `rattleback sweep`: every scene of a sweep file on a pool of threads the command owns (the
// library makes none), one CSV row per run in the sweep's order; shards, their merge, and job
// scripts for Slurm and GNU parallel (README "Sweeps").
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "tasks/output.hpp"
#include "app/plot.hpp"
#include "app/progress.hpp"
#include "scene/sweep.hpp"
#include "sim/compile.hpp"
#include "sim/rollout.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

// The columns after the varied keys, with their units (for the sidecar and the plot).
const std::pair<const char*, const char*> kResults[] = {
    {"status", "ok | stopped: reason | refused: reason"},
    {"first_reversal_s", "s: first spin reversal (as simulate), empty when none"},
    {"reversals", "count of spin reversals (as simulate)"},
    {"final_spin", "rad/s: n = w.z at the end of the run"},
    {"max_tilt_deg", "degrees: largest tilt of the body axis over the steps (to the stop, if it stopped)"},
    {"energy_lost", "fraction of the initial energy lost by the end"},
    {"wall_s", "s: wall-clock time of the run (the only column that varies between runs)"},
};

bool isMetric(const std::string& name) {
  for (const auto& [column, unit] : kResults)
    if (name == column && name != std::string("status")) return true;
  return false;
}

std::string metricNames() {
  std::string names;
  for (const auto& [column, unit] : kResults)
    if (column != std::string("status")) names += std::string(names.empty() ? "" : ", ") + column;
  return names;
}

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c == '\n' || c == '\r' ? ' ' : c;
  }
  return out + "\"";
}

// Splits one CSV line (RFC 4180 quoting); nullopt when its quotes do not close.
std::optional<std::vector<std::string>> splitCsv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') fields.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else fields.back() += c;
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

std::string number(double v, const char* format = "%.10g") {
  if (!std::isfinite(v)) return "";
  char text[48];
  std::snprintf(text, sizeof text, format, v + 0.0);
  return text;
}

std::string header(const std::vector<std::string>& keys) {
  std::string line = "row";
  // (Appended piece by piece: `"," + string` trips a false -Wrestrict of GCC 12.)
  for (const std::string& key : keys) line.append(",").append(field(key));
  for (const auto& [column, unit] : kResults) line += std::string(",") + column;
  return line;
}

std::vector<std::string> axisKeys(const scene::Sweep& sweep) {
  std::vector<std::string> keys;
  for (const auto& axis : sweep.axes) keys.push_back(axis.key);
  return keys;
}

// "row,value,value," — the part of a row fixed by the sweep, before its results.
std::string rowPrefix(const scene::Sweep& sweep, std::int64_t row) {
  std::string line = std::to_string(row);
  const std::vector<int> at = sweep.coordinates(row);
  for (std::size_t i = 0; i < sweep.axes.size(); ++i)
    line.append(",").append(field(sweep.axes[i].values[at[i]]));
  return line + ",";
}

// The compiled bodies of a sweep, one per body group, compiled by the first run that needs it
// and released when the last run of this process that uses it is done.
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

  void release(std::int64_t row) {
    Slot& slot = slots_[static_cast<std::size_t>(sweep_.bodyGroup(row))];
    if (--slot.uses == 0) slot.body.reset();
  }

 private:
  struct Slot {
    std::once_flag once;
    std::optional<Compiled> body;
    std::atomic<std::int64_t> uses{0};
  };
  const scene::Sweep& sweep_;
  std::vector<Slot> slots_;
};

// One run of the sweep: its results after rowPrefix, or nothing when it was stopped on request.
std::optional<std::string> runRow(const scene::SweepScenes& scenes,
                                  Bodies& bodies, std::int64_t row, std::stop_token stop) {
  const auto start = std::chrono::steady_clock::now();
  auto refused = [&](const std::string& why) {
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return field("refused: " + why) + ",,,,,," + number(wall, "%.6f");
  };
  auto loaded = scenes.scene(row);
  if (!loaded) return refused(loaded.error().text());
  auto body = bodies.get(row, loaded->spec);
  struct Release {
    Bodies& bodies;
    std::int64_t row;
    ~Release() { bodies.release(row); }
  } release{bodies, row};
  if (!body) return refused(scene::describe(loaded.value(), body.error()));
  auto model = sim::compileRun(loaded->spec, body.value());
  if (!model) return refused(scene::describe(loaded.value(), model.error()));

  sim::Rollout rollout(std::move(model).value());
  rollout.stopWith(stop);
  const double end = rollout.endTime();
  const bool reached = rollout.advanceTo(end);
  const sim::RunSummary& run = rollout.summary();
  if (run.stop_requested) return std::nullopt;
  std::string status = "ok";
  std::string final_spin, energy_lost;
  // A stopped run's largest tilt too: how far it went over is often why it stopped.
  const std::string max_tilt = number(run.max_tilt_deg);
  if (reached) {
    const sim::Telemetry last = rollout.sampleAt(end);
    final_spin = number(last.spin);
    energy_lost = number((run.first.energy - last.energy) / std::abs(run.first.energy));
  } else {
    status = "stopped: " + run.divergence.value_or("the run did not reach its end");
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return field(status) + "," +
         (run.first_reversal_s ? number(*run.first_reversal_s) : std::string()) + "," +
         std::to_string(run.reversals.size()) + "," + final_spin + "," + max_tilt + "," +
         energy_lost + "," + number(wall, "%.6f");
}

struct Shard {
  std::int64_t index = 0, count = 1;
};

std::optional<Shard> parseShard(const std::string& text) {
  Shard shard;
  char slash = 0, extra = 0;
  long long i = 0, n = 0;
  if (std::sscanf(text.c_str(), "%lld%c%lld%c", &i, &slash, &n, &extra) != 3 || slash != '/' ||
      n < 1 || i < 0 || i >= n)
    return std::nullopt;
  shard.index = i;
  shard.count = n;
  return shard;
}

// OUT.csv → OUT.shard-I-of-N.csv; `index` may be a shell expansion for a job script.
std::string shardPath(const std::string& output, const std::string& index, std::int64_t count) {
  fs::path p(output);
  const std::string name = p.stem().string() + ".shard-" + index + "-of-" +
                           std::to_string(count) + p.extension().string();
  return (p.parent_path() / name).string();
}

std::string shardPath(const std::string& output, const Shard& shard) {
  return shardPath(output, std::to_string(shard.index), shard.count);
}

// A word for a shell, single-quoted.
std::string shellWord(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string selfPath() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("rattleback") : exe.string();
}

int emitScript(const SweepArgs& args, const scene::Sweep& sweep, const std::string& output) {
  if (args.shards < 1) {
    std::cerr << "--emit " << args.emit << " needs --shards N (N ≥ 1): how many pieces to run\n";
    return kBadInput;
  }
  if (args.shards > sweep.rows()) {
    std::cerr << "--shards: " << args.shards << " shards for " << sweep.rows()
              << " runs leaves some empty; at most " << sweep.rows() << "\n";
    return kBadInput;
  }
  const std::string exe = selfPath();
  const std::string sweep_file = fs::absolute(sweep.file).lexically_normal().string();
  const std::string out = fs::absolute(output).lexically_normal().string();
  const std::string n = std::to_string(args.shards);
  std::vector<std::string> shard_files;
  for (int i = 0; i < args.shards; ++i) shard_files.push_back(shardPath(out, Shard{i, args.shards}));
  if (args.emit == "parallel") {
    // One command line per shard, for `parallel` (GNU parallel reads commands from stdin).
    for (int i = 0; i < args.shards; ++i)
      std::cout << shellWord(exe) << " sweep " << shellWord(sweep_file) << " --shard " << i << "/"
                << n << " -j 1 -q -o " << shellWord(shard_files[i]) << "\n";
    return kOk;
  }
  const std::string stem = fs::path(sweep.file).stem().string();
  const std::string log_dir = fs::path(out).parent_path().string();
  std::string merge = shellWord(exe) + " sweep merge -q " + shellWord(out);
  for (const std::string& f : shard_files) merge.append(" ").append(shellWord(f));
  std::cout << "#!/bin/bash\n"
            << "# " << stem << ": " << sweep.rows() << " runs of rattleback sweep "
            << sweep_file << "\n"
            << "# as a Slurm job array of " << n << " tasks, one shard each; the first task also\n"
            << "# submits the merge, which runs once every task has succeeded (afterok) and writes\n"
            << "# " << out << ".\n# Submit with: sbatch THIS_FILE\n"
            << "#SBATCH --job-name=rattleback-" << stem << "\n"
            << "#SBATCH --array=0-" << args.shards - 1 << "\n"
            << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
            << "#SBATCH --output=" << log_dir << "/slurm-" << stem << "-%A_%a.out\n"
            << "set -euo pipefail\n"
            << "mkdir -p " << shellWord(log_dir) << "\n"
            << "if [ \"$SLURM_ARRAY_TASK_ID\" = 0 ]; then\n"
            << "  sbatch --parsable --job-name=rattleback-" << stem << "-merge"
            << " --dependency=afterok:\"$SLURM_ARRAY_JOB_ID\" --output=" << log_dir << "/slurm-"
            << stem << "-merge-%j.out --wrap=" << shellWord(merge) << "\n"
            << "fi\n"
            << "exec " << shellWord(exe) << " sweep " << shellWord(sweep_file)
            << " --shard \"$SLURM_ARRAY_TASK_ID/" << n << "\" -j \"${SLURM_CPUS_PER_TASK:-1}\" -q"
            << " -o \"" << shardPath(out, "$SLURM_ARRAY_TASK_ID", args.shards) << "\"\n";
  return kOk;
}

// The axes as the sidecar records them (the merge and the plot read them back).
nlohmann::json axesJson(const scene::Sweep& sweep) {
  nlohmann::json axes = nlohmann::json::array();
  for (const auto& axis : sweep.axes) axes.push_back({{"key", axis.key}, {"values", axis.values}});
  return axes;
}

nlohmann::json columnsJson(const std::vector<std::string>& keys) {
  nlohmann::json columns = nlohmann::json::array();
  columns.push_back({{"name", "row"}, {"unit", "index of the run in the sweep's order (first axis slowest)"}});
  for (const std::string& key : keys) columns.push_back({{"name", key}, {"unit", "the value put into the scene"}});
  for (const auto& [name, unit] : kResults) columns.push_back({{"name", name}, {"unit", unit}});
  return columns;
}

struct Table {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> axis_values;  // [axis][value]
  std::vector<std::string> lines;                     // in row order
};

// Draws `metric` over the first two axes (further axes at their first value; one axis: a line
// plot).
rb::Status plotTable(const std::string& png, const std::string& metric, const std::string& title,
                     const Table& table) {
  const std::size_t axes = table.keys.size();
  std::size_t column = 1 + axes;
  for (const auto& [name, unit] : kResults) {
    if (name == metric) break;
    ++column;
  }
  auto value = [&](const std::string& line) {
    const auto fields = splitCsv(line);
    // Only a run that reached its end has a value to show.
    if (!fields || fields->size() <= column || (*fields)[column].empty() ||
        (*fields)[1 + axes] != "ok")
      return std::nan("");
    return std::strtod((*fields)[column].c_str(), nullptr);
  };
  // Row index of coordinates (i0, i1, 0, 0, …).
  std::vector<std::int64_t> stride(axes, 1);
  for (std::size_t i = axes; i-- > 1;)
    stride[i - 1] = stride[i] * static_cast<std::int64_t>(table.axis_values[i].size());
  std::string fixed;
  for (std::size_t i = 2; i < axes; ++i)
    fixed += (fixed.empty() ? "" : ", ") + table.keys[i] + " = " + table.axis_values[i][0];
  if (axes == 1) {
    Panel panel;
    panel.title = metric;
    panel.x_label = table.keys[0];
    panel.y_label = metric;
    Series series;
    series.title = metric;
    for (std::size_t i = 0; i < table.lines.size(); ++i)
      series.points.emplace_back(std::strtod(table.axis_values[0][i].c_str(), nullptr), value(table.lines[i]));
    panel.series.push_back(series);
    return plotPng(png, title + ": " + metric, {panel}, 900, 500);
  }
  Heatmap map;
  map.title = title + ": " + metric + (fixed.empty() ? "" : " (" + fixed + ")");
  map.x_label = table.keys[0];
  map.y_label = table.keys[1];
  map.value_label = metric;
  map.x_values = table.axis_values[0];
  map.y_values = table.axis_values[1];
  for (std::size_t i0 = 0; i0 < map.x_values.size(); ++i0)
    for (std::size_t i1 = 0; i1 < map.y_values.size(); ++i1)
      map.values.push_back(value(table.lines[static_cast<std::size_t>(i0 * stride[0] + i1 * stride[1])]));
  map.note = "grey: no value (" + std::string(metric == "first_reversal_s" ? "no reversal, or " : "") +
             "run stopped or refused)";
  return heatmapPng(png, map, 900, 600);
}

// A sweep's table has a sidecar and a journal beside it: it must be a file, not a device or
// descriptor written in place (/dev/stdout.json would be made).
rb::Status checkTableIsAFile(const std::string& output) {
  if (rb::outputPlace(output).temporary.empty())
    return rb::Status::fail(output + ": a sweep's table is a file (its sidecar " + output +
                            ".json and its journal go beside it), not a device or pipe");
  return {};
}

rb::Status writeTable(const std::string& output, const std::vector<std::string>& keys,
                      const std::vector<std::string>& lines, nlohmann::json sidecar) {
  if (auto made = tasks::makeParentFolder(output); !made) return made;
  auto csv = tasks::AtomicOutput::open(output);
  if (!csv) return csv.error();
  auto meta = tasks::AtomicOutput::open(output + ".json");
  if (!meta) return meta.error();
  csv->stream() << header(keys) << "\n";
  for (const std::string& line : lines) csv->stream() << line << "\n";
  sidecar["columns"] = columnsJson(keys);
  meta->stream() << sidecar.dump(2) << "\n";
  if (auto e = csv->commit(); !e) return e;
  return meta->commit();
}

}  // namespace

int sweepCommand(const SweepArgs& args) {
  installInterruptHandlers();
  if (args.file.empty()) {
    std::cerr << "sweep: give a sweep file (e.g. rattleback sweep sweeps/spin-drag.yaml), or "
                 "'sweep merge OUT.csv SHARD…'\n";
    return kBadInput;
  }
  auto loaded = scene::loadSweep(args.file);
  if (!loaded) {
    std::cerr << loaded.error().text() << "\n";
    return kBadInput;
  }
  const scene::Sweep& sweep = loaded.value();
  if (!isMetric(args.metric)) {
    std::cerr << "--metric: '" << args.metric << "' is not a column to plot (one of "
              << metricNames() << ")\n";
    return kBadInput;
  }
  if (args.jobs < 0 || args.jobs > 1024) {
    std::cerr << "--jobs: threads must be 1 … 1024 (0 or none: all cores), not " << args.jobs << "\n";
    return kBadInput;
  }
  std::optional<Shard> shard;
  if (!args.shard.empty()) {
    shard = parseShard(args.shard);
    if (!shard) {
      std::cerr << "--shard: expected I/N with 0 ≤ I < N (e.g. 0/4), not '" << args.shard << "'\n";
      return kBadInput;
    }
    if (!args.plot.empty()) {
      std::cerr << "--plot: a shard holds only some rows; plot the merged table (rattleback sweep "
                   "merge OUT.csv SHARD… --plot PNG)\n";
      return kBadInput;
    }
  }
  const std::string stem = fs::path(args.file).stem().string();
  std::string output = args.output.empty() ? "out/" + stem + ".csv" : args.output;
  if (auto ok = checkTableIsAFile(output); !ok) {
    std::cerr << ok.error().text() << "\n";
    return kBadInput;
  }
  if (!args.emit.empty()) {
    if (args.emit != "slurm" && args.emit != "parallel") {
      std::cerr << "--emit: 'slurm' or 'parallel', not '" << args.emit << "'\n";
      return kBadInput;
    }
    return emitScript(args, sweep, output);
  }
  if (shard && args.output.empty()) output = shardPath(output, *shard);
  if (!args.plot.empty()) {
    if (auto made = checkPlotFile(args.plot); !made) {
      std::cerr << made.error().text() << "\n";
      return kBadInput;
    }
  }
  if (auto made = tasks::makeParentFolder(output); !made) {
    std::cerr << made.error().text() << "\n";
    return kBadInput;
  }
  auto scenes = scene::SweepScenes::open(sweep);
  if (!scenes) {
    std::cerr << scenes.error().text() << "\n";
    return kBadInput;
  }

  // The rows of this process, and those an interrupted run already finished (its journal).
  const std::vector<std::string> keys = axisKeys(sweep);
  const std::string head = header(keys);
  const std::string journal_path = output + ".partial";
  std::map<std::int64_t, std::string> done;
  std::vector<std::int64_t> rows;
  for (std::int64_t r = shard ? shard->index : 0; r < sweep.rows(); r += shard ? shard->count : 1)
    rows.push_back(r);
  const std::set<std::int64_t> mine(rows.begin(), rows.end());
  if (args.resume) {
    std::ifstream in(journal_path);
    if (!in) {
      std::cerr << journal_path << ": nothing to resume (no interrupted run wrote it); run "
                << "without --resume\n";
      return kBadInput;
    }
    std::string line;
    if (!std::getline(in, line) || line != head) {
      std::cerr << journal_path << ": its columns are not this sweep's; remove it, or run "
                << "without --resume\n";
      return kBadInput;
    }
    while (std::getline(in, line)) {
      if (in.eof()) break;  // a last line without its newline was cut short: run it again
      const auto comma = line.find(',');
      const std::int64_t r = std::strtoll(line.substr(0, comma).c_str(), nullptr, 10);
      if (comma == std::string::npos || !mine.count(r) ||
          line.rfind(rowPrefix(sweep, r), 0) != 0) {
        std::cerr << journal_path << ": row '" << line.substr(0, 40)
                  << "…' is not one of this sweep's (was the sweep file changed?); remove it, "
                  << "or run without --resume\n";
        return kBadInput;
      }
      done[r] = line;
    }
  }
  std::vector<std::int64_t> todo;
  for (std::int64_t r : rows)
    if (!done.count(r)) todo.push_back(r);
  const std::size_t from_journal = done.size();  // `done` takes this run's rows too, below

  // The journal: every finished row as soon as it is finished, for --resume after Ctrl-C, a
  // kill or a crash. Removed once the table is in place.
  std::ofstream journal(journal_path, std::ios::trunc);
  if (!journal) {
    std::cerr << output << ": cannot write its journal " << journal_path << ": "
              << std::strerror(errno) << "\n";
    return kBadInput;
  }
  journal << head << "\n";
  for (const auto& [r, line] : done) journal << line << "\n";
  journal.flush();

  const int jobs = args.jobs > 0 ? args.jobs
                                 : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  Bodies bodies(sweep, todo);
  std::vector<std::optional<std::string>> results(todo.size());
  std::atomic<std::size_t> next{0}, finished{0};
  std::atomic<int> running{0};
  std::stop_source stop;
  std::mutex journal_mutex;
  const auto start = std::chrono::steady_clock::now();
  {
    std::vector<std::jthread> pool;
    const int threads = static_cast<int>(std::min<std::size_t>(jobs, std::max<std::size_t>(1, todo.size())));
    running = threads;
    for (int j = 0; j < threads; ++j) {
      pool.emplace_back([&] {
        while (!stop.stop_requested()) {
          const std::size_t i = next++;
          if (i >= todo.size()) break;
          std::optional<std::string> result;
          try {
            result = runRow(scenes.value(), bodies, todo[i], stop.get_token());
          } catch (const std::exception& e) {
            result = field(std::string("stopped: ") + e.what()) + ",,,,,,";
          }
          if (!result) break;
          std::string line = rowPrefix(sweep, todo[i]) + *result;
          {
            std::lock_guard lock(journal_mutex);
            journal << line << "\n";
            journal.flush();
          }
          results[i] = std::move(line);
          ++finished;
        }
        --running;
      });
    }
    Progress progress("sweep", static_cast<std::int64_t>(rows.size()), !args.quiet);
    while (running > 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (interruptSignal()) stop.request_stop();
      progress.update(static_cast<std::int64_t>(done.size() + finished));
    }
    progress.finish();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  journal.close();

  if (interruptSignal()) {
    std::cerr << args.file << ": interrupted; " << done.size() + finished << " of " << rows.size()
              << " runs kept in " << journal_path
              << "; the same command with --resume runs the rest\n";
    return interruptedStatus();
  }
  for (std::size_t i = 0; i < todo.size(); ++i) done[todo[i]] = *results[i];
  std::vector<std::string> lines;
  for (const auto& [r, line] : done) lines.push_back(line);
  nlohmann::json sidecar;
  sidecar["program"] = "rattleback " RATTLEBACK_VERSION;
  sidecar["command"] = "sweep";
  sidecar["sweep"] = args.file;
  sidecar["base"] = sweep.base;
  sidecar["rows"] = sweep.rows();
  sidecar["shard"] = shard ? nlohmann::json{{"index", shard->index}, {"count", shard->count}}
                           : nlohmann::json(nullptr);
  sidecar["axes"] = axesJson(sweep);
  if (auto e = writeTable(output, keys, lines, sidecar); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  std::error_code ec;
  fs::remove(journal_path, ec);
  if (!args.plot.empty()) {
    Table table{keys, {}, lines};
    for (const auto& axis : sweep.axes) table.axis_values.push_back(axis.values);
    if (auto e = plotTable(args.plot, args.metric, stem, table); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet) {
    std::map<std::string, int> counts;
    for (const std::string& line : lines) {
      const auto fields = splitCsv(line);
      const std::string status = fields && fields->size() > 1 + keys.size() ? (*fields)[1 + keys.size()] : "";
      ++counts[status.substr(0, status.find(':'))];
    }
    std::printf("sweep           %s: %zu runs", args.file.c_str(), lines.size());
    if (shard) std::printf(" (shard %lld of %lld)", static_cast<long long>(shard->index),
                           static_cast<long long>(shard->count));
    std::printf(", %d ok", counts["ok"]);
    if (counts["stopped"]) std::printf(", %d stopped", counts["stopped"]);
    if (counts["refused"]) std::printf(", %d refused", counts["refused"]);
    if (from_journal)
      std::printf(" (%zu from the journal of the interrupted run, %zu run now)", from_journal,
                  todo.size());
    std::printf("\nwall time       %.3f s on %d threads (%.1f runs/s, of the %zu run now)\n", wall,
                jobs, todo.empty() ? 0.0 : static_cast<double>(todo.size()) / wall, todo.size());
    std::printf("table           %s\n", output.c_str());
    if (!args.plot.empty()) std::printf("plot            %s\n", args.plot.c_str());
  }
  return kOk;
}

int sweepMergeCommand(const SweepMergeArgs& args) {
  if (!isMetric(args.metric)) {
    std::cerr << "--metric: '" << args.metric << "' is not a column to plot (one of "
              << metricNames() << ")\n";
    return kBadInput;
  }
  if (args.shards.empty()) {
    std::cerr << "sweep merge: give the shard tables to merge (OUT.csv SHARD.csv…)\n";
    return kBadInput;
  }
  if (auto ok = checkTableIsAFile(args.output); !ok) {
    std::cerr << ok.error().text() << "\n";
    return kBadInput;
  }
  if (!args.plot.empty()) {
    if (auto made = checkPlotFile(args.plot); !made) {
      std::cerr << made.error().text() << "\n";
      return kBadInput;
    }
  }
  std::optional<nlohmann::json> first;
  std::string head;
  std::map<std::int64_t, std::pair<std::string, std::string>> rows;  // row → (line, file)
  for (const std::string& path : args.shards) {
    std::ifstream meta_in(path + ".json");
    if (!meta_in) {
      std::cerr << path << ".json: cannot read the shard's sidecar (each shard writes its "
                << "table and TABLE.json beside it)\n";
      return kBadInput;
    }
    nlohmann::json meta = nlohmann::json::parse(meta_in, nullptr, false);
    if (meta.is_discarded() || meta.value("command", "") != "sweep" || !meta.contains("rows")) {
      std::cerr << path << ".json: not the sidecar of a sweep table\n";
      return kBadInput;
    }
    if (first && ((*first)["sweep"] != meta["sweep"] || (*first)["rows"] != meta["rows"] ||
                  (*first)["axes"] != meta["axes"])) {
      std::cerr << path << ": from another sweep than " << args.shards.front() << " ("
                << meta.value("sweep", "?") << ")\n";
      return kBadInput;
    }
    if (!first) first = meta;
    std::ifstream in(path);
    std::string line;
    if (!in || !std::getline(in, line)) {
      std::cerr << path << ": cannot read the shard's table\n";
      return kBadInput;
    }
    if (head.empty()) head = line;
    if (line != head) {
      std::cerr << path << ": its columns differ from " << args.shards.front() << "'s\n";
      return kBadInput;
    }
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      const std::int64_t r = std::strtoll(line.c_str(), nullptr, 10);
      if (auto [it, fresh] = rows.try_emplace(r, line, path); !fresh) {
        std::cerr << path << ": row " << r << " is also in " << it->second.second
                  << "; each row must come from one shard\n";
        return kBadInput;
      }
    }
  }
  const std::int64_t total = (*first)["rows"].get<std::int64_t>();
  std::vector<std::int64_t> missing;
  for (std::int64_t r = 0; r < total && missing.size() < 6; ++r)
    if (!rows.count(r)) missing.push_back(r);
  if (!missing.empty()) {
    std::cerr << "sweep merge: rows missing (" << total - static_cast<std::int64_t>(rows.size())
              << " of " << total << "), e.g.";
    for (std::int64_t r : missing) std::cerr << " " << r;
    std::cerr << "; give every shard of the sweep\n";
    return kBadInput;
  }
  if (static_cast<std::int64_t>(rows.size()) != total) {
    std::cerr << "sweep merge: rows beyond the sweep's " << total << "\n";
    return kBadInput;
  }
  std::vector<std::string> keys, lines;
  Table table;
  for (const auto& axis : (*first)["axes"]) {
    keys.push_back(axis["key"].get<std::string>());
    table.axis_values.push_back(axis["values"].get<std::vector<std::string>>());
  }
  for (const auto& [r, entry] : rows) lines.push_back(entry.first);
  nlohmann::json sidecar = *first;
  sidecar["shard"] = nullptr;
  sidecar["merged_from"] = args.shards;
  if (auto e = writeTable(args.output, keys, lines, sidecar); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  if (!args.plot.empty()) {
    table.keys = keys;
    table.lines = lines;
    const std::string title = fs::path((*first).value("sweep", "sweep")).stem().string();
    if (auto e = plotTable(args.plot, args.metric, title, table); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet)
    std::printf("merged          %lld rows from %zu shards into %s\n",
                static_cast<long long>(total), args.shards.size(), args.output.c_str());
  return kOk;
}

}  // namespace app

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
#include "tasks/sweep.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;

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

std::vector<std::string> axisKeys(const scene::Sweep& sweep) {
  std::vector<std::string> keys;
  for (const auto& axis : sweep.axes) keys.push_back(axis.key);
  return keys;
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

struct Table {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> axis_values;  // [axis][value]
  std::vector<double> values;  // the metric of each row in row order; NaN where none
};

// The metric of a row: only a run that reached its end has a value to show.
double metricOf(const tasks::SweepRow& row, const std::string& metric) {
  if (row.status != tasks::RowStatus::Ok) return std::nan("");
  auto or_nan = [](const std::optional<double>& v) { return v.value_or(std::nan("")); };
  if (metric == "first_reversal_s") return or_nan(row.first_reversal_s);
  if (metric == "reversals") return row.reversals ? static_cast<double>(*row.reversals) : std::nan("");
  if (metric == "final_spin") return or_nan(row.final_spin);
  if (metric == "max_tilt_deg") return or_nan(row.max_tilt_deg);
  if (metric == "energy_lost") return or_nan(row.energy_lost);
  return row.wall_s;  // wall_s
}

// The metric from a line of a shard's table (the merge reads the files the shards wrote).
double metricOf(const std::string& line, std::size_t axes, const std::string& metric) {
  std::size_t column = 1 + axes;
  for (const tasks::Column& c : tasks::sweepResultColumns()) {
    if (c.name == metric) break;
    ++column;
  }
  const auto fields = splitCsv(line);
  if (!fields || fields->size() <= column || (*fields)[column].empty() ||
      (*fields)[1 + axes] != "ok")
    return std::nan("");
  return std::strtod((*fields)[column].c_str(), nullptr);
}

// Draws `metric` over the first two axes (further axes at their first value; one axis: a line
// plot).
rb::Status plotTable(const std::string& png, const std::string& metric, const std::string& title,
                     const Table& table) {
  const std::size_t axes = table.keys.size();
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
    for (std::size_t i = 0; i < table.values.size(); ++i)
      series.points.emplace_back(std::strtod(table.axis_values[0][i].c_str(), nullptr), table.values[i]);
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
      map.values.push_back(table.values[static_cast<std::size_t>(i0 * stride[0] + i1 * stride[1])]);
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
  if (!tasks::isSweepMetric(args.metric)) {
    std::cerr << "--metric: '" << args.metric << "' is not a column to plot (one of "
              << tasks::sweepMetricNames() << ")\n";
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
  const std::string head = tasks::sweepHeader(keys);
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
          line.rfind(tasks::sweepRowPrefix(sweep, r), 0) != 0) {
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

  tasks::SweepOptions options;
  options.jobs = args.jobs;
  options.cancelled = [] { return interruptSignal() != 0; };
  options.finished = [&](const tasks::SweepRow& row) {
    journal << tasks::sweepLine(row) << "\n";
    journal.flush();
  };
  Progress progress("sweep", static_cast<std::int64_t>(rows.size()), !args.quiet);
  options.progress = [&](std::int64_t finished) {
    progress.update(static_cast<std::int64_t>(from_journal) + finished);
  };
  const tasks::SweepRun run = tasks::runSweep(sweep, scenes.value(), todo, options);
  progress.finish();
  journal.close();

  if (run.interrupted) {
    std::cerr << args.file << ": interrupted; " << from_journal + run.rows.size() << " of "
              << rows.size() << " runs kept in " << journal_path
              << "; the same command with --resume runs the rest\n";
    return interruptedStatus();
  }
  std::map<std::string, int> counts;
  std::map<std::int64_t, double> metric;
  for (const tasks::SweepRow& row : run.rows) {
    done[row.row] = tasks::sweepLine(row);
    metric[row.row] = metricOf(row, args.metric);
    ++counts[std::string(rb::nameOf(row.status))];
  }
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
  sidecar["axes"] = tasks::sweepAxesJson(sweep);
  if (auto e = tasks::writeSweepTable(output, keys, lines, sidecar); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  std::error_code ec;
  fs::remove(journal_path, ec);
  if (!args.plot.empty()) {
    Table table{keys, {}, {}};
    for (const auto& axis : sweep.axes) table.axis_values.push_back(axis.values);
    for (const auto& [r, line] : done)
      table.values.push_back(metric.count(r) ? metric[r] : metricOf(line, keys.size(), args.metric));
    if (auto e = plotTable(args.plot, args.metric, stem, table); !e) {
      std::cerr << e.error().text() << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet) {
    for (const auto& [r, line] : done)  // rows from the journal of an interrupted run
      if (!metric.count(r)) {
        const auto fields = splitCsv(line);
        const std::string status =
            fields && fields->size() > 1 + keys.size() ? (*fields)[1 + keys.size()] : "";
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
    std::printf("\nwall time       %.3f s on %d threads (%.1f runs/s, of the %zu run now)\n",
                run.wall_s, run.threads,
                todo.empty() ? 0.0 : static_cast<double>(todo.size()) / run.wall_s, todo.size());
    std::printf("table           %s\n", output.c_str());
    if (!args.plot.empty()) std::printf("plot            %s\n", args.plot.c_str());
  }
  return kOk;
}

int sweepMergeCommand(const SweepMergeArgs& args) {
  if (!tasks::isSweepMetric(args.metric)) {
    std::cerr << "--metric: '" << args.metric << "' is not a column to plot (one of "
              << tasks::sweepMetricNames() << ")\n";
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
  if (auto e = tasks::writeSweepTable(args.output, keys, lines, sidecar); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  if (!args.plot.empty()) {
    table.keys = keys;
    for (const std::string& line : lines) table.values.push_back(metricOf(line, keys.size(), args.metric));
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

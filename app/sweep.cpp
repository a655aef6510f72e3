// `rattleback sweep` and `sweep merge`: options in, tasks/sweep (the runs, the table) and
// tasks/sweep_jobs (shards, the journal, the merge, job scripts) called, a summary out.
#include "scene/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot.hpp"
#include "app/progress.hpp"
#include "app/sweep_plot.hpp"
#include "tasks/both_ways.hpp"
#include "tasks/output.hpp"
#include "tasks/scene_args.hpp"
#include "tasks/sweep.hpp"
#include "tasks/sweep_jobs.hpp"
#include "util/format.hpp"
#include "util/nearest.hpp"
#include "util/output_place.hpp"

namespace app {

namespace {

namespace fs = std::filesystem;

std::vector<std::string> axisKeys(const scene::Sweep& sweep) {
  std::vector<std::string> keys;
  for (const auto& axis : sweep.axes) keys.push_back(axis.key);
  return keys;
}

std::string selfPath() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("rattleback") : exe.string();
}

// The options that need no run: --metric, --jobs, --shard (and --plot with it).
rb::Status checkOptions(const SweepArgs& args, std::optional<tasks::Shard>& shard) {
  if (auto bad = metricProblem(args.metric); !bad) return bad;
  if (args.jobs < 0 || args.jobs > 1024)
    return rb::Status::fail("--jobs: threads must be 1 … 1024 (0 or none: all cores), not " +
                            std::to_string(args.jobs));
  if (args.shards && args.emit.empty())
    return rb::Status::fail(
        "--shards: needs --emit (slurm or parallel), whose job script runs the sweep in N "
        "shards; to run one shard here, give --shard I/N");
  if (!args.plot.empty()) {  // checked here too for --emit, whose merge draws it
    const rb::OutputNamedBy naming("--plot");
    if (auto ok = rb::checkExtension(args.plot, ".png", "PNG", false); !ok) return ok;
  }
  if (args.shard.empty()) return {};
  shard = tasks::parseShard(args.shard);
  if (!shard)
    return rb::Status::fail("--shard: expected I/N with 0 ≤ I < N (e.g. 0/4), not '" + args.shard +
                            "'");
  if (!args.plot.empty())
    return rb::Status::fail(
        "--plot: a shard holds only some rows; plot the merged table "
        "(rattleback sweep merge OUT.csv SHARD… --plot PNG)");
  return {};
}

int emitScript(const SweepArgs& args, const scene::Sweep& sweep, const std::string& output) {
  const auto kind = rb::parseName<tasks::JobScript>(args.emit);
  if (!kind)
    return fail(rb::Status::fail("--emit: " + rb::choices<tasks::JobScript>() + ", not '" +
                                 args.emit + "'"));
  tasks::JobRequest request;
  request.kind = *kind;
  request.shards = args.shards.value_or(0);
  request.program = selfPath();
  request.output = output;
  request.plot = args.plot;
  request.metric = args.metric;
  auto script = tasks::jobScript(sweep, request);
  if (!script) return fail(script);
  // A Slurm job's logs go into the table's folder, which Slurm opens before the script runs: it
  // is made now, or the tasks fail before their first line with nothing said. GNU parallel's
  // shards make it as they run; a refused --emit made none (it had left the folder behind).
  if (*kind == tasks::JobScript::Slurm)
    if (auto made = tasks::makeParentFolder(output); !made) return fail(made);
  std::cout << script.value();
  return kOk;
}

// What this process runs: its rows, those a journal kept (with --resume), and the journal.
struct Plan {
  std::vector<std::int64_t> rows, todo;
  std::map<std::int64_t, std::string> done;  // row → line; this run's rows join them
  std::size_t from_journal = 0;
  std::map<std::string, int> counts;  // of each status ("ok", "stopped", "refused")
};

// "ok", "stopped", "refused": of the status field of a line (rows kept by a journal); "" in a
// table that does not list it.
std::string statusOf(const std::string& line, std::size_t axes,
                     const tasks::SweepColumns& columns) {
  const auto fields = splitCsv(line);
  const std::string status =
      fields ? fieldOf(*fields, axes, columns, "status").value_or("") : std::string();
  return status.substr(0, status.find(':'));
}

rb::Result<Plan> planRows(const SweepArgs& args, const scene::Sweep& sweep,
                          const std::optional<tasks::Shard>& shard, const std::string& output) {
  Plan plan;
  plan.rows = tasks::shardRows(sweep, shard);
  const std::string journal = tasks::Journal::pathOf(output);
  if (tasks::Journal::busy(output)) return tasks::Journal::inUse(output);
  if (args.resume) {
    auto kept = tasks::Journal::read(journal, sweep, plan.rows);
    if (!kept) return kept.error();
    plan.done = std::move(kept).value();
  } else if (std::error_code ec; std::filesystem::exists(journal, ec)) {
    // Finished runs of this very sweep are not thrown away by a command typed without
    // --resume (a journal of a changed sweep is no use to it, and is begun afresh).
    auto kept = tasks::Journal::read(journal, sweep, plan.rows);
    if (kept && !kept->empty())
      return rb::Error{"", journal + ": holds " +
                               rb::counted(static_cast<long long>(kept->size()), "finished run") +
                               " of an interrupted run of this sweep; give "
                               "--resume to run only the rest, or remove it to start again"};
  }
  for (std::int64_t r : plan.rows)
    if (!plan.done.count(r)) plan.todo.push_back(r);
  plan.from_journal = plan.done.size();
  const tasks::SweepColumns columns = tasks::tableColumns(sweep);
  for (const auto& [r, line] : plan.done) ++plan.counts[statusOf(line, sweep.axes.size(), columns)];
  return plan;
}

// Runs the plan's rows into the journal; false when interrupted.
bool runRows(const SweepArgs& args, const scene::Sweep& sweep, const scene::SweepScenes& scenes,
             Plan& plan, tasks::Journal& journal, std::map<std::int64_t, double>& metric,
             tasks::SweepRun& run) {
  const tasks::SweepColumns columns = tasks::tableColumns(sweep);
  tasks::SweepOptions options;
  options.jobs = args.jobs;
  options.cancelled = [] { return interruptSignal() != 0; };
  options.finished = [&](const tasks::SweepRow& row) {
    journal.append(tasks::sweepLine(row, columns));
  };
  Progress progress("sweep", static_cast<std::int64_t>(plan.rows.size()), !args.quiet);
  options.progress = [&](std::int64_t finished) {
    progress.update(static_cast<std::int64_t>(plan.from_journal) + finished);
  };
  run = tasks::runSweep(sweep, scenes, plan.todo, options);
  progress.finish();
  journal.close();
  if (run.interrupted) return false;
  for (const tasks::SweepRow& row : run.rows) {
    plan.done[row.row] = tasks::sweepLine(row, columns);
    metric[row.row] = tasks::metricOf(row, metricNamed(args.metric));
    ++plan.counts[std::string(rb::nameOf(row.status))];
  }
  return true;
}

void printSummary(const SweepArgs& args, const std::optional<tasks::Shard>& shard, const Plan& plan,
                  const tasks::SweepRun& run, const std::string& output) {
  std::map<std::string, int> counts = plan.counts;
  std::printf("sweep           %s: %s", args.file.c_str(),
              rb::counted(static_cast<long long>(plan.done.size()), "run").c_str());
  if (shard)
    std::printf(" (shard %lld of %lld)", static_cast<long long>(shard->index),
                static_cast<long long>(shard->count));
  // A table whose columns: list no status keeps none for the journal's rows: those are counted
  // apart, and the statuses are the rows run now (the two had not added up to the whole).
  const bool journal_unknown = plan.from_journal && counts[""] > 0;
  if (journal_unknown)
    std::printf(" (%zu from the journal of the interrupted run; of the %zu run now",
                plan.from_journal, plan.todo.size());
  std::printf(", %d ok", counts["ok"]);
  if (counts["stopped"]) std::printf(", %d stopped", counts["stopped"]);
  if (counts["refused"]) std::printf(", %d refused", counts["refused"]);
  if (journal_unknown)
    std::printf(")");
  else if (plan.from_journal)
    std::printf(" (%zu from the journal of the interrupted run, %zu run now)", plan.from_journal,
                plan.todo.size());
  std::printf("\nwall time       %.3f s on %d thread%s: %zu run%s, %.1f a second\n", run.wall_s,
              run.threads, run.threads == 1 ? "" : "s", plan.todo.size(),
              plan.todo.size() == 1 ? "" : "s",
              plan.todo.empty() ? 0.0 : static_cast<double>(plan.todo.size()) / run.wall_s);
  std::printf("table           %s\n", output.c_str());
  if (!args.plot.empty()) std::printf("plot            %s\n", args.plot.c_str());
  // Why, where some were refused: a refused cell of the heatmap looks like "no reversal".
  const auto first = std::find_if(run.rows.begin(), run.rows.end(), [](const auto& row) {
    return row.status == tasks::RowStatus::Refused;
  });
  if (first != run.rows.end() && counts["refused"] < static_cast<int>(plan.done.size()))
    std::printf("refused         row %lld: %s\n", static_cast<long long>(first->row),
                first->message.c_str());
}

// A search over bodies spun each way: how many reverse both ways, and the first. (A shard holds
// only some of each body's rows: its summary leaves it to the merged table.)
void printBothWays(const scene::Sweep& sweep, const Plan& plan) {
  const tasks::SweepColumns columns = tasks::tableColumns(sweep);
  if (std::find(columns.begin(), columns.end(),
                &tasks::columnOf(tasks::SweepMetric::FirstReversal)) == columns.end())
    return;
  const bool has_exports = std::any_of(columns.begin(), columns.end(), [](const auto* c) {
    return c->extra == tasks::RowExtra::Exports;
  });
  std::vector<double> first(static_cast<std::size_t>(sweep.rows()), std::nan(""));
  std::vector<std::optional<bool>> exports(has_exports ? first.size() : 0);
  for (const auto& [row, line] : plan.done) {
    const auto r = static_cast<std::size_t>(row);
    const auto fields = splitCsv(line);
    if (!fields) continue;
    first[r] = metricOf(*fields, sweep.axes.size(), columns, tasks::SweepMetric::FirstReversal);
    if (!has_exports) continue;
    const auto field = fieldOf(*fields, sweep.axes.size(), columns, "exports");
    if (field && !field->empty()) exports[r] = *field == "yes";
  }
  if (const auto found = tasks::bothWays(sweep, first, exports))
    std::printf("both ways       %s\n", tasks::describe(*found).c_str());
}

// The table, its sidecar and its heatmap, once every row is done.
rb::Status writeOutputs(const SweepArgs& args, const scene::Sweep& sweep,
                        const std::optional<tasks::Shard>& shard, const Plan& plan,
                        const std::map<std::int64_t, double>& metric, const std::string& output) {
  const std::vector<std::string> keys = axisKeys(sweep);
  const tasks::SweepColumns columns = tasks::tableColumns(sweep);
  std::vector<std::string> lines;
  for (const auto& [r, line] : plan.done) lines.push_back(line);
  if (auto e =
          tasks::writeSweepTable(output, keys, columns, lines, tasks::sweepSidecar(sweep, shard));
      !e)
    return e;
  tasks::Journal::remove(tasks::Journal::pathOf(output));
  if (args.plot.empty()) return {};
  Table table{keys, {}, {}, sweep.length_unit};
  for (const auto& axis : sweep.axes) table.axis_values.push_back(axis.values);
  for (const auto& [r, line] : plan.done) {
    const auto it = metric.find(r);
    table.values.push_back(it != metric.end()
                               ? it->second
                               : metricOf(line, keys.size(), columns, metricNamed(args.metric)));
  }
  table.forecast = forecastsOf(lines, keys.size(), columns, metricNamed(args.metric));
  return plotTable(args.plot, metricNamed(args.metric), fs::path(args.file).stem().string(), table);
}

// Where the table goes, checked, with its folder made (and the plot's, added to `made`: a sweep
// refused leaves no empty folder behind).
rb::Result<std::string> outputOf(const SweepArgs& args, const scene::Sweep& sweep,
                                 const std::optional<tasks::Shard>& shard,
                                 tasks::MadeFolders& made) {
  std::string output =
      args.output.empty() ? "out/" + fs::path(args.file).stem().string() + ".csv" : args.output;
  if (auto ok = tasks::checkTableIsAFile(output); !ok) return ok.error();
  if (auto ok = rb::checkDataOutput(output, "a CSV table", ".csv", {args.file, sweep.base}); !ok)
    return ok.error();
  if (!args.emit.empty()) return output;  // (its folder: emitScript)
  if (shard && args.output.empty()) output = tasks::shardPath(output, *shard);
  if (!args.plot.empty())
    if (auto ok = checkPlotFile(args.plot, &made); !ok) return ok.error();
  if (auto ok = tasks::makeParentFolder(output, &made); !ok) return ok.error();
  return output;
}

// Ctrl-C in the middle: the finished runs stay in the journal for --resume; a journal of its
// header alone is no use, and is removed.
int interruptedSweep(const SweepArgs& args, const Plan& plan, const tasks::SweepRun& run,
                     tasks::Journal& journal, const std::string& journal_path) {
  const std::size_t kept = plan.from_journal + run.rows.size();
  if (kept == 0) {
    journal.close();
    tasks::Journal::remove(journal_path);
    tell(Tone::Error, args.file + ": interrupted before any run finished; nothing kept");
    return interruptedStatus();
  }
  tell(Tone::Error, args.file + ": interrupted; " + std::to_string(kept) + " of " +
                        rb::counted(static_cast<long long>(plan.rows.size()), "run") + " kept in " +
                        journal_path + "; the same command with --resume runs the rest");
  return interruptedStatus();
}

// Not one run made: the sweep's values are the input at fault (rows all refused for a missing
// contact.stiffness are not a success), and bad input writes nothing: a table of refusals
// would replace a good table of that name.
int everyRunRefused(const SweepArgs& args, const tasks::SweepRun& run, tasks::Journal& journal,
                    const std::string& journal_path) {
  journal.close();
  tasks::Journal::remove(journal_path);
  const auto first = std::find_if(run.rows.begin(), run.rows.end(), [](const auto& row) {
    return row.status == tasks::RowStatus::Refused;
  });
  tell(Tone::Error,
       args.file + ": every run was refused, nothing written" +
           (first == run.rows.end() ? std::string() : "; the first: " + first->message));
  return kBadInput;
}

}  // namespace

int sweepCommand(const SweepArgs& args) {
  installInterruptHandlers();
  if (args.file.empty())
    return fail(
        rb::Status::fail("sweep: give a sweep file (e.g. rattleback sweep "
                         "sweeps/spin-drag.yaml), or 'sweep merge OUT.csv SHARD…'"));
  auto loaded = tasks::loadSweep(tasks::findShipped(args.file));
  if (!loaded) return fail(loaded);
  noteShipped(args.file);
  const scene::Sweep& sweep = loaded.value();
  std::optional<tasks::Shard> shard;
  if (auto ok = checkOptions(args, shard); !ok) return fail(ok);
  if (!args.plot.empty())
    if (auto ok = metricListed(args.metric, tasks::tableColumns(sweep)); !ok) return fail(ok);
  tasks::MadeFolders made;
  auto output = outputOf(args, sweep, shard, made);
  if (!output) return fail(output);
  if (!args.emit.empty()) return emitScript(args, sweep, output.value());
  auto scenes = scene::SweepScenes::open(sweep);
  if (!scenes) return fail(scenes);
  if (!args.quiet)
    for (const std::string& note : tasks::sweepNotes(sweep, scenes.value())) tell(Tone::Note, note);
  auto plan = planRows(args, sweep, shard, output.value());
  if (!plan) return fail(plan);
  const std::string journal_path = tasks::Journal::pathOf(output.value());
  auto journal = tasks::Journal::open(
      output.value(), tasks::sweepHeader(axisKeys(sweep), tasks::tableColumns(sweep)), plan->done,
      tasks::sweepFingerprint(sweep));
  if (!journal) return fail(journal);
  std::map<std::int64_t, double> metric;
  tasks::SweepRun run;
  if (!runRows(args, sweep, scenes.value(), plan.value(), journal.value(), metric, run)) {
    return interruptedSweep(args, plan.value(), run, journal.value(), journal_path);
  }
  if (!plan->done.empty() && plan->counts["refused"] == static_cast<int>(plan->done.size()))
    return everyRunRefused(args, run, journal.value(), journal_path);
  if (auto e = writeOutputs(args, sweep, shard, plan.value(), metric, output.value()); !e)
    return fail(e);
  std::vector<tasks::OutputEntry> entries = {
      {output.value(), tasks::OutputKind::Sweep, sceneName(args.file), "", {}, {}}};
  if (!args.plot.empty())
    entries.push_back(
        {args.plot, tasks::OutputKind::SweepPlot, sceneName(args.file), args.metric, {}, {}});
  record(entries);
  if (!args.quiet) printSummary(args, shard, plan.value(), run, output.value());
  if (!args.quiet && !shard) printBothWays(sweep, plan.value());
  return kOk;
}

int sweepMergeCommand(const SweepMergeArgs& args) {
  if (auto bad = metricProblem(args.metric); !bad) return fail(bad);
  if (args.shards.empty())
    return fail(
        rb::Status::fail("sweep merge: give the shard tables to merge (OUT.csv SHARD.csv…)"));
  if (auto ok = tasks::checkTableIsAFile(args.output); !ok) return fail(ok);
  tasks::MadeFolders made;
  if (!args.plot.empty())
    if (auto ok = checkPlotFile(args.plot, &made); !ok) return fail(ok);
  // Not over one of its shards: the shard was replaced by the whole, and every later merge found
  // its rows twice.
  if (auto ok = rb::checkDataOutput(args.output, "a CSV table", ".csv", args.shards); !ok)
    return fail(ok);
  auto merged = tasks::mergeShards(args.shards);
  if (!merged) return fail(merged);
  const tasks::Merged& m = merged.value();
  if (!args.plot.empty())
    if (auto ok = metricListed(args.metric, m.columns); !ok) return fail(ok);
  if (auto e = tasks::writeSweepTable(args.output, m.keys, m.columns, m.lines, m.sidecar); !e)
    return fail(e);
  const std::string sweep_file = m.sidecar.value("sweep", "sweep");
  if (!args.plot.empty()) {
    const nlohmann::json& unit =
        m.sidecar.contains("length_unit_m") ? m.sidecar["length_unit_m"] : nlohmann::json();
    Table table{m.keys, m.axis_values, {}, unit.is_number() ? unit.get<double>() : 0.0};
    for (const std::string& line : m.lines)
      table.values.push_back(metricOf(line, m.keys.size(), m.columns, metricNamed(args.metric)));
    table.forecast = forecastsOf(m.lines, m.keys.size(), m.columns, metricNamed(args.metric));
    const std::string title = fs::path(sweep_file).stem().string();
    if (auto e = plotTable(args.plot, metricNamed(args.metric), title, table); !e) return fail(e);
  }
  // The merged table and its plot go into the folder's manifest as an in-process sweep's do.
  std::vector<tasks::OutputEntry> entries = {
      {args.output, tasks::OutputKind::Sweep, sceneName(sweep_file), "", {}, {}}};
  if (!args.plot.empty())
    entries.push_back(
        {args.plot, tasks::OutputKind::SweepPlot, sceneName(sweep_file), args.metric, {}, {}});
  record(entries);
  if (!args.quiet)
    std::printf("merged          %s from %s into %s\n", rb::counted(m.rows, "row").c_str(),
                rb::counted(static_cast<long long>(args.shards.size()), "shard").c_str(),
                args.output.c_str());
  return kOk;
}

}  // namespace app

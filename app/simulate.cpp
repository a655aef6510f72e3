#include "tasks/simulate.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot.hpp"
#include "app/progress.hpp"
#include "sim/analysis.hpp"
#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"
#include "sim/rollout.hpp"
#include "tasks/analysis.hpp"
#include "tasks/check.hpp"
#include "tasks/output.hpp"
#include "tasks/run_json.hpp"
#include "tasks/scene_args.hpp"
#include "util/format.hpp"

namespace app {
namespace {

// Whether `path` leads to the file, pipe or terminal this process's standard output is.
bool isStandardOutput(const std::string& path) {
  struct stat file;
  struct stat out;
  return ::stat(path.c_str(), &file) == 0 && ::fstat(STDOUT_FILENO, &out) == 0 &&
         file.st_dev == out.st_dev && file.st_ino == out.st_ino;
}

std::string defaultOutput(const std::string& scene) {
  return "out/" + std::filesystem::path(scene).stem().string() + ".csv";
}

void printSummary(std::FILE* out, const SimulateArgs& args, const Overrides& given,
                  const sim::Model& model, const sim::RunSummary& run, const std::string& csv,
                  std::int64_t rows) {
  const double simulated = run.last.t;
  const std::string integrator(rb::nameOf(model.integrator));
  std::fprintf(out, "scene           %s\n", sceneWithValues(args.scene, given).c_str());
  const std::vector<tasks::RunWarning> warnings = tasks::runWarnings(model, run);
  // Each warning where its line belongs: the body's at the top, a hint under the line it
  // explains.
  auto said = [&](const char* code, const char* form) {
    for (const tasks::RunWarning& w : warnings)
      if (w.code == code) std::fprintf(out, form, w.text.c_str());
  };
  for (const tasks::RunWarning& w : warnings)
    if (w.aboutTheBody()) std::fprintf(out, "WARNING         %s\n", w.text.c_str());
  const std::string steps = rb::counted(run.steps, "step");
  if (sim::isAdaptive(model.integrator))
    std::fprintf(out, "integrator      %s, tolerance %g, %s (%lld rejected), %g s simulated\n",
                 integrator.c_str(), model.tolerance, steps.c_str(),
                 static_cast<long long>(run.rejected), simulated);
  else
    std::fprintf(out, "integrator      %s, dt %g s, %s (%g s simulated)\n", integrator.c_str(),
                 model.dt, steps.c_str(), simulated);
  if (run.first_reversal_s) {
    std::fprintf(out, "first reversal  %.4f s (spin %+g rad/s changed sign)\n",
                 *run.first_reversal_s, model.initial.spin);
    if (run.reversals.size() > 1) {
      std::fprintf(out, "reversals       %zu, at", run.reversals.size());
      for (double t : run.reversals) std::fprintf(out, " %.4f", t);
      std::fprintf(out, " s\n");
    }
  } else {
    std::fprintf(out, "first reversal  none in %g s\n", simulated);
    said("upright_start", "                (%s)\n");
    said("nothing_moves", "                (%s)\n");
    said("sign_changed_uncounted", "                (%s)\n");
  }
  if (sim::contactTraits(model.contact.model).switches) {
    std::fprintf(out, "contact modes   %s",
                 rb::counted(run.switches, "switch", "switches").c_str());
    for (const auto& [t, mode] : run.mode_changes)
      std::fprintf(out, "%s %s at %.4f s", &t == &run.mode_changes.front().first ? ":" : ",",
                   std::string(rb::nameOf(mode)).c_str(), t);
    std::fprintf(out, "\n");
  }
  const double change = (run.last.energy - run.first.energy) / std::abs(run.first.energy);
  std::fprintf(out, "energy          %.6g J -> %.6g J (%+.4g %%)\n", run.first.energy,
               run.last.energy, 100 * change);
  said("energy_error", "                (%s)\n");
  said("slip_unresolved", "WARNING         %s\n");
  std::fprintf(out, "final spin      %+.4f rad/s, tilt %.2f deg\n", run.last.spin,
               run.last.tilt_deg);
  said("floor_pulled", "WARNING         %s\n");
  said("friction_exceeded", "WARNING         %s\n");
  std::fprintf(out, "wall time       %.3f s: %.4f s per simulated second, %.3f us per step\n",
               run.wall_s, run.wall_s / simulated,
               1e6 * run.wall_s / static_cast<double>(std::max<std::int64_t>(1, run.steps)));
  std::fprintf(out, "telemetry       %s (%s)\n", csv.c_str(), rb::counted(rows, "row").c_str());
}

// The estimated errors of `run` (simulate --check).
void printCheck(std::FILE* out, const tasks::RunCheck& check, const sim::RunSummary& run) {
  std::fprintf(out, "check           against %s; %s%s\n", check.setting.c_str(),
               check.method.c_str(), check.completed ? "" : " (the tighter run stopped early)");
  for (std::size_t i = 0; i < check.reversal_errors.size(); ++i) {
    if (check.reversal_errors[i])
      std::fprintf(out, "                reversal %zu at %.6f s: error about %.2g s\n", i + 1,
                   run.reversals[i], std::abs(*check.reversal_errors[i]));
    else
      std::fprintf(out,
                   "                reversal %zu at %.6f s: the tighter run has no such "
                   "reversal: the run is not converged\n",
                   i + 1, run.reversals[i]);
  }
  if (check.tighter_reversals.size() > run.reversals.size())
    std::fprintf(
        out,
        "                the tighter run reverses %s, this run %zu: the run is "
        "not converged\n",
        rb::counted(static_cast<long long>(check.tighter_reversals.size()), "time").c_str(),
        run.reversals.size());
  std::fprintf(out,
               "                n(t): error at most about %.2g rad/s (at t = %.4g s); the "
               "check cost %.2g× the run\n",
               std::abs(check.spin_error), check.spin_error_at, check.cost_ratio);
}

// The seed's figures (6–8, 12–16) from the telemetry: energy, spin, tilt and CM height, and
// the normal force, each against time, into DIR/<scene>-<what>.png.
rb::Status writePlots(const std::string& dir, const std::string& stem,
                      const std::vector<sim::Telemetry>& samples,
                      const std::vector<double>& reversals) {
  auto series = [&](const char* title, auto value, bool right = false) {
    Series s;
    s.title = title;
    s.right_axis = right;
    s.points.reserve(samples.size());
    for (const sim::Telemetry& t : samples) s.points.emplace_back(t.t, value(t));
    return s;
  };
  auto panel = [&](const char* title, const char* y_label) {
    Panel p;
    p.title = title;
    p.x_label = "time t [s]";
    p.y_label = y_label;
    p.lines_only = true;
    return p;
  };
  Panel energy = panel("Energy", "energy [mJ]");
  energy.series = {
      series("total", [](const sim::Telemetry& t) { return 1e3 * t.energy; }),
      series("kinetic", [](const sim::Telemetry& t) { return 1e3 * t.kinetic; }),
      series("potential M g z", [](const sim::Telemetry& t) { return 1e3 * t.potential; }),
      series("elastic (floor springs)", [](const sim::Telemetry& t) { return 1e3 * t.elastic; })};
  // Rolling has no floor springs: no line of zeros in the legend as if it had.
  if (std::all_of(samples.begin(), samples.end(),
                  [](const sim::Telemetry& t) { return t.elastic == 0; }))
    energy.series.pop_back();
  Panel spin =
      panel("Spin about the vertical, n = w.z (+ counter-clockwise from above)", "spin n [rad/s]");
  spin.series = {series("n", [](const sim::Telemetry& t) { return t.spin; })};
  for (double t : reversals) {  // where n changed sign, as the summary finds it
    char label[48];
    std::snprintf(label, sizeof label, "reversal %.3f s", t);
    spin.marks.push_back({t, label});
  }
  Panel tilt = panel("Tilt of the body axis and height of the centre of mass", "tilt [degrees]");
  tilt.y2_label = "CM height z [mm]";
  tilt.y_from_zero = true;
  tilt.series = {
      series("tilt", [](const sim::Telemetry& t) { return t.tilt_deg; }),
      series(
          "CM height", [](const sim::Telemetry& t) { return 1e3 * t.x_world.z(); }, true)};
  Panel normal = panel("Normal force of the floor", "normal force N [N]");
  normal.series = {series("N", [](const sim::Telemetry& t) { return t.normal_force; })};
  const std::pair<const char*, Panel*> figures[] = {
      {"energy", &energy}, {"spin", &spin}, {"tilt", &tilt}, {"normal", &normal}};
  for (const auto& [what, p] : figures) {
    const std::string png = (std::filesystem::path(dir) / (stem + "-" + what + ".png")).string();
    if (auto e = plotPng(png, stem + ": " + p->title, {*p}, 1000, 500); !e) return e;
  }
  return {};
}

}  // namespace

rb::Status putSettings(const std::vector<std::string>& entries, Overrides& o) {
  for (const std::string& entry : entries) {
    const auto equals = entry.find('=');
    if (equals == std::string::npos || equals == 0)
      return rb::Error{"", "--set: '" + entry +
                               "' is not KEY=VALUE (e.g. --set contact.model=smooth or "
                               "--set initial.tilt=[1,0])"};
    o.values.push_back({entry.substr(0, equals), entry.substr(equals + 1)});
  }
  return {};
}

// The run's overrides as simulate's options give them.
rb::Result<Overrides> overridesOf(const SimulateArgs& args) {
  Overrides o = args.overrides;
  if (auto ok = putSettings(args.set, o); !ok) return ok.error();
  return o;
}

// The figures are named after the table they plot (its file's stem: anna.csv's are
// anna-spin.png, …), so that two runs of one scene into one folder keep each its own (both were
// <scene>-spin.png, and the second overwrote the first's); a table on standard output, after
// the scene.
std::string plotStem(const SimulateArgs& args, const std::string& csv) {
  if (isStandardOutput(csv)) return sceneName(args.scene);
  return std::filesystem::path(csv).stem().string();
}

// The telemetry and the plots, for the manifest.
std::vector<tasks::OutputEntry> outputsOf(const SimulateArgs& args, const std::string& csv,
                                          const std::string& made_from) {
  const std::string scene = sceneName(args.scene);
  std::vector<tasks::OutputEntry> entries = {
      {csv, tasks::OutputKind::Telemetry, scene, "", {}, {}, made_from}};
  if (!args.plot_dir.empty())
    for (const char* what : {"energy", "spin", "tilt", "normal"})
      entries.push_back(
          {(std::filesystem::path(args.plot_dir) / (plotStem(args, csv) + "-" + what + ".png"))
               .string(),
           tasks::OutputKind::Plot,
           scene,
           what,
           {},
           {},
           made_from});
  return entries;
}

namespace {

// --plot naming the table itself would make a folder where the table goes
// (`-o a.csv --plot a.csv`).
rb::Status checkPlotIsNotTheTable(const std::string& plot_dir, const std::string& csv) {
  if (plot_dir.empty()) return {};
  std::error_code ec, ec2;
  const auto plot = std::filesystem::weakly_canonical(std::filesystem::absolute(plot_dir), ec);
  const auto table = std::filesystem::weakly_canonical(std::filesystem::absolute(csv), ec2);
  if (ec || ec2 || plot != table) return {};
  return rb::Status::fail("--plot " + plot_dir + ": is the table's own name (-o " + csv +
                          "); give the figures a folder of their own (e.g. --plot " +
                          (std::filesystem::path(plot_dir).parent_path() / "figures").string() +
                          ")");
}

}  // namespace

// Why a run wrote nothing, and its exit status.
int notWritten(const SimulateArgs& args, const tasks::Outcome& outcome, const std::string& why) {
  if (outcome.ending == tasks::Ending::Interrupted) {
    tell(Tone::Error,
         args.scene + ": interrupted at t = " + rb::show(outcome.t) + " s; no telemetry written");
    return interruptedStatus();  // the temporary files are removed unfinished
  }
  tell(Tone::Error, stoppedLine(args.scene, outcome, "telemetry", "--duration", why));
  return kDiverged;
}

std::string stoppedLine(const std::string& scene, const tasks::Outcome& outcome,
                        const std::string& what, const std::string& option,
                        const std::string& why) {
  std::string line =
      scene + ": the run stopped: " + outcome.message + why + ". No " + what + " written";
  // The run up to the stop is sound: say what it found, and how to keep it (the stop's time
  // rounded down to a tenth of a second, so that the run ends before it).
  const double before = std::floor(outcome.t * 10) / 10;
  if (outcome.first_reversal_s)
    line += "; it had reversed at " + rb::show(*outcome.first_reversal_s) + " s";
  else if (before > 0)
    line += "; it had not reversed by then";
  if (before > 0 && (!outcome.first_reversal_s || *outcome.first_reversal_s < before))
    line += ". " + option + " " + rb::show(before) + " ends the run before the stop";
  return line;
}

// What is odd about the body, said before a stopped run's line as what may be why (lengths in
// metres typed for cm make a 28 m body of 0.2 kg that tips onto its rim, lighter than air: said
// after the stop, the cause read as an afterthought to a line suggesting another contact model).
std::string saidOddBody(const sim::Model& model) {
  int odd = 0;
  for (const tasks::RunWarning& w : tasks::bodyWarnings(model)) {
    tell(Tone::Warning, w.text);
    ++odd;
  }
  return odd == 0   ? ""
         : odd == 1 ? "; the warning above may be why"
                    : "; the warnings above may be why";
}

int stopped(const SimulateArgs& args, const tasks::SimulateResult& run, const sim::Model& model) {
  if (run.outcome.ending == tasks::Ending::Interrupted) return notWritten(args, run.outcome, "");
  return notWritten(args, run.outcome, saidOddBody(model));
}

namespace {

// Where the table goes: -o, else out/<scene>.csv; "-o -" is standard output, as for most tools
// that write a table.
std::string tableOf(const SimulateArgs& args) {
  const std::string csv = args.output.empty() ? defaultOutput(args.scene) : args.output;
  return csv == "-" ? "/dev/stdout" : csv;
}

// Why the run's rows cannot be written at `rate`, or nothing. At the default rate it is the
// duration that makes too many rows: named where it was set (a scene's duration of 1e9 is not
// the fault of a --rate the user never gave).
rb::Status rateProblem(const SimulateArgs& args, const tasks::LoadedScene& loaded, double rate) {
  const sim::Model& model = loaded.model;
  auto ok = tasks::checkRate(rate, model.duration);
  if (ok) return {};
  if (!args.rate && model.duration * rate > 1e7)
    return scene::locate(
        loaded.scene,
        rb::Error{"simulation.duration",
                  rb::show(model.duration) + " s makes " +
                      rb::show(std::floor(model.duration * rate) + 1) +
                      " rows of telemetry at the default --rate of " + rb::show(rate) +
                      " samples a second; at most 1e7 rows (about 3 GB): give a "
                      "shorter duration, or a lower --rate"});
  return rb::Status::fail("--" + ok.error().text());
}

// Draws --plot's figures: the exit status when that failed, else nothing. Ctrl-C while they are
// drawn leaves the table standing and listed in the folder's manifest (else the report places it
// by its name alone), and is said with -q too, as every command's interruption is; it is not a
// failure of gnuplot's.
std::optional<int> drawPlots(const SimulateArgs& args, const std::string& csv,
                             const scene::Loaded& scene, const std::vector<sim::Telemetry>& kept,
                             const sim::RunSummary& run) {
  if (args.plot_dir.empty()) return std::nullopt;
  auto e = writePlots(args.plot_dir, plotStem(args, csv), kept, run.reversals);
  if (e) return std::nullopt;
  if (interruptSignal() == 0) return fail(e);
  record({outputsOf(args, csv, tasks::madeFrom(scene)).front()});
  tell(Tone::Error, "interrupted while drawing the figures; " + csv + " is written");
  return interruptedStatus();
}

// The summary, the check's figures and the figures' names (on standard error when the table
// went to standard output, so that it can be piped on whole).
void printResults(const SimulateArgs& args, const Overrides& given, const sim::Model& model,
                  const tasks::SimulateResult& run, const std::optional<tasks::RunCheck>& check,
                  const std::string& csv, bool to_stdout) {
  std::FILE* report = to_stdout ? stderr : stdout;
  printSummary(report, args, given, model, run.summary, to_stdout ? "standard output" : csv,
               run.rows);
  if (check) printCheck(report, *check, run.summary);
  if (!args.plot_dir.empty())
    std::fprintf(report, "plots           %s/%s-{energy,spin,tilt,normal}.png\n",
                 args.plot_dir.c_str(), plotStem(args, csv).c_str());
}

// The table's name: not the figures' folder, not the scene, not a name of another format's (the
// format is the name's: CSV, or arrays for .npz and .h5).
rb::Status checkTable(const SimulateArgs& args, const std::string& csv) {
  if (auto ok = checkPlotIsNotTheTable(args.plot_dir, csv); !ok) return ok;
  if (auto ok = tasks::checkTelemetryName(args.output, "-o"); !ok) return ok;
  const tasks::TelemetryFormat format = tasks::telemetryFormatOf(csv);
  return rb::checkDataOutput(args.output, tasks::formatName(format), tasks::extensionOf(format),
                             {args.scene});
}

}  // namespace

int simulateCommand(const SimulateArgs& args) {
  installInterruptHandlers();
  const auto overrides = overridesOf(args);
  if (!overrides) return fail(overrides);
  auto loaded = loadScene(args.scene, overrides.value());
  if (!loaded) return fail(loaded);
  noteShipped(args.scene);
  const sim::Model& model = loaded->model;
  const double rate = args.rate.value_or(tasks::kDefaultRate);
  if (auto ok = rateProblem(args, loaded.value(), rate); !ok) return fail(ok);
  // When the table goes to standard output (so also through /dev/stdout or a link to it), the
  // summary goes to standard error, so that the table can be piped on whole.
  const std::string csv = tableOf(args);
  const bool to_stdout = isStandardOutput(csv);
  if (auto ok = checkTable(args, csv); !ok) return fail(ok);
  // Declared before the writer, so that its temporary files are gone before the folders are
  // removed.
  tasks::MadeFolders made;
  if (!args.plot_dir.empty())
    if (auto plots = checkPlotFolder(args.plot_dir, plotStem(args, csv) + "-energy.png", &made);
        !plots)
      return fail(plots);
  if (auto ok = tasks::makeParentFolder(csv, &made); !ok) return fail(ok);
  auto writer = tasks::TelemetryWriter::open(csv);
  if (!writer) return fail(writer);
  if (args.verbose) describeModel(model, args.scene);
  writer->expect(static_cast<std::int64_t>(model.duration * rate) + 2);  // the samples and the end
  Progress progress("simulate", static_cast<std::int64_t>(model.duration * rate) + 1, !args.quiet);
  std::vector<sim::Telemetry> kept;  // for the plots
  std::vector<double> spins;         // for --check
  tasks::SimulateOptions options;
  options.rate = rate;
  options.cancelled = [] { return interruptSignal() != 0; };
  options.each = [&](const sim::Telemetry& sample) {
    writer->row(sample);
    if (!args.plot_dir.empty()) kept.push_back(sample);
    if (args.check) spins.push_back(sample.spin);
    progress.update(writer->rows());
  };
  const tasks::SimulateResult run = tasks::simulate(model, options);
  progress.finish();
  if (run.outcome.ending != tasks::Ending::Completed) return stopped(args, run, model);
  std::optional<tasks::RunCheck> check;
  if (args.check) {
    check = tasks::checkRun(model, rate, run.summary, spins, options.cancelled);
    if (!check) return notWritten(args, {tasks::Ending::Interrupted, {}, "", model.duration}, "");
  }
  if (auto e =
          writer->commit({loaded->scene.file, loaded->scene.values, loaded->scene.content}, model,
                         rate, run.summary, check ? tasks::checkJson(*check) : nlohmann::json());
      !e)
    return fail(e);
  if (const std::optional<int> status = drawPlots(args, csv, loaded->scene, kept, run.summary))
    return *status;
  record(outputsOf(args, csv, tasks::madeFrom(loaded->scene)));
  if (!args.quiet) printResults(args, overrides.value(), model, run, check, csv, to_stdout);
  return kOk;
}

}  // namespace app

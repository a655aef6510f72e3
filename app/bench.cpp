// `rattleback bench`: options in, tasks/bench (the measurements) called, a table printed, the
// CSV written and the error-against-cost figure drawn.
#include "tasks/bench.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/plot.hpp"
#include "tasks/output.hpp"
#include "util/format.hpp"

namespace app {
namespace {

std::string show(std::optional<double> v, const char* format = "%.3g") {
  if (!v) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, *v);
  return text;
}

void printHeader() {
  std::printf("%-8s %-10s %13s %10s %7s %8s %9s %9s %9s %9s %9s %9s %9s %9s %8s\n", "model",
              "integrator", "dt [s] / tol", "cost [s/s]", "spread", "us/step", "proc [ms]",
              "steps (rej)", "reversal", "d_rev", "d_rev_roll", "max|dn|", "|dn|_roll", "drift",
              "switches");
}

// This program run with `args` as a process of its own, its output thrown away: its wall time,
// s, or nothing when it could not start or failed.
std::optional<double> timeProcess(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  std::string self = "/proc/self/exe";
  argv.push_back(self.data());
  std::vector<std::string> copy = args;
  for (std::string& a : copy) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, self.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return std::nullopt;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return std::nullopt;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string stepText(const tasks::BenchRow& r) {
  char text[32];
  if (std::isnan(r.tolerance))
    std::snprintf(text, sizeof text, "%.3g", r.dt);
  else
    std::snprintf(text, sizeof text, "tol %.0e", r.tolerance);
  return text;
}

void printRow(const tasks::BenchRow& r) {
  const std::string model(rb::nameOf(r.model)), integrator(rb::nameOf(r.integrator));
  if (r.status != tasks::BenchStatus::Ok && std::isnan(r.cost_median)) {
    std::printf("%-8s %-10s %13s  %s\n", model.c_str(), integrator.c_str(), stepText(r).c_str(),
                r.brief.c_str());
    return;
  }
  const double spread = (r.cost_max - r.cost_min) / r.cost_median;
  char steps[40];
  std::snprintf(steps, sizeof steps, "%lld (%lld)", static_cast<long long>(r.steps),
                static_cast<long long>(r.rejected));
  const std::optional<double> process_ms =
      r.process_s ? std::optional<double>(1e3 * *r.process_s) : std::nullopt;
  std::printf("%-8s %-10s %13s %10.3g %6.0f%% %8.3g %9s %11s %9s %9s %9s %9s %9s %9s %8s%s\n",
              model.c_str(), integrator.c_str(), stepText(r).c_str(), r.cost_median, 100 * spread,
              r.us_per_step, show(process_ms).c_str(), steps, show(r.reversal, "%.4f").c_str(),
              show(r.reversal_error).c_str(), show(r.reversal_error_rolling).c_str(),
              show(r.spin_error).c_str(), show(r.spin_error_rolling).c_str(),
              show(r.energy_drift).c_str(), show(r.switches, "%.0f").c_str(),
              r.status == tasks::BenchStatus::Ok ? "" : ("  " + r.brief).c_str());
}

// Colour by integrator, marker by contact model, dashes by scene. (Each integrator its own
// colour and each model its own marker: rk4 and dopri5 shared green, rolling and auto a
// triangle, so their legend entries could not be told apart.)
void styleOf(const tasks::BenchRow& r, int dash, Series& s) {
  using I = sim::Integrator;
  using M = sim::ContactModel;
  s.color = r.integrator == I::Euler        ? "#d62728"
            : r.integrator == I::Symplectic ? "#1f77b4"
            : r.integrator == I::Rk4        ? "#2ca02c"
                                            : "#9467bd";
  s.point_type = r.model == M::Points    ? 7
                 : r.model == M::Smooth  ? 5
                 : r.model == M::Rolling ? 9
                                         : 13;
  s.dash = dash;
}

// Error against cost, log–log: one line per scene × model × integrator, its points the rungs.
rb::Status plotBench(const std::string& png, const std::vector<tasks::BenchRow>& rows,
                     const std::vector<std::string>& scenes) {
  Panel spin, reversal, drift;
  spin.title = "Largest spin error over the run against cost";
  spin.y_label = "max |n - n_ref| [rad/s]";
  reversal.title = "Error in the first reversal time against cost";
  reversal.y_label = "|t_rev - t_rev,ref| [s]";
  drift.title = "Energy drift without friction, dampers or drag against cost";
  drift.y_label = "max |E - E0| / E0";
  for (Panel* p : {&spin, &reversal, &drift}) {
    p->x_label = "wall time per simulated second [s]";
    p->log_x = p->log_y = true;
  }
  std::map<std::string, std::array<Series, 3>> lines;
  std::vector<std::string> order;
  for (const tasks::BenchRow& r : rows) {
    const std::string key = (scenes.size() > 1 ? r.scene + " " : "") +
                            std::string(rb::nameOf(r.model)) + " " +
                            std::string(rb::nameOf(r.integrator));
    if (!lines.count(key)) order.push_back(key);
    auto& s = lines[key];
    const int dash =
        1 + static_cast<int>(std::find(scenes.begin(), scenes.end(), r.scene) - scenes.begin());
    for (Series& one : s) {
      one.title = key;
      styleOf(r, dash, one);
    }
    if (std::isnan(r.cost_median)) continue;
    if (r.spin_error) s[0].points.emplace_back(r.cost_median, *r.spin_error);
    if (r.reversal_error) s[1].points.emplace_back(r.cost_median, *r.reversal_error);
    if (r.energy_drift) s[2].points.emplace_back(r.cost_median, *r.energy_drift);
  }
  for (const std::string& key : order) {
    spin.series.push_back(lines[key][0]);
    reversal.series.push_back(lines[key][1]);
    drift.series.push_back(lines[key][2]);
  }
  return plotPng(png, "rattleback bench: error against cost (lower left is better)",
                 {spin, reversal, drift}, 1100, 1500);
}

tasks::BenchOptions optionsOf(const BenchArgs& args) {
  tasks::BenchOptions o;
  o.duration = args.duration;
  o.repeats = args.repeats;
  o.rungs = args.rungs;
  // "rk4 dopri5" quoted as one word is two names, as the docs say.
  auto words = [](const std::vector<std::string>& given) {
    std::vector<std::string> out;
    for (const std::string& g : given) {
      std::istringstream in(g);
      for (std::string w; in >> w;) out.push_back(w);
    }
    return out;
  };
  o.models = words(args.models);
  o.integrators = words(args.integrators);
  o.tolerances = args.tolerances;
  o.cancelled = [] { return interruptSignal() != 0; };
  o.process = timeProcess;
  if (!args.quiet) {
    o.row = [](const tasks::BenchRow& row) {
      printRow(row);
      std::fflush(stdout);
    };
    o.note = [](const std::string& line) { std::printf("%s\n", line.c_str()); };
  }
  return o;
}

}  // namespace

int benchCommand(const BenchArgs& args) {
  installInterruptHandlers();
  const tasks::BenchOptions options = optionsOf(args);
  if (auto ok = tasks::checkBenchOptions(options); !ok) return fail(ok);
  std::vector<std::string> paths = args.scenes;
  if (paths.empty()) paths = {"scenes/rattleback.yaml", "scenes/seed-flip-ccw.yaml"};
  // Each scene's body is compiled once and shared by every run of the bench.
  std::vector<tasks::BenchScene> scenes;
  std::vector<std::string> names;
  for (const std::string& path : paths) {
    auto scene = tasks::loadBenchScene(path);
    if (!scene) return fail(scene);
    names.push_back(scene->name);
    scenes.push_back(std::move(scene).value());
  }
  // Open the outputs before the long work, so an unwritable path fails at once.
  const std::string csv_path = args.csv.empty() ? "out/bench.csv" : args.csv;
  const std::string png_path = args.plot.empty() ? "out/bench.png" : args.plot;
  tasks::MadeFolders made;  // a bench refused or stopped leaves no empty folder behind
  if (auto ok = checkPlotFile(png_path, &made); !ok) return fail(ok);
  if (auto ok = tasks::makeParentFolder(csv_path, &made); !ok) return fail(ok);
  auto csv = tasks::AtomicOutput::open(csv_path);
  if (!csv) return fail(csv);
  std::vector<tasks::BenchRow> rows;
  for (const tasks::BenchScene& scene : scenes) {
    if (!args.quiet) {
      std::printf(
          "\n%s: %g s simulated, %s; reference rk4 at 1/16 of each model's "
          "finest step\n",
          scene.name.c_str(), args.duration, rb::counted(args.repeats, "repeat").c_str());
      printHeader();
    }
    if (!tasks::benchScene(scene, options, rows)) {
      tell(Tone::Error, "bench: interrupted; no table written");
      return interruptedStatus();
    }
  }
  csv->stream() << tasks::benchCsvHeader();
  for (const tasks::BenchRow& r : rows) csv->stream() << tasks::benchCsvLine(r);
  if (auto e = csv->commit(); !e) return fail(e);
  if (auto e = plotBench(png_path, rows, names); !e) return fail(e);
  record({{csv_path, tasks::OutputKind::Bench, "bench", "", {}, {}},
          {png_path, tasks::OutputKind::BenchPlot, "bench", "", {}, {}}});
  if (!args.quiet) std::printf("\nwrote %s and %s\n", csv_path.c_str(), png_path.c_str());
  return kOk;
}

}  // namespace app

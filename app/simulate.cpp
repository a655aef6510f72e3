#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/output.hpp"
#include "app/plot.hpp"
#include "app/progress.hpp"
#include "app/scene_args.hpp"
#include "sim/initial.hpp"
#include "sim/run.hpp"

namespace app {
namespace {

constexpr double kDefaultRate = 500;  // Hz: samples per simulated second when not given

const char* kHeaderUnits =
    "# units: t s, spin rad/s (n = w.z, + counter-clockwise from above), energy kinetic "
    "potential elastic J, tilt_deg degrees, x y z m (centre of mass), wx wy wz rad/s (world), "
    "Lz kg m^2/s (about the CM), contacts count, normal_force N\n";
const char* kHeader =
    "t,spin,energy,kinetic,potential,elastic,tilt_deg,x,y,z,wx,wy,wz,Lz,contacts,normal_force\n";

void writeRow(std::ostream& out, const sim::Telemetry& s) {
  char line[512];
  std::snprintf(line, sizeof line,
                "%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%.9g\n",
                s.t, s.spin, s.energy, s.kinetic, s.potential, s.elastic, s.tilt_deg,
                s.x_world.x(), s.x_world.y(), s.x_world.z(), s.w_world.x(), s.w_world.y(),
                s.w_world.z(), s.L_world.z(), s.contacts, s.normal_force);
  out << line;
}

// Steps per telemetry sample: exact for an explicit --rate, else the whole number nearest
// the default rate.
std::variant<std::int64_t, std::string> stepsPerSample(std::optional<double> rate, double dt) {
  if (!rate) return std::max<std::int64_t>(1, std::llround(1 / (kDefaultRate * dt)));
  if (!(*rate > 0) || !std::isfinite(*rate)) return "--rate must be > 0";
  const double steps = 1 / (*rate * dt);
  if (steps < 0.999999 || std::abs(steps - std::round(steps)) > 1e-6 * steps)
    return "--rate " + std::to_string(*rate) + " Hz is not a whole number of steps of " +
           std::to_string(dt) + " s";
  return std::llround(steps);
}

std::string defaultOutput(const std::string& scene) {
  return "out/" + std::filesystem::path(scene).stem().string() + ".csv";
}

void printSummary(const SimulateArgs& args, const sim::Model& model,
                  const sim::RunSummary& run, const std::string& csv, std::int64_t rows) {
  const double simulated = run.steps * model.dt;
  const char* names[] = {"euler", "symplectic", "rk4"};
  std::printf("scene           %s\n", args.scene.c_str());
  std::printf("integrator      %s, dt %g s, %lld steps (%g s simulated)\n",
              names[static_cast<int>(model.integrator)], model.dt,
              static_cast<long long>(run.steps), simulated);
  if (run.first_reversal_s)
    std::printf("first reversal  %.4f s (spin %+g rad/s changed sign)\n", *run.first_reversal_s,
                model.initial.spin);
  else
    std::printf("first reversal  none in %g s\n", simulated);
  const double change = (run.last.energy - run.first.energy) / std::abs(run.first.energy);
  std::printf("energy          %.6g J -> %.6g J (%+.4g %%)\n", run.first.energy,
              run.last.energy, 100 * change);
  std::printf("final spin      %+.4f rad/s, tilt %.2f deg\n", run.last.spin, run.last.tilt_deg);
  std::printf("wall time       %.3f s: %.4f s per simulated second, %.3f us per step\n",
              run.wall_s, run.wall_s / simulated, 1e6 * run.wall_s / run.steps);
  std::printf("telemetry       %s (%lld rows)\n", csv.c_str(), static_cast<long long>(rows));
}

// The seed's figures (6–8, 12–16) from the telemetry: energy, spin, tilt and CM height, and
// the normal force, each against time, into DIR/<scene>-<what>.png.
std::optional<std::string> writePlots(const std::string& dir, const std::string& scene,
                                      const std::vector<sim::Telemetry>& samples) {
  const std::string stem = std::filesystem::path(scene).stem().string();
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
  energy.series = {series("total", [](const sim::Telemetry& t) { return 1e3 * t.energy; }),
                   series("kinetic", [](const sim::Telemetry& t) { return 1e3 * t.kinetic; }),
                   series("potential M g z", [](const sim::Telemetry& t) { return 1e3 * t.potential; }),
                   series("elastic (floor springs)", [](const sim::Telemetry& t) { return 1e3 * t.elastic; })};
  Panel spin = panel("Spin about the vertical, n = w.z (+ counter-clockwise from above)",
                     "spin n [rad/s]");
  spin.series = {series("n", [](const sim::Telemetry& t) { return t.spin; })};
  Panel tilt = panel("Tilt of the body axis and height of the centre of mass", "tilt [degrees]");
  tilt.y2_label = "CM height z [mm]";
  tilt.series = {series("tilt", [](const sim::Telemetry& t) { return t.tilt_deg; }),
                 series("CM height", [](const sim::Telemetry& t) { return 1e3 * t.x_world.z(); }, true)};
  Panel normal = panel("Normal force of the floor", "normal force N [N]");
  normal.series = {series("N", [](const sim::Telemetry& t) { return t.normal_force; })};
  const std::pair<const char*, Panel*> figures[] = {
      {"energy", &energy}, {"spin", &spin}, {"tilt", &tilt}, {"normal", &normal}};
  for (const auto& [what, p] : figures) {
    const std::string png = (std::filesystem::path(dir) / (stem + "-" + what + ".png")).string();
    if (auto e = plotPng(png, stem + ": " + p->title, {*p}, 1000, 500)) return e;
  }
  return std::nullopt;
}

}  // namespace

int simulateCommand(const SimulateArgs& args) {
  Overrides overrides;
  overrides.duration = args.duration;
  overrides.dt = args.dt;
  overrides.integrator = args.integrator;
  auto compiled = loadScene(args.scene, overrides);
  if (auto* e = std::get_if<std::string>(&compiled)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  const sim::Model& model = std::get<sim::Model>(compiled);

  auto every = stepsPerSample(args.rate, model.dt);
  if (auto* e = std::get_if<std::string>(&every)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  const std::string csv = args.output.empty() ? defaultOutput(args.scene) : args.output;
  if (args.output.empty()) std::filesystem::create_directories("out");
  auto opened = AtomicOutput::open(csv);
  if (auto* e = std::get_if<std::string>(&opened)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  AtomicOutput& file = std::get<AtomicOutput>(opened);
  if (!args.plot_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(args.plot_dir, ec);
    if (!std::filesystem::is_directory(args.plot_dir)) {
      std::cerr << args.plot_dir << ": --plot needs a folder it can write into\n";
      return kBadInput;
    }
  }
  if (args.verbose) describeModel(model, args.scene, std::get<std::int64_t>(every), "sample");
  file.stream() << "# rattleback simulate " << args.scene << "\n" << kHeaderUnits << kHeader;

  std::int64_t rows = 0;
  Progress progress("simulate", model.steps, !args.quiet);
  sim::RunOptions options;
  options.steps_per_sample = std::get<std::int64_t>(every);
  std::vector<sim::Telemetry> kept;  // for the plots
  options.on_sample = [&](const sim::Telemetry& t) {
    writeRow(file.stream(), t);
    ++rows;
    if (!args.plot_dir.empty()) kept.push_back(t);
  };
  options.on_progress = [&](std::int64_t step) { progress.update(step); };
  sim::State state = sim::initialState(model);
  const sim::RunSummary summary = sim::run(model, state, options);
  progress.finish();

  if (summary.divergence) {
    std::cerr << args.scene << ": the run stopped: " << *summary.divergence
              << ". No telemetry written\n";
    return kDiverged;  // `file` is removed unfinished
  }
  if (auto e = file.commit()) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  if (!args.plot_dir.empty()) {
    if (auto e = writePlots(args.plot_dir, args.scene, kept)) {
      std::cerr << *e << "\n";
      return kBadInput;
    }
  }
  if (!args.quiet) printSummary(args, model, summary, csv, rows);
  if (!args.quiet && !args.plot_dir.empty())
    std::printf("plots           %s/%s-{energy,spin,tilt,normal}.png\n", args.plot_dir.c_str(),
                std::filesystem::path(args.scene).stem().string().c_str());
  return kOk;
}

}  // namespace app

// `rattleback bench`: speed against error (SPEC "Reports: speed against error").
//
// For each contact model × integrator × step of a ladder of halvings, the scene runs
// `repeats` times; the cost is the median wall time per simulated second, and the errors are
// measured against a reference: the same model with rk4 at a step 16× below the ladder's
// finest, and the rolling model's reference where the body has a smooth surface. A
// conservative variant (no friction, no dampers, no drag) gives the energy drift.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "tasks/output.hpp"
#include "app/plot.hpp"
#include "scene/loader.hpp"
#include "sim/compile.hpp"
#include "sim/rollout.hpp"

namespace app {
namespace {

// Spin samples every 4 ms (at exact times, whatever the step), so runs compare sample by sample.
constexpr double kSampleRate = 250;  // Hz
// Wall time one run may take, s: a rung past it (an adaptive ladder on a tumbling body with
// Coulomb friction takes millions of steps at tight tolerances) stops there, is listed with the
// reason, and the ladder's tighter rungs are skipped.
constexpr double kRunBudget = 10;
// The adaptive ladder (dopri5) when --tolerances is not given: 1e-4 … 1e-10.
constexpr double kTolerances[] = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
// The points model visits every bottom point each step; past this many it is left out unless
// asked for (the default body's 0.025 cm grid has 121076).
constexpr std::size_t kMaxBenchPoints = 10000;
// A penalty model benched on a scene that has no floor constants gets SPEC's stiffness and a
// damping ratio ζ = c / (2 sqrt(kM)) of 0.06 (the default body's c = 4 N s/m).
constexpr double kDefaultStiffness = 2.0e4;
constexpr double kDefaultZeta = 0.06;

const char* kIntegrators[] = {"euler", "symplectic", "rk4", "dopri5"};

// The coarsest step of each model's ladder: rolling has no contact spring (rk4 is converged
// to 4 digits at 1 ms); the penalty models need steps near 1/ω of their floor and, with
// friction, of its slip regularisation.
double topStep(const std::string& model) {
  if (model == "rolling" || model == "auto") return 2e-3;  // auto slides in steps of its own
  if (model == "smooth") return 1.6e-4;
  return 4e-5;
}

struct Trace {
  std::optional<std::string> failure;  ///< refused by compile or stopped by run
  std::string brief;                   ///< the failure in a few words, for the table
  std::vector<sim::Telemetry> samples;
  std::optional<double> reversal;
  double wall_per_simulated = 0, us_per_step = 0;
  std::int64_t steps = 0, rejected = 0;
  int switches = 0;  ///< auto: changes between rolling and smooth
};

// One run of the shared body: compileRun only (the body was built once for the scene).
Trace runOnce(const sim::SceneSpec& spec, const std::shared_ptr<const sim::Body>& body) {
  Trace trace;
  auto compiled = sim::compileRun(spec, body);
  if (!compiled) {
    trace.failure = "refused: " + compiled.error().text();
    trace.brief = "refused: " + compiled.error().key + " too large for the contact";
    return trace;
  }
  const sim::Model& model = compiled.value();
  sim::Rollout rollout(model);
  for (double t : sim::sampleTimes(model.duration, kSampleRate)) {
    if (!rollout.advanceTo(t)) break;
    trace.samples.push_back(rollout.sampleAt(t));
    if (rollout.summary().wall_s > kRunBudget) break;
  }
  const sim::RunSummary& summary = rollout.summary();
  trace.steps = summary.steps;
  trace.rejected = summary.rejected;
  trace.switches = summary.switches;
  if (!summary.divergence && summary.wall_s > kRunBudget && rollout.current().t < model.duration) {
    char text[128];
    std::snprintf(text, sizeof text, "stopped at %.3g s: over the %g s budget of one run",
                  rollout.current().t, kRunBudget);
    trace.failure = trace.brief = text;
  } else if (summary.divergence) {
    trace.failure = "stopped: " + *summary.divergence;
    const char* brief = "NaN or infinity";
    if (summary.stop && summary.stop->reason == sim::StopReason::EnergyGain)
      brief = "energy grew beyond the bound";
    if (summary.stop && summary.stop->reason == sim::StopReason::OnRim)
      brief = "tipped onto the rim of its top";
    char text[96];
    std::snprintf(text, sizeof text, "stopped at %.3g s: %s", rollout.current().t, brief);
    trace.brief = text;
  }
  trace.reversal = summary.first_reversal_s;
  trace.wall_per_simulated = summary.wall_s / rollout.current().t;
  trace.us_per_step = 1e6 * summary.wall_s / std::max<std::int64_t>(1, summary.steps);
  return trace;
}

/// max |n − n_ref| over the samples both runs share, rad/s.
std::optional<double> maxSpinError(const Trace& a, const Trace& ref) {
  if (a.failure || ref.failure || a.samples.empty()) return std::nullopt;
  double worst = 0;
  const std::size_t n = std::min(a.samples.size(), ref.samples.size());
  for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(a.samples[i].spin - ref.samples[i].spin));
  return worst;
}

std::optional<double> reversalError(const Trace& a, const Trace& ref) {
  if (a.failure || ref.failure || !a.reversal || !ref.reversal) return std::nullopt;
  return std::abs(*a.reversal - *ref.reversal);
}

struct Row {
  std::string scene, model, integrator;
  double dt = 0;          ///< fixed step, s (NaN for adaptive rows)
  double tolerance = NAN;  ///< adaptive rows
  std::int64_t steps = 0, rejected = 0;
  std::optional<double> switches;  ///< auto rows: changes of contact model
  std::string status = "ok";  ///< or the failure in full (CSV)
  std::string brief;          ///< the failure in a few words (table)
  double cost_median = NAN, cost_min = NAN, cost_max = NAN, us_per_step = NAN;
  std::optional<double> reversal, reversal_error, reversal_error_rolling;
  std::optional<double> spin_error, spin_error_rolling, energy_drift;
};

std::string show(std::optional<double> v, const char* format = "%.3g") {
  if (!v) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, *v);
  return text;
}

// A CSV cell: empty where there is no value (what CSV readers take as missing).
std::string cell(std::optional<double> v, const char* format) { return v ? show(v, format) : ""; }

void printHeader() {
  std::printf("%-8s %-10s %13s %10s %7s %8s %9s %9s %9s %9s %9s %9s %9s %8s\n", "model",
              "integrator", "dt [s] / tol", "cost [s/s]", "spread", "us/step", "steps (rej)",
              "reversal", "d_rev", "d_rev_roll", "max|dn|", "|dn|_roll", "drift", "switches");
}

std::string stepText(const Row& r) {
  char text[32];
  if (std::isnan(r.tolerance))
    std::snprintf(text, sizeof text, "%.3g", r.dt);
  else
    std::snprintf(text, sizeof text, "tol %.0e", r.tolerance);
  return text;
}

void printRow(const Row& r) {
  if (r.status != "ok" && std::isnan(r.cost_median)) {
    std::printf("%-8s %-10s %13s  %s\n", r.model.c_str(), r.integrator.c_str(),
                stepText(r).c_str(), r.brief.c_str());
    return;
  }
  const double spread = (r.cost_max - r.cost_min) / r.cost_median;
  char steps[40];
  std::snprintf(steps, sizeof steps, "%lld (%lld)", static_cast<long long>(r.steps),
                static_cast<long long>(r.rejected));
  std::printf("%-8s %-10s %13s %10.3g %6.0f%% %8.3g %11s %9s %9s %9s %9s %9s %9s %8s%s\n",
              r.model.c_str(), r.integrator.c_str(), stepText(r).c_str(), r.cost_median,
              100 * spread, r.us_per_step, steps,
              show(r.reversal, "%.4f").c_str(), show(r.reversal_error).c_str(),
              show(r.reversal_error_rolling).c_str(), show(r.spin_error).c_str(),
              show(r.spin_error_rolling).c_str(), show(r.energy_drift).c_str(),
              show(r.switches, "%.0f").c_str(),
              r.status == "ok" ? "" : ("  " + r.brief).c_str());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// The same scene without anything that removes energy.
sim::SceneSpec conservative(sim::SceneSpec spec) {
  spec.contact.friction = 0;
  spec.contact.damping = 0;
  spec.contact.air_drag = 0;
  return spec;
}

double energyDrift(const Trace& t) {
  double worst = 0;
  const double e0 = t.samples.front().energy;
  for (const sim::Telemetry& s : t.samples) worst = std::max(worst, std::abs(s.energy - e0) / std::abs(e0));
  return worst;
}

}  // namespace

int benchCommand(const BenchArgs& args) {
  installInterruptHandlers();
  std::vector<std::string> scenes = args.scenes;
  if (scenes.empty()) scenes = {"scenes/rattleback.yaml", "scenes/seed-reversed.yaml"};
  for (const std::string& m : args.models)
    if (!rb::parseName<sim::ContactModel>(m)) {
      std::cerr << "--models: expected " << rb::choices<sim::ContactModel>() << ", not '" << m
                << "'\n";
      return kBadInput;
    }
  for (const std::string& i : args.integrators)
    if (!rb::parseName<sim::Integrator>(i)) {
      std::cerr << "--integrators: expected " << rb::choices<sim::Integrator>() << ", not '" << i
                << "'\n";
      return kBadInput;
    }
  for (double tol : args.tolerances)
    if (!(tol >= 1e-14 && tol <= 0.1)) {
      std::cerr << "--tolerances: each must lie within 1e-14 … 0.1, not " << tol << "\n";
      return kBadInput;
    }
  const std::vector<double> tolerances =
      args.tolerances.empty() ? std::vector<double>(std::begin(kTolerances), std::end(kTolerances))
                              : args.tolerances;
  if (!(args.duration > 0) || !std::isfinite(args.duration) || args.repeats < 1 || args.rungs < 1 ||
      args.rungs > 12) {
    std::cerr << "bench: --duration must be > 0, --repeats ≥ 1 and --rungs within 1 … 12\n";
    return kBadInput;
  }
  // Each scene's body is compiled once and shared by every run of the bench.
  std::vector<scene::Loaded> loaded;
  std::vector<std::shared_ptr<const sim::Body>> bodies;
  for (const std::string& path : scenes) {
    auto l = scene::loadFile(path);
    if (!l) {
      std::cerr << l.error().text() << "\n";
      return kBadInput;
    }
    auto model = scene::loadModel(l.value());
    if (!model) {
      std::cerr << model.error().text() << "\n";
      return kBadInput;
    }
    bodies.push_back(model->body);
    loaded.push_back(std::move(l).value());
  }
  // Open the outputs before the long work, so an unwritable path fails at once.
  const std::string csv_path = args.csv.empty() ? "out/bench.csv" : args.csv;
  const std::string png_path = args.plot.empty() ? "out/bench.png" : args.plot;
  if (auto made = checkPlotFile(png_path); !made) {
    std::cerr << made.error().text() << "\n";
    return kBadInput;
  }
  auto opened = tasks::AtomicOutput::open(csv_path);
  if (!opened) {
    std::cerr << opened.error().text() << "\n";
    return kBadInput;
  }
  tasks::AtomicOutput& csv = opened.value();
  // The header is the first line (plain CSV readers take it as such); what the columns mean is
  // in the README ("bench").
  csv.stream() << "scene,model,integrator,dt,tolerance,steps,rejected,status,cost_median,cost_min,"
                  "cost_max,us_per_step,reversal_s,reversal_error_s,reversal_error_vs_rolling_s,"
                  "max_spin_error,max_spin_error_vs_rolling,energy_drift,switches\n";

  std::vector<Row> rows;
  for (std::size_t scene_index = 0; scene_index < loaded.size(); ++scene_index) {
    const scene::Loaded& scene = loaded[scene_index];
    sim::SceneSpec base = scene.spec;
    base.simulation.duration = args.duration;
    const std::shared_ptr<const sim::Body>& body = bodies[scene_index];
    const std::string name = std::filesystem::path(scene.file).filename().string();
    std::vector<std::string> models = args.models;
    if (models.empty()) {
      const std::size_t bottom = body->bottom.size();
      if (base.contact.model == "points" || bottom <= kMaxBenchPoints) models.push_back("points");
      models.push_back("smooth");
      models.push_back("rolling");
      models.push_back("auto");
      if (!args.quiet && bottom > kMaxBenchPoints && base.contact.model != "points")
        std::printf("(%s: points model left out: %zu bottom points; --models points adds it)\n",
                    name.c_str(), bottom);
    }
    const std::vector<std::string> integrators =
        args.integrators.empty() ? std::vector<std::string>(std::begin(kIntegrators), std::end(kIntegrators))
                                 : args.integrators;
    if (!args.quiet)
      std::printf("\n%s: %g s simulated, %d repeats; reference rk4 at 1/16 of each model's "
                  "finest step\n",
                  name.c_str(), args.duration, args.repeats);
    if (!args.quiet) printHeader();

    auto variant = [&](const std::string& model) {
      sim::SceneSpec spec = base;
      spec.contact.model = model;
      if (model != "rolling" && std::isnan(spec.contact.stiffness)) {
        spec.contact.stiffness = kDefaultStiffness;
        spec.contact.damping = 2 * kDefaultZeta * std::sqrt(kDefaultStiffness * spec.body.mass);
      }
      if (model == "rolling") spec.initial.height = 0;
      return spec;
    };
    auto reference = [&](const std::string& model) {
      sim::SceneSpec spec = variant(model);
      spec.simulation.integrator = "rk4";
      spec.simulation.dt = topStep(model) / std::pow(2.0, args.rungs - 1) / 16;
      spec.simulation.tolerance = sim::kUnset;
      return runOnce(spec, body);
    };
    const Trace rolling_reference = reference("rolling");
    for (const std::string& model : models) {
      const Trace own_reference = model == "rolling" ? rolling_reference : reference(model);
      if (own_reference.failure && !args.quiet)
        std::printf("%-8s reference (rk4) %s\n", model.c_str(), own_reference.brief.c_str());
      for (const std::string& integrator : integrators) {
        const bool adaptive = sim::isAdaptive(*rb::parseName<sim::Integrator>(integrator));
        // The points model's thousands of stiff springs leave adaptive steps nothing to gain;
        // its dopri5 rows only when asked for by name.
        if (adaptive && model == "points" && args.integrators.empty()) continue;
        const int rungs = adaptive ? static_cast<int>(tolerances.size()) : args.rungs;
        bool over_budget = false;
        for (int rung = 0; rung < rungs; ++rung) {
          Row row;
          row.scene = name;
          row.model = model;
          row.integrator = integrator;
          sim::SceneSpec spec = variant(model);
          spec.simulation.integrator = integrator;
          if (adaptive) {
            row.dt = NAN;
            row.tolerance = tolerances[rung];
            spec.simulation.dt = sim::kUnset;
            spec.simulation.tolerance = row.tolerance;
          } else {
            row.dt = topStep(model) / std::pow(2.0, rung);
            spec.simulation.dt = row.dt;
            spec.simulation.tolerance = sim::kUnset;
          }
          if (interruptSignal()) {
            std::cerr << "bench: interrupted; no table written\n";
            return interruptedStatus();
          }
          if (over_budget) {
            row.status = row.brief = "skipped: the rung before ran over the budget of one run";
            if (!args.quiet) printRow(row);
            rows.push_back(row);
            continue;
          }
          std::vector<double> costs;
          Trace first;
          for (int r = 0; r < args.repeats; ++r) {
            Trace t = runOnce(spec, body);
            if (t.failure && t.failure->find("budget") != std::string::npos) over_budget = true;
            if (t.failure && t.samples.empty()) {  // refused: nothing ran
              row.status = *t.failure;
              row.brief = t.brief;
              break;
            }
            costs.push_back(t.wall_per_simulated);
            if (r == 0) first = std::move(t);
            if (first.failure) break;  // a run that stops stops every time
          }
          if (!costs.empty()) {
            row.cost_median = median(costs);
            row.cost_min = *std::min_element(costs.begin(), costs.end());
            row.cost_max = *std::max_element(costs.begin(), costs.end());
            row.us_per_step = first.us_per_step;
            row.steps = first.steps;
            row.rejected = first.rejected;
            if (model == "auto") row.switches = first.switches;
            if (first.failure) {
              row.status = *first.failure;
              row.brief = first.brief;
            }
            row.reversal = first.failure ? std::nullopt : first.reversal;
            row.reversal_error = reversalError(first, own_reference);
            row.reversal_error_rolling = reversalError(first, rolling_reference);
            row.spin_error = maxSpinError(first, own_reference);
            row.spin_error_rolling = maxSpinError(first, rolling_reference);
            const Trace lossless = runOnce(conservative(spec), body);
            if (!lossless.failure) row.energy_drift = energyDrift(lossless);
          }
          if (!args.quiet) printRow(row);
          std::fflush(stdout);
          rows.push_back(row);
        }
      }
    }
  }

  for (const Row& r : rows) {
    std::string status = r.status;
    std::replace(status.begin(), status.end(), ',', ';');
    char line[1024];
    std::snprintf(line, sizeof line,
                  "%s,%s,%s,%s,%s,%lld,%lld,\"%s\",%.6g,%.6g,%.6g,%.6g,%s,%s,%s,%s,%s,%s,%s\n",
                  r.scene.c_str(), r.model.c_str(), r.integrator.c_str(),
                  std::isnan(r.dt) ? "" : show(r.dt, "%.6g").c_str(),
                  std::isnan(r.tolerance) ? "" : show(r.tolerance, "%.3g").c_str(),
                  static_cast<long long>(r.steps), static_cast<long long>(r.rejected), status.c_str(),
                  r.cost_median, r.cost_min, r.cost_max, r.us_per_step,
                  cell(r.reversal, "%.9g").c_str(), cell(r.reversal_error, "%.6g").c_str(),
                  cell(r.reversal_error_rolling, "%.6g").c_str(), cell(r.spin_error, "%.6g").c_str(),
                  cell(r.spin_error_rolling, "%.6g").c_str(), cell(r.energy_drift, "%.6g").c_str(),
                  cell(r.switches, "%.0f").c_str());
    csv.stream() << line;
  }
  if (auto e = csv.commit(); !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }

  // Error against cost, log–log: one line per scene × model × integrator, its points the rungs.
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
  for (const Row& r : rows) {
    const std::string key = (loaded.size() > 1 ? r.scene + " " : "") + r.model + " " + r.integrator;
    if (!lines.count(key)) order.push_back(key);
    auto& s = lines[key];
    // Colour by integrator, marker by contact model, dashes by scene.
    // (Each integrator its own colour and each model its own marker: rk4 and dopri5 shared
    // green, rolling and auto a triangle, so their legend entries could not be told apart.)
    const std::string color = r.integrator == "euler"        ? "#d62728"
                              : r.integrator == "symplectic" ? "#1f77b4"
                              : r.integrator == "rk4"        ? "#2ca02c"
                                                             : "#9467bd";
    const int marker = r.model == "points" ? 7 : r.model == "smooth" ? 5 : r.model == "rolling" ? 9 : 13;
    const int dash = 1 + static_cast<int>(std::find_if(loaded.begin(), loaded.end(), [&](const scene::Loaded& l) {
                       return std::filesystem::path(l.file).filename().string() == r.scene;
                     }) - loaded.begin());
    for (Series& one : s) {
      one.title = key;
      one.color = color;
      one.point_type = marker;
      one.dash = dash;
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
  if (auto e = plotPng(png_path, "rattleback bench: error against cost (lower left is better)",
                       {spin, reversal, drift}, 1100, 1500);
      !e) {
    std::cerr << e.error().text() << "\n";
    return kBadInput;
  }
  if (!args.quiet) std::printf("\nwrote %s and %s\n", csv_path.c_str(), png_path.c_str());
  return kOk;
}

}  // namespace app

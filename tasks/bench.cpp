#include "tasks/bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>

#include "scene/loader.hpp"
#include "sim/compile.hpp"
#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"
#include "sim/rollout.hpp"
#include "tasks/scene_args.hpp"
#include "tasks/table.hpp"

namespace tasks {
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
// A penalty model benched on a scene that has no floor constants gets the default scene's stiffness
// and a damping ratio ζ = c / (2 sqrt(kM)) of 0.06 (the default body's c = 4 N s/m).
constexpr double kDefaultStiffness = 2.0e4;
constexpr double kDefaultZeta = 0.06;

// The coarsest step of each model's ladder: rolling has no contact spring (rk4 is converged
// to 4 digits at 1 ms); the penalty models need steps near 1/ω of their floor and, with
// friction, of its slip regularisation.
double topStep(sim::ContactModel model) {
  using M = sim::ContactModel;
  if (model == M::Rolling || model == M::Auto) return 2e-3;  // auto slides in steps of its own
  if (model == M::Smooth) return 1.6e-4;
  return 4e-5;
}

struct Trace {
  std::optional<std::string> failure;  ///< refused by compile or stopped by run
  bool over_budget = false;            ///< stopped at the budget of one run (kRunBudget)
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
    trace.brief = compiled.error().key == "simulation.dt"
                      ? "refused: simulation.dt too large for the contact"
                      : "refused: " + compiled.error().text().substr(0, 60);
    return trace;
  }
  const sim::Model& model = compiled.value();
  sim::Rollout rollout(model);
  for (double t : sim::sampleTimes(model.duration, kSampleRate)) {
    if (!rollout.advanceTo(t)) break;
    trace.samples.push_back(rollout.sampleAt(t));
    if (rollout.wallSeconds() > kRunBudget) break;
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
    trace.over_budget = true;
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
  for (std::size_t i = 0; i < n; ++i)
    worst = std::max(worst, std::abs(a.samples[i].spin - ref.samples[i].spin));
  return worst;
}

std::optional<double> reversalError(const Trace& a, const Trace& ref) {
  if (a.failure || ref.failure || !a.reversal || !ref.reversal) return std::nullopt;
  return std::abs(*a.reversal - *ref.reversal);
}

std::string show(std::optional<double> v, const char* format = "%.3g") {
  if (!v) return "";
  char text[32];
  std::snprintf(text, sizeof text, format, *v);
  return text;
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
  for (const sim::Telemetry& s : t.samples)
    worst = std::max(worst, std::abs(s.energy - e0) / std::abs(e0));
  return worst;
}

sim::SceneSpec variant(const sim::SceneSpec& base, sim::ContactModel model) {
  sim::SceneSpec spec = base;
  spec.contact.model = rb::nameOf(model);
  const bool rolling = model == sim::ContactModel::Rolling;
  if (!rolling && std::isnan(spec.contact.stiffness)) {
    spec.contact.stiffness = kDefaultStiffness;
    spec.contact.damping = 2 * kDefaultZeta * std::sqrt(kDefaultStiffness * spec.body.mass);
  }
  if (rolling) spec.initial.height = 0;
  return spec;
}

Trace reference(const BenchScene& scene, const sim::SceneSpec& base, sim::ContactModel model,
                int rungs) {
  sim::SceneSpec spec = variant(base, model);
  spec.simulation.integrator = "rk4";
  spec.simulation.dt = topStep(model) / std::pow(2.0, rungs - 1) / 16;
  spec.simulation.tolerance = sim::kUnset;
  return runOnce(spec, scene.body);
}

// The models a scene is benched with: those asked for, else all that apply.
std::vector<sim::ContactModel> modelsOf(const BenchScene& scene, const BenchOptions& options) {
  using M = sim::ContactModel;
  std::vector<M> models;
  for (const std::string& m : options.models) models.push_back(*rb::parseName<M>(m));
  if (!models.empty()) return models;
  const auto bottom = static_cast<std::size_t>(sim::censusOf(*scene.body).bottom);
  if (scene.spec.contact.model == "points" || bottom <= kMaxBenchPoints)
    models.push_back(M::Points);
  for (M m : {M::Smooth, M::Rolling, M::Auto}) models.push_back(m);
  if (bottom > kMaxBenchPoints && scene.spec.contact.model != "points" && options.note)
    options.note("(" + scene.name + ": points model left out: " + std::to_string(bottom) +
                 " bottom points; --models points adds it)");
  return models;
}

// The references a rung's errors are measured against.
struct References {
  const Trace& own;
  const Trace& rolling;
};

// One rung: `repeats` runs of `spec`, the errors of the first against the references, and the
// energy drift of its conservative variant.
BenchRow measureRung(BenchRow row, const sim::SceneSpec& spec, const BenchScene& scene,
                     const BenchOptions& options, const References& ref, bool& over_budget) {
  std::vector<double> costs;
  Trace first;
  for (int r = 0; r < options.repeats; ++r) {
    Trace t = runOnce(spec, scene.body);
    if (t.over_budget) over_budget = true;
    if (t.failure && t.samples.empty()) {  // refused: nothing ran
      row.status = BenchStatus::Failed;
      row.message = *t.failure;
      row.brief = t.brief;
      return row;
    }
    costs.push_back(t.wall_per_simulated);
    if (r == 0) first = std::move(t);
    if (first.failure) break;  // a run that stops stops every time
  }
  if (options.process && !first.failure) {
    std::vector<double> whole;
    const std::vector<std::string> args = processArguments(scene, spec, spec.simulation.duration);
    for (int r = 0; r < options.repeats; ++r)
      if (const auto seconds = options.process(args)) whole.push_back(*seconds);
    if (!whole.empty()) row.process_s = median(whole);
  }
  row.cost_median = median(costs);
  row.cost_min = *std::min_element(costs.begin(), costs.end());
  row.cost_max = *std::max_element(costs.begin(), costs.end());
  row.us_per_step = first.us_per_step;
  row.steps = first.steps;
  row.rejected = first.rejected;
  if (row.model == sim::ContactModel::Auto) row.switches = first.switches;
  if (first.failure) {
    row.status = BenchStatus::Failed;
    row.message = *first.failure;
    row.brief = first.brief;
  }
  row.reversal = first.failure ? std::nullopt : first.reversal;
  row.reversal_error = reversalError(first, ref.own);
  row.reversal_error_rolling = reversalError(first, ref.rolling);
  row.spin_error = maxSpinError(first, ref.own);
  row.spin_error_rolling = maxSpinError(first, ref.rolling);
  const Trace lossless = runOnce(conservative(spec), scene.body);
  if (!lossless.failure) row.energy_drift = energyDrift(lossless);
  return row;
}

// The ladder of one model × integrator; false when cancelled.
bool ladder(const BenchScene& scene, const sim::SceneSpec& base, sim::ContactModel model,
            sim::Integrator integrator, const BenchOptions& options, const References& ref,
            std::vector<BenchRow>& rows) {
  const bool adaptive = sim::isAdaptive(integrator);
  const std::vector<double> tolerances =
      options.tolerances.empty()
          // As many decades from 1e-4 as the step ladders have rungs (--rungs 1 is one run of
          // each, dopri5's too: it ran all seven decades).
          ? std::vector<double>(std::begin(kTolerances),
                                std::begin(kTolerances) +
                                    std::min<std::size_t>(std::size(kTolerances), options.rungs))
          : options.tolerances;
  const int rungs = adaptive ? static_cast<int>(tolerances.size()) : options.rungs;
  bool over_budget = false;
  for (int rung = 0; rung < rungs; ++rung) {
    if (options.cancelled && options.cancelled()) return false;
    BenchRow row;
    row.scene = scene.name;
    row.model = model;
    row.integrator = integrator;
    sim::SceneSpec spec = variant(base, model);
    spec.simulation.integrator = rb::nameOf(integrator);
    row.dt = adaptive ? NAN : topStep(model) / std::pow(2.0, rung);
    row.tolerance = adaptive ? tolerances[rung] : NAN;
    spec.simulation.dt = adaptive ? sim::kUnset : row.dt;
    spec.simulation.tolerance = adaptive ? row.tolerance : sim::kUnset;
    if (over_budget) {
      row.status = BenchStatus::Skipped;
      row.message = row.brief = "skipped: the rung before ran over the budget of one run";
    } else {
      row = measureRung(row, spec, scene, options, ref, over_budget);
    }
    if (options.row) options.row(row);
    rows.push_back(row);
  }
  return true;
}

}  // namespace

std::vector<std::string> processArguments(const BenchScene& scene, const sim::SceneSpec& spec,
                                          double duration) {
  std::vector<std::string> args = {"simulate", scene.path, "-q", "-o", "/dev/null"};
  auto set = [&](const std::string& key, const std::string& value) {
    args.push_back("--set");
    args.push_back(key + "=" + value);
  };
  const sim::SceneSpec& file = scene.spec;
  // What variant() changed (NaN, unset, stays unset).
  auto changed = [](double now, double before) { return !std::isnan(now) && !(now == before); };
  if (spec.contact.model != file.contact.model) set("contact.model", spec.contact.model);
  if (changed(spec.contact.stiffness, file.contact.stiffness))
    set("contact.stiffness", number(spec.contact.stiffness));
  if (changed(spec.contact.damping, file.contact.damping))
    set("contact.damping", number(spec.contact.damping));
  if (changed(spec.initial.height, file.initial.height))
    set("initial.height", number(spec.initial.height));
  args.insert(args.end(), {"--integrator", spec.simulation.integrator, "--duration",
                           number(duration), "--rate", number(kSampleRate)});
  if (std::isnan(spec.simulation.tolerance))
    args.insert(args.end(), {"--dt", number(spec.simulation.dt)});
  else
    args.insert(args.end(), {"--tolerance", number(spec.simulation.tolerance)});
  return args;
}

rb::Result<BenchScene> loadBenchScene(const std::string& path) {
  auto loaded = scene::loadFile(findShipped(path));
  if (!loaded) return loaded.error();
  auto model = scene::loadModel(loaded.value());
  if (!model) return model.error();
  // The points model is benched on this body too (modelsOf) when its grid is small enough:
  // the same body, mass properties and all, with its contact points.
  std::shared_ptr<const sim::Body> body = model->body;
  if (body->bottom.size() == 0 &&
      sim::censusOf(*body).bottom <= static_cast<std::int64_t>(kMaxBenchPoints)) {
    auto with_points = sim::compileBody(loaded->spec, sim::BodyPoints::Always);
    if (!with_points) return with_points.error();
    body = with_points.value();
  }
  return BenchScene{std::filesystem::path(path).filename().string(), findShipped(path),
                    loaded->spec, body};
}

rb::Status checkBenchOptions(const BenchOptions& o) {
  // A scene after the names was taken for one (`--models rolling mine.yaml`): said so.
  auto scene = [](const std::string& word) {
    const std::string ext = std::filesystem::path(word).extension().string();
    return ext == ".yaml" || ext == ".yml"
               ? " (a scene: give the scenes before the option, or end its names with --)"
               : "";
  };
  for (const std::string& m : o.models)
    if (!rb::parseName<sim::ContactModel>(m))
      return rb::Status::fail("--models: expected " + rb::choices<sim::ContactModel>() + ", not '" +
                              m + "'" + scene(m));
  for (const std::string& i : o.integrators)
    if (!rb::parseName<sim::Integrator>(i))
      return rb::Status::fail("--integrators: expected " + rb::choices<sim::Integrator>() +
                              ", not '" + i + "'" + scene(i));
  for (double tol : o.tolerances)
    if (!(tol >= 1e-14 && tol <= 0.1))
      return rb::Status::fail("--tolerances: each must lie within 1e-14 … 0.1, not " +
                              show(tol, "%g"));
  if (!(o.duration > 0) || !std::isfinite(o.duration) || o.repeats < 1 || o.rungs < 1 ||
      o.rungs > 12)
    return rb::Status::fail(
        "bench: --duration must be > 0, --repeats ≥ 1 and --rungs within 1 … 12");
  return {};
}

bool benchScene(const BenchScene& scene, const BenchOptions& options, std::vector<BenchRow>& rows) {
  sim::SceneSpec base = scene.spec;
  base.simulation.duration = options.duration;
  std::vector<sim::Integrator> integrators;
  for (const std::string& i : options.integrators)
    integrators.push_back(*rb::parseName<sim::Integrator>(i));
  if (integrators.empty())
    for (const auto& [integrator, name] : rb::NameTable<sim::Integrator>::entries)
      if (sim::integratorTraits(integrator).benched_by_default) integrators.push_back(integrator);
  using M = sim::ContactModel;
  const Trace rolling_reference = reference(scene, base, M::Rolling, options.rungs);
  for (const M model : modelsOf(scene, options)) {
    const Trace own =
        model == M::Rolling ? rolling_reference : reference(scene, base, model, options.rungs);
    if (own.failure && options.note)
      options.note(std::string(rb::nameOf(model)) + " reference (rk4) " + own.brief);
    for (const sim::Integrator integrator : integrators) {
      // The points model's thousands of stiff springs leave adaptive steps nothing to gain;
      // its dopri5 rows only when asked for by name.
      const bool adaptive = sim::isAdaptive(integrator);
      if (adaptive && model == M::Points && options.integrators.empty()) continue;
      // A method refused where the body rolls (semi-implicit Euler, sim/compile.cpp): its rows
      // only when asked for by name, to show the refusal.
      const bool rolls = sim::contactTraits(model).rolls;
      if (sim::integratorTraits(integrator).refused_when_rolling && rolls &&
          options.integrators.empty())
        continue;
      if (!ladder(scene, base, model, integrator, options, {own, rolling_reference}, rows))
        return false;
    }
  }
  return true;
}

namespace {

// The bench table's columns (docs/commands.md "rattleback bench" says what each measures).
constexpr Column kBenchColumns[] = {
    {"scene", "", "the scene file's name"},
    {"model", "", "contact model"},
    {"integrator", "", "integrator"},
    {"dt", "s", "fixed step (empty for adaptive rows)"},
    {"tolerance", "", "error per step (adaptive rows)"},
    {"steps", "", "accepted steps of the first run"},
    {"rejected", "", "steps tried and rejected (adaptive)"},
    {"status", "", "ok, or why the rung stopped, was refused or skipped"},
    {"cost_median", "s/s", "wall seconds per simulated second, median of the repeats"},
    {"cost_min", "s/s", "wall seconds per simulated second, least"},
    {"cost_max", "s/s", "wall seconds per simulated second, most"},
    {"us_per_step", "us", "microseconds of wall time per step"},
    {"process_s", "s", "the run as a whole process (rattleback simulate), median of the repeats"},
    {"reversal_s", "s", "first reversal"},
    {"reversal_error_s", "s", "against the model's own rk4 reference"},
    {"reversal_error_vs_rolling_s", "s", "against the rolling model's reference"},
    {"max_spin_error", "rad/s", "largest |n - n_ref| over the samples"},
    {"max_spin_error_vs_rolling", "rad/s", "the same against rolling's reference"},
    {"energy_drift", "", "largest |E - E0| / E0 of the run without dissipation"},
    {"switches", "", "auto: changes between rolling and smooth"},
};

}  // namespace

std::string benchCsvHeader() {
  return csvHeader(kBenchColumns) + "\n";
}

std::string benchCsvLine(const BenchRow& r) {
  const std::string fields[] = {csvField(r.scene),
                                std::string(rb::nameOf(r.model)),
                                std::string(rb::nameOf(r.integrator)),
                                number(r.dt, 6),
                                number(r.tolerance, 3),
                                std::to_string(r.steps),
                                std::to_string(r.rejected),
                                csvField(r.status == BenchStatus::Ok ? "ok" : r.message),
                                number(r.cost_median, 6),
                                number(r.cost_min, 6),
                                number(r.cost_max, 6),
                                number(r.us_per_step, 6),
                                r.process_s ? number(*r.process_s, 6) : std::string(),
                                number(r.reversal),
                                number(r.reversal_error, 6),
                                number(r.reversal_error_rolling, 6),
                                number(r.spin_error, 6),
                                number(r.spin_error_rolling, 6),
                                number(r.energy_drift, 6),
                                number(r.switches, 6)};
  std::string line;
  for (const std::string& f : fields) line.append(line.empty() ? "" : ",").append(f);
  return line + "\n";
}

}  // namespace tasks

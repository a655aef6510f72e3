// Cost of one step for each contact model and integrator (Google Benchmark; never part of
// the test run). The scenes are the shipped ones; the state is advanced between iterations,
// so the contact set is the one a real run sees.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>

#include "scene/sweep.hpp"
#include "sim/compile.hpp"
#include "sim/contact_model.hpp"
#include "sim/initial.hpp"
#include "sim/rollout.hpp"
#include "sim/step.hpp"
#include "tasks/scene_args.hpp"

namespace {

void stepScene(benchmark::State& state, const char* scene, const char* model,
               const char* integrator) {
  tasks::Overrides o;
  o.set(tasks::SceneOption::Integrator, std::string(integrator));
  auto loaded = tasks::loadScene(std::string(RATTLEBACK_SOURCE_DIR "/scenes/") + scene, o);
  if (!loaded) {
    state.SkipWithError(loaded.error().text().c_str());
    return;
  }
  const sim::Model& m = loaded->model;
  sim::State s = sim::initialState(m);
  for (auto _ : state) {
    sim::step(m, s);
    benchmark::DoNotOptimize(s.x_world);
  }
  // Only the points model visits the bottom points.
  state.SetLabel(sim::contactTraits(m.contact.model).touch == sim::Touch::Grid
                     ? std::string(model) + ", " + std::to_string(m.body->bottom.size()) + " points"
                     : std::string(model));
}

BENCHMARK_CAPTURE(stepScene, seed_points_euler, "seed-flip-ccw.yaml", "points", "euler");
BENCHMARK_CAPTURE(stepScene, seed_points_symplectic, "seed-flip-ccw.yaml", "points", "symplectic");
BENCHMARK_CAPTURE(stepScene, seed_points_rk4, "seed-flip-ccw.yaml", "points", "rk4");
BENCHMARK_CAPTURE(stepScene, default_rolling_rk4, "rattleback.yaml", "rolling", "rk4");
BENCHMARK_CAPTURE(stepScene, default_rolling_symplectic, "rattleback.yaml", "rolling",
                  "symplectic");
BENCHMARK_CAPTURE(stepScene, ellipsoid_rolling_rk4, "kane-levinson.yaml", "rolling", "rk4");

// Preparing another run of a compiled body (aim: ≤ 0.05 ms): a copy of the per-run value
// (the body is shared, not copied) and its initial state.
void prepareRun(benchmark::State& state, const char* scene) {
  auto loaded = tasks::loadScene(std::string(RATTLEBACK_SOURCE_DIR "/scenes/") + scene, {});
  if (!loaded) {
    state.SkipWithError(loaded.error().text().c_str());
    return;
  }
  const sim::Model& m = loaded->model;
  double spin = 1;
  for (auto _ : state) {
    sim::Model run = m;
    run.initial.spin = spin;
    sim::State s = sim::initialState(run);
    benchmark::DoNotOptimize(s);
    spin = -spin;
  }
  const sim::GridCensus census = sim::censusOf(*m.body);  // one walk of the grid
  state.SetLabel(std::to_string(census.bottom + census.top) + " surface points shared");
}

// What a sweep does for each run besides integrating (aim: ≤ 0.1 ms): build its scene from
// the base with the axes' values put in, make the run of the shared body, start the rollout,
// and take the final sample. The body is compiled once, outside the loop, as the sweep does.
void sweepRowOverhead(benchmark::State& state) {
  const std::string path = "/tmp/rattleback-bench-sweep.yaml";
  std::ofstream(path) << "base: " RATTLEBACK_SOURCE_DIR "/scenes/rattleback.yaml\n"
                      << "vary:\n  initial.spin: {from: -10, to: 10, count: 41}\n"
                      << "  contact.air_drag: [0.0, 5.9e-6, 5.9e-5]\n";
  auto sweep = scene::loadSweep(path);
  std::remove(path.c_str());
  if (!sweep) {
    state.SkipWithError(sweep.error().text().c_str());
    return;
  }
  auto scenes = scene::SweepScenes::open(sweep.value());
  auto first = scenes->scene(0);
  auto body = sim::compileBody(first->spec);
  std::int64_t row = 0;
  for (auto _ : state) {
    auto loaded = scenes->scene(row);
    auto model = sim::compileRun(loaded->spec, body.value());
    sim::Rollout rollout(std::move(model).value());
    benchmark::DoNotOptimize(rollout.sampleAt(0));
    row = (row + 1) % sweep->rows();
  }
}

}  // namespace

BENCHMARK(sweepRowOverhead)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(prepareRun, default_body, "rattleback.yaml");
BENCHMARK_CAPTURE(prepareRun, seed_body, "seed-flip-ccw.yaml");

BENCHMARK_MAIN();

// Shared helpers for the tests: inline scenes parsed by the real loader, compiled by the
// real compile(), and short runs.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "media/video_plan.hpp"
#include "scene/loader.hpp"
#include "sim/compile.hpp"
#include "sim/initial.hpp"
#include "sim/rollout.hpp"
#include "sim/step.hpp"
#include "sim/telemetry.hpp"

namespace testing_support {

/// The seed report's body (seed §3.1–3.3), lengths in cm.
inline const char* kSeedScene = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 4, p: 3, q: 0, s: 0.15, top: 2}
  dents: {scale: 0.375, at: [1.04, 9.23], inset: 0.1}
  grid: {dx: 0.52, dy: 1.42, dz: 0.2}
  mass: 0.5
contact: {model: points, stiffness: 2.0e4, damping: 20, friction: 0.3, friction_law: coulomb}
initial: {spin: 0.0, tilt: [0.0, 0.0]}
simulation: {integrator: symplectic, dt: 1.0e-5, duration: 1.0}
video: {fps: 25}
)";

/// The stable default body (docs/scenes.md "Shipped scenes": a=1, p=0.5, s=0.03, top=0.5, dents
/// 0.45 at (0.73, 4.50) cm).
inline const char* kStableScene = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}
  dents: {scale: 0.45, at: [0.73, 4.50], inset: 0.1}
  grid: {dx: 0.1, dy: 0.2, dz: 0.005}
  mass: 0.059
contact: {model: points, stiffness: 2.0e4, damping: 4, friction: 0.5, friction_law: regularized}
initial: {spin: -5.0, tilt: [0.5, 0.5]}
simulation: {integrator: symplectic, dt: 2.0e-5, duration: 1.0}
video: {fps: 25}
)";

/// The default body (scenes/rattleback.yaml) rolling without drag: it reverses at 2.33 s.
/// (Rolling ignores the grid: any spacing gives the same run.)
inline const char* kRolling = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}
  dents: {scale: 0.45, at: [0.73, 4.50], inset: 0.1}
  grid: {dx: 0.05, dy: 0.05, dz: 0.05}
  mass: 0.059
contact: {model: rolling}
initial: {spin: -5.0, tilt: [0.5, 0.5]}
simulation: {integrator: rk4, dt: 1.0e-3, duration: 3.0}
)";

inline sim::SceneSpec parse(const std::string& yaml) {
  auto loaded = scene::loadString(yaml, "inline.yaml");
  if (!loaded) {
    ADD_FAILURE() << loaded.error().text();
    return {};
  }
  return loaded->spec;
}

/// The one line `render` or `still` prints for a scene (loading, compiling and planning its
/// video), or "" when it can be drawn.
inline std::string errorFor(const std::string& yaml) {
  auto loaded = scene::loadString(yaml, "inline.yaml");
  if (!loaded) return loaded.error().text();
  auto model = scene::loadModel(loaded.value());
  if (!model) return model.error().text();
  auto plan = media::planVideo(loaded.value(), model.value(), model->duration);
  if (!plan) return plan.error().text();
  return "";
}

/// The compiled model; a test failure (and an empty model) when the scene is refused.
inline sim::Model build(const sim::SceneSpec& spec) {
  auto compiled = sim::compile(spec);
  if (!compiled) {
    ADD_FAILURE() << compiled.error().text();
    return {};
  }
  return std::move(compiled).value();
}

/// kRolling's body and spin, with fixed steps (rk4, 1 ms) or adaptive ones (dopri5 at 1e-8).
inline sim::Model rollingModel(bool adaptive) {
  sim::SceneSpec spec = parse(kRolling);
  if (adaptive) {
    spec.simulation.integrator = "dopri5";
    spec.simulation.dt = sim::kUnset;
    spec.simulation.tolerance = 1e-8;
  }
  return build(spec);
}

/// Runs `model` from `start` to its end, handing `each` a sample every `period` seconds (at
/// exact times k·period, and the end).
template <typename Each>
sim::RunSummary runFrom(const sim::Model& model, const sim::State& start, double period,
                        Each each) {
  sim::Rollout rollout(model, start);
  return sim::sampleRun(rollout, 1 / period, each);
}

/// A run's summary and its samples.
struct Recorded {
  sim::RunSummary summary;
  std::vector<sim::Telemetry> samples;
};

/// Runs `model` from its initial state to its end, sampling every `sample_period` seconds.
inline Recorded record(const sim::Model& model, double sample_period = 1e-3) {
  Recorded out;
  sim::Rollout rollout(model);
  out.summary = sim::sampleRun(rollout, 1 / sample_period,
                               [&](const sim::Telemetry& t) { out.samples.push_back(t); });
  return out;
}

/// Largest rise of the total energy above its value at any earlier sample, J.
inline double largestRise(const std::vector<sim::Telemetry>& samples) {
  double lowest = samples.front().energy, rise = 0;
  for (const sim::Telemetry& t : samples) {
    rise = std::max(rise, t.energy - lowest);
    lowest = std::min(lowest, t.energy);
  }
  return rise;
}

}  // namespace testing_support

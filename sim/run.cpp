#include "sim/run.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "sim/step.hpp"

namespace sim {
namespace {

constexpr double kReversalFraction = 0.01;

// The spin n = ω·ẑ without building the full telemetry: ω_z = (R I⁻¹ Rᵀ L)_z.
double spinOf(const Model& model, const State& s) { return angularVelocity(model, s).z(); }

bool finite(const State& s) {
  return s.x_world.allFinite() && s.v_world.allFinite() && s.q.coeffs().allFinite() &&
         s.L_world.allFinite();
}

}  // namespace

RunSummary run(const Model& model, State& s, const RunOptions& options) {
  RunSummary summary;
  summary.first = telemetryOf(model, s);
  if (options.on_sample) options.on_sample(summary.first);
  const std::int64_t progress_every = std::max<std::int64_t>(1, model.steps / 100);
  const double initial_sign = std::copysign(1.0, model.initial.spin);
  double previous_spin = summary.first.spin;
  double last_crossing = 0;

  const auto start = std::chrono::steady_clock::now();
  while (s.step < model.steps) {
    step(model, s);
    // First reversal: n crosses zero against the initial spin's sign and goes on to reach
    // kReversalFraction of the initial spin the other way (a spin that only decays to rest
    // and dithers about zero is no reversal). Reported at the zero crossing, interpolated.
    if (!summary.first_reversal_s && model.initial.spin != 0) {
      const double spin = spinOf(model, s);
      if (spin * initial_sign < 0 && previous_spin * initial_sign >= 0)
        last_crossing = s.t - model.dt * spin / (spin - previous_spin);
      if (spin * initial_sign < -kReversalFraction * std::abs(model.initial.spin))
        summary.first_reversal_s = last_crossing;
      previous_spin = spin;
    }
    const bool sample_due = s.step % options.steps_per_sample == 0 || s.step == model.steps;
    if (sample_due) {
      if (!finite(s)) {
        std::ostringstream msg;
        msg << "the state became NaN or infinite at t = " << s.t << " s (step " << s.step
            << ")";
        summary.divergence = msg.str();
        break;
      }
      if (options.on_sample) options.on_sample(telemetryOf(model, s));
    }
    if (options.on_progress && s.step % progress_every == 0) options.on_progress(s.step);
  }
  summary.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.steps = s.step;
  summary.last = telemetryOf(model, s);
  return summary;
}

}  // namespace sim

#include "sim/run.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "sim/step.hpp"

namespace sim {
namespace {

constexpr double kReversalFraction = 0.01;

// Nothing in the model adds energy (no drive; friction, dampers and drag only remove it), so a
// rise of the total energy by more than this fraction of its initial value is no integration
// error of a usable step (the bench ladders show ≤ 1e-3 where a step is stable) but the start of
// an instability. Checked about once per simulated millisecond.
constexpr double kEnergyGrowthBound = 0.10;
constexpr double kEnergyCheckPeriod = 1e-3;  // s

// The spin n = ω·ẑ without building the full telemetry: ω_z = (R I⁻¹ Rᵀ L)_z.
double spinOf(const Model& model, const State& s) { return angularVelocity(model, s).z(); }

// The first quantity of the state that is NaN or infinite, or null when all are finite.
const char* nonFinite(const State& s) {
  if (!s.x_world.allFinite()) return "the position of the centre of mass";
  if (!s.v_world.allFinite()) return "the velocity of the centre of mass";
  if (!s.q.coeffs().allFinite()) return "the orientation";
  if (!s.L_world.allFinite()) return "the angular momentum";
  return nullptr;
}

}  // namespace

RunSummary run(const Model& model, State& s, const RunOptions& options) {
  RunSummary summary;
  summary.first = telemetryOf(model, s);
  if (options.on_sample) options.on_sample(summary.first);
  const std::int64_t progress_every = std::max<std::int64_t>(1, model.steps / 100);
  // The sign of the spin n = ω·ẑ at the start (opposite to initial.spin when upside down).
  const double initial_sign = std::copysign(1.0, summary.first.spin);
  double previous_spin = summary.first.spin;
  double last_crossing = 0;
  const double initial_energy = summary.first.energy;
  const double energy_bound =
      initial_energy + kEnergyGrowthBound * std::abs(initial_energy) + 1e-12;
  const std::int64_t check_every =
      std::max<std::int64_t>(1, std::llround(kEnergyCheckPeriod / model.dt));

  const auto start = std::chrono::steady_clock::now();
  while (s.step < model.steps) {
    step(model, s);
    // First reversal: n crosses zero against the initial spin's sign and goes on to reach
    // kReversalFraction of the initial spin the other way (a spin that only decays to rest
    // and dithers about zero is no reversal). Reported at the zero crossing, interpolated.
    if (!summary.first_reversal_s && summary.first.spin != 0) {
      const double spin = spinOf(model, s);
      if (spin * initial_sign < 0 && previous_spin * initial_sign >= 0)
        last_crossing = s.t - model.dt * spin / (spin - previous_spin);
      if (spin * initial_sign < -kReversalFraction * std::abs(summary.first.spin))
        summary.first_reversal_s = last_crossing;
      previous_spin = spin;
    }
    const bool sample_due = s.step % options.steps_per_sample == 0 || s.step == model.steps;
    const bool check_due = s.step % check_every == 0;
    if (sample_due || check_due) {
      if (const char* quantity = nonFinite(s)) {
        std::ostringstream msg;
        msg << quantity << " became NaN or infinite at t = " << s.t << " s (step " << s.step
            << "); try a smaller simulation.dt";
        summary.divergence = msg.str();
        break;
      }
      const Telemetry now = telemetryOf(model, s);
      if (!(now.energy <= energy_bound)) {
        std::ostringstream msg;
        msg << "the energy rose from " << initial_energy << " J to " << now.energy << " J ("
            << std::showpos << 100 * (now.energy - initial_energy) / std::abs(initial_energy)
            << std::noshowpos << " %, beyond the " << 100 * kEnergyGrowthBound
            << " % that nothing in the model can supply) at t = " << s.t << " s (step "
            << s.step << "); try a smaller simulation.dt";
        summary.divergence = msg.str();
        break;
      }
      // Rolling is a smooth surface rolling on the floor; tipped onto the edge of its flat top
      // the body pivots on an edge, which that model cannot describe.
      if (model.contact.model == ContactModel::Rolling &&
          model.body.surface.lowestOnRim(-now.orientation.toRotationMatrix().row(2).transpose())) {
        std::ostringstream msg;
        msg << "the body tipped onto the edge of its top (tilt " << now.tilt_deg
            << " degrees) at t = " << s.t << " s (step " << s.step
            << "), where rolling on its smooth bottom no longer describes it; use "
               "contact.model smooth or points";
        summary.divergence = msg.str();
        break;
      }
      if (sample_due && options.on_sample) options.on_sample(now);
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

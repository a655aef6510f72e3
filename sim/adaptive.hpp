// Adaptive steps with error control and dense output (docs/physics.md P3: a tolerance instead
// of a step). The method is Dormand–Prince 5(4) as Boost.Odeint implements it
// (runge_kutta_dopri5 in a dense-output stepper): a well-kept, header-only library whose
// stepper takes our state as a plain array, with the step-size controller and the fourth-order
// continuous extension of the method built in. (SUNDIALS ARKODE offers the same pair but wants
// its own vector type, a context and a C callback per evaluation; for 13 unknowns Odeint is
// the lighter fit.)
#pragma once

#include <cstdint>
#include <memory>

#include "sim/model.hpp"

namespace sim {

/// Drives one run's adaptive steps. The state is integrated in the body's own units (length ℓ,
/// the body's size; time τ = √(ℓ/g); angular momentum I_max/τ), so that one `tolerance` means
/// the same for every component: Odeint's error control with abs = rel = tolerance.
class AdaptiveStepper {
 public:
  AdaptiveStepper(const Model& model, const State& start);
  ~AdaptiveStepper();
  /// An independent copy: the same state, step size and dense output (Rollout's copy).
  AdaptiveStepper(const AdaptiveStepper& other);
  AdaptiveStepper& operator=(const AdaptiveStepper&) = delete;

  /// Takes one accepted step; returns the state at its end (t and step set; the quaternion
  /// as integrated, not renormalised; under rolling, normalised and the state on the
  /// constraint).
  State step(std::int64_t step_index);
  /// The dense output inside the last step, t within it.
  State at(double t) const;
  /// The spin n = ω·ẑ (rad/s) of at(t)'s state, formed from the integrated variables alone.
  double spinAt(double t) const;
  std::int64_t evaluations() const;
  /// Whether the states it hands out are on the rolling constraint already (its model rolls:
  /// step() and at() put them there).
  bool keepsRolling() const;
  /// Steps rejected by error control so far.
  std::int64_t rejected(std::int64_t accepted) const;

  struct Impl;  ///< the Odeint stepper over the state's layout (adaptive.cpp)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace sim

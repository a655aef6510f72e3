// The door to the integrators (docs/physics.md P3): everything that differs between
// simulation.integrator euler, symplectic, rk4, dopri5 and dop853 is asked here, and answered
// by one row per method in sim/integrator.cpp, as the contact models are in
// sim/contact_model.hpp. A fixed-step method's step lives in that file beside its row; the
// adaptive ones are driven by sim/adaptive.cpp, which makes each one's stepper. A new method
// adds its enum value and name (sim/model.hpp) and its row (and, if adaptive, its stepper).
#pragma once

#include <Eigen/Dense>
#include <string_view>

#include "sim/model.hpp"

namespace sim {

/// What an integrator is, one row per method (integratorTraits).
struct IntegratorTraits {
  /// One fixed step of h (s), leaving s.t and s.step as they were; null for an adaptive
  /// method, whose steps error control chooses (sim/adaptive.hpp).
  void (*step)(const Model& model, State& s, double h) = nullptr;
  /// A fixed method's order: its global error falls as h^order (`simulate --check`'s
  /// Richardson estimate, tasks/check.cpp). An adaptive method's: its solution's (5 for
  /// Dormand–Prince 5(4), 8 for 8(5,3)), so that a tolerance a hundredth as large costs about
  /// 100^(1/order) times the steps.
  int order = 0;
  /// One step's matrix on y′ = J y, given hJ: its spectral radius says whether a fixed step
  /// keeps a floor spring's energy (sim/stability.hpp). Null for an adaptive method.
  Eigen::Matrix2d (*linear_step)(const Eigen::Matrix2d& hJ) = nullptr;
  /// Refused where the body rolls without slipping (contact.model rolling and auto): the
  /// constraint is non-holonomic and the method loses energy there (docs/physics.md P3).
  bool refused_when_rolling = false;
  /// What to try when a run stops on energy from nowhere, where a smaller step is not the
  /// way out; empty: a smaller simulation.dt or simulation.tolerance.
  std::string_view advice_on_stop;
  /// In `bench`'s ladders when no integrator is named (dop853 only when asked for: dopri5's
  /// ladder already covers the adaptive rows).
  bool benched_by_default = true;
};

/// The row of `integrator` (one switch: the table of the methods).
IntegratorTraits integratorTraits(Integrator integrator);

/// Whether the method chooses its own steps (takes simulation.tolerance, not dt).
inline bool isAdaptive(Integrator integrator) {
  return integratorTraits(integrator).step == nullptr;
}

}  // namespace sim

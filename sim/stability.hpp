// How large a step the contact stiffness allows (docs/physics.md P3: refuse a step the
// contact makes unstable and name the largest stable one).
#pragma once

#include "sim/model.hpp"

namespace sim {

struct ContactStability {
  double omega = 0;         ///< stiffest contact mode of the rest pose nearest the start, rad/s
  double zeta = 0;          ///< its damping ratio
  double largest_step = 0;  ///< s: the linear limit at rest (below)
  /// s: the largest step a run is given, kRunMargin of the linear limit. Rocking, landing and
  /// sliding load the springs beyond the rest pose: at 0.95 of the limit an undamped k 1e6 N/m
  /// floor gained 19 % of its energy with rk4 (0.8 ran), 10 % with symplectic by 0.6 s (0.6
  /// ran), and a 3 cm drop onto k 1e8 N/m by 0.03 s (0.6 ran).
  double run_step = 0;
};

/// The fraction of the linear limit a run's step may be (ContactStability::run_step).
inline constexpr double kRunMargin = 0.5;

/// Linearises the floor springs about the rest pose nearest the initial one (upright, or
/// upside down on the top when the start is upside down): K = Σ k J Jᵀ with
/// J = (ẑ, r × ẑ) for each point in contact, against the rigid body's mass matrix
/// diag(M, M, M, I); the stiffest mode is ω² = λ_max(M⁻¹K), and the dampers C = (c/k) K give
/// it the ratio ζ = c ω / (2k). The largest step is the largest h at which that mode's energy
/// grows by less than 2× over the whole run under model.integrator: ρ(h)^(2T/h) ≤ 2 with
/// ρ the spectral radius of one step (for symplectic and rk4 this is just below their
/// stability limits, about 2/ω and 2.8/ω; forward Euler always gains energy when ζ is small).
ContactStability contactStability(const Model& model);

/// Spectral radius of one step of size h of `integrator` on x'' + 2ζω x' + ω² x = 0.
double stepAmplification(Integrator integrator, double omega, double zeta, double h);

}  // namespace sim

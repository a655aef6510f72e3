// The initial state (docs/physics.md P5).
#pragma once

#include <optional>
#include <string>

#include "sim/model.hpp"
#include "util/result.hpp"

namespace sim {

/// R = Rx(tilt_x)·Ry(tilt_y); ω = R (w_x, w_y, spin); the CM at the height where the floor
/// carries the weight (static penetration); the CM velocity v = −ω × r_low so that the lowest
/// point does not slide, or the given initial velocity (not under rolling, whose constraint
/// fixes it: checkInitialVelocity).
State initialState(const Model& model);

/// The initial orientation, body → world: Rx(tilt_x)·Ry(tilt_y) (docs/physics.md P5).
Eigen::Matrix3d initialRotation(const Initial& init);

/// The CM velocity, world axes, m/s, at which the lowest point of the smooth surface does not
/// slide, for orientation R and ω = w_world (rad/s): v = −ω × r_low.
Eigen::Vector3d noSlipVelocity(const Model& model, const Eigen::Matrix3d& R,
                               const Eigen::Vector3d& w_world);

/// How closely a given initial velocity must agree with rolling's v = −ω × r_low: this fraction
/// of that velocity's size, plus kVelocityFloor. A velocity written by hand from ω and the CM
/// height that `analyze` prints to four digits is off by up to 5e-4 of it; rolling integrates
/// no velocity of its own (it follows from ω), so what is accepted is replaced by the exact one
/// and the difference never enters the run.
inline constexpr double kVelocityAgreement = 1e-3;
/// m/s: the agreement's floor, for a body given no ω (then v must be 0): a micrometre a second,
/// the width of no slip the model could tell from rolling (contact.slip_velocity is 1e-3 m/s).
inline constexpr double kVelocityFloor = 1e-6;

/// Under contact.model rolling, a given initial.velocity that the constraint contradicts (the
/// contact point would slide): the error, naming the velocity rolling needs. Nothing otherwise.
std::optional<rb::Error> checkInitialVelocity(const Model& model);

/// The error for `key` when velocity v (m/s, world) slides the lowest point, for orientation R
/// and ω = w_world (rad/s), beyond kVelocityAgreement; nothing when it agrees.
std::optional<rb::Error> rollingDisagreement(const Model& model, const Eigen::Matrix3d& R,
                                             const Eigen::Vector3d& w_world,
                                             const Eigen::Vector3d& v, const std::string& key);

/// The largest spin n = ω·ẑ (rad/s) the start's kinetic energy K₀ could become:
/// √(2 K₀ ẑᵀ I_world⁻¹ ẑ), since ½ ωᵀ I ω ≥ ½ n² / (ẑᵀ I⁻¹ ẑ) for any ω with ω·ẑ = n (a fall
/// from a tilt aside). A body struck at rest (a tap) spins up to at most this.
double spinReach(const Model& model);

/// Parts of a state to put in mid-run (Python's Simulation.set_state), each replacing the
/// state's own; SI units.
struct StateParts {
  std::optional<Eigen::Vector3d> x_world;  ///< CM, world axes, m
  std::optional<Eigen::Quaterniond> q;     ///< body → world (normalised here)
  std::optional<Eigen::Vector3d> v_world;  ///< CM velocity, world axes, m/s
  std::optional<Eigen::Vector3d> w_body;   ///< ω, body axes, rad/s
};

/// `s` with `parts` put in. ω in body axes is kept when only the attitude is given (L = R I ω).
/// Under contact.model rolling a velocity that would slide the contact point is refused as
/// initial.velocity is (the error's key: "velocity"); the constraint then fixes the height and
/// velocity (Rollout::setState).
rb::Result<State> withParts(const Model& model, State s, const StateParts& parts);

/// CM height (m) at which the floor's spring force on the body in orientation R balances
/// its weight.
double restingHeight(const Model& model, const Eigen::Matrix3d& R);

}  // namespace sim

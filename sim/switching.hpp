// contact.model auto (docs/physics.md P4): roll while rolling holds, slide when it does not. The
// Rollout runs one of two models of the same run at a time — rolling without slipping, or the
// smooth penalty contact with regularised friction — and this file says when and how it changes:
//  - rolling → smooth when the force the rolling constraint needs leaves what the floor can
//    give: the friction it needs exceeds μN, or N ≤ 0 (lift-off), or the lowest point reaches
//    the rim of the flat top. The time is located inside the step on the margins below.
//  - smooth → rolling when the contact point's slip speed has stayed below the regularisation
//    width ε (friction in its sticking branch) for kStickTime with N > 0, and rolling, tried at
//    that state, would need at most kRollFriction of μN.
// No switch adds energy. Under auto the rolling constraint holds the lowest point at the depth
// the spring had (Model::rolling_depth; at rest, M g / k), and that spring's ½ k δ² stays in the
// energy: so the switch to smooth changes no position, velocity or energy term (the spring
// starts at the compression rolling held, the contact point at rest, so its damper is idle).
// The switch back removes the contact point's remaining velocity by a plastic impulse at the
// contact, which can only take energy out (½ uᵀ K⁻¹ u, u below ε).
#pragma once

#include "sim/model.hpp"

namespace sim {

/// How long the slip must stay below ε before rolling resumes, s: a few contact periods
/// (2π√(M/k) = 11 ms for the default body), so a contact that only passes through zero slip
/// while it skids does not count.
inline constexpr double kStickTime = 0.05;
/// Rolling resumes only if it needs at most this fraction of μN at the state it would start
/// from (so it does not hand back at once: hysteresis).
inline constexpr double kRollFriction = 0.9;

/// The run's model for one mode: contact.model rolling or smooth, with rolling's depth.
Model modeOf(const Model& model, ContactModel mode, double rolling_depth);

/// How far rolling is from failing at a state (each > 0 while it holds): the friction it needs
/// below μN (N), the normal force (N), and the lowest point's height below the rim (m; +∞ for
/// the ellipsoid).
struct RollingMargins {
  double friction = 0, normal = 0, rim = 0;
  bool hold() const { return friction > 0 && normal > 0 && rim > 0; }
};
RollingMargins rollingMargins(const Model& rolling, const State& s);

/// The smooth contact at a state: the lowest point's depth below the floor (m, > 0 when
/// touching), its slip speed along the floor (m/s) and the spring's normal force (N).
struct SmoothContactState {
  double depth = 0, slip = 0, normal = 0;
};
SmoothContactState smoothContactState(const Model& smooth, const State& s);

/// Puts a smooth-contact state onto rolling: a plastic impulse P at the contact point r makes
/// its velocity u zero (K P = −u, K = 1/M − [r]ₓ I⁻¹ [r]ₓ), which changes the kinetic energy by
/// −½ uᵀ K⁻¹ u ≤ 0. Position and orientation are kept.
void projectOntoRolling(const Model& smooth, State& s);

/// The step for the smooth model inside a fixed step of auto, s: a fiftieth of the contact
/// period 2π√(M/k) (frictionless bounces then keep their energy to 1% with rk4), and a fifth
/// of the friction's relaxation time ε/(μ g) (the regularised friction acts as a damper of
/// rate μ g/ε on the slip: 0.2 ms for the default body, so 41 µs steps).
double smoothStep(const Model& model);

}  // namespace sim

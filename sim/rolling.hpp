// Rolling without slipping on the floor: the classic nonholonomic rattleback model (Walker
// 1896; Bondi 1986; Kane & Levinson 1982), docs/physics.md P4. The body's smooth
// surface always touches the floor at its lowest point, which does not slide; the contact
// force is whatever the constraint needs.
#pragma once

#include "sim/contact.hpp"
#include "sim/model.hpp"

namespace sim {

struct RollingMotion {
  Eigen::Vector3d r_world;      ///< CM → contact point, m
  Eigen::Vector3d w_dot_body;   ///< angular acceleration, body axes, rad/s²
  Eigen::Vector3d force_world;  ///< the floor's force on the body, N
};

/// With r the CM → contact vector and the no-slip constraint v = −ω × r:
///   [I + M(|r|² 1 − r rᵀ)] ω̇ = −ω × Iω − M r × (ω × ṙ) + M g r × ẑ − σω,
///   ṙ = ω × r + R ṙ_body,  F = M (v̇ + g ẑ),  v̇ = −ω̇ × r − ω × ṙ,
/// where ṙ_body is how the contact point moves over the surface as the body turns
/// (derived from Newton and Euler about the CM with the constraint differentiated once).
RollingMotion rollingMotion(const Model& model, const Kinematics& k);

/// The floor's load under rolling: the force the constraint needs at its contact point,
/// r_contact_world (CM → contact, world axes, m, set here); one contact. Under auto the
/// spring's compression that rolling holds (model.rolling_depth) keeps its ½ k δ² as elastic
/// energy.
ContactLoad rollingContact(const Model& model, const Kinematics& k,
                           Eigen::Vector3d& r_contact_world);

/// The total energy of a rolling state, J, with ω = w_world (rad/s, world axes) at hand: the
/// body on the floor and no spring but auto's held one, so no contact solve is needed.
double rollingEnergy(const Model& model, const State& s, const Eigen::Vector3d& w_world);

/// What an adaptive run integrates under rolling: the constraint fixes the CM's height and
/// velocity, so the state reduces to the CM's place on the floor, the attitude and ω in body
/// axes (where ω̇ comes straight from the equations above, with no force and no momentum).
struct RollingRates {
  Eigen::Vector2d dxy;         ///< the CM's velocity along the floor, world x and y, m/s
  Eigen::Vector4d dq;          ///< quaternion coefficients (x, y, z, w), 1/s
  Eigen::Vector3d w_dot_body;  ///< rad/s²
};
/// For the rotation of the quaternion q (body → world), of any length (the rates are those of
/// q/|q|, as the integrator holds |q| = 1 only to its tolerance), and ω in body axes.
RollingRates rollingRates(const Model& model, const Eigen::Quaterniond& q,
                          const Eigen::Vector3d& w_body);
/// Puts the state back on the constraint: contact point on the floor, or model.rolling_depth
/// below it (z_cm = −r_z − depth), and not sliding (v = −ω × r).
void enforceRolling(const Model& model, State& s);
/// The same with the rotation of s.q and ω (world axes) already at hand.
void enforceRolling(const Model& model, State& s, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& w_world);

}  // namespace sim

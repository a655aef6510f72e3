// Time stepping (docs/physics.md P3): the loads, the rates of the state, and a fixed step of
// the model's integrator (the methods themselves are behind sim/integrator.hpp).
#pragma once

#include "sim/contact.hpp"
#include "sim/model.hpp"

namespace sim {

/// Everything acting on the body at one instant: floor contact, gravity, air drag.
struct Load {
  ContactLoad contact;
  Eigen::Vector3d force_world;                                ///< total, N
  Eigen::Vector3d torque_world;                               ///< total about the CM, N m
  Eigen::Vector3d r_contact_world = Eigen::Vector3d::Zero();  ///< rolling: CM → contact, m
};

/// Loads at a given instant: contact (penalty, or the rolling constraint's force) + gravity
/// −M g ẑ + air torque −σω.
Load loadsOn(const Model& model, const Kinematics& k);

/// Time derivative of the state: ẋ = v (rolling: v = −ω × r), v̇ = F/M, q̇ = ½ (0, ω) ⊗ q,
/// L̇ = τ.
struct Rates {
  Eigen::Vector3d dx, dv;
  Eigen::Vector4d dq;  ///< quaternion coefficients (x, y, z, w)
  Eigen::Vector3d dL;
};
Rates ratesOf(const Model& model, const State& s);

/// s + h · rates, with the quaternion renormalised so that rotations stay rotations.
State advanced(const State& s, const Rates& r, double h);

/// Advances the state by h with model.integrator's fixed-step method (rolling: back on the
/// constraint after), leaving s.t and s.step as they were.
void advanceBy(const Model& model, State& s, double h);

/// Advances the state by one step of model.dt with model.integrator (a fixed-step method;
/// adaptive ones are driven by the Rollout).
void step(const Model& model, State& s);

}  // namespace sim

// Time stepping (SPEC "Integrators"): forward Euler (the seed's, §3.4), semi-implicit
// (symplectic) Euler with the exact exponential map for the rotation, and classical RK4.
#pragma once

#include "sim/contact.hpp"
#include "sim/model.hpp"

namespace sim {

/// Everything acting on the body at one instant: floor contact, gravity, air drag.
struct Load {
  ContactLoad contact;
  Eigen::Vector3d force_world;   ///< total, N
  Eigen::Vector3d torque_world;  ///< total about the CM, N m
  Eigen::Vector3d r_contact_world = Eigen::Vector3d::Zero();  ///< rolling: CM → contact, m
};

/// Loads at a given instant: contact (penalty, or the rolling constraint's force) + gravity
/// −M g ẑ + air torque −σω.
Load loadsOn(const Model& model, const Kinematics& k);

/// Advances the state by one step of model.dt with model.integrator.
void step(const Model& model, State& s);

}  // namespace sim

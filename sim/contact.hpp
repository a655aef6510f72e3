// Floor contact forces of the penalty models (docs/physics.md P4; seed §3.3, eq. 31).
#pragma once

#include <Eigen/Dense>

#include "sim/model.hpp"

namespace sim {

/// Pose and velocity of the body at one instant, with the rotation matrix evaluated once.
struct Kinematics {
  Eigen::Matrix3d R;        ///< body → world
  Eigen::Vector3d x_world;  ///< CM position, m
  Eigen::Vector3d v_world;  ///< CM velocity, m/s
  Eigen::Vector3d w_world;  ///< angular velocity, rad/s
  Eigen::Vector3d w_body;   ///< the same in body axes, rad/s
};

Kinematics kinematicsOf(const Model& model, const State& s);

/// Sum of the floor's forces on the body, about its CM.
struct ContactLoad {
  Eigen::Vector3d force_world = Eigen::Vector3d::Zero();   ///< N
  Eigen::Vector3d torque_world = Eigen::Vector3d::Zero();  ///< about the CM, N m
  double elastic_energy = 0;                               ///< Σ ½ k depth², J
  double normal_force = 0;                                 ///< Σ N, N
  int contacts = 0;                                        ///< points below the floor
};

/// Penalty contact (seed eq. 31): a point below the floor (depth d = −z > 0) gets the normal
/// force N = max(0, k d − c v_n) and friction F_t = −μ N v_t/|v_t| (coulomb) or
/// −μ N v_t / sqrt(|v_t|² + ε²) (regularized).
/// contact.model points: every bottom-surface grid point below the floor (only those are
/// visited), and the top's when its bounding box reaches the floor.
ContactLoad pointContact(const Model& model, const Kinematics& k);
/// contact.model smooth: the single lowest point of the smooth surface.
ContactLoad smoothContact(const Model& model, const Kinematics& k);

}  // namespace sim

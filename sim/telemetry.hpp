// What a run reports at each sample (docs/commands.md "The telemetry CSV").
#pragma once

#include <Eigen/Geometry>

#include "sim/model.hpp"

namespace sim {

struct Telemetry {
  double t = 0;          ///< s
  double spin = 0;       ///< n = ω·ẑ, rad/s (+ counter-clockwise from above)
  double kinetic = 0;    ///< ½ M v² + ½ ω·L, J
  double potential = 0;  ///< M g z_cm, J (zero with the CM on the floor)
  double elastic = 0;    ///< Σ ½ k depth², J
  double energy = 0;     ///< kinetic + potential + elastic, J
  double tilt_deg = 0;   ///< angle between the body z axis and the vertical, degrees
  Eigen::Vector3d x_world = Eigen::Vector3d::Zero();                ///< CM, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → world
  Eigen::Vector3d w_world = Eigen::Vector3d::Zero();                ///< ω, rad/s
  Eigen::Vector3d L_world = Eigen::Vector3d::Zero();  ///< angular momentum about the CM
  int contacts = 0;                                   ///< points below the floor
  ContactModel mode = ContactModel::Points;  ///< the contact model integrated (auto: its mode)
  double normal_force = 0;                   ///< N
  /// N: the floor's force along the floor, |F_t| (not a CSV column: under rolling the runs'
  /// check of μN, tasks::simulate).
  double friction_force = 0;
};

Telemetry telemetryOf(const Model& model, const State& s);

}  // namespace sim

// What a run reports at each sample (docs/commands.md "The telemetry CSV").
#pragma once

#include <Eigen/Geometry>
#include <array>

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

/// Every double of a sample, each once, in a fixed order: what copies a sample field by field
/// (Python's pickle of a run) loops over. A double added to Telemetry is added here, beside it;
/// the whole numbers (contacts, mode) are the copier's.
inline constexpr std::size_t kTelemetryDoubles = 22;
inline std::array<double*, kTelemetryDoubles> doublesOf(Telemetry& s) {
  return {&s.t,
          &s.spin,
          &s.kinetic,
          &s.potential,
          &s.elastic,
          &s.energy,
          &s.tilt_deg,
          &s.x_world.x(),
          &s.x_world.y(),
          &s.x_world.z(),
          &s.orientation.w(),
          &s.orientation.x(),
          &s.orientation.y(),
          &s.orientation.z(),
          &s.w_world.x(),
          &s.w_world.y(),
          &s.w_world.z(),
          &s.L_world.x(),
          &s.L_world.y(),
          &s.L_world.z(),
          &s.normal_force,
          &s.friction_force};
}

Telemetry telemetryOf(const Model& model, const State& s);

}  // namespace sim

// The immutable model built once from a scene (SI units throughout) and the state a
// step advances. Frames: "world" has z up with the floor at z = 0; "body" is the body's
// geometric axes (x short, y long, z up) with its origin moved to the centre of mass.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/body.hpp"
#include "sim/surface.hpp"

namespace sim {

enum class ContactModel { Points, Smooth, Rolling };
enum class FrictionLaw { Coulomb, Regularized };
enum class Integrator { Euler, Symplectic, Rk4 };

/// Contact points as structure-of-arrays, body frame (m), for a tight per-step loop.
struct ContactPoints {
  std::vector<double> x, y, z;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  ///< bounding box

  std::size_t size() const { return x.size(); }
  Eigen::Vector3d operator[](std::size_t i) const { return {x[i], y[i], z[i]}; }
  void push_back(const Eigen::Vector3d& r) {
    lo = size() == 0 ? r : Eigen::Vector3d(lo.cwiseMin(r));
    hi = size() == 0 ? r : Eigen::Vector3d(hi.cwiseMax(r));
    x.push_back(r.x());
    y.push_back(r.y());
    z.push_back(r.z());
  }
  /// A lower bound on the height of every point above the floor for the pose (R, z_cm): the
  /// lowest corner of the bounding box. When it is ≥ 0 no point can touch.
  double lowestBound(const Eigen::Matrix3d& R, double z_cm) const {
    double z = z_cm;
    for (int j = 0; j < 3; ++j) z += std::min(R(2, j) * lo[j], R(2, j) * hi[j]);
    return z;
  }
};

/// Rigid body: mass properties about the CM and the points that can touch the floor.
struct Body {
  double mass = 0;                     ///< kg
  Eigen::Matrix3d inertia;             ///< about the CM, body axes, kg m²
  Eigen::Matrix3d inertia_inv;         ///< its inverse, 1/(kg m²)
  Surface surface;                     ///< the smooth surface, geometric frame, m
  Eigen::Vector3d com_geometric;       ///< CM in the geometric frame, m
  MassProperties mass_properties;      ///< as computed from the grid (geometric frame)
  Grid grid;                           ///< the point grid's spacing, m
  ContactPoints bottom;                ///< bottom-surface points, body frame, m (blue)
  /// Top-surface points, body frame, m (red). They touch the floor only when the body lies
  /// on its side or upside down (the `points` model checks them then).
  ContactPoints top;
};

/// Floor contact (SPEC "Contact and friction"): normal force max(0, k·depth − c·v_n) and
/// friction μN against the sliding velocity, per contact point.
struct Contact {
  ContactModel model = ContactModel::Points;
  double stiffness = 0;      ///< k, N/m per point
  double damping = 0;        ///< c, N s/m per point
  double friction = 0;       ///< μ
  FrictionLaw law = FrictionLaw::Regularized;
  double slip_velocity = 0;  ///< ε, m/s: F_t = −μN v_t / sqrt(|v_t|² + ε²)
  double air_drag = 0;       ///< σ, N m s: torque −σω
};

/// Initial condition (SPEC "Initial state").
struct Initial {
  double spin = 0;         ///< rad/s about the body z axis, + counter-clockwise from above
  double tilt_x = 0;       ///< rad, about body x
  double tilt_y = 0;       ///< rad, then about the new body y
  double height = 0;       ///< m, lowest point above the floor at release (0: resting on it)
};

/// Video timing and framing (SPEC "Rendering and video"); the renderer reads these.
struct Video {
  int fps = 30;
  int width = 1280, height = 720;   ///< pixels
  std::string view = "oblique";     ///< oblique | above | front | side | follow
  double playback = 1;              ///< video seconds per simulated second
  std::int64_t steps_per_frame = 1; ///< whole steps of dt per video frame
  std::int64_t frames = 0;          ///< round(duration × playback × fps)
};

struct Model {
  Body body;
  Video video;
  Contact contact;
  double gravity = 9.81;   ///< m/s², along −z
  Integrator integrator = Integrator::Symplectic;
  double dt = 0;           ///< s
  std::int64_t steps = 0;  ///< whole steps in the run: round(duration / dt)
  Initial initial;
  double length_unit = 1;  ///< m per length unit of the scene file (for reports)
};

/// The changing data. Time is derived from the step count: t = step · dt.
struct State {
  Eigen::Vector3d x_world = Eigen::Vector3d::Zero();  ///< CM position, m
  Eigen::Vector3d v_world = Eigen::Vector3d::Zero();  ///< CM velocity, m/s
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  ///< body → world rotation
  Eigen::Vector3d L_world = Eigen::Vector3d::Zero();  ///< angular momentum about the CM, kg m²/s
  double t = 0;                                       ///< s
  std::int64_t step = 0;
};

/// The point of the body's smooth surface lowest along `down_body` (a unit vector in body
/// axes), relative to the CM, body axes, m: where the `smooth` and `rolling` models touch.
inline Eigen::Vector3d lowestSurfacePoint(const Body& body, const Eigen::Vector3d& down_body) {
  return body.surface.lowestPoint(down_body) - body.com_geometric;
}

/// ω_world = R I⁻¹ Rᵀ L (rad/s).
Eigen::Vector3d angularVelocity(const Model& model, const State& s);

}  // namespace sim

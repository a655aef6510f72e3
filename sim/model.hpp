// What a run is made of, split as MuJoCo splits mjModel from mjData (SI units throughout):
//  - Body: immutable and shared, built once from a scene's body keys (points, mass
//    properties, surface and the constants derived from them); runs hold it by shared_ptr.
//  - Model: the small per-run value (the shared body, contact, integrator, step or tolerance,
//    duration, gravity, initial state). Copying it costs a shared_ptr copy.
//  - State: what a step advances.
// Frames: "world" has z up with the floor at z = 0; "body" is the body's geometric axes
// (x short, y long, z up) with its origin moved to the centre of mass.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sim/body.hpp"
#include "sim/surface.hpp"
#include "util/names.hpp"

namespace sim {

/// Auto: rolling while rolling holds, smooth while it does not (sim/switching.hpp).
enum class ContactModel { Points, Smooth, Rolling, Auto };
/// Where a body's mass properties come from (body.mass_properties).
enum class MassSource { Grid, Continuum };
enum class FrictionLaw { Coulomb, Regularized };
/// Fixed-step methods take simulation.dt; Dopri5 (adaptive, Dormand–Prince 5(4) with dense
/// output, from Boost.Odeint) and Dop853 (Dormand–Prince 8(5,3) with its seventh-order
/// interpolant, sim/dop853.hpp) take simulation.tolerance. What each is: sim/integrator.hpp.
enum class Integrator { Euler, Symplectic, Rk4, Dopri5, Dop853 };

/// Contact points as structure-of-arrays, body frame (m), for a tight per-step loop.
struct ContactPoints {
  std::vector<double> x, y, z;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();  ///< bounding box

  std::size_t size() const { return x.size(); }
  void reserve(std::size_t n) {
    x.reserve(n);
    y.reserve(n);
    z.reserve(n);
  }
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
  double mass = 0;                 ///< kg
  Eigen::Matrix3d inertia;         ///< about the CM, body axes, kg m²
  Eigen::Matrix3d inertia_inv;     ///< its inverse, 1/(kg m²)
  Surface surface;                 ///< the smooth surface, geometric frame, m
  Eigen::Vector3d com_geometric;   ///< CM in the geometric frame, m
  MassProperties mass_properties;  ///< geometric frame; from `mass_source`
  /// The paraboloid's: the grid's sums or the continuum's integrals (ellipsoid: the scene's).
  MassSource mass_source = MassSource::Continuum;
  bool mass_by_cubature = false;  ///< continuum: by cubature, not the closed form
  /// A mesh body: the scene gave its CM (body.center_of_mass), its inertia (body.inertia), or
  /// both, in place of the uniform solid's.
  bool com_given = false, inertia_given = false;
  Grid grid;                   ///< the point grid's spacing, m
  std::optional<Dents> dents;  ///< the dents cut from the top (paraboloid), m
  /// The share of the plain body's volume the dents remove (sim::dentsCutShare), worked out
  /// when first asked (tasks::dentsCutShare) and kept with the body: every run's warnings ask
  /// (two closed forms at each call had been 40 % of a short `rb.simulate`), and a sweep's
  /// bodies need not pay for it (a cubature each where the dents cut through the bottom: 6 % of
  /// the dents sweep). NaN until asked; −1 without dents. Two threads asking at once both store
  /// the same number.
  struct LazyShare {
    mutable std::atomic<double> value{std::numeric_limits<double>::quiet_NaN()};
    LazyShare() = default;
    LazyShare(const LazyShare& other) : value(other.value.load()) {}
    LazyShare& operator=(const LazyShare& other) {
      value.store(other.value.load());
      return *this;
    }
  } dents_cut_share;
  /// Contact points, only for contact.model points (the others touch the smooth surface, and
  /// building the default body's 244,212 made most of a short run's cost); the
  /// drawing walks the grid itself, thinned (tasks/drawn_points), and censusOf counts it.
  /// Bottom-surface points, body frame, m (blue).
  ContactPoints bottom;
  /// Top-surface points, body frame, m (red). They touch the floor only when the body lies
  /// on its side or upside down (the `points` model checks them then).
  ContactPoints top;
  /// Half-widths of the box about the CM that holds the body (Surface::boxLow/boxHigh), body
  /// frame, m: the body's own length scale, the same on any grid.
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();
};

/// Floor contact (docs/physics.md P4): normal force max(0, k·depth − c·v_n) and
/// friction μN against the sliding velocity, per contact point.
struct Contact {
  ContactModel model = ContactModel::Points;
  double stiffness = 0;  ///< k, N/m per point
  double damping = 0;    ///< c, N s/m per point
  double friction = 0;   ///< μ
  FrictionLaw law = FrictionLaw::Regularized;
  double slip_velocity = 0;  ///< ε, m/s: F_t = −μN v_t / sqrt(|v_t|² + ε²)
  double air_drag = 0;       ///< σ, N m s: torque −σω

  /// Whether the model keeps the energy exactly: rolling without slipping does no work and
  /// gravity is conservative, so without air drag the total is constant (Kane & Levinson
  /// 1982); any change is the integrator's error.
  bool conservesEnergy() const { return model == ContactModel::Rolling && air_drag == 0; }
};

/// Initial condition (docs/physics.md P5).
struct Initial {
  double spin = 0;    ///< rad/s about the body z axis, + counter-clockwise from above
  double tilt_x = 0;  ///< rad, about body x
  double tilt_y = 0;  ///< rad, then about the new body y
  double height = 0;  ///< m, lowest point above the floor at release (0: resting on it)
  /// rad/s about the body's x and y axes: with `spin`, ω in body axes is (w_x, w_y, spin).
  double w_x = 0, w_y = 0;
  /// The CM's velocity at release, world axes, m/s; none: the lowest point does not slide (or,
  /// released above the floor, the CM at rest). Under rolling it agrees with the constraint.
  std::optional<Eigen::Vector3d> velocity;

  /// ω at release, body axes, rad/s.
  Eigen::Vector3d angularVelocityBody() const { return {w_x, w_y, spin}; }
};

/// One run of a shared body: small, cheap to copy (docs/design.md "Data flow").
struct Model {
  std::shared_ptr<const Body> body;  ///< immutable, shared by every run of this body
  Contact contact;
  double gravity = 9.81;  ///< m/s², along −z
  Integrator integrator = Integrator::Symplectic;
  double dt = 0;         ///< s, fixed-step integrators (0 for adaptive ones)
  double tolerance = 0;  ///< adaptive: error per step relative to the body's scales (0: fixed)
  double duration = 0;   ///< s, simulated time of the run
  Initial initial;
  double length_unit = 1;  ///< m per length unit of the scene file (for reports)
  /// Rolling under auto: the contact point is held this far below the floor (the smooth
  /// spring's compression when rolling began), and that spring's ½ k δ² counts in the energy.
  /// 0 for a plain rolling run. m.
  double rolling_depth = 0;
};

/// The changing data. With a fixed step, t = step · dt (never accumulated); with an adaptive
/// one, t is the end of the last accepted step.
struct State {
  Eigen::Vector3d x_world = Eigen::Vector3d::Zero();      ///< CM position, m
  Eigen::Vector3d v_world = Eigen::Vector3d::Zero();      ///< CM velocity, m/s
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  ///< body → world rotation
  Eigen::Vector3d L_world = Eigen::Vector3d::Zero();  ///< angular momentum about the CM, kg m²/s
  double t = 0;                                       ///< s
  std::int64_t step = 0;                              ///< accepted steps so far
};

/// The point of the body's smooth surface lowest along `down_body` (a unit vector in body
/// axes), relative to the CM, body axes, m: where the `smooth` and `rolling` models touch.
inline Eigen::Vector3d lowestSurfacePoint(const Body& body, const Eigen::Vector3d& down_body) {
  return body.surface.lowestPoint(down_body) - body.com_geometric;
}
/// The same, and how fast it moves over the surface as `down_body` turns at `down_rate` (m/s).
inline PointAndRate lowestSurfacePointMoving(const Body& body, const Eigen::Vector3d& down_body,
                                             const Eigen::Vector3d& down_rate) {
  PointAndRate out = body.surface.lowestPointMoving(down_body, down_rate);
  out.point -= body.com_geometric;
  return out;
}

/// ω in body axes, I⁻¹ Rᵀ L (rad/s), for rotation R (body → world): the one place this is
/// written.
inline Eigen::Vector3d bodyAngularVelocity(const Body& body, const Eigen::Matrix3d& R,
                                           const Eigen::Vector3d& L_world) {
  return body.inertia_inv * (R.transpose() * L_world);
}
/// ω_world = R I⁻¹ Rᵀ L (rad/s).
inline Eigen::Vector3d angularVelocity(const Body& body, const Eigen::Matrix3d& R,
                                       const Eigen::Vector3d& L_world) {
  return R * bodyAngularVelocity(body, R, L_world);
}
/// ω_world of a state (rad/s).
inline Eigen::Vector3d angularVelocity(const Model& model, const State& s) {
  return angularVelocity(*model.body, s.q.normalized().toRotationMatrix(), s.L_world);
}

}  // namespace sim

namespace rb {
template <>
struct NameTable<sim::ContactModel> {
  static constexpr std::array<std::pair<sim::ContactModel, std::string_view>, 4> entries{{
      {sim::ContactModel::Points, "points"},
      {sim::ContactModel::Smooth, "smooth"},
      {sim::ContactModel::Rolling, "rolling"},
      {sim::ContactModel::Auto, "auto"},
  }};
};
template <>
struct NameTable<sim::MassSource> {
  static constexpr std::array<std::pair<sim::MassSource, std::string_view>, 2> entries{{
      {sim::MassSource::Continuum, "continuum"},
      {sim::MassSource::Grid, "grid"},
  }};
};
template <>
struct NameTable<sim::FrictionLaw> {
  static constexpr std::array<std::pair<sim::FrictionLaw, std::string_view>, 2> entries{{
      {sim::FrictionLaw::Coulomb, "coulomb"},
      {sim::FrictionLaw::Regularized, "regularized"},
  }};
};
template <>
struct NameTable<sim::Integrator> {
  static constexpr std::array<std::pair<sim::Integrator, std::string_view>, 5> entries{{
      {sim::Integrator::Euler, "euler"},
      {sim::Integrator::Symplectic, "symplectic"},
      {sim::Integrator::Rk4, "rk4"},
      {sim::Integrator::Dopri5, "dopri5"},
      {sim::Integrator::Dop853, "dop853"},
  }};
};
}  // namespace rb

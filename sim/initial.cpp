#include "sim/initial.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "sim/contact_model.hpp"

namespace sim {
namespace {

// Lowest surface point (top or bottom) in world axes relative to the CM, for orientation R.
Eigen::Vector3d lowestPoint(const Model& model, const Eigen::Matrix3d& R) {
  Eigen::Vector3d lowest(0, 0, std::numeric_limits<double>::infinity());
  for (const ContactPoints* p : {&model.body->bottom, &model.body->top}) {
    for (std::size_t i = 0; i < p->size(); ++i) {
      const Eigen::Vector3d r = R * (*p)[i];
      if (r.z() < lowest.z()) lowest = r;
    }
  }
  return lowest;
}

// Σ k·max(0, −z_i): the floor's spring force with the CM at height z_cm, N.
double springForce(const Model& model, const Eigen::Matrix3d& R, double z_cm) {
  double force = 0;
  for (const ContactPoints* p : {&model.body->bottom, &model.body->top}) {
    for (std::size_t i = 0; i < p->size(); ++i) {
      const double z = z_cm + R.row(2).dot((*p)[i]);
      force += model.contact.stiffness * std::max(0.0, -z);
    }
  }
  return force;
}

}  // namespace

double restingHeight(const Model& model, const Eigen::Matrix3d& R) {
  // Smooth contact: one spring at the lowest point carries the weight, depth M g / k.
  const Touch touch = contactTraits(model.contact.model).touch;
  if (touch != Touch::Grid) {
    const Eigen::Vector3d low = R * lowestSurfacePoint(*model.body, -R.row(2).transpose());
    const bool spring = touch == Touch::Spring;
    const double depth = spring ? model.body->mass * model.gravity / model.contact.stiffness : 0.0;
    return -low.z() - depth;
  }
  // Points: the spring force falls monotonically as the CM rises; the answer lies between touching
  // (lowest point at 0) and one point carrying the whole weight.
  const double weight = model.body->mass * model.gravity;
  double high = -lowestPoint(model, R).z();
  double low = high - weight / model.contact.stiffness;
  for (int i = 0; i < 200 && high - low > 1e-15 * std::max(1.0, std::abs(high)); ++i) {
    const double mid = 0.5 * (low + high);
    (springForce(model, R, mid) > weight ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

namespace {

// ω at release in world axes, rad/s: R (w_x, w_y, spin). Written as spin × the body's z axis
// plus the rest only when there is a rest, so that a spin alone gives the very doubles it did.
Eigen::Vector3d initialAngularVelocity(const Initial& init, const Eigen::Matrix3d& R) {
  Eigen::Vector3d w_world = init.spin * R.col(2);
  if (init.w_x != 0 || init.w_y != 0) w_world += init.w_x * R.col(0) + init.w_y * R.col(1);
  return w_world;
}

}  // namespace

Eigen::Vector3d noSlipVelocity(const Model& model, const Eigen::Matrix3d& R,
                               const Eigen::Vector3d& w_world) {
  // The lowest point of the smooth surface does not slide: v_cm + ω × r_low = 0. (A grid
  // point would do for a smooth grid, but on a coarse one the lowest point jumps across the
  // flat foot and would kick the body sideways.)
  const Eigen::Vector3d r_low_body =
      lowestSurfacePoint(*model.body, R.transpose() * -Eigen::Vector3d::UnitZ());
  return -w_world.cross(R * r_low_body);
}

State initialState(const Model& model) {
  const Initial& init = model.initial;
  const Eigen::Matrix3d R = initialRotation(init);
  State s;
  s.q = Eigen::Quaterniond(R);
  const Eigen::Vector3d w_world = initialAngularVelocity(init, R);
  s.L_world = R * model.body->inertia * R.transpose() * w_world;
  if (init.height > 0) {  // released in the air, spinning, the CM at rest unless given
    const double touching = contactTraits(model.contact.model).touch == Touch::Grid
                                ? -lowestPoint(model, R).z()
                                : -(R * lowestSurfacePoint(*model.body, -R.row(2).transpose())).z();
    s.x_world = Eigen::Vector3d(0, 0, touching + init.height);
    s.v_world = init.velocity.value_or(Eigen::Vector3d::Zero());
    return s;
  }
  s.x_world = Eigen::Vector3d(0, 0, restingHeight(model, R));
  // Rolling holds the constraint: the velocity follows from ω (a given one agrees with it,
  // checkInitialVelocity). The penalty models and auto take a given one as it is: a sliding
  // start (auto then starts smooth).
  const bool given = init.velocity && !heldOnFloor(model.contact.model);
  s.v_world = given ? *init.velocity : noSlipVelocity(model, R, w_world);
  return s;
}

Eigen::Matrix3d initialRotation(const Initial& init) {
  return (Eigen::AngleAxisd(init.tilt_x, Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(init.tilt_y, Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

std::optional<rb::Error> rollingDisagreement(const Model& model, const Eigen::Matrix3d& R,
                                             const Eigen::Vector3d& w_world,
                                             const Eigen::Vector3d& v, const std::string& key) {
  const Eigen::Vector3d rolling = noSlipVelocity(model, R, w_world);
  const double slip = (v - rolling).norm();
  if (slip <= kVelocityAgreement * rolling.norm() + kVelocityFloor) return std::nullopt;
  std::ostringstream msg;
  msg.precision(6);
  msg << "slides the contact point at " << slip
      << " m/s, which contact.model rolling forbids: rolling without slipping needs v = −ω × r "
         "= ["
      << rolling.x() << ", " << rolling.y() << ", " << rolling.z() << "] m/s here (within "
      << kVelocityAgreement << " of its size); leave the velocity out to have it, or use "
      << "contact.model smooth or auto for a sliding start";
  return rb::Error{key, msg.str()};
}

std::optional<rb::Error> checkInitialVelocity(const Model& model) {
  const Initial& init = model.initial;
  if (!init.velocity || !heldOnFloor(model.contact.model)) return std::nullopt;
  const Eigen::Matrix3d R = initialRotation(init);
  auto e = rollingDisagreement(model, R, initialAngularVelocity(init, R), *init.velocity,
                               "initial.velocity");
  if (e) e->involves = {"initial.angular_velocity", "initial.spin", "initial.tilt"};
  return e;
}

double spinReach(const Model& model) {
  const State s = initialState(model);
  const Eigen::Matrix3d R = initialRotation(model.initial);
  const Eigen::Vector3d w_world = angularVelocity(*model.body, R, s.L_world);
  const double kinetic =
      0.5 * model.body->mass * s.v_world.squaredNorm() + 0.5 * w_world.dot(s.L_world);
  const Eigen::Vector3d up_body = R.transpose() * Eigen::Vector3d::UnitZ();
  return std::sqrt(2 * kinetic * up_body.dot(model.body->inertia_inv * up_body));
}

rb::Result<State> withParts(const Model& model, State s, const StateParts& parts) {
  const Eigen::Matrix3d R_was = s.q.normalized().toRotationMatrix();
  const Eigen::Vector3d w_body =
      parts.w_body.value_or(bodyAngularVelocity(*model.body, R_was, s.L_world));
  if (parts.q) s.q = parts.q->normalized();
  const Eigen::Matrix3d R = s.q.normalized().toRotationMatrix();
  // The body turned or struck keeps (or takes) its ω in body axes: L = R I ω.
  if (parts.q || parts.w_body) s.L_world = R * (model.body->inertia * w_body);
  if (parts.x_world) s.x_world = *parts.x_world;
  if (parts.v_world) {
    if (heldOnFloor(model.contact.model))
      if (auto e = rollingDisagreement(model, R, R * w_body, *parts.v_world, "velocity")) return *e;
    s.v_world = *parts.v_world;
  }
  return s;
}

}  // namespace sim

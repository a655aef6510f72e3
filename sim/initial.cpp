#include "sim/initial.hpp"

#include <algorithm>
#include <limits>

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

State initialState(const Model& model) {
  const Initial& init = model.initial;
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(init.tilt_x, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(init.tilt_y, Eigen::Vector3d::UnitY()))
                                .toRotationMatrix();
  State s;
  s.q = Eigen::Quaterniond(R);
  const Eigen::Vector3d w_world = init.spin * R.col(2);
  s.L_world = R * model.body->inertia * R.transpose() * w_world;
  if (init.height > 0) {  // released in the air, spinning, the CM at rest
    const double touching = contactTraits(model.contact.model).touch == Touch::Grid
                                ? -lowestPoint(model, R).z()
                                : -(R * lowestSurfacePoint(*model.body, -R.row(2).transpose())).z();
    s.x_world = Eigen::Vector3d(0, 0, touching + init.height);
    return s;
  }
  s.x_world = Eigen::Vector3d(0, 0, restingHeight(model, R));
  // The lowest point of the smooth surface does not slide: v_cm + ω × r_low = 0. (A grid
  // point would do for a smooth grid, but on a coarse one the lowest point jumps across the
  // flat foot and would kick the body sideways.)
  const Body& body = *model.body;
  const Eigen::Vector3d r_low_body =
      lowestSurfacePoint(body, R.transpose() * -Eigen::Vector3d::UnitZ());
  s.v_world = -w_world.cross(R * r_low_body);
  return s;
}

}  // namespace sim

#include "sim/switching.hpp"

#include <cmath>
#include <limits>

#include "sim/contact.hpp"
#include "sim/rolling.hpp"

namespace sim {
namespace {

Eigen::Matrix3d cross(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return m;
}

}  // namespace

Model modeOf(const Model& model, ContactModel mode, double rolling_depth) {
  Model out = model;
  out.contact.model = mode;
  out.rolling_depth = rolling_depth;
  return out;
}

RollingMargins rollingMargins(const Model& rolling, const State& s) {
  const Kinematics k = kinematicsOf(rolling, s);
  const Eigen::Vector3d force = rollingMotion(rolling, k).force_world;
  RollingMargins m;
  m.normal = force.z();
  m.friction = rolling.contact.friction * force.z() - force.head<2>().norm();
  m.rim = std::numeric_limits<double>::infinity();
  const Surface& surface = rolling.body->surface;
  if (surface.kind == Surface::Kind::Paraboloid) {
    const Eigen::Vector3d down_body = -k.R.row(2).transpose();
    m.rim = down_body.z() < 0
                ? surface.paraboloid.top - surface.paraboloid.lowestPoint(down_body).z()
                : -1.0;
  }
  return m;
}

SmoothContactState smoothContactState(const Model& smooth, const State& s) {
  const Kinematics k = kinematicsOf(smooth, s);
  const Eigen::Vector3d r = k.R * lowestSurfacePoint(*smooth.body, -k.R.row(2).transpose());
  const Eigen::Vector3d u = k.v_world + k.w_world.cross(r);
  SmoothContactState c;
  c.depth = -(k.x_world.z() + r.z());
  c.slip = u.head<2>().norm();
  c.normal =
      c.depth > 0
          ? std::max(0.0, smooth.contact.stiffness * c.depth - smooth.contact.damping * u.z())
          : 0.0;
  return c;
}

void projectOntoRolling(const Model& smooth, State& s) {
  const Body& body = *smooth.body;
  const Eigen::Matrix3d R = s.q.toRotationMatrix();
  const Eigen::Vector3d r = R * lowestSurfacePoint(body, -R.row(2).transpose());
  const Eigen::Vector3d w = angularVelocity(body, R, s.L_world);
  const Eigen::Vector3d u = s.v_world + w.cross(r);
  const Eigen::Matrix3d inertia_inv = R * body.inertia_inv * R.transpose();
  const Eigen::Matrix3d K =
      Eigen::Matrix3d::Identity() / body.mass - cross(r) * inertia_inv * cross(r);
  const Eigen::Vector3d impulse = K.ldlt().solve(-u);
  s.v_world += impulse / body.mass;
  s.L_world += r.cross(impulse);
}

double smoothStep(const Model& model) {
  const Contact& c = model.contact;
  const double period = 2 * M_PI * std::sqrt(model.body->mass / c.stiffness);
  double step = period / 50;
  if (c.friction > 0 && model.gravity > 0)
    step = std::min(step, 0.2 * c.slip_velocity / (c.friction * model.gravity));
  return step;
}

}  // namespace sim

#include "sim/contact.hpp"

#include <cmath>

namespace sim {

Kinematics kinematicsOf(const Model& model, const State& s) {
  Kinematics k;
  k.R = s.q.toRotationMatrix();  // q is a unit quaternion (the adaptive stepper normalises its own)
  k.x_world = s.x_world;
  k.v_world = s.v_world;
  k.w_body = bodyAngularVelocity(*model.body, k.R, s.L_world);
  k.w_world = k.R * k.w_body;
  return k;
}

namespace {

// Friction force (N) on a point sliding at v_t (horizontal, m/s) under normal force N.
Eigen::Vector2d frictionForce(const Contact& c, const Eigen::Vector2d& v_t, double normal) {
  const double limit = c.friction * normal;
  if (limit == 0) return Eigen::Vector2d::Zero();
  const double speed2 = v_t.squaredNorm();
  if (c.law == FrictionLaw::Coulomb) {
    // seed eq. 31: −μ N U_tan / |U_tan|
    return speed2 > 0 ? Eigen::Vector2d(-limit * v_t / std::sqrt(speed2)) : Eigen::Vector2d::Zero();
  }
  const double eps = c.slip_velocity;
  return -limit * v_t / std::sqrt(speed2 + eps * eps);
}

// Adds the floor's force on one material point at r (world axes, from the CM) whose height
// is z < 0.
void pressPoint(const Contact& c, const Kinematics& k, const Eigen::Vector3d& r, double z,
                ContactLoad& load) {
  const Eigen::Vector3d v_point = k.v_world + k.w_world.cross(r);
  const double depth = -z;
  ++load.contacts;
  load.elastic_energy += 0.5 * c.stiffness * depth * depth;
  const double normal = c.stiffness * depth - c.damping * v_point.z();
  if (normal <= 0) return;
  const Eigen::Vector2d friction = frictionForce(c, v_point.head<2>(), normal);
  const Eigen::Vector3d f(friction.x(), friction.y(), normal);
  load.force_world += f;
  load.torque_world += r.cross(f);
  load.normal_force += normal;
}

void pressPoints(const Contact& c, const Kinematics& k, const ContactPoints& pts,
                 ContactLoad& load) {
  const double r20 = k.R(2, 0), r21 = k.R(2, 1), r22 = k.R(2, 2);
  const double z_cm = k.x_world.z();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    // Height of the point above the floor: z = z_cm + (R r)_z. Most points are above it.
    const double z = z_cm + r20 * pts.x[i] + r21 * pts.y[i] + r22 * pts.z[i];
    if (z >= 0) continue;
    pressPoint(c, k, k.R * pts[i], z, load);
  }
}

}  // namespace

ContactLoad pointContact(const Model& model, const Kinematics& k) {
  ContactLoad load;
  pressPoints(model.contact, k, model.body->bottom, load);
  // The top surface touches only when the body lies on its side or upside down; its bounding
  // box says when none of it can, which is nearly always.
  if (model.body->top.lowestBound(k.R, k.x_world.z()) < 0)
    pressPoints(model.contact, k, model.body->top, load);
  return load;
}

ContactLoad smoothContact(const Model& model, const Kinematics& k) {
  ContactLoad load;
  const Eigen::Vector3d down_body = -k.R.row(2).transpose();  // Rᵀ(−ẑ)
  const Eigen::Vector3d r = k.R * lowestSurfacePoint(*model.body, down_body);
  const double z = k.x_world.z() + r.z();
  if (z < 0) pressPoint(model.contact, k, r, z, load);
  return load;
}

}  // namespace sim

#include "sim/telemetry.hpp"

#include <algorithm>
#include <cmath>

#include "sim/step.hpp"

namespace sim {

Telemetry telemetryOf(const Model& model, const State& s) {
  const Kinematics k = kinematicsOf(model, s);
  const ContactLoad contact = loadsOn(model, k).contact;
  Telemetry out;
  out.t = s.t;
  out.spin = k.w_world.z();
  out.kinetic = 0.5 * model.body->mass * s.v_world.squaredNorm() + 0.5 * k.w_world.dot(s.L_world);
  out.potential = model.body->mass * model.gravity * s.x_world.z();
  out.elastic = contact.elastic_energy;
  out.energy = out.kinetic + out.potential + out.elastic;
  out.tilt_deg = std::acos(std::clamp(k.R(2, 2), -1.0, 1.0)) * 180.0 / M_PI;
  out.x_world = s.x_world;
  out.orientation = s.q.normalized();
  out.w_world = k.w_world;
  out.L_world = s.L_world;
  out.contacts = contact.contacts;
  out.normal_force = contact.normal_force;
  out.friction_force = contact.force_world.head<2>().norm();
  out.mode = model.contact.model;
  return out;
}

}  // namespace sim

#include "sim/step.hpp"

#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"

namespace sim {
namespace {

Eigen::Vector4d quaternionRate(const Eigen::Quaterniond& q, const Eigen::Vector3d& w_world) {
  const Eigen::Quaterniond w(0, w_world.x(), w_world.y(), w_world.z());
  return 0.5 * (w * q).coeffs();
}

}  // namespace

Rates ratesOf(const Model& model, const State& s) {
  const Kinematics k = kinematicsOf(model, s);
  const Load load = loadsOn(model, k);
  return {cmVelocity(model, s, k, load), load.force_world / model.body->mass,
          quaternionRate(s.q, k.w_world), load.torque_world};
}

State advanced(const State& s, const Rates& r, double h) {
  State out = s;
  out.x_world += h * r.dx;
  out.v_world += h * r.dv;
  out.q.coeffs() += h * r.dq;
  out.q.normalize();
  out.L_world += h * r.dL;
  return out;
}

Load loadsOn(const Model& model, const Kinematics& k) {
  Load load;
  floorLoad(model, k, load);
  load.force_world = load.contact.force_world;
  load.force_world.z() -= model.body->mass * model.gravity;
  load.torque_world = load.contact.torque_world - model.contact.air_drag * k.w_world;
  return load;
}

void advanceBy(const Model& model, State& s, double h) {
  // (an adaptive method has no fixed step: the Rollout's AdaptiveStepper drives it)
  if (const auto method = integratorTraits(model.integrator).step) method(model, s, h);
  holdOnFloor(model, s);
}

void step(const Model& model, State& s) {
  advanceBy(model, s, model.dt);
  ++s.step;
  s.t = static_cast<double>(s.step) * model.dt;
}

}  // namespace sim

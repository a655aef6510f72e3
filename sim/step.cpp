#include "sim/step.hpp"

#include "sim/contact_model.hpp"

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

namespace {

// Forward Euler (seed §3.4): every variable moves with the rates at the start of the step.
void eulerStep(const Model& model, State& s, double h) {
  s = advanced(s, ratesOf(model, s), h);
}

// Semi-implicit Euler: kick the momenta with the loads at the start, then drift the pose with
// the new velocities; the rotation by the exact exponential map q ← exp(½ ω dt) ⊗ q.
void symplecticStep(const Model& model, State& s, double dt) {
  const Kinematics k = kinematicsOf(model, s);
  const Load load = loadsOn(model, k);
  s.v_world += dt * load.force_world / model.body->mass;
  s.L_world += dt * load.torque_world;
  s.x_world += dt * s.v_world;
  const Eigen::Vector3d w_new = angularVelocity(*model.body, k.R, s.L_world);
  const double angle = w_new.norm() * dt;
  if (angle > 0) {
    s.q = Eigen::Quaterniond(Eigen::AngleAxisd(angle, w_new.normalized())) * s.q;
    s.q.normalize();
  }
}

// Classical fourth-order Runge–Kutta on (x, v, q, L).
void rk4Step(const Model& model, State& s, double h) {
  const Rates k1 = ratesOf(model, s);
  const Rates k2 = ratesOf(model, advanced(s, k1, h / 2));
  const Rates k3 = ratesOf(model, advanced(s, k2, h / 2));
  const Rates k4 = ratesOf(model, advanced(s, k3, h));
  Rates sum;
  sum.dx = (k1.dx + 2 * k2.dx + 2 * k3.dx + k4.dx) / 6;
  sum.dv = (k1.dv + 2 * k2.dv + 2 * k3.dv + k4.dv) / 6;
  sum.dq = (k1.dq + 2 * k2.dq + 2 * k3.dq + k4.dq) / 6;
  sum.dL = (k1.dL + 2 * k2.dL + 2 * k3.dL + k4.dL) / 6;
  s = advanced(s, sum, h);
}

}  // namespace

Load loadsOn(const Model& model, const Kinematics& k) {
  Load load;
  floorLoad(model, k, load);
  load.force_world = load.contact.force_world;
  load.force_world.z() -= model.body->mass * model.gravity;
  load.torque_world = load.contact.torque_world - model.contact.air_drag * k.w_world;
  return load;
}

void advanceBy(const Model& model, State& s, double h) {
  switch (model.integrator) {
    case Integrator::Euler:
      eulerStep(model, s, h);
      break;
    case Integrator::Symplectic:
      symplecticStep(model, s, h);
      break;
    case Integrator::Rk4:
      rk4Step(model, s, h);
      break;
    case Integrator::Dopri5:
    case Integrator::Dop853:
      break;  // driven by the Rollout's adaptive stepper
  }
  holdOnFloor(model, s);
}

void step(const Model& model, State& s) {
  advanceBy(model, s, model.dt);
  ++s.step;
  s.t = static_cast<double>(s.step) * model.dt;
}

}  // namespace sim

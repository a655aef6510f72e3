#include "sim/adaptive.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "sim/step.hpp"

namespace sim {
namespace {

namespace odeint = boost::numeric::odeint;
using Vector = std::array<double, 13>;  // x (3), v (3), q (x, y, z, w), L (3), scaled
using Dense = odeint::result_of::make_dense_output<odeint::runge_kutta_dopri5<Vector>>::type;

// The body's own scales, which make the integrated state dimensionless.
struct Scales {
  double length = 1, time = 1, momentum = 1;  // m, s, kg m²/s

  explicit Scales(const Model& model) {
    const Body& body = *model.body;
    const Eigen::Vector3d extent = body.extent;
    length = extent.norm() > 0 ? extent.norm() : 1.0;
    time = model.gravity > 0 ? std::sqrt(length / model.gravity) : 1.0;
    momentum = body.inertia.diagonal().maxCoeff() / time;
  }
};

Vector pack(const State& s, const Scales& k) {
  Vector y;
  for (int i = 0; i < 3; ++i) {
    y[i] = s.x_world[i] / k.length;
    y[3 + i] = s.v_world[i] * k.time / k.length;
    y[10 + i] = s.L_world[i] / k.momentum;
  }
  for (int i = 0; i < 4; ++i) y[6 + i] = s.q.coeffs()[i];
  return y;
}

State unpack(const Vector& y, const Scales& k, double t) {
  State s;
  for (int i = 0; i < 3; ++i) {
    s.x_world[i] = y[i] * k.length;
    s.v_world[i] = y[3 + i] * k.length / k.time;
    s.L_world[i] = y[10 + i] * k.momentum;
  }
  for (int i = 0; i < 4; ++i) s.q.coeffs()[i] = y[6 + i];
  s.t = t;
  return s;
}

}  // namespace

struct AdaptiveStepper::Impl {
  Model model;
  Scales scales;
  Dense dense;
  std::int64_t evaluations = 0;

  Impl(const Model& m, const State& start)
      : model(m),
        scales(m),
        dense(odeint::make_dense_output(m.tolerance, m.tolerance,
                                        odeint::runge_kutta_dopri5<Vector>())) {
    // The controller grows a cautious first step quickly (by up to 5× a step).
    dense.initialize(pack(start, scales), start.t / scales.time, 1e-3);
  }

  // The equations of motion in scaled variables (Odeint's system signature).
  void rates(const Vector& y, Vector& dydt, double t_scaled) {
    ++evaluations;
    State s = unpack(y, scales, t_scaled * scales.time);
    // The integrator keeps |q| = 1 only to its tolerance; the rates must not depend on that
    // drift (q̇ = ½ ω ⊗ q̂ still keeps |q| constant: q · q̇ = 0).
    s.q.normalize();
    const Rates r = ratesOf(model, s);
    const double k_x = scales.time / scales.length;
    for (int i = 0; i < 3; ++i) {
      dydt[i] = r.dx[i] * k_x;
      dydt[3 + i] = r.dv[i] * k_x * scales.time;
      dydt[10 + i] = r.dL[i] * scales.time / scales.momentum;
    }
    for (int i = 0; i < 4; ++i) dydt[6 + i] = r.dq[i] * scales.time;
  }
};

AdaptiveStepper::AdaptiveStepper(const Model& model, const State& start)
    : impl_(std::make_unique<Impl>(model, start)) {}

AdaptiveStepper::~AdaptiveStepper() = default;

State AdaptiveStepper::step(std::int64_t step_index) {
  Impl& m = *impl_;
  // Odeint copies the system it is given; a small forwarding lambda keeps one Impl counting.
  Impl* self = &m;
  const auto interval = m.dense.do_step(
      [self](const Vector& y, Vector& dydt, double t) { self->rates(y, dydt, t); });
  State s = unpack(m.dense.current_state(), m.scales, interval.second * m.scales.time);
  s.step = step_index;
  return s;
}

State AdaptiveStepper::at(double t) const {
  Vector y;
  impl_->dense.calc_state(t / impl_->scales.time, y);
  return unpack(y, impl_->scales, t);
}

std::int64_t AdaptiveStepper::evaluations() const { return impl_->evaluations; }

// Dormand–Prince with first-same-as-last: every try of a step evaluates the equations six
// times (stages 2–7, the last at the new point), and the start once.
std::int64_t AdaptiveStepper::rejected(std::int64_t accepted) const {
  return (impl_->evaluations - 1) / 6 - accepted;
}

}  // namespace sim

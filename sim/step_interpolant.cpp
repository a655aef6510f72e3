#include "sim/step_interpolant.hpp"

#include "sim/adaptive.hpp"

namespace sim {
namespace {

using Vector13 = Eigen::Matrix<double, 13, 1>;

Vector13 packState(const State& s) {
  Vector13 y;
  y << s.x_world, s.v_world, s.q.coeffs(), s.L_world;
  return y;
}

Vector13 packRates(const Rates& r) {
  Vector13 y;
  y << r.dx, r.dv, r.dq, r.dL;
  return y;
}

}  // namespace

State hermite(const State& a, const Rates& rates_a, const State& b, const Rates& rates_b,
              double t) {
  const double h = b.t - a.t;
  const double u = (t - a.t) / h;
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u);
  const double h01 = u * u * (3 - 2 * u), h11 = u * u * (u - 1);
  const Vector13 y = h00 * packState(a) + h10 * h * packRates(rates_a) + h01 * packState(b) +
                     h11 * h * packRates(rates_b);
  State s;
  s.x_world = y.segment<3>(0);
  s.v_world = y.segment<3>(3);
  s.q.coeffs() = y.segment<4>(6);
  s.L_world = y.segment<3>(10);
  s.t = t;
  s.step = a.step;
  return s;
}

void StepInterpolant::stepTaken() {
  have_rates_ = false;
  dense_lost_ = false;
}

void StepInterpolant::cut(double t_cut, const Model& before, const State& before_end) {
  before_ = before;
  before_end_ = before_end;
  cut_s_ = t_cut;
  have_rates_ = false;
}

const Model& StepInterpolant::modeAt(double t, const Model& active) const {
  return t < cut_s_ && !sameTime(t, cut_s_) ? before_ : active;
}

State StepInterpolant::at(double t, const Model& active, const State& a, const State& b,
                          const AdaptiveStepper* dense, bool* on_constraint) const {
  if (on_constraint) *on_constraint = false;
  // Before a cut inside the last step: the old mode's own step, from its start to where it
  // ended before the cut (interpolating across the cut, from a rolling state to a sliding one,
  // made the samples' energy dip and recover).
  if (beforeCut(a, t))
    return hermite(a, ratesOf(before_, a), before_end_, ratesOf(before_, before_end_), t);
  if (dense && !dense_lost_) {
    if (on_constraint) *on_constraint = dense->keepsRolling();
    return dense->at(t);
  }
  if (!have_rates_) {
    rates_a_ = ratesOf(active, a);
    rates_b_ = ratesOf(active, b);
    have_rates_ = true;
  }
  return hermite(a, rates_a_, b, rates_b_, t);
}

double StepInterpolant::spinAt(double t, const Model& active, const State& a, const State& b,
                               const AdaptiveStepper* dense) const {
  if (dense && !dense_lost_ && !beforeCut(a, t)) return dense->spinAt(t);
  return angularVelocity(active, at(t, active, a, b, dense)).z();
}

}  // namespace sim

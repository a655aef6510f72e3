#include "sim/adaptive.hpp"

#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <tuple>
#include <type_traits>

#include "sim/contact_model.hpp"
#include "sim/dop853.hpp"
#include "sim/rolling.hpp"
#include "sim/step.hpp"

namespace sim {
namespace {
namespace odeint = boost::numeric::odeint;

// Gustafsson's PI step-size control, in the form of Hairer's DOPRI5 code (Hairer, Nørsett &
// Wanner, Solving Ordinary Differential Equations I, 2nd ed., §II.4, "Automatic step size
// control"; β = 0.04 as recommended there for DOPRI5): after an accepted step with error err
// (≤ 1, Odeint's norm), the next h grows by safety · err^−(1/5 − 0.75β) · err_prev^β, within
// 0.2 … 10 and never after a rejection; a rejected step shrinks by safety · err^−(1/5 − 0.75β),
// at most 5×. The embedded error is O(h⁵), so its exponent is 1/5 both ways. Odeint's own
// controller (~30 % of tries rejected on Kane & Levinson) grows up to 5×
// whenever err < ½, shrinks by err^−1/3, and keeps no memory of the last error.
class PiStepAdjuster {
 public:
  using time_type = double;
  using value_type = double;

  double decrease_step(double dt, double error, int /*error_order*/) {
    rejected_ = true;
    return dt * std::max(kLeast, kSafety * std::pow(error, -kExponent));
  }
  double increase_step(double dt, double error, int /*stepper_order*/) {
    error = std::max(error, 1e-4);  // Hairer's floor: a vanishing error grows h at most 10×
    // err^−(1/5 − 0.75β) · err_prev^β as one exponential of logarithms, the last one kept (two
    // pow calls had been 4 % of a run's instructions).
    const double log_error = std::log(error);
    double factor = kSafety * std::exp(kBeta * previous_log_ - kExponent * log_error);
    factor = std::clamp(factor, kLeast, rejected_ ? 1.0 : kMost);
    previous_log_ = log_error;
    rejected_ = false;
    return dt * factor;
  }
  bool check_step_size_limit(double /*dt*/) const { return true; }
  double get_max_dt() const { return 0; }

 private:
  static constexpr double kBeta = 0.04, kExponent = 0.2 - 0.75 * kBeta, kSafety = 0.9;
  static constexpr double kLeast = 0.2, kMost = 10;
  double previous_log_ = std::log(1e-4);
  bool rejected_ = false;
};

// The body's own scales, which make the integrated state dimensionless.
struct Scales {
  double length = 1, time = 1, momentum = 1;  // m, s, kg m²/s
  double time_over_length = 1;  // s/m: scales a velocity (divided once, not each evaluation)

  explicit Scales(const Model& model) {
    const Body& body = *model.body;
    const Eigen::Vector3d extent = body.extent;
    length = extent.norm() > 0 ? extent.norm() : 1.0;
    time = model.gravity > 0 ? std::sqrt(length / model.gravity) : 1.0;
    momentum = body.inertia.diagonal().maxCoeff() / time;
    time_over_length = time / length;
    for (int i = 0; i < 3; ++i) {
      spin[i] = time * body.inertia(i, i) / body.inertia.diagonal().maxCoeff();
      spin_inverse[i] = 1 / spin[i];
    }
  }
  // ω in body axes is scaled as the angular momentum is, component by component (I_ii ω_i
  // over I_max/τ): a rocking about a light axis is held to the error the same momentum about
  // the heaviest would be. Scaling ω by τ alone, for the same reversal error, cost the default
  // scene 7 % less and Kane & Levinson 17 % more (docs/speed.md "Simulation: speed against error").
  std::array<double, 3> spin;
  // Their inverses: an evaluation multiplies where it had divided (three divisions a stage).
  std::array<double, 3> spin_inverse;
};

// q / |q|, by one division and products (Eigen's normalized() divides each component).
Eigen::Quaterniond unitQuaternion(double w, double x, double y, double z) {
  const double inverse = 1 / std::sqrt(w * w + x * x + y * y + z * z);
  return Eigen::Quaterniond(w * inverse, x * inverse, y * inverse, z * inverse);
}

// The whole state: x (3), v (3), q (x, y, z, w), L (3), scaled.
struct Free {
  using Vector = std::array<double, 13>;

  static Vector pack(const Model&, const State& s, const Scales& k) {
    Vector y;
    for (int i = 0; i < 3; ++i) {
      y[i] = s.x_world[i] / k.length;
      y[3 + i] = s.v_world[i] * k.time / k.length;
      y[10 + i] = s.L_world[i] / k.momentum;
    }
    for (int i = 0; i < 4; ++i) y[6 + i] = s.q.coeffs()[i];
    return y;
  }

  static State unpack(const Model&, const Vector& y, const Scales& k, double t) {
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

  static double spin(const Model& model, const Vector& y, const Scales& k) {
    return angularVelocity(model, unpack(model, y, k, 0)).z();
  }

  static void rates(const Model& model, const Vector& y, Vector& dydt, const Scales& k, double t) {
    State s = unpack(model, y, k, t);
    // The integrator keeps |q| = 1 only to its tolerance; the rates must not depend on that
    // drift (q̇ = ½ ω ⊗ q̂ still keeps |q| constant: q · q̇ = 0).
    s.q.normalize();
    const Rates r = ratesOf(model, s);
    const double k_x = k.time_over_length;
    for (int i = 0; i < 3; ++i) {
      dydt[i] = r.dx[i] * k_x;
      dydt[3 + i] = r.dv[i] * k_x * k.time;
      dydt[10 + i] = r.dL[i] * k.time / k.momentum;
    }
    for (int i = 0; i < 4; ++i) dydt[6 + i] = r.dq[i] * k.time;
  }
};

// Rolling: the constraint gives the CM's height and velocity, so what is integrated is its
// place on the floor (x, y), q (x, y, z, w) and ω in body axes (sim/rolling.hpp's
// rollingRates), scaled; the states handed out are put back on the constraint. Nine unknowns
// instead of thirteen, and no force, torque or momentum to form in an evaluation.
struct Rolling {
  using Vector = std::array<double, 9>;

  static Vector pack(const Model& model, const State& s, const Scales& k) {
    Vector y;
    y[0] = s.x_world.x() / k.length;
    y[1] = s.x_world.y() / k.length;
    const Eigen::Quaterniond q = s.q.normalized();
    for (int i = 0; i < 4; ++i) y[2 + i] = q.coeffs()[i];
    const Eigen::Vector3d w = bodyAngularVelocity(*model.body, q.toRotationMatrix(), s.L_world);
    for (int i = 0; i < 3; ++i) y[6 + i] = w[i] * k.spin[i];
    return y;
  }

  static State unpack(const Model& model, const Vector& y, const Scales& k, double t) {
    State s;
    s.x_world = Eigen::Vector3d(y[0] * k.length, y[1] * k.length, 0);
    // q normalised (the integrated one is a unit quaternion only to the tolerance), L = R I ω,
    // then the height and velocity from the constraint.
    s.q = unitQuaternion(y[5], y[2], y[3], y[4]);
    const Eigen::Vector3d w(y[6] * k.spin_inverse[0], y[7] * k.spin_inverse[1],
                            y[8] * k.spin_inverse[2]);
    const Eigen::Matrix3d R = s.q.toRotationMatrix();
    s.L_world = R * (model.body->inertia * w);
    enforceRolling(model, s, R, R * w);
    s.t = t;
    return s;
  }

  // n = ω·ẑ = (Rᵀ ẑ)·ω_body, with R's bottom row from q as integrated over |q|² (unpack's
  // state gives the same to rounding: q normalised, L formed and turned back).
  static double spin(const Model&, const Vector& y, const Scales& k) {
    const double w = y[5], x = y[2], yq = y[3], z = y[4];
    const double ww = w * w, xx = x * x, yy = yq * yq, zz = z * z;
    const double along_w = 2 * (x * z - w * yq) * y[6] * k.spin_inverse[0] +
                           2 * (yq * z + w * x) * y[7] * k.spin_inverse[1] +
                           (ww + zz - xx - yy) * y[8] * k.spin_inverse[2];
    return along_w / (ww + xx + yy + zz);
  }

  static void rates(const Model& model, const Vector& y, Vector& dydt, const Scales& k, double) {
    // q as integrated: rollingRates takes its direction (normalising it first had put a square
    // root and a division at the head of every evaluation's chain).
    const Eigen::Quaterniond q(y[5], y[2], y[3], y[4]);
    const Eigen::Vector3d w(y[6] * k.spin_inverse[0], y[7] * k.spin_inverse[1],
                            y[8] * k.spin_inverse[2]);
    const RollingRates r = rollingRates(model, q, w);
    const double k_x = k.time_over_length;
    dydt[0] = r.dxy.x() * k_x;
    dydt[1] = r.dxy.y() * k_x;
    for (int i = 0; i < 4; ++i) dydt[2 + i] = r.dq[i] * k.time;
    for (int i = 0; i < 3; ++i) dydt[6 + i] = r.w_dot_body[i] * k.spin[i] * k.time;
  }
};

}  // namespace

struct AdaptiveStepper::Impl {
  virtual ~Impl() = default;
  virtual State step(std::int64_t step_index) = 0;
  virtual State at(double t) const = 0;
  virtual double spinAt(double t) const = 0;
  virtual bool keepsRolling() const = 0;
  virtual std::unique_ptr<Impl> clone() const = 0;
  virtual std::int64_t evaluationCount() const { return evaluations; }
  virtual std::int64_t rejected(std::int64_t accepted) const {
    // Dormand–Prince 5(4) with first-same-as-last: every try of a step evaluates the
    // equations six times (stages 2–7, the last at the new point), and the start once.
    return (evaluations - 1) / 6 - accepted;
  }
  std::int64_t evaluations = 0;
};

namespace {

// One run's Odeint stepper over a layout of the state (Free or Rolling).
template <class Layout>
class Integration final : public AdaptiveStepper::Impl {
 public:
  using Vector = typename Layout::Vector;

  Integration(const Model& m, const State& start)
      : model_(m),
        scales_(m),
        dense_(Controlled(Checker(m.tolerance, m.tolerance), PiStepAdjuster(), Stepper())) {
    // The controller grows a cautious first step quickly (by up to 5× a step).
    dense_.initialize(Layout::pack(model_, start, scales_), start.t / scales_.time, 1e-3);
  }

  State step(std::int64_t step_index) override {
    // Odeint copies the system it is given; a small forwarding lambda keeps one counter.
    Integration* self = this;
    const auto interval = dense_.do_step(
        [self](const Vector& y, Vector& dydt, double t) { self->rates(y, dydt, t); });
    State s =
        Layout::unpack(model_, dense_.current_state(), scales_, interval.second * scales_.time);
    s.step = step_index;
    return s;
  }

  bool keepsRolling() const override { return std::is_same_v<Layout, Rolling>; }
  // Odeint's dense-output stepper holds its states and step size by value: a copy goes on alone.
  std::unique_ptr<AdaptiveStepper::Impl> clone() const override {
    return std::make_unique<Integration>(*this);
  }

  State at(double t) const override {
    Vector y;
    dense_.calc_state(t / scales_.time, y);
    return Layout::unpack(model_, y, scales_, t);
  }
  double spinAt(double t) const override {
    Vector y;
    dense_.calc_state(t / scales_.time, y);
    return Layout::spin(model_, y, scales_);
  }

 private:
  using Stepper = odeint::runge_kutta_dopri5<Vector>;
  using Checker = odeint::default_error_checker<double, typename Stepper::algebra_type,
                                                typename Stepper::operations_type>;
  using Controlled = odeint::controlled_runge_kutta<Stepper, Checker, PiStepAdjuster>;
  using Dense = odeint::dense_output_runge_kutta<Controlled>;

  // The equations of motion in scaled variables (Odeint's system signature). Flattened: every
  // call inside is inlined where its body is in this translation unit (sim/CMakeLists.txt
  // puts the evaluation's files in one unity batch): 3.5 % fewer instructions a run. Not
  // inlined itself: GCC flattens a function only where it is compiled on its own, and inlined
  // into Odeint's stages it had left the rolling equations, the contact point and the surface
  // as calls (their arguments and results through memory) in each evaluation.
  [[gnu::flatten, gnu::noinline]] void rates(const Vector& y, Vector& dydt, double t_scaled) {
    ++evaluations;
    Layout::rates(model_, y, dydt, scales_, t_scaled * scales_.time);
  }

  Model model_;
  Scales scales_;
  Dense dense_;
};

// One run's DOP853 stepper (sim/dop853.hpp) over a layout of the state: the same scaled
// equations, the same first try of a step, its own error control.
template <class Layout>
class Integration853 final : public AdaptiveStepper::Impl {
 public:
  using Vector = typename Layout::Vector;

  Integration853(const Model& m, const State& start) : model_(m), scales_(m), dop_(m.tolerance) {
    dop_.initialize(rates(), Layout::pack(model_, start, scales_), start.t / scales_.time, 1e-3);
  }

  State step(std::int64_t step_index) override {
    dop_.step(rates());
    State s = Layout::unpack(model_, dop_.state(), scales_, dop_.time() * scales_.time);
    s.step = step_index;
    return s;
  }

  bool keepsRolling() const override { return std::is_same_v<Layout, Rolling>; }
  std::unique_ptr<AdaptiveStepper::Impl> clone() const override {
    return std::make_unique<Integration853>(*this);
  }

  // The interpolant's three extra stages are evaluated on the first time asked inside a step;
  // asking does not change the run, so a const reading may fill that cache.
  State at(double t) const override {
    Vector y;
    dop_.at(rates(), t / scales_.time, y);
    return Layout::unpack(model_, y, scales_, t);
  }
  double spinAt(double t) const override {
    Vector y;
    dop_.at(rates(), t / scales_.time, y);
    return Layout::spin(model_, y, scales_);
  }

  std::int64_t evaluationCount() const override { return dop_.evaluations(); }
  std::int64_t rejected(std::int64_t) const override { return dop_.rejected(); }

 private:
  // The equations of motion in scaled variables, flattened as in Integration.
  [[gnu::flatten, gnu::noinline]] void evaluate(const Vector& y, Vector& dydt,
                                                double t_scaled) const {
    Layout::rates(model_, y, dydt, scales_, t_scaled * scales_.time);
  }
  auto rates() const {
    return [this](const Vector& y, Vector& dydt, double t) { evaluate(y, dydt, t); };
  }

  Model model_;
  Scales scales_;
  mutable Dop853<std::tuple_size_v<Vector>> dop_;
};

std::unique_ptr<AdaptiveStepper::Impl> integrationOf(const Model& model, const State& start) {
  const bool rolling = heldOnFloor(model.contact.model);
  if (model.integrator == Integrator::Dop853) {
    if (rolling) return std::make_unique<Integration853<Rolling>>(model, start);
    return std::make_unique<Integration853<Free>>(model, start);
  }
  if (rolling) return std::make_unique<Integration<Rolling>>(model, start);
  return std::make_unique<Integration<Free>>(model, start);
}

}  // namespace

AdaptiveStepper::AdaptiveStepper(const Model& model, const State& start)
    : impl_(integrationOf(model, start)) {}

AdaptiveStepper::AdaptiveStepper(const AdaptiveStepper& other) : impl_(other.impl_->clone()) {}

AdaptiveStepper::~AdaptiveStepper() = default;

State AdaptiveStepper::step(std::int64_t step_index) {
  return impl_->step(step_index);
}

State AdaptiveStepper::at(double t) const {
  return impl_->at(t);
}

double AdaptiveStepper::spinAt(double t) const {
  return impl_->spinAt(t);
}

std::int64_t AdaptiveStepper::evaluations() const {
  return impl_->evaluationCount();
}

bool AdaptiveStepper::keepsRolling() const {
  return impl_->keepsRolling();
}

std::int64_t AdaptiveStepper::rejected(std::int64_t accepted) const {
  return impl_->rejected(accepted);
}

}  // namespace sim

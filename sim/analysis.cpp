#include "sim/analysis.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "sim/contact.hpp"
#include "sim/rolling.hpp"

namespace sim {
namespace {

using Vector5d = Eigen::Matrix<double, 5, 1>;
using Matrix5d = Eigen::Matrix<double, 5, 5>;

// A rotation (body → world) with Rᵀẑ = u: the smallest turn taking u to ẑ.
Eigen::Matrix3d tiltedBy(const Eigen::Vector3d& u) {
  return Eigen::Quaterniond::FromTwoVectors(u, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// The rolling model in the yaw-free variables y = (u_x, u_y, ω_body): u̇ = −ω × u (body
// axes) and ω̇_body = Rᵀ ω̇_world from the rolling equations.
Vector5d rollingRates(const Model& rolling, const Vector5d& y) {
  const double uz = std::sqrt(std::max(0.0, 1 - y(0) * y(0) - y(1) * y(1)));
  const Eigen::Vector3d u(y(0), y(1), uz);
  const Eigen::Vector3d w_body = y.tail<3>();
  Kinematics k;
  k.R = tiltedBy(u);
  k.x_world.setZero();
  k.w_body = w_body;
  k.w_world = k.R * w_body;
  k.v_world.setZero();
  const Eigen::Vector3d w_dot_body = rollingMotion(rolling, k).w_dot_body;
  const Eigen::Vector3d u_dot = -w_body.cross(u);
  Vector5d out;
  out << u_dot.x(), u_dot.y(), w_dot_body;
  return out;
}

Model asRolling(const Model& model) {
  Model rolling = model;
  rolling.contact.model = ContactModel::Rolling;
  return rolling;
}

}  // namespace

Rest restOf(const Model& model) {
  Rest rest;
  const Body& body = *model.body;
  rest.h = -lowestSurfacePoint(body, -Eigen::Vector3d::UnitZ()).z();
  rest.radii = body.surface.radiiAtBottom();
  rest.stable = rest.h < rest.radii.minCoeff();
  return rest;
}

namespace {

// Eigenvalues of the linearised rolling model at spin n with the spin mode left out, in two
// pairs sorted by frequency (|Im λ|), and whether the lower pair tilts the body mainly about
// its long axis (roll: u_x, ω_y) rather than its short axis (pitch: u_y, ω_x).
struct ModePairs {
  Matrix5d matrix;
  std::vector<std::complex<double>> all;
  std::array<std::complex<double>, 2> low, high;
  bool low_is_roll = true;
};

// The Jacobian of the yaw-free rolling rates at steady upright spin n.
Matrix5d jacobianAt(const Model& rolling, double spin) {
  Vector5d steady;
  steady << 0, 0, 0, 0, spin;
  // Central differences of the exact rates: ε = 1e-7 keeps truncation (ε²) and rounding
  // (1e-16/ε) errors near 1e-9 of the entries.
  Matrix5d J;
  const double eps = 1e-7;
  for (int j = 0; j < 5; ++j) {
    Vector5d step = Vector5d::Zero();
    step(j) = eps;
    J.col(j) =
        (rollingRates(rolling, steady + step) - rollingRates(rolling, steady - step)) / (2 * eps);
  }
  return J;
}

// How much more an eigenvector of the tilt (u_x, u_y, ω_x, ω_y, …) rocks the body about its
// long axis (roll: u_x, ω_y) than about its short axis (pitch: u_y, ω_x): > 0 for roll.
template <typename Vector>
double rollExcess(const Vector& v) {
  return std::abs(v(0)) + std::abs(v(3)) - std::abs(v(1)) - std::abs(v(2));
}

ModePairs modePairs(const Model& rolling, double spin) {
  // Dynamic sizes: Eigen's eigensolver for a fixed 5×5 (and 4×4 below) took the compiler
  // 34 s and 1.5 GB for this file, the longest step of a fresh build; the arithmetic is the
  // same (docs/speed.md "A fresh build").
  ModePairs out;
  out.matrix = jacobianAt(rolling, spin);
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(Eigen::MatrixXd(out.matrix));
  const Eigen::MatrixXcd vectors = solver.eigenvectors();
  // The spin mode moves ω_z alone.
  int spin_mode = 0;
  double best = -1;
  for (int i = 0; i < 5; ++i) {
    out.all.push_back(solver.eigenvalues()(i));
    const double share = std::abs(vectors(4, i)) / vectors.col(i).norm();
    if (share > best) best = share, spin_mode = i;
  }
  std::vector<int> rest;
  for (int i = 0; i < 5; ++i)
    if (i != spin_mode) rest.push_back(i);
  std::sort(rest.begin(), rest.end(), [&](int a, int b) {
    return std::abs(out.all[a].imag()) < std::abs(out.all[b].imag());
  });
  out.low = {out.all[rest[0]], out.all[rest[1]]};
  out.high = {out.all[rest[2]], out.all[rest[3]]};
  out.low_is_roll = rollExcess(vectors.col(rest[0])) + rollExcess(vectors.col(rest[1])) > 0;
  return out;
}

}  // namespace

Linearisation linearise(const Model& model, double spin) {
  const Model rolling = asRolling(model);
  const ModePairs pairs = modePairs(rolling, spin);
  // Which pair is roll is read at rest, where the modes do not mix; spin mixes them, but the
  // order of their frequencies stays.
  const bool low_is_roll = modePairs(rolling, 0).low_is_roll;
  Linearisation out;
  out.spin = spin;
  out.matrix = pairs.matrix;
  out.eigenvalues = pairs.all;
  auto growth = [](const std::array<std::complex<double>, 2>& p) {
    return std::max(p[0].real(), p[1].real());
  };
  auto hz = [](const std::array<std::complex<double>, 2>& p) {
    return std::max(std::abs(p[0].imag()), std::abs(p[1].imag())) / (2 * M_PI);
  };
  const auto& roll = low_is_roll ? pairs.low : pairs.high;
  const auto& pitch = low_is_roll ? pairs.high : pairs.low;
  out.roll_growth = growth(roll);
  out.pitch_growth = growth(pitch);
  out.roll_hz = hz(roll);
  out.pitch_hz = hz(pitch);
  return out;
}

FirstOrder firstOrderGrowth(const Model& model) {
  const double n = 1e-3;  // rad/s: small enough that the rates are linear in n
  const Linearisation up = linearise(model, n), down = linearise(model, -n);
  return {(up.roll_growth - down.roll_growth) / (2 * n),
          (up.pitch_growth - down.pitch_growth) / (2 * n)};
}

GrowthEachWay growthEachWay(const Model& model, double spin_magnitude) {
  const double n = std::max(std::abs(spin_magnitude), 1e-3);
  const Linearisation ccw = linearise(model, n), cw = linearise(model, -n);
  // Zero: below 1e-6 of the fastest rocking frequency, where the finite-difference Jacobian's
  // rates are noise (a skewed body without dents, q = 0.05, gave ±3e-11 /s at 40 rad/s and was
  // called "preferred cw"); a growth that slow would take 1e6 rocking periods to show.
  const double omega = 2 * M_PI * std::max({ccw.roll_hz, ccw.pitch_hz, cw.roll_hz, cw.pitch_hz});
  return {std::max(ccw.roll_growth, ccw.pitch_growth), std::max(cw.roll_growth, cw.pitch_growth),
          1e-6 * omega, n};
}

Direction preferredDirection(const GrowthEachWay& growth) {
  const double ccw_fastest = growth.ccw, cw_fastest = growth.cw, zero = growth.zero;
  // Alike: within 1e-9 of the rates' size (rounding; a dentless body's differ by 1e-16 /s).
  const double size = std::max({std::abs(ccw_fastest), std::abs(cw_fastest), 1e-12});
  if ((ccw_fastest <= zero && cw_fastest <= zero) ||
      std::abs(ccw_fastest - cw_fastest) <= std::max(1e-9 * size, zero))
    return Direction::None;
  return ccw_fastest < cw_fastest ? Direction::Ccw : Direction::Cw;
}

double eFoldsAgainstDrag(const Model& model, const GrowthEachWay& growth) {
  const double drag = model.contact.air_drag;
  if (drag <= 0) return std::numeric_limits<double>::infinity();
  // Drag alone slows the spin as n(t) = n₀ e^(−t/τ), τ = C/σ: dt = τ d(ln n) down the way. The
  // growth falls with the spin (about linearly in n, from zero at a spin of its own): taken at
  // the start alone it counted 6.5 e-folds for the both-ways body spun −5 rad/s, which does not
  // reverse in 30 s; integrated it counts 2.7 there, and 7 at −8 rad/s, where it reverses.
  const double tau = model.body->inertia(2, 2) / drag;
  const double sign = growth.ccw <= growth.cw ? 1 : -1;  // the way it grows more slowly
  const auto rate = [&](double n) {
    const Linearisation l = linearise(model, sign * n);
    return std::max(l.roll_growth, l.pitch_growth);
  };
  // ln n in steps of 1/32 (3 % of the spin) down to where the growth ends (found between two
  // steps by a straight line), or to 1 % of the start: trapezoids.
  constexpr double kStep = 1.0 / 32, kDown = 4.6;  // e^−4.6 ≈ 1 %
  double total = 0, u = 0, g = std::min(growth.ccw, growth.cw);
  while (g > growth.zero && u < kDown) {
    const double next_u = u + kStep, next_g = rate(growth.spin * std::exp(-next_u));
    if (next_g <= growth.zero) {
      const double part = (g - growth.zero) / (g - next_g);  // of the step, to the zero
      total += 0.5 * (g + growth.zero) * part * kStep;
      break;
    }
    total += 0.5 * (g + next_g) * kStep;
    u = next_u;
    g = next_g;
  }
  return tau * total;
}

double rockingStart(const Model& model) {
  const double tilt = std::hypot(model.initial.tilt_x, model.initial.tilt_y);
  const double rate = std::hypot(model.initial.w_x, model.initial.w_y);
  if (rate == 0) return tilt;
  // A tilt rate swings the body as far as rate / ω at the rocking's (slower) rest frequency.
  const Linearisation rest = linearise(model, 0);
  const double hz = std::min(rest.roll_hz > 0 ? rest.roll_hz : rest.pitch_hz,
                             rest.pitch_hz > 0 ? rest.pitch_hz : rest.roll_hz);
  return hz > 0 ? std::hypot(tilt, rate / (2 * M_PI * hz)) : tilt;
}

double eFoldsNeeded(const Model& model) {
  const double start = rockingStart(model);
  if (start <= 0) return std::numeric_limits<double>::infinity();
  return std::max(0.0, std::log(kRockingThatReverses / start));
}

bool growsEitherWay(const GrowthEachWay& growth, double efolds, double needed) {
  if (!(growth.ccw > growth.zero && growth.cw > growth.zero)) return false;
  // Growing is not enough: the rocking must grow from its start to some 14° before drag has
  // slowed the spin to where it no longer grows (docs/physics.md P8.4 gives the runs that set
  // the 14°, tests/theory_test.cpp ReversingEitherWayIsPredictedWhereRunsDoIt some of them).
  return efolds >= needed;
}

bool growsEitherWay(const Model& model, const GrowthEachWay& growth) {
  if (!(growth.ccw > growth.zero && growth.cw > growth.zero)) return false;
  return growsEitherWay(growth, eFoldsAgainstDrag(model, growth), eFoldsNeeded(model));
}

namespace {

// The CM's height over the floor with the body resting on it tilted so that Rᵀẑ = (u_x, u_y, ·).
double heightAt(const Body& body, double ux, double uy) {
  const Eigen::Vector3d u(ux, uy, std::sqrt(1 - ux * ux - uy * uy));
  return -lowestSurfacePoint(body, -u).dot(u);
}

// The Hessian of the potential energy M g h(u) at upright, J per unit u². Central second
// differences with ε = 1e-4: truncation ε² and rounding 1e-16 h/ε² are both below 1e-7 of K.
Eigen::Matrix2d tiltStiffness(const Model& model) {
  const Body& body = *model.body;
  const double eps = 1e-4, weight = body.mass * model.gravity;
  auto h = [&](double x, double y) { return heightAt(body, x * eps, y * eps); };
  Eigen::Matrix2d K;
  K(0, 0) = (h(1, 0) - 2 * h(0, 0) + h(-1, 0)) / (eps * eps);
  K(1, 1) = (h(0, 1) - 2 * h(0, 0) + h(0, -1)) / (eps * eps);
  K(0, 1) = K(1, 0) = (h(1, 1) - h(1, -1) - h(-1, 1) + h(-1, -1)) / (4 * eps * eps);
  return weight * K;
}

}  // namespace

std::optional<double> oneModeReversalTime(double n0, double k, double energy, double inertia) {
  if (!(k * n0 > 0) || !(energy > 0)) return std::nullopt;
  const double N = std::sqrt(n0 * n0 + 2 * energy / inertia);
  return std::atanh(std::abs(n0) / N) / (std::abs(k) * N);
}

std::optional<double> averagedReversalTime(const AveragedModes& m, double horizon) {
  using Vector3 = Eigen::Vector3d;  // (n, E_r, E_p)
  auto rates = [&](const Vector3& y) {
    return Vector3(-(m.drag * y(0) + 2 * (m.roll.k * y(1) + m.pitch.k * y(2))) / m.inertia,
                   2 * (m.roll.k * y(0) + m.roll.decay) * y(1),
                   2 * (m.pitch.k * y(0) + m.pitch.decay) * y(2));
  };
  // Classical Runge–Kutta at 1/100 of the fastest rate's time: its error (h⁴) is far below the
  // theory's own (first order in the spin). Not beyond 10⁵ of those times (10⁷ steps, well
  // under a second): what grows has grown by then, and what decays stays gone.
  const double fastest =
      std::max({std::abs(m.roll.k * m.spin), std::abs(m.pitch.k * m.spin), std::abs(m.roll.decay),
                std::abs(m.pitch.decay), m.drag / m.inertia, 1e-3});
  const double h = 0.01 / fastest;
  horizon = std::min(horizon, 1e5 / fastest);
  Vector3 y(m.spin, m.roll.energy, m.pitch.energy);
  // A zero of n counts as docs/physics.md P7's rule counts a reversal: once n has gone on to 1 %
  // of its start the new way. The sign is tested against the start's, not as n0·n1 ≤ 0: a spin
  // dying away under drag (the default body spun +5 rad/s) reached 1e-163 rad/s by 6,270 s,
  // where the product of two such spins underflows to zero and was taken for a crossing.
  const double threshold = 0.01 * std::abs(m.spin);
  std::optional<double> crossing;
  double sign = m.spin > 0 ? 1 : -1;
  for (double t = 0; t < horizon && m.spin != 0; t += h) {
    const Vector3 k1 = rates(y), k2 = rates(y + 0.5 * h * k1), k3 = rates(y + 0.5 * h * k2),
                  k4 = rates(y + h * k3);
    const Vector3 next = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    if (next(0) * sign <= 0 && y(0) * sign > 0) {
      // The zero on the cubic through the step's ends and slopes, by bisection.
      const double n0 = y(0), n1 = next(0), d0 = h * k1(0), d1 = h * rates(next)(0);
      auto cubic = [&](double s) {
        return (2 * s * s * s - 3 * s * s + 1) * n0 + (s * s * s - 2 * s * s + s) * d0 +
               (-2 * s * s * s + 3 * s * s) * n1 + (s * s * s - s * s) * d1;
      };
      double lo = 0, hi = 1;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (cubic(mid) * n0 > 0 ? lo : hi) = mid;
      }
      crossing = t + h * 0.5 * (lo + hi);
    } else if (crossing && next(0) * sign > 0) {
      crossing.reset();  // back the old way before it got anywhere
    }
    if (crossing && -next(0) * sign >= threshold) return *crossing;
    y = next;
  }
  return std::nullopt;
}

ReversalForecast forecastFirstReversal(const Model& model, double spin, double horizon) {
  ReversalForecast out;
  const Eigen::Vector3d u0 = (Eigen::AngleAxisd(model.initial.tilt_x, Eigen::Vector3d::UnitX()) *
                              Eigen::AngleAxisd(model.initial.tilt_y, Eigen::Vector3d::UnitY()))
                                 .toRotationMatrix()
                                 .transpose() *
                             Eigen::Vector3d::UnitZ();
  const Rest rest = restOf(model);
  out.applies = rest.stable;
  AveragedModes& modes = out.modes;
  modes.spin = spin * u0.z();
  modes.inertia = model.body->inertia(2, 2);
  modes.drag = model.contact.air_drag;
  out.spin_parameter = modes.spin * modes.spin * rest.radii.maxCoeff() / model.gravity;
  if (!out.applies) return out;

  // The tilt's share in each mode: the start (the tilt, no tilt rate: ω_body lies along the body
  // axis) taken apart into the modes of the conservative model spun at n, each mode's energy
  // the potential ½ aᴴ K a of its displacement a (kinetic and potential alike on average), and
  // the shares scaled to add up to the tilt's potential energy ½ u0ᵀ K u0, which is what the
  // averaged equations conserve with ½ C n² (P8.5). Taken apart at rest, where the modes do not
  // mix, a tilt about one principal axis put next to nothing in the other mode; spun, the modes
  // mix in proportion to n, and that mode, when it is the growing one (a pitch tilt spun the
  // preferred way), started some 360× larger than counted (3.6e-5 J against 1.0e-7 J, a 1°
  // pitch tilt at 4 rad/s): forecasts 23–110 % late, now 0.06–9 % late
  // (docs/physics.md P8.5). (The spin about the
  // tilted axis also starts the CM moving, by n ρ θ; that energy is second order in n and the
  // theory is first order: counting it made the forecasts worse.)
  Model conservative = asRolling(model);
  conservative.contact.air_drag = 0;
  const Eigen::Matrix4d J = jacobianAt(conservative, modes.spin).topLeftCorner<4, 4>();
  const Eigen::EigenSolver<Eigen::MatrixXd> solver{Eigen::MatrixXd(J)};
  const Eigen::MatrixXcd V = solver.eigenvectors();
  const Eigen::VectorXcd start = Eigen::Vector4cd(u0.x(), u0.y(), 0, 0);
  const Eigen::VectorXcd c = V.partialPivLu().solve(start);
  const Eigen::Matrix2d K = tiltStiffness(model);
  // Each mode's energy goes with the growth rate of the same mode (k below, from linearise): the
  // modes named as linearise names them, by frequency, the lower pair roll where at rest it
  // rocks more about the long axis (modePairs). Named each by its own eigenvector's roll excess,
  // both went to roll once deep dents turned the principal axes: dents.scale 0.65 forecast no
  // reversal where the run reversed at 0.70 s.
  const bool low_is_roll = modePairs(asRolling(model), 0).low_is_roll;
  std::vector<std::pair<double, double>> oscillations;  // (frequency, energy)
  for (int i = 0; i < 4; ++i) {
    if (solver.eigenvalues()(i).imag() <= 0) continue;  // one of each conjugate pair
    const Eigen::Vector2cd a = 2.0 * c(i) * V.col(i).head<2>();
    oscillations.emplace_back(solver.eigenvalues()(i).imag(),
                              0.5 * (a.adjoint() * K * a).real()(0, 0));
  }
  if (oscillations.size() != 2) {  // (a stable rest has two: defensive)
    out.applies = false;
    return out;
  }
  std::sort(oscillations.begin(), oscillations.end());
  (low_is_roll ? modes.roll : modes.pitch).energy = oscillations[0].second;
  (low_is_roll ? modes.pitch : modes.roll).energy = oscillations[1].second;
  out.tilt_energy = 0.5 * u0.head<2>().dot(K * u0.head<2>());
  // (Spun, the modes are not orthogonal in K: their energies add up to more than the tilt's,
  // 1.6× for a 1° pitch tilt at n²ρ/g = 0.65, the difference in the cross terms, which average
  // out as the modes drift apart.)
  const double shared = modes.roll.energy + modes.pitch.energy;
  if (shared > 0) {
    modes.roll.energy *= out.tilt_energy / shared;
    modes.pitch.energy *= out.tilt_energy / shared;
  }
  out.energy_ratio =
      2 * (modes.roll.energy + modes.pitch.energy) / (modes.inertia * modes.spin * modes.spin);

  const FirstOrder k = firstOrderGrowth(model);
  const Linearisation at_rest = linearise(model, 0);
  modes.roll.k = k.roll;
  modes.pitch.k = k.pitch;
  modes.roll.decay = at_rest.roll_growth;
  modes.pitch.decay = at_rest.pitch_growth;
  out.range = out.spin_parameter > 1 || out.energy_ratio > 1        ? ForecastRange::Outside
              : out.spin_parameter > 0.15 || out.energy_ratio > 0.1 ? ForecastRange::Beyond
                                                                    : ForecastRange::Within;
  if (out.range != ForecastRange::Outside) out.time = averagedReversalTime(modes, horizon);
  return out;
}

}  // namespace sim

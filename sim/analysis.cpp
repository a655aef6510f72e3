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
  k.w_world = k.R * w_body;
  k.v_world.setZero();
  const Eigen::Vector3d w_dot_body = k.R.transpose() * rollingMotion(rolling, k).w_dot_world;
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
  std::vector<std::complex<double>> all;
  std::array<std::complex<double>, 2> low, high;
  bool low_is_roll = true;
};

ModePairs modePairs(const Model& rolling, double spin) {
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
  const Eigen::EigenSolver<Matrix5d> solver(J);
  const Eigen::Matrix<std::complex<double>, 5, 5> vectors = solver.eigenvectors();
  ModePairs out;
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
  double roll = 0, pitch = 0;
  for (int k : {rest[0], rest[1]}) {
    roll += std::abs(vectors(0, k)) + std::abs(vectors(3, k));
    pitch += std::abs(vectors(1, k)) + std::abs(vectors(2, k));
  }
  out.low_is_roll = roll > pitch;
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

Direction preferredDirection(const Model& model, double spin_magnitude) {
  const double n = std::max(std::abs(spin_magnitude), 1e-3);
  const Linearisation ccw = linearise(model, n), cw = linearise(model, -n);
  const double ccw_fastest = std::max(ccw.roll_growth, ccw.pitch_growth);
  const double cw_fastest = std::max(cw.roll_growth, cw.pitch_growth);
  // Zero: below 1e-6 of the fastest rocking frequency, where the finite-difference Jacobian's
  // rates are noise (a skewed body without dents, q = 0.05, gave ±3e-11 /s at 40 rad/s and was
  // called "preferred cw"); a growth that slow would take 1e6 rocking periods to show. Alike:
  // within 1e-9 of the rates' size (rounding; a dentless body's differ by 1e-16 /s).
  const double omega = 2 * M_PI * std::max({ccw.roll_hz, ccw.pitch_hz, cw.roll_hz, cw.pitch_hz});
  const double zero = 1e-6 * omega;
  const double size = std::max({std::abs(ccw_fastest), std::abs(cw_fastest), 1e-12});
  if ((ccw_fastest <= zero && cw_fastest <= zero) ||
      std::abs(ccw_fastest - cw_fastest) <= std::max(1e-9 * size, zero))
    return Direction::None;
  return ccw_fastest < cw_fastest ? Direction::Ccw : Direction::Cw;
}

}  // namespace sim

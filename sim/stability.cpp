#include "sim/stability.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <vector>

#include "sim/contact_model.hpp"
#include "sim/initial.hpp"
#include "sim/integrator.hpp"

namespace sim {
namespace {

// Energy growth over a run of length T at step h stays below 2×: ρ^(2T/h) ≤ 2.
bool acceptable(Integrator integrator, double omega, double zeta, double h, double T) {
  const double rho = stepAmplification(integrator, omega, zeta, h);
  return 2 * (T / h) * std::log(rho) <= std::log(2.0);
}

// ω of the stiffest mode of the floor springs in contact with the body resting in pose R.
double stiffestMode(const Model& model, const Eigen::Matrix3d& R) {
  const double z_cm = restingHeight(model, R);
  std::vector<Eigen::Vector3d> springs;  // world axes, from the CM
  if (contactTraits(model.contact.model).touch == Touch::Spring) {
    springs.push_back(R * lowestSurfacePoint(*model.body, -R.row(2).transpose()));
  } else {
    for (const ContactPoints* p : {&model.body->bottom, &model.body->top})
      for (std::size_t i = 0; i < p->size(); ++i)
        if (z_cm + R.row(2).dot((*p)[i]) < 0) springs.push_back(R * (*p)[i]);
  }
  Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Eigen::Vector3d& r : springs) {
    Eigen::Matrix<double, 6, 1> J;
    J << Eigen::Vector3d::UnitZ(), r.cross(Eigen::Vector3d::UnitZ());
    K += model.contact.stiffness * J * J.transpose();
  }
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.topLeftCorner<3, 3>() = model.body->mass * Eigen::Matrix3d::Identity();
  M.bottomRightCorner<3, 3>() = R * model.body->inertia * R.transpose();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> modes(K, M);
  return std::sqrt(std::max(0.0, modes.eigenvalues().maxCoeff()));
}

}  // namespace

double stepAmplification(Integrator integrator, double omega, double zeta, double h) {
  // The spectral radius of a 2×2 matrix [a b; c e] from its characteristic polynomial
  // λ² − tλ + det: real roots t/2 ± √disc, or a complex pair of modulus √det, with the
  // discriminant written as ((a − e)/2)² + bc, free of the cancellation in t²/4 − det that at
  // small steps turns the oscillator's complex pair real. (Eigen's general eigensolver here made
  // this the slowest file to compile: 21 s and 1 GB, now 11 s.)
  // One step's matrix on y = (x, v) for the damped oscillator with rates J = [0 1; −ω² −2ζω];
  // an adaptive method's steps are chosen by error control, not checked here.
  const auto linear_step = integratorTraits(integrator).linear_step;
  if (!linear_step) return 1;
  Eigen::Matrix2d J;
  J << 0, 1, -omega * omega, -2 * zeta * omega;
  const Eigen::Matrix2d A = linear_step(h * J);
  const double half_difference = (A(0, 0) - A(1, 1)) / 2;
  const double disc = half_difference * half_difference + A(0, 1) * A(1, 0);
  if (disc < 0) return std::sqrt(A.determinant());
  return std::abs(A.trace()) / 2 + std::sqrt(disc);
}

ContactStability contactStability(const Model& model) {
  // Rolling has no contact spring: only the integrator's accuracy limits the step.
  if (heldOnFloor(model.contact.model))
    return {0, 0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  // The pose it starts nearest to: upright, or upside down on its top (a flat top carries
  // many more points than the bottom, hence much stiffer modes). A body that turns over
  // during a run onto a stiffer face is caught by run()'s energy bound instead.
  const Eigen::Vector3d up_in_body =
      (Eigen::AngleAxisd(model.initial.tilt_x, Eigen::Vector3d::UnitX()) *
       Eigen::AngleAxisd(model.initial.tilt_y, Eigen::Vector3d::UnitY()))
          .toRotationMatrix()
          .row(2)
          .transpose();
  const double roll = up_in_body.z() < 0 ? M_PI : 0.0;
  ContactStability out;
  out.omega =
      stiffestMode(model, Eigen::Matrix3d(Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX())));
  out.zeta = model.contact.damping * out.omega / (2 * model.contact.stiffness);
  if (out.omega == 0) {  // nothing presses on the floor (no gravity): no contact mode
    out.largest_step = out.run_step = std::numeric_limits<double>::infinity();
    return out;
  }
  // An adaptive integrator chooses its own steps: none to refuse.
  if (isAdaptive(model.integrator)) {
    out.largest_step = out.run_step = std::numeric_limits<double>::infinity();
    return out;
  }
  const double T = model.duration;
  // Walk h up geometrically until the growth bound fails, then bisect the last interval.
  double good = 1e-9 / out.omega, bad = good;
  while (bad < 10 / out.omega) {
    bad = good * 1.02;
    if (!acceptable(model.integrator, out.omega, out.zeta, bad, T)) break;
    good = bad;
  }
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (good + bad);
    (acceptable(model.integrator, out.omega, out.zeta, mid, T) ? good : bad) = mid;
  }
  out.largest_step = good;
  out.run_step = kRunMargin * good;
  return out;
}

}  // namespace sim

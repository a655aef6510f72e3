#include "sim/stability.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <vector>

#include "sim/initial.hpp"

namespace sim {
namespace {

// One step's matrix on y = (x, v) for the damped oscillator with rates J = [0 1; −ω² −2ζω].
Eigen::Matrix2d stepMatrix(Integrator integrator, double omega, double zeta, double h) {
  Eigen::Matrix2d J;
  J << 0, 1, -omega * omega, -2 * zeta * omega;
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const Eigen::Matrix2d hJ = h * J;
  switch (integrator) {
    case Integrator::Euler:
      return I + hJ;
    case Integrator::Symplectic: {
      // Kick v with the force at the old x and v, then drift x with the new v.
      Eigen::Matrix2d kick = I;
      kick.row(1) += hJ.row(1);
      Eigen::Matrix2d drift = I;
      drift(0, 1) = h;
      return drift * kick;
    }
    case Integrator::Rk4:
      return I + hJ + hJ * hJ / 2 + hJ * hJ * hJ / 6 + hJ * hJ * hJ * hJ / 24;
  }
  return I;
}

// Energy growth over a run of length T at step h stays below 2×: ρ^(2T/h) ≤ 2.
bool acceptable(Integrator integrator, double omega, double zeta, double h, double T) {
  const double rho = stepAmplification(integrator, omega, zeta, h);
  return 2 * (T / h) * std::log(rho) <= std::log(2.0);
}

}  // namespace

double stepAmplification(Integrator integrator, double omega, double zeta, double h) {
  return stepMatrix(integrator, omega, zeta, h).eigenvalues().cwiseAbs().maxCoeff();
}

ContactStability contactStability(const Model& model) {
  // Rolling has no contact spring: only the integrator's accuracy limits the step.
  if (model.contact.model == ContactModel::Rolling)
    return {0, 0, std::numeric_limits<double>::infinity()};
  // Springs in contact at the upright rest pose.
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const double z_cm = restingHeight(model, R);
  std::vector<Eigen::Vector3d> springs;  // body frame = world frame here
  if (model.contact.model == ContactModel::Smooth) {
    springs.push_back(lowestSurfacePoint(model.body, -Eigen::Vector3d::UnitZ()));
  } else {
    const ContactPoints& p = model.body.bottom;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (z_cm + p.z[i] < 0) springs.emplace_back(p.x[i], p.y[i], p.z[i]);
  }
  Eigen::Matrix<double, 6, 6> K = Eigen::Matrix<double, 6, 6>::Zero();
  for (const Eigen::Vector3d& r : springs) {
    Eigen::Matrix<double, 6, 1> J;
    J << Eigen::Vector3d::UnitZ(), r.cross(Eigen::Vector3d::UnitZ());
    K += model.contact.stiffness * J * J.transpose();
  }
  Eigen::Matrix<double, 6, 6> M = Eigen::Matrix<double, 6, 6>::Zero();
  M.topLeftCorner<3, 3>() = model.body.mass * Eigen::Matrix3d::Identity();
  M.bottomRightCorner<3, 3>() = model.body.inertia;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> modes(K, M);

  ContactStability out;
  out.omega = std::sqrt(std::max(0.0, modes.eigenvalues().maxCoeff()));
  out.zeta = model.contact.damping * out.omega / (2 * model.contact.stiffness);
  if (out.omega == 0) {  // nothing presses on the floor (no gravity): no contact mode
    out.largest_step = std::numeric_limits<double>::infinity();
    return out;
  }
  const double T = model.steps * model.dt;
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
  return out;
}

}  // namespace sim

// The body: the seed's grid, mass properties, principal axes.
#include <gtest/gtest.h>

#include <random>

#include "support.hpp"

using namespace testing_support;

// Seed §3.1–3.2: "There are a total of 4256 points taken here, and 602 of them on the surface
// … Red points are on the top plane and blue ones are on the bottom"; the issue gives 308 top,
// 294 bottom; mesh ranges x ∈ [−3.9, 3.9], y ∈ [−17.75, 17.75] (seed table, §3.1).
TEST(SeedGrid, CountsAndRangesMatchTheReport) {
  const sim::Model model = build(parse(kSeedScene));
  const sim::Body& body = *model.body;
  EXPECT_EQ(body.mass_properties.points, 4256);
  EXPECT_EQ(body.top.size(), 308u);
  EXPECT_EQ(body.bottom.size(), 294u);
  double x_min = 1e9, x_max = -1e9, y_min = 1e9, y_max = -1e9;
  for (std::size_t i = 0; i < body.top.size(); ++i) {
    const Eigen::Vector3d p = (body.top[i] + body.com_geometric) / 0.01;  // back to cm, geometric frame
    x_min = std::min(x_min, p.x());
    x_max = std::max(x_max, p.x());
    y_min = std::min(y_min, p.y());
    y_max = std::max(y_max, p.y());
  }
  // 1e-9 cm: the grid positions are products of whole numbers and the spacing.
  EXPECT_NEAR(x_min, -3.9, 1e-9);
  EXPECT_NEAR(x_max, 3.9, 1e-9);
  EXPECT_NEAR(y_min, -17.75, 1e-9);
  EXPECT_NEAR(y_max, 17.75, 1e-9);
}

// A tensor of a real mass distribution: symmetric, positive definite, and every principal
// moment no larger than the sum of the other two (I₁ + I₂ ≥ I₃, as Σ m z² ≥ 0).
TEST(MassProperties, InertiaIsAPhysicalTensor) {
  for (const char* yaml : {kSeedScene, kStableScene}) {
    const sim::MassProperties m = build(parse(yaml)).body->mass_properties;
    const double scale = m.inertia.norm();
    EXPECT_LT((m.inertia - m.inertia.transpose()).norm(), 1e-15 * scale);
    EXPECT_GT(m.principal.minCoeff(), 0);
    const Eigen::Vector3d I = m.principal;
    EXPECT_GE(I(0) + I(1), I(2));
    EXPECT_GE(I(1) + I(2), I(0));
    EXPECT_GE(I(0) + I(2), I(1));
    // The principal axes diagonalise it: Aᵀ I A = diag(I₁, I₂, I₃); 1e-12 relative is
    // rounding in a 3×3 eigen-decomposition.
    const Eigen::Matrix3d diagonal = m.axes.transpose() * m.inertia * m.axes;
    EXPECT_LT((diagonal - Eigen::Matrix3d(I.asDiagonal())).norm(), 1e-12 * scale);
    EXPECT_NEAR(m.axes.determinant(), 1.0, 1e-12);
  }
}

// Parallel-axis theorem: the inertia about any point, from the CM tensor and the mass,
// equals the brute-force sum Σ m (|p−P|² 1 − (p−P)(p−P)ᵀ) over the points.
TEST(MassProperties, ParallelAxisMatchesDirectSum) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  std::vector<Eigen::Vector3d> cloud(500);
  sim::PointMoments moments;
  for (auto& p : cloud) {
    p = Eigen::Vector3d(u(rng), 2 * u(rng), 0.5 * u(rng) + 0.03);
    moments.add(p);
  }
  const double mass = 0.7;
  const sim::MassProperties m = moments.properties(mass);
  for (const Eigen::Vector3d& P : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.02, -0.3, 0.1)}) {
    Eigen::Matrix3d direct = Eigen::Matrix3d::Zero();
    for (const auto& p : cloud) {
      const Eigen::Vector3d r = p - P;
      direct += mass / cloud.size() * (r.squaredNorm() * Eigen::Matrix3d::Identity() -
                                       r * r.transpose());
    }
    // 1e-12 relative: two summation orders of 500 terms in double precision.
    EXPECT_LT((sim::inertiaAbout(m, P) - direct).norm(), 1e-12 * direct.norm());
  }
}

// Without dents the body is a paraboloid cap of height H = top + a. Its cross-section at
// height u above the apex is an ellipse of area 2πau/√(ps), which gives (derived by
// integrating over u):  CM at 2H/3 above the apex, ⟨x²⟩ = aH/(3p), ⟨y²⟩ = aH/(3s),
// var z = H²/18, so Ixx = M(aH/3s + H²/18), Iyy = M(aH/3p + H²/18), Izz = M aH/3 (1/p + 1/s).
TEST(MassProperties, GridConvergesToTheContinuumParaboloid) {
  sim::SceneSpec spec = parse(kStableScene);
  spec.body.dents.reset();
  const double a = 0.01, p = 0.5, s = 0.03, H = 0.015, M = spec.body.mass;
  const Eigen::Vector3d exact(M * (a * H / (3 * s) + H * H / 18), M * (a * H / (3 * p) + H * H / 18),
                              M * a * H / 3 * (1 / p + 1 / s));
  std::vector<double> errors;
  for (double h : {0.04, 0.02, 0.01}) {  // grid spacing, cm
    spec.body.grid = {h, 2 * h, h / 2};
    const sim::MassProperties m = build(spec).body->mass_properties;
    const double com_height = m.com.z() + a;
    const Eigen::Vector3d diag = m.inertia.diagonal();
    errors.push_back(std::max(std::abs(com_height / (2 * H / 3) - 1),
                              ((diag - exact).cwiseQuotient(exact)).cwiseAbs().maxCoeff()));
  }
  // A uniform grid gains or misses part of a cell at the boundary: the error is first order
  // in h. Measured: 0.73%, 0.37%, 0.18%. Each halving must halve it (ratio 1.6–2.5 allows
  // for the boundary's irregular sampling), and at h = 0.01 cm it must be below 0.5%; a wrong
  // formula (say the H²/18 term dropped: 11% of Iyy) would fail both.
  EXPECT_GT(errors[0] / errors[1], 1.6);
  EXPECT_LT(errors[0] / errors[1], 2.5);
  EXPECT_GT(errors[1] / errors[2], 1.6);
  EXPECT_LT(errors[1] / errors[2], 2.5);
  EXPECT_LT(errors[2], 0.005);
}

// SPEC "The body": the default body's least-inertia axis is turned ≈ +2.2° from the long
// axis; mirroring the dents (x → −x) mirrors the angle.
TEST(MassProperties, MisalignmentOfTheDefaultBodyAndItsMirror) {
  sim::SceneSpec spec = parse(kStableScene);
  const double angle = build(spec).body->mass_properties.misalignment_deg;
  // ±0.1°: SPEC quotes one decimal ("≈ +2.2°"); the grid itself moves it by ~0.05°.
  EXPECT_NEAR(angle, 2.2, 0.1);
  spec.body.dents->at[0] *= -1;
  const double mirrored = build(spec).body->mass_properties.misalignment_deg;
  EXPECT_NEAR(mirrored, -angle, 1e-9);
}

// Exact mass properties of a closed triangle mesh (sim/mesh.hpp; docs/physics.md §P11) against
// closed forms derived independently of the code: a box, two tetrahedra, and meshes of a sphere
// and an ellipsoid converging to theirs at second order in the edge length.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh_shapes.hpp"

using namespace mesh_shapes;

namespace {

// Relative to the largest entry: the formulas are a few hundred floating-point operations on
// numbers of order one, so they agree with a closed form to rounding, 1e-13.
constexpr double kRounding = 1e-13;

void expectInertia(const Eigen::Matrix3d& got, const Eigen::Matrix3d& want, double tolerance) {
  const double scale = want.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(got(i, j), want(i, j), tolerance * scale) << "entry " << i << j;
}

}  // namespace

// A box a × b × c: V = abc, CM at its centre, I = m/12 diag(b² + c², a² + c², a² + b²).
TEST(MeshMass, BoxMatchesItsClosedForm) {
  const double a = 0.3, b = 2.0, c = 0.7, m = 5.0;
  const sim::TriangleMesh mesh = box(a, b, c);
  EXPECT_NEAR(sim::meshMoments(mesh).volume, a * b * c, kRounding);
  const sim::MassProperties p = sim::meshMassProperties(mesh, m);
  EXPECT_NEAR((p.com - Eigen::Vector3d(a / 2, b / 2, c / 2)).norm(), 0, kRounding);
  const Eigen::Vector3d d(b * b + c * c, a * a + c * c, a * a + b * b);
  expectInertia(p.inertia, Eigen::Matrix3d((m / 12 * d).asDiagonal()), kRounding);
}

TEST(MeshMass, UnitCubeHasUnitVolumeAndASixthOfItsMass) {
  const sim::MassProperties p = sim::meshMassProperties(box(1, 1, 1), 3.0);
  EXPECT_NEAR(sim::meshMoments(box(1, 1, 1)).volume, 1.0, kRounding);
  expectInertia(p.inertia, Eigen::Matrix3d::Identity() * 3.0 / 6, kRounding);
}

// The corner tetrahedron 0, (a,0,0), (0,b,0), (0,0,c), derived from the unit simplex's integrals
// ∫x² = 1/60, ∫xy = 1/120 (volume 1/6) scaled by the axes: V = abc/6, CM = (a, b, c)/4, and about
// the CM, I_xx = 3m(b² + c²)/80 and the product entry I_xy = −∫xy dm + m x̄ȳ = +m ab/80.
TEST(MeshMass, CornerTetrahedronMatchesItsClosedForm) {
  const double a = 1.0, b = 2.0, c = 3.0, m = 2.0;
  const sim::TriangleMesh mesh = cornerTetrahedron(a, b, c);
  EXPECT_NEAR(sim::meshMoments(mesh).volume, a * b * c / 6, kRounding);
  const sim::MassProperties p = sim::meshMassProperties(mesh, m);
  EXPECT_NEAR((p.com - Eigen::Vector3d(a, b, c) / 4).norm(), 0, kRounding);
  Eigen::Matrix3d want;
  want << 3 * m * (b * b + c * c) / 80, m * a * b / 80, m * a * c / 80,  //
      m * a * b / 80, 3 * m * (a * a + c * c) / 80, m * b * c / 80,      //
      m * a * c / 80, m * b * c / 80, 3 * m * (a * a + b * b) / 80;
  expectInertia(p.inertia, want, kRounding);
}

// A regular tetrahedron of edge L has an isotropic inertia m L²/20 about its centre (its
// symmetry group leaves no preferred axis); here L = 2√2, so 0.4 m, and volume L³/(6√2) = 8/3.
TEST(MeshMass, RegularTetrahedronIsIsotropic) {
  const sim::TriangleMesh mesh = regularTetrahedron();
  EXPECT_NEAR(sim::meshMoments(mesh).volume, 8.0 / 3, kRounding);
  const sim::MassProperties p = sim::meshMassProperties(mesh, 1.0);
  EXPECT_NEAR(p.com.norm(), 0, kRounding);
  expectInertia(p.inertia, Eigen::Matrix3d::Identity() * 0.4, kRounding);
}

// Moving and turning the mesh moves and turns its mass properties and nothing else: V' = V,
// CM' = R CM + t, I' = R I Rᵀ. The mesh is an ellipsoid's, with no symmetry that could hide a
// wrong axis, put 100 sizes away; rounding there is 1e-16 × 100² of the size², hence 1e-11.
TEST(MeshMass, MovingAndTurningTheMeshMovesAndTurnsItsMassProperties) {
  const sim::TriangleMesh mesh = icosphere(2, Eigen::Vector3d(0.5, 1.0, 0.3));
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(100, -50, 30);
  sim::TriangleMesh moved = mesh;
  for (auto& v : moved.vertices) v = R * v + t;
  const sim::MassProperties p = sim::meshMassProperties(mesh, 1.0);
  const sim::MassProperties q = sim::meshMassProperties(moved, 1.0);
  EXPECT_NEAR(sim::meshMoments(moved).volume, sim::meshMoments(mesh).volume, 1e-11);
  EXPECT_NEAR((q.com - (R * p.com + t)).norm(), 0, 1e-11);
  expectInertia(q.inertia, R * p.inertia * R.transpose(), 1e-11);
}

// An ellipsoid's inscribed icosphere mesh against the solid's I = m/5 diag(b² + c², a² + c²,
// a² + b²) (a sphere when the semi-axes are equal: 2/5 m r²). The mesh's faces are chords of the
// surface, h long, a sagitta h²/(8r) inside it: the error falls as h², by 4 each time the
// faces are split in four (h halves). Observed ratios (levels 2…5): 3.97, 3.99, 4.00 for the
// sphere, so the order is 2.00.
void expectSecondOrder(const Eigen::Vector3d& axes) {
  const Eigen::Vector3d sq = axes.cwiseProduct(axes);
  const Eigen::Vector3d want =
      Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y()) / 5;
  double previous = 0;
  for (int level = 2; level <= 5; ++level) {
    const sim::MassProperties p = sim::meshMassProperties(icosphere(level, axes), 1.0);
    const double error = (p.inertia.diagonal() - want).cwiseQuotient(want).cwiseAbs().maxCoeff();
    const double volume = sim::meshMoments(icosphere(level, axes)).volume;
    const double volume_error = std::abs(volume / (4 * M_PI / 3 * axes.prod()) - 1);
    if (level > 2) {
      std::printf("level %d: inertia error %.3e (ratio %.3f), volume error %.3e\n", level, error,
                  previous / error, volume_error);
      // Order 2 within 0.2: the ratio tends to 4 from below as the h⁴ term fades.
      EXPECT_NEAR(std::log2(previous / error), 2.0, 0.2) << "level " << level;
    }
    EXPECT_LT(volume_error, 5.0 / (1 << (2 * level)));  // ~ h², h ~ 1/2^level
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);  // level 5, 20480 faces: within 0.1 % of the solid
}

TEST(MeshMass, SphereMeshConvergesAtSecondOrder) {
  expectSecondOrder(Eigen::Vector3d(0.05, 0.05, 0.05));
}

TEST(MeshMass, EllipsoidMeshConvergesAtSecondOrder) {
  expectSecondOrder(Eigen::Vector3d(0.03, 0.2, 0.02));
}

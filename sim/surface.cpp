#include "sim/surface.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

namespace sim {

Eigen::Vector3d Ellipsoid::lowestPoint(const Eigen::Vector3d& down) const {
  const Eigen::Vector3d a2 = semi_axes.cwiseAbs2();
  const double s = std::sqrt(down.dot(a2.cwiseProduct(down)));
  return a2.cwiseProduct(down) / s;
}

PointAndRate Ellipsoid::lowestPointMoving(const Eigen::Vector3d& down,
                                          const Eigen::Vector3d& down_rate) const {
  const Eigen::Vector3d a2 = semi_axes.cwiseAbs2();
  const Eigen::Vector3d a2_down = a2.cwiseProduct(down), a2_rate = a2.cwiseProduct(down_rate);
  const double inverse_s = 1 / std::sqrt(down.dot(a2_down));
  PointAndRate out;
  out.point = a2_down * inverse_s;
  out.rate = (a2_rate - out.point * (down.dot(a2_rate) * inverse_s)) * inverse_s;
  return out;
}

Eigen::Vector3d MeshSurface::lowestPoint(const Eigen::Vector3d& down) const {
  Eigen::Vector3d lowest = Eigen::Vector3d::Zero();
  double reach = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : points)
    if (p.dot(down) > reach) {
      reach = p.dot(down);
      lowest = p;
    }
  return lowest;
}

namespace {

// A mesh's lowest point on its fitted bottom where there is one to reach (docs/physics.md
// §P11.4), else (the bottom unusable, or the body tipped beyond it) its lowest sampled point:
// the smooth models stop there (lowestOnRim), and the point only says where the body is.
PointAndRate meshLowest(const MeshSurface& mesh, const Eigen::Vector3d& down,
                        const Eigen::Vector3d& down_rate) {
  if (mesh.fit.usable() && down.z() < 0) {
    PointAndRate out = mesh.fit.lowestPointMoving(down, down_rate);
    if (out.point.allFinite()) return out;
  }
  return {mesh.lowestPoint(down), Eigen::Vector3d::Zero()};
}

}  // namespace

Eigen::Vector3d Surface::lowestPoint(const Eigen::Vector3d& down) const {
  if (kind == Kind::Mesh) {
    if (mesh.fit.usable() && down.z() < 0)
      if (const Eigen::Vector3d p = mesh.fit.lowestPoint(down); p.allFinite()) return p;
    return mesh.lowestPoint(down);
  }
  return kind == Kind::Ellipsoid ? ellipsoid.lowestPoint(down) : paraboloid.lowestPointOfBody(down);
}

PointAndRate Surface::lowestPointMoving(const Eigen::Vector3d& down,
                                        const Eigen::Vector3d& down_rate) const {
  if (kind == Kind::Mesh) return meshLowest(mesh, down, down_rate);
  return kind == Kind::Ellipsoid ? ellipsoid.lowestPointMoving(down, down_rate)
                                 : paraboloid.lowestPointMoving(down, down_rate);
}

Eigen::Vector2d Surface::radiiAtBottom() const {
  if (kind == Kind::Mesh)
    return mesh.fit.usable() ? mesh.fit.radiiAtApex()
                             : Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  if (kind == Kind::Ellipsoid) {
    // At (0, 0, −c) the radii are a²/c and b²/c.
    const Eigen::Vector3d& e = ellipsoid.semi_axes;
    const Eigen::Vector2d radii(e.x() * e.x() / e.z(), e.y() * e.y() / e.z());
    return radii.x() < radii.y() ? radii : Eigen::Vector2d(radii.y(), radii.x());
  }
  // The paraboloid's apex: radii are the inverse eigenvalues of [p/a, q/a²; q/a², s/a].
  const Paraboloid& s = paraboloid;
  Eigen::Matrix2d hessian;
  hessian << s.p / s.a, s.q / (s.a * s.a), s.q / (s.a * s.a), s.s / s.a;
  const Eigen::Vector2d curvatures =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian).eigenvalues();
  return {1 / curvatures(1), 1 / curvatures(0)};
}

Eigen::Vector2d Surface::footprintHalf() const {
  if (kind == Kind::Mesh)
    return mesh.low.head<2>().cwiseAbs().cwiseMax(mesh.high.head<2>().cwiseAbs());
  return kind == Kind::Ellipsoid ? Eigen::Vector2d(ellipsoid.semi_axes.head<2>())
                                 : paraboloid.rimHalfWidths();
}

Eigen::Vector3d Surface::boxLow() const {
  if (kind == Kind::Mesh) return mesh.low;
  // The paraboloid's lowest point is its apex, z = −a, at the origin (H is positive definite).
  return kind == Kind::Ellipsoid
             ? Eigen::Vector3d(-ellipsoid.semi_axes)
             : Eigen::Vector3d(-footprintHalf().x(), -footprintHalf().y(), -paraboloid.a);
}

Eigen::Vector3d Surface::boxHigh() const {
  if (kind == Kind::Mesh) return mesh.high;
  return kind == Kind::Ellipsoid
             ? Eigen::Vector3d(ellipsoid.semi_axes)
             : Eigen::Vector3d(footprintHalf().x(), footprintHalf().y(), paraboloid.top);
}

}  // namespace sim

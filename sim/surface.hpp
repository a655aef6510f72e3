// The body's smooth surface, where the `smooth` and `rolling` contacts touch: the seed's
// paraboloid body or an ellipsoid (docs/physics.md P1, P2). Geometric frame, metres.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "sim/body.hpp"
#include "sim/bottom_fit.hpp"

namespace sim {

/// x²/a² + y²/b² + z²/c² = 1 about the origin (Kane & Levinson 1982; Garcia & Hubbard 1988).
struct Ellipsoid {
  Eigen::Vector3d semi_axes;  ///< (a, b, c), m
  /// Lowest along `down`: p = A²d / √(dᵀA²d), A = diag(a, b, c).
  Eigen::Vector3d lowestPoint(const Eigen::Vector3d& down) const;
  /// That point and its rate ṗ = (A²ḋ − p (dᵀA²ḋ)/√(dᵀA²d)) / √(dᵀA²d).
  PointAndRate lowestPointMoving(const Eigen::Vector3d& down,
                                 const Eigen::Vector3d& down_rate) const;
};

/// A mesh body's surface (docs/physics.md §P11): the points sampled from it (sim/mesh_body.hpp),
/// its box, its volume and the smooth bottom fitted to it; geometric frame (the mesh file's, in
/// metres), m and m³. The smooth contacts touch the fitted bottom (where it is usable: compile
/// refuses them otherwise), `points` the sampled points.
struct MeshSurface {
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
  double volume = 0;
  BottomFit fit;
  /// The sampled point lowest along `down` (the largest p·down), m.
  Eigen::Vector3d lowestPoint(const Eigen::Vector3d& down) const;
};

struct Surface {
  enum class Kind { Paraboloid, Ellipsoid, Mesh };
  Kind kind = Kind::Paraboloid;
  Paraboloid paraboloid{1, 1, 0, 1, 0};
  Ellipsoid ellipsoid{Eigen::Vector3d::Ones()};
  MeshSurface mesh;

  /// The point lowest along `down` (unit, geometric frame), m.
  Eigen::Vector3d lowestPoint(const Eigen::Vector3d& down) const;
  /// Whether that point is on the rim of a paraboloid's flat top (never for an ellipsoid), or
  /// outside the cap of a mesh's fitted bottom: there the smooth surface ends, and rolling on it
  /// no longer applies.
  bool lowestOnRim(const Eigen::Vector3d& down) const {
    if (kind == Kind::Mesh) return mesh.fit.outsideCap(down);
    return kind == Kind::Paraboloid && paraboloid.lowestOnRim(down);
  }
  /// That point, and how fast it moves over the surface as `down` turns at `down_rate` (the
  /// two share their divisions), m and m/s.
  PointAndRate lowestPointMoving(const Eigen::Vector3d& down,
                                 const Eigen::Vector3d& down_rate) const;
  /// Principal radii of curvature at the point lowest when upright, ascending, m (a mesh's from
  /// its fitted bottom; NaN where that is not usable).
  Eigen::Vector2d radiiAtBottom() const;
  /// Half extents of the outline seen from above, across (x) and along (y), m.
  Eigen::Vector2d footprintHalf() const;
  /// Corners of the box that holds the closed body, geometric frame, m.
  Eigen::Vector3d boxLow() const;
  Eigen::Vector3d boxHigh() const;
};

}  // namespace sim

// The smooth bottom fitted to a mesh body (docs/physics.md §P11.4): where `smooth`, `rolling`
// and `auto` touch a mesh. A quadric, fitted by linear least squares to the mesh's bottom points
// over the cap where contact can happen, and used as a height function z = f(x, y). Geometric
// frame (the mesh file's), metres.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "sim/body.hpp"

namespace sim {

/// The steepest slope of the bottom a fit takes points from, and so the most a mesh body may tilt
/// under the smooth models: 30°, far beyond a rattleback's rocking (a few degrees), short of a
/// body on its side (docs/physics.md §P11.4).
inline constexpr double kFitSlopeLimitDeg = 30;
/// The RMS distance of the cap's points from the fit, as a fraction of the body's longest side,
/// above which the bottom is not smooth enough for the smooth models: 5e-4, 50 µm on a 10 cm toy
/// (docs/physics.md §P11.4 measures what passes: a mesh of Kane & Levinson's ellipsoid of 320
/// triangles, 2e-4, its radii 0.8 % off; a 2 % ripple on its bottom, 5.4e-4, does not).
inline constexpr double kFitRmsLimit = 5e-4;

/// The fitted bottom. About the origin o (the lowest bottom point of the mesh), with
/// (ξ, η, ζ) = p − o, the surface is the quadric
///   ζ = C(ξ, η) + ζ (b₁ξ + b₂η) + A ζ²,  C = c₀ + c₁ξ + c₂η + c₃ξ² + c₄ξη + c₅η²   (eq. P11.4)
/// whose lower sheet near o is the height function ζ = f(ξ, η). It holds every quadric whose ζ
/// term does not vanish at o: a paraboloid (A = b = 0) and an ellipsoid exactly.
struct BottomFit {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  ///< o, m
  std::array<double, 9> coef{};                      ///< c₀…c₅, b₁, b₂, A (SI)
  Eigen::Vector2d apex = Eigen::Vector2d::Zero();    ///< (ξ, η) where ∇f = 0, m
  Eigen::Matrix2d apex_hessian_inv = Eigen::Matrix2d::Identity();  ///< (∇²f)⁻¹ there, m
  /// tan of the largest tilt whose contact stays within the cap's points; NaN until measured
  double cap_slope = std::numeric_limits<double>::quiet_NaN();
  /// The cap's edge where it sets cap_slope is the bottom's own edge (the bottom meets the
  /// body's sides or rim there), not the fit's slope limit: a tilt past it rocks onto that edge.
  bool cap_meets_edge = false;
  /// RMS distance of the cap's points from the surface, m: NaN until measured (a fit refused
  /// before, too few points or no bowl), +∞ where the surface reaches none of them
  double rms_m = std::numeric_limits<double>::quiet_NaN();
  double max_m = std::numeric_limits<double>::quiet_NaN();  ///< the largest, m
  double size_m = 0;       ///< the body's longest side, m (the residual's scale)
  std::size_t points = 0;  ///< bottom points in the cap (the fit's data)
  std::string problem;     ///< why the smooth models cannot use it; empty when they can

  bool usable() const { return problem.empty(); }
  /// The height, slope and Hessian of f at (ξ, η): false where the sheet is not defined there.
  struct Jet {
    double z = 0;
    Eigen::Vector2d grad = Eigen::Vector2d::Zero();
    Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();
  };
  bool jet(const Eigen::Vector2d& xi, Jet& out) const;
  /// Whether the point lowest along `down` (unit, geometric frame) lies outside the cap: the
  /// surface's slope there, |(d_x, d_y)/d_z|, is the tilt's tangent.
  bool outsideCap(const Eigen::Vector3d& down) const {
    return !(down.z() < 0 && down.head<2>().norm() <= cap_slope * -down.z());
  }
  /// The point lowest along `down`: ∇f = g = −(d_x, d_y)/d_z by Newton's method from the
  /// apex's quadratic guess (eq. P11.5). m, geometric frame.
  Eigen::Vector3d lowestPoint(const Eigen::Vector3d& down) const;
  /// That point and its rate as `down` turns at `down_rate`: ∇²f (ξ̇, η̇) = ġ, ζ̇ = g·(ξ̇, η̇), the
  /// paraboloid's rule with f's Hessian at the point (eq. P11.5). m, m/s.
  PointAndRate lowestPointMoving(const Eigen::Vector3d& down,
                                 const Eigen::Vector3d& down_rate) const;
  /// The principal radii of curvature at the apex, ascending: 1/eigenvalues of ∇²f there. m.
  Eigen::Vector2d radiiAtApex() const;
  /// The long axis (the apex's principal curvature axis of the larger radius): its angle from x,
  /// counter-clockwise seen from above, radians.
  double longAxisAngle() const;
};

/// Fits the bottom of a mesh body to its bottom points `bottom` (one a column of the surface
/// points' grid, spacing `spacing`, sim/mesh_body.hpp), geometric frame, m; `size` is the body's
/// longest side, m. The cap: the columns reached from the lowest one through columns whose slope
/// (from their neighbours) is at most kFitSlopeLimitDeg. Sets `problem` where the result is not
/// a smooth bowl the smooth models can roll on.
BottomFit fitBottom(const std::vector<Eigen::Vector3d>& bottom, double spacing, double size);

}  // namespace sim

// The paraboloid body of the seed (§3.1–3.2): its surface, its point grid and
// its mass properties. All lengths here are metres, in the body's geometric
// frame: x the short axis, y the long axis, z up; the origin is the seed's,
// on the paraboloid's axis at height a above its apex.
#pragma once

#include <Eigen/Dense>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace sim {

/// A point of a surface and its velocity over it (m, m/s).
struct PointAndRate {
  Eigen::Vector3d point, rate;
};

/// Paraboloid shape in metres: bottom z = p/(2a) x² + q/a² xy + s/(2a) y² − a
/// (docs/physics.md P1; the seed's eq. 24), flat top at z = top.
struct Paraboloid {
  double a, p, q, s, top;
  /// H⁻¹ with H = [p/a, q/a²; q/a², s/a] the bottom's Hessian: derived once, here, from the
  /// five numbers above (every contact evaluation needs it).
  Eigen::Matrix2d hessian_inv;

  Paraboloid(double a_, double p_, double q_, double s_, double top_);
  /// Height of the bottom surface above (x, y), m.
  double bottom(double x, double y) const { return xx_ * x * x + xy_ * x * y + yy_ * y * y - a; }
  /// Half-widths of the top rim ellipse along x and y, m.
  Eigen::Vector2d rimHalfWidths() const;
  /// The bottom's long axis (its principal curvature axis of the smaller curvature, the larger
  /// radius): its angle from x, counter-clockwise seen from above, radians. π/2 (y) when q = 0
  /// and s < p; q turns it.
  double longAxisAngle() const;
  /// The point of the bottom surface lowest along `down` (a unit vector in the geometric
  /// frame, down.z < 0): where the outward normal (f_x, f_y, −1) is parallel to `down`, i.e.
  /// H (x, y) = −(down_x, down_y)/down_z with H the Hessian [p/a, q/a²; q/a², s/a]. Metres.
  Eigen::Vector3d lowestPoint(const Eigen::Vector3d& down) const;
  /// The same on the closed body (bottom below its rim, flat top): when the bottom's lowest
  /// point lies outside the rim, the lowest point is on the rim ellipse z = top, where
  /// ½ uᵀHu = top + a: u = √(2(top+a)) H⁻¹d / √(dᵀH⁻¹d) with d = (down_x, down_y). Metres.
  Eigen::Vector3d lowestPointOfBody(const Eigen::Vector3d& down) const;
  /// Whether the body's lowest point along `down` lies on the rim of the flat top (the body is
  /// tipped past the bottom's edge or upside down) rather than on the smooth bottom.
  bool lowestOnRim(const Eigen::Vector3d& down) const;
  /// lowestPointOfBody, and how fast the lowest point moves over the bottom when `down`
  /// turns at `down_rate`: with g = −(d_x, d_y)/d_z, ġ = −(ḋ_x, ḋ_y)/d_z − g ḋ_z/d_z,
  /// (ẋ, ẏ) = H⁻¹ ġ and ż = g·(ẋ, ẏ) (the surface's slope is g there). m, m/s.
  PointAndRate lowestPointMoving(const Eigen::Vector3d& down,
                                 const Eigen::Vector3d& down_rate) const;

 private:
  double xx_, xy_, yy_;  // p/(2a), q/a², s/(2a): bottom()'s coefficients, divided once
  // The bottom's point whose slope is g = −(d_x, d_y)/d_z: (x, y) = H⁻¹ g.
  Eigen::Vector3d pointAtSlope(const Eigen::Vector2d& g) const {
    const Eigen::Vector2d xy = hessian_inv * g;
    return {xy.x(), xy.y(), bottom(xy.x(), xy.y())};
  }
};

/// Two dents z = p/(2a k²)(x ∓ m_x)² + s/(2a k²)(y ∓ m_y)² − (a − inset) k cut from
/// the top (seed appendix; the second dent at (−m_x, −m_y)). Metres.
struct Dents {
  double scale;  ///< k
  double mx, my;
  double inset;
  /// Height of the lower of the two dent surfaces above (x, y), m: grid points at
  /// or above it are removed.
  double surface(const Paraboloid& shape, double x, double y) const;
};

/// Uniform grid spacing, m.
struct Grid {
  double dx, dy, dz;
};

/// Surface points of the grid, in the geometric frame (m).
struct SurfacePoints {
  std::vector<Eigen::Vector3d> top;     ///< topmost point of each column (red)
  std::vector<Eigen::Vector3d> bottom;  ///< lowest point of each column (blue)
};

/// Mass properties of a uniform-density point cloud.
struct MassProperties {
  std::int64_t points = 0;    ///< grid points inside the body
  double mass = 0;            ///< kg
  Eigen::Vector3d com;        ///< centre of mass in the geometric frame, m
  Eigen::Matrix3d inertia;    ///< about the CM, geometric axes, kg m²
  Eigen::Vector3d principal;  ///< principal moments, ascending, kg m²
  Eigen::Matrix3d axes;       ///< columns: principal axes (geometric frame), right-handed
  double misalignment_deg =
      0;  ///< from the long axis (y, or x when the least-inertia axis lies nearer x) to the
          ///< least-inertia axis's horizontal projection, + counter-clockwise about z
};

/// Running moments of a cloud of equal point masses: Σ1, Σp, Σ p pᵀ (geometric frame, m).
class PointMoments {
 public:
  void add(const Eigen::Vector3d& p) { addColumn(p.x(), p.y(), 1, p.z(), p.z() * p.z()); }
  /// `n` points at (x, y) whose z values sum to `sum_z` and whose squares sum to `sum_zz`.
  void addColumn(double x, double y, std::int64_t n, double sum_z, double sum_zz);
  /// Mass properties of `mass` kg spread evenly over the points:
  /// com = Σp/N, I = M (tr C · 1 − C) with C = Σ p pᵀ/N − com comᵀ.
  MassProperties properties(double mass) const;

 private:
  std::int64_t count_ = 0;
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_outer_ = Eigen::Matrix3d::Zero();
};

/// Inertia about `point` (geometric frame) by the parallel-axis theorem:
/// I_P = I_cm + M (|d|² 1 − d dᵀ), d = com − point. kg m².
Eigen::Matrix3d inertiaAbout(const MassProperties& m, const Eigen::Vector3d& point);

/// The grid columns are at half-offset positions x = (i + ½) dx, y = (j + ½) dy, symmetric
/// about the origin with none on x = 0 or y = 0 (the seed's odd-point rule, §3.1), covering
/// the top rim; z runs down from the top in steps of dz. A point belongs to the body when it
/// is on or above the bottom and below the dents. Returns the number of grid points.
std::int64_t estimateGridPoints(const Paraboloid& shape, const Grid& grid);

/// One column of the grid that holds points: its position and the levels k = first … last
/// of its points, z_k = top − k dz (computed exactly so). `ring_x`, `ring_y` count columns
/// outwards from the axes on the column's side (0 next to the axis).
struct GridColumn {
  double x, y;      ///< m, geometric frame
  int first, last;  ///< levels of the topmost and lowest point
  int ring_x, ring_y;
};

/// Calls `visit(column)` for each column that holds points, rows of y outermost, in the order
/// the grid has always been walked, until `visit` returns false. A column's levels come in closed
/// form (then checked against the exact comparisons at the ends), so the walk costs one step a
/// column, not one a point: the default body's 3.2 million points in 120,000 columns.
void forEachColumn(const Paraboloid& shape, const std::optional<Dents>& dents, const Grid& grid,
                   const std::function<bool(const GridColumn&)>& visit);

/// What the grid holds without building it: point counts and the surface points' bounding box.
struct GridCensus {
  std::int64_t points = 0;           ///< all grid points inside the body
  std::int64_t top = 0, bottom = 0;  ///< surface points, red and blue
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(),
                  hi = Eigen::Vector3d::Zero();  ///< geometric frame, m
};
GridCensus gridCensus(const Paraboloid& shape, const std::optional<Dents>& dents, const Grid& grid);

/// Whether some column holds two points or more (a body with a bottom): the walk stops there.
bool gridHasTwoLevels(const Paraboloid& shape, const std::optional<Dents>& dents, const Grid& grid);

/// The surface points (top and bottom of every column) in the geometric frame, of the columns
/// whose ring indices along x and y are both multiples of `stride` (1: all of them).
SurfacePoints gridSurface(const Paraboloid& shape, const std::optional<Dents>& dents,
                          const Grid& grid, int stride = 1);

/// Mass properties of `mass` kg spread evenly over the grid's points (a sum over every point,
/// in the walk's order).
MassProperties gridMassProperties(const Paraboloid& shape, const std::optional<Dents>& dents,
                                  const Grid& grid, double mass);

/// Principal moments, axes and misalignment angle of an inertia tensor (kg m²).
void principalAxes(MassProperties& m);

/// The misalignment (docs/physics.md P1.6) against a long axis at `long_axis_rad` from x
/// (counter-clockwise): the angle from it to the horizontal projection of the least-inertia
/// axis, counter-clockwise about z, degrees in (−90, 90].
double misalignmentDeg(const MassProperties& m, double long_axis_rad);

}  // namespace sim

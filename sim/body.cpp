#include "sim/body.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace sim {
namespace {

// Number of half-offset grid columns on one side of the origin that lie within `half_width`:
// positions (i + ½) d for i = 0 … n−1 with (n − ½) d ≤ half_width (seed §3.1: x ∈ ±3.9 for
// a half-width of 4 and d = 0.52).
int halfColumns(double half_width, double d) {
  return static_cast<int>(std::floor(half_width / d + 0.5));
}

// Number of z levels below the top: z_k = top − k dz for k = 0 … n, down to the apex.
int zLevels(const Paraboloid& shape, double dz) {
  return static_cast<int>(std::floor((shape.top + shape.a) / dz + 1e-9));
}

}  // namespace

double Paraboloid::longAxisAngle() const {
  // [A, B; B, C] = H has its larger curvature along ½ atan2(2B, A − C) from x; the long axis is
  // across it.
  return 0.5 * std::atan2(2 * q / (a * a), p / a - s / a) + M_PI / 2;
}

Paraboloid::Paraboloid(double a_, double p_, double q_, double s_, double top_)
    : a(a_),
      p(p_),
      q(q_),
      s(s_),
      top(top_),
      xx_(p_ / (2 * a_)),
      xy_(q_ / (a_ * a_)),
      yy_(s_ / (2 * a_)) {
  Eigen::Matrix2d hessian;
  hessian << p / a, q / (a * a), q / (a * a), s / a;
  hessian_inv = hessian.inverse();
}

Eigen::Vector2d Paraboloid::rimHalfWidths() const {
  // The rim is the ellipse ½ uᵀ H u = top + a with H the bottom's Hessian; its half-width
  // along an axis is sqrt(2 (top + a) (H⁻¹)_ii).
  const Eigen::Matrix2d& inverse = hessian_inv;
  const double height = top + a;
  return {std::sqrt(2 * height * inverse(0, 0)), std::sqrt(2 * height * inverse(1, 1))};
}

Eigen::Vector3d Paraboloid::lowestPoint(const Eigen::Vector3d& down) const {
  return pointAtSlope(Eigen::Vector2d(-down.x() / down.z(), -down.y() / down.z()));
}

bool Paraboloid::lowestOnRim(const Eigen::Vector3d& down) const {
  return !(down.z() < 0 && lowestPoint(down).z() <= top);
}

Eigen::Vector3d Paraboloid::lowestPointOfBody(const Eigen::Vector3d& down) const {
  // lowestOnRim's test, with the point it finds kept (it was found twice an evaluation).
  if (down.z() < 0)
    if (const Eigen::Vector3d bottom_point = lowestPoint(down); bottom_point.z() <= top)
      return bottom_point;
  const Eigen::Matrix2d& inverse = hessian_inv;
  const Eigen::Vector2d d = down.head<2>();
  const double norm = std::sqrt(d.dot(inverse * d));
  if (norm == 0) return {0, 0, top};
  const Eigen::Vector2d u = std::sqrt(2 * (top + a)) * inverse * d / norm;
  return {u.x(), u.y(), top};
}

PointAndRate Paraboloid::lowestPointMoving(const Eigen::Vector3d& down,
                                           const Eigen::Vector3d& down_rate) const {
  const double inverse_z = 1 / down.z();
  const Eigen::Vector2d g = -down.head<2>() * inverse_z;
  const Eigen::Vector2d g_rate = (-down_rate.head<2>() - g * down_rate.z()) * inverse_z;
  const Eigen::Vector2d xy_rate = hessian_inv * g_rate;
  PointAndRate out;
  out.rate = {xy_rate.x(), xy_rate.y(), g.dot(xy_rate)};
  out.point = pointAtSlope(g);
  if (!(down.z() < 0 && out.point.z() <= top)) out.point = lowestPointOfBody(down);  // on the rim
  return out;
}

double Dents::surface(const Paraboloid& shape, double x, double y) const {
  const double cx = shape.p / (2 * shape.a * scale * scale);
  const double cy = shape.s / (2 * shape.a * scale * scale);
  const double first = cx * (x - mx) * (x - mx) + cy * (y - my) * (y - my);
  const double second = cx * (x + mx) * (x + mx) + cy * (y + my) * (y + my);
  return std::min(first, second) - (shape.a - inset) * scale;
}

std::int64_t estimateGridPoints(const Paraboloid& shape, const Grid& grid) {
  // In floating point throughout: a spacing typed wrong (1e-9) makes counts past any integer,
  // and halfColumns' and zLevels' int would overflow (and pass the check below as negative).
  const Eigen::Vector2d half = shape.rimHalfWidths();
  const double columns =
      4.0 * std::floor(half.x() / grid.dx + 0.5) * std::floor(half.y() / grid.dy + 0.5);
  const double levels = std::floor((shape.top + shape.a) / grid.dz + 1e-9) + 1.0;
  if (!std::isfinite(columns * levels)) return std::numeric_limits<std::int64_t>::max();
  const double bound = columns * levels;  // the bounding box: an upper bound
  return bound > 9e18 ? std::numeric_limits<std::int64_t>::max() : static_cast<std::int64_t>(bound);
}

namespace {

// The last level k ≤ nz whose z_k = top − k dz is ≥ z_bottom, or −1: a guess from the
// division, then moved by the same comparison the levels are defined by (z_k falls with k in
// floating point too, so the set of such k is an interval from 0).
int lastLevelAbove(const Paraboloid& shape, double dz, int nz, double z_bottom) {
  const auto z = [&](int k) { return shape.top - k * dz; };
  const double guess = std::floor((shape.top - z_bottom) / dz);  // NaN: every level passes
  int k =
      std::isnan(guess) ? nz : static_cast<int>(std::clamp(guess, -1.0, static_cast<double>(nz)));
  while (k < nz && z(k + 1) >= z_bottom) ++k;
  while (k >= 0 && z(k) < z_bottom) --k;
  return k;
}

// The first level k ≥ 0 whose z_k is below z_dent (nz + 1 when none is).
int firstLevelBelow(const Paraboloid& shape, double dz, int nz, double z_dent) {
  const auto z = [&](int k) { return shape.top - k * dz; };
  if (!(z(0) >= z_dent)) return 0;  // no dent here (z_dent = +inf, or NaN), or below the top
  const double guess = std::floor((shape.top - z_dent) / dz) + 1;
  int k =
      std::isnan(guess) ? 0 : static_cast<int>(std::clamp(guess, 0.0, static_cast<double>(nz) + 1));
  while (k > 0 && !(z(k - 1) >= z_dent)) --k;
  while (k <= nz && z(k) >= z_dent) ++k;
  return k;
}

}  // namespace

void forEachColumn(const Paraboloid& shape, const std::optional<Dents>& dents, const Grid& grid,
                   const std::function<bool(const GridColumn&)>& visit) {
  const Eigen::Vector2d half = shape.rimHalfWidths();
  const int nx = halfColumns(half.x(), grid.dx);
  const int ny = halfColumns(half.y(), grid.dy);
  const int nz = zLevels(shape, grid.dz);
  for (int j = -ny; j < ny; ++j) {
    const double y = (j + 0.5) * grid.dy;
    for (int i = -nx; i < nx; ++i) {
      const double x = (i + 0.5) * grid.dx;
      const double z_bottom = shape.bottom(x, y);
      if (z_bottom > shape.top) continue;
      const double z_dent =
          dents ? dents->surface(shape, x, y) : std::numeric_limits<double>::infinity();
      // The column's points: z_k = top − k dz with z_bottom ≤ z_k < z_dent (seed appendix).
      GridColumn column{x,
                        y,
                        firstLevelBelow(shape, grid.dz, nz, z_dent),
                        lastLevelAbove(shape, grid.dz, nz, z_bottom),
                        i < 0 ? -i - 1 : i,
                        j < 0 ? -j - 1 : j};
      if (column.first <= column.last && !visit(column)) return;
    }
  }
}

GridCensus gridCensus(const Paraboloid& shape, const std::optional<Dents>& dents,
                      const Grid& grid) {
  GridCensus census;
  bool any = false;
  auto include = [&](const Eigen::Vector3d& p) {
    census.lo = any ? Eigen::Vector3d(census.lo.cwiseMin(p)) : p;
    census.hi = any ? Eigen::Vector3d(census.hi.cwiseMax(p)) : p;
    any = true;
  };
  forEachColumn(shape, dents, grid, [&](const GridColumn& c) {
    census.points += c.last - c.first + 1;
    ++census.top;
    include({c.x, c.y, shape.top - c.first * grid.dz});
    if (c.last != c.first) {
      ++census.bottom;
      include({c.x, c.y, shape.top - c.last * grid.dz});
    }
    return true;
  });
  return census;
}

bool gridHasTwoLevels(const Paraboloid& shape, const std::optional<Dents>& dents,
                      const Grid& grid) {
  bool found = false;
  forEachColumn(shape, dents, grid, [&](const GridColumn& c) {
    found = c.last > c.first;
    return !found;
  });
  return found;
}

SurfacePoints gridSurface(const Paraboloid& shape, const std::optional<Dents>& dents,
                          const Grid& grid, int stride) {
  // The column's topmost point is on the top (red), its lowest on the bottom (blue); a
  // one-point column is top only (seed §3.1 figures: 308 + 294 = 602).
  SurfacePoints out;
  forEachColumn(shape, dents, grid, [&](const GridColumn& c) {
    if (c.ring_x % stride != 0 || c.ring_y % stride != 0) return true;
    out.top.emplace_back(c.x, c.y, shape.top - c.first * grid.dz);
    if (c.last != c.first) out.bottom.emplace_back(c.x, c.y, shape.top - c.last * grid.dz);
    return true;
  });
  return out;
}

MassProperties gridMassProperties(const Paraboloid& shape, const std::optional<Dents>& dents,
                                  const Grid& grid, double mass) {
  PointMoments moments;
  forEachColumn(shape, dents, grid, [&](const GridColumn& c) {
    double sum_z = 0, sum_zz = 0;
    for (int k = c.first; k <= c.last; ++k) {
      const double z = shape.top - k * grid.dz;
      sum_z += z;
      sum_zz += z * z;
    }
    moments.addColumn(c.x, c.y, c.last - c.first + 1, sum_z, sum_zz);
    return true;
  });
  return moments.properties(mass);
}

void PointMoments::addColumn(double x, double y, std::int64_t n, double sum_z, double sum_zz) {
  const double count = static_cast<double>(n);
  count_ += n;
  sum_ += Eigen::Vector3d(count * x, count * y, sum_z);
  sum_outer_(0, 0) += count * x * x;
  sum_outer_(1, 1) += count * y * y;
  sum_outer_(0, 1) += count * x * y;
  sum_outer_(0, 2) += x * sum_z;
  sum_outer_(1, 2) += y * sum_z;
  sum_outer_(2, 2) += sum_zz;
}

MassProperties PointMoments::properties(double mass) const {
  MassProperties m;
  m.points = count_;
  m.mass = mass;
  if (count_ == 0) return m;
  const double n = static_cast<double>(count_);
  Eigen::Matrix3d outer = sum_outer_.selfadjointView<Eigen::Upper>();
  m.com = sum_ / n;
  const Eigen::Matrix3d covariance = outer / n - m.com * m.com.transpose();
  m.inertia = mass * (covariance.trace() * Eigen::Matrix3d::Identity() - covariance);
  principalAxes(m);
  return m;
}

Eigen::Matrix3d inertiaAbout(const MassProperties& m, const Eigen::Vector3d& point) {
  const Eigen::Vector3d d = m.com - point;
  return m.inertia + m.mass * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
}

void principalAxes(MassProperties& m) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(m.inertia);
  m.principal = solver.eigenvalues();  // ascending
  m.axes = solver.eigenvectors();
  // The long axis is the horizontal body axis the least-inertia axis lies nearest: y for the
  // shipped bodies, x for a body long in x (measured from y, such a body's 0.8° read
  // as 89.2°). Orient: the least-inertia axis points along the long axis's + side, the largest
  // along +z, and the set is right-handed.
  const bool long_in_x = std::abs(m.axes.col(0).x()) > std::abs(m.axes.col(0).y());
  if ((long_in_x ? m.axes.col(0).x() : m.axes.col(0).y()) < 0) m.axes.col(0) *= -1;
  if (m.axes.col(2).z() < 0) m.axes.col(2) *= -1;
  m.axes.col(1) = m.axes.col(2).cross(m.axes.col(0));
  // Misalignment: angle from the long axis to the horizontal projection of the least-inertia
  // axis, positive counter-clockwise about +z (≈ +2.2° for the default body).
  const Eigen::Vector3d least = m.axes.col(0);
  m.misalignment_deg =
      (long_in_x ? std::atan2(least.y(), least.x()) : std::atan2(-least.x(), least.y())) * 180.0 /
      M_PI;
}

double misalignmentDeg(const MassProperties& m, double long_axis_rad) {
  const Eigen::Vector3d least = m.axes.col(0);
  // An axis is a line: the difference of two of them is folded into (−90°, 90°].
  double d = std::remainder(std::atan2(least.y(), least.x()) - long_axis_rad, M_PI);
  if (d <= -M_PI / 2) d += M_PI;
  return d * 180.0 / M_PI;
}

}  // namespace sim

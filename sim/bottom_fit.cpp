#include "sim/bottom_fit.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "util/format.hpp"

namespace sim {

bool BottomFit::jet(const Eigen::Vector2d& xi, Jet& out) const {
  const auto& [c0, c1, c2, c3, c4, c5, b1, b2, A] = coef;
  const double x = xi.x(), y = xi.y();
  const double C = c0 + c1 * x + c2 * y + c3 * x * x + c4 * x * y + c5 * y * y;
  const double B = 1 - b1 * x - b2 * y;
  const double D = B * B - 4 * A * C;
  if (!(B > 0 && D > 0)) return false;
  // G(ξ, η, ζ) = Aζ² − Bζ + C = 0 (eq. P11.4); its root nearest 0, in the form that holds as
  // A → 0 (the paraboloid), has G_ζ = 2Aζ − B = −√D.
  const double root = std::sqrt(D);
  out.z = 2 * C / (B + root);
  const double z = out.z;
  // Implicit differentiation (eq. P11.4's note): f_i = −G_i/G_ζ and
  // f_ij = −(G_ij + G_iζ f_j + G_jζ f_i + G_ζζ f_i f_j)/G_ζ.
  out.grad =
      Eigen::Vector2d(c1 + 2 * c3 * x + c4 * y + b1 * z, c2 + c4 * x + 2 * c5 * y + b2 * z) / root;
  const Eigen::Vector2d& g = out.grad;
  const double b[2] = {b1, b2};
  const double second[2][2] = {{2 * c3, c4}, {c4, 2 * c5}};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      out.hessian(i, j) = (second[i][j] + b[i] * g(j) + b[j] * g(i) + 2 * A * g(i) * g(j)) / root;
  return true;
}

namespace {

// The 2×2 solve M x = r by the inverse in closed form.
Eigen::Vector2d solve2(const Eigen::Matrix2d& M, const Eigen::Vector2d& r) {
  const double det = M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0);
  return Eigen::Vector2d(M(1, 1) * r.x() - M(0, 1) * r.y(), M(0, 0) * r.y() - M(1, 0) * r.x()) /
         det;
}

// Newton's method for ∇f(ξ) = g from the apex's quadratic guess: the (ξ, η) found and the jet
// there, or false. Stops once a step is below 1e-13 of the body's size: convergence is quadratic,
// so the point is then exact to rounding, and varies smoothly with g (dopri5's error control
// sees no steps in it).
bool solveSlope(const BottomFit& fit, const Eigen::Vector2d& g, Eigen::Vector2d& xi,
                BottomFit::Jet& jet) {
  xi = fit.apex + fit.apex_hessian_inv * g;
  for (int k = 0; k < 40; ++k) {
    if (!fit.jet(xi, jet)) return false;
    const Eigen::Vector2d step = solve2(jet.hessian, jet.grad - g);
    xi -= step;
    if (!(step.norm() > 1e-13 * fit.size_m)) return fit.jet(xi, jet);
  }
  return false;
}

Eigen::Vector2d slopeOf(const Eigen::Vector3d& down) {
  return -down.head<2>() / down.z();
}

}  // namespace

Eigen::Vector3d BottomFit::lowestPoint(const Eigen::Vector3d& down) const {
  Eigen::Vector2d xi;
  Jet j;
  if (!(down.z() < 0) || !solveSlope(*this, slopeOf(down), xi, j))
    return Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  return origin + Eigen::Vector3d(xi.x(), xi.y(), j.z);
}

PointAndRate BottomFit::lowestPointMoving(const Eigen::Vector3d& down,
                                          const Eigen::Vector3d& down_rate) const {
  PointAndRate out;
  Eigen::Vector2d xi;
  Jet j;
  if (!(down.z() < 0) || !solveSlope(*this, slopeOf(down), xi, j)) {
    out.point = out.rate = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
    return out;
  }
  // ġ = −(ḋ_x, ḋ_y)/d_z − g ḋ_z/d_z (as the paraboloid's, sim/body.hpp).
  const Eigen::Vector2d g = slopeOf(down);
  const Eigen::Vector2d g_rate = (-down_rate.head<2>() - g * down_rate.z()) / down.z();
  const Eigen::Vector2d xi_rate = solve2(j.hessian, g_rate);
  out.point = origin + Eigen::Vector3d(xi.x(), xi.y(), j.z);
  out.rate = {xi_rate.x(), xi_rate.y(), g.dot(xi_rate)};
  return out;
}

Eigen::Vector2d BottomFit::radiiAtApex() const {
  Jet j;
  if (!jet(apex, j)) return Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  // At the apex the slope is 0, so the curvatures are the Hessian's eigenvalues.
  const Eigen::Vector2d k = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(j.hessian).eigenvalues();
  return {1 / k(1), 1 / k(0)};
}

double BottomFit::longAxisAngle() const {
  Jet j;
  if (!jet(apex, j)) return M_PI / 2;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(j.hessian);
  const Eigen::Vector2d v = solver.eigenvectors().col(0);  // the smaller curvature
  const double angle = std::atan2(v.y(), v.x());
  return angle < 0 ? angle + M_PI : angle;
}

namespace {

// The bottom points as a grid of columns (i, j) at ((i + ½)h, (j + ½)h), the index of each
// column's point or −1.
struct ColumnGrid {
  long i0 = 0, j0 = 0, nx = 0, ny = 0;
  std::vector<long> index;
  long at(long i, long j) const {
    if (i < 0 || j < 0 || i >= nx || j >= ny) return -1;
    return index[static_cast<std::size_t>(j * nx + i)];
  }
};

ColumnGrid columnGrid(const std::vector<Eigen::Vector3d>& bottom, double h) {
  ColumnGrid grid;
  long i_lo = std::numeric_limits<long>::max(), j_lo = i_lo, i_hi = -i_lo, j_hi = -i_lo;
  auto column = [h](double v) { return std::lround(v / h - 0.5); };
  for (const auto& p : bottom) {
    i_lo = std::min(i_lo, column(p.x())), i_hi = std::max(i_hi, column(p.x()));
    j_lo = std::min(j_lo, column(p.y())), j_hi = std::max(j_hi, column(p.y()));
  }
  grid.i0 = i_lo, grid.j0 = j_lo, grid.nx = i_hi - i_lo + 1, grid.ny = j_hi - j_lo + 1;
  grid.index.assign(static_cast<std::size_t>(grid.nx * grid.ny), -1);
  for (std::size_t k = 0; k < bottom.size(); ++k)
    grid.index[static_cast<std::size_t>((column(bottom[k].y()) - grid.j0) * grid.nx +
                                        column(bottom[k].x()) - grid.i0)] = static_cast<long>(k);
  return grid;
}

constexpr long kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// The cap: the columns reached from the lowest through columns whose four neighbours are points
// and whose central-difference slope is at most tan(kFitSlopeLimitDeg). Indices into `bottom`.
std::vector<long> capColumns(const std::vector<Eigen::Vector3d>& bottom, const ColumnGrid& grid,
                             double h) {
  const double limit = std::tan(kFitSlopeLimitDeg * M_PI / 180);
  auto gentle = [&](long i, long j) {
    const long e = grid.at(i + 1, j), w = grid.at(i - 1, j), n = grid.at(i, j + 1),
               s = grid.at(i, j - 1);
    if (e < 0 || w < 0 || n < 0 || s < 0) return false;
    const Eigen::Vector2d slope(bottom[e].z() - bottom[w].z(), bottom[n].z() - bottom[s].z());
    return slope.norm() / (2 * h) <= limit;
  };
  // From the lowest column that has its four neighbours (a flat bottom's lowest may be an edge).
  long lowest = -1;
  for (long j = 0; j < grid.ny; ++j)
    for (long i = 0; i < grid.nx; ++i) {
      const long k = grid.at(i, j);
      if (k < 0 || grid.at(i + 1, j) < 0 || grid.at(i - 1, j) < 0 || grid.at(i, j + 1) < 0 ||
          grid.at(i, j - 1) < 0)
        continue;
      if (lowest < 0 || bottom[k].z() < bottom[lowest].z()) lowest = k;
    }
  if (lowest < 0) return {};
  std::vector<char> seen(grid.index.size(), 0);
  std::vector<std::pair<long, long>> stack;
  auto column = [h](double v) { return std::lround(v / h - 0.5); };
  stack.emplace_back(column(bottom[lowest].x()) - grid.i0, column(bottom[lowest].y()) - grid.j0);
  std::vector<long> cap;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    const long k = grid.at(i, j);
    if (k < 0 || seen[static_cast<std::size_t>(j * grid.nx + i)]) continue;
    seen[static_cast<std::size_t>(j * grid.nx + i)] = 1;
    if (!gentle(i, j)) continue;
    cap.push_back(k);
    for (const auto& d : kNeighbours) stack.emplace_back(i + d[0], j + d[1]);
  }
  return cap;
}

// Least squares for eq. P11.4's nine coefficients over the cap: ζ = [1, ξ, η, ξ², ξη, η², ξζ,
// ηζ, ζ²]·θ, linear in θ. Columns scaled to unit norm first (ξ² and ζ² are 1e-4 of 1 for a body
// of centimetres); QR with column pivoting.
void fitCoefficients(const std::vector<Eigen::Vector3d>& local, BottomFit& fit) {
  Eigen::MatrixXd X(local.size(), 9);
  Eigen::VectorXd z(local.size());
  for (std::size_t k = 0; k < local.size(); ++k) {
    const double x = local[k].x(), y = local[k].y(), c = local[k].z();
    X.row(static_cast<Eigen::Index>(k)) << 1, x, y, x * x, x * y, y * y, x * c, y * c, c * c;
    z(static_cast<Eigen::Index>(k)) = c;
  }
  const Eigen::VectorXd scale = X.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::VectorXd theta =
      (X * scale.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(z).cwiseQuotient(scale);
  for (int i = 0; i < 9; ++i) fit.coef[static_cast<std::size_t>(i)] = theta(i);
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g %%", 100 * fraction);
  return text;
}

// The apex (∇f = 0, by Newton from the origin) and its Hessian: a bowl where that is positive
// definite.
bool findApex(BottomFit& fit) {
  fit.apex.setZero();
  fit.apex_hessian_inv.setZero();  // Newton's first guess is then the origin itself
  Eigen::Vector2d xi;
  BottomFit::Jet j;
  if (!solveSlope(fit, Eigen::Vector2d::Zero(), xi, j)) return false;
  fit.apex = xi;
  if (!(j.hessian.determinant() > 0 && j.hessian.trace() > 0)) return false;
  fit.apex_hessian_inv = j.hessian.inverse();
  return true;
}

// A cap column's place: inside the cap, on its edge where the bottom goes on steeper than the
// fit takes, or on its edge where the bottom itself ends (a neighbour missing, or one that is on
// the bottom's boundary: capColumns takes no column without its four neighbours).
enum CapPlace : char { kInside = 0, kSlopeEdge = 1, kBottomEdge = 2 };

// RMS and largest distance of the cap's points from the surface (|Δζ| cos of the slope), and
// the cap's slope: the least fitted slope over the cap's edge columns (a tilt whose contact
// point is no steeper stays among the cap's points), and whether that column is at the
// bottom's edge. The number of points the surface does not reach (its sheet ends before them:
// a quadric fitted to a bottom that is none).
std::size_t measure(const std::vector<Eigen::Vector3d>& local, const std::vector<char>& edge,
                    BottomFit& fit) {
  double sum = 0;
  std::size_t missed = 0;
  fit.max_m = 0;
  fit.cap_slope = std::tan(kFitSlopeLimitDeg * M_PI / 180);
  for (std::size_t k = 0; k < local.size(); ++k) {
    BottomFit::Jet j;
    if (!fit.jet(local[k].head<2>(), j)) {
      ++missed;
      continue;
    }
    const double d = std::abs(local[k].z() - j.z) / std::sqrt(1 + j.grad.squaredNorm());
    sum += d * d;
    fit.max_m = std::max(fit.max_m, d);
    if (edge[k] != kInside && j.grad.norm() < fit.cap_slope) {
      fit.cap_slope = j.grad.norm();
      fit.cap_meets_edge = edge[k] == kBottomEdge;
    }
  }
  fit.rms_m = missed < local.size() ? std::sqrt(sum / static_cast<double>(local.size() - missed))
                                    : std::numeric_limits<double>::infinity();
  return missed;
}

}  // namespace

BottomFit fitBottom(const std::vector<Eigen::Vector3d>& bottom, double h, double size) {
  BottomFit fit;
  fit.size_m = size;
  if (bottom.empty()) {
    fit.problem = "the mesh has no bottom points";
    return fit;
  }
  const ColumnGrid grid = columnGrid(bottom, h);
  const std::vector<long> cap = capColumns(bottom, grid, h);
  fit.points = cap.size();
  // Nine coefficients, and enough points around the lowest for them to mean a surface.
  if (cap.size() < 25) {
    fit.problem = "only " + std::to_string(cap.size()) +
                  " bottom points lie in the cap around its lowest point (slope at most " +
                  rb::show(kFitSlopeLimitDeg) + "°), too few to fit a surface to (25 at least)";
    return fit;
  }
  std::size_t lowest = 0;
  for (std::size_t k = 1; k < cap.size(); ++k)
    if (bottom[cap[k]].z() < bottom[cap[lowest]].z()) lowest = k;
  fit.origin = bottom[cap[lowest]];
  std::vector<Eigen::Vector3d> local;
  std::vector<char> in_cap(bottom.size(), 0), edge;
  for (long k : cap) local.push_back(bottom[k] - fit.origin), in_cap[k] = 1;
  auto column = [h](double v) { return std::lround(v / h - 0.5); };
  auto bottomsEdge = [&](long i, long j) {  // a column missing, or one without its four
    if (grid.at(i, j) < 0) return true;
    for (const auto& d : kNeighbours)
      if (grid.at(i + d[0], j + d[1]) < 0) return true;
    return false;
  };
  for (long k : cap) {
    const long i = column(bottom[k].x()) - grid.i0, j = column(bottom[k].y()) - grid.j0;
    char place = kInside;
    for (const auto& d : kNeighbours) {
      const long n = grid.at(i + d[0], j + d[1]);
      if (n >= 0 && in_cap[n]) continue;
      place = std::max<char>(place, bottomsEdge(i + d[0], j + d[1]) ? kBottomEdge : kSlopeEdge);
    }
    edge.push_back(place);
  }
  fitCoefficients(local, fit);
  if (!findApex(fit)) {
    fit.problem =
        "the quadric fitted to it is not a bowl (no lowest point with both curvatures up: a flat "
        "or saddle-shaped bottom)";
    return fit;
  }
  const std::size_t missed = measure(local, edge, fit);
  const std::string residual = rb::show(fit.rms_m) + " m RMS (" + percent(fit.rms_m / size) +
                               " of its length; largest " + rb::show(fit.max_m) + " m)";
  if (missed > 0)
    fit.problem = "the quadric fitted to its points ends before " + std::to_string(missed) +
                  " of the " + std::to_string(local.size()) + " do, and the rest lie " + residual +
                  " from it: the bottom is not smooth enough";
  else if (fit.rms_m > kFitRmsLimit * size)
    fit.problem = "its points lie " + residual + " from the quadric fitted to them, above " +
                  percent(kFitRmsLimit) + ": the bottom is not smooth enough";
  return fit;
}

}  // namespace sim

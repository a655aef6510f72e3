#include "sim/continuum.hpp"

#include <algorithm>
#include <array>
#include <boost/container/small_vector.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <unsupported/Eigen/Polynomials>
#include <vector>

namespace sim {
namespace {

// A surface z = A x² + B xy + C y² + D x + E y + F over the plane (m); differences of two such
// surfaces are of the same form, so every curve where two of the body's surfaces meet is a
// conic.
struct Quadric {
  double A = 0, B = 0, C = 0, D = 0, E = 0, F = 0;

  double operator()(double x, double y) const {
    return A * x * x + B * x * y + C * y * y + D * x + E * y + F;
  }
  Quadric operator-(const Quadric& o) const {
    return {A - o.A, B - o.B, C - o.C, D - o.D, E - o.E, F - o.F};
  }
};

Quadric bottomOf(const Paraboloid& shape) {
  return {shape.p / (2 * shape.a),
          shape.q / (shape.a * shape.a),
          shape.s / (2 * shape.a),
          0,
          0,
          -shape.a};
}

Quadric plane(double z) {
  return {0, 0, 0, 0, 0, z};
}

// The dents' paraboloids (sim::Dents::surface, seed appendix): curvatures p/(2ak²) and
// s/(2ak²), apex (a − inset) k below the origin, at ±(m_x, m_y).
struct DentShape {
  double cx, cy, depth;
  Eigen::Vector2d center;
};

std::array<DentShape, 2> dentShapes(const Paraboloid& shape, const Dents& d) {
  const double cx = shape.p / (2 * shape.a * d.scale * d.scale);
  const double cy = shape.s / (2 * shape.a * d.scale * d.scale);
  const double depth = (shape.a - d.inset) * d.scale;
  return {DentShape{cx, cy, depth, {d.mx, d.my}}, DentShape{cx, cy, depth, {-d.mx, -d.my}}};
}

Quadric quadricOf(const DentShape& d) {
  const double x0 = d.center.x(), y0 = d.center.y();
  return {d.cx, 0, d.cy, -2 * d.cx * x0, -2 * d.cy * y0, d.cx * x0 * x0 + d.cy * y0 * y0 - d.depth};
}

// Where a line crosses the surfaces' meeting curves: two roots for each pair of at most four
// surfaces (the bottom, the top and two dents), held without a heap allocation (Boost's
// small_vector; the vectors these were made one for every line, a third of a dented body's
// cubature).
using Cuts = boost::container::small_vector<double, 16>;

// Real roots of c2 y² + c1 y + c0 = 0 (a line when c2 is 0), appended to `out`.
void appendRoots(double c2, double c1, double c0, Cuts& out) {
  const double scale = std::abs(c2) + std::abs(c1) + std::abs(c0);
  if (std::abs(c2) <= 1e-15 * scale) {
    if (c1 != 0) out.push_back(-c0 / c1);
    return;
  }
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return;
  // The root without cancellation first, the other from the product c0/c2.
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  if (q != 0) out.push_back(c0 / q);
  out.push_back(q / c2);
}

// The x where the conic Q(x, y) = 0 has a vertical tangent: the y-discriminant
// (Bx + E)² − 4C(Ax² + Dx + F) vanishes there. Where these lie, columns appear or vanish.
void appendTangentXs(const Quadric& Q, Cuts& out) {
  appendRoots(Q.B * Q.B - 4 * Q.A * Q.C, 2 * Q.B * Q.E - 4 * Q.C * Q.D, Q.E * Q.E - 4 * Q.C * Q.F,
              out);
}

// A polynomial in t of degree ≤ 4, lowest power first.
using Quartic = std::array<double, 5>;

Quartic times(const Quartic& p, const Quartic& q) {
  Quartic r{};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; i + j < 5; ++j) r[i + j] += p[i] * q[j];
  return r;
}

Quartic minus(const Quartic& p, const Quartic& q) {
  Quartic r;
  for (int i = 0; i < 5; ++i) r[i] = p[i] - q[i];
  return r;
}

// The x where the conics P = 0 and Q = 0 meet (at most four): where, as quadratics in y, they
// have a root in common, that is where their resultant (a quartic in x) vanishes. Solved in
// t = x / half, where its coefficients are of one scale, by the eigenvalues of its companion
// matrix (Eigen's PolynomialSolver); the real roots in [−half, half] are appended.
void appendMeetingXs(const Quadric& P, const Quadric& Q, double half, Cuts& out) {
  // Coefficients of y², y, 1 as polynomials in t.
  const Quartic a2{P.C}, a1{P.E, P.B * half}, a0{P.F, P.D * half, P.A * half * half};
  const Quartic b2{Q.C}, b1{Q.E, Q.B * half}, b0{Q.F, Q.D * half, Q.A * half * half};
  const Quartic u = minus(times(a2, b0), times(b2, a0)), v = minus(times(a2, b1), times(b2, a1)),
                w = minus(times(a1, b0), times(b1, a0));
  const Quartic r = minus(times(u, u), times(v, w));
  double scale = 0;
  for (double c : r) scale = std::max(scale, std::abs(c));
  int degree = 4;
  while (degree > 0 && std::abs(r[degree]) <= 1e-12 * scale) --degree;
  if (degree == 0) return;  // no meeting, or the same curve
  Eigen::VectorXd poly(degree + 1);
  for (int i = 0; i <= degree; ++i) poly[i] = r[i];
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(poly);
  for (const std::complex<double>& root : solver.roots())
    if (std::abs(root.imag()) <= 1e-6 && std::abs(root.real()) < 1)
      out.push_back(root.real() * half);
}

// The body's surfaces: the bottom, and the lowest of the top and the dents over it.
struct Surfaces {
  Quadric bottom;
  std::vector<Quadric> ceilings;  // top, then the dents
};

Surfaces surfacesOf(const Paraboloid& shape, const std::optional<Dents>& dents) {
  Surfaces s{bottomOf(shape), {plane(shape.top)}};
  if (dents)
    for (const DentShape& d : dentShapes(shape, *dents)) s.ceilings.push_back(quadricOf(d));
  return s;
}

// ∫ over the column at (x, y) of 1, z, z² (m, m², m³): from the bottom up to the ceiling.
using ColumnSums = Eigen::Matrix<double, 6, 1>;  // ∫L, ∫yL, ∫y²L, ∫Z1, ∫yZ1, ∫Z2 over y

// One line x = const through the body: the y-integrals of the column moments. Between two
// consecutive points where two of the surfaces cross the line, the column runs from the bottom
// to one ceiling, both quadratic in y, so the integrands are polynomials of degree ≤ 6 and
// 7-point Gauss–Legendre (exact to degree 13) gives them to rounding.
ColumnSums lineIntegrals(const Surfaces& s, double x) {
  Cuts cuts;
  const Quadric rim = s.bottom - s.ceilings.front();
  appendRoots(rim.C, rim.B * x + rim.E, rim.A * x * x + rim.D * x + rim.F, cuts);
  if (cuts.size() < 2) return ColumnSums::Zero();
  const double lo = std::min(cuts[0], cuts[1]), hi = std::max(cuts[0], cuts[1]);
  cuts = {lo, hi};
  boost::container::small_vector<const Quadric*, 4> all{&s.bottom};
  for (const Quadric& c : s.ceilings) all.push_back(&c);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const Quadric d = *all[i] - *all[j];
      appendRoots(d.C, d.B * x + d.E, d.A * x * x + d.D * x + d.F, cuts);
    }
  std::sort(cuts.begin(), cuts.end());

  using GL = boost::math::quadrature::gauss<double, 7>;
  ColumnSums sums = ColumnSums::Zero();
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double y0 = std::max(cuts[k], lo), y1 = std::min(cuts[k + 1], hi);
    if (!(y1 > y0)) continue;
    const double mid = 0.5 * (y0 + y1), half = 0.5 * (y1 - y0);
    const Quadric* ceiling = &s.ceilings.front();
    for (const Quadric& c : s.ceilings)
      if (c(x, mid) < (*ceiling)(x, mid)) ceiling = &c;
    if (!((*ceiling)(x, mid) > s.bottom(x, mid))) continue;  // no body over this piece
    auto add = [&](double y, double w) {
      const double z0 = s.bottom(x, y), z1 = (*ceiling)(x, y);
      const double L = z1 - z0, Z1 = (z1 * z1 - z0 * z0) / 2,
                   Z2 = (z1 * z1 * z1 - z0 * z0 * z0) / 3;
      sums += w * half * (ColumnSums() << L, y * L, y * y * L, Z1, y * Z1, Z2).finished();
    };
    for (std::size_t n = 0; n < GL::abscissa().size(); ++n) {  // the nodes ≥ 0, mirrored
      add(mid + half * GL::abscissa()[n], GL::weights()[n]);
      if (GL::abscissa()[n] != 0) add(mid - half * GL::abscissa()[n], GL::weights()[n]);
    }
  }
  return sums;
}

// The ten volume moments as functions of x: V, Sx, Sy, Sz, Pxx, Pxy, Pyy, Pxz, Pyz, Pzz.
using Moments10 = Eigen::Matrix<double, 10, 1>;

Moments10 slab(const Surfaces& s, double x) {
  const ColumnSums c = lineIntegrals(s, x);
  Moments10 m;
  m << c[0], x * c[0], c[1], c[3], x * x * c[0], x * c[1], c[2], x * c[3], c[4], c[5];
  return m;
}

// Gauss–Kronrod 31-point estimate over [a, b] (Boost.Math's nodes and weights), with the
// embedded 15-point Gauss estimate and the L1 integral of each component.
struct Estimate {
  Moments10 kronrod = Moments10::Zero(), gauss = Moments10::Zero(), l1 = Moments10::Zero();
};

template <class F>
Estimate gaussKronrod(const F& f, double a, double b) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  using G = boost::math::quadrature::gauss<double, 15>;
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  Estimate e;
  const Moments10 f0 = f(mid);
  e.kronrod = f0 * GK::weights()[0];
  e.gauss = f0 * G::weights()[0];
  e.l1 = f0.cwiseAbs() * GK::weights()[0];
  for (std::size_t i = 1; i < GK::abscissa().size(); ++i) {
    const Moments10 fp = f(mid + half * GK::abscissa()[i]), fm = f(mid - half * GK::abscissa()[i]);
    e.kronrod += (fp + fm) * GK::weights()[i];
    e.l1 += (fp.cwiseAbs() + fm.cwiseAbs()) * GK::weights()[i];
    if (i % 2 == 0) e.gauss += (fp + fm) * G::weights()[i / 2];
  }
  e.kronrod *= half;
  e.gauss *= half;
  e.l1 *= half;
  return e;
}

// Adaptive bisection: an interval is accepted when Kronrod and Gauss agree within its share of
// the tolerance (halved with each split) in every component.
// `e` is the estimate over [a, b] itself (the first level's comes from the pass that set the
// scales: computing it twice had been half of a dented body's cubature when no piece splits).
template <class F>
Moments10 adaptive(const F& f, double a, double b, const Estimate& e, const Moments10& tolerance,
                   int depth) {
  if (((e.kronrod - e.gauss).cwiseAbs().array() <= tolerance.array()).all() || depth == 0)
    return e.kronrod;
  const double mid = 0.5 * (a + b);
  return adaptive(f, a, mid, gaussKronrod(f, a, mid), tolerance / 2, depth - 1) +
         adaptive(f, mid, b, gaussKronrod(f, mid, b), tolerance / 2, depth - 1);
}

VolumeMoments momentsOf(const Moments10& m) {
  VolumeMoments v;
  v.volume = m[0];
  v.first = {m[1], m[2], m[3]};
  v.second << m[4], m[5], m[7], m[5], m[6], m[8], m[7], m[8], m[9];
  return v;
}

// The smallest value of the conic Q over the ellipse {cx u² + cy v² ≤ h} around `center`:
// an interior critical point when Q is convex, else the boundary, sampled and then refined by
// golden-section search (a degree-2 trigonometric polynomial has at most two minima).
double minimumOverEllipse(const Quadric& Q, const DentShape& d, double h) {
  const double rx = std::sqrt(h / d.cx), ry = std::sqrt(h / d.cy);
  double best = std::numeric_limits<double>::infinity();
  Eigen::Matrix2d hess;
  hess << 2 * Q.A, Q.B, Q.B, 2 * Q.C;
  if (hess.determinant() > 0 && hess(0, 0) > 0) {
    const Eigen::Vector2d p = hess.ldlt().solve(Eigen::Vector2d(-Q.D, -Q.E));
    const Eigen::Vector2d u = p - d.center;
    if (d.cx * u.x() * u.x() + d.cy * u.y() * u.y() <= h) best = Q(p.x(), p.y());
  }
  auto onRim = [&](double theta) {
    return Q(d.center.x() + rx * std::cos(theta), d.center.y() + ry * std::sin(theta));
  };
  constexpr int kSamples = 720;
  int k_best = 0;
  for (int k = 0; k < kSamples; ++k)
    if (onRim(2 * M_PI * k / kSamples) < onRim(2 * M_PI * k_best / kSamples)) k_best = k;
  double lo = 2 * M_PI * (k_best - 1) / kSamples, hi = 2 * M_PI * (k_best + 1) / kSamples;
  const double ratio = (std::sqrt(5.0) - 1) / 2;
  while (hi - lo > 1e-12) {
    const double m1 = hi - ratio * (hi - lo), m2 = lo + ratio * (hi - lo);
    if (onRim(m1) < onRim(m2))
      hi = m2;
    else
      lo = m1;
  }
  return std::min(best, onRim(0.5 * (lo + hi)));
}

}  // namespace

VolumeMoments& VolumeMoments::operator-=(const VolumeMoments& o) {
  volume -= o.volume;
  first -= o.first;
  second -= o.second;
  return *this;
}

MassProperties VolumeMoments::properties(double mass) const {
  MassProperties m;
  m.mass = mass;
  m.com = first / volume;
  const Eigen::Matrix3d covariance = second / volume - m.com * m.com.transpose();
  m.inertia = mass * (covariance.trace() * Eigen::Matrix3d::Identity() - covariance);
  principalAxes(m);
  return m;
}

VolumeMoments paraboloidCapMoments(const Eigen::Matrix2d& hessian, const Eigen::Vector2d& center,
                                   double apex_z, double height) {
  VolumeMoments v;
  if (!(height > 0)) return v;
  v.volume = M_PI * height * height / std::sqrt(hessian.determinant());
  const Eigen::Vector3d mean(center.x(), center.y(), apex_z + 2 * height / 3);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  covariance.topLeftCorner<2, 2>() = height / 3 * hessian.inverse();
  covariance(2, 2) = height * height / 18;
  v.first = v.volume * mean;
  v.second = v.volume * (covariance + mean * mean.transpose());
  return v;
}

std::optional<VolumeMoments> closedFormMoments(const Paraboloid& shape,
                                               const std::optional<Dents>& dents) {
  Eigen::Matrix2d hessian;
  hessian << shape.p / shape.a, shape.q / (shape.a * shape.a), shape.q / (shape.a * shape.a),
      shape.s / shape.a;
  VolumeMoments body =
      paraboloidCapMoments(hessian, Eigen::Vector2d::Zero(), -shape.a, shape.top + shape.a);
  if (!dents) return body;
  const std::array<DentShape, 2> cuts = dentShapes(shape, *dents);
  const double h = shape.top + cuts[0].depth;  // each cut's height below the top
  if (!(h > 0)) return body;                   // the dents' apexes are above the top
  // The cuts meet where both lie below the top. Their difference is linear (equal curvatures),
  // zero on a line through the origin, and on it both equal cx m_x² + cy m_y² − depth there.
  const DentShape& d = cuts[0];
  const double meet =
      d.cx * d.center.x() * d.center.x() + d.cy * d.center.y() * d.center.y() - d.depth;
  if (meet < shape.top) return std::nullopt;
  const Quadric bottom = bottomOf(shape);
  for (const DentShape& cut : cuts) {
    // Wholly inside: over the cut's ellipse at the top, the dent stays above the bottom.
    if (minimumOverEllipse(quadricOf(cut) - bottom, cut, h) < 0) return std::nullopt;
    const Eigen::Matrix2d dent_hessian = Eigen::Vector2d(2 * cut.cx, 2 * cut.cy).asDiagonal();
    body -= paraboloidCapMoments(dent_hessian, cut.center, -cut.depth, h);
  }
  return body;
}

VolumeMoments cubatureMoments(const Paraboloid& shape, const std::optional<Dents>& dents,
                              double tolerance) {
  const Surfaces surfaces = surfacesOf(shape, dents);
  // Split x where columns appear or vanish (a vertical tangent of any meeting curve), so each
  // piece's integrand is smooth inside, with at most a square-root behaviour at its ends.
  const double half = shape.rimHalfWidths().x();
  Cuts xs{-half, half};
  boost::container::small_vector<const Quadric*, 4> all{&surfaces.bottom};
  for (const Quadric& c : surfaces.ceilings) all.push_back(&c);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) appendTangentXs(*all[i] - *all[j], xs);
  // And where three surfaces meet: there the lowest ceiling changes, and the integrand has a
  // kink that no split found (a dented body's cubature bisected down to them).
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j)
      for (std::size_t k = j + 1; k < all.size(); ++k)
        appendMeetingXs(*all[i] - *all[j], *all[i] - *all[k], half, xs);
  xs.erase(std::remove_if(xs.begin(), xs.end(), [&](double x) { return !(std::abs(x) <= half); }),
           xs.end());
  std::sort(xs.begin(), xs.end());

  // Each piece [a, b] is integrated over θ in [0, π] with x = (a + b)/2 − (b − a)/2 cos θ, so
  // dx = (b − a)/2 sin θ dθ: a square-root behaviour at an end, b − x = (b − a) cos²(θ/2),
  // becomes smooth in θ, and Gauss–Kronrod needs far fewer bisections down to it (the dents
  // sweep's 78 bodies: a third of the instructions they took in x; against the closed form
  // 4e-16 instead of 3e-15).
  auto piece = [&surfaces](double a, double b) {
    return [&surfaces, mid = 0.5 * (a + b), half = 0.5 * (b - a)](double theta) -> Moments10 {
      return slab(surfaces, mid - half * std::cos(theta)) * (half * std::sin(theta));
    };
  };
  std::vector<Estimate> pieces;
  Moments10 l1 = Moments10::Zero();
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    pieces.push_back(xs[k + 1] > xs[k] ? gaussKronrod(piece(xs[k], xs[k + 1]), 0.0, M_PI)
                                       : Estimate{});
    l1 += pieces.back().l1;
  }
  // Each moment's scale: ∫|integrand|, and at least V·R^n for a moment of n lengths beyond the
  // volume (R the body's largest extent), so a moment that is zero by symmetry is held to the
  // others' scale instead of to its own rounding noise.
  const double reach = std::max({half, shape.rimHalfWidths().y(), shape.top + shape.a});
  const std::array<int, 10> lengths{0, 1, 1, 1, 2, 2, 2, 2, 2, 2};
  for (int i = 0; i < 10; ++i) l1[i] = std::max(l1[i], l1[0] * std::pow(reach, lengths[i]));
  Moments10 total = Moments10::Zero();
  for (std::size_t k = 0; k + 1 < xs.size(); ++k)
    if (xs[k + 1] > xs[k])
      total += adaptive(piece(xs[k], xs[k + 1]), 0.0, M_PI, pieces[k],
                        tolerance * l1 * (xs[k + 1] - xs[k]) / (2 * half), 50);
  return momentsOf(total);
}

std::optional<double> dentsCutShare(const Paraboloid& shape, const std::optional<Dents>& dents) {
  if (!dents) return std::nullopt;
  const double whole = closedFormMoments(shape, std::nullopt)->volume;
  const std::optional<VolumeMoments> closed = closedFormMoments(shape, dents);
  const double dented = closed ? closed->volume : cubatureMoments(shape, dents, 1e-10).volume;
  // Cubature's error is 1e-10 of the volume's scale: a share below that is none.
  const double share = 1 - dented / whole;
  return share < 1e-9 ? 0.0 : share;
}

Continuum continuumMassProperties(const Paraboloid& shape, const std::optional<Dents>& dents,
                                  double mass) {
  if (auto exact = closedFormMoments(shape, dents))
    return {exact->properties(mass), ContinuumMethod::ClosedForm};
  return {cubatureMoments(shape, dents).properties(mass), ContinuumMethod::Cubature};
}

}  // namespace sim

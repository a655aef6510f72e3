#include "sim/mesh_body.hpp"

#include <cmath>
#include <limits>

#include "util/format.hpp"

namespace sim {
namespace {

double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// The highest and lowest crossing of each column of a box of columns i0 … i0 + nx − 1 (x) by
// j0 … j0 + ny − 1 (y); ±∞ where none.
struct Columns {
  long i0, j0, nx, ny;
  std::vector<double> high, low;
  void cross(long i, long j, double z) {
    const std::size_t k = static_cast<std::size_t>((j - j0) * nx + (i - i0));
    high[k] = std::max(high[k], z);
    low[k] = std::min(low[k], z);
  }
};

// One face over the columns under it: the column's point p lies in the face's shadow when its
// barycentric weights are all ≥ 0 (to rounding, so that a line through a shared edge is caught by
// both faces rather than neither), and the line crosses the face at the weights' mix of the
// corners' heights. Faces seen edge-on from above (no shadow) are skipped: their edges belong to
// neighbours that are not.
void rasterise(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
               double h, Columns& columns) {
  const Eigen::Vector2d a2 = a.head<2>(), ab = (b - a).head<2>(), ac = (c - a).head<2>();
  const double d = cross2(ab, ac);
  if (!(std::abs(d) > 1e-14 * ab.squaredNorm() + 1e-300)) return;
  const double lo_x = std::min({a.x(), b.x(), c.x()}), hi_x = std::max({a.x(), b.x(), c.x()});
  const double lo_y = std::min({a.y(), b.y(), c.y()}), hi_y = std::max({a.y(), b.y(), c.y()});
  constexpr double kSlack = 1e-12;
  for (long j = std::lround(std::ceil(lo_y / h - 0.5)); (j + 0.5) * h <= hi_y; ++j)
    for (long i = std::lround(std::ceil(lo_x / h - 0.5)); (i + 0.5) * h <= hi_x; ++i) {
      const Eigen::Vector2d ap = Eigen::Vector2d((i + 0.5) * h, (j + 0.5) * h) - a2;
      const double wb = cross2(ap, ac) / d, wc = cross2(ab, ap) / d;
      if (wb < -kSlack || wc < -kSlack || wb + wc > 1 + kSlack) continue;
      columns.cross(i, j, a.z() + wb * (b.z() - a.z()) + wc * (c.z() - a.z()));
    }
}

}  // namespace

SurfacePoints meshSurfacePoints(const TriangleMesh& mesh, double h) {
  const Eigen::AlignedBox3d box = meshBounds(mesh);
  Columns columns;
  columns.i0 = std::lround(std::floor(box.min().x() / h - 0.5));
  columns.j0 = std::lround(std::floor(box.min().y() / h - 0.5));
  columns.nx = std::lround(std::ceil(box.max().x() / h - 0.5)) - columns.i0 + 1;
  columns.ny = std::lround(std::ceil(box.max().y() / h - 0.5)) - columns.j0 + 1;
  const auto n = static_cast<std::size_t>(columns.nx * columns.ny);
  columns.high.assign(n, -std::numeric_limits<double>::infinity());
  columns.low.assign(n, std::numeric_limits<double>::infinity());
  for (const auto& f : mesh.faces)
    rasterise(mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]], h, columns);
  SurfacePoints points;
  for (long j = 0; j < columns.ny; ++j)
    for (long i = 0; i < columns.nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * columns.nx + i);
      if (!(columns.high[k] >= columns.low[k])) continue;  // the line misses the mesh
      const double x = (columns.i0 + i + 0.5) * h, y = (columns.j0 + j + 0.5) * h;
      points.top.emplace_back(x, y, columns.high[k]);
      points.bottom.emplace_back(x, y, columns.low[k]);
    }
  return points;
}

double meshPointSpacing(const TriangleMesh& mesh) {
  const Eigen::Vector3d size = meshBounds(mesh).sizes();
  return std::min(size.x(), size.y()) / 24;
}

namespace {

bool given(const std::array<double, 3>& v) {
  return !std::isnan(v[0]) || !std::isnan(v[1]) || !std::isnan(v[2]);
}

}  // namespace

std::optional<rb::Error> checkMeshBody(const BodySpec& b) {
  if (!(std::isfinite(b.mass) && b.mass > 0))
    return rb::Error{"body.mass", "must be > 0, not " + rb::show(b.mass)};
  if (given(b.center_of_mass))
    for (double c : b.center_of_mass)
      if (!std::isfinite(c))
        return rb::Error{"body.center_of_mass", "must hold three finite numbers (file units)"};
  return std::nullopt;
}

rb::Result<Body> buildMeshBody(const BodySpec& b, double unit) {
  if (!b.mesh.data)
    return rb::Error{"body.mesh.file", "was not read: give the scene as a file that names it"};
  if (auto problem = checkMesh(*b.mesh.data, b.mesh.file, unit))
    return rb::Error{"body.mesh.file", problem->message};
  TriangleMesh mesh = *b.mesh.data;
  for (Eigen::Vector3d& v : mesh.vertices) v *= unit;
  const Eigen::AlignedBox3d box = meshBounds(mesh);
  MassProperties m = meshMassProperties(mesh, b.mass);
  // A weighted toy: its own CM and inertia replace the uniform solid's.
  if (given(b.center_of_mass)) {
    m.com = Eigen::Vector3d(b.center_of_mass.data()) * unit;
    if (!box.contains(m.com))
      return rb::Error{"body.center_of_mass",
                       "lies outside the mesh's box: it is in the mesh file's frame and units"};
  }
  if (b.inertia != Matrix3Spec{})
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m.inertia(i, j) = b.inertia[i][j];
  principalAxes(m);
  Body body;
  body.com_given = given(b.center_of_mass);
  body.inertia_given = b.inertia != Matrix3Spec{};
  body.mass = b.mass;
  body.mass_properties = m;
  body.com_geometric = m.com;
  body.inertia = m.inertia;
  body.inertia_inv = m.inertia.inverse();
  const double h = meshPointSpacing(mesh);
  body.grid = Grid{h, h, h};
  const SurfacePoints points = meshSurfacePoints(mesh, h);
  body.surface.kind = Surface::Kind::Mesh;
  body.surface.mesh = MeshSurface{points.top, box.min(), box.max(), meshMoments(mesh).volume, {}};
  body.surface.mesh.points.insert(body.surface.mesh.points.end(), points.bottom.begin(),
                                  points.bottom.end());
  // The smooth bottom (§P11.4), fitted to the bottom points, whatever the contact model: analyze
  // gives the theory from it. The misalignment is then measured from its long axis, as the
  // paraboloid's is from its bottom's (§P1.6).
  body.surface.mesh.fit = fitBottom(points.bottom, h, box.sizes().maxCoeff());
  if (body.surface.mesh.fit.usable())
    body.mass_properties.misalignment_deg =
        misalignmentDeg(body.mass_properties, body.surface.mesh.fit.longAxisAngle());
  for (const Eigen::Vector3d& p : points.top) body.top.push_back(p - m.com);
  for (const Eigen::Vector3d& p : points.bottom) body.bottom.push_back(p - m.com);
  return body;
}

}  // namespace sim

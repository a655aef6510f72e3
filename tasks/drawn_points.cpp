#include "tasks/drawn_points.hpp"

#include <algorithm>
#include <cmath>

#include "sim/compile.hpp"

namespace tasks {

// A fine grid (the default body has 244,212 surface points) reads as moiré, so columns are
// thinned to about kDrawnPoints by keeping every k-th column counted outwards from the axes,
// which keeps the set symmetric; the spheres grow with k.
constexpr double kDrawnPoints = 2500;

DrawnPoints drawnPointsOf(const sim::Model& model) {
  const sim::Body& body = *model.body;
  const sim::GridCensus census = sim::censusOf(body);
  const double total = static_cast<double>(census.top + census.bottom);
  const int k = std::max(1, static_cast<int>(std::ceil(std::sqrt(total / kDrawnPoints))));
  const sim::Grid& grid = body.grid;
  DrawnPoints points;
  auto keep = [&](const Eigen::Vector3d& p_geom, std::vector<Eigen::Vector3f>& out) {
    out.push_back((p_geom - body.com_geometric).cast<float>());
  };
  if (body.surface.kind == sim::Surface::Kind::Paraboloid) {
    // Only the kept columns, straight from the shape (the physics builds no points but for
    // contact.model points).
    const sim::SurfacePoints kept = sim::gridSurface(body.surface.paraboloid, body.dents, grid, k);
    for (const Eigen::Vector3d& p : kept.top) keep(p, points.top);
    for (const Eigen::Vector3d& p : kept.bottom) keep(p, points.bottom);
  } else {
    auto kept = [&](const Eigen::Vector3d& r) {
      const Eigen::Vector3d p = r + body.com_geometric;  // column (i + ½) dx, (j + ½) dy
      const long i = std::lround(std::abs(p.x()) / grid.dx - 0.5);
      const long j = std::lround(std::abs(p.y()) / grid.dy - 0.5);
      return i % k == 0 && j % k == 0;
    };
    for (std::size_t i = 0; i < body.top.size(); ++i)
      if (kept(body.top[i])) points.top.push_back(body.top[i].cast<float>());
    for (std::size_t i = 0; i < body.bottom.size(); ++i)
      if (kept(body.bottom[i])) points.bottom.push_back(body.bottom[i].cast<float>());
  }
  points.spacing = static_cast<float>(k * std::min(grid.dx, grid.dy));
  points.radius = 0.35f * points.spacing;
  points.footprint_half = body.surface.footprintHalf().cast<float>();
  return points;
}

float reachOf(const DrawnPoints& points) {
  float reach = 0;
  for (const auto* set : {&points.top, &points.bottom})
    for (const auto& p : *set) reach = std::max(reach, p.norm() + points.radius);
  return reach;
}

}  // namespace tasks

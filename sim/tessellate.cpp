#include "sim/tessellate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "util/format.hpp"

namespace sim {
namespace {

using Face = std::array<int, 3>;

// Two triangles for the cell between an inner ring's spokes j, j+1 (a, b) and an outer ring's
// (c, d): counter-clockwise seen from above when `up`, so that a top faces up and a bottom down
// (the ellipse map below keeps orientation: its determinant is positive).
void addCell(std::vector<Face>& faces, int a, int b, int c, int d, bool up) {
  if (up) {
    faces.push_back({a, c, d});
    faces.push_back({a, d, b});
  } else {
    faces.push_back({a, d, c});
    faces.push_back({a, b, d});
  }
}

// A place on the floor plan as the scene gives lengths: in its own unit (a maker's file in cm
// was told of a hole at (0.013651, 0.034654) m).
std::string placeOf(const Eigen::Vector2d& u, double length_unit) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4g, %.4g)", u.x() / length_unit, u.y() / length_unit);
  return std::string(text) + (length_unit == 1 ? " m" : " in the scene's units");
}

rb::Result<TriangleMesh> paraboloidMeshAt(const Paraboloid& shape,
                                          const std::optional<Dents>& dents, int segments,
                                          double length_unit = 1) {
  // ½ uᵀHu = top + a is the rim; with H = L Lᵀ, u = √(2(top + a)) r L⁻ᵀ(cos θ, sin θ) puts the
  // rim at r = 1 and the apex at r = 0.
  Eigen::Matrix2d h;
  h << shape.p / shape.a, shape.q / (shape.a * shape.a), shape.q / (shape.a * shape.a),
      shape.s / shape.a;
  const Eigen::LLT<Eigen::Matrix2d> llt(h);
  const Eigen::Matrix2d map =
      std::sqrt(2 * (shape.top + shape.a)) *
      llt.matrixU().solve(Eigen::Matrix2d::Identity());  // L⁻ᵀ = U⁻¹ with U = Lᵀ
  const int rings = std::max(2, (segments + 5) / 6);
  const auto upper = [&](double x, double y) {
    return dents ? std::min(shape.top, dents->surface(shape, x, y)) : shape.top;
  };
  TriangleMesh mesh;
  std::vector<Eigen::Vector3d>& v = mesh.vertices;
  // Vertices: the bottom's apex, its rings 1 … rings−1, the rim, the top's rings rings−1 … 1,
  // the top's centre. ring(i, j) below is the index of spoke j on ring i (i = rings: the rim).
  v.emplace_back(0, 0, shape.bottom(0, 0));
  std::vector<Eigen::Vector2d> at;
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double r = static_cast<double>(i) / rings;
      const double theta = 2 * std::numbers::pi * j / segments;
      at.push_back(map * Eigen::Vector2d(r * std::cos(theta), r * std::sin(theta)));
    }
  const auto ring = [&](int i, int j) { return 1 + (i - 1) * segments + (j % segments); };
  for (int i = 1; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Eigen::Vector2d& u = at[static_cast<std::size_t>(ring(i, j) - 1)];
      v.emplace_back(u.x(), u.y(), i == rings ? shape.top : shape.bottom(u.x(), u.y()));
    }
  const int top_base = static_cast<int>(v.size());
  const auto top_ring = [&](int i, int j) {
    return i == rings ? ring(i, j) : top_base + (i - 1) * segments + (j % segments);
  };
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Eigen::Vector2d& u = at[static_cast<std::size_t>(ring(i, j) - 1)];
      const double z = upper(u.x(), u.y());
      if (!(z > shape.bottom(u.x(), u.y())))
        return rb::Error{"body.dents",
                         "cut through the bottom at " + placeOf(u, length_unit) +
                             ", a hole through the body: export draws bodies whose dents lie "
                             "within the top"};
      v.emplace_back(u.x(), u.y(), z);
    }
  for (int j = 0; j < segments; ++j) {
    const Eigen::Vector2d& u = at[static_cast<std::size_t>(ring(rings, j) - 1)];
    if (upper(u.x(), u.y()) < shape.top)
      return rb::Error{"body.dents",
                       "cut the rim: export draws bodies whose dents lie within the top"};
  }
  const int top_centre = static_cast<int>(v.size());
  v.emplace_back(0, 0, upper(0, 0));
  if (!(v.back().z() > v.front().z()))
    return rb::Error{"body.dents",
                     "cut through the bottom at the centre: export draws bodies whose dents "
                     "lie within the top"};
  std::vector<Face>& f = mesh.faces;
  for (int j = 0; j < segments; ++j) {
    f.push_back({0, ring(1, j + 1), ring(1, j)});
    f.push_back({top_centre, top_ring(1, j), top_ring(1, j + 1)});
    for (int i = 1; i < rings; ++i) {
      addCell(f, ring(i, j), ring(i, j + 1), ring(i + 1, j), ring(i + 1, j + 1), false);
      addCell(f, top_ring(i, j), top_ring(i, j + 1), top_ring(i + 1, j), top_ring(i + 1, j + 1),
              true);
    }
  }
  return mesh;
}

// The largest dents.scale, to two decimals, whose dents at the same place lie within the
// body; 0 where none does. Deeper dents cut further (eq. P1.2: a dent's depth and width grow
// with its scale), so whether a scale exports is monotone in it and bisection finds the edge.
double largestExportableScale(const Paraboloid& shape, Dents dents, int segments) {
  const auto fits = [&](double scale) {
    dents.scale = scale;
    return paraboloidMeshAt(shape, dents, segments).ok();
  };
  double fit = 0, cut = dents.scale;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (fit + cut);
    (fits(mid) ? fit : cut) = mid;
  }
  const double shown = std::floor(fit * 100) / 100;
  return shown > 0 && fits(shown) ? shown : 0;
}

// A refusal says how far the dents may go where they are, so that a maker need not guess.
rb::Result<TriangleMesh> paraboloidMesh(const Paraboloid& shape, const std::optional<Dents>& dents,
                                        int segments, double length_unit) {
  rb::Result<TriangleMesh> mesh = paraboloidMeshAt(shape, dents, segments, length_unit);
  if (mesh.ok() || !dents) return mesh;
  const double largest = largestExportableScale(shape, *dents, segments);
  rb::Error error = mesh.error();
  error.message += largest > 0
                       ? " (make body.dents.scale smaller: where they are, the dents export "
                         "up to scale " +
                             rb::show(largest) + ")"
                       : " (move body.dents.at inwards: where they are, no scale exports)";
  return error;
}

TriangleMesh ellipsoidMesh(const Ellipsoid& shape, int segments) {
  const int bands = std::max(2, segments / 2);
  const Eigen::Vector3d& axes = shape.semi_axes;
  TriangleMesh mesh;
  mesh.vertices.emplace_back(0, 0, -axes.z());
  for (int k = 1; k < bands; ++k) {
    const double phi = -std::numbers::pi / 2 + std::numbers::pi * k / bands;
    for (int j = 0; j < segments; ++j) {
      const double theta = 2 * std::numbers::pi * j / segments;
      mesh.vertices.emplace_back(axes.x() * std::cos(phi) * std::cos(theta),
                                 axes.y() * std::cos(phi) * std::sin(theta),
                                 axes.z() * std::sin(phi));
    }
  }
  const int north = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0, 0, axes.z());
  const auto at = [&](int k, int j) { return 1 + (k - 1) * segments + (j % segments); };
  // Outwards is ∂θ × ∂φ (east then north): a band's cell is (lower j, lower j+1, upper j+1).
  for (int j = 0; j < segments; ++j) {
    mesh.faces.push_back({0, at(1, j + 1), at(1, j)});
    for (int k = 1; k + 1 < bands; ++k) {
      mesh.faces.push_back({at(k, j), at(k, j + 1), at(k + 1, j + 1)});
      mesh.faces.push_back({at(k, j), at(k + 1, j + 1), at(k + 1, j)});
    }
    mesh.faces.push_back({at(bands - 1, j), at(bands - 1, j + 1), north});
  }
  return mesh;
}

}  // namespace

bool dentsLieWithin(const Surface& surface, const std::optional<Dents>& dents, int segments) {
  return surface.kind != Surface::Kind::Paraboloid ||
         paraboloidMeshAt(surface.paraboloid, dents, segments).ok();
}

rb::Result<TriangleMesh> tessellate(const Surface& surface, const std::optional<Dents>& dents,
                                    int segments, double length_unit) {
  if (segments < kMinSegments || segments > kMaxSegments)
    return rb::Error{"", "must be " + std::to_string(kMinSegments) + " to " +
                             std::to_string(kMaxSegments) + ", not " + std::to_string(segments)};
  switch (surface.kind) {
    case Surface::Kind::Paraboloid:
      return paraboloidMesh(surface.paraboloid, dents, segments, length_unit);
    case Surface::Kind::Ellipsoid:
      return ellipsoidMesh(surface.ellipsoid, segments);
    case Surface::Kind::Mesh:
      break;
  }
  return rb::Error{"", "a mesh body is exported from its own triangles, not tessellated"};
}

}  // namespace sim

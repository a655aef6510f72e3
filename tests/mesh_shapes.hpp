// Small meshes made in code for the mesh tests: a box, tetrahedra, an icosphere (a sphere or an
// ellipsoid when scaled). Each is closed and wound outwards: the convex ones are made so by
// turning every face whose normal points at the centre (orientOutwards).
#pragma once

#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "sim/mesh.hpp"

namespace mesh_shapes {

/// Turns every face of a convex mesh to face away from its vertices' centroid.
inline void orientOutwards(sim::TriangleMesh& mesh) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) centre += v;
  centre /= static_cast<double>(mesh.vertices.size());
  for (auto& f : mesh.faces) {
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    const Eigen::Vector3d n = (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a);
    if (n.dot(a - centre) < 0) std::swap(f[1], f[2]);
  }
}

/// The box [0, a] × [0, b] × [0, c]: corner i at (a·bit0, b·bit1, c·bit2), two faces a side.
inline sim::TriangleMesh box(double a, double b, double c) {
  sim::TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.emplace_back(a * (i & 1), b * (i >> 1 & 1), c * (i >> 2));
  mesh.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 4, 6}, {0, 6, 2},
                {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3}};
  return mesh;
}

/// The corner tetrahedron 0, (a, 0, 0), (0, b, 0), (0, 0, c).
inline sim::TriangleMesh cornerTetrahedron(double a, double b, double c) {
  sim::TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}};
  mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return mesh;
}

/// The regular tetrahedron on alternate corners of the cube [−1, 1]³ (edge 2√2).
inline sim::TriangleMesh regularTetrahedron() {
  sim::TriangleMesh mesh;
  mesh.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  mesh.faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
  orientOutwards(mesh);
  return mesh;
}

/// The icosahedron in the unit sphere, each face split into 4^levels by edge midpoints pushed
/// out to the sphere; then scaled by `semi_axes` (an ellipsoid's mesh, inscribed in it).
inline sim::TriangleMesh icosphere(int levels,
                                   const Eigen::Vector3d& semi_axes = Eigen::Vector3d::Ones()) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  sim::TriangleMesh mesh;
  mesh.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& v : mesh.vertices) v.normalize();
  mesh.faces = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      auto [it, added] = middle.try_emplace(key, static_cast<int>(mesh.vertices.size()));
      if (added) mesh.vertices.push_back((mesh.vertices[i] + mesh.vertices[j]).normalized());
      return it->second;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : mesh.faces) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    mesh.faces = std::move(finer);
  }
  orientOutwards(mesh);
  for (auto& v : mesh.vertices) v = v.cwiseProduct(semi_axes);
  return mesh;
}

/// The mesh with every face wound the other way.
inline sim::TriangleMesh flipped(sim::TriangleMesh mesh) {
  for (auto& f : mesh.faces) std::swap(f[1], f[2]);
  return mesh;
}

}  // namespace mesh_shapes

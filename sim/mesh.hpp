// A body given as a closed triangle mesh: its exact mass properties by the divergence
// theorem (docs/physics.md §P11) and the checks a mesh must pass before they mean anything.
// Lengths are whatever the vertices are in (the scene's file units until scaled to metres).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/body.hpp"

namespace sim {

/// Triangles over shared vertices; each face lists three vertex indices, counter-clockwise seen
/// from outside (its normal (b − a) × (c − a) points out of the body).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> faces;
};

/// The solid a closed mesh bounds: volume (vertex units³, negative when the faces wind inwards),
/// first moment ∫r dV and second moment ∫r rᵀ dV about `origin` (docs/physics.md eq. P11.1).
struct MeshMoments {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
};
MeshMoments meshMoments(const TriangleMesh& mesh);

/// Mass properties of the solid at uniform density, `mass` kg in all: the CM (vertex units) and
/// the inertia about it (kg · vertex units²), with principal moments and axes. The mesh must have
/// passed checkMesh (closed, wound outwards).
MassProperties meshMassProperties(const TriangleMesh& mesh, double mass);

/// Axis-aligned bounds of the vertices.
Eigen::AlignedBox3d meshBounds(const TriangleMesh& mesh);

/// What checkMesh found wrong, in the order it looks.
enum class MeshFault {
  Empty,         ///< no faces
  BadIndex,      ///< a face names a vertex that is not there
  NotFinite,     ///< a vertex with an infinite or NaN coordinate
  Degenerate,    ///< faces of zero area
  Open,          ///< edges with one face: the surface has holes
  NonManifold,   ///< edges with three faces or more
  Inconsistent,  ///< neighbouring faces wound opposite ways
  InsideOut,     ///< closed and consistent, but every face winds inwards (volume < 0)
  Pieces,        ///< two solids or more, apart (a print plate): not one body
  WrongSize,     ///< in metres, not a size a hand holds: the unit is likely wrong
};

/// One fault: what and the one-line message, naming `name` (the file), the cause and the way out.
struct MeshProblem {
  MeshFault fault;
  std::string message;
};

/// The first fault of the mesh, or nothing. `unit` is metres per vertex unit (units.length): the
/// size check asks for a body between kHandMin and kHandMax metres long. The mesh is never altered
/// (docs/physics.md §P11.2 says why inside-out meshes are refused, not mended).
std::optional<MeshProblem> checkMesh(const TriangleMesh& mesh, std::string_view name, double unit);

/// The longest side of a body a hand holds, m: anything outside is taken for a wrong unit.
inline constexpr double kHandMin = 0.005, kHandMax = 2.0;

}  // namespace sim

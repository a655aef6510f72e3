// The body of `body.shape: mesh` (docs/physics.md §P11): checked, its mass properties exact for
// the polyhedron (or the scene's own for a weighted toy), and its surface sampled into the points
// the `points` contact and the drawing use.
#pragma once

#include "sim/mesh.hpp"
#include "sim/model.hpp"
#include "sim/spec.hpp"
#include "util/result.hpp"

namespace sim {

/// The mesh's surface points over vertical lines at x = (i + ½)h, y = (j + ½)h (the grid rule of
/// §P1.3, about the mesh's own origin): on each line that meets the mesh, its highest crossing
/// (`top`, red: there the surface faces up, the line leaving the solid upwards) and its lowest
/// (`bottom`, blue: facing down). Vertex units, the mesh's frame. Deterministic: the same mesh
/// and spacing give the same points in the same order (rows of y outermost, as the grid's).
SurfacePoints meshSurfacePoints(const TriangleMesh& mesh, double spacing);

/// The spacing of a mesh body's surface points: a 24th of the smaller side of its footprint, so
/// that the narrow side has 24 columns across.
double meshPointSpacing(const TriangleMesh& mesh);

/// The keys of a mesh body, before its file is looked at: the mass, and the CM and inertia when
/// given.
std::optional<rb::Error> checkMeshBody(const BodySpec& body);

/// The body of a mesh that the scene loader has read (spec.mesh.data), in file units scaled by
/// `unit` (m per file unit): checked (checkMesh, key body.mesh.file), its mass properties at
/// uniform density or the scene's, and its surface points relative to the CM.
rb::Result<Body> buildMeshBody(const BodySpec& body, double unit);

}  // namespace sim

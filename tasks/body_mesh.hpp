// A scene's body as triangles, in metres: what `rattleback export` writes and Python's
// Scene.mesh() gives (docs/commands.md "rattleback export").
#pragma once

#include "sim/mesh.hpp"
#include "tasks/scene_args.hpp"
#include "util/result.hpp"

namespace tasks {

/// The body's closed surface in its geometric frame, metres, wound outwards: the analytic bodies
/// tessellated on `segments` (sim/tessellate.hpp), a mesh body's own triangles scaled by
/// units.length. An error of the scene's keys names its file, line and key.
rb::Result<sim::TriangleMesh> bodyMesh(const LoadedScene& loaded, int segments);

/// The body's surface as a scene's video.surface: triangles draws it (stills, videos and the
/// report's player alike): bodyMesh on sim::kDefaultSegments, about the body's CM (the frame
/// its points are drawn in), metres.
rb::Result<sim::TriangleMesh> drawnMesh(const LoadedScene& loaded);

}  // namespace tasks

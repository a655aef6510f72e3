#include "tasks/body_mesh.hpp"

#include "scene/loader.hpp"
#include "sim/tessellate.hpp"

namespace tasks {

rb::Result<sim::TriangleMesh> bodyMesh(const LoadedScene& loaded, int segments) {
  const sim::SceneSpec& spec = loaded.scene.spec;
  if (spec.body.shape == "mesh") {
    sim::TriangleMesh mesh = *spec.body.mesh.data;
    for (auto& v : mesh.vertices) v *= spec.units.length;
    return mesh;
  }
  const sim::Body& body = *loaded.model.body;
  auto made = sim::tessellate(body.surface, body.dents, segments, loaded.model.length_unit);
  if (!made && !made.error().key.empty()) return scene::locate(loaded.scene, made.error());
  return made;
}

rb::Result<sim::TriangleMesh> drawnMesh(const LoadedScene& loaded) {
  // export's default: 24,192 triangles for the default body, its facets a few pixels across in
  // a 720p frame (the shape reads smooth; a mesh body's own facets show as they are).
  auto mesh = bodyMesh(loaded, sim::kDefaultSegments);
  if (!mesh) return mesh;
  const Eigen::Vector3d com = loaded.model.body->com_geometric;
  for (Eigen::Vector3d& v : mesh.value().vertices) v -= com;
  return mesh;
}

}  // namespace tasks

// libFuzzer target for the mesh reader (scene/mesh_file.hpp) and what follows it: any bytes, read
// as STL and as OBJ, must give either a mesh or one non-empty line of error naming the file; a
// mesh must give a fault of one line naming the file, or pass the checks and then have a positive
// volume and finite mass properties. Never a crash, a hang or a sanitizer report.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/mesh_file.hpp"
#include "sim/mesh_body.hpp"

namespace {

void checkLine(const std::string& message, const std::string& name) {
  if (message.empty() || message.find('\n') != std::string::npos ||
      !message.starts_with(name + ": "))
    __builtin_trap();
}

void checkMesh(const sim::TriangleMesh& mesh, const std::string& name) {
  // The size check is given the unit that makes any mesh pass it, so the rest is reached.
  const double length = sim::meshBounds(mesh).sizes().maxCoeff();
  const double unit = std::isfinite(length) && length > 0 ? 0.1 / length : 1.0;
  if (auto problem = sim::checkMesh(mesh, name, unit)) return checkLine(problem->message, name);
  if (!(sim::meshMoments(mesh).volume > 0)) __builtin_trap();
  const sim::MassProperties m = sim::meshMassProperties(mesh, 1.0);
  if (!m.com.allFinite() || !m.inertia.allFinite()) __builtin_trap();
  // The surface points over at most 24 × (24 × aspect) columns: bounded unless the mesh is a
  // needle, which a bound on the columns keeps quick.
  const Eigen::Vector3d size = sim::meshBounds(mesh).sizes();
  const double h = sim::meshPointSpacing(mesh);
  if (h > 0 && size.x() / h * size.y() / h < 1e5) sim::meshSurfacePoints(mesh, h);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (const auto& [format, name] : {std::pair{scene::MeshFormat::Stl, std::string("fuzz.stl")},
                                     std::pair{scene::MeshFormat::Obj, std::string("fuzz.obj")}}) {
    auto mesh = scene::parseMesh(bytes, name, format);
    if (!mesh)
      checkLine(mesh.error().message, name);
    else
      checkMesh(mesh.value(), name);
  }
  return 0;
}

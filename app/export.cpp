// rattleback export: a scene's body as a binary STL (docs/commands.md "rattleback export"; the
// surface is sim/tessellate.hpp's, or a mesh body's own triangles in the units asked for).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/commands.hpp"
#include "scene/loader.hpp"
#include "scene/mesh_file.hpp"
#include "sim/mesh.hpp"
#include "tasks/body_mesh.hpp"
#include "tasks/output.hpp"
#include "util/output_place.hpp"

namespace app {
namespace {

// The unit by its name (the option has checked it is one of them).
const ExportUnit& unitNamed(const std::string& name) {
  for (const ExportUnit& unit : kExportUnits)
    if (unit.name == name) return unit;
  return kExportUnits.back();
}

std::string defaultOutput(const std::string& scene) {
  return "out/" + std::filesystem::path(scene).stem().string() + ".stl";
}

}  // namespace

int exportCommand(const ExportArgs& args) {
  auto loaded = loadScene(args.scene, args.overrides);
  if (!loaded) return fail(loaded);
  noteShipped(args.scene);
  const std::string output = args.output.empty() ? defaultOutput(args.scene) : args.output;
  // Not over the scene, nor over the mesh it reads (a maker's `-o hull.stl` of hull.stl).
  if (auto ok = rb::checkDataOutput(output, "an STL mesh", ".stl",
                                    scene::filesRead(loaded.value().scene));
      !ok)
    return fail(ok);
  if (std::filesystem::path(output).extension() != ".stl")
    return fail(rb::Status::fail("-o " + output +
                                 ": export writes binary STL; give a name ending in .stl"));
  auto made = tasks::bodyMesh(loaded.value(), args.segments);
  if (!made) {
    rb::Error e = made.error();
    if (e.key.empty() && !e.where) e.message = "--segments: " + e.message;
    return fail(e);
  }
  const sim::TriangleMesh& mesh = made.value();
  // What export writes passes what import checks: a fault here is ours, not the scene's.
  if (auto problem = sim::checkMesh(mesh, output, 1.0);
      problem && problem->fault != sim::MeshFault::WrongSize)
    return fail(rb::Status::fail("rattleback export made a mesh that fails its own check (" +
                                 problem->message + "): please report it with the scene"));
  const ExportUnit& unit = unitNamed(args.units);
  const std::string bytes = scene::binaryStl(
      mesh, 1.0 / unit.metres,
      "rattleback export of " + std::filesystem::path(args.scene).filename().string() +
          "; units: " + args.units + " (units.length: " + unit.length + ")");
  if (auto made = tasks::makeParentFolder(output); !made) return fail(made);
  auto file = tasks::AtomicOutput::open(output);
  if (!file) return fail(file);
  file->stream().write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (auto ok = file->commit(); !ok) return fail(ok);
  if (!args.quiet) {
    const sim::MeshMoments m = sim::meshMoments(mesh);
    std::printf(
        "wrote %s: %zu triangles, %.4g cm³, binary STL in %s (read it back with "
        "body.shape: mesh, units.length: %s)\n",
        output.c_str(), mesh.faces.size(), m.volume * 1e6, args.units.c_str(), unit.length);
  }
  return kOk;
}

}  // namespace app

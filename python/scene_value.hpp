// The compiled scene shared by rattleback._core and rattleback._draw: pybind11 registers it
// once (in _core) and both modules pass it by this one C++ type.
#pragma once

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "python/convert.hpp"
#include "scene/loader.hpp"
#include "tasks/scene_args.hpp"

namespace pyrb {

/// A scene loaded, checked and compiled, with its overrides applied.
struct LoadedScene {
  tasks::LoadedScene value;
  bool has_file = false;  ///< read from a file (from_file), not made from text or a dict
};

/// A mesh body's triangles given from NumPy (Scene.from_mesh), converted once and shared by every
/// scene made from them: they stand for body.mesh.file's (scene::loadWithValues).
struct HeldMesh {
  std::shared_ptr<const sim::TriangleMesh> mesh;
};

/// The stem a scene's outputs are named by (out/<stem>.mp4, the folder's manifest): its file's,
/// or a name's given for a scene with no file; "scene" for from_dict's "<dict>" and from_yaml's
/// "<yaml>", which stand for no file (out/<dict>.mp4 is a name a shell takes for redirections).
inline std::string stemOf(const std::string& name, bool has_file) {
  const std::string stem = std::filesystem::path(name).stem().string();
  return !has_file && (stem.empty() || stem.front() == '<') ? "scene" : stem;
}

/// The overrides a Python call may give (tasks::sceneOptions, by name: dt=…, size=(w, h)),
/// named in messages as "argument dt".
inline tasks::Overrides overridesOf(const py::dict& kw) {
  tasks::Overrides o;
  o.option_prefix = "argument ";
  for (const tasks::SceneOptionRow& row : tasks::sceneOptions()) {
    if (!kw.contains(row.name) || kw[row.name].is_none()) continue;
    const py::handle value = kw[row.name];
    switch (row.kind) {
      case tasks::OptionKind::Number:
        o.set(row.option, value.cast<double>());
        break;
      case tasks::OptionKind::Name:
        o.set(row.option, value.cast<std::string>());
        break;
      case tasks::OptionKind::Size: {
        const auto size = value.cast<std::vector<int>>();
        if (size.size() != 2)
          throw py::value_error("argument " + std::string(row.name) +
                                ": give (width, height) in pixels");
        o.set(row.option, std::array<int, 2>{size[0], size[1]});
        break;
      }
    }
  }
  return o;
}

inline void bindScene(py::module_& m) {
  py::class_<LoadedScene>(m, "LoadedScene")
      .def_property_readonly("file", [](const LoadedScene& s) { return s.value.scene.file; })
      .def_property_readonly("duration",
                             [](const LoadedScene& s) { return s.value.model.duration; })
      .def_property_readonly("spin",
                             [](const LoadedScene& s) { return s.value.model.initial.spin; });
  m.def(
      "read_scene_file", [](const std::string& path) { return take(scene::readSceneFile(path)); },
      py::arg("path"));
  m.def(
      "yaml_with_values",
      [](const std::string& yaml, const std::string& name,
         const std::vector<std::pair<std::string, std::string>>& values, const std::string& place) {
        std::vector<scene::KeyValue> kv;
        for (const auto& [key, text] : values) kv.push_back({key, text});
        return take(scene::yamlWithValues(yaml, name, kv, place));
      },
      py::arg("yaml"), py::arg("name"), py::arg("values"), py::arg("place"));
  // As the command line finds a scene: a relative name not here is the installed copy's.
  m.def("find_shipped", &tasks::findShipped, py::arg("path"));
  m.def(
      "load",
      [](const std::string& yaml, const std::string& name,
         const std::vector<std::pair<std::string, std::string>>& values, const py::dict& overrides,
         bool has_file, const std::optional<HeldMesh>& mesh, const std::string& place) {
        std::vector<scene::KeyValue> kv;
        for (const auto& [key, text] : values) kv.push_back({key, text});
        const tasks::Overrides o = overridesOf(overrides);
        GilReleased release;  // compiling a body takes tens of ms
        auto loaded = scene::loadWithValues(yaml, name, kv, place, mesh ? mesh->mesh : nullptr);
        if (!loaded) {
          py::gil_scoped_acquire acquire;
          raise(loaded.error());
        }
        auto applied = tasks::applyOverrides(std::move(loaded).value(), o);
        py::gil_scoped_acquire acquire;
        return LoadedScene{take(std::move(applied)), has_file};
      },
      py::arg("yaml"), py::arg("name"), py::arg("values"), py::arg("overrides"),
      py::arg("has_file"), py::arg("mesh") = py::none(), py::arg("place") = "with_values");
}

// A scene's name with the values put into it, for a message that must tell apart runs of one
// scene (a Pool's): "mine.yaml (initial.spin = -5)".
inline std::string namedWithValues(const std::string& scene,
                                   const std::vector<scene::KeyValue>& values) {
  return values.empty() ? scene : scene + " (" + scene::valuesSaid(values, " = ") + ")";
}

}  // namespace pyrb

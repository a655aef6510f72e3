#include "python/body_mesh.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "python/convert.hpp"
#include "python/scene_value.hpp"
#include "sim/tessellate.hpp"
#include "tasks/body_mesh.hpp"

namespace py = pybind11;

namespace pyrb {

// The same surface `rattleback export` writes (tasks::bodyMesh), as (vertices m, faces).
void bindBodyMesh(py::module_& m) {
  m.def(
      "body_mesh",
      [](const LoadedScene& loaded, std::optional<int> segments) {
        auto mesh = tasks::bodyMesh(loaded.value, segments.value_or(sim::kDefaultSegments));
        if (!mesh) {
          rb::Error e = mesh.error();
          if (e.key.empty() && !e.where) e.message = "argument segments: " + e.message;
          raise(e);
        }
        const auto n = static_cast<py::ssize_t>(mesh->vertices.size());
        const auto m = static_cast<py::ssize_t>(mesh->faces.size());
        py::array_t<double> vertices({n, py::ssize_t{3}});
        py::array_t<std::int64_t> faces({m, py::ssize_t{3}});
        auto v = vertices.mutable_unchecked<2>();
        auto f = faces.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i)
          for (py::ssize_t k = 0; k < 3; ++k)
            v(i, k) = mesh->vertices[static_cast<std::size_t>(i)][k];
        for (py::ssize_t i = 0; i < m; ++i)
          for (py::ssize_t k = 0; k < 3; ++k)
            f(i, k) = mesh->faces[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
        return py::make_tuple(vertices, faces);
      },
      py::arg("scene"), py::arg("segments") = py::none());

  // Scene.from_mesh's arrays, checked for shape and range in Python first (its messages name the
  // argument); the checks here only keep a bad index from reading outside the vertices.
  py::class_<HeldMesh>(m, "HeldMesh");
  m.def(
      "hold_mesh",
      [](const py::array_t<double, py::array::c_style | py::array::forcecast>& vertices,
         const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& faces) {
        if (vertices.ndim() != 2 || vertices.shape(1) != 3 || faces.ndim() != 2 ||
            faces.shape(1) != 3)
          throw py::value_error("give vertices as an (N, 3) array and faces as an (M, 3) array");
        auto held = std::make_shared<sim::TriangleMesh>();
        const auto v = vertices.unchecked<2>();
        const auto f = faces.unchecked<2>();
        held->vertices.reserve(static_cast<std::size_t>(v.shape(0)));
        for (py::ssize_t i = 0; i < v.shape(0); ++i)
          held->vertices.emplace_back(v(i, 0), v(i, 1), v(i, 2));
        held->faces.reserve(static_cast<std::size_t>(f.shape(0)));
        for (py::ssize_t i = 0; i < f.shape(0); ++i) {
          std::array<int, 3> face{};
          for (py::ssize_t k = 0; k < 3; ++k) {
            if (f(i, k) < 0 || f(i, k) >= v.shape(0))
              throw py::value_error("argument faces: row " + std::to_string(i) +
                                    " names a vertex that is not in vertices");
            face[static_cast<std::size_t>(k)] = static_cast<int>(f(i, k));
          }
          held->faces.push_back(face);
        }
        return HeldMesh{std::move(held)};
      },
      py::arg("vertices"), py::arg("faces"));
}

}  // namespace pyrb

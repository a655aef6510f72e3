#include "python/body_mesh.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>

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
}

}  // namespace pyrb

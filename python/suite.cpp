#include "python/suite.hpp"

#include <pybind11/stl.h>

#include <string>

#include "python/convert.hpp"
#include "scene/snapshot.hpp"

namespace py = pybind11;

namespace pyrb {

// The suite's cases read by the command line's own reader (scene/snapshot.hpp), so that a pytest
// test over them draws what `rattleback snapshot` draws: paths resolved against the suite file's
// folder, the top's defaults put into each case, errors naming the suite's file, line and key.
void bindSnapshotSuite(py::module_& m) {
  m.def(
      "snapshot_suite",
      [](const std::string& path) {
        const scene::SnapshotSuite suite = take(scene::loadSnapshotSuite(path));
        py::list cases;
        for (const scene::SnapshotCase& c : suite.cases) {
          py::dict d;
          d["name"] = c.name;
          d["place"] = c.place;
          d["scene"] = c.scene;
          // A moment is given by its name, as rb.still takes it; seconds as a number.
          d["t"] = c.t.named ? py::object(py::str(std::string(rb::nameOf(*c.t.named))))
                             : py::object(py::float_(c.t.seconds));
          d["view"] = c.view ? py::object(py::str(std::string(rb::nameOf(*c.view)))) : py::none();
          d["size"] = c.size ? py::object(py::make_tuple((*c.size)[0], (*c.size)[1])) : py::none();
          d["backend"] =
              c.backend ? py::object(py::str(std::string(rb::nameOf(*c.backend)))) : py::none();
          d["title"] = c.title ? py::object(py::str(*c.title)) : py::none();
          d["tolerance"] = c.tolerance.channel;
          d["pixels"] = c.tolerance.pixels;
          d["square"] = c.tolerance.square;
          cases.append(d);
        }
        py::dict out;
        out["file"] = suite.file;
        out["goldens"] = suite.goldens;
        out["cases"] = cases;
        return out;
      },
      py::arg("path"));
}

}  // namespace pyrb

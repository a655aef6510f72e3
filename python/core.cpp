// rattleback._core: the library's scenes, runs, analysis and sweeps for Python. Wiring only:
// every check, number and text comes from tasks/, scene/ and sim/, as for the command line.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <vector>

#include "python/convert.hpp"
#include "python/scene_value.hpp"
#include "tasks/analysis.hpp"
#include "tasks/run_json.hpp"
#include "tasks/simulate.hpp"

namespace py = pybind11;

namespace pyrb {
namespace {

/// A finished run: its samples, summary and settings, kept in C++ so that to_csv writes the
/// command line's exact text.
struct Run {
  std::string scene;
  sim::Model model;
  double rate = tasks::kDefaultRate;
  std::vector<sim::Telemetry> samples;
  sim::RunSummary summary;
};

// One column of the samples as a NumPy array (a copy: the arrays outlive the run).
template <typename F>
py::array_t<double> column(const std::vector<sim::Telemetry>& samples, F value) {
  py::array_t<double> out(static_cast<py::ssize_t>(samples.size()));
  double* p = out.mutable_data();
  for (const sim::Telemetry& s : samples) *p++ = value(s);
  return out;
}

py::dict columns(const Run& run) {
  using T = sim::Telemetry;
  const auto& s = run.samples;
  py::dict d;
  d["t"] = column(s, [](const T& x) { return x.t; });
  d["spin"] = column(s, [](const T& x) { return x.spin; });
  d["energy"] = column(s, [](const T& x) { return x.energy; });
  d["kinetic"] = column(s, [](const T& x) { return x.kinetic; });
  d["potential"] = column(s, [](const T& x) { return x.potential; });
  d["elastic"] = column(s, [](const T& x) { return x.elastic; });
  d["tilt_deg"] = column(s, [](const T& x) { return x.tilt_deg; });
  d["x"] = column(s, [](const T& x) { return x.x_world.x(); });
  d["y"] = column(s, [](const T& x) { return x.x_world.y(); });
  d["z"] = column(s, [](const T& x) { return x.x_world.z(); });
  d["wx"] = column(s, [](const T& x) { return x.w_world.x(); });
  d["wy"] = column(s, [](const T& x) { return x.w_world.y(); });
  d["wz"] = column(s, [](const T& x) { return x.w_world.z(); });
  d["Lz"] = column(s, [](const T& x) { return x.L_world.z(); });
  py::array_t<std::int32_t> contacts(static_cast<py::ssize_t>(s.size()));
  std::int32_t* c = contacts.mutable_data();
  for (const T& x : s) *c++ = x.contacts;
  d["contacts"] = contacts;
  d["normal_force"] = column(s, [](const T& x) { return x.normal_force; });
  py::list modes;
  for (const T& x : s) modes.append(py::str(std::string(rb::nameOf(x.mode))));
  d["mode"] = py::module_::import("numpy").attr("array")(modes);
  return d;
}

std::shared_ptr<Run> simulate(const LoadedScene& loaded, double rate) {
  const sim::Model& model = loaded.value.model;
  if (auto ok = tasks::checkRate(rate, model.duration); !ok) raise(ok.error());
  auto run = std::make_shared<Run>();
  run->scene = loaded.value.scene.file;
  run->model = model;
  run->rate = rate;
  const tasks::SimulateResult result = interruptible([&](const std::function<bool()>& cancelled) {
    tasks::SimulateOptions options;
    options.rate = rate;
    options.cancelled = cancelled;
    options.each = [&](const sim::Telemetry& s) { run->samples.push_back(s); };
    return tasks::simulate(model, options);
  });
  run->summary = result.summary;
  if (result.outcome.ending == tasks::Ending::Stopped) {
    py::object cls = py::module_::import("rattleback._errors").attr("RunStopped");
    py::object e = cls(run->scene + ": the run stopped: " + result.outcome.message,
                       std::string(rb::nameOf(result.outcome.stop->reason)),
                       result.outcome.stop->t, result.outcome.stop->step);
    PyErr_SetObject(cls.ptr(), e.ptr());
    throw py::error_already_set();
  }
  return run;
}

}  // namespace
}  // namespace pyrb

PYBIND11_MODULE(_core, m) {
  using namespace pyrb;
  m.doc() = "rattleback's C++ library: scenes, runs, analysis and sweeps (see rattleback).";
  m.attr("version") = RATTLEBACK_VERSION;
  m.attr("default_rate") = tasks::kDefaultRate;
  py::list names;
  for (const tasks::Column& c : tasks::telemetryColumns())
    names.append(py::make_tuple(c.name, c.unit));
  m.attr("telemetry_columns") = names;

  bindScene(m);

  py::class_<Run, std::shared_ptr<Run>>(m, "Run")
      .def("columns", &columns)
      .def("result", [](const Run& r) { return toPython(tasks::runJson(r.summary)); })
      .def("model", [](const Run& r) { return toPython(tasks::modelJson(r.model)); })
      .def("sidecar",
           [](const Run& r) {
             return toPython(tasks::telemetrySidecar(r.scene, r.model, r.rate, r.summary,
                                                     static_cast<std::int64_t>(r.samples.size())));
           })
      .def_readonly("scene", &Run::scene)
      .def_readonly("rate", &Run::rate)
      .def("to_csv", [](const Run& r, const std::string& path) {
        rb::Status written;
        {
          py::gil_scoped_release release;
          written = tasks::writeTelemetry(path, r.scene, r.model, r.rate, r.summary, r.samples);
        }
        if (!written) raise(written.error());
      });

  m.def("simulate", &simulate, py::arg("scene"), py::arg("rate"));
  m.def("analyze", [](const LoadedScene& loaded, std::optional<double> spin) {
    const sim::Model& model = loaded.value.model;
    return toPython(tasks::analysisJson(model, tasks::analysisSpin(model, spin)));
  }, py::arg("scene"), py::arg("spin") = py::none());
}

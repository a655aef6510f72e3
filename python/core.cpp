// rattleback._core: the library's scenes, runs, analysis and sweeps for Python. Wiring only:
// every check, number and text comes from tasks/, scene/ and sim/, as for the command line.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "python/body_mesh.hpp"
#include "python/convert.hpp"
#include "python/scene_value.hpp"
#include "python/simulation.hpp"
#include "python/suite.hpp"
#include "scene/keys.hpp"
#include "tasks/analysis.hpp"
#include "tasks/check.hpp"
#include "tasks/manifest.hpp"
#include "tasks/player_data.hpp"
#include "tasks/run_json.hpp"
#include "tasks/simulate.hpp"
#include "tasks/sweep.hpp"
#include "tasks/sweep_jobs.hpp"
#include "util/arguments.hpp"
#include "util/output_place.hpp"

namespace py = pybind11;

namespace pyrb {
namespace {

// A finished run: its samples, and its sidecar, made with it (the scene as read, the model, what
// the run found, the check), from which its result, model and check are read and which to_csv
// writes. So a run pickles as these four, exactly, and a worker process can return one.
struct Run {
  std::string scene;
  double rate = tasks::kDefaultRate;
  std::vector<sim::Telemetry> samples;
  nlohmann::json sidecar;  ///< telemetrySidecar: its "check" null without check=True
};

// A sample as its doubles (sim::doublesOf), then the count and the mode as whole numbers
// (exact).
constexpr std::size_t kSampleFields = sim::kTelemetryDoubles + 2;

void packSample(sim::Telemetry s, double* out) {
  for (double* field : sim::doublesOf(s)) *out++ = *field;
  *out++ = s.contacts;
  *out = static_cast<int>(s.mode);
}

sim::Telemetry unpackSample(const double* f) {
  sim::Telemetry s;
  for (double* field : sim::doublesOf(s)) *field = *f++;
  s.contacts = static_cast<int>(f[0]);
  s.mode = static_cast<sim::ContactModel>(static_cast<int>(f[1]));
  return s;
}

// Pickled as (scene, rate, sidecar as JSON text, samples as bytes of doubles); the version first,
// so that a pickle of another layout is refused rather than misread.
constexpr int kRunPickleVersion = 2;  // 2: with friction_force

py::tuple runState(const Run& r) {
  std::vector<double> packed(r.samples.size() * kSampleFields);
  for (std::size_t i = 0; i < r.samples.size(); ++i)
    packSample(r.samples[i], packed.data() + i * kSampleFields);
  return py::make_tuple(
      kRunPickleVersion, r.scene, r.rate, r.sidecar.dump(),
      py::bytes(reinterpret_cast<const char*>(packed.data()), packed.size() * sizeof(double)));
}

std::shared_ptr<Run> runOfState(const py::tuple& state) {
  if (state.size() != 5 || state[0].cast<int>() != kRunPickleVersion)
    throw py::value_error("not a pickled rattleback Run of this version");
  auto run = std::make_shared<Run>();
  run->scene = state[1].cast<std::string>();
  run->rate = state[2].cast<double>();
  run->sidecar = nlohmann::json::parse(state[3].cast<std::string>());
  const std::string bytes = state[4].cast<std::string>();
  if (bytes.size() % (kSampleFields * sizeof(double)) != 0)
    throw py::value_error("not a pickled rattleback Run of this version");
  std::vector<double> packed(bytes.size() / sizeof(double));
  std::memcpy(packed.data(), bytes.data(), bytes.size());
  for (std::size_t i = 0; i < packed.size(); i += kSampleFields)
    run->samples.push_back(unpackSample(packed.data() + i));
  return run;
}

// Made read-only: a column is the run's record, and to_csv writes the samples, not the arrays
// (`s = run.spin; s *= 2` changed run.spin and to_pandas() but not the CSV). The flag is set on
// the array itself, as pybind11's Eigen views set it, for the per-call cost.
template <typename A>
A frozen(A a) {
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// One column of the samples as a NumPy array (a copy: the arrays outlive the run), read-only.
template <typename F>
py::array_t<double> column(const std::vector<sim::Telemetry>& samples, F value) {
  py::array_t<double> out(static_cast<py::ssize_t>(samples.size()));
  double* p = out.mutable_data();
  for (const sim::Telemetry& s : samples) *p++ = value(s);
  return frozen(std::move(out));
}

// The array a column fills, of its kind's type (tasks::ColumnKind): float64; int64 for a count,
// as pandas and NumPy read a column of whole numbers (pd.read_csv of the CSV gives int64, so a
// frame from to_pandas and one read from the CSV compare equal); and for the mode an index into
// its names, made text by NumPy at once (a Python string a sample was most of the column's cost).
struct ColumnArray {
  py::array_t<double> numbers;
  py::array_t<std::int64_t> counts;
  py::array_t<std::uint8_t> modes;
  double* number = nullptr;
  std::int64_t* count = nullptr;
  std::uint8_t* mode = nullptr;
  void make(tasks::ColumnKind kind, py::ssize_t n) {
    switch (kind) {
      case tasks::ColumnKind::Number:
        number = (numbers = py::array_t<double>(n)).mutable_data();
        break;
      case tasks::ColumnKind::Count:
        count = (counts = py::array_t<std::int64_t>(n)).mutable_data();
        break;
      case tasks::ColumnKind::Mode:
        mode = (modes = py::array_t<std::uint8_t>(n)).mutable_data();
        break;
    }
  }
  void set(py::ssize_t k, double value) {
    if (number) number[k] = value;
    if (count) count[k] = static_cast<std::int64_t>(value);
    if (mode) mode[k] = static_cast<std::uint8_t>(value);
  }
  py::object array(tasks::ColumnKind kind) && {
    if (kind == tasks::ColumnKind::Number) return frozen(std::move(numbers));
    if (kind == tasks::ColumnKind::Count) return frozen(std::move(counts));
    py::list names;
    for (const auto& [value, name] : rb::NameTable<sim::ContactModel>::entries)
      names.append(py::str(std::string(name)));
    const py::module_ np = py::module_::import("numpy");
    return frozen(py::array(np.attr("array")(names).attr("__getitem__")(modes)));
  }
};

// Every telemetry column (tasks::telemetryTable, in the CSV's order) as a read-only array, all
// filled in one pass over the samples (a pass a column read a 10 kHz run's 30 MB 20 times over).
py::dict columns(const Run& run) {
  const auto table = tasks::telemetryTable();
  const auto n = static_cast<py::ssize_t>(run.samples.size());
  std::vector<ColumnArray> arrays(table.size());
  for (std::size_t i = 0; i < table.size(); ++i) arrays[i].make(table[i].kind, n);
  py::ssize_t k = 0;
  for (const sim::Telemetry& s : run.samples) {
    const Eigen::Quaterniond q = tasks::attitude(s);
    const tasks::SampleView view{s, q};
    for (std::size_t i = 0; i < table.size(); ++i) arrays[i].set(k, table[i].value(view));
    ++k;
  }
  py::dict d;
  for (std::size_t i = 0; i < table.size(); ++i)
    d[table[i].column.name] = std::move(arrays[i]).array(table[i].kind);
  return d;
}

std::shared_ptr<Run> simulate(const LoadedScene& loaded, double rate, bool check) {
  const sim::Model& model = loaded.value.model;
  if (auto ok = tasks::checkRate(rate, model.duration); !ok) raise(ok.error());
  auto run = std::make_shared<Run>();
  run->scene = loaded.value.scene.file;
  run->rate = rate;
  const tasks::SimulateResult result =
      interruptibleHere([&](const std::function<bool()>& cancelled) {
        tasks::SimulateOptions options;
        options.rate = rate;
        options.cancelled = cancelled;
        options.each = [&](const sim::Telemetry& s) { run->samples.push_back(s); };
        return tasks::simulate(model, options);
      });
  run->sidecar = tasks::telemetrySidecar(
      {run->scene, loaded.value.scene.values, loaded.value.scene.content, loaded.has_file}, model,
      rate, result.summary, static_cast<std::int64_t>(run->samples.size()), nullptr);
  if (result.outcome.ending == tasks::Ending::Stopped) {
    // The run as far as it went goes with the exception; the message names the values put in,
    // so that of a Pool's runs of one scene the one that stopped is told apart.
    const std::string named = namedWithValues(run->scene, loaded.value.scene.values);
    py::object cls = py::module_::import("rattleback._errors").attr("RunStopped");
    py::object e = cls(named + ": the run stopped: " + result.outcome.message,
                       std::string(rb::nameOf(result.outcome.stop->reason)), result.outcome.stop->t,
                       result.outcome.stop->step, py::cast(run));
    PyErr_SetObject(cls.ptr(), e.ptr());
    throw py::error_already_set();
  }
  if (check) {
    std::vector<double> spins;
    for (const sim::Telemetry& s : run->samples) spins.push_back(s.spin);
    const auto checked = interruptibleHere([&](const std::function<bool()>& cancelled) {
      return tasks::checkRun(model, rate, result.summary, spins, cancelled);
    });
    // Where telemetrySidecar puts a check (last, as the command line's sidecar has it).
    if (checked) run->sidecar["check"] = tasks::checkJson(*checked);
  }
  return run;
}

/// A sweep's table: the rows in the sweep's order, typed.
struct SweepTable {
  scene::Sweep sweep;
  std::vector<tasks::SweepRow> rows;
  std::vector<std::string> notes;  ///< tasks::sweepNotes: warned of by rattleback.sweep
  bool interrupted = false;        ///< the rows finished before Ctrl-C only
};

void checkJobs(int jobs) {
  if (jobs < 0 || jobs > 1024)
    throw py::value_error("argument jobs: threads must be 1 … 1024 (0: all cores), not " +
                          std::to_string(jobs));
}

// Whether two sweeps run the same scenes: the same base, values, axes and duration.
bool sameSweep(const scene::Sweep& a, const scene::Sweep& b) {
  std::vector<std::string> a_columns, b_columns;
  for (const auto& c : a.columns) a_columns.push_back(c.name);
  for (const auto& c : b.columns) b_columns.push_back(c.name);
  if (a.base_text != b.base_text || a.duration != b.duration || a_columns != b_columns ||
      a.base_values.size() != b.base_values.size() || a.axes.size() != b.axes.size())
    return false;
  for (std::size_t i = 0; i < a.base_values.size(); ++i)
    if (a.base_values[i].key != b.base_values[i].key ||
        a.base_values[i].yaml != b.base_values[i].yaml)
      return false;
  for (std::size_t i = 0; i < a.axes.size(); ++i)
    if (a.axes[i].key != b.axes[i].key || a.axes[i].values != b.axes[i].values) return false;
  return true;
}

// `done` and `more` as one table in the sweep's order.
std::vector<tasks::SweepRow> together(std::vector<tasks::SweepRow> done,
                                      std::vector<tasks::SweepRow> more) {
  done.insert(done.end(), std::make_move_iterator(more.begin()),
              std::make_move_iterator(more.end()));
  std::sort(done.begin(), done.end(),
            [](const tasks::SweepRow& x, const tasks::SweepRow& y) { return x.row < y.row; });
  return done;
}

// Runs the sweep's rows (those not in `resume`, a table of it kept from Ctrl-C, whose rows
// the table then holds too).
std::shared_ptr<SweepTable> runSweepTable(scene::Sweep sweep, int jobs,
                                          const std::shared_ptr<SweepTable>& resume) {
  auto table = std::make_shared<SweepTable>();
  table->sweep = std::move(sweep);
  if (resume && !sameSweep(resume->sweep, table->sweep))
    throw py::value_error("argument resume: a table of another sweep (" + resume->sweep.file +
                          "): its base, values, axes or duration differ from these");
  auto scenes = take(scene::SweepScenes::open(table->sweep));
  table->notes = tasks::sweepNotes(table->sweep, scenes);
  std::vector<tasks::SweepRow> done = resume ? resume->rows : std::vector<tasks::SweepRow>{};
  std::vector<bool> ran(static_cast<std::size_t>(table->sweep.rows()), false);
  for (const tasks::SweepRow& r : done) ran[static_cast<std::size_t>(r.row)] = true;
  std::vector<std::int64_t> rows;
  for (std::int64_t r = 0; r < table->sweep.rows(); ++r)
    if (!ran[static_cast<std::size_t>(r)]) rows.push_back(r);
  // Ctrl-C keeps the rows finished by then, as the exception's `table` (the command line keeps
  // them in its journal for --resume).
  const auto keep = [&](py::handle interrupt, tasks::SweepRun&& stopped) {
    auto kept = std::make_shared<SweepTable>();
    kept->sweep = table->sweep;
    kept->notes = table->notes;
    kept->rows = together(done, std::move(stopped.rows));
    kept->interrupted = true;
    (void)PyObject_SetAttrString(interrupt.ptr(), "table", py::cast(kept).ptr());
  };
  tasks::SweepRun run = interruptibleHere(
      [&](const std::function<bool()>& cancelled) {
        tasks::SweepOptions options;
        options.jobs = jobs;
        options.cancelled = cancelled;
        return tasks::runSweep(table->sweep, scenes, rows, options);
      },
      keep);
  table->rows = together(std::move(done), std::move(run.rows));
  return table;
}

// The argument columns= (Python's: a sweep file's columns: is its own), put over the sweep's.
void putColumns(scene::Sweep& sweep, const std::optional<std::vector<std::string>>& columns) {
  if (!columns) return;
  if (auto ok = tasks::setColumns(sweep, *columns, "argument columns"); !ok) raise(ok.error());
}

std::shared_ptr<SweepTable> sweep(const std::string& path, int jobs,
                                  const std::shared_ptr<SweepTable>& resume,
                                  const std::optional<std::vector<std::string>>& columns) {
  checkJobs(jobs);
  scene::Sweep made = take(tasks::loadSweep(tasks::findShipped(path)));
  putColumns(made, columns);
  return runSweepTable(std::move(made), jobs, resume);
}

// A sweep made in Python: `vary` (and `duration`) as a sweep file's YAML, over a scene's text
// and values; messages name "argument vary"; the table is named `name`.
std::shared_ptr<SweepTable> sweepOf(const std::string& vary, const std::string& name,
                                    const std::string& base_yaml, const std::string& base_name,
                                    const std::vector<std::pair<std::string, std::string>>& values,
                                    int jobs, const std::shared_ptr<SweepTable>& resume,
                                    const std::optional<std::vector<std::string>>& columns) {
  checkJobs(jobs);
  scene::SweepBase base{base_yaml, base_name, {}};
  for (const auto& [key, yaml] : values) base.values.push_back({key, yaml});
  scene::Sweep made = take(tasks::loadSweepText(vary, "argument vary", base));
  putColumns(made, columns);
  made.file = name;
  return runSweepTable(std::move(made), jobs, resume);
}

// The table's columns by name: the row index, each axis's values as written (the package makes
// numbers of them), and each result column (tasks::sweepResultTable): a number where the column
// has one (NaN for none), else its text.
py::dict sweepColumns(const SweepTable& t) {
  py::dict d;
  const auto n = static_cast<py::ssize_t>(t.rows.size());
  py::array_t<std::int64_t> row(n);
  for (py::ssize_t i = 0; i < n; ++i) row.mutable_data()[i] = t.rows[i].row;
  d["row"] = row;
  for (std::size_t a = 0; a < t.sweep.axes.size(); ++a) {
    py::list values;
    for (const tasks::SweepRow& r : t.rows) values.append(r.values[a]);
    d[py::str(t.sweep.axes[a].key)] = values;
  }
  for (const tasks::SweepResultColumn* c : tasks::tableColumns(t.sweep)) {
    if (c->value) {
      py::array_t<double> out(n);
      for (py::ssize_t i = 0; i < n; ++i) out.mutable_data()[i] = c->value(t.rows[i]);
      d[c->column.name] = out;
    } else {
      py::list text;
      for (const tasks::SweepRow& r : t.rows) text.append(c->text(r));
      d[c->column.name] = text;
    }
  }
  return d;
}

void sweepToCsv(const SweepTable& t, const std::string& path) {
  std::vector<std::string> keys, lines;
  const tasks::SweepColumns columns = tasks::tableColumns(t.sweep);
  for (const auto& axis : t.sweep.axes) keys.push_back(axis.key);
  for (const tasks::SweepRow& r : t.rows) lines.push_back(tasks::sweepLine(r, columns));
  nlohmann::json sidecar = tasks::sweepSidecar(t.sweep, std::nullopt);
  // A table kept from Ctrl-C says so, and counts its own rows, not the sweep's (its sidecar claimed
  // all 40,000 for 3,802 rows).
  if (t.interrupted) {
    sidecar["rows"] = t.rows.size();
    sidecar["interrupted"] = {{"rows_run", t.rows.size()}, {"sweep_rows", t.sweep.rows()}};
  }
  rb::Status written;
  {
    GilReleased release;
    const rb::OutputNamedBy naming("to_csv");  // the way out an error line suggests
    // Not over the sweep or its base, nor as a picture, as the command line refuses them
    // (to_csv("mine.yaml") would replace the scene).
    written = rb::checkDataOutput(path, "a CSV table", ".csv", {t.sweep.file, t.sweep.base});
    if (written) written = tasks::writeSweepTable(path, keys, columns, lines, sidecar);
    if (written)
      (void)tasks::recordOutputs({{path,
                                   tasks::OutputKind::Sweep,
                                   std::filesystem::path(t.sweep.file).stem().string(),
                                   "",
                                   {},
                                   {}}});
  }
  if (!written) raise(written.error());
}

}  // namespace
}  // namespace pyrb

namespace pyrb {
namespace {

// Writes a finished run as `format` with its sidecar, as simulate -o does. Ctrl-C stops the
// writing, puts nothing in place and raises KeyboardInterrupt (it finished, replaced the file
// there and then raised it).
void writeRun(const Run& r, const std::string& path, const char* method,
              tasks::TelemetryFormat format) {
  const rb::Status written = interruptibleHere([&](const std::function<bool()>& cancelled) {
    const rb::OutputNamedBy naming(method);  // the way out an error line suggests
    // Not over the run's scene, nor as a picture, as the command line refuses them
    // (to_csv("mine.yaml") would replace the scene); nor in another format than the method's.
    const nlohmann::json& scene_path = r.sidecar.at("scene_path");
    rb::Status status = rb::checkDataOutput(
        path, tasks::formatName(format), tasks::extensionOf(format),
        {scene_path.is_string() ? scene_path.get<std::string>() : std::string()});
    if (status) status = tasks::checkTelemetryName(path, method);
    if (status && tasks::telemetryFormatOf(path) != format)
      status = rb::Status::fail(std::string(method) + " " + path + ": writes " +
                                tasks::formatName(format) + "; give a name ending in " +
                                tasks::extensionOf(format));
    if (status) status = tasks::writeTelemetry(path, r.samples, r.sidecar, cancelled, format);
    // Listed in the folder's manifest, as the command line lists it (a failure to list loses
    // nothing: the report then places the file by its name).
    if (status)
      (void)tasks::recordOutputs({{path,
                                   tasks::OutputKind::Telemetry,
                                   stemOf(r.scene, !scene_path.is_null()),
                                   "",
                                   {},
                                   {},
                                   tasks::madeFrom(r.sidecar)}});
    return status;
  });
  if (!written) raise(written.error());
}

// A finished run: its columns, what it found, its pickle and its files.
void bindRun(py::module_& m) {
  py::class_<Run, std::shared_ptr<Run>>(m, "Run")
      .def("columns", &columns)
      .def("result", [](const Run& r) { return toPython(r.sidecar.at("result")); })
      .def("check",
           [](const Run& r) {
             return toPython(r.sidecar.contains("check") ? r.sidecar["check"] : nullptr);
           })
      .def("model", [](const Run& r) { return toPython(r.sidecar.at("model")); })
      .def("sidecar", [](const Run& r) { return toPython(r.sidecar); })
      .def(py::pickle([](const Run& r) { return runState(r); },
                      [](const py::tuple& state) { return runOfState(state); }))
      .def_readonly("scene", &Run::scene)
      .def_readonly("rate", &Run::rate)
      .def("to_csv",
           [](const Run& r, const std::string& path) {
             writeRun(r, path, "to_csv", tasks::TelemetryFormat::Csv);
           })
      .def("to_npz",
           [](const Run& r, const std::string& path) {
             writeRun(r, path, "to_npz", tasks::TelemetryFormat::Npz);
           })
      .def("to_hdf5", [](const Run& r, const std::string& path) {
        writeRun(r, path, "to_hdf5", tasks::TelemetryFormat::Hdf5);
      });
}

// A sweep's table and the calls that make one.
void bindSweep(py::module_& m) {
  py::class_<SweepTable, std::shared_ptr<SweepTable>>(m, "SweepTable")
      .def("columns", &sweepColumns)
      .def("to_csv", &sweepToCsv, py::arg("path"))
      .def_property_readonly("file", [](const SweepTable& t) { return t.sweep.file; })
      .def_property_readonly("notes", [](const SweepTable& t) { return t.notes; })
      .def_property_readonly("interrupted", [](const SweepTable& t) { return t.interrupted; })
      .def_property_readonly("base", [](const SweepTable& t) { return t.sweep.base; })
      // Where every row was refused, the first one's reason (whether or not the table's columns
      // list status and message): rattleback.sweep warns of it, as the command line exits 2.
      .def_property_readonly("first_refusal",
                             [](const SweepTable& t) -> std::optional<std::string> {
                               if (t.rows.empty()) return std::nullopt;
                               for (const tasks::SweepRow& r : t.rows)
                                 if (r.status != tasks::RowStatus::Refused) return std::nullopt;
                               return t.rows.front().message;
                             })
      // The result columns that count (SweepResultColumn::whole), in the table's order.
      .def_property_readonly(
          "whole_columns",
          [](const SweepTable& t) {
            std::vector<std::string> names;
            for (const tasks::SweepResultColumn* c : tasks::tableColumns(t.sweep))
              if (c->whole) names.push_back(c->column.name);
            return names;
          })
      .def_property_readonly("keys", [](const SweepTable& t) {
        std::vector<std::string> keys;
        for (const auto& axis : t.sweep.axes) keys.push_back(axis.key);
        return keys;
      });
  m.def("sweep", &sweep, py::arg("path"), py::arg("jobs"), py::arg("resume") = nullptr,
        py::arg("columns") = py::none());
  m.def("sweep_of", &sweepOf, py::arg("vary"), py::arg("name"), py::arg("base_yaml"),
        py::arg("base_name"), py::arg("values"), py::arg("jobs"), py::arg("resume") = nullptr,
        py::arg("columns") = py::none());
}

// Runs, the player's data and the analysis of a loaded scene.
std::string playerScriptOf(const LoadedScene& loaded, const Run& run, const std::string& id) {
  const sim::Model& model = loaded.value.model;
  std::vector<double> reversals;
  for (const auto& t : run.sidecar.at("result").at("reversals_s"))
    reversals.push_back(t.get<double>());
  tasks::PlayerRun player = tasks::playerRunOf(
      id, model, tasks::playerFrame(loaded.value.scene, model), tasks::posesOf(run.samples),
      std::move(reversals), tasks::playerSurfaceOf(loaded.value));
  // The body spun the other way, as the report adds it: the same function, from the model the
  // run recorded (simulate(duration=1)'s other way runs 1 s too).
  player.other = tasks::otherSpinOf(model, run.sidecar.at("model"), run.rate);
  return tasks::playerScript(player);
}

// For bench/python_speed.py: the C++ run alone (samples kept as simulate keeps them), the median
// of `repeats` calls, s.
double nativeSeconds(const LoadedScene& loaded, double rate, int repeats) {
  GilReleased release;
  std::vector<double> times;
  for (int i = 0; i < repeats; ++i) {
    std::vector<sim::Telemetry> samples;
    tasks::SimulateOptions options;
    options.rate = rate;
    options.each = [&](const sim::Telemetry& x) { samples.push_back(x); };
    const auto start = std::chrono::steady_clock::now();
    tasks::simulate(loaded.value.model, options);
    times.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

py::object analyzeOf(const LoadedScene& loaded, std::optional<double> spin) {
  if (auto ok = tasks::checkAnalysisSpin(spin, "argument spin"); !ok) raise(ok.error());
  return toPython(tasks::analysisJson(tasks::analyze(loaded.value.model, spin)));
}

py::object linearizeOf(const LoadedScene& loaded, std::optional<double> spin) {
  if (auto ok = tasks::checkAnalysisSpin(spin, "argument spin"); !ok) raise(ok.error());
  const sim::Model& model = loaded.value.model;
  if (model.body->surface.kind == sim::Surface::Kind::Mesh &&
      !model.body->surface.mesh.fit.usable())
    throw py::value_error(
        "linearize: this mesh body's bottom does not fit a smooth surface to roll on (" +
        model.body->surface.mesh.fit.problem +
        "), so it has no linearised rolling model (docs/physics.md P11.4)");
  return toPython(
      tasks::linearisationJson(sim::linearise(model, tasks::analysisSpin(model, spin))));
}

void bindCalls(py::module_& m) {
  m.def("player_script", &playerScriptOf, py::arg("scene"), py::arg("run"), py::arg("id"));
  m.def("_native_seconds", &nativeSeconds, py::arg("scene"), py::arg("rate"), py::arg("repeats"));
  m.def("simulate", &simulate, py::arg("scene"), py::arg("rate"), py::arg("check") = false);
  m.def("analyze", &analyzeOf, py::arg("scene"), py::arg("spin") = py::none());
  m.def("linearize", &linearizeOf, py::arg("scene"), py::arg("spin") = py::none());
  // Every scene key's dotted path, from the keys' one table (scene/keys.cpp): a function's
  // unknown keyword that is a key's last word is told where it goes (rattleback/_args.py).
  std::vector<std::string> paths;
  for (const scene::Key& key : scene::keys()) paths.emplace_back(key.path);
  m.attr("scene_keys") = paths;
}

}  // namespace
}  // namespace pyrb

PYBIND11_MODULE(_core, m) {
  using namespace pyrb;
  m.doc() = "rattleback's C++ library: scenes, runs, analysis and sweeps (see rattleback).";
  // Messages name "argument dt", not "--dt" (each module holds its own copy of the style).
  rb::argument_style = rb::ArgumentStyle::Keyword;
  m.attr("version") = RATTLEBACK_VERSION;
  m.attr("default_rate") = tasks::kDefaultRate;
  py::list names;
  for (const tasks::Column& c : tasks::telemetryColumns())
    names.append(py::make_tuple(c.name, c.unit, c.meaning));
  m.attr("telemetry_columns") = names;

  bindScene(m);
  bindSimulation(m);
  bindBodyMesh(m);
  bindRun(m);
  bindSweep(m);
  bindCalls(m);
  bindSnapshotSuite(m);
}

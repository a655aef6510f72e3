// rattleback._core.Simulation: a run stepped from Python (rattleback.Simulation), the library's
// sim::Rollout as the commands drive it. Wiring only: the physics of a state set mid-run
// (sim::withParts, Rollout::setState) and of stepping is sim/'s.
#include "python/simulation.hpp"

#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "python/convert.hpp"
#include "python/scene_value.hpp"
#include "sim/initial.hpp"
#include "sim/rollout.hpp"
#include "sim/step_interpolant.hpp"
#include "tasks/telemetry_columns.hpp"
#include "util/format.hpp"

namespace pyrb {
namespace {

// One run being stepped. Its steps release the GIL, so a lock keeps two Python threads from
// stepping the same run at once (each waits for the other's call to end).
struct Simulation {
  sim::Rollout run;
  std::string scene;
  std::shared_ptr<std::mutex> busy = std::make_shared<std::mutex>();
};

py::list listOf(const Eigen::Vector3d& v) {
  return py::cast(std::vector<double>{v.x(), v.y(), v.z()});
}

// The state at time t of the last step, as the fields of rattleback.State: the run's own
// state (stateAt: on the constraint, quaternion normalised) and its telemetry there.
py::dict stateDict(const sim::Rollout& run, double t) {
  const sim::State s = run.stateAt(t);
  const sim::Telemetry m = run.sampleAt(t);
  const Eigen::Quaterniond q = tasks::attitude(m);  // as the telemetry's qw … qz columns
  py::dict d;
  // Every telemetry column's value at t, from the one table (rb.State keeps those it declares:
  // spin, tilt_deg, mode, contacts, normal_force and the energies), as simulate's arrays give it.
  const auto& modes = rb::NameTable<sim::ContactModel>::entries;
  for (const tasks::TelemetryColumn& c : tasks::telemetryTable()) {
    const double value = c.value({m, q});
    if (c.kind == tasks::ColumnKind::Number)
      d[c.column.name] = value;
    else if (c.kind == tasks::ColumnKind::Count)
      d[c.column.name] = static_cast<std::int64_t>(value);
    else
      d[c.column.name] = std::string(modes[static_cast<std::size_t>(value)].second);
  }
  // The vectors the columns hold in parts, and those they do not hold (body-axes ω, velocity).
  d["t"] = t;
  d["position"] = listOf(s.x_world);
  d["quaternion"] = py::cast(std::vector<double>{q.w(), q.x(), q.y(), q.z()});
  d["velocity"] = listOf(s.v_world);
  d["angular_velocity"] = listOf(q.toRotationMatrix().transpose() * m.w_world);
  d["angular_velocity_world"] = listOf(m.w_world);
  return d;
}

// RunStopped for a run that stopped by itself (as simulate raises it; no Run goes with it).
void raiseIfStopped(const Simulation& s) {
  const sim::RunSummary& summary = s.run.summary();
  if (!summary.stop) return;
  py::object cls = py::module_::import("rattleback._errors").attr("RunStopped");
  py::object e = cls(s.scene + ": the run stopped: " + summary.divergence.value_or(""),
                     std::string(rb::nameOf(summary.stop->reason)), summary.stop->t,
                     summary.stop->step, py::none());
  PyErr_SetObject(cls.ptr(), e.ptr());
  throw py::error_already_set();
}

// The run's end, as a message's way out says it.
std::string pastTheEnd(const Simulation& s, double t) {
  return rb::show(t) + " s is past the run's end, " + rb::show(s.run.endTime()) +
         " s: give Simulation a longer duration=";
}

// Steps while `more()` and the run goes on, with the GIL released; Ctrl-C (asked after every
// step, at most every 20 ms a look: interruptibleHere) leaves the run at the step reached and
// raises KeyboardInterrupt. The last step's telemetry is then due at its end.
template <typename More>
void stepWhile(Simulation& s, More more) {
  interruptibleHere([&](const std::function<bool()>& cancelled) {
    std::lock_guard lock(*s.busy);
    while (more() && !cancelled())
      if (!s.run.advanceOneStep()) break;
    return 0;
  });
  raiseIfStopped(s);
}

bool reached(const sim::Rollout& run, double t) {
  return run.current().t >= t || sim::sameTime(run.current().t, t);
}

// advance(t): the steps Rollout::advanceTo(t) takes (until the run reaches t), then the state
// at t on the last step's interpolant, as simulate samples it.
py::dict advanceTo(Simulation& s, double t, bool exactly) {
  if (!std::isfinite(t)) throw py::value_error("argument t: must be a finite number");
  if (t > s.run.endTime() && !sim::sameTime(t, s.run.endTime()))
    throw py::value_error("argument t: " + pastTheEnd(s, t));
  if (t < s.run.previousTime() && !sim::sameTime(t, s.run.previousTime()))
    throw py::value_error(
        "argument t: " + rb::show(t) + " s lies before the last step, which starts at " +
        rb::show(s.run.previousTime()) + " s: a run goes forward (copy() keeps one to go back to)");
  bool landing = false;
  if (exactly) {
    std::lock_guard lock(*s.busy);  // (as stepping does: another thread may hold the run)
    landing = s.run.landAt(t);
  }
  if (exactly && !landing) {
    // Fixed steps end at multiples of dt: t is one already, or cannot be landed on.
    const double dt = s.run.model().dt, k = std::round(t / dt);
    if (!sim::sameTime(k * dt, t))
      throw py::value_error("argument exactly: fixed steps end at multiples of dt, " +
                            rb::show(dt) + " s, and " + rb::show(t) +
                            " s is none: give a multiple of dt, or an adaptive integrator");
  }
  stepWhile(s, [&] { return !reached(s.run, t); });
  if (landing) {
    std::lock_guard lock(*s.busy);
    (void)s.run.landAt(std::nullopt);  // a run stopped before t lands nowhere later
  }
  (void)s.run.advanceTo(t);  // takes no step: the summary's last sample is now at t
  return stateDict(s.run, std::min(t, s.run.current().t));
}

// advance(until="reversal"): steps until the reversal rule confirms its next reversal (n has
// gone on to 1 % of the initial spin the new way and held there 0.2 s), or to the run's end. The
// reversal's time, its zero crossing located on the step it fell in, s; None at the end.
py::object advanceToReversal(Simulation& s) {
  const std::size_t before = s.run.reversals().size();
  stepWhile(s,
            [&] { return s.run.reversals().size() == before && !reached(s.run, s.run.endTime()); });
  if (s.run.reversals().size() == before) return py::none();
  return py::float_(s.run.reversals()[before]);
}

std::optional<Eigen::Vector3d> vectorOf(const std::optional<std::vector<double>>& v,
                                        const char* name) {
  if (!v) return std::nullopt;
  if (v->size() != 3) throw py::value_error(std::string("argument ") + name + ": give 3 numbers");
  return Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
}

py::dict setState(Simulation& s, const std::optional<std::vector<double>>& position,
                  const std::optional<std::vector<double>>& quaternion,
                  const std::optional<std::vector<double>>& velocity,
                  const std::optional<std::vector<double>>& angular_velocity) {
  sim::StateParts parts;
  parts.x_world = vectorOf(position, "position");
  parts.v_world = vectorOf(velocity, "velocity");
  parts.w_body = vectorOf(angular_velocity, "angular_velocity");
  if (quaternion) {
    const std::vector<double>& q = *quaternion;
    if (q.size() != 4 || Eigen::Vector4d(q[0], q[1], q[2], q[3]).norm() == 0)
      throw py::value_error("argument quaternion: give 4 numbers (w, x, y, z), not all 0");
    parts.q = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  }
  std::lock_guard lock(*s.busy);
  auto state = sim::withParts(s.run.model(), s.run.current(), parts);
  if (!state) throw py::value_error("argument " + state.error().key + ": " + state.error().message);
  s.run.setState(state.value());
  return stateDict(s.run, s.run.current().t);
}

}  // namespace

void bindSimulation(py::module_& m) {
  py::class_<Simulation, std::shared_ptr<Simulation>>(m, "Simulation")
      .def(py::init([](const LoadedScene& loaded) {
             auto s = std::make_shared<Simulation>(
                 Simulation{sim::Rollout(loaded.value.model), loaded.value.scene.file});
             raiseIfStopped(*s);  // a body started on its rim
             return s;
           }),
           py::arg("scene"))
      .def_property_readonly("t", [](const Simulation& s) { return s.run.current().t; })
      .def_property_readonly("end", [](const Simulation& s) { return s.run.endTime(); })
      .def_property_readonly("steps", [](const Simulation& s) { return s.run.current().step; })
      .def_property_readonly("reversals", [](const Simulation& s) { return s.run.reversals(); })
      .def("state", [](const Simulation& s) { return stateDict(s.run, s.run.current().t); })
      .def("state_at",
           [](const Simulation& s, double t) {
             if (!(t >= s.run.previousTime() || sim::sameTime(t, s.run.previousTime())) ||
                 !(t <= s.run.current().t || sim::sameTime(t, s.run.current().t)))
               throw py::value_error(
                   "argument t: " + rb::show(t) + " s is outside the last step, [" +
                   rb::show(s.run.previousTime()) + ", " + rb::show(s.run.current().t) +
                   "] s: advance(t) goes on to a later time; copy() before stepping keeps a run "
                   "to read earlier times from");
             return stateDict(s.run, t);
           })
      .def("step",
           [](Simulation& s) {
             if (reached(s.run, s.run.endTime()))
               throw py::value_error("the run is at its end, " + rb::show(s.run.endTime()) +
                                     " s: give Simulation a longer duration=");
             bool once = true;
             stepWhile(s, [&] { return std::exchange(once, false); });
             return stateDict(s.run, s.run.current().t);
           })
      .def("advance_to", &advanceTo, py::arg("t"), py::arg("exactly"))
      .def("advance_to_reversal", &advanceToReversal)
      .def("set_state", &setState, py::arg("position"), py::arg("quaternion"), py::arg("velocity"),
           py::arg("angular_velocity"))
      .def("copy",
           [](const Simulation& s) {
             std::lock_guard lock(*s.busy);
             return std::make_shared<Simulation>(Simulation{sim::Rollout(s.run), s.scene});
           })
      .def_readonly("scene", &Simulation::scene);
}

}  // namespace pyrb

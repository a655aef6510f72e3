#include "sim/compile.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <sstream>

#include "sim/analysis.hpp"
#include "sim/contact_model.hpp"
#include "sim/continuum.hpp"
#include "sim/initial.hpp"
#include "sim/integrator.hpp"
#include "sim/mesh_body.hpp"
#include "sim/stability.hpp"
#include "util/arguments.hpp"
#include "util/format.hpp"
#include "util/nearest.hpp"

namespace sim {
namespace {

using rb::show;

// Range checks, each returning the error for `key` or nothing.
std::optional<rb::Error> needFinite(const std::string& key, double v) {
  if (std::isfinite(v)) return std::nullopt;
  return rb::Error{key, "must be a finite number, not " + show(v)};
}
// A word that is none of its key's choices, with the nearest when it is a typo of one ("must
// be points, smooth, rolling or auto, not 'roling'; did you mean rolling?").
template <typename E>
rb::Error wrongWord(const char* key, const std::string& given) {
  const std::optional<std::string> nearest = rb::nearestWord(given, rb::namesOf<E>());
  return rb::Error{key, "must be " + rb::choices<E>() + ", not '" + given + "'" +
                            (nearest ? "; did you mean " + *nearest + "?" : "")};
}

std::optional<rb::Error> needPositive(const std::string& key, double v) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return rb::Error{key, "must be > 0, not " + show(v)};
}
std::optional<rb::Error> needNonNegative(const std::string& key, double v) {
  if (std::isfinite(v) && v >= 0) return std::nullopt;
  return rb::Error{key, "must be ≥ 0, not " + show(v)};
}

std::optional<rb::Error> checkParaboloid(const ParaboloidSpec& p) {
  const std::string k = "body.paraboloid.";
  if (auto e = needPositive(k + "a", p.a)) return e;
  if (auto e = needPositive(k + "p", p.p)) return e;
  if (auto e = needPositive(k + "s", p.s)) return e;
  if (auto e = needFinite(k + "q", p.q)) return e;
  if (auto e = needFinite(k + "top", p.top)) return e;
  if (p.top <= -p.a) return rb::Error{k + "top", "must be above the apex at −a = " + show(-p.a)};
  // The bottom must be a bowl: its Hessian [p/a, q/a²; q/a², s/a] positive definite.
  if (p.p * p.s * p.a * p.a <= p.q * p.q)
    return rb::Error{k + "q", "too large: the bottom is not a bowl (need q² < p·s·a²)"};
  return std::nullopt;
}

// An inertia tensor a rigid body can have: finite, symmetric, positive definite, and each
// principal moment at most the sum of the other two.
std::optional<rb::Error> checkInertia(const Matrix3Spec& spec) {
  Eigen::Matrix3d I;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) I(i, j) = spec[i][j];
  if (!I.allFinite()) return rb::Error{"body.inertia", "must hold finite numbers"};
  if ((I - I.transpose()).norm() > 1e-12 * I.norm())
    return rb::Error{"body.inertia", "must be symmetric"};
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (m(0) <= 0) return rb::Error{"body.inertia", "must be positive definite"};
  if (m(2) > m(0) + m(1) * (1 + 1e-12))
    return rb::Error{"body.inertia",
                     "is impossible: a principal moment exceeds the sum of the "
                     "other two"};
  return std::nullopt;
}

std::optional<rb::Error> checkEllipsoid(const BodySpec& b) {
  for (double axis : b.ellipsoid.semi_axes)
    if (auto e = needPositive("body.ellipsoid.semi_axes", axis)) return e;
  for (double c : b.ellipsoid.center)
    if (auto e = needFinite("body.ellipsoid.center", c)) return e;
  // The centre of mass of a body within the ellipsoid lies within it: (c/a)² summed below 1.
  // One outside (a new user's center [0, 0, 0.5] on semi-axes 0.02 high) put the CM under the
  // floor, and the body "stood" upright with a negative energy and drew nothing.
  double reach = 0;
  for (int i = 0; i < 3; ++i)
    reach += std::pow(b.ellipsoid.center[i] / b.ellipsoid.semi_axes[i], 2);
  if (!(reach < 1))
    return rb::Error{"body.ellipsoid.center",
                     "puts the centre of mass outside the ellipsoid (the sum of (center / "
                     "semi_axes)² is " +
                         rb::show(reach) +
                         ", not below 1): it is the ellipsoid's centre seen from the centre of "
                         "mass, in file units, e.g. [0, 0, 0.01]"};
  if (auto e = needPositive("body.mass", b.mass)) return e;
  return checkInertia(b.inertia);
}

std::optional<rb::Error> checkBody(const BodySpec& b) {
  if (b.shape == "ellipsoid") return checkEllipsoid(b);
  if (b.shape == "mesh") {
    if (auto e = checkMeshBody(b)) return e;
    return b.inertia == Matrix3Spec{} ? std::nullopt : checkInertia(b.inertia);
  }
  if (b.shape != "paraboloid") {
    const std::vector<std::string_view> shapes = {"paraboloid", "ellipsoid", "mesh"};
    const std::optional<std::string> nearest = rb::nearestWord(b.shape, shapes);
    return rb::Error{"body.shape", "must be paraboloid, ellipsoid or mesh, not '" + b.shape + "'" +
                                       (nearest ? "; did you mean " + *nearest + "?" : "")};
  }
  if (auto e = checkParaboloid(b.paraboloid)) return e;
  if (b.dents) {
    if (auto e = needPositive("body.dents.scale", b.dents->scale)) return e;
    if (auto e = needFinite("body.dents.at", b.dents->at[0])) return e;
    if (auto e = needFinite("body.dents.at", b.dents->at[1])) return e;
    if (auto e = needFinite("body.dents.inset", b.dents->inset)) return e;
  }
  if (auto e = needPositive("body.grid.dx", b.grid.dx)) return e;
  if (auto e = needPositive("body.grid.dy", b.grid.dy)) return e;
  if (auto e = needPositive("body.grid.dz", b.grid.dz)) return e;
  if (!b.mass_properties.empty() && !rb::parseName<MassSource>(b.mass_properties))
    return wrongWord<MassSource>("body.mass_properties", b.mass_properties);
  if (auto e = needPositive("body.mass", b.mass)) return e;
  return std::nullopt;
}

std::optional<rb::Error> checkContact(const ContactSpec& c) {
  if (!rb::parseName<ContactModel>(c.model))
    return wrongWord<ContactModel>("contact.model", c.model);
  if (!heldOnFloor(*rb::parseName<ContactModel>(c.model)))  // the constraint needs no spring
    if (auto e = needPositive("contact.stiffness", c.stiffness)) return e;
  if (auto e = needNonNegative("contact.damping", c.damping)) return e;
  if (auto e = needNonNegative("contact.friction", c.friction)) return e;
  if (!rb::parseName<FrictionLaw>(c.friction_law))
    return wrongWord<FrictionLaw>("contact.friction_law", c.friction_law);
  if (auto e = needPositive("contact.slip_velocity", c.slip_velocity)) return e;
  if (auto e = needNonNegative("contact.air_drag", c.air_drag)) return e;
  return std::nullopt;
}

// Exactly one of dt and tolerance; the integrator fits the one given.
std::optional<rb::Error> checkSimulation(const SimulationSpec& sim) {
  const bool has_dt = !std::isnan(sim.dt), has_tolerance = !std::isnan(sim.tolerance);
  if (has_dt == has_tolerance)
    return rb::Error{"simulation.dt",
                     has_dt ? "and simulation.tolerance are both given; give exactly one: dt for "
                              "a fixed step, tolerance for adaptive steps"
                            : "or simulation.tolerance is required: dt for a fixed step (e.g. "
                              "dt: 1.0e-4), tolerance for adaptive steps (e.g. tolerance: 1.0e-8)"};
  if (has_dt) {
    if (auto e = needPositive("simulation.dt", sim.dt)) return e;
  } else {
    if (auto e = needPositive("simulation.tolerance", sim.tolerance)) return e;
    if (sim.tolerance < 1e-14 || sim.tolerance > 1e-1)
      return rb::Error{
          "simulation.tolerance",
          "must lie within 1e-14 … 0.1 (rounding and sense), not " + show(sim.tolerance)};
  }
  if (!sim.integrator.empty() && !rb::parseName<Integrator>(sim.integrator))
    return wrongWord<Integrator>("simulation.integrator", sim.integrator);
  const Integrator integrator = !sim.integrator.empty() ? *rb::parseName<Integrator>(sim.integrator)
                                : has_dt                ? Integrator::Symplectic
                                                        : Integrator::Dopri5;
  if (isAdaptive(integrator) && has_dt)
    return rb::Error{"simulation.integrator",
                     std::string(rb::nameOf(integrator)) +
                         " chooses its own steps: give simulation.tolerance (or " +
                         rb::argumentName("tolerance") + ") instead of dt"};
  if (!isAdaptive(integrator) && has_tolerance)
    return rb::Error{"simulation.integrator", std::string(rb::nameOf(integrator)) +
                                                  " takes a fixed step: give simulation.dt (or " +
                                                  rb::argumentName("dt") +
                                                  "), or use dopri5 with the tolerance"};
  if (auto e = needPositive("simulation.duration", sim.duration)) return e;
  if (has_dt && sim.duration / sim.dt > kMaxSteps)
    return rb::Error{"simulation.dt",
                     show(sim.dt) + " s over simulation.duration " + show(sim.duration) +
                         " s makes more than 1e11 steps: shorten the run or "
                         "lengthen the step",
                     std::nullopt,
                     {"simulation.duration"}};
  return std::nullopt;
}

bool given(const std::array<double, 3>& v) {
  return !std::isnan(v[0]) || !std::isnan(v[1]) || !std::isnan(v[2]);
}

// initial.spin is the shortcut for angular_velocity [0, 0, spin]: one or the other.
std::optional<rb::Error> checkInitialMotion(const InitialSpec& init) {
  const bool spin = !std::isnan(init.spin);
  if (spin)
    if (auto e = needFinite("initial.spin", init.spin)) return e;
  if (given(init.angular_velocity)) {
    if (spin)
      return rb::Error{"initial.spin",
                       "is given with initial.angular_velocity: give one of them (spin n is the "
                       "shortcut for angular_velocity: [0, 0, n])",
                       std::nullopt,
                       {"initial.angular_velocity"}};
    for (double w : init.angular_velocity)
      if (auto e = needFinite("initial.angular_velocity", w)) return e;
  }
  if (given(init.velocity))
    for (double v : init.velocity)
      if (auto e = needFinite("initial.velocity", v)) return e;
  return std::nullopt;
}

// The spec's initial state in the model's terms: SI units, radians, ω in body axes.
Initial initialOf(const SceneSpec& spec) {
  const InitialSpec& init = spec.initial;
  Initial out;
  out.spin = std::isnan(init.spin) ? 0.0 : init.spin;
  out.tilt_x = init.tilt[0] * M_PI / 180.0;
  out.tilt_y = init.tilt[1] * M_PI / 180.0;
  out.height = init.height * spec.units.length;
  if (given(init.angular_velocity)) {
    out.w_x = init.angular_velocity[0];
    out.w_y = init.angular_velocity[1];
    out.spin = init.angular_velocity[2];
  }
  if (given(init.velocity)) out.velocity = Eigen::Vector3d(init.velocity.data());
  return out;
}

std::optional<rb::Error> checkRest(const SceneSpec& spec) {
  if (auto e = needPositive("units.length", spec.units.length)) return e;
  if (auto e = needNonNegative("gravity", spec.gravity)) return e;
  if (auto e = checkInitialMotion(spec.initial)) return e;
  for (double tilt : spec.initial.tilt) {
    if (auto e = needFinite("initial.tilt", tilt)) return e;
    if (std::abs(tilt) > 180)
      return rb::Error{"initial.tilt", "must lie within ±180 degrees, not " + rb::show(tilt)};
  }
  if (auto e = needNonNegative("initial.height", spec.initial.height)) return e;
  const std::optional<ContactModel> model = rb::parseName<ContactModel>(spec.contact.model);
  if (spec.initial.height > 0 && model && heldOnFloor(*model))  // auto starts sliding
    return rb::Error{"initial.height",
                     "must be 0 with contact.model rolling (it keeps the body on the floor); "
                     "drop it with smooth or points"};
  if (auto e = checkSimulation(spec.simulation)) return e;
  return std::nullopt;
}

// A fixed step must resolve the body's own rocking where it rolls, as it must the floor's
// stiffness for the penalty models: at least kStepsPerRocking steps a period of its fastest
// mode, at rest or at the scene's spin (the linearised rolling model, docs/physics.md P8).
// (--dt 0.05 on a body rocking at 7 Hz, a third of a period a step, runs and reports
// no reversal, where at 1e-4 s it reverses at 1.584 s.)
constexpr double kStepsPerRocking = 8;

std::optional<rb::Error> checkRockingStep(const Model& model) {
  if (!contactTraits(model.contact.model).rolls || isAdaptive(model.integrator))
    return std::nullopt;
  double omega = 0;  // rad/s: the fastest rocking
  for (double spin : {0.0, model.initial.spin})
    for (const auto& lambda : linearise(model, spin).eigenvalues)
      omega = std::max(omega, std::abs(lambda.imag()));
  if (!(omega > 0)) return std::nullopt;
  const double largest = 2 * M_PI / omega / kStepsPerRocking;
  if (model.dt <= largest) return std::nullopt;
  std::ostringstream msg;
  msg << model.dt << " s is too large for the body's rocking: its fastest mode ("
      << omega / (2 * M_PI) << " Hz, a period of " << 2 * M_PI / omega << " s) needs at least "
      << kStepsPerRocking << " steps a period, so at most " << largest
      << " s (or give simulation.tolerance for adaptive steps)";
  return rb::Error{"simulation.dt", msg.str()};
}

// The integrator the scene names, or the default for what it gives: with a tolerance dopri5;
// with a step symplectic for the penalty models, rk4 where the body rolls (below).
Integrator integratorOf(const SimulationSpec& sim, ContactModel contact) {
  if (auto named = rb::parseName<Integrator>(sim.integrator)) return *named;
  if (!std::isnan(sim.tolerance)) return Integrator::Dopri5;
  return contactTraits(contact).rolls ? Integrator::Rk4 : Integrator::Symplectic;
}

// Surface points and contact points from the geometric frame to the CM's.
void placePoints(Body& body, const SurfacePoints& surface) {
  body.top.reserve(surface.top.size());
  body.bottom.reserve(surface.bottom.size());
  for (const Eigen::Vector3d& p_geom : surface.top) body.top.push_back(p_geom - body.com_geometric);
  for (const Eigen::Vector3d& p_geom : surface.bottom)
    body.bottom.push_back(p_geom - body.com_geometric);
}

// An ellipsoid with its given inertia. Geometric frame: the ellipsoid's centre at the origin,
// so the CM sits at −center. Its surface is sampled like the paraboloid's grid: columns at
// half-offset (x, y) spaced h = min(a, b)/8, the upper point of each red, the lower blue.
Body buildEllipsoid(const BodySpec& b, double unit) {
  Body body;
  const Eigen::Vector3d axes = Eigen::Vector3d(b.ellipsoid.semi_axes.data()) * unit;
  body.mass = b.mass;
  body.surface.kind = Surface::Kind::Ellipsoid;
  body.surface.ellipsoid = Ellipsoid{axes};
  body.com_geometric = -Eigen::Vector3d(b.ellipsoid.center.data()) * unit;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) body.inertia(i, j) = b.inertia[i][j];
  body.inertia_inv = body.inertia.inverse();
  MassProperties& m = body.mass_properties;
  m.mass = b.mass;
  m.com = body.com_geometric;
  m.inertia = body.inertia;
  principalAxes(m);

  const double h = std::min(axes.x(), axes.y()) / 8;
  body.grid = Grid{h, h, h};
  SurfacePoints surface;
  const int nx = static_cast<int>(std::floor(axes.x() / h + 0.5));
  const int ny = static_cast<int>(std::floor(axes.y() / h + 0.5));
  for (int j = -ny; j < ny; ++j) {
    for (int i = -nx; i < nx; ++i) {
      const double x = (i + 0.5) * h, y = (j + 0.5) * h;
      const double inside = 1 - x * x / (axes.x() * axes.x()) - y * y / (axes.y() * axes.y());
      if (inside < 0) continue;
      const double z = axes.z() * std::sqrt(inside);
      surface.top.emplace_back(x, y, z);
      surface.bottom.emplace_back(x, y, -z);
    }
  }
  placePoints(body, surface);
  return body;
}

// Mass properties from the shape or the grid; surface points moved to the CM, in SI units.
rb::Result<Body> buildBody(const BodySpec& b, double unit, MassSource source, bool contact_points) {
  if (b.shape == "ellipsoid") return buildEllipsoid(b, unit);
  if (b.shape == "mesh") return buildMeshBody(b, unit);
  const ParaboloidSpec& p = b.paraboloid;
  const Paraboloid shape(p.a * unit, p.p, p.q * unit, p.s, p.top * unit);
  const Grid grid{b.grid.dx * unit, b.grid.dy * unit, b.grid.dz * unit};
  const double estimate = static_cast<double>(estimateGridPoints(shape, grid));
  if (estimate > kMaxGridPoints)
    return rb::Error{"body.grid",
                     (estimate >= 9e18 ? std::string("makes more than 9e18 points")
                                       : "makes about " + show(estimate) + " points") +
                         "; at most " + show(kMaxGridPoints) +
                         " are allowed (the spacings are in units.length: a typo such as 1e-9?)"};
  std::optional<Dents> dents;
  if (b.dents)
    dents =
        Dents{b.dents->scale, b.dents->at[0] * unit, b.dents->at[1] * unit, b.dents->inset * unit};
  // Dents that leave a sliver (a scale typed 100 for 0.45): the body is found without them
  // (a finer grid, which a message could ask for, would not help).
  if (dents && !gridHasTwoLevels(shape, dents, grid) && gridHasTwoLevels(shape, std::nullopt, grid))
    return rb::Error{"body.dents.scale",
                     "cuts the body away: with the dents the grid finds fewer than two levels of "
                     "points, without them the body is there; a smaller scale (the default "
                     "body's is 0.45), or dents placed further out"};
  if (!gridHasTwoLevels(shape, dents, grid)) {
    // Its sizes, so that a body given in metres in a file of centimetres (0.01 for 1) shows as
    // the body it is, not as a grid to make finer.
    const double height = (shape.top - shape.lowestPoint(Eigen::Vector3d(0, 0, -1)).z()) / unit;
    return rb::Error{"body.grid",
                     "is too coarse: the body has fewer than two levels of points (it "
                     "is " +
                         show(height) + " high against dz " + show(b.grid.dz) +
                         ", both in units.length, " + show(unit) +
                         " m: a finer grid, or the body's sizes in those units?)"};
  }

  Body body;
  body.mass = b.mass;
  body.mass_source = source;
  if (source == MassSource::Continuum) {
    const Continuum continuum = continuumMassProperties(shape, dents, b.mass);
    body.mass_properties = continuum.mass;
    body.mass_by_cubature = continuum.method == ContinuumMethod::Cubature;
  } else {
    body.mass_properties = gridMassProperties(shape, dents, grid, b.mass);
  }
  // Measured from the bottom's long curvature axis, which q turns from y: a skewed body without
  // dents is a symmetric one turned, its inertia axes on its curvature axes (measured from y,
  // q 0.05 would read +6.0°, where growth rates and runs show no misalignment).
  body.mass_properties.misalignment_deg =
      misalignmentDeg(body.mass_properties, shape.longAxisAngle());
  body.surface.kind = Surface::Kind::Paraboloid;
  body.surface.paraboloid = shape;
  body.grid = grid;
  body.com_geometric = body.mass_properties.com;
  body.inertia = body.mass_properties.inertia;
  if (body.mass_properties.principal.minCoeff() <= 0)
    return rb::Error{"body.grid", "is too coarse: the inertia tensor is singular"};
  body.inertia_inv = body.inertia.inverse();
  body.dents = dents;
  if (contact_points) placePoints(body, gridSurface(shape, dents, grid));
  return body;
}

}  // namespace

MassSource massSourceOf(const SceneSpec& spec) {
  if (auto named = rb::parseName<MassSource>(spec.body.mass_properties)) return *named;
  return spec.contact.model == "points" ? MassSource::Grid : MassSource::Continuum;
}

rb::Result<std::shared_ptr<const Body>> compileBody(const SceneSpec& scene, BodyPoints points) {
  const BodySpec& spec = scene.body;
  const double length_unit = scene.units.length;
  if (auto e = checkBody(spec)) return *e;
  if (auto e = needPositive("units.length", length_unit)) return *e;
  auto body = buildBody(spec, length_unit, massSourceOf(scene),
                        points == BodyPoints::Always || scene.contact.model == "points");
  if (!body) return body.error();
  const Eigen::Vector3d com = body->com_geometric;
  body->extent = (body->surface.boxHigh() - com)
                     .cwiseAbs()
                     .cwiseMax((body->surface.boxLow() - com).cwiseAbs());
  return std::shared_ptr<const Body>(std::make_shared<Body>(std::move(body).value()));
}

GridCensus censusOf(const Body& body) {
  if (body.surface.kind == Surface::Kind::Paraboloid)
    return gridCensus(body.surface.paraboloid, body.dents, body.grid);
  GridCensus census;  // the ellipsoid's points, always built (a few hundred)
  census.top = static_cast<std::int64_t>(body.top.size());
  census.bottom = static_cast<std::int64_t>(body.bottom.size());
  census.points = census.top + census.bottom;
  census.lo = body.top.lo.cwiseMin(body.bottom.lo) + body.com_geometric;
  census.hi = body.top.hi.cwiseMax(body.bottom.hi) + body.com_geometric;
  return census;
}

rb::Result<Model> compileRun(const SceneSpec& spec, std::shared_ptr<const Body> body) {
  if (auto e = checkContact(spec.contact)) return *e;
  if (auto e = checkRest(spec)) return *e;

  // A mesh body's smooth models touch the bottom fitted to it, which must be a smooth bowl
  // (docs/physics.md §P11.4).
  if (body->surface.kind == Surface::Kind::Mesh && spec.contact.model != "points" &&
      !body->surface.mesh.fit.usable())
    return rb::Error{"contact.model",
                     spec.contact.model + " touches the smooth bottom fitted to the mesh, and " +
                         spec.body.mesh.file +
                         "'s does not fit: " + body->surface.mesh.fit.problem +
                         " (z is up: is its bottom the mesh's lowest side?); or touch the mesh's "
                         "own surface points: contact: {model: points, stiffness: 20, damping: "
                         "0.05}"};
  Model model;
  model.body = std::move(body);
  model.length_unit = spec.units.length;
  const ContactSpec& c = spec.contact;
  model.contact =
      Contact{*rb::parseName<ContactModel>(c.model),       c.stiffness,     c.damping, c.friction,
              *rb::parseName<FrictionLaw>(c.friction_law), c.slip_velocity, c.air_drag};
  model.gravity = spec.gravity;
  model.integrator = integratorOf(spec.simulation, model.contact.model);
  // Semi-implicit Euler keeps a penalty floor's energy, not the rolling model's: rolling
  // without slipping is non-holonomic, and the method is not symplectic for it (Kane &
  // Levinson without dissipation lose 17.9 % of their energy in 60 s at 0.1 ms and reverse at
  // the wrong times).
  if (integratorTraits(model.integrator).refused_when_rolling &&
      contactTraits(model.contact.model).rolls)
    return rb::Error{"simulation.integrator",
                     std::string(rb::nameOf(model.integrator)) +
                         " does not keep the energy of contact.model " +
                         std::string(rb::nameOf(model.contact.model)) +
                         " (rolling without slipping is non-holonomic: semi-implicit Euler loses "
                         "energy and moves the reversals); use rk4 with a step or dopri5 with a "
                         "tolerance"};
  if (isAdaptive(model.integrator))
    model.tolerance = spec.simulation.tolerance;
  else
    model.dt = spec.simulation.dt;
  model.duration = spec.simulation.duration;
  model.initial = initialOf(spec);
  if (auto e = checkInitialVelocity(model)) return *e;

  if (auto e = checkRockingStep(model)) return *e;
  // Auto runs its smooth phases in steps of their own (sim/switching.hpp: smoothStep).
  const ContactStability stability = contactStability(model);
  // Refused above the step a run completes at (kRunMargin of the linear limit at rest), which
  // the message names: between the two, rk4 ran on with exit 0 and symplectic gained 11 % of
  // its energy by 0.25 s (the margin is measured in sim/stability.hpp).
  if (contactTraits(model.contact.model).penalty_at_run_step && model.dt > stability.run_step) {
    std::ostringstream msg;
    msg << model.dt << " s is too large for contact.stiffness " << c.stiffness << " N/m with "
        << rb::nameOf(model.integrator) << ": the stiffest contact mode (" << stability.omega
        << " rad/s) grows above " << stability.largest_step
        << " s at rest, and a run that rocks or lands needs half that: the largest stable step "
           "for a run is "
        << stability.run_step << " s (or give simulation.tolerance for adaptive steps)";
    return rb::Error{"simulation.dt", msg.str()};
  }
  return model;
}

rb::Result<Model> compile(const SceneSpec& spec) {
  // The run's keys first: they are cheap to check, and the body may take a while to build.
  if (auto e = checkContact(spec.contact)) return *e;
  if (auto e = checkRest(spec)) return *e;
  auto body = compileBody(spec);
  if (!body) return body.error();
  return compileRun(spec, std::move(body).value());
}

}  // namespace sim

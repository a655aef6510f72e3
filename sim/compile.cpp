#include "sim/compile.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <sstream>

#include "sim/initial.hpp"
#include "sim/stability.hpp"

namespace sim {
namespace {

std::string show(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Range checks, each returning the error for `key` or nothing.
std::optional<SpecError> needFinite(const std::string& key, double v) {
  if (std::isfinite(v)) return std::nullopt;
  return SpecError{key, "must be a finite number, not " + show(v)};
}
std::optional<SpecError> needPositive(const std::string& key, double v) {
  if (std::isfinite(v) && v > 0) return std::nullopt;
  return SpecError{key, "must be > 0, not " + show(v)};
}
std::optional<SpecError> needNonNegative(const std::string& key, double v) {
  if (std::isfinite(v) && v >= 0) return std::nullopt;
  return SpecError{key, "must be ≥ 0, not " + show(v)};
}

std::optional<SpecError> checkParaboloid(const ParaboloidSpec& p) {
  const std::string k = "body.paraboloid.";
  if (auto e = needPositive(k + "a", p.a)) return e;
  if (auto e = needPositive(k + "p", p.p)) return e;
  if (auto e = needPositive(k + "s", p.s)) return e;
  if (auto e = needFinite(k + "q", p.q)) return e;
  if (auto e = needFinite(k + "top", p.top)) return e;
  if (p.top <= -p.a) return SpecError{k + "top", "must be above the apex at −a = " + show(-p.a)};
  // The bottom must be a bowl: its Hessian [p/a, q/a²; q/a², s/a] positive definite.
  if (p.p * p.s * p.a * p.a <= p.q * p.q)
    return SpecError{k + "q", "too large: the bottom is not a bowl (need q² < p·s·a²)"};
  return std::nullopt;
}

// An inertia tensor a rigid body can have: finite, symmetric, positive definite, and each
// principal moment at most the sum of the other two.
std::optional<SpecError> checkInertia(const Matrix3Spec& spec) {
  Eigen::Matrix3d I;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) I(i, j) = spec[i][j];
  if (!I.allFinite()) return SpecError{"body.inertia", "must hold finite numbers"};
  if ((I - I.transpose()).norm() > 1e-12 * I.norm())
    return SpecError{"body.inertia", "must be symmetric"};
  const Eigen::Vector3d m = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (m(0) <= 0) return SpecError{"body.inertia", "must be positive definite"};
  if (m(2) > m(0) + m(1) * (1 + 1e-12))
    return SpecError{"body.inertia", "is impossible: a principal moment exceeds the sum of the "
                                     "other two"};
  return std::nullopt;
}

std::optional<SpecError> checkEllipsoid(const BodySpec& b) {
  for (double axis : b.ellipsoid.semi_axes)
    if (auto e = needPositive("body.ellipsoid.semi_axes", axis)) return e;
  for (double c : b.ellipsoid.center)
    if (auto e = needFinite("body.ellipsoid.center", c)) return e;
  if (auto e = needPositive("body.mass", b.mass)) return e;
  return checkInertia(b.inertia);
}

std::optional<SpecError> checkBody(const BodySpec& b) {
  if (b.shape == "ellipsoid") return checkEllipsoid(b);
  if (b.shape != "paraboloid")
    return SpecError{"body.shape", "must be paraboloid or ellipsoid, not '" + b.shape + "'"};
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
  if (auto e = needPositive("body.mass", b.mass)) return e;
  return std::nullopt;
}

std::optional<SpecError> checkContact(const ContactSpec& c) {
  if (c.model != "points" && c.model != "smooth" && c.model != "rolling")
    return SpecError{"contact.model", "must be points, smooth or rolling, not '" + c.model + "'"};
  if (c.model != "rolling")
    if (auto e = needPositive("contact.stiffness", c.stiffness)) return e;
  if (auto e = needNonNegative("contact.damping", c.damping)) return e;
  if (auto e = needNonNegative("contact.friction", c.friction)) return e;
  if (c.friction_law != "coulomb" && c.friction_law != "regularized")
    return SpecError{"contact.friction_law",
                     "must be coulomb or regularized, not '" + c.friction_law + "'"};
  if (auto e = needPositive("contact.slip_velocity", c.slip_velocity)) return e;
  if (auto e = needNonNegative("contact.air_drag", c.air_drag)) return e;
  return std::nullopt;
}

std::optional<SpecError> checkRest(const SceneSpec& spec) {
  if (auto e = needPositive("units.length", spec.units.length)) return e;
  if (auto e = needNonNegative("gravity", spec.gravity)) return e;
  if (auto e = needFinite("initial.spin", spec.initial.spin)) return e;
  for (double tilt : spec.initial.tilt) {
    if (auto e = needFinite("initial.tilt", tilt)) return e;
    if (std::abs(tilt) > 180) return SpecError{"initial.tilt", "must lie within ±180 degrees"};
  }
  if (auto e = needNonNegative("initial.height", spec.initial.height)) return e;
  if (spec.initial.height > 0 && spec.contact.model == "rolling")
    return SpecError{"initial.height",
                     "must be 0 with contact.model rolling (it keeps the body on the floor); "
                     "drop it with smooth or points"};
  const SimulationSpec& sim = spec.simulation;
  if (sim.integrator != "euler" && sim.integrator != "symplectic" && sim.integrator != "rk4")
    return SpecError{"simulation.integrator",
                     "must be euler, symplectic or rk4, not '" + sim.integrator + "'"};
  if (auto e = needPositive("simulation.dt", sim.dt)) return e;
  if (auto e = needPositive("simulation.duration", sim.duration)) return e;
  if (sim.duration / sim.dt > 1e11)
    return SpecError{"simulation.dt", "makes more than 1e11 steps for the duration"};
  if (sim.duration / sim.dt < 0.5)
    return SpecError{"simulation.duration", "is shorter than one step"};
  const VideoSpec& v = spec.video;
  if (v.fps <= 0 || v.fps > 1000) return SpecError{"video.fps", "must be within 1 … 1000"};
  for (int side : v.size)
    if (side < 16 || side > 8192) return SpecError{"video.size", "sides must be within 16 … 8192"};
  if (auto e = needPositive("video.playback", v.playback)) return e;
  if (v.view != "oblique" && v.view != "above" && v.view != "front" && v.view != "side" &&
      v.view != "follow")
    return SpecError{"video.view",
                     "must be oblique, above, front, side or follow, not '" + v.view + "'"};
  return std::nullopt;
}

Integrator integratorOf(const std::string& name) {
  if (name == "euler") return Integrator::Euler;
  if (name == "rk4") return Integrator::Rk4;
  return Integrator::Symplectic;
}

// Surface points and contact points from the geometric frame to the CM's.
void placePoints(Body& body, const SurfacePoints& surface) {
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

// Mass properties from the grid; surface points moved to the CM, in SI units.
std::variant<Body, SpecError> buildBody(const BodySpec& b, double unit) {
  if (b.shape == "ellipsoid") return buildEllipsoid(b, unit);
  const ParaboloidSpec& p = b.paraboloid;
  const Paraboloid shape{p.a * unit, p.p, p.q * unit, p.s, p.top * unit};
  const Grid grid{b.grid.dx * unit, b.grid.dy * unit, b.grid.dz * unit};
  const double estimate = static_cast<double>(estimateGridPoints(shape, grid));
  if (estimate > kMaxGridPoints)
    return SpecError{"body.grid", "makes about " + show(estimate) + " points; at most " +
                                      show(kMaxGridPoints) + " are allowed"};
  std::optional<Dents> dents;
  if (b.dents)
    dents = Dents{b.dents->scale, b.dents->at[0] * unit, b.dents->at[1] * unit,
                  b.dents->inset * unit};
  const BodyGrid built = buildBodyGrid(shape, dents, grid, b.mass);
  if (built.mass.points < 2 || built.surface.bottom.empty())
    return SpecError{"body.grid", "is too coarse: the body has fewer than two levels of points"};

  Body body;
  body.mass = b.mass;
  body.mass_properties = built.mass;
  body.surface.kind = Surface::Kind::Paraboloid;
  body.surface.paraboloid = shape;
  body.grid = grid;
  body.com_geometric = built.mass.com;
  body.inertia = built.mass.inertia;
  if (built.mass.principal.minCoeff() <= 0)
    return SpecError{"body.grid", "is too coarse: the inertia tensor is singular"};
  body.inertia_inv = body.inertia.inverse();
  placePoints(body, built.surface);
  return body;
}

// Frames are scheduled by whole steps: steps_per_frame = 1 / (fps · playback · dt) must be
// a whole number (to 1e-6), and the video has round(duration · playback · fps) frames.
std::optional<SpecError> compileVideo(const SceneSpec& spec, Model& model) {
  const VideoSpec& v = spec.video;
  const double steps = 1.0 / (v.fps * v.playback * spec.simulation.dt);
  const double whole = std::round(steps);
  if (whole < 1 || std::abs(steps - whole) > 1e-6 * steps) {
    std::ostringstream msg;
    msg << v.fps << " with playback " << v.playback << " needs " << steps
        << " steps of simulation.dt " << spec.simulation.dt
        << " s per frame; it must be a whole number: choose dt = "
        << 1.0 / (v.fps * v.playback * std::max(1.0, std::round(steps))) << " s or another fps";
    return SpecError{"video.fps", msg.str()};
  }
  model.video = Video{v.fps,   v.size[0],    v.size[1],
                      v.view,  v.playback,   static_cast<std::int64_t>(whole),
                      std::llround(spec.simulation.duration * v.playback * v.fps)};
  return std::nullopt;
}

}  // namespace

std::variant<Model, SpecError> compile(const SceneSpec& spec) {
  if (auto e = checkBody(spec.body)) return *e;
  if (auto e = checkContact(spec.contact)) return *e;
  if (auto e = checkRest(spec)) return *e;

  Model model;
  model.length_unit = spec.units.length;
  auto body = buildBody(spec.body, spec.units.length);
  if (auto* e = std::get_if<SpecError>(&body)) return *e;
  model.body = std::move(std::get<Body>(body));

  const ContactSpec& c = spec.contact;
  model.contact = Contact{c.model == "smooth"    ? ContactModel::Smooth
                          : c.model == "rolling" ? ContactModel::Rolling
                                                 : ContactModel::Points,
                          c.stiffness,
                          c.damping,
                          c.friction,
                          c.friction_law == "coulomb" ? FrictionLaw::Coulomb
                                                      : FrictionLaw::Regularized,
                          c.slip_velocity,
                          c.air_drag};
  model.gravity = spec.gravity;
  model.integrator = integratorOf(spec.simulation.integrator);
  model.dt = spec.simulation.dt;
  model.steps = std::llround(spec.simulation.duration / spec.simulation.dt);
  model.initial = Initial{spec.initial.spin, spec.initial.tilt[0] * M_PI / 180.0,
                          spec.initial.tilt[1] * M_PI / 180.0,
                          spec.initial.height * spec.units.length};

  // The step's stability first: it is the error that matters more than frame timing.
  const ContactStability stability = contactStability(model);
  if (model.dt > stability.largest_step) {
    std::ostringstream msg;
    msg << "= " << model.dt << " s is too large for contact.stiffness " << c.stiffness
        << " N/m with " << spec.simulation.integrator << ": the stiffest contact mode ("
        << stability.omega << " rad/s) grows; the largest stable step is "
        << stability.largest_step << " s";
    return SpecError{"simulation.dt", msg.str()};
  }
  if (auto e = compileVideo(spec, model)) return *e;
  return model;
}

}  // namespace sim

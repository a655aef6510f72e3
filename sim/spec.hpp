// Plain description of a scene, mirroring the scene file key for key.
// Lengths are in the file's length unit (units.length metres each); everything
// else is SI. The loader fills it; compile() checks it and builds a Model.
#pragma once

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace sim {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

/// units: metres per length unit of the file (0.01 = centimetres).
struct UnitsSpec {
  double length = 1.0;  ///< m per file length unit, > 0
};

/// body.paraboloid: bottom z = p/(2a) x² + q/a² xy + s/(2a) y² − a, flat top at z = top
/// (docs/physics.md P1; seed eq. 24). Lengths in file units; p, q, s dimensionless.
struct ParaboloidSpec {
  double a = kUnset;    ///< depth of the apex below the origin, > 0
  double p = kUnset;    ///< curvature across the short axis (x), > 0
  double q = 0.0;       ///< skew term, makes the bottom's axes turn
  double s = kUnset;    ///< curvature along the long axis (y), > 0
  double top = kUnset;  ///< height of the flat top, > −a
};

/// body.dents: two paraboloid dents cut from the top (seed §3.2 and appendix),
/// at (+x, +y) and (−x, −y).
struct DentsSpec {
  double scale = kUnset;  ///< k: dent curvature p/(2a k²), depth (a − inset) k
  std::array<double, 2> at{kUnset, kUnset};  ///< (m_x, m_y), file units
  double inset = 0.1;                        ///< the seed's constant, file units
};

/// body.grid: uniform point grid (seed §3.1), file units.
struct GridSpec {
  double dx = kUnset, dy = kUnset, dz = kUnset;
};

/// body.ellipsoid: a smooth ellipsoid (Kane & Levinson 1982), file units.
struct EllipsoidSpec {
  std::array<double, 3> semi_axes{kUnset, kUnset, kUnset};  ///< along x, y, z
  std::array<double, 3> center{0.0, 0.0, 0.0};  ///< the ellipsoid's centre relative to the CM
};

using Matrix3Spec = std::array<std::array<double, 3>, 3>;

struct TriangleMesh;

/// body.mesh: a closed triangle mesh from a file (docs/physics.md §P11).
struct MeshSpec {
  std::string file;  ///< STL or OBJ, relative to the scene file; its numbers in file units
  /// The file's mesh as the scene loader read it (scene/mesh_file.hpp), file units; null until
  /// read.
  std::shared_ptr<const TriangleMesh> data;
};

struct BodySpec {
  std::string shape = "paraboloid";  ///< paraboloid | ellipsoid | mesh
  ParaboloidSpec paraboloid;
  EllipsoidSpec ellipsoid;
  MeshSpec mesh;
  /// mesh: the CM of a weighted toy, file units in the mesh's frame; unset: the uniform solid's.
  std::array<double, 3> center_of_mass{kUnset, kUnset, kUnset};
  /// ellipsoid, and optionally mesh (all zeros: the uniform solid's): kg m², about the CM, body
  /// axes.
  Matrix3Spec inertia{};
  std::optional<DentsSpec> dents;  ///< absent: no dents
  GridSpec grid;
  /// paraboloid: where the mass properties come from: "continuum" (the shape's volume, exact)
  /// or "grid" (the point grid's sums, the seed's first-order rule); "" leaves it to the
  /// contact model: grid for points (the seed's scenes reproduce its report), else continuum.
  std::string mass_properties;
  double mass = kUnset;  ///< kg, > 0
};

struct ContactSpec {
  std::string model = "points";              ///< points | smooth | rolling
  double stiffness = kUnset;                 ///< N/m (points: per point)
  double damping = 0.0;                      ///< N s/m (points: per point)
  double friction = 0.5;                     ///< Coulomb coefficient μ
  std::string friction_law = "regularized";  ///< coulomb | regularized
  double slip_velocity = 1.0e-3;             ///< m/s, ε of the regularised law
  double air_drag = 0.0;                     ///< σ, N m s: torque −σω
};

/// initial: the state at release (docs/physics.md P5). Unset members (NaN) were not given.
struct InitialSpec {
  /// rad/s about the body's z axis, + = counter-clockwise from above; unset: 0, or the z of
  /// angular_velocity (giving both is refused).
  double spin = kUnset;
  std::array<double, 2> tilt{0.0, 0.0};  ///< degrees, about body x then the new body y
  double height = 0.0;  ///< lowest point above the floor at release, length units; 0: resting
  /// ω at release, rad/s, body axes; unset: [0, 0, spin].
  std::array<double, 3> angular_velocity{kUnset, kUnset, kUnset};
  /// The CM's velocity at release, m/s, world axes; unset: the lowest point does not slide
  /// (resting), or the CM at rest (released above the floor).
  std::array<double, 3> velocity{kUnset, kUnset, kUnset};
};

/// simulation: exactly one of dt (a fixed step) and tolerance (adaptive steps).
struct SimulationSpec {
  /// euler | symplectic | rk4 (with dt) | dopri5, dop853 (with tolerance); empty: symplectic with
  /// dt, dopri5 with tolerance.
  std::string integrator;
  double dt = kUnset;         ///< s, > 0
  double tolerance = kUnset;  ///< error per step, relative to the body's own scales, > 0
  double duration = kUnset;   ///< s, > 0
};

struct SceneSpec {
  UnitsSpec units;
  BodySpec body;
  ContactSpec contact;
  double gravity = 9.81;  ///< m/s²
  InitialSpec initial;
  SimulationSpec simulation;
  // The scene file's `video` section is not the simulation's: scene::VideoSpec holds it.
};

}  // namespace sim

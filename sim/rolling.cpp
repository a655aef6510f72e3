#include "sim/rolling.hpp"

#include <cmath>

namespace sim {
namespace {

// A x = b for the symmetric positive definite 3×3 A (the inertia about the contact point) by
// its cofactors: x = adj(A) b / det A. A's condition is that of the body's inertia (≤ 10⁴ for
// any body a scene can give), so the cofactors lose at most 4 of 16 digits, as LDLT's pivots
// would; it takes a sixth of LDLT's time, which was an eighth of a rolling run's.
Eigen::Vector3d solveSymmetric(const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  const double c00 = A(1, 1) * A(2, 2) - A(1, 2) * A(1, 2);
  const double c01 = A(0, 2) * A(1, 2) - A(0, 1) * A(2, 2);
  const double c02 = A(0, 1) * A(1, 2) - A(0, 2) * A(1, 1);
  const double c11 = A(0, 0) * A(2, 2) - A(0, 2) * A(0, 2);
  const double c12 = A(0, 1) * A(0, 2) - A(0, 0) * A(1, 2);
  const double c22 = A(0, 0) * A(1, 1) - A(0, 1) * A(0, 1);
  // One division, then products: three divisions by det had stalled the evaluation (a tenth of
  // its time on them); the result differs by at most an ulp a component.
  const double inverse_det = 1 / (A(0, 0) * c00 + A(0, 1) * c01 + A(0, 2) * c02);
  return Eigen::Vector3d(c00 * b(0) + c01 * b(1) + c02 * b(2), c01 * b(0) + c11 * b(1) + c12 * b(2),
                         c02 * b(0) + c12 * b(1) + c22 * b(2)) *
         inverse_det;
}

// ω̇ in body axes, where the inertia is constant: the equations are between vectors, so they
// hold in any axes, and only the contact point and the force are turned into the world's.
struct Core {
  Eigen::Vector3d up, r, r_rate, w_dot;  // body axes
};

// `along` is Rᵀ ẑ times any positive factor, and `unit` the factor's inverse. The lowest point
// and its rate depend only on the direction of down, and its rate scales with it (paraboloid
// and ellipsoid: sim/surface.hpp), so they are found from `along` itself: the division that
// makes it a unit vector (a square root and a division for the integrated quaternion) is then
// off the evaluation's chain of dependent operations, which sets its time.
Core rollingCore(const Model& model, const Eigen::Vector3d& along, double unit,
                 const Eigen::Vector3d& w) {
  const Body& body = *model.body;
  const double M = body.mass;
  Core c;
  c.up = along * unit;
  // The down direction turns in body axes as ḋ = −ω × d; the contact point follows. A mesh's
  // fitted bottom wants a unit direction.
  const Eigen::Vector3d up = body.surface.kind == Surface::Kind::Mesh ? c.up : along;
  const PointAndRate contact = lowestSurfacePointMoving(body, -up, w.cross(up));
  c.r = contact.point;
  c.r_rate = w.cross(c.r) + contact.rate;
  const Eigen::Matrix3d& I = body.inertia;
  const Eigen::Matrix3d A =
      I + M * (c.r.squaredNorm() * Eigen::Matrix3d::Identity() - c.r * c.r.transpose());
  const Eigen::Vector3d rhs = -w.cross(I * w) - M * c.r.cross(w.cross(c.r_rate)) +
                              M * model.gravity * c.r.cross(c.up) - model.contact.air_drag * w;
  c.w_dot = solveSymmetric(A, rhs);
  return c;
}

}  // namespace

RollingMotion rollingMotion(const Model& model, const Kinematics& k) {
  const Core c = rollingCore(model, k.R.row(2).transpose(), 1.0, k.w_body);
  RollingMotion out;
  out.w_dot_body = c.w_dot;
  const Eigen::Vector3d v_dot = -c.w_dot.cross(c.r) - k.w_body.cross(c.r_rate);
  out.r_world = k.R * c.r;
  out.force_world = k.R * (model.body->mass * (v_dot + model.gravity * c.up));
  return out;
}

RollingRates rollingRates(const Model& model, const Eigen::Quaterniond& q,
                          const Eigen::Vector3d& w_body) {
  // |q|² R from q's coefficients by products alone; 1/|q|² and 1/|q| are then needed only
  // where the contact point's chain does not wait on them.
  const double x = q.x(), y = q.y(), z = q.z(), w = q.w();
  const double xx = x * x, yy = y * y, zz = z * z, ww = w * w;
  const double norm2 = xx + yy + zz + ww;
  const double inverse_norm2 = 1 / norm2;
  const Eigen::Vector3d along(2 * (x * z - w * y), 2 * (y * z + w * x), ww + zz - xx - yy);
  const Core c = rollingCore(model, along, inverse_norm2, w_body);
  RollingRates out;
  // ẋ = −ω × r, turned into world axes; only its floor components are integrated.
  Eigen::Matrix<double, 2, 3> top_rows;
  top_rows << ww + xx - yy - zz, 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), ww - xx + yy - zz, 2 * (y * z - w * x);
  out.dxy = -(top_rows * w_body.cross(c.r)) * inverse_norm2;
  // q̇ = ½ q̂ ⊗ (0, ω_body), the same as ½ (0, ω_world) ⊗ q̂.
  out.dq = (0.5 / std::sqrt(norm2)) *
           (q * Eigen::Quaterniond(0, w_body.x(), w_body.y(), w_body.z())).coeffs();
  out.w_dot_body = c.w_dot;
  return out;
}

ContactLoad rollingContact(const Model& model, const Kinematics& k,
                           Eigen::Vector3d& r_contact_world) {
  // The floor pushes with whatever force keeps the contact point still.
  const RollingMotion motion = rollingMotion(model, k);
  r_contact_world = motion.r_world;
  ContactLoad load;
  load.force_world = motion.force_world;
  load.torque_world = motion.r_world.cross(motion.force_world);
  load.normal_force = motion.force_world.z();
  load.contacts = 1;
  if (model.rolling_depth > 0)  // auto: the spring's compression rolling holds (no k otherwise)
    load.elastic_energy = 0.5 * model.contact.stiffness * model.rolling_depth * model.rolling_depth;
  return load;
}

double rollingEnergy(const Model& model, const State& s, const Eigen::Vector3d& w_world) {
  const double M = model.body->mass, depth = model.rolling_depth;
  return 0.5 * M * s.v_world.squaredNorm() + 0.5 * w_world.dot(s.L_world) +
         M * model.gravity * s.x_world.z() +
         (depth > 0 ? 0.5 * model.contact.stiffness * depth * depth : 0.0);
}

void enforceRolling(const Model& model, State& s) {
  const Eigen::Matrix3d R = s.q.toRotationMatrix();
  enforceRolling(model, s, R, angularVelocity(*model.body, R, s.L_world));
}

void enforceRolling(const Model& model, State& s, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& w_world) {
  const Eigen::Vector3d r = R * lowestSurfacePoint(*model.body, -R.row(2).transpose());
  s.x_world.z() = -r.z() - model.rolling_depth;
  s.v_world = -w_world.cross(r);
}

}  // namespace sim

// Mass properties of the paraboloid body from its shape (docs/physics.md P1): the solid between the
// bottom paraboloid and the flat top, less the two dents, of uniform density. Two ways, which
// the tests hold against each other:
//  - closed form: the cap's exact moments minus each dent's exact moments, when each dent's
//    cut lies wholly inside the body and the two cuts do not meet (the default body, and every
//    body the seed's construction makes with its own numbers);
//  - cubature otherwise: each column's z-moments exactly, then y exactly (Gauss–Legendre on the
//    pieces where the column's ends are one polynomial each), then x by adaptive Gauss–Kronrod
//    (Boost.Math's nodes) to a relative 1e-13 of each moment's scale.
// Geometric frame and metres throughout (sim/body.hpp).
#pragma once

#include <Eigen/Dense>
#include <optional>

#include "sim/body.hpp"

namespace sim {

/// The volume integrals of a solid: ∫ dV, ∫ r dV and ∫ r rᵀ dV (geometric frame; m³, m⁴, m⁵).
/// Moments of disjoint pieces add, so a body with a part cut away is the whole minus the part.
struct VolumeMoments {
  double volume = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();

  VolumeMoments& operator-=(const VolumeMoments& o);
  /// `mass` kg spread evenly over the volume: com = ∫r/V, C = ∫rrᵀ/V − com comᵀ,
  /// I = M (tr C · 1 − C) about the CM; principal axes as principalAxes. `points` is 0.
  MassProperties properties(double mass) const;
};

/// The cap of an elliptic paraboloid, z from its apex `apex_z` up to `apex_z + height`, with
/// horizontal Hessian `hessian` (z = apex_z + ½ uᵀ H u, u = (x, y) − center). The slice at
/// w = z − apex_z is the ellipse ½uᵀHu ≤ w: area 2πw/√det H, second moment (w/2) H⁻¹ per unit
/// area; over w ∈ [0, h]: V = π h²/√det H, centroid at w = 2h/3, horizontal covariance
/// (h/3) H⁻¹, vertical variance h²/18, no cross terms. Zero for height ≤ 0.
VolumeMoments paraboloidCapMoments(const Eigen::Matrix2d& hessian, const Eigen::Vector2d& center,
                                   double apex_z, double height);

/// How continuumMassProperties obtained its numbers.
enum class ContinuumMethod { ClosedForm, Cubature };

/// The body's exact moments when they have a closed form: the cap minus the two dents, each
/// dent's cut (its paraboloid below the top) wholly inside the body and the two apart.
/// Otherwise nothing.
std::optional<VolumeMoments> closedFormMoments(const Paraboloid& shape,
                                               const std::optional<Dents>& dents);

/// The body's moments by cubature, for any dents (cuts through the bottom or the rim, cuts that
/// meet): `tolerance` relative to each moment's own scale (∫|integrand|).
VolumeMoments cubatureMoments(const Paraboloid& shape, const std::optional<Dents>& dents,
                              double tolerance = 1e-13);

struct Continuum {
  MassProperties mass;
  ContinuumMethod method = ContinuumMethod::ClosedForm;
};

/// Mass properties of `mass` kg spread evenly over the body's volume: the closed form when
/// there is one, else cubature.
Continuum continuumMassProperties(const Paraboloid& shape, const std::optional<Dents>& dents,
                                  double mass);

/// The share of the plain paraboloid's volume that the dents remove (0: they cut nothing, lying
/// wholly outside the body; nothing without dents), from the closed form where there is one,
/// else cubature to 1e-10 (a share below 1e-9 is none).
std::optional<double> dentsCutShare(const Paraboloid& shape, const std::optional<Dents>& dents);

}  // namespace sim

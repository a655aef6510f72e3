// Theory for a body (SPEC "Theory"; seed §2): its rest on the floor and the linearised
// rolling model about steady upright spin.
#pragma once

#include <complex>
#include <vector>

#include "sim/model.hpp"

namespace sim {

/// The upright rest: the CM above the contact point and the bottom's curvature there.
struct Rest {
  double h = 0;           ///< CM height above the rest contact, m
  Eigen::Vector2d radii;  ///< principal radii of curvature, ascending, m
  bool stable = false;    ///< h below both radii (Bondi 1986: p<1, s<1,
                          ///< (1−p)(1−s) > q² in his units)
};
Rest restOf(const Model& model);

/// The rolling model linearised about upright spin n: five eigenvalues of the tilt
/// (u = Rᵀẑ, two components) and ω_body (three); one is zero (the spin itself), the other
/// four are the roll (rocking about the long axis) and pitch (about the short axis) modes.
struct Linearisation {
  double spin = 0;                                ///< rad/s
  std::vector<std::complex<double>> eigenvalues;  ///< 1/s
  double roll_growth = 0, pitch_growth = 0;       ///< largest real part in each mode, 1/s
  double roll_hz = 0, pitch_hz = 0;               ///< |imaginary part| / 2π, Hz
};
Linearisation linearise(const Model& model, double spin);

/// First order in n (Walker 1896, Bondi 1986; the seed's eqs. 18–20 generalised): the growth
/// rates are n·k with k = d(Re λ)/dn at n = 0, here from the exact linearisation. 1/(rad).
struct FirstOrder {
  double roll = 0, pitch = 0;
};
FirstOrder firstOrderGrowth(const Model& model);

/// A direction of spin seen from above.
enum class Direction {
  Ccw,   ///< counter-clockwise: n > 0
  Cw,    ///< clockwise: n < 0
  None,  ///< no preferred direction (preferredDirection: neither way grows, or both alike)
};

/// The direction of spin (at |spin|) whose fastest mode grows more slowly: the one that keeps
/// turning; spun the other way the body is predicted to reverse. None where neither direction's
/// rocking grows (spun either way it is predicted to keep turning) or where both grow alike
/// (a body with no misalignment): a dentless body got "cw" from rounding (issue 26).
Direction preferredDirection(const Model& model, double spin_magnitude);

/// Whether a spin n (rad/s) turns in `direction` (never in None).
inline bool turns(Direction direction, double spin) {
  if (direction == Direction::None) return false;
  return direction == Direction::Ccw ? spin > 0 : spin < 0;
}

}  // namespace sim

namespace rb {
template <>
struct NameTable<sim::Direction> {
  static constexpr std::array<std::pair<sim::Direction, std::string_view>, 3> entries{{
      {sim::Direction::Ccw, "ccw"},
      {sim::Direction::Cw, "cw"},
      {sim::Direction::None, "none"},
  }};
};
}  // namespace rb

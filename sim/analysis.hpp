// Theory for a body (docs/physics.md P8; seed §2): its rest on the floor and the linearised
// rolling model about steady upright spin.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <optional>
#include <string_view>
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

/// The state of the linearised rolling model, in the order of Linearisation::matrix's rows and
/// columns: the tilt u = Rᵀẑ (the world's up in body axes; two components, the third follows)
/// and the angular velocity in body axes. Yaw and the position drop out (the floor is the same
/// everywhere and every way round).
struct LinearState {
  std::string_view name, unit, meaning;
};
inline constexpr std::array<LinearState, 5> kLinearStates{{
    {"u_x", "1", "the world's up along body x (tilt about body y)"},
    {"u_y", "1", "the world's up along body y (tilt about body x)"},
    {"w_x", "rad/s", "angular velocity about body x"},
    {"w_y", "rad/s", "angular velocity about body y"},
    {"w_z", "rad/s", "angular velocity about body z (n at steady spin)"},
}};

/// The rolling model linearised about upright spin n: d/dt (x − x̄) = A (x − x̄) with x the
/// state above and x̄ = (0, 0, 0, 0, n). Five eigenvalues; one is the spin's own: zero without
/// air drag (every n is a steady state), −σ/C with it (the drag's slowing of n, C the moment of
/// inertia about the vertical); the other four are the roll (rocking about the long axis) and
/// pitch (about the short axis) modes.
struct Linearisation {
  double spin = 0;  ///< rad/s
  /// A, 1/s (entries in the states' units); NaN until linearise fills it
  Eigen::Matrix<double, 5, 5> matrix = Eigen::Matrix<double, 5, 5>::Constant(NAN);
  std::vector<std::complex<double>> eigenvalues;  ///< of A, 1/s
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

/// The averaged small-oscillation theory of the first reversal (docs/physics.md P8.5; Garcia &
/// Hubbard 1988 in the form of Kondo & Nakanishi 2017): the spin n and the energies of the roll
/// and pitch modes E_r, E_p, averaged over the rocking, obey
///   C ṅ = −σ n − 2 (k_r E_r + k_p E_p),   Ė_j = 2 (k_j n + g_j) E_j,
/// with C the moment of inertia about the vertical, σ the air drag, k_j the first-order growth
/// (FirstOrder) and g_j the modes' own growth at rest (their decay under drag). Without drag
/// the energy ½ C n² + E_r + E_p is conserved.
struct AveragedModes {
  double spin = 0;     ///< n at the start, rad/s
  double inertia = 0;  ///< C, kg m²
  double drag = 0;     ///< σ, N m s
  struct Mode {
    double k = 0;       ///< first-order growth per spin, 1/rad
    double decay = 0;   ///< g: growth at rest, 1/s (≤ 0)
    double energy = 0;  ///< J at the start
  } roll, pitch;
};

/// The first zero of n within `horizon` s, integrating the averaged equations.
std::optional<double> averagedReversalTime(const AveragedModes& modes, double horizon);

/// Their closed form for one mode without drag: n = −N tanh(k N (t − t_r)) with
/// N² = n0² + 2 E/C, so t_r = artanh(|n0| / N) / (|k| N) where k·n0 > 0 (the mode grows);
/// none where it decays.
std::optional<double> oneModeReversalTime(double n0, double k, double energy, double inertia);

/// How far the averaged theory holds for a forecast (ReversalForecast), from the measured
/// table of docs/physics.md P8.5.
enum class ForecastRange {
  Within,   ///< n²ρ/g ≤ 0.15 and the energy ratio ≤ 0.1: within about 1.5 % of a run
  Beyond,   ///< either larger, up to 1: 11 % early to 10 % late in the runs measured
  Outside,  ///< either above 1: no forecast (Kane & Levinson's scene, 5.1: 60 % early)
};

/// The forecast for a model's initial tilt spun at `spin` about the body axis.
struct ReversalForecast {
  bool applies = false;    ///< the body stands upright (Rest::stable)
  AveragedModes modes;     ///< the equations' values; the modes' energies are the initial tilt's
                           ///< share in each (linearised at rest, where the modes do not mix)
  double tilt_energy = 0;  ///< J: the tilt's potential energy ½ δuᵀ K δu (= E_r + E_p)
  /// The theory is first order in n² ρ / g (ρ the larger radius of curvature at rest: the spin's
  /// centripetal acceleration at the contact's lever against gravity) and needs the rocking's
  /// energy small against the spin's, 2 (E_r + E_p) / (C n²). Measured against rolling runs
  /// without drag (docs/physics.md P8.5): 13 % early at 0.85, 3 % at 0.14, 1 % at 0.03.
  double spin_parameter = 0;
  double energy_ratio = 0;
  ForecastRange range = ForecastRange::Outside;
  std::optional<double> time;  ///< s: the first zero of n within the horizon, if any
};

/// The forecast for the model's initial tilt spun at `spin` about the body axis (n = spin ×
/// cos tilt), followed for `horizon` seconds.
ReversalForecast forecastFirstReversal(const Model& model, double spin, double horizon);

/// A direction of spin seen from above.
enum class Direction {
  Ccw,   ///< counter-clockwise: n > 0
  Cw,    ///< clockwise: n < 0
  None,  ///< no preferred direction (preferredDirection: neither way grows, or both alike)
};

/// The fastest growth of the rocking spun each way at |spin| (at least 1e-3 rad/s), 1/s, and
/// the rate below which a growth counts as none: what the two questions below read.
struct GrowthEachWay {
  double ccw, cw, zero;
  double spin = 1e-3;  ///< the |spin| they were found at, rad/s
};
GrowthEachWay growthEachWay(const Model& model, double spin_magnitude);

/// The direction of spin (at |spin|) whose fastest mode grows more slowly: the one that keeps
/// turning; spun the other way the body is predicted to reverse. None where neither direction's
/// rocking grows (spun either way it is predicted to keep turning) or where both grow alike
/// (a body with no misalignment): a dentless body got "cw" from rounding.
Direction preferredDirection(const GrowthEachWay& growth);
inline Direction preferredDirection(const Model& model, double spin_magnitude) {
  return preferredDirection(growthEachWay(model, spin_magnitude));
}

/// The e-folds the rocking grows, spun the way it grows more slowly, as drag alone slows the spin
/// (by e in C/σ) to where it no longer grows: the growth rate integrated along the spin's decay,
/// each moment's rate the linearised theory's at that moment's spin; infinite without drag.
double eFoldsAgainstDrag(const Model& model, const GrowthEachWay& growth);
/// The rocking the rule of thumb asks for (docs/physics.md P8.4): from its start to this, rad.
inline constexpr double kRockingThatReverses = 14 * M_PI / 180;
/// The rocking's start, rad: the initial tilt's, with the swing a tilt rate (initial.angular_
/// velocity's x and y) starts at the slower rest frequency.
double rockingStart(const Model& model);
/// The e-folds the rule of thumb asks for: from the rocking's start to kRockingThatReverses;
/// infinite where nothing starts the rocking, 0 from a start beyond it.
double eFoldsNeeded(const Model& model);

/// Whether the rocking grows spun either way at |spin| (a body with deep dents), the slower
/// growth as many e-folds as eFoldsNeeded or more as drag slows the spin: then it is predicted
/// to reverse spun either way, the preferred way later (docs/physics.md P8.4).
bool growsEitherWay(const Model& model, const GrowthEachWay& growth);
/// The same from the e-folds and the need already worked out (eFoldsAgainstDrag, eFoldsNeeded).
bool growsEitherWay(const GrowthEachWay& growth, double efolds, double needed);
inline bool growsEitherWay(const Model& model, double spin_magnitude) {
  return growsEitherWay(model, growthEachWay(model, spin_magnitude));
}

/// Whether a spin n (rad/s) turns in `direction` (never in None).
inline bool turns(Direction direction, double spin) {
  if (direction == Direction::None) return false;
  return direction == Direction::Ccw ? spin > 0 : spin < 0;
}

}  // namespace sim

namespace rb {
template <>
struct NameTable<sim::ForecastRange> {
  static constexpr std::array<std::pair<sim::ForecastRange, std::string_view>, 3> entries{{
      {sim::ForecastRange::Within, "within"},
      {sim::ForecastRange::Beyond, "beyond"},
      {sim::ForecastRange::Outside, "outside"},
  }};
};
template <>
struct NameTable<sim::Direction> {
  static constexpr std::array<std::pair<sim::Direction, std::string_view>, 3> entries{{
      {sim::Direction::Ccw, "ccw"},
      {sim::Direction::Cw, "cw"},
      {sim::Direction::None, "none"},
  }};
};
}  // namespace rb

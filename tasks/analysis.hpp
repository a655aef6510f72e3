// What `analyze` finds about a scene, as one JSON value: mass properties, rest, contact limits,
// the linearised theory and the preferred direction (docs/commands.md "rattleback analyze"). The
// command prints it; Python's analyze() returns it as a dict.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sim/analysis.hpp"
#include "sim/body.hpp"
#include "sim/model.hpp"
#include "sim/stability.hpp"
#include "util/names.hpp"
#include "util/result.hpp"

namespace tasks {

/// The spin the theory is evaluated at: `spin` when given, else the scene's, else (a scene not
/// spun, whose theory at 0 says nothing of a direction) 5 rad/s.
double analysisSpin(const sim::Model& model, const std::optional<double>& spin);
/// A spin given for the analysis (analyze --spin, Python's spin=) is finite: a NaN printed
/// numbers of no meaning and a preferred direction. `option` names it in the error.
rb::Status checkAnalysisSpin(const std::optional<double>& spin, const std::string& option);

/// The share of the undented paraboloid's volume that the dents cut away (0 … 1), or nothing
/// for a body without dents (or an ellipsoid). 0: dents placed wholly outside the body (a body
/// made smaller with its dents left where they were), which cut nothing and so make no
/// rattleback; analyze says so.
std::optional<double> dentsCutShare(const sim::Body& body);

/// Where the mass properties came from (body.mass_properties): scene, grid or continuum.
std::string massSourceText(const sim::Body& body);

/// A mesh body's fitted bottom (docs/physics.md §P11.4) as JSON: its residual (RMS and largest,
/// m and as a fraction of the body's longest side), the cap's points and largest tilt, and why
/// the smooth models cannot use it (null when they can). Null for any other body. The same in
/// `analyze --json` and the run's sidecar.
nlohmann::json fittedBottomJson(const sim::Body& body);
nlohmann::json fittedBottomJson(const sim::BottomFit& fit);

/// The body's size: the box that holds it, length (the longer horizontal side), width, height,
/// m.
Eigen::Vector3d bodySize(const sim::Body& body);
/// Whether a frame of `frame_m` metres (video.frame) frames `body` sensibly: within 1/10 … 50
/// times its length. Beyond 50 times the body is a few pixels long; within a tenth of it the
/// picture shows part of a point or two: either is a slip of unit (a file in cm given metres,
/// or the other way), which `still` and `render` refuse and the player ignores.
bool frameFits(double frame_m, const sim::Body& body);
/// The size as people read it, in the file's unit: "20 × 6.06 × 2.55 cm".
std::string sizeText(const Eigen::Vector3d& size_m, double length_unit);
/// A mass that no material gives a body of this size, said with the likely slip (a mass typed
/// in grams, lengths in centimetres read as metres for want of `units:`), or nothing. The
/// body fills at most its box, so mass / box volume is the least its density can be: above
/// 23,000 kg/m³ it is denser than any solid (osmium, 22,590 kg/m³); a body that fills even a
/// tenth of its box and is lighter than air (1.2 kg/m³) cannot stand on a floor.
std::optional<std::string> implausibleMass(const sim::Body& body, double length_unit);

/// A rocking mode of the body upright at rest: its frequency, or none where it grows without
/// rocking (a body that cannot stand topples along it), and its growth rate, 1/s.
struct RestMode {
  std::optional<double> hz;
  double growth = 0;
};
struct RestModes {
  RestMode roll, pitch;
};

/// The modes of `at_rest` (sim::linearise at spin 0). A mode is unstable where it grows faster
/// than 1e-6 of the fastest rocking frequency (below that the rates are the finite-difference
/// Jacobian's noise, as in sim::preferredDirection); its growth is 0 below that.
RestModes restModes(const sim::Linearisation& at_rest);

/// How early the forecast of the first reversal came beyond the theory's range: the least and
/// largest error measured there, rounded out (docs/physics.md P8.5's table; a test reads it).
inline constexpr const char* kBeyondRangeError = "between 40 % early and 10 % late";

/// The linearised rolling model's growth rates at one spin.
struct GrowthAt {
  double spin = 0;             ///< n, rad/s
  double roll = 0, pitch = 0;  ///< largest real part in each mode, 1/s
};

/// What `analyze` finds about a scene, worked out once: the text (app/analyze.cpp), the JSON
/// (analysisJson) and Python's analyze() only format it. Lengths in m unless said.
struct Analysis {
  // The body.
  double length_unit = 1;   ///< m per file unit (units.length)
  bool paraboloid = false;  ///< points on a grid; else an ellipsoid's (scene's)
  bool mesh = false;        ///< a mesh body: points sampled from it, theory from its fitted bottom
  /// A mesh body's fitted bottom (docs/physics.md §P11.4); default for any other body.
  sim::BottomFit fit;
  /// The theory was worked out: every body but a mesh whose bottom does not fit.
  bool theory = false;
  sim::GridCensus census;                 ///< the grid's points (total for a paraboloid only)
  std::string mass_source;                ///< massSourceText
  std::optional<double> dents_cut_share;  ///< dentsCutShare
  double mass = 0;                        ///< kg
  Eigen::Vector3d size = Eigen::Vector3d::Zero();       ///< bodySize: length, width, height
  std::optional<std::string> implausible_mass;          ///< implausibleMass
  Eigen::Vector3d com = Eigen::Vector3d::Zero();        ///< shape's frame, rounding's zeros as 0
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();    ///< about the CM, geometric axes, kg m²
  Eigen::Vector3d principal = Eigen::Vector3d::Zero();  ///< principal moments, kg m²
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();   ///< principal axes as columns
  double misalignment_deg = 0;  ///< least-inertia axis from the bottom's long axis, ccw
  // The contact.
  sim::ContactModel contact_model = sim::ContactModel::Rolling;
  double drag = 0;  ///< contact.air_drag, N m s
  sim::Integrator integrator = sim::Integrator::Symplectic;
  sim::ContactStability stability;
  double auto_smooth_step = 0;  ///< s: auto's smooth steps within each fixed step, else 0
  // Rest and the theory.
  sim::Rest rest;
  RestModes modes;          ///< at rest (spin 0)
  double spin = 0;          ///< rad/s: the spin the theory is at (analysisSpin)
  bool spin_given = false;  ///< given by the caller rather than the scene's
  bool unspun = false;      ///< not given and the scene is not spun: at 5 rad/s
  sim::FirstOrder first_order;
  std::vector<GrowthAt> growth;  ///< at ±1, 2, 5, 10 rad/s and `spin`, ascending
  sim::Linearisation at_spin;    ///< linearised at `spin`
  sim::Direction preferred = sim::Direction::None;  ///< at |spin|
  /// Where no direction is preferred at |spin| by a body that stands: the one preferred at
  /// max(5, |spin|) rad/s (a slow spin may see the rocking die out both ways).
  std::optional<sim::Direction> preferred_faster;
  /// Whether the rocking grows spun either way at |spin|: then the body is predicted to reverse
  /// spun the preferred way too, later (sim::growsEitherWay).
  bool grows_either_way = false;
  /// The slower growth's e-folds as drag slows the spin (sim::eFoldsAgainstDrag; infinite
  /// without drag), and the count the rule asks for (sim::eFoldsNeeded).
  double either_way_efolds = 0;
  double either_way_needed = 0;
  double rocking_start = 0;        ///< rad: what the needed count starts from (sim::rockingStart)
  double preferred_growth = 0;     ///< 1/s: the fastest growth spun the preferred way at |spin|
  sim::ReversalForecast forecast;  ///< of the first reversal spun `spin`, within `duration`
  double duration = 0;             ///< s: how far the forecast looks
};

/// The analysis of `model` at `spin` rad/s when given, else as analysisSpin chooses.
Analysis analyze(const sim::Model& model, const std::optional<double>& spin);

/// Whether the linearised theory applies to the body: a smooth body, or a mesh body whose bottom
/// a quadric fits (docs/physics.md §P11.4). `analyze`'s theory and a sweep's forecast_s ask it.
bool hasTheory(const sim::Model& model);

/// Why a forecast is, or is not, a time: a word a table groups by.
enum class ForecastNote {
  Within,        ///< a time, n²ρ/g and the energy ratio in the theory's range (about 1.5 %)
  Beyond,        ///< a time, past that range (40 % early to 10 % late in the runs measured)
  NoneInRun,     ///< no zero of n within the run: spun the preferred way, or too slowly
  OutsideRange,  ///< spin or tilt too large for the averaged theory: no forecast
  NotSpun,       ///< initial spin 0
  CannotStand,   ///< the body does not stand upright at rest
  NoTheory,      ///< a mesh body whose bottom no quadric fits
};

/// The first reversal `analyze` forecasts for the scene as it is, and why it is or is not one.
struct Forecast {
  std::optional<double> time;  ///< s, where `note` is Within or Beyond
  ForecastNote note = ForecastNote::NoTheory;
};

/// The first reversal `analyze` forecasts for the scene as it is (its "first reversal" line,
/// docs/physics.md P8.5), s; none where that line gives no time: a scene not spun, a body that
/// cannot stand or has no smooth bottom (a mesh no quadric fits), a spin outside the averaged
/// theory's range, or no reversal within the run — `note` says which. The theory alone: no run
/// is integrated (a sweep's forecast_s and forecast_note).
Forecast forecastReversal(const sim::Model& model);

/// The analysis as one JSON value (docs/commands.md "rattleback analyze").
nlohmann::json analysisJson(const Analysis& analysis);
/// The linearised rolling model as JSON: its spin, the states' names, units and meanings
/// (sim::kLinearStates), the state matrix by rows and its eigenvalues as [re, im] pairs: the
/// `linearised` entry of analysisJson, and Python's rb.linearize.
nlohmann::json linearisationJson(const sim::Linearisation& linearisation);
/// The analysis of `model` at `spin` rad/s as JSON.
inline nlohmann::json analysisJson(const sim::Model& model, double spin) {
  return analysisJson(analyze(model, spin));
}

}  // namespace tasks

namespace rb {
template <>
struct NameTable<tasks::ForecastNote> {
  static constexpr std::array<std::pair<tasks::ForecastNote, std::string_view>, 7> entries{{
      {tasks::ForecastNote::Within, "within"},
      {tasks::ForecastNote::Beyond, "beyond"},
      {tasks::ForecastNote::NoneInRun, "none_in_run"},
      {tasks::ForecastNote::OutsideRange, "outside_range"},
      {tasks::ForecastNote::NotSpun, "not_spun"},
      {tasks::ForecastNote::CannotStand, "cannot_stand"},
      {tasks::ForecastNote::NoTheory, "no_theory"},
  }};
};
}  // namespace rb

#include "tasks/analysis.hpp"

#include <algorithm>
#include <cmath>

#include "sim/analysis.hpp"
#include "sim/compile.hpp"
#include "sim/continuum.hpp"
#include "sim/integrator.hpp"
#include "sim/stability.hpp"
#include "sim/switching.hpp"
#include "util/format.hpp"

namespace tasks {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

nlohmann::json matrixJson(const Eigen::Matrix3d& m) {
  return {vectorJson(m.row(0)), vectorJson(m.row(1)), vectorJson(m.row(2))};
}

// A value that is zero but for rounding (a symmetric body's CM at −8.5e−18 m) is 0.
double clean(double v, double scale) {
  return std::abs(v) < 1e-12 * scale ? 0.0 : v;
}

Eigen::Vector3d clean(const Eigen::Vector3d& v, double scale) {
  return {clean(v.x(), scale), clean(v.y(), scale), clean(v.z(), scale)};
}

// `value` where it means something, else null (a body that cannot stand has no modes).
template <typename T>
nlohmann::json orNull(bool meaningful, const T& value) {
  return meaningful ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace

// Where the mass properties came from (body.mass_properties), as analyze reports it.
std::string massSourceText(const sim::Body& body) {
  if (body.surface.kind == sim::Surface::Kind::Mesh) {
    // Which of the two the scene gave: a CM without an inertia keeps the uniform solid's
    // inertia, about the scene's CM (a weight moves both: docs/your-own-body.md).
    if (body.com_given && body.inertia_given) return "the scene's center_of_mass and inertia";
    if (body.com_given) return "the scene's center_of_mass, the uniform solid's inertia";
    if (body.inertia_given) return "the scene's inertia, the uniform solid's CM";
    return "mesh (exact for the polyhedron, uniform density)";
  }
  if (body.surface.kind != sim::Surface::Kind::Paraboloid) return "scene";
  if (body.mass_source == sim::MassSource::Grid) return "grid";
  return body.mass_by_cubature ? "continuum (cubature)" : "continuum (closed form)";
}

nlohmann::json fittedBottomJson(const sim::Body& body) {
  if (body.surface.kind != sim::Surface::Kind::Mesh) return nullptr;
  return fittedBottomJson(body.surface.mesh.fit);
}

nlohmann::json fittedBottomJson(const sim::BottomFit& fit) {
  // Not measured (NaN) or reaching no point (∞): null, as every non-finite number here.
  auto number = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  return {{"surface", "quadric, least squares (docs/physics.md P11.4)"},
          {"points", fit.points},
          {"rms_m", number(fit.rms_m)},
          {"max_m", number(fit.max_m)},
          {"rms_fraction", number(fit.rms_m / fit.size_m)},
          {"max_fraction", number(fit.max_m / fit.size_m)},
          {"rms_limit_fraction", sim::kFitRmsLimit},
          {"cap_deg", number(std::atan(fit.cap_slope) * 180 / M_PI)},
          {"problem", fit.usable() ? nlohmann::json(nullptr) : nlohmann::json(fit.problem)}};
}

Eigen::Vector3d bodySize(const sim::Body& body) {
  const Eigen::Vector3d box = body.surface.boxHigh() - body.surface.boxLow();
  return {std::max(box.x(), box.y()), std::min(box.x(), box.y()), box.z()};
}

bool frameFits(double frame_m, const sim::Body& body) {
  // (With rounding's slack: a tenth of the default body, 2 cm of 20, is 0.02 m, and 0.1 × 0.2 is
  // 0.020000000000000004: `--frame 2` was refused as below a tenth.)
  const double length = bodySize(body).x(), slack = 1 + 1e-12;
  return frame_m <= 50 * length * slack && frame_m * slack >= 0.1 * length;
}

std::string sizeText(const Eigen::Vector3d& size_m, double length_unit) {
  const char* unit = length_unit == 1       ? "m"
                     : length_unit == 0.01  ? "cm"
                     : length_unit == 0.001 ? "mm"
                                            : nullptr;
  char text[160];
  const Eigen::Vector3d s = size_m / length_unit;
  if (unit)
    std::snprintf(text, sizeof text, "%.3g × %.3g × %.3g %s", s.x(), s.y(), s.z(), unit);
  else
    std::snprintf(text, sizeof text, "%.3g × %.3g × %.3g (× %g m)", s.x(), s.y(), s.z(),
                  length_unit);
  return text;
}

namespace {

// The body's volume, m³: the dented paraboloid's (closed form, else cubature), the ellipsoid's
// 4/3 π a b c, or the mesh's (docs/physics.md §P11.1).
double bodyVolume(const sim::Body& body) {
  if (body.surface.kind == sim::Surface::Kind::Mesh) return body.surface.mesh.volume;
  if (body.surface.kind == sim::Surface::Kind::Ellipsoid)
    return 4.0 / 3.0 * M_PI * body.surface.ellipsoid.semi_axes.prod();
  const sim::Paraboloid& shape = body.surface.paraboloid;
  const std::optional<sim::VolumeMoments> closed = sim::closedFormMoments(shape, body.dents);
  return closed ? closed->volume : sim::cubatureMoments(shape, body.dents, 1e-10).volume;
}

}  // namespace

std::optional<std::string> implausibleMass(const sim::Body& body, double length_unit) {
  const Eigen::Vector3d size = bodySize(body);
  const double box = size.prod();
  if (!(box > 0) || !(body.mass > 0)) return std::nullopt;
  const double least = body.mass / box;  // kg/m³: the body fills at most its box
  char text[400];
  if (least > 23000) {
    // With a unit of its own the lengths may be the slip: mm written for cm (units.length 0.001 for
    // a body measured in cm was blamed on the mass alone).
    const std::string unit = length_unit < 0.01 ? ", or the lengths are larger than units.length " +
                                                      rb::show(length_unit) +
                                                      " m makes them (0.01 reads them in cm)"
                                                : "";
    std::snprintf(text, sizeof text,
                  "body.mass %g kg in a body of %s is at least %.2g kg/m³, denser than any solid "
                  "(osmium: 22,590 kg/m³): body.mass is in kg (59 g is 0.059)%s",
                  body.mass, sizeText(size, length_unit).c_str(), least, unit.c_str());
    return text;
  }
  if (10 * least < 1.2) {
    std::snprintf(text, sizeof text,
                  "body.mass %g kg in a body of %s is lighter than air: lengths are in metres "
                  "unless units: says otherwise (units: {length: 0.01} reads them in cm)",
                  body.mass, sizeText(size, length_unit).c_str());
    return text;
  }
  // Over its own volume, lighter than any foam: lengths ten times too large (mm numbers in a file
  // of cm made a 2 m body of 59 g, 1.2 kg/m³, with nothing said). (Filling at most its box, it is
  // at least `least` dense: the volume is worked out only for a body light for its box.)
  if (const double density = least < 5 ? body.mass / bodyVolume(body) : least; density < 5) {
    std::snprintf(text, sizeof text,
                  "body.mass %g kg in a body of %s is %.2g kg/m³, lighter than any foam "
                  "(expanded polystyrene: 10–30 kg/m³): are the lengths larger than meant? "
                  "(units.length %s m; 0.01 reads them in cm, 0.001 in mm)",
                  body.mass, sizeText(size, length_unit).c_str(), density,
                  rb::show(length_unit).c_str());
    return text;
  }
  return std::nullopt;
}

RestModes restModes(const sim::Linearisation& at_rest) {
  const double zero = 1e-6 * 2 * M_PI * std::max(at_rest.roll_hz, at_rest.pitch_hz);
  auto mode = [&](double hz, double growth) {
    if (growth > zero) return RestMode{std::nullopt, growth};
    return RestMode{hz, std::abs(growth) <= zero ? 0.0 : growth};
  };
  return {mode(at_rest.roll_hz, at_rest.roll_growth), mode(at_rest.pitch_hz, at_rest.pitch_growth)};
}

std::optional<double> dentsCutShare(const sim::Body& body) {
  if (body.surface.kind != sim::Surface::Kind::Paraboloid) return std::nullopt;
  double share = body.dents_cut_share.value.load();
  if (std::isnan(share)) {
    share = sim::dentsCutShare(body.surface.paraboloid, body.dents).value_or(-1.0);
    body.dents_cut_share.value.store(share);
  }
  if (share < 0) return std::nullopt;
  return share;
}

double analysisSpin(const sim::Model& model, const std::optional<double>& spin) {
  if (spin) return *spin;
  return model.initial.spin != 0 ? model.initial.spin : 5.0;
}

rb::Status checkAnalysisSpin(const std::optional<double>& spin, const std::string& option) {
  if (spin && !std::isfinite(*spin))
    return rb::Status::fail(option + ": must be a finite number, not " + rb::show(*spin));
  return {};
}

namespace {

// The growth rates at ±1, 2, 5, 10 rad/s and at `spin`, ascending; at `spin` they are
// `at_spin`'s.
std::vector<GrowthAt> growthTable(const sim::Model& model, double spin,
                                  const sim::Linearisation& at_spin) {
  std::vector<double> spins = {-10, -5, -2, -1, 1, 2, 5, 10};
  if (std::find(spins.begin(), spins.end(), spin) == spins.end()) spins.push_back(spin);
  std::sort(spins.begin(), spins.end());
  std::vector<GrowthAt> table;
  for (double n : spins) {
    const sim::Linearisation l = n == spin ? at_spin : sim::linearise(model, n);
    table.push_back({n, l.roll_growth, l.pitch_growth});
  }
  return table;
}

// The body's mass properties, size and the checks on them.
void analyzeBody(const sim::Model& model, Analysis& a) {
  const sim::Body& body = *model.body;
  const sim::MassProperties& m = body.mass_properties;
  a.length_unit = model.length_unit;
  a.paraboloid = body.surface.kind == sim::Surface::Kind::Paraboloid;
  a.mesh = body.surface.kind == sim::Surface::Kind::Mesh;
  if (a.mesh) a.fit = body.surface.mesh.fit;
  a.census = sim::censusOf(body);
  a.mass_source = massSourceText(body);
  a.dents_cut_share = dentsCutShare(body);
  a.mass = m.mass;
  a.size = bodySize(body);
  a.implausible_mass = implausibleMass(body, model.length_unit);
  a.com = clean(m.com, body.surface.footprintHalf().maxCoeff());
  a.inertia = m.inertia;
  a.principal = m.principal;
  a.axes = m.axes;
  a.misalignment_deg = m.misalignment_deg;
}

// The rest, the linearised theory at `a.spin` and the forecast first reversal.
void analyzeTheory(const sim::Model& model, Analysis& a) {
  a.rest = sim::restOf(model);
  a.modes = restModes(sim::linearise(model, 0));
  a.first_order = sim::firstOrderGrowth(model);
  a.at_spin = sim::linearise(model, a.spin);
  a.growth = growthTable(model, a.spin, a.at_spin);
  // The two directions linearised once for all three answers.
  const sim::GrowthEachWay each_way = sim::growthEachWay(model, a.spin);
  a.preferred = sim::preferredDirection(each_way);
  a.either_way_efolds = sim::eFoldsAgainstDrag(model, each_way);
  a.either_way_needed = sim::eFoldsNeeded(model);
  a.grows_either_way = sim::growsEitherWay(each_way, a.either_way_efolds, a.either_way_needed);
  a.rocking_start = sim::rockingStart(model);
  a.preferred_growth = a.preferred == sim::Direction::Ccw  ? each_way.ccw
                       : a.preferred == sim::Direction::Cw ? each_way.cw
                                                           : 0;
  if (a.rest.stable && a.preferred == sim::Direction::None)
    a.preferred_faster = sim::preferredDirection(model, std::max(5.0, std::abs(a.spin)));
  a.forecast = sim::forecastFirstReversal(model, a.spin, model.duration);
  a.duration = model.duration;
}

}  // namespace

Analysis analyze(const sim::Model& model, const std::optional<double>& spin) {
  Analysis a;
  a.spin = analysisSpin(model, spin);
  a.spin_given = spin.has_value();
  a.unspun = !a.spin_given && model.initial.spin == 0;
  analyzeBody(model, a);
  a.contact_model = model.contact.model;
  a.drag = model.contact.air_drag;
  a.integrator = model.integrator;
  a.stability = sim::contactStability(model);
  if (model.contact.model == sim::ContactModel::Auto && !sim::isAdaptive(model.integrator))
    a.auto_smooth_step = std::min(sim::smoothStep(model), model.dt);
  a.theory = hasTheory(model);
  if (a.theory) analyzeTheory(model, a);
  return a;
}

bool hasTheory(const sim::Model& model) {
  // The theory linearises rolling on the smooth bottom: a mesh body's fitted one (§P11.4).
  const sim::Surface& surface = model.body->surface;
  return surface.kind != sim::Surface::Kind::Mesh || surface.mesh.fit.usable();
}

Forecast forecastReversal(const sim::Model& model) {
  using N = ForecastNote;
  if (!hasTheory(model)) return {std::nullopt, N::NoTheory};
  if (model.initial.spin == 0) return {std::nullopt, N::NotSpun};
  const sim::ReversalForecast forecast =
      sim::forecastFirstReversal(model, analysisSpin(model, std::nullopt), model.duration);
  if (!forecast.applies) return {std::nullopt, N::CannotStand};
  if (forecast.range == sim::ForecastRange::Outside) return {std::nullopt, N::OutsideRange};
  if (!forecast.time) return {std::nullopt, N::NoneInRun};
  return {forecast.time, forecast.range == sim::ForecastRange::Within ? N::Within : N::Beyond};
}

namespace {

nlohmann::json bodyJson(const Analysis& a) {
  nlohmann::json j;
  const auto top = static_cast<std::size_t>(a.census.top);
  const auto bottom = static_cast<std::size_t>(a.census.bottom);
  j["points"] = {{"total", a.paraboloid ? nlohmann::json(a.census.points) : nlohmann::json()},
                 {"top", top},
                 {"bottom", bottom},
                 {"surface", top + bottom}};
  j["mass_properties"] = a.mass_source;
  j["length_unit_m"] = a.length_unit;
  j["mass"] = a.mass;
  j["size_m"] = vectorJson(a.size);  // length, width, height
  j["implausible_mass"] =
      a.implausible_mass ? nlohmann::json(*a.implausible_mass) : nlohmann::json(nullptr);
  j["com"] = vectorJson(a.com);
  j["inertia"] = matrixJson(a.inertia);
  j["principal_moments"] = vectorJson(a.principal);
  j["principal_axes"] = matrixJson(a.axes.transpose());
  j["misalignment_deg"] = a.misalignment_deg;
  j["dents_cut_share"] =
      a.dents_cut_share ? nlohmann::json(*a.dents_cut_share) : nlohmann::json(nullptr);
  j["fitted_bottom"] = a.mesh ? fittedBottomJson(a.fit) : nlohmann::json(nullptr);
  j["contact"] = {{"omega_rad_s", a.stability.omega},
                  {"damping_ratio", a.stability.zeta},
                  {"largest_stable_dt_s", a.stability.run_step},  // inf → null
                  {"largest_stable_dt_at_rest_s", a.stability.largest_step}};
  return j;
}

nlohmann::json eigenvaluesJson(const sim::Linearisation& l) {
  nlohmann::json eigenvalues = nlohmann::json::array();
  for (const auto& lambda : l.eigenvalues) eigenvalues.push_back({lambda.real(), lambda.imag()});
  return eigenvalues;
}

nlohmann::json forecastJson(const Analysis& a) {
  const sim::ReversalForecast& forecast = a.forecast;
  return {{"theory", "averaged small-oscillation (Garcia & Hubbard 1988; docs/physics.md P8.5)"},
          {"applies", forecast.applies},
          {"range", orNull(forecast.applies, std::string(rb::nameOf(forecast.range)))},
          {"time_s", forecast.time ? nlohmann::json(*forecast.time) : nlohmann::json(nullptr)},
          {"within_s", a.duration},
          {"spin", forecast.modes.spin},
          {"spin_parameter", forecast.spin_parameter},
          {"energy_ratio", orNull(forecast.applies, forecast.energy_ratio)},
          {"mode_energy_j",
           orNull(forecast.applies, nlohmann::json{{"roll", forecast.modes.roll.energy},
                                                   {"pitch", forecast.modes.pitch.energy}})}};
}

}  // namespace

nlohmann::json linearisationJson(const sim::Linearisation& l) {
  nlohmann::json states = nlohmann::json::array(), matrix = nlohmann::json::array();
  for (const sim::LinearState& s : sim::kLinearStates)
    states.push_back({{"name", s.name}, {"unit", s.unit}, {"meaning", s.meaning}});
  for (int i = 0; i < l.matrix.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int k = 0; k < l.matrix.cols(); ++k) row.push_back(l.matrix(i, k));
    matrix.push_back(row);
  }
  return {{"model", "rolling, about steady upright spin (docs/physics.md P8)"},
          {"spin", l.spin},
          {"states", states},
          {"matrix", matrix},
          {"eigenvalues", eigenvaluesJson(l)}};
}

nlohmann::json analysisJson(const Analysis& a) {
  nlohmann::json j = bodyJson(a);
  j["h"] = a.rest.h;
  j["radii_of_curvature"] = {a.rest.radii(0), a.rest.radii(1)};
  j["rest_stable"] = a.rest.stable;
  // A mode that grows at rest does not rock: no frequency, and how fast it grows.
  auto hzOrNull = [](const RestMode& m) { return m.hz ? nlohmann::json(*m.hz) : nlohmann::json(); };
  j["frequencies_hz"] = {{"roll", hzOrNull(a.modes.roll)}, {"pitch", hzOrNull(a.modes.pitch)}};
  j["growth_rates_at_rest"] = {{"roll", a.modes.roll.growth}, {"pitch", a.modes.pitch.growth}};
  j["spin"] = a.spin;
  j["growth_rates"] = {{"roll", a.at_spin.roll_growth}, {"pitch", a.at_spin.pitch_growth}};
  j["first_order_growth_per_spin"] = {{"roll", a.first_order.roll}, {"pitch", a.first_order.pitch}};
  j["eigenvalues"] = eigenvaluesJson(a.at_spin);
  // A mesh body whose bottom does not fit has no theory (§P11.4): null, not a matrix never
  // computed.
  j["linearised"] = a.theory ? linearisationJson(a.at_spin) : nlohmann::json(nullptr);
  // A body that cannot stand has no rocking about upright for a spin direction to favour.
  j["preferred"] = orNull(a.rest.stable, std::string(rb::nameOf(a.preferred)));
  j["grows_either_way"] = orNull(a.rest.stable, a.grows_either_way);
  // The rule's count, where it is one: drag to slow the spin, and rocking that grows spun the
  // preferred way (docs/physics.md P8.4).
  j["either_way_efolds"] =
      orNull(a.rest.stable && a.drag > 0 && a.preferred_growth > 0, a.either_way_efolds);
  j["predicted_first_reversal"] = forecastJson(a);
  // A mesh body whose bottom does not fit has no theory (§P11.4): null, not numbers never
  // worked out.
  if (!a.theory)
    for (const char* key :
         {"h", "radii_of_curvature", "rest_stable", "frequencies_hz", "growth_rates_at_rest",
          "growth_rates", "first_order_growth_per_spin", "eigenvalues", "preferred",
          "grows_either_way", "either_way_efolds", "predicted_first_reversal"})
      j[key] = nullptr;
  return j;
}

}  // namespace tasks

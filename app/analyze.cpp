#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "sim/analysis.hpp"
#include "sim/stability.hpp"
#include "sim/switching.hpp"

namespace app {
namespace {

nlohmann::json vectorJson(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json matrixJson(const Eigen::Matrix3d& m) {
  return {vectorJson(m.row(0)), vectorJson(m.row(1)), vectorJson(m.row(2))};
}

// A value that is zero but for rounding (a symmetric body's CM at −8.5e−18 m) prints as 0.
double clean(double v, double scale) { return std::abs(v) < 1e-12 * scale ? 0.0 : v; }

Eigen::Vector3d clean(const Eigen::Vector3d& v, double scale) {
  return {clean(v.x(), scale), clean(v.y(), scale), clean(v.z(), scale)};
}

// Where the mass properties came from (body.mass_properties), as analyze reports it.
std::string massSourceText(const sim::Body& body) {
  if (body.surface.kind != sim::Surface::Kind::Paraboloid) return "scene";
  if (body.mass_source == sim::MassSource::Grid) return "grid";
  return body.mass_by_cubature ? "continuum (cubature)" : "continuum (closed form)";
}

double spinFor(const sim::Model& model, const std::optional<double>& spin) {
  if (spin) return *spin;
  return model.initial.spin != 0 ? model.initial.spin : 5.0;
}

void printJson(const sim::Model& model, double spin) {
  const sim::Body& body = *model.body;
  const sim::MassProperties& m = body.mass_properties;
  const sim::Rest rest = sim::restOf(model);
  const sim::Linearisation at_rest = sim::linearise(model, 0);
  const sim::Linearisation spinning = sim::linearise(model, spin);
  const sim::FirstOrder first = sim::firstOrderGrowth(model);
  const sim::ContactStability stability = sim::contactStability(model);
  const double size = body.surface.footprintHalf().maxCoeff();
  const std::size_t top = body.top.size(), bottom = body.bottom.size();
  nlohmann::json j;
  const bool grid = body.surface.kind == sim::Surface::Kind::Paraboloid;
  j["points"] = {{"total", grid ? nlohmann::json(m.points) : nlohmann::json(nullptr)},
                 {"top", top},
                 {"bottom", bottom},
                 {"surface", top + bottom}};
  j["mass_properties"] = massSourceText(body);
  j["length_unit_m"] = model.length_unit;
  j["mass"] = m.mass;
  j["com"] = vectorJson(clean(m.com, size));
  j["inertia"] = matrixJson(m.inertia);
  j["principal_moments"] = vectorJson(m.principal);
  j["principal_axes"] = matrixJson(m.axes.transpose());
  j["misalignment_deg"] = m.misalignment_deg;
  j["contact"] = {{"omega_rad_s", stability.omega},
                  {"damping_ratio", stability.zeta},
                  {"largest_stable_dt_s", stability.largest_step}};  // inf → null
  j["h"] = rest.h;
  j["radii_of_curvature"] = {rest.radii(0), rest.radii(1)};
  j["rest_stable"] = rest.stable;
  j["frequencies_hz"] = {{"roll", at_rest.roll_hz}, {"pitch", at_rest.pitch_hz}};
  j["spin"] = spin;
  j["growth_rates"] = {{"roll", spinning.roll_growth}, {"pitch", spinning.pitch_growth}};
  j["first_order_growth_per_spin"] = {{"roll", first.roll}, {"pitch", first.pitch}};
  nlohmann::json eigenvalues = nlohmann::json::array();
  for (const auto& lambda : spinning.eigenvalues) eigenvalues.push_back({lambda.real(), lambda.imag()});
  j["eigenvalues"] = eigenvalues;
  j["preferred"] = sim::preferredDirection(model, spin);
  std::printf("%s\n", j.dump(2).c_str());
}

void printTheory(const sim::Model& model, double spin) {
  const double unit = model.length_unit;
  const sim::Rest rest = sim::restOf(model);
  std::printf("rest contact     CM %.4g above it; radii of curvature %.4g and %.4g "
              "(file units)\n",
              rest.h / unit, rest.radii(0) / unit, rest.radii(1) / unit);
  if (rest.stable) {
    std::printf("rest             stable upright (h below both radii)\n");
  } else {
    std::printf("WARNING: the body cannot stand upright: its CM is %.4g above the contact, "
                "above the radius of curvature %.4g (needs h below both radii)\n",
                rest.h / unit, rest.radii(0) / unit);
  }
  const sim::Linearisation at_rest = sim::linearise(model, 0);
  std::printf("at rest          roll %.4g Hz, pitch %.4g Hz (linearised rolling model)\n",
              at_rest.roll_hz, at_rest.pitch_hz);
  const sim::FirstOrder first = sim::firstOrderGrowth(model);
  std::printf("first order      growth rate = n × (roll %+.4g, pitch %+.4g) 1/rad "
              "(Walker, Bondi; seed eqs. 18–20)\n",
              first.roll, first.pitch);
  std::printf("growth rates     exact linearised rolling model, 1/s:\n");
  std::printf("                 %8s %10s %10s\n", "n rad/s", "roll", "pitch");
  std::vector<double> spins = {-10, -5, -2, -1, 1, 2, 5, 10};
  if (std::find(spins.begin(), spins.end(), spin) == spins.end()) spins.push_back(spin);
  std::sort(spins.begin(), spins.end());
  for (double n : spins) {
    const sim::Linearisation l = sim::linearise(model, n);
    std::printf("                 %8.3g %+10.4f %+10.4f%s\n", n, l.roll_growth, l.pitch_growth,
                n == spin ? "   <- --spin" : "");
  }
  const sim::Linearisation l = sim::linearise(model, spin);
  std::printf("eigenvalues      at n = %g rad/s:", spin);
  double largest = 0;
  for (const auto& lambda : l.eigenvalues) largest = std::max(largest, std::abs(lambda));
  for (const auto& lambda : l.eigenvalues)
    std::printf(" %.4g%+.4gi", clean(lambda.real(), largest), clean(lambda.imag(), largest));
  std::printf("\n");
  const char* preferred = sim::preferredDirection(model, spin);
  std::printf("preferred        %s (%s seen from above); spun the other way it is predicted to "
              "reverse\n",
              preferred, preferred[0] == 'c' && preferred[1] == 'c' ? "counter-clockwise"
                                                                      : "clockwise");
}

void printText(const std::string& scene, const sim::Model& model) {
  const sim::MassProperties& m = model.body->mass_properties;
  const double unit = model.length_unit;
  const sim::ContactStability stability = sim::contactStability(model);
  const std::size_t top = model.body->top.size();
  const std::size_t bottom = model.body->bottom.size();
  std::printf("scene            %s (lengths below in the file's unit, %g m)\n", scene.c_str(),
              unit);
  if (model.body->surface.kind == sim::Surface::Kind::Paraboloid)
    std::printf("points           %lld in all, %zu on the surface (%zu top, %zu bottom)\n",
                static_cast<long long>(m.points), top + bottom, top, bottom);
  else
    std::printf("points           %zu drawn on the surface (%zu top, %zu bottom); the mass "
                "properties are the scene's\n",
                top + bottom, top, bottom);
  std::printf("mass properties  %s\n", massSourceText(*model.body).c_str());
  std::printf("mass             %g kg\n", m.mass);
  const Eigen::Vector3d com = clean(m.com, model.body->surface.footprintHalf().maxCoeff()) / unit;
  std::printf("centre of mass   (%.6g, %.6g, %.6g) in the shape's frame\n", com.x(), com.y(),
              com.z());
  std::printf("inertia about the CM, geometric axes [kg m^2]\n");
  // Products of inertia a symmetric body does not have come out of cubature as 1e-19 of the
  // moments, not 0: shown as the 0 they are.
  const double moment = m.inertia.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    std::printf("                 [% .6e  % .6e  % .6e]\n", clean(m.inertia(i, 0), moment),
                clean(m.inertia(i, 1), moment), clean(m.inertia(i, 2), moment));
  std::printf("principal        %.6e  %.6e  %.6e kg m^2, along (columns)\n", m.principal(0),
              m.principal(1), m.principal(2));
  for (int i = 0; i < 3; ++i)
    std::printf("                 [% .6f  % .6f  % .6f]\n", m.axes(i, 0), m.axes(i, 1),
                m.axes(i, 2));
  std::printf("misalignment     %+.4f deg (least-inertia axis from the long axis, "
              "counter-clockwise seen from above)\n",
              m.misalignment_deg);
  if (model.contact.model == sim::ContactModel::Rolling)
    std::printf("contact          rolling: no contact spring, so no step limit from the floor\n");
  else if (model.contact.model == sim::ContactModel::Auto && sim::isAdaptive(model.integrator))
    std::printf("contact          auto: rolls while the floor can give the force rolling needs, "
                "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g); the "
                "adaptive integrator chooses its steps\n",
                stability.omega, stability.zeta);
  else if (model.contact.model == sim::ContactModel::Auto)
    std::printf("contact          auto: rolls while the floor can give the force rolling needs, "
                "else slides (smooth: stiffest mode %.4g rad/s, damping ratio %.3g) in steps of "
                "%.3g s within each step\n",
                stability.omega, stability.zeta, std::min(sim::smoothStep(model), model.dt));
  else if (sim::isAdaptive(model.integrator))
    std::printf("contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); the "
                "adaptive integrator chooses its steps\n",
                stability.omega, stability.zeta);
  else
    std::printf("contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); "
                "largest stable dt %.3g s with %s (the scene's integrator)\n",
                stability.omega, stability.zeta, stability.largest_step,
                std::string(rb::nameOf(model.integrator)).c_str());
}

}  // namespace

int analyzeCommand(const AnalyzeArgs& args) {
  auto loaded = loadScene(args.scene, {});
  if (!loaded) {
    std::cerr << loaded.error().text() << "\n";
    return kBadInput;
  }
  const sim::Model& model = loaded->model;
  const double spin = spinFor(model, args.spin);
  if (args.json) {
    printJson(model, spin);
  } else {
    printText(args.scene, model);
    printTheory(model, spin);
  }
  return kOk;
}

}  // namespace app

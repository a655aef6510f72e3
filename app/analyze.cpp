#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>
#include <iostream>
#include <sstream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
#include "sim/analysis.hpp"
#include "sim/stability.hpp"

namespace app {
namespace {

std::string jsonVector(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s.precision(10);
  s << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return s.str();
}

std::string jsonMatrix(const Eigen::Matrix3d& m) {
  std::ostringstream s;
  s << "[" << jsonVector(m.row(0)) << ", " << jsonVector(m.row(1)) << ", "
    << jsonVector(m.row(2)) << "]";
  return s.str();
}

double spinFor(const sim::Model& model, const std::optional<double>& spin) {
  if (spin) return *spin;
  return model.initial.spin != 0 ? model.initial.spin : 5.0;
}

void printJson(const sim::Model& model, double spin) {
  const sim::MassProperties& m = model.body.mass_properties;
  const sim::Rest rest = sim::restOf(model);
  const sim::Linearisation at_rest = sim::linearise(model, 0);
  const sim::Linearisation spinning = sim::linearise(model, spin);
  const sim::FirstOrder first = sim::firstOrderGrowth(model);
  const sim::ContactStability stability = sim::contactStability(model);
  const std::size_t top = model.body.top.size();
  const std::size_t bottom = model.body.bottom.size();
  std::printf("{\n");
  std::printf("  \"points\": {\"total\": %lld, \"top\": %zu, \"bottom\": %zu, \"surface\": %zu},\n",
              static_cast<long long>(m.points), top, bottom, top + bottom);
  std::printf("  \"length_unit_m\": %.10g,\n", model.length_unit);
  std::printf("  \"mass\": %.10g,\n", m.mass);
  std::printf("  \"com\": %s,\n", jsonVector(m.com).c_str());
  std::printf("  \"inertia\": %s,\n", jsonMatrix(m.inertia).c_str());
  std::printf("  \"principal_moments\": %s,\n", jsonVector(m.principal).c_str());
  std::printf("  \"principal_axes\": %s,\n", jsonMatrix(m.axes.transpose()).c_str());
  std::printf("  \"misalignment_deg\": %.10g,\n", m.misalignment_deg);
  std::printf("  \"contact\": {\"omega_rad_s\": %.10g, \"damping_ratio\": %.10g, "
              "\"largest_stable_dt_s\": %.10g},\n",
              stability.omega, stability.zeta, stability.largest_step);
  std::printf("  \"h\": %.10g,\n", rest.h);
  std::printf("  \"radii_of_curvature\": [%.10g, %.10g],\n", rest.radii(0), rest.radii(1));
  std::printf("  \"rest_stable\": %s,\n", rest.stable ? "true" : "false");
  std::printf("  \"frequencies_hz\": {\"roll\": %.10g, \"pitch\": %.10g},\n", at_rest.roll_hz,
              at_rest.pitch_hz);
  std::printf("  \"spin\": %.10g,\n", spin);
  std::printf("  \"growth_rates\": {\"roll\": %.10g, \"pitch\": %.10g},\n",
              spinning.roll_growth, spinning.pitch_growth);
  std::printf("  \"first_order_growth_per_spin\": {\"roll\": %.10g, \"pitch\": %.10g},\n",
              first.roll, first.pitch);
  std::printf("  \"eigenvalues\": [");
  for (std::size_t i = 0; i < spinning.eigenvalues.size(); ++i)
    std::printf("%s[%.10g, %.10g]", i ? ", " : "", spinning.eigenvalues[i].real(),
                spinning.eigenvalues[i].imag());
  std::printf("],\n");
  std::printf("  \"preferred\": \"%s\"\n", sim::preferredDirection(model, spin));
  std::printf("}\n");
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
  for (const auto& lambda : l.eigenvalues) std::printf(" %.4g%+.4gi", lambda.real(), lambda.imag());
  std::printf("\n");
  const char* preferred = sim::preferredDirection(model, spin);
  std::printf("preferred        %s (%s seen from above); spun the other way it is predicted to "
              "reverse\n",
              preferred, preferred[0] == 'c' && preferred[1] == 'c' ? "counter-clockwise"
                                                                      : "clockwise");
}

void printText(const std::string& scene, const sim::Model& model) {
  const sim::MassProperties& m = model.body.mass_properties;
  const double unit = model.length_unit;
  const sim::ContactStability stability = sim::contactStability(model);
  const std::size_t top = model.body.top.size();
  const std::size_t bottom = model.body.bottom.size();
  std::printf("scene            %s (lengths below in the file's unit, %g m)\n", scene.c_str(),
              unit);
  std::printf("points           %lld in all, %zu on the surface (%zu top, %zu bottom)\n",
              static_cast<long long>(m.points), top + bottom, top, bottom);
  std::printf("mass             %g kg\n", m.mass);
  const Eigen::Vector3d com = m.com / unit;
  std::printf("centre of mass   (%.6g, %.6g, %.6g) in the shape's frame\n", com.x(), com.y(),
              com.z());
  std::printf("inertia about the CM, geometric axes [kg m^2]\n");
  for (int i = 0; i < 3; ++i)
    std::printf("                 [% .6e  % .6e  % .6e]\n", m.inertia(i, 0), m.inertia(i, 1),
                m.inertia(i, 2));
  std::printf("principal        %.6e  %.6e  %.6e kg m^2, along (columns)\n", m.principal(0),
              m.principal(1), m.principal(2));
  for (int i = 0; i < 3; ++i)
    std::printf("                 [% .6f  % .6f  % .6f]\n", m.axes(i, 0), m.axes(i, 1),
                m.axes(i, 2));
  std::printf("misalignment     %+.4f deg (least-inertia axis from the long axis, "
              "counter-clockwise seen from above)\n",
              m.misalignment_deg);
  std::printf("contact          stiffest mode at rest %.4g rad/s (damping ratio %.3g); "
              "largest stable dt %.3g s\n",
              stability.omega, stability.zeta, stability.largest_step);
}

}  // namespace

int analyzeCommand(const AnalyzeArgs& args) {
  auto compiled = loadScene(args.scene, {});
  if (auto* e = std::get_if<std::string>(&compiled)) {
    std::cerr << *e << "\n";
    return kBadInput;
  }
  const sim::Model& model = std::get<sim::Model>(compiled);
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

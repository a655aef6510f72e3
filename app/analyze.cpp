#include <cstdio>
#include <iostream>
#include <sstream>

#include "app/commands.hpp"
#include "app/scene_args.hpp"
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

void printJson(const sim::Model& model) {
  const sim::MassProperties& m = model.body.mass_properties;
  const sim::ContactStability stability = sim::contactStability(model);
  const std::size_t top = model.body.top_points.size();
  const std::size_t bottom = model.body.bottom_points.size();
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
              "\"largest_stable_dt_s\": %.10g}\n",
              stability.omega, stability.zeta, stability.largest_step);
  std::printf("}\n");
}

void printText(const std::string& scene, const sim::Model& model) {
  const sim::MassProperties& m = model.body.mass_properties;
  const double unit = model.length_unit;
  const sim::ContactStability stability = sim::contactStability(model);
  const std::size_t top = model.body.top_points.size();
  const std::size_t bottom = model.body.bottom_points.size();
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
  if (args.json)
    printJson(model);
  else
    printText(args.scene, model);
  return kOk;
}

}  // namespace app

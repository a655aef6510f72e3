// What a large mesh costs (target: ≤ 1 s for a 1,000,000-triangle binary STL, read,
// welded, checked and its mass properties, whole process): writes a UV sphere of exactly 1e6
// triangles (1000 meridians × 501 bands: two a quad, one a pole cap: 2 × 1000 × 500) as binary STL
// to a temporary file, then times each stage. Usage: rattleback_mesh_bench [FILE.stl]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "scene/mesh_file.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void writeFacet(std::ofstream& out, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                const Eigen::Vector3d& c) {
  float values[12] = {};
  for (int i = 0; i < 3; ++i) {
    values[3 + i] = static_cast<float>(a[i]);
    values[6 + i] = static_cast<float>(b[i]);
    values[9 + i] = static_cast<float>(c[i]);
  }
  out.write(reinterpret_cast<const char*>(values), sizeof values);
  out.write("\0\0", 2);
}

// A sphere of radius 50 (mm): `meridians` around, `bands` from pole to pole, wound outwards.
void writeSphere(const std::string& path, int meridians, int bands) {
  std::ofstream out(path, std::ios::binary);
  out << std::string(80, ' ');
  const auto count = static_cast<std::uint32_t>(2 * meridians * (bands - 1));
  out.write(reinterpret_cast<const char*>(&count), 4);
  const auto at = [&](int band, int m) {
    const double theta = M_PI * band / bands, phi = 2 * M_PI * (m % meridians) / meridians;
    if (band == 0) return Eigen::Vector3d(0, 0, 50);
    if (band == bands) return Eigen::Vector3d(0, 0, -50);
    return Eigen::Vector3d(50 * std::sin(theta) * std::cos(phi),
                           50 * std::sin(theta) * std::sin(phi), 50 * std::cos(theta));
  };
  for (int band = 0; band < bands; ++band)
    for (int m = 0; m < meridians; ++m) {
      if (band > 0) writeFacet(out, at(band, m), at(band + 1, m), at(band, m + 1));
      if (band < bands - 1) writeFacet(out, at(band, m + 1), at(band + 1, m), at(band + 1, m + 1));
    }
}

}  // namespace

int main(int argc, char** argv) {
  // A file given is read as it is, written first when missing (and then kept, so that a second
  // run times the whole process on it: `time rattleback_mesh_bench sphere.stl`).
  const std::string path =
      argc > 1 ? argv[1]
               : (std::filesystem::temp_directory_path() / "rattleback_mesh_bench.stl").string();
  if (!std::filesystem::exists(path)) writeSphere(path, 1000, 501);
  const Clock::time_point start = Clock::now();
  auto mesh = scene::readMesh(path);
  if (!mesh) {
    std::fprintf(stderr, "%s\n", mesh.error().message.c_str());
    return 1;
  }
  const double read_s = secondsSince(start);
  const Clock::time_point checked = Clock::now();
  const auto problem = sim::checkMesh(mesh.value(), path, 0.001);
  const double check_s = secondsSince(checked);
  const Clock::time_point massed = Clock::now();
  const sim::MassProperties m = sim::meshMassProperties(mesh.value(), 0.1);
  const double mass_s = secondsSince(massed);
  std::printf("%zu triangles, %zu vertices: %s\n", mesh->faces.size(), mesh->vertices.size(),
              problem ? problem->message.c_str() : "passes the checks");
  std::printf("read + weld  %.3f s\ncheck        %.3f s\nmass props   %.3f s\n", read_s, check_s,
              mass_s);
  std::printf("all          %.3f s (target 1 s)   Izz %.6g kg mm² (sphere 2/5 m r² = 100)\n",
              secondsSince(start), m.inertia(2, 2));
  if (argc <= 1) std::filesystem::remove(path);
  return 0;
}

// libFuzzer target for the scene loader and compile(): any bytes must give either a model or
// one non-empty line of error — never a crash, a hang, a sanitizer report or a multi-line
// message.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/loader.hpp"

namespace {

// Paraboloid grids are streamed but still cost time per point; the fuzzer skips compiling
// scenes whose grid is bigger than this so that each input stays fast (the limit itself,
// 2e8 points, is checked in the bad-scene battery).
constexpr double kMaxFuzzGridPoints = 2e5;

// The grid's bounding box over its spacing, in doubles (no integer conversions that could
// overflow): an upper estimate of the points compile() would build. Scenes it cannot judge
// (non-finite or not a bowl) are left to compile(), which refuses them before building.
bool tooManyPoints(const sim::SceneSpec& spec) {
  const sim::ParaboloidSpec& p = spec.body.paraboloid;
  const sim::GridSpec& g = spec.body.grid;
  const double height = p.top + p.a;
  const double det = p.p * p.s / (p.a * p.a) - p.q * p.q / (p.a * p.a * p.a * p.a);
  if (!(det > 0) || !(height > 0) || !(g.dx > 0) || !(g.dy > 0) || !(g.dz > 0)) return false;
  const double half_x = std::sqrt(2 * height * (p.s / p.a) / det);
  const double half_y = std::sqrt(2 * height * (p.p / p.a) / det);
  const double points = (2 * half_x / g.dx + 2) * (2 * half_y / g.dy + 2) * (height / g.dz + 2);
  return !(points <= kMaxFuzzGridPoints);
}

void checkMessage(const std::string& message) {
  if (message.empty() || message.find('\n') != std::string::npos) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto loaded = scene::loadString(text, "fuzz.yaml");
  if (!loaded) {
    checkMessage(loaded.error().text());
    return 0;
  }
  const scene::Loaded& scene = loaded.value();
  const sim::BodySpec& b = scene.spec.body;
  if (b.shape == "paraboloid" && tooManyPoints(scene.spec)) return 0;
  auto model = scene::loadModel(scene);
  if (!model) checkMessage(model.error().text());
  return 0;
}

#include "tasks/scene_args.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "sim/compile.hpp"
#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"
#include "util/assets.hpp"
#include "util/format.hpp"

namespace tasks {

std::string findShipped(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty() || fs::exists(path, ec) || fs::path(path).is_absolute()) return path;
  // "./scenes/x.yaml" names this folder's, and only that: a missing scene of a shipped one's
  // name must not run the shipped one.
  if (path.starts_with("./") || path.starts_with("../")) return path;
  const fs::path shipped = fs::path(rb::assetsDir()) / path;
  return fs::is_regular_file(shipped, ec) ? shipped.lexically_normal().string() : path;
}

rb::Result<LoadedScene> loadScene(const std::string& path, const Overrides& o) {
  const std::string file = findShipped(path);
  auto loaded = [&]() -> rb::Result<scene::Loaded> {
    if (o.values.empty()) return scene::loadFile(file);
    auto text = scene::readSceneFile(file);
    if (!text) return text.error();
    return scene::loadWithValues(text.value(), file, o.values, o.option_prefix + "set");
  }();
  if (!loaded) return loaded.error();
  return applyOverrides(std::move(loaded).value(), o);
}

namespace {

// A scene's video.fps is a whole number of frames per second within 1 … kMaxFps. Placed as the
// other options' errors are (the option, no line, the key it sets), so that Python raises
// SceneError for a bad fps as for a bad view or size.
rb::Status checkFps(const Overrides& o) {
  const std::optional<double> fps = o.number(SceneOption::Fps);
  if (!fps) return {};
  const std::string name = o.option_prefix + "fps";
  char text[64];
  std::snprintf(text, sizeof text, "%g", *fps);
  auto refused = [&](const std::string& why) {
    return rb::Error{"", name + ": " + why, rb::Error::Where{name, 0, "video.fps"}};
  };
  if (*fps != std::floor(*fps))  // (NaN too)
    return refused("must be a whole number of frames per second (24, 25, 30, 60 …), not " +
                   std::string(text));
  if (*fps < 1 || *fps > scene::kMaxFps)
    return refused("must be within 1 … " + std::to_string(scene::kMaxFps) + ", not " + text);
  return {};
}

// What no option may be given: a NaN (the scene's "not given", sim::kUnset) where a number must
// be finite, an option and a --set entry for the same key (one command gives each key once, and
// the report lists the entry among the values put in), a step and a tolerance together, and an
// fps that no video has. Each is named as the front end spells the option.
rb::Status checkOverrides(const Overrides& o) {
  for (const auto& [option, value] : o.given) {
    const SceneOptionRow& row = rowOf(option);
    const std::string name = o.option_prefix + row.name;
    if (row.finite && !std::isfinite(value.number))
      return rb::Error{"", name + ": must be a finite number, not " + rb::show(value.number),
                       rb::Error::Where{name, 0, row.key}};
  }
  for (const auto& [option, value] : o.given)
    for (const scene::KeyValue& kv : o.values)
      if (kv.key == rowOf(option).key)
        return rb::Error{"", o.option_prefix + rowOf(option).name + " and " + o.option_prefix +
                                 "set " + kv.key + " set the same key: give one of them"};
  if (o.has(SceneOption::Dt) && o.has(SceneOption::Tolerance))
    return rb::Error{"", o.option_prefix + "dt and " + o.option_prefix +
                             "tolerance: give one, a fixed step or adaptive steps to a tolerance"};
  return checkFps(o);
}

}  // namespace

rb::Result<LoadedScene> applyOverrides(scene::Loaded scene, const Overrides& o) {
  if (auto ok = checkOverrides(o); !ok) return ok.error();
  sim::SceneSpec& spec = scene.spec;
  // A step or a tolerance from the command line replaces whichever of the two the file gives,
  // and an integrator of the other kind gives way to that kind's default (dopri5 for a
  // tolerance, symplectic for a step) unless --integrator names one.
  const bool dt = o.has(SceneOption::Dt), tolerance = o.has(SceneOption::Tolerance);
  if (dt) spec.simulation.tolerance = sim::kUnset;
  if (tolerance) spec.simulation.dt = sim::kUnset;
  if (!o.has(SceneOption::Integrator)) {
    const auto named = rb::parseName<sim::Integrator>(spec.simulation.integrator);
    if (named && ((dt && sim::isAdaptive(*named)) || (tolerance && !sim::isAdaptive(*named))))
      spec.simulation.integrator.clear();
  }
  for (const auto& [option, value] : o.given) {
    const SceneOptionRow& row = rowOf(option);
    row.apply(scene, value);
    scene.overrides[row.key] = (value.prefix.empty() ? o.option_prefix : value.prefix) + row.name;
  }
  auto compiled = scene::loadModel(scene);
  if (!compiled) return compiled.error();
  return LoadedScene{std::move(scene), std::move(compiled).value()};
}

void describeModel(const sim::Model& model, const std::string& scene) {
  const sim::Body& body = *model.body;
  const sim::GridCensus census = sim::censusOf(body);
  std::fprintf(stderr, "%s: %zu bottom and %zu top points, mass %g kg, contact %s", scene.c_str(),
               static_cast<std::size_t>(census.bottom), static_cast<std::size_t>(census.top),
               body.mass, std::string(rb::nameOf(model.contact.model)).c_str());
  if (!sim::heldOnFloor(model.contact.model))
    std::fprintf(stderr, " (k %g N/m, c %g N s/m, mu %g)", model.contact.stiffness,
                 model.contact.damping, model.contact.friction);
  const std::string integrator(rb::nameOf(model.integrator));
  if (sim::isAdaptive(model.integrator))
    std::fprintf(stderr, ", %s tolerance %g, %g s\n", integrator.c_str(), model.tolerance,
                 model.duration);
  else
    std::fprintf(stderr, ", %s dt %g s, %g s\n", integrator.c_str(), model.dt, model.duration);
}

bool parseSize(const std::string& text, std::array<int, 2>& size) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X'))
    return false;
  size = {w, h};
  return true;
}

}  // namespace tasks

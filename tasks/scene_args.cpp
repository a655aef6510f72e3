#include "tasks/scene_args.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <tuple>

#include "sim/compile.hpp"
#include "util/assets.hpp"
#include "util/format.hpp"

namespace tasks {

std::string findShipped(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty() || fs::exists(path, ec) || fs::path(path).is_absolute()) return path;
  // "./scenes/x.yaml" names this folder's, and only that (a CI maintainer's trial: a missing
  // scene of a shipped one's name ran the shipped one, ./ or not).
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

rb::Result<LoadedScene> applyOverrides(scene::Loaded scene, const Overrides& o) {
  sim::SceneSpec& spec = scene.spec;
  // Each override is named as the front end spells it: "--dt" on the command line,
  // "argument dt" in Python.
  auto name = [&](const char* option) { return o.option_prefix + option; };
  auto set = [&](auto& field, const auto& value, const char* key, const char* option) {
    if (!value) return;
    field = *value;
    scene.overrides[key] = name(option);
  };
  // A NaN is the scene's "not given" (sim::kUnset): a NaN --dt read as no step at all ("--dt: or
  // simulation.tolerance is required"). Refused as a scene's non-finite number is, placed as
  // the fps's error is below.
  for (const auto& [value, option, key] :
       {std::tuple{&o.duration, "duration", "simulation.duration"},
        std::tuple{&o.dt, "dt", "simulation.dt"},
        std::tuple{&o.tolerance, "tolerance", "simulation.tolerance"},
        std::tuple{&o.frame, "frame", "video.frame"}})
    if (*value && !std::isfinite(**value))
      return rb::Error{"", name(option) + ": must be a finite number, not " + rb::show(**value),
                       rb::Error::Where{name(option), 0, key}};
  // An option and a --set entry for the same key: the option won, and the report page listed
  // the entry among the values put in beside the option's value ("initial.spin = -4", "spun -3
  // rad/s"; a teacher's trial). One command gives each key once.
  for (const auto& [given, key, option] :
       {std::tuple{bool(o.duration), "simulation.duration", "duration"},
        std::tuple{bool(o.dt), "simulation.dt", "dt"},
        std::tuple{bool(o.tolerance), "simulation.tolerance", "tolerance"},
        std::tuple{bool(o.integrator), "simulation.integrator", "integrator"},
        std::tuple{bool(o.spin), "initial.spin", "spin"},
        std::tuple{bool(o.playback), "video.playback", "playback"},
        std::tuple{bool(o.view), "video.view", "view"},
        std::tuple{bool(o.frame), "video.frame", "frame"},
        std::tuple{bool(o.size), "video.size", "size"},
        std::tuple{bool(o.fps), "video.fps", "fps"}})
    for (const scene::KeyValue& kv : o.values)
      if (given && kv.key == key)
        return rb::Error{"", name(option) + " and " + name("set") + " " + kv.key +
                                 " set the same key: give one of them"};
  set(spec.simulation.duration, o.duration, "simulation.duration", "duration");
  if (o.dt && o.tolerance)
    return rb::Error{"", name("dt") + " and " + name("tolerance") +
                             ": give one, a fixed step or adaptive steps to a tolerance"};
  // A step or a tolerance from the command line replaces whichever of the two the file gives.
  if (o.dt) spec.simulation.tolerance = sim::kUnset;
  if (o.tolerance) spec.simulation.dt = sim::kUnset;
  // …and an integrator of the other kind gives way to that kind's default (dopri5 for a
  // tolerance, symplectic for a step) unless --integrator names one.
  if (!o.integrator) {
    const auto named = rb::parseName<sim::Integrator>(spec.simulation.integrator);
    if (named && ((o.dt && sim::isAdaptive(*named)) || (o.tolerance && !sim::isAdaptive(*named))))
      spec.simulation.integrator.clear();
  }
  set(spec.simulation.dt, o.dt, "simulation.dt", "dt");
  set(spec.simulation.tolerance, o.tolerance, "simulation.tolerance", "tolerance");
  set(spec.simulation.integrator, o.integrator, "simulation.integrator", "integrator");
  set(spec.initial.spin, o.spin, "initial.spin", "spin");
  set(scene.video.playback, o.playback, "video.playback", "playback");
  set(scene.video.view, o.view, "video.view", "view");
  set(scene.video.frame, o.frame, "video.frame", "frame");
  set(scene.video.size, o.size, "video.size", "size");
  if (o.fps) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", *o.fps);
    // Placed as the other overrides' errors are (the option, no line, the key it sets), so that
    // Python raises SceneError for a bad fps as for a bad view or size.
    auto refused = [&](const std::string& why) {
      return rb::Error{"", name("fps") + ": " + why, rb::Error::Where{name("fps"), 0, "video.fps"}};
    };
    if (*o.fps != std::floor(*o.fps))  // (NaN too)
      return refused("must be a whole number of frames per second (24, 25, 30, 60 …), not " +
                     std::string(text));
    if (*o.fps < 1 || *o.fps > scene::kMaxFps)
      return refused("must be within 1 … " + std::to_string(scene::kMaxFps) + ", not " + text);
    scene.video.fps = static_cast<int>(*o.fps);
    scene.overrides["video.fps"] = name("fps");
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
  if (model.contact.model != sim::ContactModel::Rolling)
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

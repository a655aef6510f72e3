#include "app/scene_args.hpp"

#include <cstdio>

#include "scene/loader.hpp"

namespace app {

std::variant<sim::Model, std::string> loadScene(const std::string& path, const Overrides& o) {
  auto loaded = scene::loadFile(path);
  if (auto* e = std::get_if<scene::LoadError>(&loaded)) return e->message;
  scene::Loaded& scene = std::get<scene::Loaded>(loaded);
  sim::SceneSpec& spec = scene.spec;
  auto set = [&](auto& field, const auto& value, const char* key, const char* option) {
    if (!value) return;
    field = *value;
    scene.overrides[key] = option;
  };
  set(spec.simulation.duration, o.duration, "simulation.duration", "--duration");
  set(spec.simulation.dt, o.dt, "simulation.dt", "--dt");
  set(spec.simulation.integrator, o.integrator, "simulation.integrator", "--integrator");
  set(spec.initial.spin, o.spin, "initial.spin", "--spin");
  set(spec.video.playback, o.playback, "video.playback", "--playback");
  set(spec.video.view, o.view, "video.view", "--view");
  set(spec.video.size, o.size, "video.size", "--size");
  set(spec.video.fps, o.fps, "video.fps", "--fps");
  auto compiled = scene::loadModel(scene);
  if (auto* e = std::get_if<scene::LoadError>(&compiled)) return e->message;
  return std::move(std::get<sim::Model>(compiled));
}

void describeModel(const sim::Model& model, const std::string& scene, std::int64_t every,
                   const char* what) {
  const char* contact[] = {"points", "smooth", "rolling"};
  const char* integrator[] = {"euler", "symplectic", "rk4"};
  std::fprintf(stderr, "%s: %zu bottom and %zu top points, mass %g kg, contact %s", scene.c_str(),
               model.body.bottom.size(), model.body.top.size(), model.body.mass,
               contact[static_cast<int>(model.contact.model)]);
  if (model.contact.model != sim::ContactModel::Rolling)
    std::fprintf(stderr, " (k %g N/m, c %g N s/m, mu %g)", model.contact.stiffness,
                 model.contact.damping, model.contact.friction);
  std::fprintf(stderr, ", %s dt %g s, %lld steps, a %s every %lld steps\n",
               integrator[static_cast<int>(model.integrator)], model.dt,
               static_cast<long long>(model.steps), what, static_cast<long long>(every));
}

bool parseSize(const std::string& text, std::array<int, 2>& size) {
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X'))
    return false;
  size = {w, h};
  return true;
}

}  // namespace app

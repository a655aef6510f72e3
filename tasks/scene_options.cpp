#include "tasks/scene_options.hpp"

namespace tasks {
namespace {

using O = SceneOption;
using K = OptionKind;

using L = scene::Loaded;
using V = OptionValue;

constexpr SceneOptionRow kOptions[] = {
    {O::Duration, "duration", "simulation.duration", K::Number,
     "Simulated time, s (overrides the scene)", true,
     [](L& s, const V& v) { s.spec.simulation.duration = v.number; }},
    {O::Dt, "dt", "simulation.dt", K::Number,
     "Fixed time step, s (overrides the scene's dt or tolerance)", true,
     [](L& s, const V& v) { s.spec.simulation.dt = v.number; }},
    {O::Tolerance, "tolerance", "simulation.tolerance", K::Number,
     "Adaptive steps (dopri5) to this error per step (overrides the scene's dt or tolerance)", true,
     [](L& s, const V& v) { s.spec.simulation.tolerance = v.number; }},
    {O::Integrator, "integrator", "simulation.integrator", K::Name, "The integrator", false,
     [](L& s, const V& v) { s.spec.simulation.integrator = v.name; }},
    {O::Spin, "spin", "initial.spin", K::Number, "Initial spin, rad/s (overrides the scene)", true,
     [](L& s, const V& v) { s.spec.initial.spin = v.number; }},
    {O::Playback, "playback", "video.playback", K::Number,
     "Playback speed: simulated seconds per video second (0.5 = slow motion)", false,
     [](L& s, const V& v) { s.video.playback = v.number; }},
    {O::View, "view", "video.view", K::Name, "The camera's view", false,
     [](L& s, const V& v) { s.video.view = v.name; }},
    {O::Frame, "frame", "video.frame", K::Number,
     "Frame every view for a body this long, in the scene's length unit (default: the body's "
     "own); bodies drawn with the same --frame are drawn at one scale",
     true, [](L& s, const V& v) { s.video.frame = v.number; }},
    {O::Size, "size", "video.size", K::Size, "Frame size WxH, e.g. 1280x720", false,
     [](L& s, const V& v) { s.video.size = v.size; }},
    // Whole and within range: checked before it is put in (tasks::applyOverrides).
    {O::Fps, "fps", "video.fps", K::Number,
     "Frames per second, a whole number 1–240 (default: the scene's video.fps, or 30)", false,
     [](L& s, const V& v) { s.video.fps = static_cast<int>(v.number); }},
    {O::Surface, "surface", "video.surface", K::Name,
     "The body drawn as its surface points or as shaded triangles (red facing up, blue down)",
     false, [](L& s, const V& v) { s.video.surface = v.name; }},
};

}  // namespace

std::span<const SceneOptionRow> sceneOptions() {
  return kOptions;
}

const SceneOptionRow& rowOf(SceneOption option) {
  for (const SceneOptionRow& row : kOptions)
    if (row.option == option) return row;
  return kOptions[0];  // (every option has its row: SceneOptions tests look up each)
}

std::optional<double> Overrides::number(SceneOption o) const {
  const auto it = given.find(o);
  if (it == given.end()) return std::nullopt;
  return it->second.number;
}

}  // namespace tasks

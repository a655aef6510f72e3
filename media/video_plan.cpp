#include "media/video_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "sim/initial.hpp"
#include "tasks/analysis.hpp"
#include "util/format.hpp"

namespace media {
namespace {

using rb::show;

rb::Result<VideoPlan> check(const scene::VideoSpec& v, const sim::Model& model, double duration) {
  if (v.fps < 1 || v.fps > kMaxFps)
    return rb::Error{"video.fps", "must be within 1 … " + std::to_string(kMaxFps) + ", not " +
                                      std::to_string(v.fps)};
  for (int side : v.size) {
    if (side < 16 || side > 8192)
      return rb::Error{"video.size",
                       "sides must be within 16 … 8192 pixels, not " + std::to_string(side)};
  }
  const auto [w, h] = std::pair{v.size[0], v.size[1]};
  if (w % 2 || h % 2)  // both sides in one message, so one retry fixes both
    return rb::Error{"video.size",
                     "sides must be even (H.264 video in yuv420p, and stills by the same rule), "
                     "not " +
                         std::to_string(w) + "x" + std::to_string(h) + ": try " +
                         std::to_string(w + w % 2) + "x" + std::to_string(h + h % 2)};
  const auto view = rb::parseName<render::View>(v.view);
  if (!view)
    return rb::Error{"video.view",
                     "must be " + rb::choices<render::View>() + ", not '" + v.view + "'"};
  const auto surface = rb::parseName<render::Surface>(v.surface);
  if (!surface)
    return rb::Error{"video.surface",
                     "must be " + rb::choices<render::Surface>() + ", not '" + v.surface + "'"};
  const std::string speeds =
      " (1 real time, 0.5 slow motion, 2 twice as fast), not " + show(v.playback);
  if (!(v.playback > 0))  // and NaN
    return rb::Error{"video.playback", "must be a speed > 0" + speeds};
  if (!(v.playback <= 1e6))  // and infinity
    return rb::Error{"video.playback", "must be a speed of at most " + show(1e6) + speeds};
  VideoPlan plan;
  if (!std::isnan(v.frame)) {  // given: a length of body, in the file's unit
    const double unit = model.length_unit;
    const double length = tasks::bodySize(*model.body).x();  // m
    char body[32];
    std::snprintf(body, sizeof body, "%.3g", length / unit);
    const std::string way = ": the body is " + std::string(body) + " long in the file's unit (" +
                            (unit == 1 ? std::string("m") : show(unit) + " m, units.length") + ")";
    if (!(v.frame > 0) || !std::isfinite(v.frame))
      return rb::Error{"video.frame", "must be a length > 0, not " + show(v.frame) + way};
    if (!tasks::frameFits(v.frame * unit, *model.body))
      return rb::Error{"video.frame", "must be within 1/10 … 50 times the body's length, not " +
                                          show(v.frame) + way};
    plan.frame = v.frame * unit;
  }
  plan.fps = v.fps;
  plan.width = v.size[0];
  plan.height = v.size[1];
  plan.view = *view;
  plan.surface = *surface;
  plan.playback = v.playback;
  const double frames = std::round(duration / v.playback * v.fps);
  if (frames > 1e7)
    return rb::Error{"video.playback",
                     "makes more than 10 million frames of " + show(duration) +
                         " s of simulated time (at playback " + show(v.playback) + " and " +
                         std::to_string(v.fps) +
                         " fps): shorten the run (--duration) or speed up the playback"};
  plan.frames = std::max<std::int64_t>(1, static_cast<std::int64_t>(frames));
  return plan;
}

}  // namespace

rb::Result<VideoPlan> planVideo(const scene::Loaded& scene, const sim::Model& model,
                                double duration) {
  auto plan = check(scene.video, model, duration);
  if (!plan) {
    rb::Error error = plan.error();
    // Too many frames because --duration asked for a long run: that option is named.
    if (error.key == "video.playback" && scene.overrides.count("simulation.duration") &&
        !scene.overrides.count("video.playback"))
      error.key = "simulation.duration";
    return scene::locate(scene, error);  // one line, and where it is for Python's SceneError
  }
  return plan;
}

std::string frameNamed(const scene::Loaded& scene) {
  // (--set and with_values name the key themselves: "--set video.frame=10".)
  const auto option = scene.overrides.find("video.frame");
  return option == scene.overrides.end() || option->second.find("video.frame") != std::string::npos
             ? "video.frame"
             : option->second;
}

namespace {

std::string describeSpin(double spin) {
  char text[64];
  std::snprintf(text, sizeof text, "%+g rad/s, %s", spin,
                spin > 0   ? "counter-clockwise"
                : spin < 0 ? "clockwise"
                           : "no spin");
  return text;
}

// A start with ω about body x or y (a tap): "struck at ω = [3, 0, 0] rad/s (body axes)".
std::string describeStrike(const sim::Initial& initial) {
  char text[96];
  std::snprintf(text, sizeof text, "struck at ω = [%g, %g, %g] rad/s (body axes)", initial.w_x,
                initial.w_y, initial.spin);
  return text;
}

// The inset's ± spin axis, rad/s: 1.1 × the spin (at least 1); struck, the most spin the
// start's kinetic energy could become (sim::spinReach), which a tap's spin-up stays below,
// rounded up to half a rad/s for its label ("n ±2 rad/s").
double spinRange(const sim::Model& run) {
  if (run.initial.w_x == 0 && run.initial.w_y == 0)
    return std::max(1.0, 1.1 * std::abs(run.initial.spin));
  return std::max(1.0, std::ceil(2 * 1.1 * sim::spinReach(run)) / 2);
}

// A --both half's title said shorter, for a half too narrow for the whole: the values put in
// left out, then "its", "spun" and the scene's name ("-8 rad/s, against preferred way").
std::vector<std::string> shorterTitles(const std::string& name, double spin,
                                       const std::string& way) {
  std::string short_way = way;
  if (const std::size_t its = short_way.find("its "); its != std::string::npos)
    short_way.erase(its, 4);
  char rate[48];
  std::snprintf(rate, sizeof rate, "%+g rad/s, ", spin);
  return {name + ": spun " + rate + short_way, name + ": " + rate + short_way, rate + short_way};
}

}  // namespace

// The title of a run's frames, the same in its video and its stills: the scene and the spin.
render::RenderSettings settingsOf(const VideoPlan& plan, const sim::Model& run,
                                  const std::string& scene,
                                  const std::vector<scene::KeyValue>& values,
                                  render::Backend backend,
                                  const std::optional<std::string>& given_title,
                                  const std::string& way) {
  // The values put in name the variant: a class's bodies made with --set all read "mine: spun −5
  // rad/s". The renderer shortens a title too long for the frame.
  const bool struck = run.initial.w_x != 0 || run.initial.w_y != 0;
  std::string start =
      struck ? describeStrike(run.initial) : "spun " + describeSpin(run.initial.spin);
  if (!way.empty()) {
    // "spun -5 rad/s, against its preferred way": --both's text is drawn larger, and a title
    // saying both the sense and the way ran past a 1280-wide half; the read-out says the sense.
    char spun[48];
    std::snprintf(spun, sizeof spun, "spun %+g rad/s", run.initial.spin);
    start = (struck ? describeStrike(run.initial) : std::string(spun)) + ", " + way;
  }
  const std::string name =
      given_title ? *given_title : std::filesystem::path(scene).stem().string();
  std::string title = name + ": " + start;
  if (!given_title)
    for (const scene::KeyValue& kv : values)
      title += (&kv == &values.front() ? "; " : ", ") + kv.key + " = " + kv.yaml;
  render::RenderSettings s;
  if (!way.empty() && !struck) s.shorter_titles = shorterTitles(name, run.initial.spin, way);
  s.backend = backend;
  s.width = plan.width;
  s.height = plan.height;
  s.view = plan.view;
  s.title = title;
  s.duration = run.duration;
  s.spin_range = spinRange(run);
  s.frame = static_cast<float>(plan.frame);
  s.surface = plan.surface;
  return s;
}

}  // namespace media

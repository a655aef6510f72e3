// What the drawing commands (render, still) make of a scene's `video` section: checked here,
// never by the simulation. Frame k shows the simulated time t_k = k · playback / fps exactly
// (playback is the speed as players mean it: 0.5 = slow motion), whatever the step.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "render/frame.hpp"
#include "scene/loader.hpp"
#include "sim/model.hpp"
#include "util/result.hpp"

namespace media {

using scene::kMaxFps;

struct VideoPlan {
  int fps = 30;                    ///< frames per second of video
  int width = 1280, height = 720;  ///< pixels, even (H.264 in yuv420p halves the chroma)
  render::View view = render::View::Oblique;
  double playback = 1;      ///< simulated seconds per second of video
  std::int64_t frames = 0;  ///< round(duration / playback · fps), at least 1
  /// The length of body the views are framed for, m; 0: the body's own (video.frame).
  double frame = 0;
  render::Surface surface = render::Surface::Points;  ///< the body's points or its triangles

  /// Simulated time shown by frame k, s.
  double frameTime(std::int64_t k) const { return static_cast<double>(k) * playback / fps; }
};

/// Checks the video section (fps 1 … 240, even sizes 16 … 8192, a known view, playback > 0, a
/// frame for a body within 1/10 … 50 times `model`'s length) for a run of `duration` simulated
/// seconds; an error is one line naming file, line and key (or the option that set it).
rb::Result<VideoPlan> planVideo(const scene::Loaded& scene, const sim::Model& model,
                                double duration);

/// video.frame as the user gave it: the key, or the option that set it ("--frame", "argument
/// frame").
std::string frameNamed(const scene::Loaded& scene);

/// The renderer's settings for the frames of `run` (its duration and initial state): the plan's
/// size and view, titled with the scene's name, the values put in over its file (--set,
/// with_values) and the spin or the angular velocity it starts with (the same in its video and
/// its stills). A `title` given replaces the scene's name and values (a snapshot case's name: its
/// golden then does not depend on the scene file's path); the start is said after it all the
/// same. A `way` ("against its preferred way": --both's halves) is said after the spin, in place
/// of its sense of turning, which the read-out under the title says.
render::RenderSettings settingsOf(const VideoPlan& plan, const sim::Model& run,
                                  const std::string& scene,
                                  const std::vector<scene::KeyValue>& values,
                                  render::Backend backend,
                                  const std::optional<std::string>& title = std::nullopt,
                                  const std::string& way = "");

}  // namespace media

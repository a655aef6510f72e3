// One frame of a scene's run at a time t, as an image: what `still` writes as PNG and Python's
// still() returns as an array.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "render/frame.hpp"
#include "render/image_io.hpp"
#include "tasks/outcome.hpp"
#include "tasks/scene_args.hpp"
#include "tasks/still_time.hpp"
#include "util/result.hpp"

namespace media {

struct StillRequest {
  std::string scene_name;  ///< the scene's path or name: its stem titles the frame
  double t = 0;            ///< s; past the scene's duration the run goes on to it
  /// A moment of the run instead of `t` (still --t reversal): found by running the scene first.
  std::optional<tasks::NamedTime> t_name;
  /// The frame's title instead of the scene's stem and its values (a snapshot case's name, so
  /// that its golden does not depend on where the scene file is); the spin is still said.
  std::optional<std::string> title;
  std::string t_named = "--t";  ///< t as messages name it: the option, "argument t" in Python
  /// The caller has no duration argument (a snapshot case): a run too short to reach the time
  /// named is lengthened by the scene's simulation.duration alone.
  bool scene_duration_only = false;
  bool readouts = true;      ///< title, read-outs and the spin inset
  bool transparent = false;  ///< alpha: no floor, no background, no read-outs
  render::Backend backend = render::Backend::Auto;
  /// What an OpenGL fault's line begins with: the command, or a snapshot case's place and name.
  std::string asked_by = "still";
  std::function<bool()> cancelled;  ///< asked as the run goes: true stops (may be empty)
  /// Called as the runs go (the one to t, then the framing's over the whole run), with the
  /// thousandths done and 1000 (may be empty).
  std::function<void(std::int64_t, std::int64_t)> progress;
};

struct StillResult {
  render::Image image;     ///< RGBA; empty unless outcome.ending is Completed
  tasks::Outcome outcome;  ///< outcome.t: the time drawn (a named time resolved)
  std::string opengl;      ///< the OpenGL in use
  render::View view = render::View::Oblique;
  /// Where the body goes out of the frame asked for (video.frame): what to say (leavesNote).
  std::optional<std::string> leaves;
};

/// Draws the scene's run at request.t with the scene's (or overridden) video settings.
rb::Result<StillResult> renderStill(const tasks::LoadedScene& loaded, const StillRequest& request);

}  // namespace media

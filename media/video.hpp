// Videos of a scene's runs: frames at exact times drawn on a thread of their own and encoded to
// MP4, one encoding thread per output behind a bounded queue (about 48 MB), so that no run
// holds its frames in memory. The threads are started and joined within renderVideo().
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "render/frame.hpp"
#include "sim/model.hpp"
#include "tasks/manifest.hpp"
#include "tasks/outcome.hpp"
#include "tasks/scene_args.hpp"
#include "util/output_place.hpp"
#include "util/result.hpp"

namespace media {

/// What to make of a loaded scene.
struct VideoRequest {
  std::string scene_name;  ///< the scene's path or name: its stem titles the frames
  /// The .mp4 path; with `both`, the base of BASE-preferred.mp4, BASE-reversed.mp4 and
  /// BASE-both.mp4 (any .mp4 dropped).
  std::string output;
  bool both = false;  ///< also the opposite spin, and the two side by side
  int crf = 20;       ///< x264 quality 1 … 51
  std::string preset = "veryfast";
  render::Backend backend = render::Backend::Auto;
  std::function<bool()> cancelled;  ///< asked before each frame: true stops (may be empty)
  /// Called after each frame with the frames done and the total (may be empty).
  std::function<void(std::int64_t, std::int64_t)> progress;
};

/// One video written.
struct VideoFile {
  std::string path;
  std::string role;  ///< single, or with `both`: preferred, reversed, both
  std::int64_t frames = 0;
  std::optional<double> spin;              ///< rad/s: the run it shows (none: side by side)
  std::optional<double> first_reversal_s;  ///< of that run
  std::vector<double> reversals_s;         ///< of that run: every reversal the rule counted, s
  std::optional<double> final_spin;        ///< of that run: n at its end, rad/s
};

struct VideoResult {
  std::vector<VideoFile> files;  ///< empty unless outcome.ending is Completed
  tasks::Outcome outcome;        ///< a stopped or interrupted run writes no video
  std::int64_t frames = 0;       ///< frames drawn per run
  double wall_s = 0;             ///< drawing and encoding, s
  std::string opengl;            ///< the OpenGL in use
  /// Where a run disagrees with the predicted preferred direction (with `both`).
  std::vector<std::string> notes;
  /// Where the body goes out of the frame asked for (video.frame): what to say (leavesNote).
  std::optional<std::string> leaves;
  /// With `both`, the initial spin of the run that stopped (none wrote a video).
  std::optional<double> stopped_spin;
};

/// crf within 1 … 51 and a known preset; one line naming the option otherwise.
rb::Status checkEncoderOptions(int crf, const std::string& preset);
/// An output name whose extension says another format than the one written is refused.
using rb::checkExtension;
/// Loads the OpenGL driver behind `backend` on a thread of its own (about 40 ms with
/// llvmpipe), while the caller loads its scene.
std::jthread preloadDriver(render::Backend backend);

/// One half of --both's side-by-side video: its run's initial spin, rad/s, and the way its title
/// says it turns for the body ("against its preferred way", "its preferred way"; "" for a body
/// with no preferred direction).
struct BothHalf {
  double spin = 0;
  std::string way;
};
/// --both's halves, left first: the spin against the body's preferred direction (the one the
/// linearised theory says reverses: sim::preferredDirection), then the preferred one, whichever
/// the scene spins; a body with no preferred direction has the scene's spin on the left.
std::array<BothHalf, 2> bothHalves(const sim::Model& model);

/// A video's title with its playback speed after the scene's name ("mine, at 0.5× speed: spun
/// …"), where it is not 1: the frames' clock is the run's, and a reversal at 0.83 s shown at
/// half speed is seen at 1.66 s. Said first, so that a title too long for the frame loses its
/// end, not the speed. Stills have no speed and keep their title.
std::string titleWithPlayback(const std::string& title, double playback);

/// The scene's video(s) as the request says. An error (a bad video section, an encoder or
/// renderer that fails) is one line; a run that stops or is cancelled is an outcome, with no
/// video written and no temporary file left.
rb::Result<VideoResult> renderVideo(const tasks::LoadedScene& loaded, const VideoRequest& request);

/// The manifest's entry for a video of `loaded` (its scene named `scene_name`): what the report
/// captions it with. Every front end that renders records its videos through this.
tasks::OutputEntry videoEntry(const VideoFile& file, const tasks::LoadedScene& loaded,
                              const std::string& scene_name);

}  // namespace media

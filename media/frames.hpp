// From the simulation's model and samples to the renderer's inputs.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/frame.hpp"
#include "sim/model.hpp"
#include "sim/telemetry.hpp"
#include "tasks/scene_args.hpp"
#include "util/result.hpp"

namespace media {

/// The surface points to draw, thinned to about 2500 on fine grids (see frames.cpp).
render::BodyPoints bodyPointsOf(const sim::Model& model);
render::FrameInput frameOf(const sim::Telemetry& t);

/// The triangles to draw when `surface` asks for them (none otherwise): the scene's body as
/// `export` makes it at its default resolution (tasks::bodyMesh), moved to the body frame about
/// the CM, as the points are.
rb::Result<render::BodyTriangles> bodyTrianglesOf(const tasks::LoadedScene& loaded,
                                                  render::Surface surface);

/// What the fixed views keep in frame over a run: a sphere around the centre of mass at the
/// start that holds every drawn point in any orientation, with a quarter more for the body's
/// wander as it rocks and rolls. `frame` (m, video.frame; 0 for none) frames a body that long
/// instead, whatever this one's length: bodies drawn with the same frame are drawn at one scale.
render::Framing framingOf(const sim::Telemetry& start, const render::BodyPoints& points,
                          float frame = 0);

/// A run's framing, and whether the body goes out of it (only where a frame was asked for: the
/// body's own framing holds it).
struct RunFraming {
  render::Framing framing;
  bool body_leaves = false;
  float needs = 0;  ///< m: the length of frame that would hold the body over the run
  /// The run's spin reversals (docs/physics.md P7), s: found by the same pass, so that each
  /// frame can mark a reversal when it comes (the video's own run counts one only 0.2 s on).
  std::vector<double> reversals;
};

/// The same for a whole run, known before a frame is drawn (with the run's reversals): where the
/// centre of mass wanders further than that quarter (a body sliding on a slippery floor), the
/// sphere holds the path of the body over the run instead (a body spun −50 rad/s on friction 0.02
/// slid 10 cm, off the frame of the fixed views); with a `frame`, the sphere keeps its size and is
/// centred on the path. Runs `model` to its end, sampling every 10 ms, or until `cancelled` (when
/// given) says to stop; `reached` (when given) hears each sample's time.
RunFraming framingOfRun(const sim::Model& model, const render::BodyPoints& points, float frame,
                        const std::function<bool()>& cancelled = {},
                        const std::function<void(double)>& reached = {});

/// What a still or video says where the body goes out of the frame asked for (video.frame,
/// `frame` in the file's unit), in `view`: the length of frame that holds it, in the file's unit.
/// `named` is the frame as given: "video.frame", or the option that set it ("--frame").
std::optional<std::string> leavesNote(const RunFraming& framing, const render::BodyPoints& points,
                                      render::View view, float frame, double length_unit,
                                      const std::string& named);

}  // namespace media

// From the simulation's model and samples to the renderer's inputs.
#pragma once

#include <functional>

#include "render/frame.hpp"
#include "sim/model.hpp"
#include "sim/telemetry.hpp"

namespace media {

/// The surface points to draw, thinned to about 2500 on fine grids (see frames.cpp).
render::BodyPoints bodyPointsOf(const sim::Model& model);
render::FrameInput frameOf(const sim::Telemetry& t);

/// What the fixed views keep in frame over a run: a sphere around the centre of mass at the
/// start that holds every drawn point in any orientation, with a quarter more for the body's
/// wander as it rocks and rolls.
render::Framing framingOf(const sim::Telemetry& start, const render::BodyPoints& points);

/// The same for a whole run, known before a frame is drawn: where the centre of mass wanders
/// further than that quarter (a body sliding on a slippery floor), the sphere holds the path of
/// the body over the run instead (issue 26: a body spun −50 rad/s on friction 0.02 slid 10 cm,
/// off the frame of the fixed views). Runs `model` to its end, sampling every 10 ms, or until
/// `cancelled` (when given) says to stop; `reached` (when given) hears each sample's time.
render::Framing framingOfRun(const sim::Model& model, const render::BodyPoints& points,
                             const std::function<bool()>& cancelled = {},
                             const std::function<void(double)>& reached = {});

}  // namespace media

// From the simulation's model and samples to the renderer's inputs.
#pragma once

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

}  // namespace media

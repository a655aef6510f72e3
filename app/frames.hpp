// From the simulation's model and samples to the renderer's inputs.
#pragma once

#include "render/frame.hpp"
#include "sim/model.hpp"
#include "sim/telemetry.hpp"

namespace app {

/// The surface points to draw, thinned to about 2500 on fine grids (see frames.cpp).
render::BodyPoints bodyPointsOf(const sim::Model& model);
render::FrameInput frameOf(const sim::Telemetry& t);

}  // namespace app

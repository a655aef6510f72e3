// The initial state (docs/physics.md P5).
#pragma once

#include "sim/model.hpp"

namespace sim {

/// R = Rx(tilt_x)·Ry(tilt_y); ω = spin × body z axis; the CM at the height where the floor
/// carries the weight (static penetration); the CM velocity v = −ω × r_low so that the lowest
/// point does not slide.
State initialState(const Model& model);

/// CM height (m) at which the floor's spring force on the body in orientation R balances
/// its weight.
double restingHeight(const Model& model, const Eigen::Matrix3d& R);

}  // namespace sim

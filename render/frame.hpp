// What the renderer is given for one video frame: a pose and body-frame points, plus the
// read-outs to print. It includes nothing of the simulation. The renderer itself comes with
// the rendering issue; this header is the contract between the two halves.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <vector>

namespace render {

struct FrameInput {
  Eigen::Vector3d position_world;     ///< body origin, m
  Eigen::Quaterniond orientation;     ///< body → world
  double t = 0;                       ///< s
  double spin = 0;                    ///< rad/s
};

struct BodyPoints {
  std::vector<Eigen::Vector3f> top;     ///< body frame, m (drawn red)
  std::vector<Eigen::Vector3f> bottom;  ///< body frame, m (drawn blue)
};

}  // namespace render

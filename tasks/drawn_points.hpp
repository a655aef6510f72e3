// The body's points as they are drawn (the renderer's, the report's player): the surface grid
// thinned to about 2,500 points, top and bottom apart, in the body frame about the centre of
// mass. Plain values, no drawing library: media/ hands them to render/, the report to the page.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/model.hpp"

namespace tasks {

struct DrawnPoints {
  std::vector<Eigen::Vector3f> top;              ///< body frame about the CM, m (drawn red)
  std::vector<Eigen::Vector3f> bottom;           ///< body frame about the CM, m (drawn blue)
  float spacing = 0.003f;                        ///< between neighbouring points, m
  float radius = 0.001f;                         ///< of each drawn sphere, m
  Eigen::Vector2f footprint_half{0.01f, 0.05f};  ///< outline half extents along x and y, m
};

/// The points to draw, thinned to about 2500 on fine grids.
DrawnPoints drawnPointsOf(const sim::Model& model);

/// The largest distance of a drawn sphere's edge from the CM, m: the body fits in a sphere of
/// this radius in any orientation.
float reachOf(const DrawnPoints& points);

}  // namespace tasks

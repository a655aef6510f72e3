// Cameras for the views of the seed's figures 2–5 (oblique, above, front, side) and one that
// follows the body.
#pragma once

#include <Eigen/Dense>

#include "render/frame.hpp"

namespace render {

struct Camera {
  Eigen::Matrix4f view = Eigen::Matrix4f::Identity();
  Eigen::Matrix4f proj = Eigen::Matrix4f::Identity();
  Eigen::Vector3f eye = Eigen::Vector3f::Zero();  ///< world, m
};

/// Frames a body of half extents `half` (x across, y along, z up; m) whose middle is at
/// `target` (world, m). Above, front and side are orthographic, like the seed's figures;
/// oblique and follow are perspective.
Camera cameraFor(View view, const Eigen::Vector3f& target, const Eigen::Vector3f& half,
                 float aspect);

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fov_y, float aspect, float near, float far);
Eigen::Matrix4f orthographic(float half_w, float half_h, float near, float far);

}  // namespace render

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
  /// Front and side (orthographic, 10° down): the floor has no horizon of its own, so it fades
  /// into the background by depth behind the target, along `depth_direction` (horizontal,
  /// away from the camera): its checker from `fog_near` (m), its colour by `fog_far`, which
  /// lies below the top of the frame. fog_far 0: the other views' fade with distance.
  Eigen::Vector2f depth_direction = Eigen::Vector2f::Zero();
  float fog_near = 0, fog_far = 0;
};

/// The fixed views: they keep `framing`'s sphere in the frame with a margin, whatever the
/// body's turn (above, front and side are orthographic, like the seed's figures; oblique is
/// perspective). `half_height` is the body's half height (m), for front and side.
Camera fixedCamera(View view, const Framing& framing, float half_height, float aspect);

/// The follow view: a chase camera beside the body, looking across its long axis (`heading`,
/// horizontal, world) at `middle` from 25° above, turning and moving with it; `radius` is the
/// body's own (m).
Camera chaseCamera(const Eigen::Vector3f& middle, const Eigen::Vector2f& heading, float radius,
                   float aspect);

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up);
Eigen::Matrix4f perspective(float fov_y, float aspect, float near, float far);
Eigen::Matrix4f orthographic(float half_w, float half_h, float near, float far);

}  // namespace render

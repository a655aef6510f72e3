#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

namespace render {
namespace {
const float kElevation = 10.0f * static_cast<float>(M_PI) / 180;
}  // namespace

Eigen::Matrix4f lookAt(const Eigen::Vector3f& eye, const Eigen::Vector3f& target,
                       const Eigen::Vector3f& up) {
  const Eigen::Vector3f f = (target - eye).normalized();
  const Eigen::Vector3f s = f.cross(up).normalized();
  const Eigen::Vector3f u = s.cross(f);
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4f perspective(float fov_y, float aspect, float near, float far) {
  const float f = 1.0f / std::tan(fov_y / 2);
  Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2 * far * near / (near - far);
  m(3, 2) = -1;
  return m;
}

Eigen::Matrix4f orthographic(float half_w, float half_h, float near, float far) {
  Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
  m(0, 0) = 1 / half_w;
  m(1, 1) = 1 / half_h;
  m(2, 2) = -2 / (far - near);
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

Camera fixedCamera(View view, const Framing& framing, float half_height, float aspect) {
  const Eigen::Vector3f& target = framing.center;
  const float r = framing.radius;
  Camera c;
  // Orthographic views: the visible half extents (across the screen, up the screen) hold
  // `across` and `upwards` with a 10 % margin, at the frame's aspect.
  auto ortho = [&](const Eigen::Vector3f& direction, const Eigen::Vector3f& up, float across,
                   float upwards) {
    const float half_w = 1.1f * std::max(across, upwards * aspect);
    // Far enough back (20 r) that the floor runs to the bottom of the frame even when the scene
    // is drawn shrunk into a band (narrow frames, renderer.cpp): nearer, the floor in front of
    // the body would pass behind the eye.
    c.eye = target + 20 * r * direction;
    c.view = lookAt(c.eye, target, up);
    c.proj = orthographic(half_w, half_w / aspect, 0.1f * r, 40 * r);
  };
  // Front and side: a floor point d behind the target shows d·sin e − z·cos e above it on the
  // screen (e the elevation, z the target's height); the floor is gone into the background
  // at 80 % of the way to the top of the frame, its checker from just behind the body.
  auto horizon = [&](const Eigen::Vector3f& direction) {
    const float half_h = 1.0f / c.proj(1, 1);
    c.depth_direction = -direction.head<2>().normalized();
    c.fog_far = (0.8f * half_h + target.z() * std::cos(kElevation)) / std::sin(kElevation);
    c.fog_near = std::min(r, 0.5f * c.fog_far);
  };
  const Eigen::Vector3f look_down(std::cos(kElevation), 0, std::sin(kElevation));
  switch (view) {
    case View::Above:  // +y to the right, +x down; the body turns within the circle r
      ortho(Eigen::Vector3f::UnitZ(), -Eigen::Vector3f::UnitX(), r, r);
      break;
    // Front and side look 10° down so that the floor shows as a band, not a line; the body
    // turns within r across, and its height plus r·sin 10° up the screen.
    case View::Front:
      ortho(Eigen::Vector3f(0, -std::cos(kElevation), std::sin(kElevation)),
            Eigen::Vector3f::UnitZ(), r, half_height + r * std::sin(kElevation));
      horizon(Eigen::Vector3f(0, -std::cos(kElevation), std::sin(kElevation)));
      break;
    case View::Side:
    case View::Follow:  // (follow has its own camera: chaseCamera)
      ortho(look_down, Eigen::Vector3f::UnitZ(), r, half_height + r * std::sin(kElevation));
      horizon(look_down);
      break;
    case View::Oblique: {
      // Fixed: from the front right, 30° field of view; far enough that the sphere fits the
      // narrower of the two angles with a 10 % margin.
      const float fov = 30.0f * static_cast<float>(M_PI) / 180;
      const float narrow = aspect >= 1 ? fov : 2 * std::atan(std::tan(fov / 2) * aspect);
      const Eigen::Vector3f direction = Eigen::Vector3f(0.75f, -0.55f, 0.55f).normalized();
      const float distance = 1.1f * r / std::sin(narrow / 2);
      c.eye = target + distance * direction;
      c.view = lookAt(c.eye, target, Eigen::Vector3f::UnitZ());
      c.proj = perspective(fov, aspect, 0.05f * distance, 8 * distance);
      break;
    }
  }
  return c;
}

Camera chaseCamera(const Eigen::Vector3f& middle, const Eigen::Vector2f& heading, float radius,
                   float aspect) {
  const float fov = 30.0f * static_cast<float>(M_PI) / 180;
  const float narrow = aspect >= 1 ? fov : 2 * std::atan(std::tan(fov / 2) * aspect);
  const float elevation = 25.0f * static_cast<float>(M_PI) / 180;
  // Beside the body: across its long axis, so the whole length shows.
  const Eigen::Vector2f across(-heading.y(), heading.x());
  const Eigen::Vector3f direction(std::cos(elevation) * across.x(),
                                  std::cos(elevation) * across.y(), std::sin(elevation));
  const float distance = 1.1f * radius / std::sin(narrow / 2);
  Camera c;
  c.eye = middle + distance * direction;
  c.view = lookAt(c.eye, middle, Eigen::Vector3f::UnitZ());
  c.proj = perspective(fov, aspect, 0.05f * distance, 8 * distance);
  return c;
}

}  // namespace render

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

Camera cameraFor(View view, const Eigen::Vector3f& target, const Eigen::Vector3f& half,
                 float aspect) {
  const float size = half.maxCoeff();
  Camera c;
  // Orthographic views: the visible half extents (across the screen, up the screen) with a
  // margin, fitted to the frame's aspect.
  auto ortho = [&](const Eigen::Vector3f& direction, const Eigen::Vector3f& up, float across,
                   float upwards) {
    const float half_w = 1.3f * std::max(across, upwards * aspect);
    c.eye = target + 4 * size * direction;
    c.view = lookAt(c.eye, target, up);
    c.proj = orthographic(half_w, half_w / aspect, 0.1f * size, 10 * size);
  };
  switch (view) {
    case View::Above:  // long axis across the screen, +y to the right, +x down
      ortho(Eigen::Vector3f::UnitZ(), -Eigen::Vector3f::UnitX(), half.y(), half.x());
      break;
    // Front and side look 10° down so that the floor shows as a band, not a line.
    case View::Front:  // along the long axis: x across, z up
      ortho(Eigen::Vector3f(0, -std::cos(kElevation), std::sin(kElevation)),
            Eigen::Vector3f::UnitZ(), half.x(), half.z() + half.y() * std::sin(kElevation));
      break;
    case View::Side:  // across the long axis: y across, z up
      ortho(Eigen::Vector3f(std::cos(kElevation), 0, std::sin(kElevation)),
            Eigen::Vector3f::UnitZ(), half.y(), half.z() + half.x() * std::sin(kElevation));
      break;
    case View::Oblique:
    case View::Follow: {
      const float fov = 30.0f * static_cast<float>(M_PI) / 180;
      const Eigen::Vector3f direction = Eigen::Vector3f(0.75f, -0.55f, 0.55f).normalized();
      // Far enough that the whole length fits across the frame with a margin.
      const float distance = 0.95f * size / std::tan(fov / 2) / std::min(1.0f, aspect);
      c.eye = target + distance * direction;
      c.view = lookAt(c.eye, target, Eigen::Vector3f::UnitZ());
      c.proj = perspective(fov, aspect, 0.05f * distance, 4 * distance);
      break;
    }
  }
  return c;
}

}  // namespace render

#include "render/camera.hpp"

#include <algorithm>
#include <cmath>

#include "util/picture.hpp"

namespace render {
namespace {

float radians(float degrees) {
  return degrees * static_cast<float>(M_PI) / 180;
}

// The preset's direction towards the eye, raised by its elevation where it has one.
Eigen::Vector3f towardEye(const ViewPreset& p) {
  const Eigen::Vector3f toward(p.toward_eye[0], p.toward_eye[1], p.toward_eye[2]);
  if (p.elevation_deg == 0) return toward;
  const float e = radians(p.elevation_deg);
  return Eigen::Vector3f(toward.x() * std::cos(e), toward.y() * std::cos(e), std::sin(e));
}

Eigen::Vector3f upOf(const ViewPreset& p) {
  return Eigen::Vector3f(p.up[0], p.up[1], p.up[2]);
}

// The narrower of the two angles of a perspective view's field at this aspect.
float narrowAngle(float fov, float aspect) {
  return aspect >= 1 ? fov : 2 * std::atan(std::tan(fov / 2) * aspect);
}

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
  // (follow has its own camera, chaseCamera: framed here as side)
  const ViewPreset& p = presetOf(view == View::Follow ? View::Side : view);
  Camera c;
  if (p.projection == Projection::Perspective) {
    // Far enough that the sphere fits the narrower of the two angles with the margin.
    const float fov = radians(p.fov_deg);
    const float distance = p.margin * r / std::sin(narrowAngle(fov, aspect) / 2);
    c.eye = target + distance * towardEye(p).normalized();
    c.view = lookAt(c.eye, target, upOf(p));
    c.proj = perspective(fov, aspect, 0.05f * distance, 8 * distance);
    return c;
  }
  // Orthographic: the visible half extents (across the screen, up the screen) hold the sphere
  // across, and up the screen the sphere (above) or the body's height plus r·sin e (front and
  // side, which look down by e), with the margin, at the frame's aspect.
  const float e = radians(p.elevation_deg);
  const float upwards = p.elevation_deg == 0 ? r : half_height + r * std::sin(e);
  const float half_w = p.margin * std::max(r, upwards * aspect);
  const Eigen::Vector3f direction = towardEye(p);
  c.eye = target + p.eye_r * r * direction;
  c.view = lookAt(c.eye, target, upOf(p));
  c.proj = orthographic(half_w, half_w / aspect, p.near_r * r, p.far_r * r);
  // Front and side: a floor point d behind the target shows d·sin e − z·cos e above it on the
  // screen (z the target's height); the floor is gone into the background at 80 % of the way
  // to the top of the frame, its checker from just behind the body.
  if (p.elevation_deg != 0) {
    const float half_h = 1.0f / c.proj(1, 1);
    c.depth_direction = -direction.head<2>().normalized();
    c.fog_far = (0.8f * half_h + target.z() * std::cos(e)) / std::sin(e);
    c.fog_near = std::min(r, 0.5f * c.fog_far);
  }
  return c;
}

Camera chaseCamera(const Eigen::Vector3f& middle, const Eigen::Vector2f& heading, float radius,
                   float aspect) {
  const ViewPreset& p = presetOf(View::Follow);
  const float fov = radians(p.fov_deg);
  const float narrow = narrowAngle(fov, aspect);
  const float elevation = radians(p.elevation_deg);
  // Beside the body: across its long axis, so the whole length shows.
  const Eigen::Vector2f across(-heading.y(), heading.x());
  const Eigen::Vector3f direction(std::cos(elevation) * across.x(),
                                  std::cos(elevation) * across.y(), std::sin(elevation));
  const float distance = p.margin * radius / std::sin(narrow / 2);
  Camera c;
  c.eye = middle + distance * direction;
  c.view = lookAt(c.eye, middle, upOf(p));
  c.proj = perspective(fov, aspect, 0.05f * distance, 8 * distance);
  return c;
}

}  // namespace render

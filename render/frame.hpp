// What the renderer is given: the body's points once, and a pose with read-outs per frame.
// It includes nothing of the simulation (docs/design.md "Data flow").
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "util/picture.hpp"

namespace render {

/// The body as the renderer sees it, body frame (origin at the CM), metres.
struct BodyPoints {
  std::vector<Eigen::Vector3f> top;              ///< drawn red
  std::vector<Eigen::Vector3f> bottom;           ///< drawn blue
  float radius = 0.001f;                         ///< sphere radius, m
  float spacing = 0.003f;                        ///< distance between neighbouring points, m
  Eigen::Vector2f footprint_half{0.01f, 0.05f};  ///< outline half extents across and along y, m
};

/// The body's closed surface as triangles, body frame (origin at the CM), metres; each face's
/// corners counter-clockwise seen from outside, so that (b − a) × (c − a) points out of the body.
struct BodyTriangles {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<int, 3>> faces;
};

/// The colour rule of the triangles, the points' own (docs/physics.md §P11.3): the highest point
/// of a vertical line through the body is where the surface faces up (red), the lowest where it
/// faces down (blue). A face is red when its outward normal points up in the body frame, blue
/// when it points down; a vertical face, which no vertical line crosses and so no point lies
/// on, is red.
inline bool facesUp(const Eigen::Vector3f& outward_normal) {
  return outward_normal.z() >= 0;
}

/// The largest distance of a drawn sphere's edge from the CM, m: the body fits in a sphere of
/// this radius in any orientation.
inline float reachOf(const BodyPoints& body) {
  float reach = 0;
  for (const auto* points : {&body.top, &body.bottom})
    for (const auto& p : *points) reach = std::max(reach, p.norm() + body.radius);
  return reach;
}

/// What the fixed views (oblique, above, front, side) keep in frame for a whole run: a sphere
/// that holds the body in any orientation, around where it starts.
struct Framing {
  Eigen::Vector3f center = Eigen::Vector3f::Zero();  ///< world, m
  float radius = 0.1f;                               ///< m
};

/// One frame, and everything drawn from it: what the renderer keeps from frame to frame (the
/// floor it drew, where the last frame drew over it) changes how much it draws, never what, so
/// a frame depends on its own values only (drawn in any order, it is the same).
struct FrameInput {
  Eigen::Vector3d position_world = Eigen::Vector3d::Zero();         ///< CM, m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body → world
  double t = 0;                                                     ///< s
  double spin = 0;                                                  ///< n, rad/s
  Framing framing;  ///< the fixed views' camera: the same for every frame of a run
  /// (t, n) of the run's frames so far, this one included: the inset's curve.
  std::span<const std::array<float, 2>> history;
  /// The run's spin reversals (docs/physics.md P7), s, all of them: a frame marks those at or
  /// before its time (a tick on the inset, and "reversal" for a while after one).
  std::span<const double> reversals;
};

struct RenderSettings {
  int width = 1280, height = 720;  ///< pixels
  Backend backend{};               ///< OpenGL through EGL or OSMesa (Backend::Auto: EGL first)
  View view = View::Oblique;
  std::string title;  ///< printed in the corner ("" for none)
  /// Shorter forms of the title, tried in order where it does not fit the frame, before the
  /// last is cut (--both's narrow halves: "mine: -8 rad/s, against preferred way").
  std::vector<std::string> shorter_titles;
  bool readouts = true;      ///< time, spin and the n(t) inset
  bool transparent = false;  ///< no floor and no background: alpha 0 but the body and its shadow
  double duration = 1;       ///< s, the inset's time axis
  double spin_range = 1;     ///< rad/s, the inset's ± spin axis
  /// m: the length of body every view is framed for, and the floor's squares chosen by; 0: the
  /// body's own (each body fills the picture). The fixed views' sphere is the frame's
  /// (Framing, media/frames.cpp); this is the follow view's and the floor's.
  float frame = 0;
  /// Every sphere's fragments at their true depth, also where the spheres are small enough to
  /// be drawn as discs (under 4 px in radius; tests compare the two).
  bool exact_sphere_depth = false;
  /// The body's points, or its triangles (then given to Renderer::create).
  Surface surface = Surface::Points;
  /// The text (title, read-outs, inset, labels) this many times its usual size for the frame.
  /// --both draws 1.4: its halves are shown side by side, so a 2560-wide frame put on a
  /// 1280-wide screen halves them, and their text must start out larger to stay readable.
  float text_scale = 1;
};

/// An RGBA image, rows top to bottom.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  /// The OpenGL that drew it (GlContext::rasteriser; "" when not known), kept in a PNG as its
  /// tEXt "Software": a golden holds for the rasteriser that drew it, and compare says so
  /// when two images that differ were drawn by different ones.
  std::string drawn_by;
};

}  // namespace render

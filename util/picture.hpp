// The words a picture is asked for in, below everything that asks: the view and its camera's
// numbers, the body's surface, the OpenGL backend, and when two images count as the same. The
// scene's key table (video.view, video.surface), snapshot suites, the commands and the
// player's data (which write no picture and link no renderer) name them as the renderer does,
// so they live here and not in render/, which draws with them (docs/design.md "Data flow").
#pragma once

#include <array>
#include <string_view>
#include <utility>

#include "util/names.hpp"

namespace render {

enum class View { Oblique, Above, Front, Side, Follow };

/// How the body is drawn: its surface points as spheres, or its closed surface as shaded
/// triangles (video.surface).
enum class Surface { Points, Triangles };

/// How OpenGL is reached (render/gl.hpp): EGL (a GPU, or Mesa's surfaceless llvmpipe) or OSMesa;
/// Auto tries EGL first.
enum class Backend { Auto, Egl, OsMesa };

// The views' cameras as numbers, one row a view: where the eye stands, which way is up, the
// field of view and the margins. render/camera.cpp places its cameras by this table, and the
// report's player (tasks/player_data.hpp, player/src/camera.js) gets the same rows with each
// run's data, so the two place their cameras alike.
enum class Projection { Perspective, Orthographic };

struct ViewPreset {
  View view;
  Projection projection;
  /// From the target towards the eye, world; front and side: its horizontal part, raised by
  /// `elevation_deg`; oblique: normalised where used; follow: across the body's long axis.
  std::array<float, 3> toward_eye;
  std::array<float, 3> up;  ///< the screen's up, world
  float elevation_deg;      ///< how far the view looks down from level (front, side, follow)
  float fov_deg;            ///< perspective: the vertical field of view
  /// The framed sphere (orthographic: the body's half height as well) with this margin: 1.1
  /// leaves 10 % of the frame around it.
  float margin;
  /// Orthographic: the eye's distance and the near and far planes, in framing radii (far
  /// enough back that the floor runs to the bottom of the frame even when the scene is drawn
  /// shrunk into a band: nearer, the floor in front of the body would pass behind the eye).
  float eye_r = 0, near_r = 0, far_r = 0;
};

// Above: +y to the right, +x down. Front and side look 10° down so that the floor shows as a
// band, not a line. Oblique: fixed, from the front right. Follow: a chase camera beside the
// body, 25° above (chaseCamera).
inline constexpr std::array<ViewPreset, 5> kViewPresets{{
    {View::Oblique, Projection::Perspective, {0.75f, -0.55f, 0.55f}, {0, 0, 1}, 0, 30, 1.1f},
    {View::Above, Projection::Orthographic, {0, 0, 1}, {-1, 0, 0}, 0, 0, 1.1f, 20, 0.1f, 40},
    {View::Front, Projection::Orthographic, {0, -1, 0}, {0, 0, 1}, 10, 0, 1.1f, 20, 0.1f, 40},
    {View::Side, Projection::Orthographic, {1, 0, 0}, {0, 0, 1}, 10, 0, 1.1f, 20, 0.1f, 40},
    {View::Follow, Projection::Perspective, {0, 0, 0}, {0, 0, 1}, 25, 30, 1.1f},
}};

/// The row of a view.
constexpr const ViewPreset& presetOf(View view) {
  for (const ViewPreset& p : kViewPresets)
    if (p.view == view) return p;
  return kViewPresets[0];
}

/// When two images count as the same (`rattleback compare`, snapshot suites, Python's compare):
/// a pixel differs when a channel differs by more than `channel` (0–255); the images match when
/// at most the fraction `pixels` of them differ and no square of `square` pixels a side all
/// differ (0: no square check). The defaults are those of docs/testing.md "Snapshot tests in
/// your CI": 2 steps absorb the one-step moves another CPU's rasteriser makes.
struct Tolerance {
  int channel = 2;
  double pixels = 0.002;
  int square = 4;
};

}  // namespace render

namespace rb {
template <>
struct NameTable<render::View> {
  static constexpr std::array<std::pair<render::View, std::string_view>, 5> entries{{
      {render::View::Oblique, "oblique"},
      {render::View::Above, "above"},
      {render::View::Front, "front"},
      {render::View::Side, "side"},
      {render::View::Follow, "follow"},
  }};
};
template <>
struct NameTable<render::Surface> {
  static constexpr std::array<std::pair<render::Surface, std::string_view>, 2> entries{{
      {render::Surface::Points, "points"},
      {render::Surface::Triangles, "triangles"},
  }};
};
template <>
struct NameTable<render::Backend> {
  static constexpr std::array<std::pair<render::Backend, std::string_view>, 3> entries{{
      {render::Backend::Auto, "auto"},
      {render::Backend::Egl, "egl"},
      {render::Backend::OsMesa, "osmesa"},
  }};
};
template <>
struct NameTable<render::Projection> {
  static constexpr std::array<std::pair<render::Projection, std::string_view>, 2> entries{{
      {render::Projection::Perspective, "perspective"},
      {render::Projection::Orthographic, "orthographic"},
  }};
};
}  // namespace rb

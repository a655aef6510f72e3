// Draws frames of the body on the floor: OpenGL 3.3 core (EGL or OSMesa), into an FBO.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "render/camera.hpp"
#include "render/frame.hpp"
#include "render/gl.hpp"
#include "render/overlay.hpp"
#include "render/triangles.hpp"
#include "util/result.hpp"

namespace render {

/// Frames with a side shorter than this carry no title, read-outs or inset, pixels.
inline constexpr int kSmallestSideForReadouts = 180;

/// The height of the frame's text (title, read-outs, inset, labels), pixels: a 25th of the
/// height, at most a 30th of the width, times `text_scale` (but then at most a 24th of the
/// width), and at least 8.
int textPixels(const RenderSettings& settings);

/// The floor's checker square, m, for a body of these half extents (m): 1, 2 or 5 × 10ⁿ, about
/// a fifth of its half length; four times that where the floor is seen at 10° (front, side:
/// `fogged`), whose squares would otherwise show as stripes.
float floorSquare(const Eigen::Vector3f& half_extent, bool fogged);

class Renderer {
 public:
  /// A renderer owns an OpenGL context, made current (and put back) around each of its calls,
  /// so several renderers can take turns on one thread; one thread at a time. The body is drawn
  /// as `triangles` when the settings ask for its surface (Surface::Triangles); its points still
  /// set the framing, the floor and the shadow, so that both drawings frame the body alike.
  static rb::Result<std::unique_ptr<Renderer>> create(const RenderSettings& settings,
                                                      const BodyPoints& body,
                                                      const BodyTriangles& triangles = {});
  ~Renderer();

  /// The backend and the GL vendor, renderer and version (for --verbose).
  const std::string& description() const { return context_->description(); }
  const std::string& rasteriser() const { return context_->rasteriser(); }
  /// The title as drawn: the settings', or the first of its shorter forms that fits, or the
  /// last cut with an ellipsis.
  const std::string& title() const { return title_; }

  /// Draws one frame into `out` (resized to the settings' size), read-outs included, from the
  /// frame's values and the renderer's fixed setup only.
  void draw(const FrameInput& frame, Image& out);

 private:
  Renderer(const RenderSettings& settings, const BodyPoints& body);
  std::string init(const BodyTriangles& triangles);
  /// The whole floor under `camera`, with the body's shadow when `shadow`.
  void drawFloor(const Camera& camera, const FrameInput& frame, const Eigen::Vector2f& center,
                 bool shadow);
  /// The body's shadow alone, over the cached floor: a quad around it (shadow.frag).
  void drawShadow(const Camera& camera, const FrameInput& frame, const Eigen::Vector2f& center);
  /// Makes `program` (floor.frag's or shadow.frag's) current with the floor's uniforms.
  void useFloorProgram(GLuint program, const Camera& camera, const FrameInput& frame,
                       const Eigen::Vector2f& center, bool shadow);
  /// The body's long axis on the floor, a unit vector (the shadow's and the chase camera's
  /// heading).
  static Eigen::Vector2f longAxisOnFloor(const FrameInput& frame);
  /// The polygon on the floor (world x, y) the shadow is drawn in, around the body's footprint.
  static constexpr int kShadowSides = 16;
  using ShadowOutline = std::array<Eigen::Vector2f, kShadowSides>;
  ShadowOutline shadowOutline(const FrameInput& frame) const;
  /// The blending of every pass but the shadow's.
  void setBlending();
  /// The fixed views' floor without the shadow, drawn once into its own FBO and copied into
  /// the frame: the same for every frame of a run, and most of the drawing's cost (its
  /// shader runs at every pixel). Only what the last frame drew over it (dirty_) is copied
  /// back. Redrawn, and copied whole, whenever the camera or the centre changes, so a frame
  /// still depends only on its own values.
  void copyCachedFloor(const Camera& camera, const FrameInput& frame,
                       const Eigen::Vector2f& center);
  /// Pixels, in window coordinates (rows from the bottom), from x0, y0 up to x1, y1 exclusive.
  struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  };
  /// A rectangle holding every pixel the shadow and the body change in this frame, with a
  /// margin; the whole frame where the body is too near the camera to bound.
  PixelRect drawnRect(const Camera& camera, const FrameInput& frame) const;
  /// The radius in pixels of the largest sphere any point of the body could be drawn with.
  float largestSpherePx(const Camera& camera, const FrameInput& frame) const;
  /// The body as points or as triangles (settings_.surface).
  void drawBody(const Camera& camera, const FrameInput& frame);
  void drawPoints(const Camera& camera, const FrameInput& frame, const Eigen::Matrix4f& model,
                  const Eigen::Vector3f& light_view);
  void drawReadouts(const FrameInput& frame, const Camera& camera, Image& out);
  /// The spin cue: an arrow around the body on the floor, its sense the spin's, its colour by
  /// the direction, its sweep by |n| (docs/commands.md "The spin cue").
  void drawSpinCue(const FrameInput& frame, const Camera& camera, Image& out);
  bool readoutsShown() const;
  /// Baselines of the title and of the read-outs' first and (in a narrow frame) second line.
  struct ReadoutLayout {
    int x, title, first, second, band;  ///< band: pixels from the top the text takes at most
  };
  ReadoutLayout readoutLayout() const;
  std::string fittedTitle();

  RenderSettings settings_;
  BodyPoints body_;
  std::unique_ptr<GlContext> context_;
  Overlay font_;
  /// The bottom corners' text (the inset's title, the floor's scale) at the frame's usual size
  /// even where the rest is scaled up (--both): scaled, the inset's title left its curve a strip,
  /// and a taller inset covered the spin cue's arrowhead.
  Overlay corner_font_;
  /// The spheres with each fragment's depth on their surface, and as discs at their nearest
  /// point (cheaper: depth is tested before shading); drawPoints picks by the spheres' size.
  GLuint points_program_ = 0, flat_points_program_ = 0;
  GLuint floor_program_ = 0, shadow_program_ = 0;
  GLuint points_vao_ = 0, points_vbo_ = 0, floor_vao_ = 0, floor_vbo_ = 0;
  GLsizei point_count_ = 0;
  GLuint shadow_vao_ = 0, shadow_vbo_ = 0;
  TriangleBody triangles_;  ///< made only for Surface::Triangles
  Framebuffer cache_;       ///< the fixed views' floor, drawn once (copyCachedFloor)
  bool cache_valid_ = false;
  Camera cache_camera_;  ///< the camera the cached floor was drawn with
  Eigen::Vector2f cache_center_;
  /// Where the frame buffer may differ from the cached floor: what the last frame drew over
  /// it (drawnRect), or nothing known (the whole frame). The next frame copies only this back.
  std::optional<PixelRect> dirty_;
  Eigen::Vector3f low_, high_;     ///< the sphere centres' box, body frame, m
  Eigen::Vector3f half_extent_;    ///< body half extents, m
  std::string title_;              ///< settings_.title as drawn, cut to the frame (fittedTitle)
  bool readouts_one_line_ = true;  ///< time and spin on one line (init), else a line each
  std::string scale_label_;        ///< "floor squares 1 cm"
  float middle_height_ = 0;        ///< height of the body's middle above its CM, m
  float radius_ = 0;               ///< the largest distance of a drawn point from the CM, m
  /// Half the length the picture is scaled by (settings_.frame, or the body's own), m: the
  /// floor's squares and fade.
  float scale_half_ = 0;
  float follow_radius_ = 0;  ///< what the follow camera keeps in frame, m
  Eigen::Vector3f scaleExtent() const { return Eigen::Vector3f::Constant(scale_half_); }
};

}  // namespace render

#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace render {
namespace {

const Eigen::Vector3f kBackground(0.93f, 0.94f, 0.96f);

// The widest the read-outs' time and spin can be drawn (all digits are alike wide), as
// drawReadouts formats them.
constexpr const char* kWidestTime = "t = 888.88 s";
constexpr const char* kWidestSpin = "spin n = +88.88 rad/s  (counter-clockwise)";

void setMatrix(const GlApi& gl, GLuint program, const char* name, const Eigen::Matrix4f& m) {
  gl.glUniformMatrix4fv(gl.glGetUniformLocation(program, name), 1, GL_FALSE, m.data());
}

// Blending over a transparent background leaves colour multiplied by alpha (c·a over 0);
// PNG stores colour unmultiplied ("straight"), and viewers composite it so: divide it out.
void straightenAlpha(Image& image) {
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const int a = image.rgba[i + 3];
    if (a == 0 || a == 255) continue;
    for (int k = 0; k < 3; ++k)
      image.rgba[i + k] =
          static_cast<unsigned char>(std::min(255, (image.rgba[i + k] * 255 + a / 2) / a));
  }
}

}  // namespace

Renderer::Renderer(const RenderSettings& settings, const BodyPoints& body)
    : settings_(settings), body_(body) {}

Renderer::~Renderer() {
  if (!context_) return;
  CurrentContext current(*context_);
  if (!current.ok()) return;
  const GlApi& gl = context_->api();
  if (points_vbo_) gl.glDeleteBuffers(1, &points_vbo_);
  if (floor_vbo_) gl.glDeleteBuffers(1, &floor_vbo_);
  if (points_vao_) gl.glDeleteVertexArrays(1, &points_vao_);
  if (floor_vao_) gl.glDeleteVertexArrays(1, &floor_vao_);
  if (shadow_vbo_) gl.glDeleteBuffers(1, &shadow_vbo_);
  if (shadow_vao_) gl.glDeleteVertexArrays(1, &shadow_vao_);
  deleteFramebuffer(gl, cache_);
  if (points_program_) gl.glDeleteProgram(points_program_);
  if (flat_points_program_) gl.glDeleteProgram(flat_points_program_);
  if (floor_program_) gl.glDeleteProgram(floor_program_);
  if (shadow_program_) gl.glDeleteProgram(shadow_program_);
  triangles_.destroy(gl);
}

rb::Result<std::unique_ptr<Renderer>> Renderer::create(const RenderSettings& settings,
                                                       const BodyPoints& body,
                                                       const BodyTriangles& triangles) {
  std::unique_ptr<Renderer> r(new Renderer(settings, body));
  if (std::string error = r->init(triangles); !error.empty()) return rb::machineError(error);
  return r;
}

std::string Renderer::init(const BodyTriangles& triangles) {
  auto context = GlContext::create(settings_.backend, settings_.width, settings_.height);
  if (!context) return context.error().text();
  context_ = std::move(context).value();
  if (std::string e = font_.load(textPixels(settings_)); !e.empty()) return e;
  {
    RenderSettings usual = settings_;
    usual.text_scale = 1;
    if (std::string e = corner_font_.load(textPixels(usual)); !e.empty()) return e;
  }
  title_ = fittedTitle();
  // The time and the spin share a line where it leaves room for the reversal's badge at its
  // right (drawReadouts), else they take a line each. Decided once, from the widest each can
  // be, so that the read-outs do not jump between one line and two as the spin changes sense.
  {
    const int x = readoutLayout().x;
    const int widest = font_.width(std::string(kWidestTime) + "    " + kWidestSpin);
    readouts_one_line_ = x + widest + x + reversalLabelWidth(font_) <= settings_.width - x;
  }
  CurrentContext current(*context_);
  if (!current.ok()) return "cannot make the OpenGL context current";
  const GlApi& gl = context_->api();
  try {
    points_program_ = loadProgram(gl, "points.vert", {"points.frag", "points_depth_sphere.frag"});
    flat_points_program_ =
        loadProgram(gl, "points.vert", {"points.frag", "points_depth_flat.frag"});
    floor_program_ = loadProgram(gl, "floor.vert", {"floor.frag", "floor_common.frag"});
    shadow_program_ = loadProgram(gl, "floor.vert", {"shadow.frag", "floor_common.frag"});
  } catch (const std::exception& e) {
    return e.what();
  }

  // Points: position and kind (0 top, 1 bottom), uploaded once; the pose is a model matrix.
  std::vector<float> data;
  Eigen::Vector3f low = Eigen::Vector3f::Constant(1e9f), high = -low;
  auto add = [&](const std::vector<Eigen::Vector3f>& points, float kind) {
    for (const auto& p : points) {
      data.insert(data.end(), {p.x(), p.y(), p.z(), kind});
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  };
  add(body_.top, 0);
  add(body_.bottom, 1);
  radius_ = reachOf(body_);
  point_count_ = static_cast<GLsizei>(data.size() / 4);
  low_ = low;
  high_ = high;
  half_extent_ = 0.5f * (high - low) + Eigen::Vector3f::Constant(body_.radius);
  // What the picture is scaled by: the body's own size, or the frame asked for (half a body
  // of that length: the floor's squares and fade, and the follow camera's distance).
  scale_half_ = settings_.frame > 0 ? 0.5f * settings_.frame : half_extent_.maxCoeff();
  follow_radius_ = settings_.frame > 0 ? 0.5f * settings_.frame : radius_;
  // The floor's scale, made once: the square follows the body's size, so without it a longer body
  // drawn to fill the frame looked no longer (bodies of 20, 24.5 and 40 cm were all 262 pixels
  // long, on squares of 1, 2 and 2 cm).
  const bool fogged = settings_.view == View::Front || settings_.view == View::Side;
  scale_label_ = "floor squares " + lengthText(floorSquare(scaleExtent(), fogged));
  middle_height_ = 0.5f * (high.z() + low.z());
  gl.glGenVertexArrays(1, &points_vao_);
  gl.glBindVertexArray(points_vao_);
  gl.glGenBuffers(1, &points_vbo_);
  gl.glBindBuffer(GL_ARRAY_BUFFER, points_vbo_);
  gl.glBufferData(GL_ARRAY_BUFFER, data.size() * sizeof(float), data.data(), GL_STATIC_DRAW);
  gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  gl.glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 4 * sizeof(float),
                           reinterpret_cast<void*>(3 * sizeof(float)));
  gl.glEnableVertexAttribArray(0);
  gl.glEnableVertexAttribArray(1);

  // Floor: a quad far larger than the body; the shader fades it out with distance.
  const float r = 40 * scale_half_;
  const float quad[] = {-r, -r, r, -r, -r, r, r, r};
  gl.glGenVertexArrays(1, &floor_vao_);
  gl.glBindVertexArray(floor_vao_);
  gl.glGenBuffers(1, &floor_vbo_);
  gl.glBindBuffer(GL_ARRAY_BUFFER, floor_vbo_);
  gl.glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
  gl.glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  gl.glEnableVertexAttribArray(0);

  // The polygon the shadow is drawn in: floor points, rewritten for each frame.
  gl.glGenVertexArrays(1, &shadow_vao_);
  gl.glBindVertexArray(shadow_vao_);
  gl.glGenBuffers(1, &shadow_vbo_);
  gl.glBindBuffer(GL_ARRAY_BUFFER, shadow_vbo_);
  gl.glBufferData(GL_ARRAY_BUFFER, 2 * kShadowSides * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  gl.glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  gl.glEnableVertexAttribArray(0);

  // The cached floor's own framebuffer, of the frame's size and formats (so a blit copies it).
  const bool complete = makeFramebuffer(gl, settings_.width, settings_.height, cache_);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, context_->framebuffer());
  if (!complete) return "the floor's framebuffer object is incomplete";

  if (settings_.surface == Surface::Triangles)
    if (std::string e = triangles_.init(gl, triangles); !e.empty()) return e;

  gl.glEnable(GL_DEPTH_TEST);
  gl.glEnable(GL_PROGRAM_POINT_SIZE);
  gl.glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  gl.glEnable(GL_BLEND);
  setBlending();
  return "";
}

void Renderer::setBlending() {
  // Colour blends by the source's alpha; alpha accumulates (a + (1 − a)·dst), so a sphere's
  // smoothed edge over a transparent background keeps its own alpha.
  context_->api().glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE,
                                      GL_ONE_MINUS_SRC_ALPHA);
}

void Renderer::useFloorProgram(GLuint program, const Camera& camera, const FrameInput& frame,
                               const Eigen::Vector2f& center, bool shadow) {
  const float size = scale_half_;
  const float tile = floorSquare(scaleExtent(), camera.fog_far > 0);
  const Eigen::Vector2f axis = longAxisOnFloor(frame);
  const Eigen::Vector2f position = frame.position_world.head<2>().cast<float>();

  const GlApi& gl = context_->api();
  gl.glUseProgram(program);
  auto at = [&](const char* name) { return gl.glGetUniformLocation(program, name); };
  setMatrix(gl, program, "u_view", camera.view);
  setMatrix(gl, program, "u_proj", camera.proj);
  gl.glUniform1f(at("u_tile"), tile);
  gl.glUniform2f(at("u_center"), center.x(), center.y());
  gl.glUniform1f(at("u_fade_near"), 3 * size);
  gl.glUniform1f(at("u_fade_far"), 12 * size);
  gl.glUniform2f(at("u_depth_direction"), camera.depth_direction.x(), camera.depth_direction.y());
  gl.glUniform1f(at("u_fog_near"), camera.fog_near);
  gl.glUniform1f(at("u_fog_far"), camera.fog_far);
  gl.glUniform3fv(at("u_background"), 1, kBackground.data());
  gl.glUniform2f(at("u_shadow_center"), position.x(), position.y());
  gl.glUniform2f(at("u_shadow_axis"), axis.x(), axis.y());
  gl.glUniform2f(at("u_shadow_half"), body_.footprint_half.x(), body_.footprint_half.y());
  gl.glUniform1f(at("u_shadow_strength"), shadow ? 0.45f : 0.0f);
  gl.glUniform1f(at("u_transparent"), settings_.transparent ? 1.0f : 0.0f);
}

Eigen::Vector2f Renderer::longAxisOnFloor(const FrameInput& frame) {
  const Eigen::Vector2f axis =
      frame.orientation.cast<float>().toRotationMatrix().col(1).head<2>();  // the long axis
  return axis.norm() > 1e-6f ? axis.normalized() : Eigen::Vector2f(0, 1);
}

void Renderer::drawFloor(const Camera& camera, const FrameInput& frame,
                         const Eigen::Vector2f& center, bool shadow) {
  useFloorProgram(floor_program_, camera, frame, center, shadow);
  const GlApi& gl = context_->api();
  gl.glBindVertexArray(floor_vao_);
  gl.glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

Renderer::ShadowOutline Renderer::shadowOutline(const FrameInput& frame) const {
  // The shadow is zero beyond the ellipse of 1.15 half extents (floor_common.frag), so a
  // polygon around that ellipse changes every pixel the shadow does, and none outside it
  // (there the shader's colour and alpha are 0). Its sides touch the ellipse of 1.16 (a margin
  // for rounding): the vertices lie at 1.16/cos(π/n) in units of the half extents. It covers
  // a third less floor than the rectangle around the ellipse, and each pixel costs shading.
  const Eigen::Vector2f axis = longAxisOnFloor(frame);
  const Eigen::Vector2f position = frame.position_world.head<2>().cast<float>();
  const Eigen::Vector2f across(axis.y(), -axis.x());
  const float n = static_cast<float>(kShadowSides);
  const float reach = 1.16f / std::cos(static_cast<float>(M_PI) / n);
  ShadowOutline outline;
  for (int k = 0; k < kShadowSides; ++k) {
    const float angle = 2 * static_cast<float>(M_PI) * static_cast<float>(k) / n;
    outline[k] = position + reach * (body_.footprint_half.x() * std::cos(angle) * across +
                                     body_.footprint_half.y() * std::sin(angle) * axis);
  }
  return outline;
}

void Renderer::drawShadow(const Camera& camera, const FrameInput& frame,
                          const Eigen::Vector2f& center) {
  useFloorProgram(shadow_program_, camera, frame, center, true);
  // Drawn without the depth test over the copied floor (whose depth it shares), blended as
  // shadow.frag says.
  const ShadowOutline outline = shadowOutline(frame);
  float fan[2 * kShadowSides];
  for (int i = 0; i < kShadowSides; ++i) {
    fan[2 * i] = outline[i].x();
    fan[2 * i + 1] = outline[i].y();
  }
  const GlApi& gl = context_->api();
  gl.glBindVertexArray(shadow_vao_);
  gl.glBindBuffer(GL_ARRAY_BUFFER, shadow_vbo_);
  gl.glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof fan, fan);
  gl.glDisable(GL_DEPTH_TEST);
  gl.glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  gl.glDrawArrays(GL_TRIANGLE_FAN, 0, kShadowSides);
  setBlending();
  gl.glEnable(GL_DEPTH_TEST);
}

void Renderer::copyCachedFloor(const Camera& camera, const FrameInput& frame,
                               const Eigen::Vector2f& center) {
  const GlApi& gl = context_->api();
  // Everything the floor's pass reads that can change: the camera (with its fog) and the
  // centre the floor fades from; the rest is the renderer's fixed setup.
  const bool same = cache_valid_ && cache_camera_.view == camera.view &&
                    cache_camera_.proj == camera.proj &&
                    cache_camera_.depth_direction == camera.depth_direction &&
                    cache_camera_.fog_near == camera.fog_near &&
                    cache_camera_.fog_far == camera.fog_far && cache_center_ == center;
  if (!same) {
    gl.glBindFramebuffer(GL_FRAMEBUFFER, cache_.fbo);
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawFloor(camera, frame, center, false);
    cache_camera_ = camera;
    cache_center_ = center;
    cache_valid_ = true;
    dirty_.reset();
  }
  // Only what the last frame drew over the floor is copied back (a 720p frame's colour and
  // depth are 7 MB; the body and its shadow cover a tenth of it or less).
  const PixelRect r = dirty_.value_or(PixelRect{0, 0, settings_.width, settings_.height});
  if (r.x0 < r.x1 && r.y0 < r.y1) {
    gl.glBindFramebuffer(GL_READ_FRAMEBUFFER, cache_.fbo);
    gl.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, context_->framebuffer());
    gl.glBlitFramebuffer(r.x0, r.y0, r.x1, r.y1, r.x0, r.y0, r.x1, r.y1,
                         GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
  gl.glBindFramebuffer(GL_FRAMEBUFFER, context_->framebuffer());
}

float Renderer::largestSpherePx(const Camera& camera, const FrameInput& frame) const {
  // As points.vert sizes a sphere, at the nearest any point of the body can be to the camera.
  const Eigen::Vector3f center_view =
      (camera.view * frame.position_world.cast<float>().homogeneous()).head<3>();
  const bool perspective = camera.proj(3, 3) == 0;
  const float nearest = perspective ? std::max(-center_view.z() - radius_, 1e-6f) : 1.0f;
  const float px_per_m = std::abs(camera.proj(1, 1)) * settings_.height * 0.5f / nearest;
  return std::max(body_.radius * px_per_m, std::min(0.6f * body_.spacing * px_per_m, 2.0f));
}

Renderer::PixelRect Renderer::drawnRect(const Camera& camera, const FrameInput& frame) const {
  const PixelRect whole{0, 0, settings_.width, settings_.height};
  // The sphere centres lie in their box; projected, in the hull of its corners' images, and
  // each sprite reaches at most its half size (points.vert: the radius and half an edge of at
  // most a pixel) beyond its centre. The shadow lies in its polygon (shadowOutline). Two
  // pixels more for rounding.
  const Eigen::Matrix4f to_clip = camera.proj * camera.view;
  const Eigen::Matrix3f rotation = frame.orientation.cast<float>().toRotationMatrix();
  const Eigen::Vector3f position = frame.position_world.cast<float>();
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
  auto add = [&](const Eigen::Vector3f& world, float margin_px) {
    const Eigen::Vector4f clip = to_clip * world.homogeneous();
    if (!(clip.w() > 1e-6f)) return false;
    const float x = (clip.x() / clip.w() * 0.5f + 0.5f) * settings_.width;
    const float y = (clip.y() / clip.w() * 0.5f + 0.5f) * settings_.height;
    x0 = std::min(x0, x - margin_px), x1 = std::max(x1, x + margin_px);
    y0 = std::min(y0, y - margin_px), y1 = std::max(y1, y + margin_px);
    return true;
  };
  const float sprite_px = std::max(largestSpherePx(camera, frame), 0.75f) + 0.5f + 2;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3f local((corner & 1 ? high_ : low_).x(), (corner & 2 ? high_ : low_).y(),
                                (corner & 4 ? high_ : low_).z());
    if (!add(rotation * local + position, sprite_px)) return whole;
  }
  // The triangles reach the surface itself, beyond the sphere centres: their own box too.
  if (settings_.surface == Surface::Triangles)
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3f& low = triangles_.low();
      const Eigen::Vector3f& high = triangles_.high();
      const Eigen::Vector3f local((corner & 1 ? high : low).x(), (corner & 2 ? high : low).y(),
                                  (corner & 4 ? high : low).z());
      if (!add(rotation * local + position, 2)) return whole;
    }
  for (const Eigen::Vector2f& c : shadowOutline(frame))
    if (!add(Eigen::Vector3f(c.x(), c.y(), 0), 2)) return whole;
  if (!(x1 - x0 < 4.0f * settings_.width && y1 - y0 < 4.0f * settings_.height)) return whole;
  PixelRect r;
  r.x0 = std::clamp(static_cast<int>(std::floor(x0)), 0, settings_.width);
  r.y0 = std::clamp(static_cast<int>(std::floor(y0)), 0, settings_.height);
  r.x1 = std::clamp(static_cast<int>(std::ceil(x1)), 0, settings_.width);
  r.y1 = std::clamp(static_cast<int>(std::ceil(y1)), 0, settings_.height);
  return r;
}

void Renderer::drawBody(const Camera& camera, const FrameInput& frame) {
  Eigen::Matrix4f model = Eigen::Matrix4f::Identity();
  model.topLeftCorner<3, 3>() = frame.orientation.cast<float>().toRotationMatrix();
  model.topRightCorner<3, 1>() = frame.position_world.cast<float>();
  // Light from above, in front and to the left of the default camera (the same for both
  // drawings, so that their shading reads alike).
  const Eigen::Vector3f light_world = Eigen::Vector3f(0.3f, -0.6f, 1.0f).normalized();
  const Eigen::Vector3f light_view = camera.view.topLeftCorner<3, 3>() * light_world;
  if (settings_.surface == Surface::Triangles)
    triangles_.draw(context_->api(), model, camera, light_view);
  else
    drawPoints(camera, frame, model, light_view);
}

void Renderer::drawPoints(const Camera& camera, const FrameInput& frame,
                          const Eigen::Matrix4f& model, const Eigen::Vector3f& light_view) {
  // Spheres under 4 px in radius (the default body's are about 1–2 px at 720p) are drawn as discs
  // at their nearest point: where two overlap, the true surfaces would meet along a curve a pixel
  // or two long. (At 720p 0.1–0.2 % of pixels differ; from 4 px up the curve shows, and each
  // fragment gets its own depth.) The largest radius is that of a sphere as near the camera as
  // any point of the body can be, as points.vert computes it.
  const GLuint program = !settings_.exact_sphere_depth && largestSpherePx(camera, frame) < 4
                             ? flat_points_program_
                             : points_program_;

  const GlApi& gl = context_->api();
  gl.glUseProgram(program);
  setMatrix(gl, program, "u_model", model);
  setMatrix(gl, program, "u_view", camera.view);
  setMatrix(gl, program, "u_proj", camera.proj);
  gl.glUniform1f(gl.glGetUniformLocation(program, "u_radius"), body_.radius);
  gl.glUniform1f(gl.glGetUniformLocation(program, "u_spacing"), body_.spacing);
  gl.glUniform1f(gl.glGetUniformLocation(program, "u_viewport_h"),
                 static_cast<float>(settings_.height));
  gl.glUniform3fv(gl.glGetUniformLocation(program, "u_light_view"), 1, light_view.data());
  const Eigen::Vector3f half_view = (light_view + Eigen::Vector3f::UnitZ()).normalized();
  gl.glUniform3fv(gl.glGetUniformLocation(program, "u_half_view"), 1, half_view.data());
  const Eigen::Matrix4f& P = camera.proj;
  gl.glUniform4f(gl.glGetUniformLocation(program, "u_depth"), P(2, 2), P(2, 3), P(3, 2),
                 P(3, 3));  // (not in the flat program: location −1, ignored)
  gl.glBindVertexArray(points_vao_);
  gl.glDrawArrays(GL_POINTS, 0, point_count_);
}

int textPixels(const RenderSettings& settings) {
  // A 25th of the height (29 px at 720p: a 36th, 20 px, was marginal at the back of a
  // classroom), and at most a 30th of the width: the title and each read-out line (up to about
  // 45 characters, each about half the size wide) then fit in three quarters of a portrait or
  // square frame, where the time and the spin take a line each. (A 64th of the width made a
  // 480-wide portrait frame's text 8 px high.) Scaled up (--both), never beyond a 24th of the
  // width: the spin's line is about 21 sizes wide with its margins, and in a portrait half it
  // ran off the edge, as the floor's scale ran into the inset. Under 8 px it cannot be read.
  const float usual = std::min(settings.height / 25.0f, settings.width / 30.0f);
  const float px = std::min(settings.text_scale * usual, std::max(usual, settings.width / 24.0f));
  return std::max(8, static_cast<int>(std::lround(px)));
}

float floorSquare(const Eigen::Vector3f& half_extent, bool fogged) {
  const float raw = half_extent.maxCoeff() / 5;
  const float decade = std::pow(10.0f, std::floor(std::log10(raw)));
  const float tile = raw / decade < 2 ? decade : raw / decade < 5 ? 2 * decade : 5 * decade;
  // Front and side see the floor at 10°: squares 4× deeper show as bands, not stripes.
  return fogged ? 4 * tile : tile;
}

// The title as drawn, made once: a title wider than the frame (a variant's values, a long name)
// is said shorter where the caller gave a shorter form, else cut, saying so with an ellipsis,
// rather than run off the edge.
std::string Renderer::fittedTitle() {
  std::string title = settings_.title;
  const int room = settings_.width - 2 * readoutLayout().x;
  if (title.empty() || font_.width(title) <= room) return title;
  for (const std::string& shorter : settings_.shorter_titles) {
    title = shorter;
    if (font_.width(title) <= room) return title;
  }
  while (!title.empty() && font_.width(title + "…") > room) {
    unsigned char last = 0;  // one UTF-8 character off the end: its continuation bytes, then
    do {                     // its first
      last = static_cast<unsigned char>(title.back());
      title.pop_back();
    } while (!title.empty() && (last & 0xC0) == 0x80);
  }
  return title + "…";
}

bool Renderer::readoutsShown() const {
  // Below 180 pixels a side the text and the inset would cover the body (a 100×100 frame is
  // almost all body): such frames carry none.
  return std::min(settings_.width, settings_.height) >= kSmallestSideForReadouts &&
         (settings_.readouts || !settings_.title.empty());
}

Renderer::ReadoutLayout Renderer::readoutLayout() const {
  // The title's baseline two lines down, the read-outs 1½ lines below it (or where it would
  // be), their second line (narrow frames, large text) 1½ lines lower, and half a line for
  // descenders. (At 1¼ the second line touched the reversal's badge on the first.)
  const int line = font_.lineHeight();
  ReadoutLayout l;
  l.x = line;
  l.title = line * 2;
  l.first = l.title + (settings_.title.empty() ? 0 : line * 3 / 2);
  l.second = l.first + line * 3 / 2;
  l.band = line * 2 + line * 3 / 2 + line * 3 / 2 + line / 2;  // with a title and two lines
  return l;
}

void Renderer::drawSpinCue(const FrameInput& frame, const Camera& camera, Image& out) {
  if (!(std::abs(frame.spin) >= kSlowestShownSpin)) return;
  // On the floor, a quarter beyond the sphere that holds the body in any orientation, and on
  // the half of that circle nearer the camera: it passes in front of the body, never over it.
  const float radius = 1.25f * radius_;
  const Eigen::Vector3f centre(static_cast<float>(frame.position_world.x()),
                               static_cast<float>(frame.position_world.y()), 0);
  // Towards the camera along the floor: its back axis less its up axis (the view's rows), so
  // that seen from above, where the back axis is vertical, it is towards the frame's bottom.
  const Eigen::Vector3f towards =
      camera.view.block<1, 3>(2, 0).transpose() - camera.view.block<1, 3>(1, 0).transpose();
  const float facing = std::atan2(towards.y(), towards.x());
  // The sweep is |n| over the inset's range, up to the half circle; n > 0 turns counter-
  // clockwise seen from above (docs/physics.md, sign convention), the angle's own sense.
  const double share = std::min(1.0, std::abs(frame.spin) / settings_.spin_range);
  const float sweep = static_cast<float>(M_PI * share);
  const float sense = frame.spin > 0 ? 1.0f : -1.0f;
  const Eigen::Matrix4f to_clip = camera.proj * camera.view;
  constexpr int kPoints = 48;
  std::vector<std::array<float, 2>> arc;
  for (int k = 0; k <= kPoints; ++k) {
    const float angle = facing + sense * sweep * (static_cast<float>(k) / kPoints - 0.5f);
    const Eigen::Vector3f p =
        centre + radius * Eigen::Vector3f(std::cos(angle), std::sin(angle), 0);
    const Eigen::Vector4f clip = to_clip * p.homogeneous();
    if (!(clip.w() > 1e-6f)) return;  // behind the camera: no cue rather than a wrong one
    // (The picture is drawn flipped: its rows read back top first, as the image's rows.)
    arc.push_back({(clip.x() / clip.w() * 0.5f + 0.5f) * settings_.width,
                   (clip.y() / clip.w() * 0.5f + 0.5f) * settings_.height});
  }
  // A 120th of the height wide (6 px at 720p, 3 at 360p), at least 2.
  const float width = std::max(2.0f, settings_.height / 120.0f);
  // The inset and the floor's scale are drawn over the arrow: an end that would run under
  // either (a long body seen from above puts the tail at the inset's corner) stops short of it,
  // by the head's length, the head's own reach.
  const Box boxes[] = {spinInsetBox(out, corner_font_, settings_.duration, settings_.spin_range),
                       scaleLabelBox(out, corner_font_, scale_label_)};
  drawArrow(out, endsClearOf(arc, boxes, 4 * width), width,
            frame.spin > 0 ? kCounterClockwiseColor : kClockwiseColor);
}

void Renderer::drawReadouts(const FrameInput& frame, const Camera& camera, Image& out) {
  if (!readoutsShown()) return;
  const ReadoutLayout layout = readoutLayout();
  const int x = layout.x;
  if (!title_.empty()) font_.text(out, x, layout.title, title_, {30, 30, 30, 255});
  if (!settings_.readouts) return;
  char time[32], spin_text[96];
  // A spin that rounds to zero is shown as +0.00, not -0.00.
  const double spin = std::abs(frame.spin) < 0.005 ? 0.0 : frame.spin;
  std::snprintf(time, sizeof time, "t = %6.2f s", frame.t);
  std::snprintf(spin_text, sizeof spin_text, "spin n = %+6.2f rad/s  %s", spin,
                spin > kSlowestShownSpin    ? "(counter-clockwise)"
                : spin < -kSlowestShownSpin ? "(clockwise)"
                                            : "");
  if (readouts_one_line_) {
    font_.text(out, x, layout.first, std::string(time) + "    " + spin_text, {30, 30, 30, 255});
  } else {  // a narrow frame, or large text: time and spin on a line each
    font_.text(out, x, layout.first, time, {30, 30, 30, 255});
    font_.text(out, x, layout.second, spin_text, {30, 30, 30, 255});
  }
  drawSpinCue(frame, camera, out);
  drawSpinInset(out, corner_font_, frame.history, settings_.duration, settings_.spin_range,
                frame.reversals);
  drawScaleLabel(out, corner_font_, scale_label_);
  // The latest reversal at or before this frame, for a while after it: at the top right.
  for (auto it = frame.reversals.rbegin(); it != frame.reversals.rend(); ++it) {
    if (*it > frame.t) continue;
    if (frame.t - *it < kReversalShownFor)
      drawReversalLabel(out, font_, settings_.width - x, layout.first, *it,
                        static_cast<int>(frame.reversals.rend() - it));
    break;
  }
}

void Renderer::draw(const FrameInput& frame, Image& out) {
  const Eigen::Vector3f position = frame.position_world.cast<float>();
  const Eigen::Vector3f middle(position.x(), position.y(), position.z() + middle_height_);
  const float aspect = static_cast<float>(settings_.width) / settings_.height;
  const bool follow = settings_.view == View::Follow;
  const Eigen::Vector2f heading = longAxisOnFloor(frame);
  Camera camera = follow ? chaseCamera(middle, heading, follow_radius_, aspect)
                         : fixedCamera(settings_.view, frame.framing, half_extent_.z(), aspect);
  // In a frame narrower than 3:2 the body reaches the corners where the title and read-outs
  // (top left) and the inset (bottom right) go; seen from above it spans the height. The scene
  // is drawn scaled into the band between them, so that they never cover it.
  // (The same whether or not this frame draws them, so that a frame and its --no-readouts or
  // --transparent twin show the body alike.)
  if (aspect < 1.5f && std::min(settings_.width, settings_.height) >= kSmallestSideForReadouts) {
    // Between the read-outs at the top and the inset at the bottom, with a pixel to spare.
    const float top = static_cast<float>(readoutLayout().band) / settings_.height;
    const float bottom =
        static_cast<float>(settings_.height - insetTop(settings_.height) + 1) / settings_.height;
    Eigen::Matrix4f between = Eigen::Matrix4f::Identity();
    between(0, 0) = between(1, 1) = 1 - top - bottom;
    between(1, 3) = bottom - top;  // in clip coordinates (× w), so perspective too
    camera.proj = between * camera.proj;
  } else if (settings_.view == View::Above &&
             std::min(settings_.width, settings_.height) >= kSmallestSideForReadouts) {
    // Wider frames keep their corners for the text, but seen from above the body spans the
    // height through the middle, where the read-outs now reach (at 29 px the spin's line runs
    // to the middle of a 720p frame, and its end covered the body's): the scene is drawn below
    // them. The inset and the floor's scale stay in corners the body does not reach.
    const ReadoutLayout layout = readoutLayout();
    const int band =
        readouts_one_line_ ? layout.band - (layout.second - layout.first) : layout.band;
    // Above a 40th of the height at the bottom (the inset's margin): drawn down to the edge, the
    // spin cue's arrow below the body ran out of the frame.
    const float top = static_cast<float>(band) / settings_.height;
    const float bottom = 1.0f / 40;
    Eigen::Matrix4f below = Eigen::Matrix4f::Identity();
    below(0, 0) = below(1, 1) = 1 - top - bottom;
    below(1, 3) = bottom - top;
    camera.proj = below * camera.proj;
  }
  // Upside down: OpenGL's first row is the window's bottom one, so a picture drawn flipped
  // reads back top row first, with no copy to flip it (sprites count their y from the window's
  // bottom to match: init).
  camera.proj.row(1) *= -1;
  const Eigen::Vector2f center = follow ? middle.head<2>() : frame.framing.center.head<2>();
  CurrentContext current(*context_);
  const GlApi& gl = context_->api();
  if (settings_.transparent)
    gl.glClearColor(0, 0, 0, 0);
  else
    gl.glClearColor(kBackground.x(), kBackground.y(), kBackground.z(), 1);
  if (follow) {  // the camera moves with the body: the whole floor, every frame
    gl.glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    drawFloor(camera, frame, center, true);
    dirty_.reset();
  } else {
    copyCachedFloor(camera, frame, center);  // (clear colour set above, for the cache's clear)
    drawShadow(camera, frame, center);
    dirty_ = drawnRect(camera, frame);
  }
  drawBody(camera, frame);
  out.width = settings_.width;
  out.height = settings_.height;
  out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
  context_->readPixels(out.rgba.data());
  if (settings_.transparent) straightenAlpha(out);
  drawReadouts(frame, camera, out);
}

}  // namespace render

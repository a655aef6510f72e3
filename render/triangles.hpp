// The body drawn as its closed surface, shaded triangles (video.surface: triangles), beside the
// points the renderer draws by default (render/renderer.hpp).
#pragma once

#include <Eigen/Dense>
#include <string>

#include "render/camera.hpp"
#include "render/frame.hpp"
#include "render/gl.hpp"

namespace render {

/// The triangles' buffers and program, made once in the renderer's context; every call needs
/// that context current (the renderer holds a CurrentContext around each).
class TriangleBody {
 public:
  /// Uploads the faces, three corners each with the face's normal and colour (flat shading: the
  /// facets show, as the mesh is), and compiles triangles.vert/.frag; an error's text, or "".
  std::string init(const GlApi& gl, const BodyTriangles& body);
  void destroy(const GlApi& gl);
  /// Draws the body at `model` (body → world), lit from `light_view` (unit, view frame).
  void draw(const GlApi& gl, const Eigen::Matrix4f& model, const Camera& camera,
            const Eigen::Vector3f& light_view) const;
  /// The vertices' box, body frame, m (where the frame may change: Renderer::drawnRect).
  const Eigen::Vector3f& low() const { return low_; }
  const Eigen::Vector3f& high() const { return high_; }

 private:
  GLuint program_ = 0, vao_ = 0, vbo_ = 0;
  GLsizei vertex_count_ = 0;
  Eigen::Vector3f low_ = Eigen::Vector3f::Zero(), high_ = Eigen::Vector3f::Zero();
};

}  // namespace render

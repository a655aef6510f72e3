#include "render/triangles.hpp"

#include <stdexcept>
#include <vector>

namespace render {

std::string TriangleBody::init(const GlApi& gl, const BodyTriangles& body) {
  if (body.faces.empty()) return "the body has no triangles to draw";
  try {
    program_ = loadProgram(gl, "triangles.vert", {"triangles.frag"});
  } catch (const std::exception& e) {
    return e.what();
  }
  // Each face's corners on their own (7 floats: position, normal, kind), not shared: a corner
  // on the rim belongs to red faces above and blue faces below, and takes each face's colour
  // and normal there.
  std::vector<float> data;
  data.reserve(body.faces.size() * 3 * 7);
  low_ = Eigen::Vector3f::Constant(1e9f);
  high_ = -low_;
  const int count = static_cast<int>(body.vertices.size());
  for (const auto& face : body.faces) {
    if (face[0] < 0 || face[1] < 0 || face[2] < 0 || face[0] >= count || face[1] >= count ||
        face[2] >= count)
      return "a triangle names a vertex that is not there";
    const Eigen::Vector3f& a = body.vertices[face[0]];
    const Eigen::Vector3f& b = body.vertices[face[1]];
    const Eigen::Vector3f& c = body.vertices[face[2]];
    const Eigen::Vector3f normal = (b - a).cross(c - a).normalized();
    const float kind = facesUp(normal) ? 0.0f : 1.0f;  // 0 red, 1 blue, as points.vert's
    for (const Eigen::Vector3f* p : {&a, &b, &c}) {
      data.insert(data.end(), {p->x(), p->y(), p->z(), normal.x(), normal.y(), normal.z(), kind});
      low_ = low_.cwiseMin(*p);
      high_ = high_.cwiseMax(*p);
    }
  }
  vertex_count_ = static_cast<GLsizei>(data.size() / 7);
  gl.glGenVertexArrays(1, &vao_);
  gl.glBindVertexArray(vao_);
  gl.glGenBuffers(1, &vbo_);
  gl.glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  gl.glBufferData(GL_ARRAY_BUFFER, data.size() * sizeof(float), data.data(), GL_STATIC_DRAW);
  const GLsizei stride = 7 * sizeof(float);
  gl.glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  gl.glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(3 * sizeof(float)));
  gl.glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<void*>(6 * sizeof(float)));
  for (GLuint attribute : {0u, 1u, 2u}) gl.glEnableVertexAttribArray(attribute);
  return "";
}

void TriangleBody::destroy(const GlApi& gl) {
  if (vbo_) gl.glDeleteBuffers(1, &vbo_);
  if (vao_) gl.glDeleteVertexArrays(1, &vao_);
  if (program_) gl.glDeleteProgram(program_);
  vbo_ = vao_ = program_ = 0;
}

void TriangleBody::draw(const GlApi& gl, const Eigen::Matrix4f& model, const Camera& camera,
                        const Eigen::Vector3f& light_view) const {
  gl.glUseProgram(program_);
  auto matrix = [&](const char* name, const Eigen::Matrix4f& m) {
    gl.glUniformMatrix4fv(gl.glGetUniformLocation(program_, name), 1, GL_FALSE, m.data());
  };
  matrix("u_model", model);
  matrix("u_view", camera.view);
  matrix("u_proj", camera.proj);
  gl.glUniform3fv(gl.glGetUniformLocation(program_, "u_light_view"), 1, light_view.data());
  gl.glBindVertexArray(vao_);
  gl.glDrawArrays(GL_TRIANGLES, 0, vertex_count_);
}

}  // namespace render

#version 330 core
// The body's closed surface as triangles (render/triangles.cpp): each corner carries its face's
// normal and colour, so every face is shaded flat and its facets show.
layout(location = 0) in vec3 a_position;  // body frame, m
layout(location = 1) in vec3 a_normal;    // the face's outward unit normal, body frame
layout(location = 2) in float a_kind;     // 0 faces up (red), 1 faces down (blue)
uniform mat4 u_model;  // body -> world (a rotation and a move: normals turn with it)
uniform mat4 u_view;
uniform mat4 u_proj;
out vec3 v_color;
out vec3 v_normal_view;

void main() {
  mat4 model_view = u_view * u_model;
  gl_Position = u_proj * model_view * vec4(a_position, 1.0);
  v_normal_view = mat3(model_view) * a_normal;
  // The points' colours (points.vert), so that a still of either reads alike.
  v_color = a_kind < 0.5 ? vec3(0.86, 0.13, 0.10) : vec3(0.13, 0.32, 0.88);
}

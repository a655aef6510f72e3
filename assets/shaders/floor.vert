#version 330 core
// The floor: one large quad in the plane z = 0.
layout(location = 0) in vec2 a_xy;  // world, m
uniform mat4 u_view;
uniform mat4 u_proj;
out vec2 v_xy;

void main() {
  v_xy = a_xy;
  gl_Position = u_proj * u_view * vec4(a_xy, 0.0, 1.0);
}

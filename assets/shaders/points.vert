#version 330 core
// Surface points as sphere impostors: one GL point per sphere, sized to the sphere's
// projected radius in pixels.
layout(location = 0) in vec3 a_position;  // body frame, m
layout(location = 1) in float a_kind;     // 0 top (red), 1 bottom (blue)
uniform mat4 u_model;       // body -> world
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;     // sphere radius, m
uniform float u_viewport_h; // pixels
out vec3 v_color;
out vec3 v_center_view;
out float v_radius_px;

void main() {
  vec4 view = u_view * u_model * vec4(a_position, 1.0);
  gl_Position = u_proj * view;
  // Projected radius: r · |P[1][1]| · h/2 / w, where w = −z_view in perspective and 1 in
  // ortho (P[1][1] is negative: the renderer draws upside down).
  float w = (u_proj[2][3] == 0.0) ? 1.0 : -view.z;
  v_radius_px = max(u_radius * abs(u_proj[1][1]) * u_viewport_h * 0.5 / w, 0.75);
  gl_PointSize = 2.0 * v_radius_px + 2.0;  // one pixel of margin for the smoothed edge
  v_center_view = view.xyz;
  v_color = a_kind < 0.5 ? vec3(0.86, 0.13, 0.10) : vec3(0.13, 0.32, 0.88);
}

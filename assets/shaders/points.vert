#version 330 core
// Surface points as sphere impostors: one GL point per sphere, sized to the sphere's
// projected radius in pixels.
layout(location = 0) in vec3 a_position;  // body frame, m
layout(location = 1) in float a_kind;     // 0 top (red), 1 bottom (blue)
uniform mat4 u_model;       // body -> world
uniform mat4 u_view;
uniform mat4 u_proj;
uniform float u_radius;     // sphere radius, m
uniform float u_spacing;    // distance between neighbouring points, m
uniform float u_viewport_h; // pixels
out vec3 v_color;
out vec3 v_center_view;
out float v_radius_px;
out float v_radius_m;       // the sphere as drawn, m
out float v_edge_px;        // width of the smoothed edge, px
out float v_sprite_radii;   // the sprite's half-width in sphere radii

void main() {
  vec4 view = u_view * u_model * vec4(a_position, 1.0);
  gl_Position = u_proj * view;
  // Projected radius: r · |P[1][1]| · h/2 / w, where w = −z_view in perspective and 1 in
  // ortho (P[1][1] is negative: the renderer draws upside down).
  float w = (u_proj[2][3] == 0.0) ? 1.0 : -view.z;
  float px_per_m = abs(u_proj[1][1]) * u_viewport_h * 0.5 / w;
  // Spheres a pixel or two across leave gaps the floor shows through, and a small frame's body
  // reads as pink speckle: below 2 px they grow towards overlapping their neighbours (0.6 of
  // the spacing), so the surface reads as one.
  float radius_px = max(u_radius * px_per_m, min(0.6 * u_spacing * px_per_m, 2.0));
  v_radius_m = radius_px / px_per_m;
  v_radius_px = max(radius_px, 0.75);
  // The edge is smoothed over a pixel; on spheres under 2.5 px over less, down to a hard edge
  // at 1.5 px: there nearly every pixel is an edge, and edges blended over the floor (a
  // neighbour behind fails the depth test) would let it show through the body.
  v_edge_px = clamp(v_radius_px - 1.5, 0.05, 1.0);
  // The coverage reaches 0 half an edge beyond the radius: the sprite ends there. (llvmpipe
  // shades whole 4 × 4 blocks, so each pixel of margin costs blocks on every sphere.)
  float half_px = v_radius_px + 0.5 * v_edge_px;
  gl_PointSize = 2.0 * half_px;
  v_sprite_radii = half_px / v_radius_px;
  v_center_view = view.xyz;
  // The sprite's depth is the sphere's nearest point, for the program that does not compute
  // each fragment's depth (points_depth_flat.frag: small spheres); the other replaces it.
  vec4 front = u_proj * vec4(view.xy, view.z + v_radius_m, 1.0);
  gl_Position.z = front.z / front.w * gl_Position.w;
  v_color = a_kind < 0.5 ? vec3(0.86, 0.13, 0.10) : vec3(0.13, 0.32, 0.88);
}

#version 330 core
// Shades a sphere impostor: the normal from the point's coordinates, the true sphere depth,
// and an edge smoothed over one pixel (cheaper than multisampling on llvmpipe).
in vec3 v_color;
in vec3 v_center_view;
in float v_radius_px;
uniform mat4 u_proj;
uniform float u_radius;
uniform vec3 u_light_view;  // unit vector towards the light, view frame
out vec4 frag_color;

void main() {
  // Position on the sprite in sphere radii (gl_PointCoord runs down the picture in y: the renderer draws upside down, with the sprites' origin at the lower left).
  vec2 p = (gl_PointCoord * 2.0 - 1.0) * (v_radius_px + 1.0) / v_radius_px;
  p.y = -p.y;
  float r = length(p);
  float coverage = clamp((1.0 - r) * v_radius_px + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  vec3 n = vec3(p, sqrt(max(0.0, 1.0 - min(r * r, 1.0))));
  vec4 clip = u_proj * vec4(v_center_view + n * u_radius, 1.0);
  gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
  float diffuse = max(dot(n, u_light_view), 0.0);
  vec3 h = normalize(u_light_view + vec3(0.0, 0.0, 1.0));
  float specular = pow(max(dot(n, h), 0.0), 40.0);
  vec3 color = v_color * (0.30 + 0.75 * diffuse) + vec3(0.35) * specular;
  frag_color = vec4(color, coverage);
}

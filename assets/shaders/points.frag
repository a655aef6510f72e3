#version 330 core
// Shades a sphere impostor: the normal from the point's coordinates, its depth
// (points_depth_*.frag), and an edge smoothed over one pixel (cheaper than multisampling on
// llvmpipe).
in vec3 v_color;
in vec3 v_center_view;
in float v_radius_px;
in float v_radius_m;
in float v_edge_px;
in float v_sprite_radii;
uniform vec3 u_light_view;  // unit vector towards the light, view frame
uniform vec3 u_half_view;   // unit vector halfway between the light and the eye, view frame
out vec4 frag_color;

// The depth of the sphere's surface at this fragment (view z, m): written by
// points_depth_sphere.frag, left at the sphere's nearest point by points_depth_flat.frag.
void writeDepth(float z_view);

void main() {
  // Position on the sprite in sphere radii (gl_PointCoord runs down the picture in y: the
  // renderer draws upside down, with the sprites' origin at the lower left).
  vec2 p = (gl_PointCoord * 2.0 - 1.0) * v_sprite_radii;
  p.y = -p.y;
  float rr = dot(p, p);
  float r = sqrt(rr);
  float coverage = clamp((1.0 - r) * v_radius_px / v_edge_px + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  vec3 n = vec3(p, sqrt(max(0.0, 1.0 - rr)));
  writeDepth(v_center_view.z + n.z * v_radius_m);
  float diffuse = max(dot(n, u_light_view), 0.0);
  // The highlight, smaller than a pixel on spheres a pixel or two across, would read as white
  // speckle: it fades out below 2.5 px.
  // (x⁴⁰ = x³² x⁸ by squaring: six products, where pow() takes a logarithm and an exponential.)
  float h = max(dot(n, u_half_view), 0.0);
  float h2 = h * h, h4 = h2 * h2, h8 = h4 * h4, h16 = h8 * h8;
  float specular = h16 * h16 * h8 * smoothstep(1.0, 2.5, v_radius_px);
  vec3 color = v_color * (0.30 + 0.75 * diffuse) + vec3(0.35) * specular;
  frag_color = vec4(color, coverage);
}

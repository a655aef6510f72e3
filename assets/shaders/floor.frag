#version 330 core
// A checker floor, box-filtered against aliasing, fading into the background with distance,
// with a soft contact shadow: an ellipse under the body, aligned with its long axis.
in vec2 v_xy;
uniform float u_tile;           // checker square, m
uniform vec2 u_center;          // where the floor fades from, m
uniform float u_fade_near;      // m
uniform float u_fade_far;       // m
uniform vec3 u_background;
uniform vec2 u_shadow_center;   // m
uniform vec2 u_shadow_axis;     // unit vector along the body's long axis, floor plane
uniform vec2 u_shadow_half;     // half extents across and along the long axis, m
uniform float u_shadow_strength;
uniform float u_transparent;    // 1: no floor, only the shadow, as alpha over nothing
uniform vec2 u_depth_direction;  // front and side: horizontal, away from the camera
uniform float u_fog_near;       // m behind u_center: the checker fades from here …
uniform float u_fog_far;        // … and the floor is the background by here; 0: radial fade
out vec4 frag_color;

void main() {
  vec2 p = v_xy / u_tile;
  vec2 w = fwidth(p) + 1e-4;
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  float checker = 0.5 - 0.5 * i.x * i.y;
  // Front and side look along the floor: far squares shrink to stripes; they fade to grey
  // first, and the floor then into the background: a horizon below the top of the frame.
  float depth = dot(v_xy - u_center, u_depth_direction);
  float horizon_fog = u_fog_far > 0.0 ? smoothstep(u_fog_near, u_fog_far, depth) : 0.0;
  checker = mix(checker, 0.5, smoothstep(u_fog_near, mix(u_fog_near, u_fog_far, 0.5), depth) *
                                  step(0.0, u_fog_far - 1e-9));
  vec3 color = mix(vec3(0.80, 0.80, 0.78), vec3(0.66, 0.67, 0.66), checker);

  vec2 d = v_xy - u_shadow_center;
  vec2 local = vec2(dot(d, vec2(u_shadow_axis.y, -u_shadow_axis.x)), dot(d, u_shadow_axis));
  float e = length(local / u_shadow_half);
  float shadow = u_shadow_strength * (1.0 - smoothstep(0.55, 1.15, e));
  if (u_transparent > 0.5) {
    frag_color = vec4(0.0, 0.0, 0.0, shadow);
    return;
  }
  color *= 1.0 - shadow;

  float fade = u_fog_far > 0.0 ? horizon_fog
                               : smoothstep(u_fade_near, u_fade_far, length(v_xy - u_center));
  frag_color = vec4(mix(color, u_background, fade), 1.0);
}

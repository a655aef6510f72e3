#version 330 core
// A checker floor, box-filtered against aliasing, fading into the background with distance,
// with a soft contact shadow (floor_common.frag).
in vec2 v_xy;
uniform float u_tile;           // checker square, m
uniform vec3 u_background;
uniform float u_transparent;    // 1: no floor, only the shadow, as alpha over nothing
uniform float u_fog_near;
uniform float u_fog_far;
out vec4 frag_color;

float shadowAt(vec2 xy);
float depthAt(vec2 xy);
float fadeAt(vec2 xy);

void main() {
  vec2 p = v_xy / u_tile;
  vec2 w = fwidth(p) + 1e-4;
  vec2 i = 2.0 * (abs(fract((p - 0.5 * w) * 0.5) - 0.5) - abs(fract((p + 0.5 * w) * 0.5) - 0.5)) / w;
  float checker = 0.5 - 0.5 * i.x * i.y;
  // Front and side look along the floor: far squares shrink to stripes; they fade to grey
  // first, and the floor then into the background: a horizon below the top of the frame.
  checker = mix(checker, 0.5, smoothstep(u_fog_near, mix(u_fog_near, u_fog_far, 0.5), depthAt(v_xy)) *
                                  step(0.0, u_fog_far - 1e-9));
  vec3 color = mix(vec3(0.80, 0.80, 0.78), vec3(0.66, 0.67, 0.66), checker);
  float shadow = shadowAt(v_xy);
  if (u_transparent > 0.5) {
    frag_color = vec4(0.0, 0.0, 0.0, shadow);
    return;
  }
  frag_color = vec4(mix(color * (1.0 - shadow), u_background, fadeAt(v_xy)), 1.0);
}

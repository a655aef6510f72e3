#version 330 core
// The contact shadow alone, over a copy of the floor drawn without it (the fixed views'
// cached floor), blended as dst·(1 − s) + src, so that each pixel comes out as floor.frag
// draws it with the shadow: there the colour is (1 − f)(1 − s)·c + f·bg for the checker colour
// c, the fade f and the shadow s; the copy holds (1 − f)·c + f·bg; and
// (1 − f)(1 − s)·c + f·bg = (1 − s)·[(1 − f)·c + f·bg] + s·f·bg.
// Without the checker to compute, this pass costs a fraction of the floor's.
in vec2 v_xy;
uniform vec3 u_background;
uniform float u_transparent;    // 1: the shadow as alpha over nothing
out vec4 frag_color;

float shadowAt(vec2 xy);
float fadeAt(vec2 xy);

void main() {
  float shadow = shadowAt(v_xy);
  vec3 added = u_transparent > 0.5 ? vec3(0.0) : shadow * fadeAt(v_xy) * u_background;
  frag_color = vec4(added, shadow);
}

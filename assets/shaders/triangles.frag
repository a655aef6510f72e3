#version 330 core
// Lambert with an ambient term, the points' own weights (points.frag) without their highlight
// (on flat faces a highlight lights whole facets at once and hides the shape), and a weaker
// fill from the opposite side: lit from above only, the bottom's faces got the ambient alone
// and read as near black, where the points' spheres show their lit upper halves blue.
in vec3 v_color;
in vec3 v_normal_view;
uniform vec3 u_light_view;  // unit vector towards the light, view frame
out vec4 frag_color;

void main() {
  vec3 n = normalize(v_normal_view);
  float towards = dot(n, u_light_view);
  float diffuse = max(towards, 0.0);
  float fill = max(-towards, 0.0);
  frag_color = vec4(v_color * (0.30 + 0.75 * diffuse + 0.35 * fill), 1.0);
}

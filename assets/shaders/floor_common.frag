#version 330 core
// What the floor's pass (floor.frag) and the shadow's pass (shadow.frag) share: the contact
// shadow, and how the floor fades into the background. Linked into both programs.
uniform vec2 u_center;          // where the floor fades from, m
uniform float u_fade_near;      // m
uniform float u_fade_far;       // m
uniform vec2 u_shadow_center;   // m
uniform vec2 u_shadow_axis;     // unit vector along the body's long axis, floor plane
uniform vec2 u_shadow_half;     // half extents across and along the long axis, m
uniform float u_shadow_strength;
uniform vec2 u_depth_direction;  // front and side: horizontal, away from the camera
uniform float u_fog_near;       // m behind u_center: the checker fades from here …
uniform float u_fog_far;        // … and the floor is the background by here; 0: radial fade

// The soft contact shadow at floor point xy (m): an ellipse under the body, aligned with its
// long axis, 0 beyond 1.15 of its half extents.
float shadowAt(vec2 xy) {
  vec2 d = xy - u_shadow_center;
  vec2 local = vec2(dot(d, vec2(u_shadow_axis.y, -u_shadow_axis.x)), dot(d, u_shadow_axis));
  float e = length(local / u_shadow_half);
  return u_shadow_strength * (1.0 - smoothstep(0.55, 1.15, e));
}

// Front and side: how far xy lies behind the centre, away from the camera, m.
float depthAt(vec2 xy) { return dot(xy - u_center, u_depth_direction); }

// How far the floor at xy has faded into the background, 0 … 1: towards the horizon in front
// and side, with distance from the centre otherwise.
float fadeAt(vec2 xy) {
  return u_fog_far > 0.0 ? smoothstep(u_fog_near, u_fog_far, depthAt(xy))
                         : smoothstep(u_fade_near, u_fade_far, length(xy - u_center));
}

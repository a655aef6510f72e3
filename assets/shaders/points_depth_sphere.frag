#version 330 core
// Each fragment at the depth of the sphere's surface there, so that spheres that cut into
// each other meet along their true intersection (seen on spheres several pixels across).
// The projection's rows 2 and 3 against view z and 1: (P22, P23, P32, P33); neither row
// depends on view x or y, so the depth needs only z.
uniform vec4 u_depth;

void writeDepth(float z_view) {
  gl_FragDepth = (u_depth.x * z_view + u_depth.y) / (u_depth.z * z_view + u_depth.w) * 0.5 + 0.5;
}

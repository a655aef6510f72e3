#version 330 core
// Each sphere at the depth of its nearest point (points.vert), as a disc facing the camera:
// on spheres a few pixels across the difference from their true surfaces is a pixel or so
// where two overlap, and a shader that writes no depth lets llvmpipe test depth before
// shading, so that spheres hidden behind others cost no shading.
void writeDepth(float z_view) {}

// rattleback._core.body_mesh (python/body_mesh.cpp), registered by the module (core.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace pyrb {

/// Adds body_mesh(scene, segments) to `m`: the body's surface as NumPy arrays (Scene.mesh()).
void bindBodyMesh(pybind11::module_& m);

}  // namespace pyrb

// rattleback._core.Simulation (python/simulation.cpp), registered by the module (core.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace pyrb {

/// Adds the class Simulation to `m`: a run stepped from Python (rattleback.Simulation).
void bindSimulation(pybind11::module_& m);

}  // namespace pyrb

// rattleback._core.snapshot_suite (python/suite.cpp), registered by the module (core.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace pyrb {

/// Adds snapshot_suite(path) to `m`: a suite file's cases as `rattleback snapshot` reads them.
void bindSnapshotSuite(pybind11::module_& m);

}  // namespace pyrb

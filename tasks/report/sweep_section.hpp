// A sweep's section of the report page: what it varied, its table and its heatmaps.
#pragma once

#include <ostream>

#include "tasks/report/inventory.hpp"

namespace tasks::report {

void writeSweep(std::ostream& out, const SweepFiles& sweep);

}  // namespace tasks::report

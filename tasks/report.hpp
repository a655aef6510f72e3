// The report page: DIR/index.html showing what the runs left in DIR — each scene's videos
// (preferred and reversed side by side), stills, plots, and its analysis beside the measured
// reversal; the sweeps; the bench plot; any other figure. Files are placed by the folder's
// manifest (tasks/manifest.hpp), else by their names. Plain HTML and CSS, no network, every
// path relative to DIR so the folder can be moved or served.
#pragma once

#include <string>

#include "util/result.hpp"

namespace tasks {

/// Writes DIR/index.html (whole or not at all); its path.
rb::Result<std::string> writeReport(const std::string& dir);

}  // namespace tasks

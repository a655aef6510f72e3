// The report page: DIR/index.html showing what the runs left in DIR — each scene's videos
// (preferred and reversed side by side), stills, plots, and its analysis beside the measured
// reversal; the sweeps; the bench plot; any other figure. Files are placed by the folder's
// manifest (tasks/manifest.hpp), else by their names. Plain HTML and CSS, no network, every
// path relative to DIR so the folder can be moved or served.
#pragma once

#include <string>
#include <vector>

#include "util/result.hpp"

namespace tasks {

struct ReportPage {
  std::string path;    ///< DIR/index.html
  bool empty = false;  ///< DIR held no runs, videos, stills, plots or tables to show
  /// What the page leaves out and why, one line each ("…/x.csv: scenes/x.yaml has changed since
  /// this run was simulated: no 3D player for it …"), for the front end to say (not with -q).
  std::vector<std::string> notes;
};

/// Writes DIR/index.html (whole or not at all).
rb::Result<ReportPage> writeReport(const std::string& dir);

}  // namespace tasks

// The page a failing snapshot suite leaves (`rattleback snapshot`'s --report): for each case that
// differs or has no golden, the golden, the new image and their difference side by side with the
// figures. Plain HTML with relative images, so that it works opened from disk (file://) and as a
// CI artifact.
#pragma once

#include <string>
#include <vector>

#include "media/snapshot.hpp"
#include "scene/snapshot.hpp"
#include "util/result.hpp"

namespace media {

/// The report's folder for `suite`: `given`, or snapshot-report beside the suite file.
std::string reportFolder(const scene::SnapshotSuite& suite, const std::string& given);

/// Refuses a folder that exists and is not a report of ours (a user's folder would be replaced).
rb::Status checkReportFolder(const std::string& folder);

/// Writes the report of the cases not Same into `folder`: built whole beside it and renamed into
/// place, replacing an earlier report. A fault of the disk is a machine error.
rb::Status writeReport(const std::string& folder, const scene::SnapshotSuite& suite,
                       const std::vector<CaseResult>& results);

/// Removes an earlier report from `folder` (ours only); true when there was one.
bool removeReport(const std::string& folder);

}  // namespace media

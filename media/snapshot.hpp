// Running a snapshot suite (scene/snapshot.hpp): each case's still drawn as `still` draws it,
// titled with the case's name, and compared with its golden under the case's tolerance; cases run
// on a pool of threads (tasks/job_pool.hpp). Front ends decide what to write and say.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/image_io.hpp"
#include "scene/snapshot.hpp"
#include "tasks/outcome.hpp"
#include "tasks/scene_args.hpp"
#include "util/result.hpp"

namespace media {

/// What became of one case.
enum class CaseStatus {
  Same,        ///< matches its golden within the tolerance
  Differs,     ///< beyond it (or of another size)
  Missing,     ///< no golden yet
  Unreadable,  ///< a file in the golden's place that is not a PNG (CaseResult::error says why)
  Failed,      ///< not drawn: its run stopped, or the machine failed (CaseResult::error)
};

struct CaseResult {
  CaseStatus status = CaseStatus::Failed;
  std::string golden;      ///< the golden's path: GOLDENS/NAME.png
  double t = 0;            ///< the time drawn, s (a named time resolved)
  render::Image image;     ///< as drawn now
  render::Image expected;  ///< the golden as read (empty when missing)
  render::Comparison comparison;
  std::optional<rb::Error> error;  ///< Failed, Unreadable: why (machine set for its faults)
  tasks::Ending ending = tasks::Ending::Completed;
};

/// Every case's scene loaded with its view and size, before anything is drawn: the first that
/// cannot be is the one line to print (its case's place and name, then the scene's own words).
rb::Result<std::vector<tasks::LoadedScene>> loadCases(const scene::SnapshotSuite& suite);

struct SnapshotOptions {
  int jobs = 0;                                     ///< threads; 0: one per core
  render::Backend backend = render::Backend::Auto;  ///< for the cases that name none
  std::function<bool()> cancelled;  ///< asked as the cases run: true stops them (may be empty)
  std::function<void(std::int64_t)> progress;  ///< cases finished so far (may be empty)
};

/// Draws every case and compares it with its golden (read now, when there is one). The results
/// are in the suite's order whatever the threads.
std::vector<CaseResult> runCases(const scene::SnapshotSuite& suite,
                                 const std::vector<tasks::LoadedScene>& scenes,
                                 const SnapshotOptions& options);

}  // namespace media

// `rattleback report DIR`: the page tasks/report writes, and its path.
#include "tasks/report.hpp"

#include <cstdio>
#include <iostream>

#include "app/commands.hpp"

namespace app {

int reportCommand(const ReportArgs& args) {
  auto page = tasks::writeReport(args.dir);
  if (!page) return fail(page);
  if (args.quiet) return kOk;
  // The page is written all the same (a CI step may open it), but a page of only its header,
  // made in silence, left a new user to guess that the folder was the wrong one.
  if (page->empty)
    std::cerr << args.dir
              << ": no runs, videos, stills or plots here, so the page shows none; make them with "
                 "`rattleback simulate SCENE -o "
              << args.dir << "/NAME.csv --plot " << args.dir
              << "` (docs/getting-started.md), or `bash scripts/run.sh` for the main job\n";
  std::printf("%s\n", page->path.c_str());
  return kOk;
}

}  // namespace app

// `rattleback report DIR`: the page tasks/report writes, and its path.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "tasks/report/page.hpp"
#include "util/assets.hpp"

namespace app {

namespace {

// The main job as this program's user runs it: the installed script beside the shipped scenes (an
// installed report pointed to scripts/run.sh, which only the source has), else the source tree's.
std::string mainJob(const std::string& dir) {
  const std::filesystem::path installed = std::filesystem::path(rb::assetsDir()) / "main-job.sh";
  std::error_code ec;
  if (std::filesystem::is_regular_file(installed, ec))
    return "`bash " + installed.string() + " " + dir + "`";
  return "`bash scripts/run.sh`";
}

}  // namespace

int reportCommand(const ReportArgs& args) {
  auto page = tasks::writeReport(args.dir);
  if (!page) return fail(page);
  if (args.quiet) return kOk;  // -q: the notes too
  for (const std::string& note : page->notes) tell(Tone::Note, note);
  // The page is written all the same (a CI step may open it), but a page of only its header,
  // made in silence, left a new user to guess that the folder was the wrong one.
  if (page->empty)
    tell(Tone::Note, args.dir +
                         ": no runs, videos, stills or plots here, so the page shows none; make "
                         "them with `rattleback simulate SCENE -o " +
                         args.dir + "/NAME.csv --plot " + args.dir + "` (" +
                         rb::docPage("getting-started.md") + "), or " + mainJob(args.dir) +
                         " for the main job");
  std::printf("%s\n", page->path.c_str());
  return kOk;
}

}  // namespace app

// `rattleback report DIR`: the page tasks/report writes, and its path.
#include "tasks/report.hpp"

#include <cstdio>

#include "app/commands.hpp"

namespace app {

int reportCommand(const ReportArgs& args) {
  auto page = tasks::writeReport(args.dir);
  if (!page) return fail(page);
  if (!args.quiet) std::printf("%s\n", page->c_str());
  return kOk;
}

}  // namespace app

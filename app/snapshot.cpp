// snapshot: a suite of stills compared with their goldens (media/snapshot.hpp); --update writes
// the goldens; a failure leaves an HTML report. Parse, run, then say: this file only says.
#include "media/snapshot.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/cli.hpp"
#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "media/snapshot_report.hpp"
#include "tasks/output.hpp"
#include "util/format.hpp"

namespace app {
namespace {

namespace fs = std::filesystem;
using media::CaseResult;
using media::CaseStatus;

// "12 of 57600 pixels (0.0208 %) differ by more than 2 in a channel (allowed 0.2000 %); largest
// channel difference 87": the figures `compare` prints, for one case.
std::string figures(const CaseResult& r, const render::Tolerance& tolerance) {
  const render::Comparison& c = r.comparison;
  if (!c.same_size)
    return "of another size: " + std::to_string(r.image.width) + "x" +
           std::to_string(r.image.height) + " now, " + std::to_string(r.expected.width) + "x" +
           std::to_string(r.expected.height) + " in the golden";
  char text[200];
  std::snprintf(text, sizeof text,
                "%lld of %lld pixels (%.4f %%) differ by more than %d in a channel (allowed "
                "%.4f %%); largest channel difference %d",
                c.differing, c.pixels, 100 * c.fraction(), tolerance.channel,
                100 * tolerance.pixels, c.max_channel_delta);
  std::string said = text;
  if (render::squareDiffers(c, tolerance))
    said += "; a square of them " + std::to_string(c.square) + " px a side (square " +
            std::to_string(tolerance.square) + ")";
  return said;
}

// The cases that could not be drawn, each said; the worst exit status among them (0: none).
int sayFailed(const std::vector<CaseResult>& results) {
  int status = kOk;
  for (const CaseResult& r : results) {
    if (r.status != CaseStatus::Failed || !r.error) continue;
    tell(Tone::Error, r.error->text());
    const int own = r.error->machine                     ? kMachine
                    : r.ending == tasks::Ending::Stopped ? kDiverged
                                                         : kBadInput;
    status = std::max(status, own);
  }
  return status;
}

// --update: the goldens that differ or are missing are written; the rest are left alone, so that
// an unchanged suite writes nothing.
int update(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results, bool quiet) {
  int counts[3] = {0, 0, 0};  // added, changed, unchanged
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const int kind = r.status == CaseStatus::Missing ? 0 : r.status == CaseStatus::Differs ? 1 : 2;
    if (kind < 2) {
      if (auto made = tasks::makeParentFolder(r.golden); !made) return fail(made);
      const rb::OutputNamedBy naming("goldens:");
      if (auto e = render::writePng(r.golden, r.image); !e) return fail(e);
    }
    ++counts[kind];
    if (!quiet)
      std::printf("%-10s %s  %s\n",
                  kind == 0   ? "added"
                  : kind == 1 ? "changed"
                              : "unchanged",
                  suite.cases[i].name.c_str(), r.golden.c_str());
  }
  if (!quiet) std::printf("%d added, %d changed, %d unchanged\n", counts[0], counts[1], counts[2]);
  return kOk;
}

}  // namespace

namespace {

// Each case's verdict on standard output; the report when any differs or is missing.
int verdicts(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results,
             const std::string& report, bool quiet) {
  int same = 0, differ = 0, missing = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const scene::SnapshotCase& c = suite.cases[i];
    same += r.status == CaseStatus::Same;
    differ += r.status == CaseStatus::Differs;
    missing += r.status == CaseStatus::Missing;
    if (quiet) continue;
    if (r.status == CaseStatus::Missing)
      std::printf("missing  %s  %s does not exist: rattleback snapshot %s --update writes it\n",
                  c.name.c_str(), r.golden.c_str(), suite.file.c_str());
    else
      std::printf("%-7s  %s  %s\n", r.status == CaseStatus::Same ? "same" : "DIFFERS",
                  c.name.c_str(), figures(r, c.tolerance).c_str());
  }
  if (differ + missing == 0) {
    if (media::removeReport(report) && !quiet)
      std::printf("removed %s, the report of an earlier run that failed\n", report.c_str());
    if (!quiet) std::printf("%s: all %d match\n", suite.file.c_str(), same);
    return kOk;
  }
  if (auto e = media::writeReport(report, suite, results); !e) return fail(e);
  if (!quiet)
    std::printf("%d same, %d differ, %d missing; report: %s\n", same, differ, missing,
                (fs::path(report) / "index.html").c_str());
  return 1;
}

}  // namespace

int snapshotCommand(const SnapshotArgs& args) {
  installInterruptHandlers();
  auto suite = scene::loadSnapshotSuite(args.file);
  if (!suite) return fail(suite);
  const std::string report = media::reportFolder(suite.value(), args.report);
  if (auto ok = media::checkReportFolder(report); !ok) return fail(ok);
  auto scenes = media::loadCases(suite.value());
  if (!scenes) return fail(scenes);
  Progress progress("snapshot", static_cast<std::int64_t>(suite->cases.size()), !args.quiet);
  media::SnapshotOptions options;
  options.jobs = args.jobs;
  // As for still: the environment's backend is the default of the cases that name none.
  if (const char* env = std::getenv("RATTLEBACK_BACKEND"); env && *env) {
    const auto backend = rb::parseName<render::Backend>(env);
    if (!backend) {
      tell(Tone::Error, std::string("RATTLEBACK_BACKEND (the environment): ") +
                            rb::choices<render::Backend>() + ", not '" + env + "'");
      return kBadInput;
    }
    options.backend = *backend;
  }
  options.cancelled = [] { return interruptSignal() != 0; };
  options.progress = [&](std::int64_t done) { progress.update(done); };
  const std::vector<CaseResult> results = media::runCases(suite.value(), scenes.value(), options);
  progress.finish();
  if (interruptSignal() != 0) {
    tell(Tone::Error, args.file + ": interrupted; nothing written");
    return interruptedStatus();
  }
  if (const int failed = sayFailed(results); failed != kOk) return failed;
  return args.update ? update(suite.value(), results, args.quiet)
                     : verdicts(suite.value(), results, report, args.quiet);
}

int runSnapshot(Cli& cli) {
  return snapshotCommand(cli.snapshot_args);
}

}  // namespace app

// snapshot: a suite of stills compared with their goldens (media/snapshot.hpp); --update writes
// the goldens; a failure leaves an HTML report. Parse, run, then say: this file only says.
#include "media/snapshot.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "app/cli.hpp"
#include "app/commands.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "media/snapshot_report.hpp"
#include "tasks/output.hpp"
#include "tasks/report/html.hpp"
#include "util/arguments.hpp"
#include "util/format.hpp"
#include "util/output_place.hpp"

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

// As compare says it: a golden holds for the rasteriser that drew it (softpipe against
// llvmpipe: 2.8 % of a still's pixels), so where the golden's PNG names another than the one that
// drew the case now, that is the likely cause of a difference.
std::string otherRasteriser(const CaseResult& r) {
  const std::string &now = r.image.drawn_by, &then = r.expected.drawn_by;
  if (r.status != CaseStatus::Differs || now.empty() || then.empty() || now == then) return "";
  return "; the golden was drawn by " + then + ", this by " + now +
         ": a golden holds for the rasteriser that drew it";
}

// The cases that could not be drawn, each said; the worst exit status among them (0: none). A
// reason that many cases share (an OpenGL that will not start fails them all) is said once, with
// the others' names after it.
int sayFailed(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results) {
  int status = kOk;
  std::vector<std::pair<std::string, std::vector<std::string>>> said;  // reason, other cases
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    if (r.status != CaseStatus::Failed || !r.error) continue;
    const std::string text = r.error->text();
    const std::string own = suite.cases[i].place + ": " + suite.cases[i].name + ": ";
    const std::string reason = text.starts_with(own) ? text.substr(own.size()) : text;
    const auto same =
        std::find_if(said.begin(), said.end(), [&](const auto& s) { return s.first == reason; });
    if (same != said.end()) {
      same->second.push_back(suite.cases[i].name);
    } else {
      tell(Tone::Error, text);
      said.push_back({reason, {}});
    }
    const int code = r.error->machine                     ? kMachine
                     : r.ending == tasks::Ending::Stopped ? kDiverged
                                                          : kBadInput;
    status = std::max(status, code);
  }
  for (const auto& [reason, others] : said) {
    if (others.empty()) continue;
    std::string names;
    for (const std::string& name : others) names += (names.empty() ? "" : ", ") + name;
    tell(Tone::Note, "the same for " + std::to_string(others.size()) +
                         (others.size() == 1 ? " more case: " : " more cases: ") + names);
  }
  return status;
}

// The PNGs in the goldens folder that no case of the suite names: a case removed or renamed
// leaves its golden behind, which nothing compares any more. Said, never removed (the folder may
// hold another suite's goldens too).
void sayStrayGoldens(const scene::SnapshotSuite& suite) {
  std::set<std::string> named;
  for (const scene::SnapshotCase& c : suite.cases) named.insert(c.name + ".png");
  std::vector<std::string> stray;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(suite.goldens, ec))
    if (entry.path().extension() == ".png" && !named.contains(entry.path().filename().string()))
      stray.push_back(entry.path().string());
  if (stray.empty()) return;
  std::sort(stray.begin(), stray.end());
  std::string list;
  for (std::size_t i = 0; i < stray.size() && i < 5; ++i) list += (i ? ", " : "") + stray[i];
  if (stray.size() > 5) list += " and " + std::to_string(stray.size() - 5) + " more";
  tell(Tone::Note, suite.file + ": " + std::to_string(stray.size()) +
                       (stray.size() == 1 ? " golden belongs" : " goldens belong") +
                       " to no case of this suite (a case removed or renamed?): " + list +
                       (stray.size() == 1 ? "; delete it if its case is gone"
                                          : "; delete them if their cases are gone"));
}

// --update: the goldens that differ or are missing are written; the rest are left alone, so that
// an unchanged suite writes nothing.
int update(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results,
           const std::string& report, bool quiet) {
  int counts[3] = {0, 0, 0};  // added, changed, unchanged
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const int kind = r.status == CaseStatus::Missing                                         ? 0
                     : r.status == CaseStatus::Differs || r.status == CaseStatus::Unreadable ? 1
                                                                                             : 2;
    if (kind < 2) {
      if (auto made = tasks::makeParentFolder(r.golden); !made) return fail(made);
      const rb::OutputNamedBy naming("goldens:");
      if (auto e = render::writePng(r.golden, r.image); !e) return fail(e);
    }
    ++counts[kind];
    if (!quiet)
      std::printf("%-10s %s  %s\n",
                  kind == 0                            ? "added"
                  : r.status == CaseStatus::Unreadable ? "replaced"
                  : kind == 1                          ? "changed"
                                                       : "unchanged",
                  suite.cases[i].name.c_str(), r.golden.c_str());
  }
  if (!quiet) std::printf("%d added, %d changed, %d unchanged\n", counts[0], counts[1], counts[2]);
  // Every golden is now what was drawn: a report of an earlier failure no longer stands.
  if (media::removeReport(report) && !quiet)
    std::printf("removed %s, the report of an earlier run that failed\n", report.c_str());
  return kOk;
}

// Text for XML: escaped, and without the control characters XML 1.0 cannot hold.
std::string xmlText(const std::string& text) {
  std::string kept;
  for (const char c : text)
    if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n') kept += c;
  return tasks::report::escape(kept);
}

// --junit: every case as a JUnit test case (the schema GitLab, Jenkins and pytest's --junitxml
// share): a golden that differs or is missing is a failure, one that cannot be read or a case
// that could not be drawn an error, each with the words the terminal gives it; after --update
// every case passes, its golden added, changed or unchanged in its output.
rb::Status writeJunit(const std::string& path, const scene::SnapshotSuite& suite,
                      const std::vector<CaseResult>& results, bool updated,
                      const std::string& report) {
  std::string cases;
  int failures = 0, errors = 0;
  const std::string name = xmlText(fs::path(suite.file).stem().string());
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const scene::SnapshotCase& c = suite.cases[i];
    // The case's place, "suite.yaml:7", as the file and line attributes CI views link to.
    const std::size_t colon = c.place.rfind(':');
    cases +=
        "    <testcase classname=\"" + name + "\" name=\"" + xmlText(c.name) + "\" file=\"" +
        xmlText(c.place.substr(0, colon)) + "\"" +
        (colon == std::string::npos ? "" : " line=\"" + xmlText(c.place.substr(colon + 1)) + "\"");
    std::string inner;
    if (r.status == CaseStatus::Failed || (r.status == CaseStatus::Unreadable && !updated)) {
      ++errors;
      inner = "<error message=\"" + xmlText(r.error ? r.error->text() : "not drawn") + "\"/>";
    } else if (updated) {  // as update() says each (a golden that was not a PNG is replaced)
      inner = std::string("<system-out>golden ") +
              (r.status == CaseStatus::Missing      ? "added"
               : r.status == CaseStatus::Differs    ? "changed"
               : r.status == CaseStatus::Unreadable ? "replaced"
                                                    : "unchanged") +
              ": " + xmlText(r.golden) + "</system-out>";
    } else if (r.status != CaseStatus::Same) {
      ++failures;
      const std::string what = r.status == CaseStatus::Missing
                                   ? r.golden + " does not exist: rattleback snapshot " +
                                         suite.file + " --update writes it"
                                   : "differs: " + figures(r, c.tolerance) + otherRasteriser(r);
      inner = "<failure type=\"" +
              std::string(r.status == CaseStatus::Missing ? "missing" : "differs") +
              "\" message=\"" + xmlText(what) +
              "\">report: " + xmlText((fs::path(report) / "index.html").string()) + "#" +
              xmlText(c.name) + "</failure>";
    }
    cases += inner.empty() ? "/>\n" : ">" + inner + "</testcase>\n";
  }
  const std::string counts = " tests=\"" + std::to_string(results.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\"";
  if (auto made = tasks::makeParentFolder(path); !made) return made;
  auto out = tasks::AtomicOutput::open(path);
  if (!out) return out.error();
  out->stream() << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites" << counts
                << ">\n  <testsuite name=\"" << name << "\"" << counts << ">\n"
                << cases << "  </testsuite>\n</testsuites>\n";
  return out->commit();
}

// A suite that cannot run, as JUnit XML: one test case in error, at the line at fault where
// there is one, so that a CI's test view shows it rather than an earlier run's verdicts.
rb::Status writeJunitRefusal(const std::string& path, const std::string& file,
                             const rb::Error& error) {
  const std::string name = xmlText(fs::path(file).stem().string());
  // Where the error is: the suite's line (a case whose scene is at fault is placed at the
  // case), else the suite itself.
  const std::string at_file = error.where ? error.where->file : file;
  const int at_line = error.where ? error.where->line : 0;
  std::string place = " file=\"" + xmlText(at_file) + "\"";
  if (at_line > 0) place += " line=\"" + std::to_string(at_line) + "\"";
  if (auto made = tasks::makeParentFolder(path); !made) return made;
  auto out = tasks::AtomicOutput::open(path);
  if (!out) return out.error();
  out->stream() << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites tests=\"1\" "
                   "failures=\"0\" errors=\"1\">\n  <testsuite name=\""
                << name << "\" tests=\"1\" failures=\"0\" errors=\"1\">\n    <testcase classname=\""
                << name << "\" name=\"suite\"" << place << "><error message=\""
                << xmlText(error.text()) << "\"/></testcase>\n  </testsuite>\n</testsuites>\n";
  return out->commit();
}

}  // namespace

namespace {

// The suite's error, said, and put in --junit's file when one is asked for (it had been left as
// the last run wrote it: green cases in the CI's view of a job that failed).
int refused(const SnapshotArgs& args, const rb::Error& error) {
  if (!args.junit.empty()) {
    const rb::OutputNamedBy naming("--junit");
    if (auto e = writeJunitRefusal(args.junit, args.file, error); !e)
      tell(Tone::Error, e.error().text());
  }
  return fail(error);
}

// Each case's verdict on standard output; the report when any differs or is missing.
int verdicts(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results,
             const std::string& report, bool quiet) {
  int same = 0, differ = 0, missing = 0, unreadable = 0;
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const scene::SnapshotCase& c = suite.cases[i];
    same += r.status == CaseStatus::Same;
    differ += r.status == CaseStatus::Differs;
    missing += r.status == CaseStatus::Missing;
    unreadable += r.status == CaseStatus::Unreadable;
    if (r.status == CaseStatus::Unreadable) {
      // The input at fault, said on standard error even with -q, as any bad input is.
      tell(Tone::Error, r.error->text() + "; it is case " + c.name +
                            "'s golden: rattleback snapshot " + suite.file +
                            " --update replaces it with the image drawn now");
      continue;
    }
    if (quiet) continue;
    if (r.status == CaseStatus::Missing)
      std::printf("missing  %s  %s does not exist: rattleback snapshot %s --update writes it\n",
                  c.name.c_str(), r.golden.c_str(), suite.file.c_str());
    else
      std::printf("%-7s  %s  %s%s\n", r.status == CaseStatus::Same ? "same" : "DIFFERS",
                  c.name.c_str(), figures(r, c.tolerance).c_str(), otherRasteriser(r).c_str());
  }
  if (differ + missing + unreadable == 0) {
    if (media::removeReport(report) && !quiet)
      std::printf("removed %s, the report of an earlier run that failed\n", report.c_str());
    if (!quiet) std::printf("%s: all %d match\n", suite.file.c_str(), same);
    return kOk;
  }
  if (auto e = media::writeReport(report, suite, results); !e) return fail(e);
  if (!quiet) {
    std::printf("%d same, %d differ, %d missing%s; report: %s\n", same, differ, missing,
                unreadable ? (", " + std::to_string(unreadable) + " unreadable").c_str() : "",
                (fs::path(report) / "index.html").c_str());
    // The way out on the terminal too, not only on the report's page: a change meant is blessed.
    if (differ + missing > 0)
      std::printf("rattleback snapshot %s --update makes the images drawn now the goldens\n",
                  suite.file.c_str());
  }
  return unreadable ? kBadInput : 1;
}

}  // namespace

int snapshotCommand(const SnapshotArgs& args) {
  installInterruptHandlers();
  // The cases' arguments come from the suite's keys, and messages name them so ("backend egl").
  rb::argument_style = rb::ArgumentStyle::Key;
  if (!args.junit.empty()) {  // first: a suite refused below is said in it
    const rb::OutputNamedBy naming("--junit");
    if (auto ok = rb::checkDataOutput(args.junit, "JUnit XML", ".xml", {args.file}); !ok)
      return fail(ok);
    if (auto ok = rb::checkExtension(args.junit, ".xml", "JUnit XML", false); !ok) return fail(ok);
  }
  auto suite = scene::loadSnapshotSuite(args.file);
  if (!suite) return refused(args, suite.error());
  const std::string report = media::reportFolder(suite.value(), args.report);
  if (auto ok = media::checkReportFolder(report); !ok) return refused(args, ok.error());
  auto scenes = media::loadCases(suite.value());
  if (!scenes) return refused(args, scenes.error());
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
  const int failed = sayFailed(suite.value(), results);
  if (!args.junit.empty()) {
    const rb::OutputNamedBy naming("--junit");
    if (auto e =
            writeJunit(args.junit, suite.value(), results, args.update && failed == kOk, report);
        !e)
      return fail(e);
  }
  if (failed != kOk) return failed;
  const int status = args.update ? update(suite.value(), results, report, args.quiet)
                                 : verdicts(suite.value(), results, report, args.quiet);
  if (!args.quiet) sayStrayGoldens(suite.value());
  return status;
}

int runSnapshot(Cli& cli) {
  return snapshotCommand(cli.snapshot_args);
}

}  // namespace app

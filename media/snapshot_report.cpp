#include "media/snapshot_report.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tasks/report/html.hpp"

namespace media {
namespace fs = std::filesystem;
namespace {

// The file that marks a folder as a snapshot report: only such a folder is ever replaced.
constexpr const char* kMark = ".rattleback-snapshot-report";

using tasks::report::escape;
using tasks::report::url;

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }
.case { background: #fff; border: 1px solid #ccc; border-radius: 6px; padding: 1em; margin-bottom: 1.5em; }
.images { display: flex; gap: 1em; flex-wrap: wrap; }
figure { margin: 0; }
figure img { max-width: 420px; border: 1px solid #999; image-rendering: pixelated; }
figcaption { font-size: 90%; color: #555; }
table.figures td { padding: 0 1em 0 0; }
.differs { color: #b00; } .missing { color: #a60; } .unreadable { color: #a60; }
</style>)";

void writeImage(std::ostream& out, const std::string& file, const std::string& caption) {
  out << "<figure><a href=\"" << url(file) << "\"><img src=\"" << url(file) << "\" alt=\""
      << escape(caption) << "\"></a><figcaption>" << escape(caption) << "</figcaption></figure>\n";
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4f %%", 100 * fraction);
  return text;
}

void writeFigures(std::ostream& out, const scene::SnapshotCase& c, const CaseResult& r) {
  const render::Comparison& k = r.comparison;
  out << "<table class=\"figures\">\n<tr><td>scene</td><td>" << escape(c.scene_as_written)
      << "</td></tr>\n<tr><td>t</td><td>" << escape(c.t_text) << " (" << r.t
      << " s)</td></tr>\n<tr><td>golden</td><td>" << escape(r.golden) << "</td></tr>\n";
  if (r.status == CaseStatus::Differs && k.same_size)
    out << "<tr><td>pixels differing</td><td class=\"pixels\">" << k.differing << " of " << k.pixels
        << " (" << percent(k.fraction()) << "; allowed " << percent(c.tolerance.pixels)
        << ")</td></tr>\n<tr><td>worst level</td><td "
        << "class=\"worst\">" << k.max_channel_delta << " (tolerance " << c.tolerance.channel
        << ")</td></tr>\n<tr><td>largest square</td><td>" << k.square << " px a side (fails at "
        << c.tolerance.square << ")</td></tr>\n";
  if (r.status == CaseStatus::Differs && !r.expected.drawn_by.empty())
    out << "<tr><td>drawn now by</td><td>" << escape(r.image.drawn_by)
        << "</td></tr>\n<tr><td>the golden by</td><td>" << escape(r.expected.drawn_by)
        << "</td></tr>\n";
  if (r.status == CaseStatus::Differs && !k.same_size)
    out << "<tr><td>size</td><td>" << r.image.width << "x" << r.image.height << " now, "
        << r.expected.width << "x" << r.expected.height << " in the golden</td></tr>\n";
  out << "</table>\n";
}

// Whether a case is in the report: it differs, or there is no golden to compare it with.
bool reported(const CaseResult& r) {
  return r.status == CaseStatus::Differs || r.status == CaseStatus::Missing ||
         r.status == CaseStatus::Unreadable;
}

// One case's section; its images are written beside the page by the caller.
void writeCase(std::ostream& out, const scene::SnapshotCase& c, const CaseResult& r) {
  const bool missing = r.status != CaseStatus::Differs;  // no golden image to show
  out << "<section class=\"case\" id=\"" << escape(c.name) << "\">\n<h2 class=\""
      << (missing ? "missing" : "differs") << "\">" << escape(c.name) << ": "
      << (r.status == CaseStatus::Missing      ? "no golden yet (--update writes it)"
          : r.status == CaseStatus::Unreadable ? "the golden cannot be read (--update replaces it)"
                                               : "differs")
      << "</h2>\n";
  if (r.status == CaseStatus::Unreadable && r.error)
    out << "<p class=\"unreadable\">" << escape(r.error->text()) << "</p>\n";
  writeFigures(out, c, r);
  out << "<div class=\"images\">\n";
  if (!missing) writeImage(out, c.name + "-golden.png", "golden");
  writeImage(out, c.name + "-new.png", "new");
  if (!missing && r.comparison.same_size)
    writeImage(out, c.name + "-diff.png", "diff (differing pixels in magenta)");
  out << "</div>\n</section>\n";
}

}  // namespace

namespace {

std::string pageOf(const scene::SnapshotSuite& suite, const std::vector<CaseResult>& results) {
  std::ostringstream out;
  int failing = 0;
  for (const CaseResult& r : results) failing += r.status != CaseStatus::Same;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<title>Snapshot report: " << escape(suite.file) << "</title>\n"
      << kStyle << "\n</head>\n<body>\n<h1>Snapshot report</h1>\n<p id=\"summary\">"
      << escape(suite.file) << ": " << failing << " of " << results.size()
      << " cases differ or have no golden. Where the new images are right (an intended "
      << "change), <code>rattleback snapshot " << escape(suite.file)
      << " --update</code> makes them the goldens.</p>\n";
  for (std::size_t i = 0; i < results.size(); ++i)
    if (reported(results[i])) writeCase(out, suite.cases[i], results[i]);
  out << "</body>\n</html>\n";
  return out.str();
}

// The images of each failing case, into `dir`.
rb::Status writeImages(const fs::path& dir, const scene::SnapshotSuite& suite,
                       const std::vector<CaseResult>& results) {
  for (std::size_t i = 0; i < results.size(); ++i) {
    const CaseResult& r = results[i];
    const std::string name = suite.cases[i].name;
    if (!reported(r)) continue;
    if (auto e = render::writePng((dir / (name + "-new.png")).string(), r.image); !e) return e;
    if (r.status != CaseStatus::Differs) continue;
    if (r.expected.width > 0)
      if (auto e = render::writePng((dir / (name + "-golden.png")).string(), r.expected); !e)
        return e;
    if (!r.comparison.same_size) continue;
    const render::Image diff =
        render::diffImage(r.image, r.expected, suite.cases[i].tolerance.channel);
    if (auto e = render::writePng((dir / (name + "-diff.png")).string(), diff); !e) return e;
  }
  return {};
}

rb::Status writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) return rb::Status::fault(path.string() + ": writing failed");
  return {};
}

}  // namespace

std::string reportFolder(const scene::SnapshotSuite& suite, const std::string& given) {
  if (!given.empty()) return given;
  const fs::path here = fs::path(suite.file).parent_path();
  return ((here.empty() ? fs::path(".") : here) / "snapshot-report").lexically_normal().string();
}

namespace {

// Where a report is written before it is moved into `folder`: beside it, named for this process.
fs::path reportTemporary(const std::string& folder) {
  const fs::path target = fs::path(folder).lexically_normal();
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  return parent / ("." + target.filename().string() + ".part-" + std::to_string(::getpid()));
}

}  // namespace

rb::Status checkReportFolder(const std::string& folder) {
  std::error_code ec;
  // The report is made beside its folder and moved in (writeReport). That place is tried
  // before any case is drawn (made, then removed with any folder made for it), so that a report
  // that cannot be written is bad input, not a failed suite told after the drawing.
  {
    const fs::path temp = reportTemporary(folder);
    std::vector<fs::path> missing;  // what making it makes, deepest first
    for (fs::path up = temp; !up.empty() && up != up.parent_path(); up = up.parent_path()) {
      if (fs::exists(fs::symlink_status(up, ec))) break;
      missing.push_back(up);
    }
    fs::create_directories(temp, ec);
    const std::error_code made = ec;
    for (const fs::path& m : missing)
      if (fs::is_directory(m, ec) && fs::is_empty(m, ec)) fs::remove(m, ec);
    if (made)
      return rb::Status::fail("--report " + folder + ": cannot make the report's folder: " +
                              made.message() + "; give --report a folder you can write to");
  }
  if (!fs::exists(folder, ec)) return {};
  if (!fs::is_directory(folder, ec))
    return rb::Status::fail("--report " + folder + ": is a file; give the report a folder");
  if (!fs::exists(fs::path(folder) / kMark, ec) && !fs::is_empty(folder, ec))
    return rb::Status::fail("--report " + folder +
                            ": is a folder of other files, not an earlier snapshot report, which "
                            "it would replace; give --report a new folder");
  return {};
}

rb::Status writeReport(const std::string& folder, const scene::SnapshotSuite& suite,
                       const std::vector<CaseResult>& results) {
  const fs::path target = fs::path(folder).lexically_normal();
  const fs::path temp = reportTemporary(folder);
  std::error_code ec;
  fs::create_directories(temp, ec);
  if (ec) return rb::Status::fail(folder + ": cannot make the report's folder: " + ec.message());
  auto written = writeImages(temp, suite, results);
  if (written) written = writeText(temp / "index.html", pageOf(suite, results));
  if (written) written = writeText(temp / kMark, "rattleback snapshot report\n");
  // The earlier report goes only once the new one is whole beside it.
  std::error_code moved;
  if (written && fs::exists(target, ec)) fs::remove_all(target, moved);
  if (written && !moved) fs::rename(temp, target, moved);
  if (!written || moved) fs::remove_all(temp, ec);
  if (!written) return written;
  if (moved)
    return rb::Status::fault(folder + ": cannot move the report into place: " + moved.message());
  return {};
}

bool removeReport(const std::string& folder) {
  std::error_code ec;
  if (!fs::exists(fs::path(folder) / kMark, ec)) return false;
  fs::remove_all(folder, ec);
  return !ec;
}

}  // namespace media

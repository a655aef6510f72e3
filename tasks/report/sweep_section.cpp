#include "tasks/report/sweep_section.hpp"

#include "tasks/report/html.hpp"
#include "tasks/report/sidecars.hpp"
#include "util/format.hpp"

namespace tasks::report {
namespace {

// The base scene as the sweep file names it, not as the machine that ran it resolved it (an
// absolute path of that machine); a sidecar from before `base_as_written` has only that.
std::string baseAsNamed(const nlohmann::json& meta) {
  const std::string written = stringOr(field(meta, "base_as_written"), "");
  return written.empty() ? stringOr(field(meta, "base"), "?") : written;
}

// The sweep's runs: the product of its axes' sizes.
long long sweepRows(const nlohmann::json& meta) {
  long long rows = 1;
  const nlohmann::json& axes = field(meta, "axes");
  for (std::size_t i = 0; axes.is_array() && i < axes.size(); ++i) {
    const nlohmann::json& values = field(axes[i], "values");
    rows *= values.is_array() ? static_cast<long long>(values.size()) : 0;
  }
  return rows;
}

// "N runs of <code>BASE</code> (the base scene of <code>FILE</code>) over ": which shard, where
// it is one not merged yet.
void writeWhat(std::ostream& out, const nlohmann::json& meta) {
  const nlohmann::json& shard = field(meta, "shard");
  out << number(field(meta, "rows"), "%g") << (field(meta, "rows") == 1 ? " run of " : " runs of ");
  if (shard.is_object())
    out << "the sweep's " << sweepRows(meta) << " (shard " << number(field(shard, "index"), "%g")
        << " of " << number(field(shard, "count"), "%g") << ", not merged here) of ";
  const std::string sweep_file = stringOr(field(meta, "sweep"), "");
  out << "<code>" << escape(baseAsNamed(meta)) << "</code>"
      << (sweep_file.empty() ? std::string()
                             : " (the base scene of <code>" +
                                   escape(fs::path(sweep_file).filename().string()) + "</code>)")
      << " over ";
}

// The axes: "<code>KEY</code> (N values) × …".
void writeAxes(std::ostream& out, const nlohmann::json& meta) {
  const nlohmann::json& axes = field(meta, "axes");
  for (std::size_t i = 0; axes.is_array() && i < axes.size(); ++i) {
    const nlohmann::json& values = field(axes[i], "values");
    out << (i ? " × " : "") << "<code>" << escape(stringOr(field(axes[i], "key"), "?"))
        << "</code> ("
        << rb::counted(values.is_array() ? static_cast<long long>(values.size()) : 0, "value")
        << ")";
  }
}

}  // namespace

void writeSweep(std::ostream& out, const SweepFiles& sweep) {
  out << "<section id=\"sweep-" << escape(sweep.name) << "\"><h2>Sweep: " << escape(sweep.name)
      << "</h2>\n<p>";
  writeWhat(out, sweep.meta);
  writeAxes(out, sweep.meta);
  out << ": <a href=\"" << url(sweep.csv) << "\">the table (CSV)</a>";
  if (!sweep.parts.empty()) {
    out << "; merged from " << sweep.parts.size() << " shard"
        << (sweep.parts.size() == 1 ? "" : "s") << ":";
    for (const std::string& part : sweep.parts)
      out << " <a href=\"" << url(part) << "\">" << escape(part) << "</a>";
  }
  // Heatmaps wider than the stills' grid (900 px drawn: at 300 their labels cannot be read).
  out << "</p><div class=\"grid wide\">\n";
  for (const std::string& image : sweep.images) writeFigure(out, image, "");
  out << "</div></section>\n";
}

}  // namespace tasks::report

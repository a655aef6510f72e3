#include "app/plot.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "app/interrupt.hpp"
#include "tasks/output.hpp"

extern char** environ;

namespace app {
namespace fs = std::filesystem;
namespace {

// A gnuplot double-quoted string: backslashes and quotes escaped (enhanced text is off).
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;  // gnuplot's own message is its last line
  return last;
}

// runGnuplot's outcomes besides an exit status.
constexpr int kGnuplotMissing = -1;
constexpr int kGnuplotInterrupted = -2;

// Runs `gnuplot script` with stderr into `log`; the exit status, 128 + the signal that ended it,
// kGnuplotMissing, or kGnuplotInterrupted (Ctrl-C or SIGTERM to this program: gnuplot is ended
// too, not waited for: a long run's figures could take ten minutes).
int runGnuplot(const fs::path& script, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  const std::string script_path = script.string();
  char* argv[] = {const_cast<char*>("gnuplot"), const_cast<char*>(script_path.c_str()), nullptr};
  // This program ignores SIGXFSZ (a write beyond a file-size limit is an error it reports); gnuplot
  // ignores write errors, so it gets the signal's default back: a PNG cut short by the limit ends
  // gnuplot, rather than standing as a finished figure.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGXFSZ);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t pid;
  const int spawned = posix_spawnp(&pid, "gnuplot", &actions, &attributes, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) return kGnuplotMissing;
  int status = 0;
  bool interrupted = false;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
    if (interruptSignal() != 0 && !interrupted) {
      ::kill(pid, SIGTERM);
      interrupted = true;
    }
  if (interrupted || interruptSignal() != 0) return kGnuplotInterrupted;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Whether the file is a whole PNG: it ends with the IEND chunk (its type, then its CRC).
bool wholePng(const fs::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  if (!in || size < 12) return false;
  char tail[8];
  in.seekg(size - 8);
  in.read(tail, 8);
  return in && std::string(tail, 4) == "IEND";
}

}  // namespace

namespace {

// Writes a file into `dir` and removes it: "" when that works, else the system's reason.
std::string probeWrite(const fs::path& dir) {
  const fs::path probe = dir / (".rattleback-probe-" + std::to_string(getpid()));
  std::ofstream test(probe);
  if (!test) return std::strerror(errno);
  test.close();
  std::error_code ec;
  fs::remove(probe, ec);
  return "";
}

// A plot is drawn into a temporary file and renamed into place: never onto a device or pipe.
rb::Status refuseDevice(const std::string& png, const rb::OutputPlace& place) {
  if (!place.temporary.empty()) return {};
  return rb::Status::fail(png + ": a plot is a PNG file, not written to a device or pipe");
}

}  // namespace

rb::Status checkPlotFolder(const std::string& dir, const std::string& first_figure,
                           tasks::MadeFolders* made) {
  std::error_code ec;
  // sweep, sweep merge and bench take `--plot FILE.png`: a simulate --plot named as an image
  // would otherwise become a folder of that name holding the four figures.
  std::string ext = fs::path(dir).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  for (const char* image :
       {".png", ".jpg", ".jpeg", ".svg", ".pdf", ".gif", ".webp", ".bmp", ".tif", ".tiff", ".eps"})
    if (ext == image && !fs::is_directory(dir, ec))
      return rb::Status::fail("--plot " + dir +
                              ": takes a folder for the four figures, not an image's name (e.g. " +
                              "--plot " + (fs::path(dir).parent_path() / "figures").string() + ")");
  // Said as every writer says it, of the first figure's file, with --plot's way out.
  const std::string figure = (fs::path(dir) / first_figure).string();
  const rb::OutputNamedBy naming("--plot", "a folder");
  if (auto ok = tasks::makeParentFolder(figure, made); !ok) return ok;
  if (std::string why = probeWrite(dir); !why.empty())
    return rb::Status::fail(rb::cannotWriteIn(figure, why));
  return {};
}

rb::Status checkPlotFile(const std::string& png, tasks::MadeFolders* made, const char* option) {
  std::error_code ec;
  if (fs::is_directory(png, ec))
    return rb::Status::fail(png + ": " + option + " is a folder, not a file");
  const rb::OutputNamedBy naming(option);
  // gnuplot draws a PNG whatever the name says (--plot x.jpg).
  if (auto ok = rb::checkExtension(png, ".png", "PNG", false); !ok) return ok;
  const rb::OutputPlace place = rb::outputPlace(png);
  if (auto refused = refuseDevice(png, place); !refused) return refused;
  if (auto ok = tasks::makeParentFolder(place.target, made); !ok) return ok;
  const fs::path dir = fs::absolute(place.target).parent_path();
  if (std::string why = probeWrite(dir); !why.empty())
    return rb::Status::fail(rb::cannotWriteIn(png, why));
  return {};
}

namespace {

// Runs the gnuplot script that `write` puts into a private temporary folder; the script is
// handed the folder (for its data files) and the temporary PNG beside `png` to draw into, which
// is renamed into place only when gnuplot succeeded.
template <typename Write>
rb::Status drawWithGnuplot(const std::string& png, Write write) {
  std::error_code ec;
  if (fs::is_directory(png, ec)) return rb::Status::fail(png + ": is a directory, not a file");
  const rb::OutputPlace place = rb::outputPlace(png);
  if (auto refused = refuseDevice(png, place); !refused) return refused;
  const fs::path parent = fs::absolute(place.target).parent_path();
  if (!fs::is_directory(parent, ec)) return rb::Status::fail(rb::cannotWriteIn(png, ENOENT));
  char pattern[] = "/tmp/rattleback-plot-XXXXXX";
  if (!mkdtemp(pattern))
    return rb::Status::fail(png + ": cannot make a temporary folder: " + std::strerror(errno));
  const fs::path work = pattern;
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove_all(dir, ignored);
    }
  } cleanup{work};
  const fs::path temp_png = place.temporary;
  std::ofstream script(work / "plot.gp");
  write(script, work, temp_png);
  script.close();
  if (!script) return rb::Status::fail(png + ": cannot write the plot script");
  const int status = runGnuplot(work / "plot.gp", work / "gnuplot.log");
  if (status == kGnuplotMissing) {
    fs::remove(temp_png, ec);
    return rb::Status::fault(png +
                             ": cannot run gnuplot (install it: apt-get install gnuplot-nox)");
  }
  if (status == kGnuplotInterrupted) {
    fs::remove(temp_png, ec);
    return rb::Status::fault(png + ": interrupted while drawing");
  }
  // Ended by a signal, or a PNG cut short: the machine's (a file-size limit, a full disk), said
  // as such; an error of gnuplot's own, its last line.
  if (status > 128) {
    fs::remove(temp_png, ec);
    return rb::Status::fault(png + ": gnuplot was ended by " +
                             (status - 128 == SIGXFSZ ? std::string("the file-size limit")
                                                      : "signal " + std::to_string(status - 128)) +
                             "; nothing written");
  }
  if (status != 0 || !fs::exists(temp_png, ec) || fs::file_size(temp_png, ec) == 0) {
    fs::remove(temp_png, ec);
    return rb::Status::fail(png + ": gnuplot failed: " + firstLine(work / "gnuplot.log"));
  }
  if (!wholePng(temp_png)) {
    fs::remove(temp_png, ec);
    return rb::Status::fault(png +
                             ": gnuplot wrote an incomplete PNG (a full disk, or a "
                             "file-size limit?); nothing written");
  }
  fs::rename(temp_png, place.target, ec);
  if (ec) {
    fs::remove(temp_png, ec);
    return rb::Status::fail(png + ": cannot move the finished plot into place: " + ec.message());
  }
  return {};
}

}  // namespace

// One series' data file and its plot clause; nothing when it has no point the axes can show.
std::optional<std::string> seriesClause(const Panel& panel, const Series& series,
                                        const fs::path& data) {
  std::ofstream out(data);
  out.precision(10);
  int kept = 0;
  bool gap = false;
  for (const auto& [x, y] : series.points) {
    // Log axes cannot show zero or negative values; gnuplot would refuse the series. A point
    // left out breaks the line there (gnuplot's blank line), so that the line does not join
    // its neighbours across it: a sweep's runs that did not reverse had been bridged by a
    // straight line, which read as a trend through them.
    if (!std::isfinite(x) || !std::isfinite(y) || (panel.log_x && x <= 0) ||
        (panel.log_y && y <= 0)) {
      gap = kept > 0;
      continue;
    }
    if (gap) out << '\n';  // one blank line: two would start another data set
    gap = false;
    out << x << ' ' << y << '\n';
    ++kept;
  }
  if (kept == 0) return std::nullopt;
  std::string style =
      panel.lines_only ? " with lines lw 1.5"
                       : " with linespoints lw 1.5 ps 0.9 pt " + std::to_string(series.point_type);
  style += " dt " + std::to_string(series.dash);
  if (!series.color.empty()) style += " lc rgb " + quoted(series.color);
  return quoted(data.string()) + " using 1:2" + (series.right_axis ? " axes x1y2" : "") + style +
         " title " + quoted(series.title);
}

// One panel of a multiplot: its axes, then its series (or "no data").
void writePanel(std::ostream& script, const Panel& panel, bool titled, const fs::path& work,
                int& file_index) {
  // A twentieth of the height above and below the data, so that a line at its top or bottom
  // (a conserved energy) is not drawn on the frame; none below an axis from 0.
  script << "unset logscale\nunset y2label\nunset y2tics\nset ytics mirror\n"
         << "set offsets 0, 0, graph 0.05, " << (panel.y_from_zero ? "0" : "graph 0.05") << "\n"
         << "set title " << quoted(titled ? panel.title : std::string()) << "\n"
         << "set xlabel " << quoted(panel.x_label) << "\nset ylabel " << quoted(panel.y_label)
         << "\n";
  script << (panel.log_x ? "set logscale x\nset format x '%g'\n" : "set format x '% g'\n");
  script << (panel.log_y ? "set logscale y\nset format y '%.0e'\n" : "set format y '% g'\n");
  script << (panel.y_from_zero ? "set yrange [0:*]\n" : "set autoscale y\n");
  if (!panel.y2_label.empty())
    script << "set y2label " << quoted(panel.y2_label) << "\nset y2tics\nset ytics nomirror\n";
  if (panel.x_range)
    script << "set xrange [" << panel.x_range->first << ":" << panel.x_range->second << "]\n";
  else
    script << "set autoscale x\n";
  if (!panel.note.empty())
    script << "set bmargin 5\nset label 90 " << quoted(panel.note)
           << " at screen 0.5, character 1 center\n";
  std::vector<std::string> clauses;
  for (const Series& series : panel.series) {
    const fs::path data = work / ("series" + std::to_string(file_index++) + ".dat");
    if (auto clause = seriesClause(panel, series, data)) clauses.push_back(*clause);
  }
  if (clauses.empty()) {
    script << "unset logscale\nset label 1 'no data' at graph 0.5, graph 0.5 center\n"
           << "plot [0:1][0:1] NaN notitle\nunset label 1\nunset label 90\nunset bmargin\n";
    return;
  }
  // Each mark's label right of its line, or left of one in the last fifth of the data's x
  // range (it would run off the frame); every other one a line lower, so that neighbours'
  // labels do not run into each other.
  double x_lo = INFINITY, x_hi = -INFINITY;
  for (const Series& series : panel.series)
    for (const auto& [x, y] : series.points)
      if (std::isfinite(x)) x_lo = std::min(x_lo, x), x_hi = std::max(x_hi, x);
  for (std::size_t i = 0; i < panel.marks.size(); ++i) {
    const Mark& mark = panel.marks[i];
    if (!std::isfinite(mark.x)) continue;
    const bool late = mark.x > x_hi - (x_hi - x_lo) / 5;
    script << "set arrow " << i + 1 << " from first " << mark.x << ", graph 0 to first " << mark.x
           << ", graph 1 nohead dt 2 lw 1.5 lc rgb '#e6550d' front\n"
           << "set label " << i + 2 << " " << quoted(mark.label) << " at first " << mark.x
           << ", graph " << (i % 2 ? 0.91 : 0.97) << " "
           << (late ? "right offset -0.5, 0" : "left offset 0.5, 0") << " tc rgb '#e6550d' front\n";
  }
  script << "plot ";
  for (std::size_t i = 0; i < clauses.size(); ++i) script << (i ? ", \\\n     " : "") << clauses[i];
  script << "\n";
  if (!panel.marks.empty()) script << "unset arrow\nunset label\n";
  if (!panel.note.empty()) script << "unset label 90\nunset bmargin\n";
}

bool logarithmicAxis(const std::vector<double>& values) {
  if (values.size() < 3) return false;
  for (double v : values)
    if (!(v > 0) || !std::isfinite(v)) return false;
  const double ratio = values[1] / values[0];
  // Ratios equal within 1e-9: the values are the sweep's own, written to round trip.
  for (std::size_t i = 1; i + 1 < values.size(); ++i)
    if (std::abs(values[i + 1] / values[i] / ratio - 1) > 1e-9) return false;
  const double span = values.back() / values.front();
  return span > 10 || span < 0.1;
}

rb::Status plotPng(const std::string& png, const std::string& title,
                   const std::vector<Panel>& panels, int width, int height) {
  return drawWithGnuplot(png, [&](std::ofstream& script, const fs::path& work,
                                  const fs::path& temp_png) {
    // Tic labels' minus signs as U+2212, as the heatmap's (ticLabel): the hyphen is shorter
    // than a digit's width and reads as a dash.
    script << "set encoding utf8\nset minussign\n"
           << "set terminal pngcairo size " << width << "," << height
           << " font \"DejaVu Sans,10\" noenhanced\n"
           << "set output " << quoted(temp_png.string()) << "\n"
           << "set datafile separator ' '\nset grid lc rgb '#dddddd'\nset key outside right top\n"
           << "set multiplot layout " << panels.size() << ",1 title " << quoted(title)
           << " font \",12\"\n";
    int file_index = 0;
    for (const Panel& panel : panels)
      writePanel(script, panel, panels.size() > 1, work, file_index);
    script << "unset multiplot\nset output\n";
  });
}

namespace {

// A tic label as printed: a number's minus signs as U+2212 (the font's hyphen is a short dash
// that, rotated, reads as "`6"); any other label as it is.
std::string ticLabel(const std::string& value) {
  char* end = nullptr;
  (void)std::strtod(value.c_str(), &end);
  if (value.empty() || end != value.c_str() + value.size()) return value;
  std::string out;
  for (char c : value) out += c == '-' ? std::string("\xE2\x88\x92") : std::string(1, c);
  return out;
}

// The labels of an axis's values: each number with the fewest significant digits that keep all the
// axis's values apart and each within 1 % of itself, in %g's form with the exponent's zeros and
// plus dropped ("3.16e-7"), or as written where that is no longer: a log axis's values come as
// 3.16227766017e-07, 18 characters that had to be turned and ran into the axis title. Text that is
// not a number stays as it is.
std::vector<std::string> axisLabels(const std::vector<std::string>& values) {
  std::vector<std::optional<double>> numbers;
  for (const std::string& v : values) {
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    numbers.push_back(!v.empty() && end == v.c_str() + v.size() && std::isfinite(x)
                          ? std::optional(x)
                          : std::nullopt);
  }
  auto shortest = [](double x, int digits) {
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    std::string s = text;
    const std::size_t e = s.find('e');
    if (e == std::string::npos) return s;
    std::string exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    return s.substr(0, e + 1) + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
  };
  for (int digits = 1; digits <= 17; ++digits) {
    std::vector<std::string> labels;
    bool close = true;
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!numbers[i]) {
        labels.push_back(values[i]);
        continue;
      }
      // As written where that is no longer ("-10", not "-1e1").
      const std::string made = shortest(*numbers[i], digits);
      labels.push_back(values[i].size() <= made.size() ? values[i] : made);
      const double shown = std::strtod(labels.back().c_str(), nullptr);
      close = close && std::abs(shown - *numbers[i]) <= 0.01 * std::abs(*numbers[i]);
    }
    std::vector<std::string> sorted = labels;
    std::sort(sorted.begin(), sorted.end());
    if (close && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return labels;
  }
  return values;
}

}  // namespace

void writeHeatmapScript(std::ostream& script, const Heatmap& map, const fs::path& work,
                        const fs::path& temp_png, int width, int height) {
  const std::size_t nx = map.x_values.size(), ny = map.y_values.size();
  // At most about a dozen labels on an axis: every k-th value, each as axisLabels gives it.
  auto shown = [](const std::vector<std::string>& values) {
    std::vector<std::pair<std::string, std::size_t>> tics;
    const std::vector<std::string> labels = axisLabels(values);
    const std::size_t every = std::max<std::size_t>(1, (values.size() + 11) / 12);
    for (std::size_t i = 0; i < values.size(); i += every) tics.emplace_back(labels[i], i);
    return tics;
  };
  auto list = [](const std::vector<std::pair<std::string, std::size_t>>& tics) {
    std::string text;
    for (const auto& [label, i] : tics)
      text += (text.empty() ? "" : ", ") + quoted(ticLabel(label)) + " " + std::to_string(i);
    return "(" + text + ")";
  };
  // The x labels level when each fits its column (10-point DejaVu Sans: about 7 pixels a
  // character, the map about three quarters of the width); turned by 30° only when they would
  // run into each other.
  const auto x_tics = shown(map.x_values);
  std::size_t longest = 0;
  for (const auto& tic : x_tics) longest = std::max(longest, tic.first.size());
  const double column = 0.75 * width / std::max<std::size_t>(1, x_tics.size());
  const bool rotate = 7.0 * static_cast<double>(longest) + 8.0 > column;
  script
      << "set terminal pngcairo size " << width << "," << height
      << " font \"DejaVu Sans,10\" noenhanced\n"
      << "set output " << quoted(temp_png.string()) << "\n"
      << "set title " << quoted(map.title) << "\n"
      << "set xlabel " << quoted(map.x_label) << "\nset ylabel " << quoted(map.y_label) << "\n"
      << "set cblabel " << quoted(map.value_label) << "\n"
      << "set xtics " << list(x_tics) << (rotate ? " rotate by -30" : "") << "\n"
      << "set ytics " << list(shown(map.y_values)) << "\n"
      << "set xrange [-0.5:" << nx - 0.5 << "]\nset yrange [-0.5:" << ny - 0.5
      << "]\n"
      // Viridis (perceptually uniform, readable in grey and by colour-blind readers).
      << "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n"
      << "set object 1 rectangle from graph 0,0 to graph 1,1 behind fc rgb '#c8c8c8' fs solid\n";
  // The note on a line of its own under the axis title, centred: the bottom margin grows by
  // two lines to hold it, and by the turned labels' depth (a 30° turn drops a label by half its
  // length: 3.5 pixels a character, against lines of about 15).
  const int label_lines =
      rotate ? static_cast<int>(std::ceil(3.5 * static_cast<double>(longest) / 15.0)) : 1;
  if (!map.note.empty())
    script << "set bmargin " << 5 + label_lines << "\n"
           << "set label 1 " << quoted(map.note) << " at screen 0.5, character 1 center\n";
  bool any = false;
  for (double v : map.values) any = any || std::isfinite(v);
  if (!any) script << "set cbrange [0:1]\n";
  script << "plot " << quoted((work / "map.dat").string()) << " matrix with image notitle\n"
         << "set output\n";
}

rb::Status heatmapPng(const std::string& png, const Heatmap& map, int width, int height) {
  return drawWithGnuplot(
      png, [&](std::ofstream& script, const fs::path& work, const fs::path& temp_png) {
        // The data as gnuplot's matrix: one line per y value, one column per x value; NaN for a
        // cell without a value, which shows the grey background.
        const std::size_t nx = map.x_values.size(), ny = map.y_values.size();
        std::ofstream data(work / "map.dat");
        data.precision(10);
        for (std::size_t iy = 0; iy < ny; ++iy) {
          for (std::size_t ix = 0; ix < nx; ++ix) {
            const double v = map.values[ix * ny + iy];
            data << (ix ? " " : "");
            if (std::isfinite(v))
              data << v;
            else
              data << "NaN";
          }
          data << "\n";
        }
        writeHeatmapScript(script, map, work, temp_png, width, height);
      });
}

}  // namespace app

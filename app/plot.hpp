// Figures drawn by gnuplot (Debian's gnuplot-nox), driven by the program: the data go to a
// private temporary folder, gnuplot writes a PNG under a temporary name beside the target,
// and it is renamed into place only when gnuplot succeeded.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "util/result.hpp"

namespace tasks {
class MadeFolders;
}

namespace app {

struct Series {
  std::string title;
  std::vector<std::pair<double, double>> points;
  bool right_axis = false;  ///< plotted against the panel's second y axis
  std::string color;        ///< "#rrggbb"; empty: gnuplot's next colour
  int point_type = 7;       ///< gnuplot point type (7 disc, 5 square, 9 triangle, 13 diamond)
  int dash = 1;             ///< gnuplot dash type (1 solid)
};

/// A moment marked across a panel: a dashed vertical line at x, labelled at its top.
struct Mark {
  double x = 0;
  std::string label;
};

struct Panel {
  std::string title, x_label, y_label, y2_label;
  std::vector<Mark> marks;  ///< e.g. the spin's reversals
  bool log_x = false, log_y = false;
  bool lines_only = false;   ///< no point markers (time series)
  bool y_from_zero = false;  ///< a quantity never negative (a tilt): its axis starts at 0
  /// The x axis's span when it is not the data's (a sweep's axis, where some values have no
  /// point); absent: the data's.
  std::optional<std::pair<double, double>> x_range;
  std::string note;  ///< a line under the panel (what a missing point means); "": none
  std::vector<Series> series;
};

/// Whether values are best drawn on a logarithmic axis: three or more, all positive, each a
/// constant ratio to the one before (a sweep axis with `scale: log`, or values listed by
/// powers), spanning more than a factor of 10. On a linear axis all but the last few of them
/// crowd at its left.
bool logarithmicAxis(const std::vector<double>& values);

/// A sweep plot's label for a varied key or a result column: the name with its unit,
/// "initial.spin [rad/s]" (the schema's unit; none for a count). A length in file units takes
/// the base scene's unit, `length_unit` m ("body.dents.at[0] [cm]" at 0.01), none when 0.
std::string sweepLabel(const std::string& name, double length_unit = 0);

/// Makes `dir` when missing and checks that a file can be written into it (before a run whose
/// plots go there); otherwise the error line every writer gives, for `first_figure` (a file
/// name) in `dir`, with --plot's way out. The folders it made are added to `made`, when given.
rb::Status checkPlotFolder(const std::string& dir, const std::string& first_figure,
                           tasks::MadeFolders* made = nullptr);
/// The same for one PNG: its folder made when missing and a file written into it and removed,
/// so that an unwritable --plot fails before the run, not after it. The folders made are added
/// to `made`, when given. `option` names the PNG in messages (compare's --diff uses it too).
rb::Status checkPlotFile(const std::string& png, tasks::MadeFolders* made = nullptr,
                         const char* option = "--plot");

/// Draws the panels stacked top to bottom into one PNG of width × height pixels.
/// Returns one error line naming `png` on failure; an existing `png` is then left as it was.
rb::Status plotPng(const std::string& png, const std::string& title,
                   const std::vector<Panel>& panels, int width, int height);

/// One panel's part of plotPng's gnuplot script: its axes, marks and series (their data
/// written into `work`/series<file_index>.dat, file_index counting on).
void writePanel(std::ostream& script, const Panel& panel, bool titled,
                const std::filesystem::path& work, int& file_index);

/// A map of values over two axes (a sweep's first two), drawn as coloured cells.
struct Heatmap {
  std::string title, x_label, y_label, value_label;
  std::vector<std::string> x_values, y_values;  ///< labels of the columns and the rows
  std::vector<double> values;  ///< values[ix · y_values.size() + iy]; NaN: no value (grey)
  std::string note;            ///< a line under the map (what grey means, fixed axes)
};

/// Draws `map` into a PNG of width × height pixels, as plotPng.
rb::Status heatmapPng(const std::string& png, const Heatmap& map, int width, int height);
/// The gnuplot script heatmapPng runs (its data in `work`/map.dat, drawn into `temp_png`).
void writeHeatmapScript(std::ostream& script, const Heatmap& map, const std::filesystem::path& work,
                        const std::filesystem::path& temp_png, int width, int height);

}  // namespace app

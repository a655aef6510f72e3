// Sweep files (YAML): a base scene and axes of values for any of its keys; the sweep is the
// product of the axes, first axis slowest (docs/scenes.md "Sweep files"). Errors name file, line
// and key, as for scenes.
//
//   base: ../scenes/rattleback.yaml        # relative to the sweep file
//   vary:
//     initial.spin: {from: -10, to: 10, count: 41}
//     contact.air_drag: [0.0, 5.9e-6, 5.9e-5]
//     body.dents.at[0]: {from: 0.1, to: 1.0, count: 10, scale: log}
//   duration: 8.0                           # optional: simulation.duration of every run
//   columns: [first_reversal_s]             # optional: the result columns to compute
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "util/result.hpp"

namespace scene {

struct SweepAxis {
  std::string key;    ///< dotted scene key, optionally ending in [i] for an element of a list
  std::string place;  ///< "sweeps/x.yaml:4", where the axis is written
  /// Each value as YAML flow text: what goes into the scene, and into the table.
  std::vector<std::string> values;
  /// Whether the key belongs to the body (body.*, units.*): runs that share the values of all
  /// such axes share one compiled body.
  bool body = false;
};

/// A result column a sweep lists (`columns:`), where it is listed. Which names are columns is
/// the table's to say (tasks/sweep_columns.hpp): the reader checks the list's form only.
struct SweepColumnName {
  std::string name;
  rb::Error::Where where;  ///< the file (or "argument columns"), the line (0: none), "columns"
};

struct Sweep {
  std::string file;  ///< as given
  std::string base;  ///< the base scene's path (resolved against the sweep file's folder)
  std::string base_as_written;  ///< the base scene's path as the sweep file writes it
  std::vector<SweepAxis> axes;
  /// The base scene's text as read, and values put in over it (Python's Scene.with_values): the
  /// scene every row starts from.
  std::string base_text;
  std::vector<KeyValue> base_values;
  std::optional<double> duration;  ///< s; overrides simulation.duration
  /// The result columns the table holds, as `columns:` lists them; empty: the default table.
  std::vector<SweepColumnName> columns;
  double length_unit = 1;  ///< m per length unit of the base scene (units.length)
  /// What a read of the files found, kept so that nothing reads or parses them again (each parse
  /// of a scene by yaml-cpp is a tenth of a millisecond or more, in every sweep's start-up):
  /// the sweep file's and the base scene's content (scene::yamlContent of each), empty for a
  /// sweep without a file (Python's), and the base file's keys' lines.
  std::string file_content, base_content;
  std::optional<std::map<std::string, int>> base_lines;

  /// The number of runs: the product of the axes' sizes.
  std::int64_t rows() const;
  /// Which value of each axis row `row` takes (first axis slowest).
  std::vector<int> coordinates(std::int64_t row) const;
  /// Rows that share a body have the same body group (0 … bodyGroups() − 1).
  std::int64_t bodyGroup(std::int64_t row) const;
  std::int64_t bodyGroups() const;
};

/// Reads and checks a sweep file: its keys, the base scene (which must load), each axis key
/// (which must be a scene key), and each range. A value that makes one scene invalid is not an
/// error here: that run is refused when it is built.
rb::Result<Sweep> loadSweep(const std::string& path);

/// The base of a sweep made without a sweep file (Python's sweep(scene, vary=…)): a scene's text,
/// its name (its file's path, or what stands for it in messages) and values put in over it.
struct SweepBase {
  std::string yaml;
  std::string name;
  std::vector<KeyValue> values;
};

/// A sweep written as YAML text with the keys vary and duration (no base: `base` is it), as a
/// sweep file's; `name` stands for the text in messages, which name no line.
rb::Result<Sweep> loadSweepText(const std::string& yaml, const std::string& name,
                                const SweepBase& base);

/// The scenes of a sweep: the base parsed once, then for each row a copy with one value of
/// each axis put in. Safe to use from several threads.
class SweepScenes {
 public:
  static rb::Result<SweepScenes> open(const Sweep& sweep);
  SweepScenes(SweepScenes&&) noexcept;
  ~SweepScenes();

  /// The scene of `row`, or why it is refused (one line naming the sweep file's line for a
  /// varied key, the base scene's for the others).
  rb::Result<Loaded> scene(std::int64_t row) const;
  /// The same scene made the long way, through a copy of the base's YAML tree with the row's
  /// values put in: what scene() gives for a row it cannot make directly (scene/direct_rows.hpp);
  /// the tests compare the two.
  rb::Result<Loaded> sceneFromTree(std::int64_t row) const;

 private:
  struct Impl;
  explicit SweepScenes(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace scene

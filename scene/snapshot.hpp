// Snapshot suites (YAML): a folder of golden images and the cases drawn to compare with them
// (docs/testing.md "Snapshot tests in your CI"). Errors name file, line and key, as a scene's do.
//
//   goldens: goldens              # folder of NAME.png, relative to this file (default goldens)
//   size: 640x360                 # defaults for every case: view, size, backend, tolerances
//   cases:
//     - {name: spun-cw, scene: ../scenes/rattleback.yaml, t: reversal, view: oblique}
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/run_time.hpp"
#include "util/picture.hpp"  // views, backends and render::Tolerance
#include "util/result.hpp"

namespace scene {

/// What a key of a suite file takes.
enum class SnapshotKind {
  Folder,
  Cases,
  Name,
  Scene,
  Time,
  Title,
  View,
  Size,
  Backend,
  Channel,
  Fraction,
  Side
};
/// Where a key may stand: at the top (for the whole suite or as every case's default), in a
/// case, or both (a case's own value over the top's).
enum class SnapshotWhere { Top, Case, Both };

/// One key of the suite file: the reader takes each map's allowed keys and its messages from
/// this table, and `rattleback snapshot --help` lists it (so docs/commands-reference.md does).
struct SnapshotKey {
  std::string_view name;
  SnapshotKind kind;
  SnapshotWhere where;
  std::string_view help;  ///< one line: what it is, its default
};

std::span<const SnapshotKey> snapshotKeys();

struct SnapshotCase {
  std::string name;   ///< its golden is GOLDENS/NAME.png
  std::string place;  ///< "suite.yaml:7", where the case begins (for messages)
  int line = 0;       ///< 7: the line of `place`
  std::string scene;  ///< the scene's path, resolved against the suite file's folder
  std::string scene_as_written;
  sim::RunTime t;
  std::string t_text = "0";  ///< as written
  std::optional<render::View> view;
  std::optional<std::array<int, 2>> size;
  /// "suite.yaml:1" where the suite's top gave `size` to every case; empty where the case gives
  /// its own (or none is given).
  std::string top_size_place;
  /// Not given: the runner's default ($RATTLEBACK_BACKEND for the command line, else auto).
  std::optional<render::Backend> backend;
  std::optional<std::string> title;  ///< the frame's title; default the case's name
  render::Tolerance tolerance;
};

struct SnapshotSuite {
  std::string file;     ///< as given
  std::string goldens;  ///< the goldens' folder, resolved against the file's folder
  std::vector<SnapshotCase> cases;
};

/// Reads and checks a suite file (its keys, values and case names; not the scenes, which the
/// runner loads). One line naming file, line and key for anything wrong.
rb::Result<SnapshotSuite> loadSnapshotSuite(const std::string& path);
/// The same from text (`path` names it in messages and anchors relative paths).
rb::Result<SnapshotSuite> parseSnapshotSuite(const std::string& text, const std::string& path);

}  // namespace scene

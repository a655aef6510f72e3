// Scene files (YAML) → sim::SceneSpec. The only code that knows YAML. Every error names
// the file, the line and the key: "scenes/x.yaml:12: contact.friction must be ≥ 0, not -1".
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "sim/compile.hpp"
#include "sim/spec.hpp"
#include "util/result.hpp"

namespace scene {

/// The largest frame rate accepted, frames per second of video.
inline constexpr int kMaxFps = 240;

/// The scene file's `video` section, as written: read only by the commands that draw
/// (render, still), which check it (app/video_plan). Simulating never looks at it.
struct VideoSpec {
  int fps = 30;                        ///< frames per second of video, 1 … 240
  std::array<int, 2> size{1280, 720};  ///< pixels
  std::string view = "oblique";        ///< oblique | above | front | side | follow
  /// Playback speed as players mean it: simulated seconds per second of video (0.5 = slow
  /// motion, 2 = twice as fast).
  double playback = 1.0;
  /// The length of body every view is framed for, in the file's length unit; unset (NaN): the
  /// body's own, so that each body fills the picture. Bodies drawn with the same value are
  /// drawn at one scale, on the same floor squares.
  double frame = sim::kUnset;
  std::string surface = "points";  ///< points | triangles: how the body is drawn
};

/// A value for a dotted scene key ("initial.spin", "body.dents.at[1]"), as YAML flow text
/// ("-5", "[0.5, 0.5]", "rk4").
struct KeyValue {
  std::string key;
  std::string yaml;
};

/// A parsed scene and where each of its keys sits.
struct Loaded {
  sim::SceneSpec spec;
  VideoSpec video;
  std::string file;                              ///< as given, for messages
  std::map<std::string, int> lines;              ///< dotted key → 1-based line
  std::map<std::string, std::string> overrides;  ///< dotted key → the option that set it
  /// The values put in over the text (loadWithValues: --set, Python's with_values), in order:
  /// with the file they make the scene as run (a telemetry sidecar records them).
  std::vector<KeyValue> values;
  /// The file's content as read, before any values were put in (yamlContent's text): what a
  /// telemetry sidecar's scene_fingerprint is of, taken when the scene was read, so that a file
  /// edited while the run goes on (or before Python's to_csv) does not stand for the run's.
  std::string content;
};

/// The values put in, as a message names them: each key once, at its last value (a key put in
/// twice holds the last), a long value cut short, joined by ", " with `equals` between key and
/// value ("contact.air_drag=0, body.inertia=[[6.46e-07, …").
std::string valuesSaid(const std::vector<KeyValue>& values, const std::string& equals);

/// The files the scene was made from: its own (when it has one) and the mesh its body reads,
/// as paths from here, so that no output is written over one of them.
std::vector<std::string> filesRead(const Loaded& loaded);

/// Errors come back as rb::Error with an empty key and one line, ready to print:
/// "file:line: key message".
rb::Result<Loaded> loadFile(const std::string& path);
/// The text of a scene file, or why it cannot be read (a folder, missing, unreadable).
rb::Result<std::string> readSceneFile(const std::string& path);
/// `name` stands for the file in messages.
rb::Result<Loaded> loadString(const std::string& yaml, const std::string& name);

/// The 1-based line of the last `{` or `[` in YAML text that is never closed (outside quotes
/// and comments), or 0. yaml-cpp reports an unclosed flow map or list ("end of map flow not
/// found") at the end of the file, where nothing is wrong; this is the line to name.
int unclosedFlowLine(const std::string& text);

/// A YAML text's content without its comments and layout (yaml-cpp's own emitting of what it
/// read), or the text itself when it is no YAML: two texts that differ only in comments, blank
/// lines or indentation give the same.
std::string yamlContent(const std::string& text);

/// "file:line: key message" for an error found in a loaded scene (by compile() or a video
/// check); a key set from the command line is named by its option instead.
std::string describe(const Loaded& loaded, const rb::Error& error);
/// The same line as an error whose `where` holds the file (or option), line and key.
rb::Error locate(const Loaded& loaded, const rb::Error& error);

/// As loadString, with each value put at its key first; an error in one of them names `place`
/// ("with_values") and the key. `mesh`, when given, stands for body.mesh.file's triangles
/// (loadTree).
rb::Result<Loaded> loadWithValues(const std::string& yaml, const std::string& name,
                                  const std::vector<KeyValue>& values, const std::string& place,
                                  std::shared_ptr<const sim::TriangleMesh> mesh = nullptr);

/// The YAML text of `yaml` with each value put at its key, as loadWithValues puts them (its
/// comments and layout are yaml-cpp's own); an error names `place` and the key.
rb::Result<std::string> yamlWithValues(const std::string& yaml, const std::string& name,
                                       const std::vector<KeyValue>& values,
                                       const std::string& place);

/// compile() of a loaded scene, with any error as one line.
rb::Result<sim::Model> loadModel(const Loaded& loaded);

}  // namespace scene

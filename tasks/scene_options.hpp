// The options that set a scene key (--dt sets simulation.dt, …), declared once: each one's name,
// the key it sets, the kind of value it takes and its help. The command line's options, the
// overrides put into a loaded scene, their messages and Python's keyword arguments all loop over
// this table, so an option that sets a key is one row here (and its place among a command's
// options).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/loader.hpp"

namespace tasks {

enum class SceneOption {
  Duration,
  Dt,
  Tolerance,
  Integrator,
  Spin,
  Playback,
  View,
  Frame,
  Size,
  Fps,
  Surface
};

/// The value an option takes.
enum class OptionKind {
  Number,  ///< a double (the key's unit)
  Name,    ///< a word the key's name table checks (an integrator, a view)
  Size,    ///< width and height in pixels ("1280x720" on the command line, (w, h) in Python)
};

struct OptionValue;

struct SceneOptionRow {
  SceneOption option;
  const char* name;  ///< "dt": --dt on the command line, the keyword dt in Python
  const char* key;   ///< the scene key it sets, "simulation.dt"
  OptionKind kind;
  const char* help;  ///< what it sets, for --help (a command may say more of its own use)
  /// Refused unless finite: NaN is the scene's own "not given" (sim::kUnset), so a NaN given
  /// here would read as no value at all.
  bool finite = false;
  /// Puts the value into the loaded scene (its spec or its video settings).
  void (*apply)(scene::Loaded& scene, const OptionValue& value) = nullptr;
};

/// Every option that sets a scene key.
std::span<const SceneOptionRow> sceneOptions();
const SceneOptionRow& rowOf(SceneOption option);

/// A value given to an option (the member of its kind).
struct OptionValue {
  double number = 0;
  std::string name;
  std::array<int, 2> size{};
  /// Where messages say it was given, in place of Overrides::option_prefix ("" for that): a
  /// snapshot suite's top-level size is every case's, and is named at its own line.
  std::string prefix;
};

struct Overrides {
  /// The options given, by option.
  std::map<SceneOption, OptionValue> given;
  /// Scene keys and their values (YAML) put into the file before the options ("--set").
  std::vector<scene::KeyValue> values;
  /// How messages name an option: "--" + "dt" on the command line, "argument " + "dt" in
  /// Python. Either way the option is named alone, not with the key it sets.
  std::string option_prefix = "--";

  bool has(SceneOption o) const { return given.count(o) > 0; }
  void set(SceneOption o, double number) { given[o].number = number; }
  void set(SceneOption o, std::string name) { given[o].name = std::move(name); }
  void set(SceneOption o, std::array<int, 2> size) { given[o].size = size; }
  std::optional<double> number(SceneOption o) const;
};

}  // namespace tasks

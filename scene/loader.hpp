// Scene files (YAML) → sim::SceneSpec. The only code that knows YAML. Every error names
// the file, the line and the key: "scenes/x.yaml:12: contact.friction must be ≥ 0, not -1".
#pragma once

#include <map>
#include <set>
#include <string>
#include <variant>

#include "sim/compile.hpp"
#include "sim/spec.hpp"

namespace scene {

/// A parsed scene and where each of its keys sits.
struct Loaded {
  sim::SceneSpec spec;
  std::string file;                  ///< as given, for messages
  std::map<std::string, int> lines;  ///< dotted key → 1-based line
  std::map<std::string, std::string> overrides;  ///< dotted key → the option that set it
};

/// One line, ready to print: "file:line: key message".
struct LoadError {
  std::string message;
};

std::variant<Loaded, LoadError> loadFile(const std::string& path);
/// `name` stands for the file in messages.
std::variant<Loaded, LoadError> loadString(const std::string& yaml, const std::string& name);

/// "file:line: key message" for an error compile() found in a loaded scene; a key set from
/// the command line is named by its option instead.
std::string describe(const Loaded& loaded, const sim::SpecError& error);

/// loadFile + compile, with any error as one line.
std::variant<sim::Model, LoadError> loadModel(const Loaded& loaded);

}  // namespace scene

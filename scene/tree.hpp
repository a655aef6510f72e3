// Inside scene/: loading a scene from a YAML tree that was built or changed in code (a sweep's
// copies of its base scene). Only scene/ includes yaml-cpp.
#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <memory>
#include <string>

#include "scene/loader.hpp"

namespace scene {

/// The 1-based line of a node in its file (1 for a node built in code).
inline int lineOf(const YAML::Node& node) {
  return node.Mark().is_null() ? 1 : node.Mark().line + 1;
}

/// `text` on one line, whatever it holds: control characters (a newline in a quoted key, a NUL
/// byte, an escape yaml-cpp quotes back) shown escaped.
std::string printable(const std::string& text);

/// "NAME:LINE: malformed YAML: …" for a parse error in `text` (an unclosed bracket named at
/// the line that opened it).
rb::Error malformedYaml(const std::string& name, const std::string& text, const YAML::Exception& e);

/// `text` as one line: control characters (a newline in a quoted key, a NUL byte) escaped.
std::string printable(const std::string& text);

/// As loadString, from a parsed tree. `places` maps dotted keys that were set from elsewhere
/// to where ("sweeps/x.yaml:4"): an error in such a key (or inside it) names that place.
/// `lines` gives the lines of the keys of a tree copied from a file (the copy has none). `mesh`,
/// when given, is a mesh body's triangles held in memory (Python's Scene.from_mesh): it stands
/// for body.mesh.file's, which is then not read.
rb::Result<Loaded> loadTree(const YAML::Node& root, const std::string& name,
                            const std::map<std::string, std::string>& places,
                            const std::map<std::string, int>& lines = {},
                            std::shared_ptr<const sim::TriangleMesh> mesh = nullptr);

/// As loadString, the parsed text left in `tree` for a caller that reads it further (a sweep's
/// base), so that it is not parsed twice.
rb::Result<Loaded> loadString(const std::string& yaml, const std::string& name, YAML::Node& tree);

}  // namespace scene

// Inside scene/: dotted scene keys ("body.dents.at[1]") and putting a value at one in a YAML
// tree: what a sweep's axes and Python's Scene.with_values() both do to a scene.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace scene {

// A key split into its dotted parts and an optional list index: "body.dents.at[1]" →
// {body, dents, at}, 1.
struct KeyPath {
  std::vector<std::string> parts;
  std::optional<std::size_t> index;
};

inline std::optional<KeyPath> splitKey(const std::string& key) {
  KeyPath path;
  std::string name = key;
  if (!name.empty() && name.back() == ']') {
    const auto open = name.rfind('[');
    if (open == std::string::npos) return std::nullopt;
    const std::string digits = name.substr(open + 1, name.size() - open - 2);
    if (digits.empty() || digits.size() > 3 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      return std::nullopt;
    path.index = std::stoul(digits);
    name = name.substr(0, open);
  }
  std::size_t start = 0;
  while (true) {
    const auto dot = name.find('.', start);
    const std::string part = name.substr(start, dot == std::string::npos ? dot : dot - start);
    if (part.empty()) return std::nullopt;
    path.parts.push_back(part);
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return path;
}

inline std::string withoutIndex(const std::string& key) {
  const auto open = key.rfind('[');
  return key.back() == ']' && open != std::string::npos ? key.substr(0, open) : key;
}

// Puts `value` at `path` in `node`, making the maps on the way when they are missing. The
// caller has checked that an indexed list exists and is long enough.
inline void put(YAML::Node node, const KeyPath& path, std::size_t depth, const YAML::Node& value) {
  const std::string& part = path.parts[depth];
  if (depth + 1 == path.parts.size()) {
    if (path.index)
      node[part][*path.index] = value;
    else
      node[part] = value;
    return;
  }
  if (!node[part].IsMap()) node[part] = YAML::Node(YAML::NodeType::Map);
  put(node[part], path, depth + 1, value);
}

// A step set on top of a scene (`given`: the keys set, without indices) replaces the scene's
// tolerance, and a tolerance its step, as --dt and --tolerance do on the command line: a scene
// has exactly one of them, and one given with the other is left for the loader to refuse. The
// scene's integrator goes with what it replaced (rk4 takes no tolerance, dopri5 no step), unless
// one is given too: the default for the new setting follows, as with the options.
// The start's motion likewise: initial.spin is the shortcut for initial.angular_velocity
// [0, 0, n], and one set on top of a scene that gives the other replaces it (the default scene's
// spin had left with_values {initial.angular_velocity: …} refused, with no key to remove it by).
template <typename Keys>
void replaceAlternatives(YAML::Node root, const Keys& given) {
  for (const auto& [set, other] :
       {std::pair{"simulation.dt", "tolerance"}, std::pair{"simulation.tolerance", "dt"}}) {
    if (!given.count(set) || given.count(std::string("simulation.") + other) ||
        !root["simulation"].IsMap() || !root["simulation"][other])
      continue;
    root["simulation"].remove(other);
    if (!given.count("simulation.integrator")) root["simulation"].remove("integrator");
  }
  for (const auto& [set, other] : {std::pair{"initial.angular_velocity", "spin"},
                                   std::pair{"initial.spin", "angular_velocity"}}) {
    if (given.count(set) && !given.count(std::string("initial.") + other) &&
        root["initial"].IsMap() && root["initial"][other])
      root["initial"].remove(other);
  }
}

// A copy of the node at `path` without its index, or an undefined node. The walk reads through
// const nodes (yaml-cpp's non-const [] keeps the key it looked for, and assigning to a node
// found changes the tree it is in), and only the node found is copied: copying the whole tree
// at each call had cost a sweep's start-up as much as parsing its base scene.
inline YAML::Node find(const YAML::Node& root, const KeyPath& path, std::size_t depth = 0) {
  if (depth == path.parts.size()) return YAML::Clone(root);
  if (!root.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  const YAML::Node child = root[path.parts[depth]];
  if (!child.IsDefined()) return YAML::Node(YAML::NodeType::Undefined);
  return find(child, path, depth + 1);
}

}  // namespace scene

// The scene file's keys, each written once: the loader takes every map's allowed keys, its
// required keys and the lines its messages suggest from this table, and the page
// docs/scene-reference.md is generated from it (docs/gen_scene_reference.cpp), as MuJoCo makes
// its XML reference from one schema (docs/design.md, "one schema for scene keys").
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/loader.hpp"

namespace scene {

/// The member a leaf key fills in a scene being loaded (its type is the key's type), or
/// std::monostate for a map of keys.
using Field =
    std::variant<std::monostate, double& (*)(Loaded&), int& (*)(Loaded&), std::string& (*)(Loaded&),
                 std::array<double, 2>& (*)(Loaded&), std::array<double, 3>& (*)(Loaded&),
                 std::array<int, 2>& (*)(Loaded&), sim::Matrix3Spec& (*)(Loaded&)>;

/// When a key must be given.
enum class Need {
  Optional,
  Always,
  Paraboloid,     ///< with body.shape paraboloid (the default)
  Ellipsoid,      ///< with body.shape: ellipsoid
  Mesh,           ///< with body.shape: mesh
  UnlessRolling,  ///< unless contact.model: rolling (a misspelt model is reported as such)
};

/// The shape a body key belongs to: the other shapes' keys are refused ("belongs to shape: …").
enum class Shape { Any, Paraboloid, Ellipsoid, Mesh, EllipsoidOrMesh };
/// The words of body.shape a key of `shape` belongs to: "paraboloid", "ellipsoid or mesh", ….
std::string shapeWords(Shape shape);

/// One key of the scene file.
struct Key {
  std::string_view path{};  ///< dotted: "body.paraboloid.a"
  Field field{};
  Need need = Need::Optional;
  Shape shape = Shape::Any;
  std::string_view unit{};  ///< "" for none
  std::string_view doc{};   ///< one line: what it is
  /// What the program checks of the value (sim/compile.cpp, media/video_plan.cpp), beyond its
  /// type and choices.
  std::string_view check{};
  /// A value that loads and compiles in a complete scene, as YAML flow text ("0.059"); "" for a
  /// map. The tests set each key to it.
  std::string_view sample{};
  /// The line a message for the missing key suggests ("mass: 0.059 (kg)"); "" for none.
  std::string_view example{};
  /// A word's choices, from the name table its checker uses; nullptr for other types.
  std::vector<std::string_view> (*choices)() = nullptr;
  /// The default when it depends on other keys (the member is left empty); "" otherwise.
  std::string_view default_note{};
  /// Called when the map is given, before its keys are read (body.dents makes its member).
  void (*given)(Loaded&) = nullptr;
};

/// Every key, in the order a file lists them and the loader reads them.
std::span<const Key> keys();
/// The key at a dotted path without an index, or nullptr.
const Key* findKey(std::string_view path);
/// The keys directly inside a map ("" is the top level), in the table's order.
std::vector<const Key*> keysIn(std::string_view map);
/// The map a key sits in ("" for the top level) and its own name.
std::string_view parentOf(std::string_view path);
std::string_view nameIn(std::string_view path);

inline bool isMap(const Key& key) {
  return std::holds_alternative<std::monostate>(key.field);
}
/// "number", "whole number", "word", "two numbers", …, "map".
std::string typeOf(const Key& key);
/// The key's member in `scene` as YAML flow text ("0.059", "[0.73, 4.5]", "rk4"), or "" when it
/// is unset (NaN, an empty word) and for a map.
std::string valueOf(const Key& key, Loaded& scene);
/// The program's own default (of a default-constructed scene) as YAML flow text, or "" when the
/// member starts unset (a required key, or one whose default is its note).
std::string defaultOf(const Key& key);
/// Whether the key must be given in a scene whose words read so far are `spec`'s.
bool requiredIn(const Key& key, const sim::SceneSpec& spec);
/// The loader's message for the key when it is missing: "is required", or with the table's
/// example "is required, e.g. mass: 0.059 (kg) (docs/scenes.md has a complete scene)".
std::string requiredMessage(const Key& key);
/// Whether the key may be given with this body's shape.
bool belongsTo(const Key& key, const sim::BodySpec& body);

}  // namespace scene

// compile(spec) → Model, or an error naming the offending key.
#pragma once

#include <string>
#include <variant>

#include "sim/model.hpp"
#include "sim/spec.hpp"

namespace sim {

/// A scene that cannot run: `key` is the dotted path in the scene file ("contact.stiffness"),
/// `message` says what is wrong and, where it helps, what would be right.
struct SpecError {
  std::string key;
  std::string message;
};

/// Largest point-grid size compile() accepts (bounding-box estimate), points.
inline constexpr double kMaxGridPoints = 2.0e8;

/// Checks every field of the spec and builds the model: mass properties from the grid,
/// bottom points relative to the CM, SI units, a whole number of steps. Refuses a step that
/// the contact stiffness makes unstable, naming the largest stable one.
std::variant<Model, SpecError> compile(const SceneSpec& spec);

}  // namespace sim

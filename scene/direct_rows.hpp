// Inside scene/: a sweep's rows made without a YAML tree. A row whose every varied key is a
// number (or one number of a list) that the base scene already gives is the base's loaded scene
// with those numbers written into their members: the loader reads such a key by decoding the
// number into the member and nothing else (no other key's reading depends on a number: only
// body.shape and contact.model decide which keys are read), so this is the scene the row's tree
// loads to, member for member, lines and places included. Copying the base's tree, putting the
// values in and reading it again had been 15 % of a `columns:` sweep's time.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <optional>
#include <vector>

#include "scene/keys.hpp"
#include "scene/loader.hpp"
#include "util/result.hpp"

namespace scene {

struct SweepAxis;

class DirectRows {
 public:
  /// `base` is the tree every row starts from; `load` loads a copy of it untouched (the scene
  /// the rows' numbers are written into). Nothing is made direct when an axis is not a number
  /// already in the base, or when the base alone does not load (its rows then go the long way,
  /// which says why).
  static DirectRows open(const YAML::Node& base, const std::vector<SweepAxis>& axes,
                         const std::function<rb::Result<Loaded>()>& load);

  /// The scene of the row at `at` (each axis's value index), or nothing when one of its values
  /// is not a plain number (a word, a quoted "0.5", a list: the tree's loader says what is wrong
  /// with it, as it would have).
  std::optional<Loaded> scene(const std::vector<int>& at) const;

 private:
  struct Axis {
    const Key* key = nullptr;
    std::optional<std::size_t> index;
    std::vector<std::optional<double>> numbers;  ///< each value as the loader reads it
  };
  std::optional<Loaded> base_;
  std::vector<Axis> axes_;
};

}  // namespace scene

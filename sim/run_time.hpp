// A time of a run as a file or an option gives it: seconds, or a moment the run itself finds
// (its first reversal, its end). Declared here, beside the run that finds the moments, so that
// readers of files (scene/) and front ends (tasks/) share one name table.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>

#include "util/names.hpp"

namespace sim {

/// The moments a time may name (docs/commands.md "rattleback still").
enum class NamedTime {
  Reversal,       ///< the first reversal counted by the reversal rule (docs/physics.md P7)
  FirstReversal,  ///< the same, named as the sidecar's and the sweep's first_reversal_s
  End,            ///< the end of the run: simulation.duration
};

/// A time as given: seconds, or a moment of the run.
struct RunTime {
  double seconds = 0;  ///< s, when `named` is empty
  std::optional<NamedTime> named;
};

}  // namespace sim

namespace rb {
template <>
struct NameTable<sim::NamedTime> {
  static constexpr std::array<std::pair<sim::NamedTime, std::string_view>, 3> entries{{
      {sim::NamedTime::Reversal, "reversal"},
      {sim::NamedTime::FirstReversal, "first_reversal"},
      {sim::NamedTime::End, "end"},
  }};
};
}  // namespace rb

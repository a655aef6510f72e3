// How a run's reversal compares with what the linearised theory predicts of its spin, and the
// words each front says it in: the report's captions (tasks/report/captions.cpp measuredAs) and
// render --both's notes (media/video.cpp). One rule and one table, so the two cannot drift.
#pragma once

#include <string_view>

namespace tasks {

/// A run against the theory's prediction for its direction (docs/physics.md P8.4).
enum class AgainstTheory {
  NothingToSay,               ///< as predicted: the reversing way reversed, or the preferred way
                              ///< kept where the rocking grows only the other way
  ReversedEitherWay,          ///< preferred way, reversed, as predicted where it grows either way
  KeptAlthoughEitherWay,      ///< preferred way, no reversal, though it grows either way
  ReversedAlthoughPreferred,  ///< preferred way, reversed, where it grows only the other way
  KeptAlthoughReversing,      ///< the reversing way, no reversal within the run
};

/// Which of these a run is: spun the theory's `preferred` way or not, `reversed` within the run
/// or not, `either_way`: the theory finds the rocking grows either way (analyze's
/// `grows_either_way`).
AgainstTheory againstTheory(bool preferred, bool reversed, bool either_way);

/// Where the words are said.
enum class Front {
  Caption,  ///< the report's HTML, after "measured (…): <its reversals>"
  Note,     ///< render --both's plain text, after "spun −5 rad/s"
};

/// The words for `a` at `front`; empty for NothingToSay.
std::string_view wordsFor(AgainstTheory a, Front front);

}  // namespace tasks

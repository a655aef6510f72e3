// A still's time: a number of seconds, or a moment of the scene's run named by a word
// (`still --t reversal`), so that a still at the reversal needs no time copied from `simulate`.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "sim/rollout.hpp"
#include "sim/run_time.hpp"
#include "util/names.hpp"
#include "util/result.hpp"

namespace tasks {

using sim::NamedTime;
using StillTime = sim::RunTime;

/// "2.5", "reversal", "first_reversal" or "end"; anything else is refused with one line naming
/// `option` (the option or argument as typed: "--t", "argument t").
rb::Result<StillTime> parseStillTime(std::string_view text, const std::string& option);

/// The time in s that `time` stands for in `run`'s scene. A name runs `run` (a fresh Rollout)
/// as far as it must: to the first reversal counted, or not at all for `end`. Refused with a
/// line naming `option` when the run has no reversal within its duration. `cancelled` (may be
/// empty) is asked between slices of the run; the caller reads a stopped run from run.summary()
/// and a cancel from `cancelled` (no time then). `scene_duration_only`: the caller has no
/// duration argument (a snapshot suite), so the way to a longer run is the scene's key alone.
rb::Result<double> resolveStillTime(const StillTime& time, sim::Rollout& run,
                                    const std::string& option,
                                    const std::function<bool()>& cancelled = {},
                                    bool scene_duration_only = false);

}  // namespace tasks

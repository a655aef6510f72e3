#include "tasks/still_time.hpp"

#include <charconv>
#include <cmath>

#include "util/arguments.hpp"
#include "util/format.hpp"

namespace tasks {
namespace {

// The way to a longer run in the caller's words: the front end's duration argument, or the
// scene's own where the caller has none (a snapshot suite).
std::string longerDuration(bool scene_duration_only) {
  if (scene_duration_only) return ": a longer one in the scene";
  return "; a longer " + rb::argumentName("duration");
}

}  // namespace

rb::Result<StillTime> parseStillTime(std::string_view text, const std::string& option) {
  StillTime time;
  if (auto named = rb::parseName<NamedTime>(text)) {
    time.named = named;
    return time;
  }
  // The whole text a number (from_chars takes no leading '+' or spaces; strtod would take "1x"
  // up to the x): the range (≥ 0, finite) is checked where the time is used.
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, time.seconds);
  if (text.empty() || error != std::errc() || stop != end)
    return rb::Error{"", option + ": a time in s (e.g. 1.5) or " + rb::choices<NamedTime>() +
                             ", not '" + std::string(text) + "'"};
  return time;
}

rb::Result<double> resolveStillTime(const StillTime& time, sim::Rollout& run,
                                    const std::string& option,
                                    const std::function<bool()>& cancelled,
                                    bool scene_duration_only) {
  if (!time.named) return time.seconds;
  const double duration = run.endTime();
  if (*time.named == NamedTime::End) return duration;
  // Slices of 50 ms, so that the run stops soon after the reversal is counted (the rule holds
  // a crossing 0.2 s before counting it) rather than at the scene's end. The stepping does not
  // depend on where the slices end (the samples are interpolated), so the time found is the one
  // `simulate` reports.
  constexpr double kSlice = 0.05;
  const auto slices = static_cast<long long>(std::ceil(duration / kSlice));
  for (long long k = 1; k <= slices && !run.summary().first_reversal_s; ++k)
    if ((cancelled && cancelled()) || !run.advanceTo(k == slices ? duration : k * kSlice))
      return rb::Error{"", option + " " + std::string(rb::nameOf(*time.named)) +
                               ": the run stopped (or was stopped) before its first reversal"};
  if (const auto& first = run.summary().first_reversal_s) return *first;
  return rb::Error{"", option + " " + std::string(rb::nameOf(*time.named)) +
                           ": the run has no reversal within its " + rb::show(duration) +
                           " s (simulation.duration" + longerDuration(scene_duration_only) +
                           ", or the other spin, may reverse)"};
}

}  // namespace tasks

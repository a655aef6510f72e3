// The report page's words for what a run measured (its sidecar, tasks/report/sidecars.hpp),
// what the theory predicts (analyze --json) and what a still or plot shows.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tasks/manifest.hpp"
#include "tasks/report/sidecars.hpp"

namespace tasks::report {

/// What the theory predicts of a spin the preferred way: by the definition of preferred, that
/// its rocking grows more slowly, if at all; not that it never reverses (bodies with deep dents
/// reverse that way too, as their forecast says).
inline constexpr const char* kPreferredWay =
    "the theory predicts its rocking grows more slowly this way, if at all, so it turns longer "
    "before any reversal";
/// The same where the theory finds the rocking grows either way (analyze's `grows_either_way`,
/// docs/physics.md P8.4): a reversal this way too is the prediction, not a surprise.
inline constexpr const char* kPreferredWayEitherWay =
    "the theory predicts its rocking grows more slowly this way, but grows: it is predicted to "
    "reverse this way too, later";

/// "counter-clockwise", "clockwise" or "no spin".
std::string spinWords(double spin);

/// Whether a run reversed, and when: every reversal, as the player's n(t) plot counts them
/// (the first few of more); a sidecar without the list gives its first.
std::string reversalOf(const RunRecord& run);

/// What a run measured: its values put in, spin, reversal, final spin, energy and check.
std::string measuredOf(const RunRecord& run);

/// What simulate measured, when its run was spun counter-clockwise (`ccw`) or clockwise as a
/// video was; empty otherwise. A run whose command is "render" is the video's own, as the
/// manifest lists it (its first reversal only), and is said to be. Where `preferred` says whether
/// that is the theory's preferred direction, a run that disagrees with the caption's prediction is
/// said to, plainly: reversed although preferred (a preferred spin's rocking grows more slowly, and
/// may still grow), or no reversal the reversing way within the run. `either_way`: the theory
/// predicts a reversal the preferred way too, so one there agrees with it, and none there is said
/// to disagree (the prediction is a rule of thumb: docs/physics.md P8.4).
std::string measuredAs(const std::optional<RunRecord>& run, bool ccw,
                       std::optional<bool> preferred = std::nullopt, bool either_way = false);

/// The theory's column (analyze --json): the preferred direction, growth rates, the rocking at
/// rest, the misalignment and the forecast first reversal.
std::string predictedOf(const nlohmann::json& theory);

/// What a still shows, from its manifest entry: "oblique view, t = 1 s, spun −4 rad/s".
std::string stillCaption(const OutputEntry& e);

/// What a plot against time shows, by its suffix; else "" (the file's name is shown).
std::string plotCaption(const std::string& file);

}  // namespace tasks::report

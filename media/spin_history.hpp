// The spin so far, as the video's inset draws it (render and still).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "sim/rollout.hpp"
#include "sim/telemetry.hpp"

namespace media {

/// The spin so far that the inset draws, as the least and the greatest spin in each of the
/// inset's pixel columns (three tenths of the image's width over the run's duration; in the
/// order they came), then the spin at the time drawn. The spin is sampled every 5 ms or
/// finer, at least twice a column, so the curve shows what the body did between frames: at
/// frame times alone, a 17 Hz wobble at 30 fps drew as a false 13 Hz one, and a column's
/// extremes draw a wobble too fast for the inset as the band it sweeps. `render` and `still`
/// both draw from it, so a still at a frame's time has that frame's history.
class SpinHistory {
 public:
  SpinHistory(double duration, int image_width);
  /// Advances `run` through the sample times before t, keeping each column's extremes; false
  /// when the run stops first or `cancelled` (when given) says to stop.
  bool advanceTo(sim::Rollout& run, double t, const std::function<bool()>& cancelled = {});
  /// The history drawn at `now.t`: the extremes of the columns so far, then `now`.
  std::span<const std::array<float, 2>> with(const sim::Telemetry& now);

 private:
  using Point = std::array<float, 2>;  ///< t, spin
  /// Appends the open column's extremes, in the order they came (one point when the same).
  void appendOpenColumn();
  double step_;              ///< between samples, s
  std::int64_t per_column_;  ///< samples in a column
  std::int64_t next_ = 0;    ///< the next sample is at next_ · step_
  Point low_{}, high_{};     ///< the open column's extremes (when next_ is past its start)
  std::size_t closed_ = 0;   ///< samples_ starts with the closed columns' extremes
  std::vector<Point> samples_;
};

}  // namespace media

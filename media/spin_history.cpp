#include "media/spin_history.hpp"

#include <algorithm>
#include <cmath>

namespace media {

SpinHistory::SpinHistory(double duration, int image_width) {
  constexpr double kLongestStep = 0.005;  // s: 200 samples a second, 10 of a 20 Hz wobble
  const double column = duration / std::max(1, image_width * 3 / 10);
  per_column_ =
      std::max<std::int64_t>(2, static_cast<std::int64_t>(std::ceil(column / kLongestStep)));
  step_ = column / static_cast<double>(per_column_);
}

void SpinHistory::appendOpenColumn() {
  if (low_[0] == high_[0]) {
    samples_.push_back(low_);
  } else {  // in the order they came
    samples_.push_back(low_[0] < high_[0] ? low_ : high_);
    samples_.push_back(low_[0] < high_[0] ? high_ : low_);
  }
}

bool SpinHistory::advanceTo(sim::Rollout& run, double t, const std::function<bool()>& cancelled) {
  samples_.resize(closed_);
  for (double at = static_cast<double>(next_) * step_; at < t;
       at = static_cast<double>(next_) * step_) {
    if ((cancelled && cancelled()) || !run.advanceTo(at)) return false;
    const sim::Telemetry sample = run.sampleAt(at);
    const Point point{static_cast<float>(sample.t), static_cast<float>(sample.spin)};
    if (next_ % per_column_ == 0) {
      low_ = high_ = point;
    } else {
      if (point[1] < low_[1]) low_ = point;
      if (point[1] > high_[1]) high_ = point;
    }
    ++next_;
    if (next_ % per_column_ == 0) {
      appendOpenColumn();
      closed_ = samples_.size();
    }
  }
  return true;
}

std::span<const std::array<float, 2>> SpinHistory::with(const sim::Telemetry& now) {
  samples_.resize(closed_);
  if (next_ % per_column_ != 0) appendOpenColumn();  // its extremes so far
  samples_.push_back({static_cast<float>(now.t), static_cast<float>(now.spin)});
  return samples_;
}

}  // namespace media

#include "sim/reversals.hpp"

#include <cmath>

namespace sim {

ReversalDetector::ReversalDetector(double initial_spin)
    : threshold_(kFraction * std::abs(initial_spin)),
      reference_sign_(initial_spin == 0 ? 0 : std::copysign(1.0, initial_spin)) {}

void ReversalDetector::step(double t0, double n0, double t1, double n1, double last_flight,
                            bool at_end, const std::function<double()>& locate) {
  (void)t0;
  if (reference_sign_ == 0 || !std::isfinite(n1)) return;
  // Before n has reached the threshold the other way, the latest crossing is the candidate;
  // after it, the crossing stays, and only n back beyond the threshold the old way undoes it
  // (a wiggle about zero in the middle of a reversal keeps its first crossing).
  if (n1 * reference_sign_ < 0 && n0 * reference_sign_ >= 0 && !crossing_reached_)
    crossing_ = locate();
  // A crossing while the body was in the air or still bouncing is none, nor one that n takes
  // back before it has held the new side for kHoldTime.
  if (crossing_ && *crossing_ - last_flight < kSettleTime) crossing_.reset();
  if (crossing_ && crossing_reached_ && n1 * reference_sign_ > threshold_) crossing_.reset();
  if (crossing_ && n1 * reference_sign_ < -threshold_) crossing_reached_ = true;
  // It counts once n is beyond the threshold the new way kHoldTime or more after the crossing:
  // beyond it then, not merely not back (a spin braked to rest that overshot past the threshold
  // and died out at zero would be counted). A crossing within kHoldTime of the
  // run's end counts there, its hold cut short: nothing undid it.
  const bool held = crossing_ && t1 - *crossing_ >= kHoldTime;
  if (crossing_ && crossing_reached_ &&
      ((held && n1 * reference_sign_ < -threshold_) || (at_end && !held))) {
    reversals_.push_back(*crossing_);
    crossing_.reset();
    reference_sign_ = -reference_sign_;
  }
  if (!crossing_) crossing_reached_ = false;
}

}  // namespace sim

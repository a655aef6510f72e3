// contact.model auto's switch (docs/physics.md P4) as a unit of its own: which of its two modes,
// rolling or smooth, a run starts in, when rolling fails inside a step and from what state the
// smooth contact takes over, and when sliding has stuck long enough for rolling to resume
// (the rules and their constants: sim/switching.hpp). A Rollout asks it after each step and
// carries out the changes; tests feed it scripted states.
#pragma once

#include <functional>
#include <optional>

#include "sim/model.hpp"

namespace sim {

/// A change of auto's mode: from time t_s (s) the run goes on in `next` from `start` (a state
/// already in next's terms).
struct ModeChange {
  double t_s = 0;
  State start;
  Model next;
};

class AutoSwitch {
 public:
  /// The state at a time (s) of the last step, on its interpolant (Rollout::stateAt).
  using StateAt = std::function<State(double)>;

  /// For the auto run `run` (contact.model auto).
  explicit AutoSwitch(const Model& run) : run_(run) {}

  /// The first mode, from the start state s: rolling when s touches the floor and rolling
  /// holds there, with the spring's compression as its depth (at rest M g / k), s then put on
  /// rolling's constraint; else smooth, s unchanged.
  Model start(State& s) const;

  /// Whether `active` is auto's sliding mode (smooth), whose steps go through advance().
  static bool sliding(const Model& active);

  /// Advances s from s.t to t_end (s) in `active`: the smooth contact in equal steps no
  /// longer than smoothStep, counting how long the contact point sticks; rolling in one step.
  void advance(const Model& active, State& s, double t_end);

  /// Sliding: the contact point stuck or not over a step of h s ending at s (slip below ε with
  /// the spring pressing); the time stuck is counted up or restarted.
  void countStuck(const Model& smooth, const State& s, double h);

  /// After a step from a to b in `active`. Rolling: the change to smooth at the earliest time
  /// a failing margin reaches zero inside the step (located on `state_at`), when one fails at
  /// b. Smooth: none now; when the contact has stuck for kStickTime and rolling would hold with
  /// friction to spare, a hand-back to rolling is kept for handBack().
  std::optional<ModeChange> afterStep(const Model& active, const State& a, const State& b,
                                      const StateAt& state_at);

  /// The hand-back to rolling afterStep found, once: it takes effect at the start of the next
  /// step, so that the step just ended stays the sliding one it was.
  std::optional<ModeChange> handBack();

  /// How long the contact point has stuck so far while sliding, s.
  double stuckFor() const { return stuck_for_s_; }

 private:
  std::optional<ModeChange> toSmooth(const Model& rolling, const State& a, const State& b,
                                     const StateAt& state_at);
  void tryRolling(const Model& smooth, const State& b);

  Model run_;                            ///< the run as compiled
  double stuck_for_s_ = 0;               ///< sliding: how long the contact point has stuck, s
  std::optional<ModeChange> hand_back_;  ///< pending until the next step starts
};

}  // namespace sim

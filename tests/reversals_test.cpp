// The reversal rule (sim/reversals.hpp, docs/physics.md P7) on scripted n(t), without a body:
// each case is a spin history a run can produce, fed at 1 ms steps (or coarser) with the script
// itself as the interpolant between step ends (crossings are then found by regula falsi on the
// piecewise-linear scripts to rounding, so times compare to 1e-9 s).
#include "sim/reversals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace {

struct Script {
  std::function<double(double)> n;  ///< rad/s at t
  double duration = 3;              ///< s
  double last_flight = -1e300;      ///< s
};

std::vector<double> reversalsOf(const Script& s, double initial, double h = 1e-3) {
  sim::ReversalDetector detector(initial);
  const int steps = static_cast<int>(std::ceil(s.duration / h - 1e-9));
  for (int k = 0; k < steps; ++k) {
    const double t0 = k * h, t1 = std::min((k + 1) * h, s.duration);
    const double n0 = s.n(t0), n1 = s.n(t1);
    detector.step(t0, n0, t1, n1, s.last_flight, k + 1 == steps, s.n);
  }
  return detector.reversals();
}

// Piecewise linear through (t, n) knots.
std::function<double(double)> through(std::vector<std::pair<double, double>> knots) {
  return [knots](double t) {
    if (t <= knots.front().first) return knots.front().second;
    for (std::size_t i = 1; i < knots.size(); ++i)
      if (t <= knots[i].first) {
        const auto [t0, n0] = knots[i - 1];
        const auto [t1, n1] = knots[i];
        return n0 + (n1 - n0) * (t - t0) / (t1 - t0);
      }
    return knots.back().second;
  };
}

}  // namespace

TEST(Reversals, ACrossingThatGoesOnIsAReversalAtTheCrossing) {
  // n linear from −5 to +4.99 over 2 s: across at 2·5/9.99 s, inside a step (not on its end).
  const auto r = reversalsOf({through({{0, -5}, {2, 4.99}})}, -5);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 10 / 9.99, 1e-9);
}

TEST(Reversals, ADipThroughZeroAndBackIsNone) {
  // n swings to +0.5 (past 1 % of 5) for 60 ms while the body rocks, and back: no reversal.
  const auto r = reversalsOf(
      {through({{0, -5}, {1.0, -0.5}, {1.02, 0.5}, {1.06, 0.5}, {1.1, -3}, {3, -3}})}, -5);
  EXPECT_TRUE(r.empty());
}

TEST(Reversals, ASpinThatDiesOutAndDithersIsNone) {
  // Down to rest, then ±0.02 rad/s about zero (within 1 % of 5): never a reversal.
  const auto r =
      reversalsOf({[](double t) { return t < 1 ? -5 * (1 - t) : 0.02 * std::sin(40 * t); }}, -5);
  EXPECT_TRUE(r.empty());
}

TEST(Reversals, ASpinBrakedToRestThatOvershootsIsNone) {
  // A flat-bottomed body's points brake the spin to rest; n overshoots past 1 % (to +0.093, 1.9 %
  // of 5) for a tenth of a second and dies out at zero (a physicist's trial, contact.model
  // points on a coarse grid: counted at 0.39 s). n never holds the new side: none, at the end
  // of the run either.
  const auto braked =
      through({{0, -5}, {0.39, 0}, {0.42, 0.093}, {0.484, -8e-7}, {1.0, 0}, {3, 0}});
  EXPECT_TRUE(reversalsOf({braked}, -5).empty());
  EXPECT_TRUE(reversalsOf({braked, 0.6}, -5).empty());
}

TEST(Reversals, WigglesAfterTheThresholdKeepTheCrossing) {
  // Across at 1.0 s, up to +0.1 (reached), back to +0.01 and up again: one reversal at 1.0 s.
  const auto r = reversalsOf(
      {through({{0, -5}, {1.0, 0}, {1.02, 0.1}, {1.04, 0.01}, {1.06, 0.2}, {2, 4}, {3, 4}})}, -5);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 1.0, 1e-9);
}

TEST(Reversals, WithinHalfASecondOfAFlightIsNone) {
  // A dropped body: n crosses 0.3 s after its last flight, and stays: not counted.
  Script bounce{through({{0, -5}, {1.0, 0}, {2, 4}, {3, 4}})};
  bounce.last_flight = 0.7;
  EXPECT_TRUE(reversalsOf(bounce, -5).empty());
  bounce.last_flight = 0.4;  // 0.6 s before: settled
  EXPECT_EQ(reversalsOf(bounce, -5).size(), 1u);
}

TEST(Reversals, AtTheEndACrossingThatReachedTheThresholdCounts) {
  // Across at 2.9 s and past 1 % by 2.95 s; the run ends at 3 s, before the 0.2 s hold.
  const auto r = reversalsOf({through({{0, -5}, {2.9, 0}, {2.95, 0.1}, {3, 0.2}})}, -5);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 2.9, 1e-9);
}

TEST(Reversals, TheNextIsCountedFromTheNewSign) {
  // −5 → +3 (at 1 s) → −2 (at 2 s): two reversals; n = 0 from the start: none.
  const auto r =
      reversalsOf({through({{0, -5}, {1, 0}, {1.5, 3}, {2, 0}, {2.5, -2}, {3, -2}})}, -5);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0], 1.0, 1e-9);
  EXPECT_NEAR(r[1], 2.0, 1e-9);
  EXPECT_TRUE(reversalsOf({through({{0, 0}, {3, 1}})}, 0).empty());
}

// A spin that crosses at 1.003 s, reaches +0.06 (past 1 % of 5) for 2 ms around 1.0085 s, falls
// back to +0.02, dips back across zero (−0.02) for 12 ms and turns for good at 1.043 s: the
// crossing at 1.003 s reached the threshold, so the dip (within 1 %) keeps it.
std::function<double(double)> knifeEdge() {
  return through({{0, -5},
                  {1.003, 0},
                  {1.0085, 0.06},
                  {1.0105, 0.02},
                  {1.031, 0},
                  {1.037, -0.02},
                  {1.043, 0},
                  {1.5, 2},
                  {3, 2}});
}

TEST(Reversals, ABriefExcursionPastTheThresholdInsideAStepIsSeen) {
  // At 20 ms steps the step ends (1.00, 1.02 s) miss the excursion past 1 %: read at the ends
  // only, the crossing would never reach it and the later one (1.043 s) would count.
  const auto r = reversalsOf({knifeEdge()}, -5, 0.02);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], 1.003, 1e-9);
}

TEST(Reversals, ABriefExcursionBackPastTheThresholdInsideAStepUndoesTheCrossing) {
  // Across at 1.0 s and on to +1; at 1.105 s (within the 0.2 s hold) n swings back to −0.2
  // (past 1 % the old way) for 4 ms and crosses again at 1.1063 s for good. The swing back
  // undoes the first crossing: the reversal is the second. Steps of 20 ms end at 1.10 and
  // 1.12 s, on either side of the swing.
  const auto swing = through(
      {{0, -5}, {1.0, 0}, {1.1, 1}, {1.103, 1}, {1.105, -0.2}, {1.107, 0.1}, {2, 2}, {3, 2}});
  const double second = 1.105 + 0.002 * 0.2 / 0.3;  // n = 0 on the way up from −0.2 to +0.1
  const auto r = reversalsOf({swing}, -5, 0.02);
  ASSERT_EQ(r.size(), 1u);
  EXPECT_NEAR(r[0], second, 1e-9);
}

TEST(Reversals, TheReversalDoesNotDependOnWhereStepsEnd) {
  // The two histories above, and a plain crossing, fed at steps from 0.1 to 20 ms (one of
  // them not dividing the run): the same reversals as at 0.1 ms, to rounding.
  const std::vector<std::function<double(double)>> histories = {
      knifeEdge(),
      through(
          {{0, -5}, {1.0, 0}, {1.1, 1}, {1.103, 1}, {1.105, -0.2}, {1.107, 0.1}, {2, 2}, {3, 2}}),
      through({{0, -5}, {2, 4.99}})};
  for (const auto& n : histories) {
    const auto fine = reversalsOf({n}, -5, 1e-4);
    ASSERT_EQ(fine.size(), 1u);
    for (const double h : {1e-3, 0.0037, 0.01, 0.0137, 0.02}) {
      const auto r = reversalsOf({n}, -5, h);
      ASSERT_EQ(r.size(), fine.size()) << "steps of " << h << " s";
      EXPECT_NEAR(r[0], fine[0], 1e-9) << "steps of " << h << " s";
    }
  }
}

// What the report's 3D player is given of a run (tasks/player_data).
#include "tasks/player_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

// The player keeps as few of a run's poses as replay it within half a pixel and half the spin
// read-out's last digit (tasks::kPlayerAttitudeDeg, kPlayerSpin): a body rocking slowly keeps
// 100 a second, one whose spin swings fast keeps more. Poses at 500 a second over 4 s, rocking
// 2° at 1.5 Hz, n swinging by A sin(2π f t). f = 3 Hz, A = 0.01 rad/s: smooth, 100 a second.
// f = 17 Hz (Kane & Levinson's pitch): the player's cubic (slopes by central differences) over
// every second pose misses it by 7.7e-4 A, over every third by 7.2e-3 A (worked out for this
// series alone, in a scratch script): A = 1 keeps every second pose, A = 10 every pose.
TEST(Player, PosesAreKeptAsTheReplayNeedsThem) {
  auto poses = [](double f, double amplitude) {
    std::vector<tasks::Pose> out;
    for (int i = 0; i <= 2000; ++i) {
      const double t = i / 500.0, tilt = 2 * M_PI / 180 * std::sin(2 * M_PI * 1.5 * t);
      out.push_back({t, 0, 0, 0.01, std::cos(tilt / 2), std::sin(tilt / 2), 0, 0,
                     -5 + amplitude * std::sin(2 * M_PI * f * t)});
    }
    return out;
  };
  const std::vector<tasks::Pose> slow = tasks::thinPoses(poses(3, 0.01));
  EXPECT_EQ(slow.size(), 401u);  // every 5th: 100 a second, and the last
  EXPECT_EQ(slow.back().t, 4.0);
  EXPECT_EQ(tasks::thinPoses(poses(17, 1)).size(), 1001u);
  EXPECT_EQ(tasks::thinPoses(poses(17, 10)).size(), 2001u);
}

}  // namespace

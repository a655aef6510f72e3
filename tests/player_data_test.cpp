// What the report's 3D player is given of a run (tasks/player_data).
#include "tasks/player_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "render/views.hpp"

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

// The player places its cameras by the renderer's own table (render/views.hpp), which comes with
// each run's data: every view, in the renderer's order, with the table's numbers as written
// (0.55, not the float's 0.550000011920929).
TEST(Player, DataCarriesTheRenderersViews) {
  tasks::PlayerRun run;
  run.id = "x";
  run.poses = {tasks::Pose{}, tasks::Pose{0.01}};
  const std::string script = tasks::playerScript(run);
  const std::size_t start = script.find("] = ") + 4, end = script.rfind(';');
  const nlohmann::json data = nlohmann::json::parse(script.substr(start, end - start));
  ASSERT_EQ(data.at("views").size(), render::kViewPresets.size());
  for (std::size_t i = 0; i < render::kViewPresets.size(); ++i) {
    const render::ViewPreset& p = render::kViewPresets[i];
    const nlohmann::json& v = data["views"][i];
    EXPECT_EQ(v.at("name"), rb::nameOf(p.view));
    EXPECT_EQ(v.at("projection"), rb::nameOf(p.projection));
    for (int k = 0; k < 3; ++k)
      EXPECT_FLOAT_EQ(v.at("toward_eye")[k].get<double>(), p.toward_eye[k]);
    EXPECT_FLOAT_EQ(v.at("elevation_deg").get<double>(), p.elevation_deg);
    EXPECT_FLOAT_EQ(v.at("margin").get<double>(), p.margin);
  }
  EXPECT_EQ(data["views"][0].at("toward_eye")[1].dump(), "-0.55");
}

}  // namespace

// What the report's 3D player is given of a run (tasks/player_data).
#include "tasks/player_data.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "scene/loader.hpp"
#include "sim/tessellate.hpp"
#include "tasks/body_mesh.hpp"
#include "tasks/run_json.hpp"
#include "util/picture.hpp"

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

// The player places its cameras by the renderer's own table (util/picture.hpp), which comes with
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

// The default body with its dents mirrored (at: [-0.73, 4.50]) prefers clockwise: spun -5 rad/s
// as its scene spins it, it keeps turning, and the player of that run alone showed no reversal (a
// teacher's trial). The player's data carries the body spun +5 rad/s beside it, simulated by
// otherSpinOf, which reverses; the run's own spin goes with it.
sim::Model mirroredModel(const std::string& dents_at = "[-0.73, 4.50]") {
  const std::string file = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/rattleback.yaml";
  const std::vector<scene::KeyValue> values = {{"body.dents.at", dents_at},
                                               {"simulation.duration", "4"}};
  auto loaded = scene::loadWithValues(scene::readSceneFile(file).value(), file, values, "test");
  EXPECT_TRUE(loaded) << loaded.error().text();
  auto model = scene::loadModel(loaded.value());
  EXPECT_TRUE(model) << model.error().text();
  return model.value();
}

nlohmann::json dataOf(const std::string& script) {
  const std::size_t start = script.find("] = ") + 4, end = script.rfind(';');
  return nlohmann::json::parse(script.substr(start, end - start));
}

TEST(Player, DataHoldsTheBodySpunTheOtherWay) {
  const sim::Model model = mirroredModel();
  ASSERT_EQ(model.initial.spin, -5);
  const std::optional<tasks::SpunRun> other =
      tasks::otherSpinOf(model, tasks::modelJson(model), 500);
  ASSERT_TRUE(other);
  EXPECT_EQ(other->spun, 5);
  // Spun +5 rad/s the mirrored body reverses, about when the default body spun -5 does
  // (2.37 s; the tilt is not mirrored with it, so not at the same time).
  ASSERT_FALSE(other->reversals.empty());
  EXPECT_GT(other->reversals[0], 1.5);
  EXPECT_LT(other->reversals[0], 3.5);
  EXPECT_NEAR(other->poses.front().spin, 5, 0.05);
  EXPECT_LT(other->poses.back().spin, 0);  // turned back
  EXPECT_EQ(other->poses.back().t, 4);     // the run's duration, not the file's 8 s
  tasks::PlayerRun run;
  run.id = "mirrored";
  run.poses = {tasks::Pose{}, tasks::Pose{0.01}};
  run.other = other;
  const nlohmann::json data = dataOf(tasks::playerScript(run));
  EXPECT_EQ(data.at("spun"), -5);
  const nlohmann::json& shown = data.at("other");
  EXPECT_EQ(shown.at("spun"), 5);
  EXPECT_EQ(shown.at("t").size(), other->poses.size());
  EXPECT_EQ(shown.at("spin").size(), other->poses.size());
  ASSERT_EQ(shown.at("reversals").size(), other->reversals.size());
  EXPECT_NEAR(shown["reversals"][0].get<double>(), other->reversals[0], 1e-6);
  // A run alone says no more than it did before.
  run.other.reset();
  EXPECT_FALSE(dataOf(tasks::playerScript(run)).contains("other"));
  EXPECT_FALSE(dataOf(tasks::playerScript(run)).contains("spun"));
}

// The run's other way is of the run's own model: the spin and duration its sidecar records
// (a command's --spin, --duration), and nothing where there is none to show or the sidecar's model
// is another: spin 0, a body that prefers neither way (its dents on its long axis), another
// body.
TEST(Player, TheOtherSpinIsOfTheRunsOwnModel) {
  const sim::Model model = mirroredModel();
  sim::Model run = model;  // simulate --spin 3 --duration 2
  run.initial.spin = 3;
  run.duration = 2;
  const auto other = tasks::otherSpinOf(model, tasks::modelJson(run), 500);
  ASSERT_TRUE(other);
  EXPECT_EQ(other->spun, -3);
  EXPECT_EQ(other->poses.back().t, 2);
  run.initial.spin = 0;
  EXPECT_FALSE(tasks::otherSpinOf(model, tasks::modelJson(run), 500));
  // Dents on the long axis (at x = 0): the body is its own mirror image.
  const sim::Model dentless = mirroredModel("[0, 4.50]");
  EXPECT_FALSE(tasks::otherSpinOf(dentless, tasks::modelJson(dentless), 500));
  sim::Model heavier = model;  // not a key a command sets: another body
  heavier.gravity = 9.7;
  EXPECT_FALSE(tasks::otherSpinOf(model, tasks::modelJson(heavier), 500));
  EXPECT_FALSE(tasks::otherSpinOf(model, nlohmann::json(), 500));
}

// A scene whose video.surface is triangles gives the player the surface its stills and videos
// draw (tasks::bodyMesh on kDefaultSegments, about the CM): every face, each vertex once. A
// scene drawn as points gives none: its data is as it was.
TEST(Player, TrianglesScenesCarryTheirSurface) {
  auto data = [](const std::string& name, std::vector<scene::KeyValue> values) {
    tasks::Overrides o;
    o.values = std::move(values);
    auto loaded = tasks::loadScene(std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/" + name, o);
    EXPECT_TRUE(loaded) << loaded.error().text();
    const tasks::LoadedScene& scene = loaded.value();
    const tasks::PlayerRun run = tasks::playerRunOf(
        "x", scene.model, 0, {tasks::Pose{}, tasks::Pose{0.01}}, {}, tasks::playerSurfaceOf(scene));
    const std::string script = tasks::playerScript(run);
    const std::size_t start = script.find("] = ") + 4, end = script.rfind(';');
    auto mesh = tasks::bodyMesh(scene, sim::kDefaultSegments);
    EXPECT_TRUE(mesh);
    const Eigen::Vector3d com = scene.model.body->com_geometric;
    return std::make_tuple(nlohmann::json::parse(script.substr(start, end - start)),
                           std::move(mesh).value(), com);
  };
  for (const auto& [name, values] :
       {std::pair<std::string, std::vector<scene::KeyValue>>{"printed.yaml", {}},
        {"rattleback.yaml", {{"video.surface", "triangles"}}}}) {
    SCOPED_TRACE(name);
    const auto [d, mesh, com] = data(name, values);
    ASSERT_TRUE(d.contains("faces"));
    ASSERT_EQ(d.at("faces").size(), 3 * mesh.faces.size());
    ASSERT_EQ(d.at("vertices").size(), 3 * mesh.vertices.size());
    for (std::size_t i = 0; i < d["faces"].size(); ++i)
      ASSERT_EQ(d["faces"][i].get<int>(), mesh.faces[i / 3][i % 3]);
    // At the points' precision: 6 digits, 0.05 µm on a body 3 cm from its CM.
    for (std::size_t i = 0; i < d["vertices"].size(); ++i)
      ASSERT_NEAR(d["vertices"][i].get<double>(), (mesh.vertices[i / 3] - com)[i % 3], 1e-7);
    EXPECT_EQ(d.at("title"), "x");
  }
  const auto [points, mesh, com] = data("rattleback.yaml", {});
  EXPECT_FALSE(points.contains("faces"));
  EXPECT_FALSE(points.contains("vertices"));
  EXPECT_GT(points.at("top").size(), 0u);
}

}  // namespace

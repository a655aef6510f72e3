// A sweep's rows made directly (the base's loaded scene with the row's numbers written in,
// scene/direct_rows.hpp) are the scenes their YAML trees load to: every key's value, every
// line and every place an error would name, and the same refusal for a value the run refuses.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/keys.hpp"
#include "scene/sweep.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kBase = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/rattleback.yaml";

scene::Sweep sweepOf(const std::string& name, const std::string& vary) {
  const fs::path dir = fs::path(testing::TempDir()) / "rattleback_sweep_scenes";
  fs::create_directories(dir);
  const fs::path path = dir / name;
  std::ofstream(path) << "base: " << kBase << "\nvary:\n" << vary << "duration: 3\n";
  auto sweep = scene::loadSweep(path.string());
  EXPECT_TRUE(sweep) << (sweep ? "" : sweep.error().text());
  return sweep.value();
}

// Every row of the sweep, both ways.
void expectRowsAlike(const scene::Sweep& sweep) {
  auto scenes = scene::SweepScenes::open(sweep);
  ASSERT_TRUE(scenes) << scenes.error().text();
  for (std::int64_t row = 0; row < sweep.rows(); ++row) {
    auto direct = scenes->scene(row);
    auto tree = scenes->sceneFromTree(row);
    ASSERT_EQ(bool(direct), bool(tree)) << "row " << row;
    if (!tree) {
      EXPECT_EQ(direct.error().text(), tree.error().text()) << "row " << row;
      continue;
    }
    for (const scene::Key& key : scene::keys())
      EXPECT_EQ(scene::valueOf(key, direct.value()), scene::valueOf(key, tree.value()))
          << "row " << row << ": " << key.path;
    EXPECT_EQ(direct->lines, tree->lines) << "row " << row;
    EXPECT_EQ(direct->overrides, tree->overrides) << "row " << row;
    EXPECT_EQ(direct->file, tree->file) << "row " << row;
  }
}

}  // namespace

TEST(SweepScenes, NumbersWrittenDirectlyMakeTheScenesTheTreesLoadTo) {
  expectRowsAlike(sweepOf("numbers.yaml",
                          "  initial.spin: {from: -8, to: 8, count: 3}\n"
                          "  initial.tilt[1]: [0.1, 2]\n"
                          "  contact.air_drag: [0, 5.9e-5]\n"
                          "  body.dents.at[0]: [0.73, 0.5]\n"
                          "  body.mass: [0.059, -1]\n"));
}

TEST(SweepScenes, NumbersWrittenInAnyFormReadAsTheTreeReadsThem) {
  // (A value that is no number is refused when the sweep is read, naming its line.)
  expectRowsAlike(sweepOf("forms.yaml", "  initial.spin: [-5, -5.0e0, +3, 7.5e-1]\n"));
  // Numerals read without YAML (scene/direct_rows.cpp) and those left to it, side by side: a
  // point at either end, leading zeros, a signed zero, a capital E, the shortest texts of a
  // range and one that is subnormal.
  expectRowsAlike(sweepOf("numerals.yaml",
                          "  initial.spin: [.5, 1., 007, -0, 1E2, +2.5E+1, -1.0e-3, 1e-310]\n"
                          "  contact.air_drag: {from: 0, to: 5.9e-5, count: 7}\n"));
}

TEST(SweepScenes, KeysTheBaseDoesNotGiveGoTheLongWayAlike) {
  // simulation.dt replaces the base's tolerance; contact.friction is not in the base.
  expectRowsAlike(sweepOf("absent.yaml",
                          "  simulation.dt: [5e-4, 1e-3]\n  contact.friction: [0.3, 0.5]\n"
                          "  initial.tilt: [[0.5, 0.5], [1, 2]]\n"));
}

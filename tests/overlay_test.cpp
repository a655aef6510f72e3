// The read-outs and the inset against the goldens at one step: the snapshot comparison allows
// 0.5 % of a still's pixels to differ (another CPU moves ~0.1 % by a step), more than the whole
// time/spin read-out (≈200 dark pixels) or the inset's curve (≈70). Here the pixels the
// read-outs draw — those where a still and the same still with --no-readouts differ — must
// each match the golden within one step per channel (text and lines are drawn on the CPU, the
// same on any machine but for that step).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "render/image_io.hpp"
#include "render_support.hpp"

namespace fs = std::filesystem;
using namespace render_support;

namespace {


}  // namespace

TEST(Snapshots, ReadoutsAndInsetMatchTheGoldensToOneStep) {
  std::ifstream list(kSource / "tests/golden/stills.txt");
  std::string line;
  int checked = 0;
  while (std::getline(list, line)) {
    if (line.empty() || line[0] == '#' || line.find("--no-readouts") != std::string::npos) continue;
    std::istringstream fields(line);
    std::string name, args;
    fields >> name;
    std::getline(fields, args);
    const fs::path with = scratch(name + ".png"), without = scratch(name + "-bare.png");
    ASSERT_EQ(rattleback("still" + args + " -q -o " + with.string()), 0) << name;
    ASSERT_EQ(rattleback("still" + args + " --no-readouts -q -o " + without.string()), 0) << name;
    render::Image a, bare, golden;
    ASSERT_TRUE(render::readPng(with.string(), a).ok());
    ASSERT_TRUE(render::readPng(without.string(), bare).ok());
    ASSERT_TRUE(render::readPng((kSource / "tests/golden" / (name + ".png")).string(), golden).ok());
    ASSERT_EQ(a.rgba.size(), golden.rgba.size()) << name;
    long drawn = 0, off = 0;
    for (std::size_t p = 0; p < a.rgba.size(); p += 4) {
      bool overlay = false, beyond = false;
      for (int c = 0; c < 3; ++c) {
        overlay = overlay || a.rgba[p + c] != bare.rgba[p + c];
        beyond = beyond || std::abs(a.rgba[p + c] - golden.rgba[p + c]) > 1;
      }
      drawn += overlay;
      off += overlay && beyond;
    }
    // The read-outs are there (title, time, spin, the inset's frame, labels and curve) …
    EXPECT_GT(drawn, 300) << name;
    // … and every one of their pixels is the golden's.
    EXPECT_EQ(off, 0) << name << ": " << off << " of the " << drawn << " read-out pixels differ from "
                      << "the golden by more than one step (" << with << ")";
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

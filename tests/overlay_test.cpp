// The read-outs and the inset against the goldens at one step: the snapshot comparison allows
// 0.5 % of a still's pixels to differ (another CPU moves ~0.1 % by a step), more than the whole
// time/spin read-out (≈200 dark pixels) or the inset's curve (≈70). Here the pixels the
// read-outs draw — those where a still and the same still with --no-readouts differ — must
// each match the golden within one step per channel (text and lines are drawn on the CPU, the
// same on any machine but for that step).
#include "render/overlay.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "render/image_io.hpp"
#include "render/renderer.hpp"
#include "render_support.hpp"
#include "scene/snapshot.hpp"

namespace fs = std::filesystem;
using namespace render_support;

namespace {

// A still (`rattleback ARGS`) and its --no-readouts twin, and which pixels the read-outs
// changed (beyond 2 levels in a channel), one flag per pixel. False (a test failure) when
// either could not be made.
struct Twins {
  render::Image with, bare;
  std::vector<bool> drawn;
};
bool twins(const std::string& args, Twins& out) {
  const fs::path with = scratch("with.png"), bare = scratch("bare.png");
  EXPECT_EQ(rattleback(args + " -o " + with.string()), 0) << args;
  EXPECT_EQ(rattleback(args + " --no-readouts -o " + bare.string()), 0) << args;
  if (!render::readPng(with.string(), out.with).ok() ||
      !render::readPng(bare.string(), out.bare).ok() ||
      out.with.rgba.size() != out.bare.rgba.size()) {
    std::error_code ec;
    ADD_FAILURE() << "unreadable stills for " << args << " (sizes " << fs::file_size(with, ec)
                  << " and " << fs::file_size(bare, ec) << " bytes; " << out.with.width << "x"
                  << out.with.height << " and " << out.bare.width << "x" << out.bare.height << ")";
    return false;
  }
  out.drawn.assign(out.with.rgba.size() / 4, false);
  for (std::size_t p = 0; p < out.with.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(out.with.rgba[p + c] - out.bare.rgba[p + c]) > 2) out.drawn[p / 4] = true;
  return true;
}

}  // namespace

TEST(Snapshots, ReadoutsAndInsetMatchTheGoldensToOneStep) {
  // The project's golden suite, each case as the `still` arguments that draw it.
  auto suite = scene::loadSnapshotSuite((kSource / "tests/golden/suite.yaml").string());
  ASSERT_TRUE(suite) << suite.error().text();
  int checked = 0;
  for (const scene::SnapshotCase& c : suite->cases) {
    const std::string name = c.name;
    const std::string args = " " + fs::path(c.scene).lexically_relative(kSource).string() +
                             " --view " + std::string(rb::nameOf(*c.view)) + " --size " +
                             std::to_string((*c.size)[0]) + "x" + std::to_string((*c.size)[1]) +
                             " --t " + c.t_text;
    const fs::path with = scratch(name + ".png"), without = scratch(name + "-bare.png");
    ASSERT_EQ(rattleback("still" + args + " -q -o " + with.string()), 0) << name;
    ASSERT_EQ(rattleback("still" + args + " --no-readouts -q -o " + without.string()), 0) << name;
    render::Image a, bare, golden;
    ASSERT_TRUE(render::readPng(with.string(), a).ok());
    ASSERT_TRUE(render::readPng(without.string(), bare).ok());
    ASSERT_TRUE(
        render::readPng((kSource / "tests/golden" / (name + ".png")).string(), golden).ok());
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
    EXPECT_EQ(off, 0) << name << ": " << off << " of the " << drawn
                      << " read-out pixels differ from "
                      << "the golden by more than one step (" << with << ")";
    ++checked;
  }
  EXPECT_GE(checked, 4);
}

// The read-outs and the inset never cover the body: for each shipped scene, in every
// view, a quarter of the way through the run, the pixels the read-outs change
// (a still against its --no-readouts twin, beyond 2 levels) hold no body pixel of the twin (a
// saturated red or blue point: red > 120 with green, blue < 80; blue > 120 with red < 80 and
// green < 120). Zero such pixels are allowed: the overlay is drawn after the scene, so any is a
// point hidden from the viewer.
TEST(Overlay, ReadoutsNeverCoverTheBody) {
  struct Scene {
    const char* name;
    double duration;
  };
  for (const Scene scene :
       {Scene{"rattleback", 8}, Scene{"kane-levinson", 8}, Scene{"seed-flip-ccw", 10}}) {
    for (const char* view : {"oblique", "above", "front", "side", "follow"}) {
      for (double fraction : {0.25}) {
        for (const char* size : {"480x270", "180x180"}) {
          Twins t;
          ASSERT_TRUE(twins(std::string("still scenes/") + scene.name + ".yaml --size " + size +
                                " --view " + view + " --t " +
                                std::to_string(fraction * scene.duration),
                            t));
          long covered = 0;
          for (std::size_t i = 0; i < t.drawn.size(); ++i) {
            const int r = t.bare.rgba[4 * i], g = t.bare.rgba[4 * i + 1],
                      bl = t.bare.rgba[4 * i + 2];
            const bool body = (r > 120 && g < 80 && bl < 80) || (bl > 120 && r < 80 && g < 120);
            covered += t.drawn[i] && body;
          }
          EXPECT_EQ(covered, 0) << scene.name << ", " << view << ", " << size
                                << ", t = " << fraction * scene.duration << ": " << covered
                                << " body pixels under the read-outs";
        }
      }
    }
  }
}

// The read-outs fit the frame whatever its shape: in a portrait still the time/spin line (about
// 50 characters) ran off the right edge at a 36th of the height. No pixel the read-outs change
// lies on the outermost two columns or rows, for landscape, portrait and tall frames.
// Frames smaller than 180 pixels a side (the body fills them) carry no read-outs at all; from
// 180 up they do.
TEST(Overlay, SmallFramesCarryNoReadouts) {
  for (const char* size : {"100x100", "160x90", "400x170"}) {
    Twins t;
    ASSERT_TRUE(twins(std::string("still scenes/rattleback.yaml --t 2 --size ") + size, t));
    EXPECT_EQ(std::count(t.drawn.begin(), t.drawn.end(), true), 0) << size;
  }
  Twins t;
  ASSERT_TRUE(twins("still scenes/rattleback.yaml --t 2 --size 180x180", t));
  EXPECT_GT(std::count(t.drawn.begin(), t.drawn.end(), true), 100);
}

TEST(Overlay, ReadoutsFitPortraitAndLandscapeFrames) {
  // The values put in over the file lengthen the title (a variant is named by them); a title
  // too long for the frame is cut with an ellipsis.
  const std::string values =
      " --set body.paraboloid.s=0.02 --set body.mass=0.07 --set contact.air_drag=0";
  for (const std::string& size : std::vector<std::string>{"640x360", "360x640", "200x600",
                                                          "360x640" + values, "200x600" + values}) {
    Twins t;
    ASSERT_TRUE(twins(std::string("still scenes/rattleback.yaml --t 2 --size ") + size, t));
    const int width = t.with.width, height = t.with.height;
    long on_edge = 0, drawn = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const bool changed = t.drawn[static_cast<std::size_t>(y) * width + x];
        drawn += changed;
        on_edge += changed && (x < 2 || y < 2 || x >= width - 2 || y >= height - 2);
      }
    EXPECT_GT(drawn, 100) << size << ": no read-outs drawn";
    EXPECT_EQ(on_edge, 0) << size << ": read-outs reach the edge of the frame";
  }
}

// A variant's title names the values put in over its file (a teacher's trial: a class's bodies
// made with --set all read "mine: spun -5 rad/s"): the title runs further right than the same
// scene's without them.
TEST(Overlay, AVariantsTitleNamesItsValues) {
  // The rightmost text pixel (dark: the text is (30, 30, 30), the floor and sky far lighter) in
  // the title's rows: its baseline is two lines down (a line is a 36th of the height), the
  // read-outs' a line and a half below it. (The title is drawn with --no-readouts too, so it
  // is not among the pixels Twins finds the read-outs drew.)
  auto titleEnd = [](const std::string& args) {
    const fs::path png = scratch("title.png");
    EXPECT_EQ(rattleback(args + " -o " + png.string()), 0) << args;
    render::Image image;
    EXPECT_TRUE(render::readPng(png.string(), image).ok());
    int right = -1;
    for (int y = 0; y < image.height / 18; ++y)
      for (int x = 0; x < image.width; ++x) {
        const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
        if (p[0] < 80 && p[1] < 80 && p[2] < 80) right = std::max(right, x);
      }
    return right;
  };
  const int plain = titleEnd("still scenes/rattleback.yaml --size 1280x720");
  const int variant = titleEnd("still scenes/rattleback.yaml --size 1280x720 --set body.mass=0.07");
  // (", body.mass = 0.07" is 18 characters of about 11 px at 20 px text: some 200 px further;
  // 100 leaves room for the font.)
  EXPECT_GT(plain, 200);
  EXPECT_GT(variant, plain + 100);
}

// The floor's scale is said in the unit that makes it a whole number of at least 1 (the squares
// are 1, 2 or 5 × 10ⁿ m, held in float: 0.01f is 0.0099999998, which read "10 mm").
TEST(Overlay, TheFloorsScaleIsSaidInItsUnit) {
  EXPECT_EQ(render::lengthText(0.01f), "1 cm");
  EXPECT_EQ(render::lengthText(0.02f), "2 cm");
  EXPECT_EQ(render::lengthText(0.05f), "5 cm");
  EXPECT_EQ(render::lengthText(0.5f), "50 cm");
  EXPECT_EQ(render::lengthText(0.005f), "5 mm");
  EXPECT_EQ(render::lengthText(0.001f), "1 mm");
  EXPECT_EQ(render::lengthText(1.0f), "1 m");
  EXPECT_EQ(render::lengthText(2.0f), "2 m");
}

// A longer body is drawn as large as the default one (each view frames its body), so the floor's
// scale is what tells them apart (a teacher's trial: bodies of 20, 24.5 and 40 cm were all
// 262 pixels long): the square follows the body's size in steps of 1, 2, 5, and every still with
// read-outs says it, in a box in the bottom-left corner.
TEST(Overlay, AStillSaysItsFloorsScale) {
  // A fifth of the half length rounded down to 1, 2 or 5 × 10ⁿ m: 9.6 cm gives 1 cm squares,
  // 28.8 cm 5 cm, and front and side four times deeper.
  EXPECT_FLOAT_EQ(render::floorSquare({0.096f, 0.03f, 0.02f}, false), 0.01f);
  EXPECT_FLOAT_EQ(render::floorSquare({0.288f, 0.09f, 0.06f}, false), 0.05f);
  EXPECT_FLOAT_EQ(render::floorSquare({0.288f, 0.09f, 0.06f}, true), 0.2f);
  EXPECT_FLOAT_EQ(render::floorSquare({0.03f, 0.2f, 0.02f}, false), 0.02f);  // along y
  for (const char* view : {"oblique", "above", "front", "side", "follow"}) {
    Twins t;
    ASSERT_TRUE(
        twins(std::string("still scenes/rattleback.yaml --size 640x360 --view ") + view, t));
    long corner = 0, all = 0;
    for (int y = 0; y < t.with.height; ++y)
      for (int x = 0; x < t.with.width; ++x) {
        const bool drawn = t.drawn[static_cast<std::size_t>(y) * t.with.width + x];
        all += drawn;
        corner += drawn && y >= t.with.height * 3 / 4 && x < t.with.width / 3;
      }
    EXPECT_GT(corner, 1000) << view << " of " << all;
  }
}

// The inset's curve is read from the back of a room: at 720p it is at least 3 px thick, at
// 1080p at least 4, while a 180-px frame (the goldens') keeps its 2 px. Counted down the
// middle column of a flat curve at n = range / 2: the rows at least half covered by it.
namespace {
int curveRows(int width, int height) {
  render::Image image;
  image.width = width, image.height = height;
  image.rgba.assign(static_cast<std::size_t>(width) * height * 4, 255);
  render::Overlay font;
  EXPECT_EQ(font.load(std::max(10, height / 24)), "");
  const std::vector<std::array<float, 2>> history{{0.0f, 2.5f}, {8.0f, 2.5f}};
  render::drawSpinInset(image, font, history, 8.0, 5.0, {});
  const int x = width - width * 3 / 20 - height / 40;  // about the inset's middle
  int rows = 0;
  for (int y = render::insetTop(height); y < height; ++y) {
    const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * width + x) * 4];
    if (p[0] < 140 && p[2] > p[0] + 60) ++rows;  // the curve's blue, at least half covering
  }
  return rows;
}
}  // namespace

TEST(Overlay, TheInsetsCurveIsThickEnoughToReadAtADistance) {
  EXPECT_EQ(curveRows(320, 180), 2);
  EXPECT_GE(curveRows(1280, 720), 3);
  EXPECT_GE(curveRows(1920, 1080), 4);
}

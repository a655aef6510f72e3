// The body drawn as its closed surface (`--surface triangles`, video.surface): in the points'
// colours by their rule (red where the surface faces up in the body frame, blue where it faces
// down; docs/commands.md "rattleback render"), and covering the picture the points cover.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "render/image_io.hpp"
#include "render_support.hpp"

namespace {

using namespace render_support;

// The body's colours as the other render tests tell them (the floor, the background and the
// read-outs are grey, the spin cue green).
enum class Hue { None, Red, Blue };
Hue hueAt(const render::Image& image, int x, int y) {
  const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  if (p[0] > p[1] + 60 && p[0] > p[2] + 60) return Hue::Red;
  if (p[2] > p[0] + 60 && p[2] > p[1] + 40) return Hue::Blue;
  return Hue::None;
}

render::Image still(const std::string& options) {
  const fs::path png = scratch("still.png");
  EXPECT_EQ(rattleback("still " + options + " --no-readouts -q -o " + png.string()), 0) << options;
  render::Image image;
  EXPECT_TRUE(render::readPng(png.string(), image)) << options;
  return image;
}

struct Hues {
  long red = 0, blue = 0;
};
Hues huesOf(const render::Image& image) {
  Hues h;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Hue hue = hueAt(image, x, y);
      if (hue == Hue::Red) ++h.red;
      if (hue == Hue::Blue) ++h.blue;
    }
  return h;
}

}  // namespace

// Seen from above the body shows its top: red. Turned upside down (initial.tilt [180, 0], drawn
// at its release) the same camera sees its bottom: blue. For the paraboloid (tessellated) and
// the printed mesh body (its own triangles). Measured at 320 × 180: 99.9–100 % of the body's
// pixels are of the expected colour either way (the rest: edges blended over the floor); the
// bound is 95 %. A rule turned over, or colours by anything but the faces' facing, fails.
TEST(Triangles, TopIsRedAndBottomIsBlue) {
  for (const std::string scene : {"scenes/rattleback.yaml", "scenes/printed.yaml"}) {
    const std::string options = scene + " --surface triangles --view above --size 320x180";
    // (From above the body is drawn below the read-outs, at 0.73 of the frame's scale: 1,725 to
    // 1,802 pixels of its colour, measured; about half what it had, when 2,000 was the bound.)
    const Hues up = huesOf(still(options + " --t 1"));
    EXPECT_GT(up.red, 1200) << scene;
    EXPECT_GT(up.red, 0.95 * (up.red + up.blue)) << scene << ": " << up.blue << " blue px";
    const Hues down = huesOf(still(options + " --set initial.tilt=[180,0]"));
    EXPECT_GT(down.blue, 1200) << scene;
    EXPECT_GT(down.blue, 0.95 * (down.red + down.blue)) << scene << ": " << down.red << " red px";
  }
}

// A pixel of the body's colour, however shaded (its dents' dark sides too): the floor, the
// background and the shadow are grey, the title dark grey.
bool coloured(const render::Image& image, int x, int y) {
  const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  return std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) > 40;
}

// The body's outline: on each row, every pixel from its first coloured one to its last. (The
// points leave the floor showing between their rows, where the triangles are solid; the body's
// outline is convex along each row in every view.)
std::vector<bool> outlineOf(const render::Image& image) {
  std::vector<bool> inside(static_cast<std::size_t>(image.width) * image.height, false);
  for (int y = 0; y < image.height; ++y) {
    int first = image.width, last = -1;
    for (int x = 0; x < image.width; ++x)
      if (coloured(image, x, y)) first = std::min(first, x), last = std::max(last, x);
    for (int x = first; x <= last; ++x)
      inside[static_cast<std::size_t>(y) * image.width + x] = true;
  }
  return inside;
}

// The triangles are the surface the points sample, posed by the same model matrix: in one
// frame they fill the outline the points fill. Compared from above, from the side and from the
// oblique camera at 640 × 360, by the share of pixels inside either outline that are inside
// both (intersection over union). Measured: 0.969, 0.958 and 0.949 (the points' spheres reach
// their radius beyond the surface, 1 px here, and blend their edges); the bound is 0.93.
// Triangles drawn 5 % too large fall below it from above and from the side (0.910); drawn
// without the body's turn, to 0.18–0.24. (A pose off by the default body's centre of mass,
// 0.34 mm below the shape's origin, is under 2 px here, and not caught.)
TEST(Triangles, FillThePointsOutline) {
  for (const std::string view : {"above", "side", "oblique"}) {
    const std::string options =
        "scenes/rattleback.yaml --t 1 --size 640x360 --view " + view + " --surface ";
    const std::vector<bool> points = outlineOf(still(options + "points"));
    const std::vector<bool> triangles = outlineOf(still(options + "triangles"));
    ASSERT_EQ(points.size(), triangles.size());
    long both = 0, either = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      both += points[i] && triangles[i];
      either += points[i] || triangles[i];
    }
    ASSERT_GT(either, 5000) << view;
    EXPECT_GT(static_cast<double>(both) / either, 0.93)
        << view << ": " << both << " of " << either << " px in both outlines";
  }
}

// The key's and the option's words are checked before anything is drawn.
TEST(Triangles, AnUnknownSurfaceIsRefused) {
  const fs::path png = scratch("refused.png");
  EXPECT_EQ(rattleback("still scenes/rattleback.yaml --surface dots -o " + png.string()), 2);
  EXPECT_FALSE(fs::exists(png));
}

// The spin cue (docs/commands.md "The spin cue"): an arrow on the floor around the body that
// turns the body's way in the direction's colour, its sweep growing with |n|; "reversal at T s"
// for a while after each reversal and a tick on the inset; none of it without read-outs. Drawn
// by a Renderer directly from frame values (no run), so each property is one change of input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "render/overlay.hpp"
#include "render/renderer.hpp"
#include "render_support.hpp"

namespace {

// A flat bar 16 cm long along y on the floor, as the default body is drawn (red top, blue
// bottom), framed as the fixed views frame a run (media::framingOf: 1.25 × its reach).
render::BodyPoints bar() {
  render::BodyPoints body;
  for (int i = 0; i < 200; ++i) {
    const float y = -0.08f + 0.16f * static_cast<float>(i) / 199;
    for (float x : {-0.01f, 0.0f, 0.01f}) {
      body.top.emplace_back(x, y, 0.006f);
      body.bottom.emplace_back(x, y, -0.006f);
    }
  }
  body.radius = 0.002f;
  body.footprint_half = {0.012f, 0.08f};
  return body;
}

render::Image draw(double spin, double t, std::vector<double> reversals, bool readouts = true,
                   int width = 640, int height = 360, render::View view = render::View::Oblique) {
  const render::BodyPoints body = bar();
  render::RenderSettings s;
  s.width = width;
  s.height = height;
  const std::string backend = render_support::backendName();
  s.backend = backend == "osmesa" ? render::Backend::OsMesa
              : backend == "egl"  ? render::Backend::Egl
                                  : render::Backend::Auto;
  s.readouts = readouts;
  s.view = view;
  s.title = "spin cue";  // as a still's: drawn with or without read-outs
  s.duration = 8;
  s.spin_range = 5.5;  // 1.1 × a spin of 5 rad/s, as media/video_plan.cpp sets it
  auto created = render::Renderer::create(s, body);
  render::Image out;
  if (!created) {
    ADD_FAILURE() << created.error().text();
    return out;
  }
  render::FrameInput f;
  f.t = t;
  f.spin = spin;
  f.position_world = {0, 0, 0.008};
  f.orientation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ());
  f.framing.center = Eigen::Vector3f(0, 0, 0.008f);
  f.framing.radius = 1.25f * render::reachOf(body);
  const std::vector<std::array<float, 2>> history{
      {0, static_cast<float>(spin)}, {static_cast<float>(t), static_cast<float>(spin)}};
  f.history = history;
  f.reversals = reversals;
  created.value()->draw(f, out);
  return out;
}

// Pixels within 12 levels of `color` in every channel (its solid core: the anti-aliased edge
// blends it with the dark rim and the floor), and their mean column.
struct Count {
  long pixels = 0;
  double mean_x = 0;
};
Count countOf(const render::Image& image, render::Rgba color) {
  Count c;
  double sum_x = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
      if (std::abs(p[0] - color[0]) <= 12 && std::abs(p[1] - color[1]) <= 12 &&
          std::abs(p[2] - color[2]) <= 12) {
        ++c.pixels;
        sum_x += x;
      }
    }
  c.mean_x = c.pixels ? sum_x / static_cast<double>(c.pixels) : 0;
  return c;
}

}  // namespace

// A later reversal's badge carries its number ("reversal 2 at 2.00 s"): a body that reverses
// three times showed "reversal at 6.93 s" and a class asked which one. The badge's right edge
// stays put, so the numbered one reaches further left; the first keeps its plain words.
TEST(SpinCue, ALaterReversalIsNumbered) {
  const Count first = countOf(draw(0.3, 2.1, {2.0}), render::kReversalColor);
  const Count second = countOf(draw(0.3, 2.1, {1.0, 2.0}), render::kReversalColor);
  ASSERT_GT(first.pixels, 500);
  // " 2" widens the badge's fill by two characters: 273 px more at 640×360 (measured; about
  // 2 × 7 px × 20 px). Half of that is beyond any edge's rounding, and one character short.
  EXPECT_GT(second.pixels, first.pixels + 135) << "the second reversal's badge is no wider";
  EXPECT_LT(second.mean_x, first.mean_x);
}

// n > 0 is counter-clockwise seen from above (docs/physics.md, sign convention): the near side of
// a body turning so moves to the viewer's right. The arrow lies on the near half of a circle
// around the body with its head at the end it travels to, so its head, and with it the mean
// column of its coloured pixels, is right of the middle for n > 0 and left for n < 0 (the arc
// alone is symmetric: the head is the difference). Its colour is the direction's, and only it.
TEST(SpinCue, TurnsTheWayTheBodyTurnsInItsColour) {
  const render::Image ccw = draw(+3, 1, {}), cw = draw(-3, 1, {});
  const Count ccw_orange = countOf(ccw, render::kCounterClockwiseColor);
  const Count ccw_green = countOf(ccw, render::kClockwiseColor);
  const Count cw_orange = countOf(cw, render::kCounterClockwiseColor);
  const Count cw_green = countOf(cw, render::kClockwiseColor);
  // (At 640×360 the arrow is 3 px wide and some 200 px long: ~600 core pixels; measured 1000
  // and more. 200 is a third of the least it can be and far above the none that a missing
  // arrow leaves.)
  EXPECT_GT(ccw_orange.pixels, 200);
  EXPECT_EQ(ccw_green.pixels, 0);
  EXPECT_GT(cw_green.pixels, 200);
  EXPECT_EQ(cw_orange.pixels, 0);
  // The head is ~10 px long and wide; it moves the mean column by a few pixels either way.
  // The frame's middle column (320) lies between the two.
  EXPECT_GT(ccw_orange.mean_x, 322) << "n > 0: the head should be on the right";
  EXPECT_LT(cw_green.mean_x, 318) << "n < 0: the head should be on the left";
}

// The sweep is |n| over the inset's range: at 4 rad/s the arrow is longer than at 1.
TEST(SpinCue, GrowsWithTheSpin) {
  const long slow = countOf(draw(1, 1, {}), render::kCounterClockwiseColor).pixels;
  const long fast = countOf(draw(4, 1, {}), render::kCounterClockwiseColor).pixels;
  EXPECT_GT(slow, 0);
  // 4 times the sweep; the head is the same: well over twice the pixels.
  EXPECT_GT(fast, 2 * slow) << "slow " << slow << ", fast " << fast;
}

// No arrow for a spin the read-out gives no direction (|n| < 0.05 rad/s), and no cue, label or
// tick without read-outs: such a frame is the same whatever the spin and the reversals.
TEST(SpinCue, NoneWithoutReadoutsOrSpin) {
  const render::Image still = draw(0.04, 1, {});
  EXPECT_EQ(countOf(still, render::kCounterClockwiseColor).pixels, 0);
  EXPECT_EQ(countOf(still, render::kClockwiseColor).pixels, 0);
  const render::Image bare = draw(0, 2.5, {}, false);
  const render::Image spun = draw(-3, 2.5, {2.0}, false);
  EXPECT_EQ(countOf(spun, render::kClockwiseColor).pixels, 0);
  EXPECT_TRUE(bare.rgba == spun.rgba) << "a frame without read-outs changed with the spin";
}

// "reversal at T s" (in its yellow box) from the reversal on for kReversalShownFor, and not
// before it nor after; the inset's tick from the reversal on, within the inset.
TEST(SpinCue, ReversalIsMarkedOnlyAfterIt) {
  const std::vector<double> at2{2.0};
  auto yellow = [](const render::Image& i) { return countOf(i, render::kReversalColor).pixels; };
  EXPECT_EQ(yellow(draw(0.3, 1.9, at2)), 0) << "marked before the reversal";
  EXPECT_TRUE(draw(-0.3, 1.9, at2).rgba == draw(-0.3, 1.9, {}).rgba)
      << "a reversal to come changed the frame (its tick or label drawn early)";
  // (The box is a line of text high and some 18 characters wide: thousands of pixels.)
  EXPECT_GT(yellow(draw(0.3, 2.1, at2)), 500) << "not marked just after the reversal";
  EXPECT_GT(yellow(draw(0.3, 2.0 + render::kReversalShownFor - 0.05, at2)), 500);
  EXPECT_EQ(yellow(draw(0.3, 2.0 + render::kReversalShownFor + 0.05, at2)), 0)
      << "still marked long after the reversal";
  // The tick: a frame long after the reversal differs from the same frame without it only
  // inside the inset (the bottom-right box), and there by a line across its band.
  const render::Image with = draw(0.3, 5, at2), without = draw(0.3, 5, {});
  long inside = 0, outside = 0;
  const int top = render::insetTop(with.height);
  for (int y = 0; y < with.height; ++y)
    for (int x = 0; x < with.width; ++x) {
      const std::size_t p = (static_cast<std::size_t>(y) * with.width + x) * 4;
      const bool differs =
          with.rgba[p] != without.rgba[p] || with.rgba[p + 1] != without.rgba[p + 1];
      (x > with.width / 2 && y >= top ? inside : outside) += differs;
    }
  EXPECT_EQ(outside, 0);
  // (The inset's band is ~50 px high at 360p and the tick 2 px wide: ~100 pixels.)
  EXPECT_GT(inside, 40);
}

// The inset and the floor's scale are drawn over the arrow; an end of the arrow that would run
// under either stops short of it (a long body seen from above had put the tail under
// the inset): the points of an arc's ends within the margin of a box go, the rest stay, even
// where its middle passes near one; an arc wholly under a box is none.
TEST(SpinCue, AnArrowsEndsStopShortOfTheTextBoxes) {
  std::vector<std::array<float, 2>> arc;
  for (int k = 0; k <= 10; ++k) arc.push_back({10.0f * k, 50.0f});  // x 0 … 100 along y = 50
  const render::Box left{-20, 40, 15, 60}, right{85, 40, 120, 60}, middle{45, 0, 55, 45};
  const render::Box both[] = {left, right, middle};
  // Within 2 px of the left box: x 0, 10 go; of the right: 90, 100 go (80 is 5 px off).
  auto kept = render::endsClearOf(arc, both, 2);
  ASSERT_EQ(kept.size(), 7u);
  EXPECT_EQ(kept.front()[0], 20.0f);
  EXPECT_EQ(kept.back()[0], 80.0f);
  // The middle box is within 5 px of x = 50, which is not an end: it stays.
  kept = render::endsClearOf(arc, both, 6);
  ASSERT_EQ(kept.size(), 5u);
  EXPECT_EQ(kept.front()[0], 30.0f);
  EXPECT_EQ(kept.back()[0], 70.0f);
  const render::Box all[] = {{-5, 0, 105, 100}};
  EXPECT_TRUE(render::endsClearOf(arc, all, 0).empty());
  EXPECT_EQ(render::endsClearOf(arc, {}, 100).size(), arc.size());
}

// A frame drawn at its reversal's own time (a still at t: reversal) has the inset's tick: the
// curve's times are floats, and a reversal at 2.0000000001 s, after the float 2.0 the curve
// ends at, had been left out. Only the inset's rows are compared (the badge is at the top).
TEST(SpinCue, AFrameAtItsReversalHasTheTick) {
  const double t = 2.0000000001;
  ASSERT_LT(static_cast<double>(static_cast<float>(t)), t);
  const render::Image ticked = draw(-0.3, t, {t}), plain = draw(-0.3, t, {});
  const std::size_t from =
      static_cast<std::size_t>(render::insetTop(plain.height)) * plain.width * 4;
  EXPECT_FALSE(std::equal(ticked.rgba.begin() + static_cast<std::ptrdiff_t>(from),
                          ticked.rgba.end(),
                          plain.rgba.begin() + static_cast<std::ptrdiff_t>(from)))
      << "no tick in the inset at the reversal's own time";
}

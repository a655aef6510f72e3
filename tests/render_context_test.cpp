// Renderers as the library's users hold them: several on one thread, each drawing with its own
// OpenGL context whatever the order (CurrentContext), on either backend.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "render/gl.hpp"
#include "render/image_io.hpp"
#include "render/renderer.hpp"

namespace {

// Two bodies of different point counts: a long row (1000 points) and a small ring (60).
render::BodyPoints row() {
  render::BodyPoints body;
  for (int i = 0; i < 500; ++i) {
    const float y = -0.08f + 0.16f * static_cast<float>(i) / 499;
    body.top.emplace_back(0.0f, y, 0.01f);
    body.bottom.emplace_back(0.0f, y, -0.01f);
  }
  body.radius = 0.002f;
  body.footprint_half = {0.01f, 0.08f};
  return body;
}

render::BodyPoints ring() {
  render::BodyPoints body;
  for (int i = 0; i < 30; ++i) {
    const float a = 2 * static_cast<float>(M_PI) * static_cast<float>(i) / 30;
    body.top.emplace_back(0.03f * std::cos(a), 0.03f * std::sin(a), 0.005f);
    body.bottom.emplace_back(0.02f * std::cos(a), 0.02f * std::sin(a), -0.005f);
  }
  body.radius = 0.003f;
  body.footprint_half = {0.03f, 0.03f};
  return body;
}

render::FrameInput pose(double t) {
  render::FrameInput f;
  f.t = t;
  f.spin = 2;
  f.position_world = {0, 0, 0.02};
  f.orientation = Eigen::AngleAxisd(2 * t, Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX());
  return f;
}

std::unique_ptr<render::Renderer> make(render::Backend backend, const render::BodyPoints& body) {
  render::RenderSettings s;
  s.width = 160;
  s.height = 90;
  s.backend = backend;
  s.readouts = false;
  auto created = render::Renderer::create(s, body);
  if (!created) {
    ADD_FAILURE() << created.error().text();
    return nullptr;
  }
  return std::move(created).value();
}

void twoRenderersTakingTurns(render::Backend backend) {
  const std::vector<double> times = {0.0, 0.3, 0.6};
  // Each alone: its own renderer, its frames in order, destroyed before the next is made.
  std::vector<render::Image> row_alone, ring_alone;
  {
    auto r = make(backend, row());
    ASSERT_TRUE(r);
    for (double t : times) r->draw(pose(t), row_alone.emplace_back());
  }
  {
    auto r = make(backend, ring());
    ASSERT_TRUE(r);
    for (double t : times) r->draw(pose(t), ring_alone.emplace_back());
  }
  // Both alive on this thread, drawing in turns; the second one made after the first drew.
  auto a = make(backend, row());
  ASSERT_TRUE(a);
  render::Image first;
  a->draw(pose(times[0]), first);
  auto b = make(backend, ring());
  ASSERT_TRUE(b);
  EXPECT_EQ(first.rgba, row_alone[0].rgba);
  for (std::size_t i = 0; i < times.size(); ++i) {
    render::Image from_b, from_a;
    b->draw(pose(times[i]), from_b);
    a->draw(pose(times[i]), from_a);
    EXPECT_EQ(from_a.rgba, row_alone[i].rgba) << "the row's frame " << i;
    EXPECT_EQ(from_b.rgba, ring_alone[i].rgba) << "the ring's frame " << i;
  }
  // The two bodies look different (the test compares something).
  EXPECT_NE(row_alone[1].rgba, ring_alone[1].rgba);
  // Destroying one leaves the other drawing as before.
  b.reset();
  render::Image after;
  a->draw(pose(times[2]), after);
  EXPECT_EQ(after.rgba, row_alone[2].rgba);
}

}  // namespace

TEST(Renderer, TwoRenderersOnOneThreadDrawAsEachAloneWithEgl) {
  twoRenderersTakingTurns(render::Backend::Egl);
}

TEST(Renderer, TwoRenderersOnOneThreadDrawAsEachAloneWithOsMesa) {
  twoRenderersTakingTurns(render::Backend::OsMesa);
}

// The same frame through either backend: llvmpipe behind both, byte-identical here; the
// goldens hold for both within their tolerance (Snapshots.* run with RATTLEBACK_BACKEND).
TEST(Renderer, BothBackendsDrawTheSameFrame) {
  auto egl = make(render::Backend::Egl, row());
  auto osmesa = make(render::Backend::OsMesa, row());
  ASSERT_TRUE(egl && osmesa);
  render::Image a, b;
  egl->draw(pose(0.3), a);
  osmesa->draw(pose(0.3), b);
  const render::Comparison c = render::compareImages(a, b, 2);
  EXPECT_LE(c.fraction(), 0.005) << c.differing << " pixels differ";
  EXPECT_NE(egl->description().find("EGL"), std::string::npos) << egl->description();
  EXPECT_NE(osmesa->description().find("OSMesa"), std::string::npos) << osmesa->description();
}

// A frame depends on its own values only: frames drawn in reverse order (each with its own
// history of the spin so far) equal the frames drawn in order, byte for byte.
TEST(Renderer, FramesDrawnInReverseOrderEqualFramesDrawnInOrder) {
  std::vector<std::array<float, 2>> history;
  std::vector<render::FrameInput> frames;
  for (int k = 0; k < 5; ++k) {
    render::FrameInput f = pose(0.2 * k);
    f.spin = 2 - k;
    f.position_world.x() = 0.01 * k;  // it moves: a camera that followed it would show it
    f.framing.center = {0, 0, 0.02f};
    f.framing.radius = 0.12f;
    frames.push_back(f);
  }
  std::vector<std::vector<std::array<float, 2>>> histories(frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    history.push_back({static_cast<float>(frames[k].t), static_cast<float>(frames[k].spin)});
    histories[k] = history;
  }
  for (std::size_t k = 0; k < frames.size(); ++k) frames[k].history = histories[k];
  for (render::View view : {render::View::Oblique, render::View::Follow, render::View::Above}) {
    render::RenderSettings s;
    s.width = 160;
    s.height = 90;
    s.view = view;
    s.duration = 1;
    s.spin_range = 3;
    auto forward = render::Renderer::create(s, row());
    auto backward = render::Renderer::create(s, row());
    ASSERT_TRUE(forward && backward);
    std::vector<render::Image> in_order(frames.size()), reversed(frames.size());
    for (std::size_t k = 0; k < frames.size(); ++k) forward.value()->draw(frames[k], in_order[k]);
    for (std::size_t k = frames.size(); k-- > 0;) backward.value()->draw(frames[k], reversed[k]);
    for (std::size_t k = 0; k < frames.size(); ++k)
      EXPECT_EQ(in_order[k].rgba, reversed[k].rgba) << rb::nameOf(view) << ", frame " << k;
    EXPECT_NE(in_order[0].rgba, in_order[4].rgba);
  }
}

// Small spheres are drawn as discs at their nearest point (no depth per fragment, so llvmpipe
// tests depth before shading); from 4 px in radius each fragment gets the sphere's true depth.
// A plate of two layers of spheres, close enough that they overlap on screen: in a 480×270
// frame (spheres under 4 px in radius) the discs differ from the true surfaces only where
// spheres overlap, in a fraction of a percent of the pixels (the same bound as the goldens'
// 0.2 %, doubled: this body is all overlaps); in a 2560×1440 frame (over 4 px) the exact
// depth is used whatever the setting, so the two frames are the same.
TEST(Renderer, SmallSpheresAsDiscsDifferOnlyWhereTheyOverlap) {
  render::BodyPoints plate;
  for (int i = -20; i <= 20; ++i)
    for (int j = -6; j <= 6; ++j) {
      const float x = 0.004f * j, y = 0.004f * i;
      plate.top.emplace_back(x, y, 0.004f);
      plate.bottom.emplace_back(x + 0.002f, y + 0.002f, 0.001f - 2 * (x * x + y * y));
    }
  plate.spacing = 0.004f;
  plate.radius = 0.0022f;  // neighbours cut into each other: where depth per fragment shows
  plate.footprint_half = {0.024f, 0.08f};
  render::FrameInput f = pose(0.3);
  f.framing.center = {0, 0, 0.02f};
  f.framing.radius = 0.1f;
  auto frame = [&](int width, int height, bool exact) {
    render::RenderSettings s;
    s.width = width;
    s.height = height;
    s.readouts = false;
    s.exact_sphere_depth = exact;
    render::Image image;
    auto r = render::Renderer::create(s, plate);
    if (!r) {
      ADD_FAILURE() << r.error().text();
      return image;
    }
    r.value()->draw(f, image);
    return image;
  };
  const render::Comparison small =
      render::compareImages(frame(480, 270, false), frame(480, 270, true), 2);
  EXPECT_GT(small.differing, 0) << "the discs were not drawn";
  EXPECT_LT(small.fraction(), 0.004) << small.differing << " of " << small.pixels;
  const render::Comparison large =
      render::compareImages(frame(2560, 1440, false), frame(2560, 1440, true), 0);
  EXPECT_EQ(large.differing, 0);
}

// Each frame copies back only the part of the cached floor the frame before drew over (the
// body and its shadow, bounded on screen): a frame drawn after others is byte for byte the
// frame a new renderer draws first (which copies the whole floor). The body turns, tips, moves
// across the floor and towards the camera, so the bounds move and grow frame to frame.
TEST(Renderer, AFrameAfterOthersEqualsTheSameFrameDrawnFirst) {
  render::BodyPoints body = row();
  body.radius = 0.004f;  // large spheres: the margin around their centres counts
  std::vector<render::FrameInput> frames;
  for (int k = 0; k < 8; ++k) {
    render::FrameInput f = pose(0.4 * k);
    f.orientation = Eigen::AngleAxisd(0.9 * k, Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(0.3 * std::sin(k), Eigen::Vector3d::UnitX());
    f.position_world = {0.03 * std::cos(k), -0.02 * k, 0.02 + 0.004 * k};
    f.framing.center = {0, -0.07f, 0.02f};
    f.framing.radius = 0.16f;
    frames.push_back(f);
  }
  // 16:9, and a portrait frame (the scene drawn scaled between the read-outs and the inset).
  for (auto [width, height] : {std::pair{320, 180}, std::pair{200, 240}})
    for (render::View view :
         {render::View::Oblique, render::View::Above, render::View::Front, render::View::Side}) {
      render::RenderSettings s;
      s.width = width;
      s.height = height;
      s.view = view;
      s.readouts = false;
      auto running = render::Renderer::create(s, body);
      ASSERT_TRUE(running) << running.error().text();
      for (std::size_t k = 0; k < frames.size(); ++k) {
        render::Image after_others, first;
        running.value()->draw(frames[k], after_others);
        auto fresh = render::Renderer::create(s, body);
        ASSERT_TRUE(fresh);
        fresh.value()->draw(frames[k], first);
        const render::Comparison c = render::compareImages(after_others, first, 0);
        EXPECT_EQ(c.differing, 0) << width << "x" << height << " " << rb::nameOf(view) << ", frame "
                                  << k << ": within x " << c.box[0] << "–" << c.box[2] << ", y "
                                  << c.box[1] << "–" << c.box[3];
      }
    }
}

// The driver can be loaded on another thread while this one loads its scene (as `render` and
// `still` do), also while a context is being made: the frames are the same as without.
TEST(Renderer, ADriverLoadedOnAnotherThreadDrawsTheSameFrames) {
  for (render::Backend backend : {render::Backend::Egl, render::Backend::OsMesa}) {
    render::Image without, with;
    {
      auto r = make(backend, row());
      ASSERT_TRUE(r);
      r->draw(pose(0.3), without);
    }
    std::thread preload([backend] { render::preloadBackend(backend); });
    auto r = make(backend, row());  // maybe while the other thread still loads
    preload.join();
    std::thread([backend] { render::preloadBackend(backend); }).join();  // and again, after
    ASSERT_TRUE(r);
    r->draw(pose(0.3), with);
    EXPECT_EQ(with.rgba, without.rgba) << rb::nameOf(backend);
  }
}

namespace {

// A child process whose other thread draws frame after frame while the main thread calls
// exit(): Mesa's exit handlers free the driver's state then, and a frame still being drawn
// crashed (SIGSEGV in llvmpipe) or hung (an exit handler joining llvmpipe's threads). The
// child's exit status: 0 when the exit went cleanly; 128 + the signal that ended it (SIGALRM
// when it hung).
int exitWhileAnotherThreadDraws(render::Backend backend) {
  const pid_t child = fork();
  if (child == 0) {
    alarm(30);  // a frame takes milliseconds: 30 s is a hang, also on a loaded machine
    render::RenderSettings s;
    s.width = 640;
    s.height = 480;
    s.backend = backend;
    auto created = render::Renderer::create(s, row());
    if (!created) _exit(3);
    std::atomic<int> frames{0};
    std::thread([&] {
      render::Image image;
      for (int i = 0;; ++i, ++frames) created.value()->draw(pose(0.01 * i), image);
    }).detach();
    while (frames < 2) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

// Fifteen exits a backend. Without the wait at exit, 18 of 30 exits with OSMesa crashed or hung
// (measured), 1 of 30 with EGL: fifteen clean exits by chance are 1 in 10^6 with OSMesa.
TEST(Renderer, TheProcessExitsCleanlyWhileAnotherThreadDraws) {
  for (render::Backend backend : {render::Backend::Egl, render::Backend::OsMesa})
    for (int i = 0; i < 15; ++i)
      ASSERT_EQ(exitWhileAnotherThreadDraws(backend), 0) << rb::nameOf(backend) << ", exit " << i;
}

// A title too wide for the frame is said in the first shorter form that fits (a --both half's:
// "mine, at 2× speed: spun -8 rad/s, against its preferred way" ran past a 427-wide half and
// was cut to "… against its preferred …"), and only the last is cut.
TEST(Renderer, ATitleTooWideTakesTheFirstShorterFormThatFits) {
  // A --both half's text (1.4 times its usual size): a line of about 45 characters fits a frame
  // of any width.
  auto titleOf = [](const std::string& title, std::vector<std::string> shorter) {
    render::RenderSettings s;
    s.width = 854;
    s.height = 480;
    s.text_scale = 1.4f;
    s.title = title;
    s.shorter_titles = std::move(shorter);
    auto created = render::Renderer::create(s, row());
    if (!created) {
      ADD_FAILURE() << created.error().text();
      return std::string();
    }
    return created.value()->title();
  };
  const std::string fits = "mine: spun -8 rad/s, against its preferred way";
  const std::string wide = "mine, at 2× speed: spun -8 rad/s, against its preferred way";
  const std::vector<std::string> shorter = {
      "mine, at 2× speed: spun -8 rad/s, against preferred way, and more words than fit",
      "-8 rad/s, against preferred way, at 2× speed", "-8 rad/s"};
  EXPECT_EQ(titleOf(fits, shorter), fits);
  EXPECT_EQ(titleOf(wide, shorter), "-8 rad/s, against preferred way, at 2× speed");
  const std::string cut = titleOf(wide, {});
  EXPECT_EQ(cut.substr(0, 10), "mine, at 2");
  EXPECT_EQ(cut.substr(cut.size() - 3), "…");
  EXPECT_LT(cut.size(), wide.size() + 3);  // (the ellipsis takes three bytes)
  EXPECT_EQ(wide.rfind(cut.substr(0, cut.size() - 3), 0), 0u);
}

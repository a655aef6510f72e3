// What the renderer and encoder write: snapshot stills against goldens, the MP4's stream
// and layout, --both naming, failures that leave nothing behind, and `compare`.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

extern "C" {
#include <libavformat/avformat.h>
#include <libavutil/pixdesc.h>
#include <png.h>
}

#include "render/image_io.hpp"
#include "render_support.hpp"

namespace fs = std::filesystem;
using namespace render_support;

// The golden stills themselves are checked by `rattleback snapshot tests/golden/suite.yaml`
// (CTest: Golden.StillsMatchTheSuite), as a user's suite is.

// The seed's views are what the seed's figures show: red on top, blue below. In the side
// view (looking across the body, 10° from above) the upper half of the body's pixels are
// mostly red and the lower half mostly blue. Rendered afresh (not read from the golden).
TEST(Snapshots, TopIsRedAndBottomIsBlue) {
  const fs::path side = scratch("side.png");
  ASSERT_EQ(
      rattleback("still scenes/seed-flip-ccw.yaml --view side --size 320x180 -o " + side.string()),
      0);
  render::Image image;
  ASSERT_TRUE(render::readPng(side.string(), image));
  long red_top = 0, blue_top = 0, red_bottom = 0, blue_bottom = 0;
  int first = image.height, last = 0;
  auto colour = [&](int x, int y) {
    const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return p[0] > 120 && p[1] < 80 && p[2] < 80 ? 1 : p[2] > 120 && p[0] < 80 && p[1] < 120 ? 2 : 0;
  };
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (colour(x, y)) {
        first = std::min(first, y);
        last = std::max(last, y);
      }
  const int middle = (first + last) / 2;
  for (int y = first; y <= last; ++y)
    for (int x = 0; x < image.width; ++x) {
      const int c = colour(x, y);
      if (c == 1) ++(y < middle ? red_top : red_bottom);
      if (c == 2) ++(y < middle ? blue_top : blue_bottom);
    }
  EXPECT_GT(red_top, blue_top);
  EXPECT_GT(blue_bottom, red_bottom);
}

// In a small frame the spheres are a pixel or two across: drawn as at 720p (a smoothed edge,
// the floor between them) the body read as pink speckle. They now grow towards their
// neighbours with hard edges, and the body is solid. Measured at 320 × 180 from above: of the
// pixels between two body pixels 4 apart in a row, 5.4 % are not body (15.7 % before).
TEST(Snapshots, SmallFramesDrawTheBodySolid) {
  const fs::path png = scratch("small.png");
  ASSERT_EQ(rattleback("still scenes/rattleback.yaml --t 1 --view above --no-readouts --size "
                       "320x180 -q -o " +
                       png.string()),
            0);
  render::Image image;
  ASSERT_TRUE(render::readPng(png.string(), image));
  auto body = [&](int x, int y) {
    const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    return (p[0] > p[1] + 60 && p[0] > p[2] + 60) || (p[2] > p[0] + 60 && p[2] > p[1] + 40);
  };
  long between = 0, holes = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 2; x < image.width - 2; ++x)
      if (body(x - 2, y) && body(x + 2, y)) {
        ++between;
        if (!body(x, y)) ++holes;
      }
  ASSERT_GT(between, 1000);
  EXPECT_LT(holes, between / 10);
}

// Each view frames its body, so a body twice as long was drawn as long as the other (a
// teacher's trial). video.frame (--frame) frames a body of that length instead: the default
// body (20 cm) and the same body in units twice as large (40 cm), both framed for 60 cm from
// above, are drawn in the ratio of their lengths. The lengths are measured as the body's
// pixels across the frame (from above +y, the long axis at t = 0, runs to the right); each
// end is uncertain by a sphere's edge, a pixel or two of the 100-odd: 4 %. Without --frame
// both fill the frame alike (the ratio is 1 within the same 4 %), which is what the test
// tells apart.
TEST(Snapshots, OneFrameDrawsBodiesAtOneScale) {
  auto widthOf = [](const std::string& options) {
    const fs::path png = scratch("scale.png");
    EXPECT_EQ(rattleback("still scenes/rattleback.yaml --view above --no-readouts --size 640x360 "
                         "-q " +
                         options + " -o " + png.string()),
              0)
        << options;
    render::Image image;
    EXPECT_TRUE(render::readPng(png.string(), image)) << options;
    int first = image.width, last = -1;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
        if ((p[0] > p[1] + 60 && p[0] > p[2] + 60) || (p[2] > p[0] + 60 && p[2] > p[1] + 40)) {
          first = std::min(first, x);
          last = std::max(last, x);
        }
      }
    return last - first + 1;
  };
  // --frame is in the file's unit: 60 cm is 60 in the first, 30 (of 2 cm) in the second.
  const int short_framed = widthOf("--frame 60");
  const int long_framed = widthOf("--frame 30 --set units.length=0.02");
  ASSERT_GT(short_framed, 50);
  EXPECT_NEAR(static_cast<double>(long_framed) / short_framed, 2.0, 0.08)
      << short_framed << " and " << long_framed << " px";
  const int short_own = widthOf("");
  const int long_own = widthOf("--set units.length=0.02");
  EXPECT_NEAR(static_cast<double>(long_own) / short_own, 1.0, 0.04)
      << short_own << " and " << long_own << " px";
}

// Front and side look along the floor from 10° above (orthographic, like the seed's
// figures): the floor fades into the background by depth, so the frame shows a horizon —
// sky above, floor below — and its squares are deep enough not to read as stripes.
// Measured at 640×360 on the default scene, now (and with the floor before the horizon): the
// top 10% of rows right of the title differs from the background by 0 levels (73: floor); the
// bottom 10% by 61.5 on average (60.6); a column beside the body changes brightness by more
// than 10 levels between neighbouring rows 12 times in its lower 40% (47: stripes). Bounds:
// 3 levels (one flat colour; 3 allows the backends' rounding), 20 levels, 24 changes.
TEST(Snapshots, FrontAndSideShowAHorizon) {
  for (const char* view : {"front", "side"}) {
    const fs::path still = scratch(std::string(view) + ".png");
    ASSERT_EQ(rattleback(
                  std::string("still scenes/rattleback.yaml --no-readouts --size 640x360 --view ") +
                  view + " -o " + still.string()),
              0);
    render::Image image;
    ASSERT_TRUE(render::readPng(still.string(), image));
    auto pixel = [&](int x, int y) {
      return &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    };
    const int background[3] = {237, 240, 245};  // kBackground (0.93, 0.94, 0.96) in 8 bits
    auto fromBackground = [&](int x, int y) {
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(pixel(x, y)[c] - background[c]));
      return worst;
    };
    int sky = 0;  // the right half: the title stays at the top left
    for (int y = 0; y < image.height / 10; ++y)
      for (int x = image.width / 2; x < image.width; ++x) sky = std::max(sky, fromBackground(x, y));
    EXPECT_LE(sky, 3) << view << ": the top of the frame is not the background";
    double floor = 0;
    for (int y = image.height * 9 / 10; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) floor += fromBackground(x, y);
    floor /= (image.height / 10) * image.width;
    EXPECT_GT(floor, 20) << view << ": no floor at the bottom of the frame";
    const int x = image.width / 20;  // beside the body in both views
    int changes = 0;
    for (int y = image.height * 6 / 10 + 1; y < image.height; ++y)
      changes += std::abs(pixel(x, y)[1] - pixel(x, y - 1)[1]) > 10;
    EXPECT_LE(changes, 24) << view << ": the floor shows as stripes";
  }
}

namespace {

struct Probe {
  std::string codec, pix_fmt;
  int width = 0, height = 0;
  long long frames = 0;
  double duration = 0;
  std::string color;
  std::vector<double> times;  ///< presentation time of each frame, s, ascending
};

// Reads the MP4 back with libavformat, counting the packets (frames) of its video stream.
Probe probe(const fs::path& path) {
  Probe p;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return p;
  avformat_find_stream_info(format, nullptr);
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index >= 0) {
    const AVCodecParameters* par = format->streams[index]->codecpar;
    p.codec = avcodec_get_name(par->codec_id);
    const char* pix = av_get_pix_fmt_name(static_cast<AVPixelFormat>(par->format));
    p.pix_fmt = pix ? pix : "";
    p.width = par->width;
    p.height = par->height;
    p.color = av_color_space_name(par->color_space);
    p.duration = format->duration / static_cast<double>(AV_TIME_BASE);
    AVPacket* packet = av_packet_alloc();
    while (av_read_frame(format, packet) >= 0) {
      if (packet->stream_index == index) {
        ++p.frames;
        p.times.push_back(packet->pts * av_q2d(format->streams[index]->time_base));
      }
      av_packet_unref(packet);
    }
    av_packet_free(&packet);
    std::sort(p.times.begin(), p.times.end());
  }
  avformat_close_input(&format);
  return p;
}

// Top-level MP4 boxes in file order.
std::vector<std::string> topLevelBoxes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> boxes;
  unsigned char header[8];
  while (in.read(reinterpret_cast<char*>(header), 8)) {
    std::uint64_t size =
        (std::uint64_t(header[0]) << 24) | (header[1] << 16) | (header[2] << 8) | header[3];
    boxes.emplace_back(reinterpret_cast<char*>(header + 4), 4);
    if (size == 1) {  // 64-bit size follows
      unsigned char big[8];
      in.read(reinterpret_cast<char*>(big), 8);
      size = 0;
      for (unsigned char b : big) size = (size << 8) | b;
      in.seekg(static_cast<std::streamoff>(size - 16), std::ios::cur);
    } else if (size < 8) {
      break;
    } else {
      in.seekg(static_cast<std::streamoff>(size - 8), std::ios::cur);
    }
  }
  return boxes;
}

}  // namespace

// H.264, yuv420p, BT.709, the asked size, exactly round(duration × playback × fps) frames
// with the right duration, and the index (moov) before the media (mdat) so that a browser
// can start playing before it has the whole file.
TEST(Video, StreamAndLayoutAreWhatBrowsersPlay) {
  const fs::path video = scratch("seed.mp4");
  ASSERT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --duration 0.4 --size 320x180 --fps 25 "
                       "-o " +
                       video.string()),
            0);
  const Probe p = probe(video);
  EXPECT_EQ(p.codec, "h264");
  EXPECT_EQ(p.pix_fmt, "yuv420p");
  EXPECT_EQ(p.color, "bt709");
  EXPECT_EQ(p.width, 320);
  EXPECT_EQ(p.height, 180);
  EXPECT_EQ(p.frames, 10);             // 0.4 s × 25 fps
  EXPECT_NEAR(p.duration, 0.4, 1e-3);  // 1 ms: the container's time base rounding
  const auto boxes = topLevelBoxes(video);
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin());
}

// Playback is a speed, as players mean it: 0.5 (slow motion) shows the same simulated time in
// twice the video time, so twice the frames; 2 in half.
TEST(Video, PlaybackScalesTheFrameCount) {
  const fs::path slow = scratch("slow.mp4"), fast = scratch("fast.mp4");
  ASSERT_EQ(
      rattleback("render scenes/seed-flip-ccw.yaml --duration 0.4 --playback 0.5 --size 160x90 "
                 "-o " +
                 slow.string()),
      0);
  EXPECT_EQ(probe(slow).frames, 20);  // 0.4 s / 0.5 × 25 fps
  ASSERT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --duration 0.4 --playback 2 --size 160x90 "
                       "-o " +
                       fast.string()),
            0);
  EXPECT_EQ(probe(fast).frames, 5);  // 0.4 s / 2 × 25 fps
}

// Any frame rate from 1 to 240 works with every shipped scene, whatever its step (frames are
// drawn at exact times between steps): 24, 30 and 60 fps give round(duration · fps) frames,
// frame k stamped at k / fps in the MP4 (to the stream's time base).
TEST(Video, CommonFrameRatesWorkForEveryShippedScene) {
  for (const char* scene : {"rattleback", "kane-levinson", "seed-flip-ccw", "seed-flip-cw"}) {
    for (int fps : {24, 30, 60}) {
      const fs::path video = scratch(std::string(scene) + "-" + std::to_string(fps) + ".mp4");
      ASSERT_EQ(rattleback(std::string("render scenes/") + scene + ".yaml --duration 0.25 --fps " +
                           std::to_string(fps) + " --size 160x90 -q -o " + video.string()),
                0)
          << scene << " at " << fps << " fps";
      const Probe p = probe(video);
      const long long expected = std::llround(0.25 * fps);
      EXPECT_EQ(p.frames, expected) << scene << " at " << fps << " fps";
      ASSERT_EQ(p.times.size(), static_cast<std::size_t>(p.frames));
      for (std::size_t k = 0; k < p.times.size(); ++k)
        EXPECT_NEAR(p.times[k], static_cast<double>(k) / fps, 1e-6) << scene << " frame " << k;
    }
  }
}

// --both writes the preferred, reversed and side-by-side videos; the side-by-side one is
// two frames wide. No temporary file is left.
TEST(Video, BothWritesThreeVideos) {
  const fs::path base = scratch("pair");
  ASSERT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --both --duration 0.2 --size 160x90 -o " +
                       base.string()),
            0);
  for (const char* suffix : {"-preferred.mp4", "-reversed.mp4"})
    EXPECT_EQ(probe(base.string() + suffix).width, 160) << suffix;
  EXPECT_EQ(probe(base.string() + "-both.mp4").width, 320);
  for (const auto& entry : fs::directory_iterator(base.parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".part"), std::string::npos);
  // At spin 0 the spin and its reverse are one run (the two videos were written over each
  // other): refused, with nothing written.
  const fs::path zero = scratch("zero");
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --both --spin 0 --duration 0.2 --size "
                       "160x90 -o " +
                       zero.string()),
            2);
  for (const char* suffix : {"-preferred.mp4", "-reversed.mp4", "-both.mp4"})
    EXPECT_FALSE(fs::exists(zero.string() + suffix)) << suffix;
}

// A render that cannot run writes nothing and keeps what was there.
TEST(Video, FailureLeavesAnExistingFileAlone) {
  const fs::path video = scratch("keep.mp4");
  std::ofstream(video) << "precious";
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --size 321x180 -o " + video.string()), 2);
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --fps 500 -o " + video.string()), 2);
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --crf 60 -o " + video.string()), 2);
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --preset bogus -o " + video.string()), 2);
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --view sideways -o " + video.string()), 2);
  std::ifstream in(video);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "precious");
  EXPECT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --duration 0.1 -o /dev/null/x.mp4"), 2);
  EXPECT_EQ(rattleback("still scenes/seed-flip-ccw.yaml -o /dev/null/x.png"), 2);
}

// A small thing changed whole differs, though it is a fraction of the pixels --pixels allows
// (a CI maintainer's trial: a 40×40 patch of a 1280×720 frame is 0.17 %, within the default
// 0.2 %); scattered changes of as many pixels, lines one pixel wide as another CPU's rasteriser
// makes on edges, still pass. compareImages measures the largest square of differing pixels.
TEST(Compare, ASmallThingChangedWholeDiffers) {
  const fs::path golden = kSource / "tests/golden/seed-above.png";
  render::Image image, lines, patch;
  ASSERT_TRUE(render::readPng(golden.string(), image));
  lines = patch = image;
  const auto flip = [](render::Image& im, int x, int y) {
    im.rgba[(static_cast<std::size_t>(y) * im.width + x) * 4] ^= 0x80;
  };
  // 1-pixel diagonal lines, every 8th diagonal: 1/8 of the pixels, no two in a row or column.
  for (int y = 0; y < lines.height; ++y)
    for (int x = 0; x < lines.width; ++x)
      if ((x + y) % 8 == 0) flip(lines, x, y);
  for (int y = 30; y < 34; ++y)  // a 4×4 square: 16 of 57600 pixels (0.03 %)
    for (int x = 50; x < 54; ++x) flip(patch, x, y);
  const render::Comparison scattered = render::compareImages(lines, image, 2);
  EXPECT_EQ(scattered.square, 1);
  const render::Comparison whole = render::compareImages(patch, image, 2);
  EXPECT_EQ(whole.differing, 16);
  EXPECT_EQ(whole.square, 4);
  EXPECT_EQ(whole.square_at[0], 50);
  EXPECT_EQ(whole.square_at[1], 30);
  const fs::path a = scratch("lines.png"), b = scratch("patch.png"), said = scratch("said.txt");
  ASSERT_TRUE(render::writePng(a.string(), lines));
  ASSERT_TRUE(render::writePng(b.string(), patch));
  EXPECT_EQ(rattleback("compare " + a.string() + " " + golden.string() + " --pixels 0.2"), 0);
  const std::string command = "cd " + kSource.string() + " && " + RATTLEBACK_BIN + " compare " +
                              b.string() + " " + golden.string() + " >" + said.string();
  EXPECT_EQ(WEXITSTATUS(std::system(command.c_str())), 1);
  std::ifstream in(said);
  std::string line;
  std::getline(in, line);
  EXPECT_NE(line.find("largest square of them 4x4 at x 50, y 30 (--square 4)"), std::string::npos)
      << line;
  EXPECT_EQ(rattleback("compare " + b.string() + " " + golden.string() + " --square 5"), 0);
}

// A golden holds for the rasteriser that drew it: softpipe draws the spheres' edges otherwise
// than llvmpipe (2.8 % of a 1280×720 still's pixels, docs/commands.md), and a CI machine with
// another one failed every comparison with no hint why (a CI maintainer's trial). A still keeps
// what drew it in its PNG (tEXt Software, read back by readPng), and compare says so when two
// images that differ were drawn by different ones; images drawn by one say nothing of it.
// (OSMesa here: its softpipe and llvmpipe are Mesa's on any machine.)
TEST(Compare, ImagesDrawnByDifferentRasterisersSaySo) {
  const fs::path llvm = scratch("llvmpipe.png"), soft = scratch("softpipe.png"),
                 later = scratch("later.png"), said = scratch("said.txt");
  const std::string still = "still scenes/rattleback.yaml --backend osmesa --size 320x180 -q ";
  ASSERT_EQ(rattleback(still + "-o " + llvm.string()), 0);
  ASSERT_EQ(rattleback(still + "--t 0.5 -o " + later.string()), 0);
  {
    const char* before = std::getenv("GALLIUM_DRIVER");
    const std::string kept = before ? before : "";
    ::setenv("GALLIUM_DRIVER", "softpipe", 1);
    const int status = rattleback(still + "-o " + soft.string());
    if (before)
      ::setenv("GALLIUM_DRIVER", kept.c_str(), 1);
    else
      ::unsetenv("GALLIUM_DRIVER");
    ASSERT_EQ(status, 0);
  }
  render::Image image;
  ASSERT_TRUE(render::readPng(soft.string(), image));
  EXPECT_NE(image.drawn_by.find("softpipe"), std::string::npos) << image.drawn_by;
  auto compare = [&](const fs::path& a, const fs::path& b) {
    const std::string command = "cd " + kSource.string() + " && " + RATTLEBACK_BIN + " compare " +
                                a.string() + " " + b.string() + " >" + said.string();
    const int status = WEXITSTATUS(std::system(command.c_str()));
    std::ifstream in(said);
    return std::pair{status, std::string(std::istreambuf_iterator<char>(in), {})};
  };
  const auto [status, text] = compare(soft, llvm);
  EXPECT_EQ(status, 1) << text;
  EXPECT_NE(text.find("\nnote: drawn by different OpenGL: " + soft.string() +
                      " by Mesa/X.org "
                      "softpipe"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find(llvm.string() + " by Mesa/X.org llvmpipe"), std::string::npos) << text;
  const auto [moved, moved_text] = compare(later, llvm);  // another moment, one rasteriser
  EXPECT_EQ(moved, 1) << moved_text;
  EXPECT_EQ(moved_text.find("note:"), std::string::npos) << moved_text;
}

// `compare` is the snapshot check users can call: 0 when equal within the tolerance, 1 when
// not, with a diff image.
TEST(Compare, SameAndDifferentImages) {
  const fs::path golden = kSource / "tests/golden/seed-above.png";
  EXPECT_EQ(rattleback("compare " + golden.string() + " " + golden.string()), 0);
  render::Image image;
  ASSERT_TRUE(render::readPng(golden.string(), image));
  for (int y = 20; y < 60; ++y)  // paint a 40×40 square: 1600 of 57600 pixels (2.8%)
    for (int x = 20; x < 60; ++x) image.rgba[(y * image.width + x) * 4] ^= 0x80;
  const fs::path changed = scratch("changed.png"), diff = scratch("diff.png");
  ASSERT_TRUE(render::writePng(changed.string(), image));
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() + " --diff " +
                       diff.string()),
            1);
  EXPECT_TRUE(fs::exists(diff));
  // Within a looser allowance (5% of pixels) the same pair passes only without the square
  // check: the 40×40 square changed whole is a changed thing, whatever its fraction.
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() +
                       " --pixels 0.05 --square 0"),
            0);
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() + " --pixels 0.05"),
            1);
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() + " --square -1"), 2);
  // Options out of range are bad input, not a silent pass.
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() + " --tolerance 300"),
            2);
  EXPECT_EQ(rattleback("compare " + changed.string() + " " + golden.string() + " --pixels 2"), 2);
  // Different sizes differ, and the message says no diff was written.
  const fs::path small = scratch("small.png"), out = scratch("compare.txt");
  ASSERT_EQ(rattleback("still scenes/seed-flip-ccw.yaml --size 160x90 -q -o " + small.string()), 0);
  const std::string command = "cd " + kSource.string() + " && " + RATTLEBACK_BIN + " compare " +
                              small.string() + " " + golden.string() + " --diff " +
                              scratch("none.png").string() + " >" + out.string();
  EXPECT_EQ(WEXITSTATUS(std::system(command.c_str())), 1);
  std::ifstream in(out);
  std::string line;
  std::getline(in, line);
  EXPECT_NE(line.find("different sizes, 160x90 and 320x180"), std::string::npos) << line;
  EXPECT_NE(line.find("no diff image was written"), std::string::npos) << line;
  EXPECT_FALSE(fs::exists(scratch("none.png")));
  // -q: nothing printed, the same verdicts, the diff image still written.
  const fs::path quiet_diff = scratch("quiet-diff.png"), quiet_out = scratch("quiet.txt");
  const std::string quiet = "cd " + kSource.string() + " && " + RATTLEBACK_BIN + " compare -q " +
                            changed.string() + " " + golden.string() + " --diff " +
                            quiet_diff.string() + " >" + quiet_out.string();
  EXPECT_EQ(WEXITSTATUS(std::system(quiet.c_str())), 1);
  EXPECT_TRUE(fs::exists(quiet_diff));
  EXPECT_EQ(fs::file_size(quiet_out), 0u);
  EXPECT_EQ(rattleback("compare -q " + golden.string() + " " + golden.string()), 0);
}

// --diff's folder is made as every output's is, and checked before the verdict: into a missing
// folder compare said "differ" and then exited 2 with no diff (a CI maintainer's trial). A pass,
// or a refusal, leaves no folder behind; nor does a video that stops.
TEST(Compare, TheDiffsFolderIsMadeAndLeftOnlyWithADiff) {
  const fs::path golden = kSource / "tests/golden/seed-above.png";
  render::Image image;
  ASSERT_TRUE(render::readPng(golden.string(), image));
  image.rgba[0] ^= 0x80;
  const fs::path dir = scratch("stderr.txt").parent_path() / "made";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path changed = dir / "changed.png", expected = dir / "golden.png";
  ASSERT_TRUE(render::writePng(changed.string(), image));
  fs::copy_file(golden, expected);  // a copy: a mutant must not write over the source's golden
  const std::string pair = changed.string() + " " + expected.string();
  EXPECT_EQ(rattleback("compare " + pair + " --pixels 0 --diff " + (dir / "d/e/diff.png").string()),
            1);
  EXPECT_TRUE(fs::exists(dir / "d/e/diff.png"));
  EXPECT_EQ(rattleback("compare " + pair + " --diff " + (dir / "pass/diff.png").string()), 0);
  EXPECT_FALSE(fs::exists(dir / "pass"));
  // A pass removes the diff an earlier comparison left at that name: it would stand beside the
  // pass as if this one had differed.
  EXPECT_EQ(rattleback("compare " + pair + " --diff " + (dir / "d/e/diff.png").string()), 0);
  EXPECT_FALSE(fs::exists(dir / "d/e/diff.png"));
  // A diff over one of the images compared is refused, and the image kept.
  EXPECT_EQ(rattleback("compare " + pair + " --pixels 0 --diff " + expected.string()), 2);
  EXPECT_EQ(rattleback("compare " + pair + " --pixels 0 --diff " + changed.string()), 2);
  EXPECT_EQ(fs::file_size(expected), fs::file_size(golden));
  render::Image kept;
  ASSERT_TRUE(render::readPng(changed.string(), kept));
  EXPECT_EQ(kept.rgba, image.rgba);
  std::ofstream(dir / "afile") << "";
  EXPECT_EQ(
      rattleback("compare " + pair + " --pixels 0 --diff " + (dir / "afile/diff.png").string()), 2);
  // A video that stops (explicit Euler at 5 ms gains energy) removes the folder made for it.
  EXPECT_EQ(rattleback("render scenes/rattleback.yaml --set simulation.integrator=euler "
                       "--set simulation.dt=5e-3 --size 160x90 -o " +
                       (dir / "v/w/x.mp4").string()),
            3);
  EXPECT_FALSE(fs::exists(dir / "v"));
}

// A write the machine cannot finish (here a file-size limit, SIGXFSZ ignored as a shell's
// ulimit leaves it) exits 4, not bad input's 2, for a still and a video alike; nothing is left.
TEST(Video, AWriteTheMachineCannotFinishExitsFour) {
  for (const std::string output : {"limited.png", "limited.mp4"}) {
    const fs::path path = scratch(output);
    const std::string command = "cd " + kSource.string() + " && (ulimit -f 4; trap '' XFSZ; " +
                                RATTLEBACK_BIN + " " +
                                (output.ends_with(".png") ? "still" : "render --duration 1") +
                                " scenes/rattleback.yaml -q -o " + path.string() + ") 2>/dev/null";
    const int raw = std::system(command.c_str());
    EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, 4) << output;
    EXPECT_FALSE(fs::exists(path)) << output;
  }
}

// A PNG's stored values are compared as stored, whatever gAMA/cHRM chunks it carries (ffmpeg
// writes them into frames it extracts; libpng's simplified reader would convert by them, by up
// to 11 steps for a gamma of 1/1.8). The chunks are written here through libpng itself.
TEST(Compare, ColourChunksDoNotChangeTheValuesCompared) {
  render::Image plain;
  plain.width = 64;
  plain.height = 8;
  for (int i = 0; i < plain.width * plain.height; ++i)
    plain.rgba.insert(plain.rgba.end(), {static_cast<unsigned char>(4 * (i % 64)), 128,
                                         static_cast<unsigned char>(255 - 4 * (i % 64)), 255});
  const fs::path stored = scratch("stored.png"), tagged = scratch("tagged.png");
  ASSERT_TRUE(render::writePng(stored.string(), plain));
  FILE* f = std::fopen(tagged.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_init_io(png, f);
  png_set_IHDR(png, info, plain.width, plain.height, 8, PNG_COLOR_TYPE_RGB_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_gAMA(png, info, 1 / 1.8);
  png_set_cHRM(png, info, 0.3127, 0.3290, 0.64, 0.33, 0.30, 0.60, 0.15, 0.06);  // BT.709
  png_write_info(png, info);
  for (int y = 0; y < plain.height; ++y)
    png_write_row(png, &plain.rgba[static_cast<std::size_t>(y) * plain.width * 4]);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  std::fclose(f);
  render::Image read;
  ASSERT_TRUE(render::readPng(tagged.string(), read));
  EXPECT_EQ(read.rgba, plain.rgba);
  EXPECT_EQ(rattleback("compare " + tagged.string() + " " + stored.string() + " --tolerance 0"), 0);
}

// Ctrl-C (SIGINT) or SIGTERM in the middle of a render: exit 130 / 143, the temporary file is
// gone, and an existing video of the same name is kept; also with a second Ctrl-C right after
// the first (as `timeout -s INT` sends, to the process and then its group), which ends the
// process at once.
TEST(Video, AnInterruptKeepsTheOldFileAndLeavesNoTemporary) {
  for (auto [signal, twice] :
       {std::pair{SIGINT, false}, std::pair{SIGTERM, false}, std::pair{SIGINT, true}}) {
    const fs::path video = scratch("kept.mp4");
    for (const auto& entry : fs::directory_iterator(video.parent_path())) fs::remove(entry.path());
    std::ofstream(video) << "precious";
    const std::string command =
        "cd " + kSource.string() + " && exec " + RATTLEBACK_BIN +
        " render scenes/rattleback.yaml --size 640x360 --duration 60 -q -o " + video.string() +
        " 2>/dev/null";
    const pid_t child = fork();
    if (child == 0) {
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    // Signal once the temporary file exists (the encoder is writing), with 1500 frames (tens of
    // seconds of work) still ahead, so the signal lands mid-render on a fast machine too.
    const auto hasTemporary = [&] {
      for (const auto& entry : fs::directory_iterator(video.parent_path()))
        if (entry.path().filename().string().find(".part") != std::string::npos) return true;
      return false;
    };
    for (int tries = 0; tries < 1000 && !hasTemporary(); ++tries) usleep(10000);
    ASSERT_TRUE(hasTemporary()) << "no temporary file appeared within 10 s";
    usleep(100000);
    kill(child, signal);
    if (twice) kill(child, signal);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << "killed outright by signal " << signal;
    EXPECT_EQ(WEXITSTATUS(status), 128 + signal);
    std::ifstream in(video);
    std::string content;
    in >> content;
    EXPECT_EQ(content, "precious");
    for (const auto& entry : fs::directory_iterator(video.parent_path()))
      EXPECT_EQ(entry.path().filename().string().find(".part"), std::string::npos) << entry.path();
  }
}

// libavcodec's and x264's own log lines never reach the terminal: a render's stderr is empty
// (x264 logs its CPU capabilities and statistics at libav's info level).
TEST(Video, NoLibraryLogLinesOnTheTerminal) {
  const fs::path video = scratch("quiet.mp4");
  ASSERT_EQ(rattleback("render scenes/seed-flip-ccw.yaml --duration 0.2 --size 160x90 -q -o " +
                       video.string()),
            0);
  std::ifstream err(video.parent_path() / "stderr.txt");
  std::stringstream text;
  text << err.rdbuf();
  EXPECT_EQ(text.str(), "");
}

// What the videos show, and when: frames decoded from the MP4s `render` writes (libavcodec)
// against `still --t t_k` of the same scene, time and size; the colours after the RGBA → YUV
// → RGB round trip; frames that move; and --both's files, counts and spins.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include "render/image_io.hpp"
#include "render_support.hpp"

namespace fs = std::filesystem;
using namespace render_support;

namespace {

constexpr int kWidth = 320, kHeight = 180;

// Every frame of the MP4's video stream in presentation order, as RGBA; the YUV is read as
// it is tagged (BT.709, limited range), as a browser does.
std::vector<render::Image> decodeFrames(const fs::path& path) {
  std::vector<render::Image> frames;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return frames;
  avformat_find_stream_info(format, nullptr);
  const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  const AVCodec* codec = avcodec_find_decoder(format->streams[stream]->codecpar->codec_id);
  AVCodecContext* decoder = avcodec_alloc_context3(codec);
  avcodec_parameters_to_context(decoder, format->streams[stream]->codecpar);
  decoder->thread_count = 1;
  avcodec_open2(decoder, codec, nullptr);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  SwsContext* sws = nullptr;
  auto drain = [&] {
    while (avcodec_receive_frame(decoder, frame) == 0) {
      sws = sws_getCachedContext(
          sws, frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
          frame->height, AV_PIX_FMT_RGBA, SWS_BICUBIC, nullptr, nullptr, nullptr);
      const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
      sws_setColorspaceDetails(sws, bt709, 0, bt709, 1, 0, 1 << 16, 1 << 16);
      render::Image image;
      image.width = frame->width;
      image.height = frame->height;
      image.rgba.resize(static_cast<std::size_t>(4) * frame->width * frame->height);
      uint8_t* out[] = {image.rgba.data()};
      const int stride[] = {4 * frame->width};
      sws_scale(sws, frame->data, frame->linesize, 0, frame->height, out, stride);
      frames.push_back(std::move(image));
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == stream) {
      avcodec_send_packet(decoder, packet);
      drain();
    }
    av_packet_unref(packet);
  }
  avcodec_send_packet(decoder, nullptr);
  drain();
  sws_freeContext(sws);
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&decoder);
  avformat_close_input(&format);
  return frames;
}

render::Image still(const std::string& args) {
  static int count = 0;
  const fs::path png = scratch("still" + std::to_string(count++) + ".png");
  render::Image image;
  if (rattleback("still " + args + " -q --size " + std::to_string(kWidth) + "x" +
                 std::to_string(kHeight) + " -o " + png.string()) != 0) {
    ADD_FAILURE() << "still " << args;
    return image;
  }
  EXPECT_TRUE(render::readPng(png.string(), image).ok());
  return image;
}

// Mean absolute difference per channel (0–255) between the 4 × 4-pixel block averages of two
// images, over the middle of the frame, where the body is in every view; the read-outs (top
// lines, the inset in a corner) lie outside it, and a video frame's titles say more than a
// still's. Blocks, because 4:2:0 video keeps colour at 2 × 2 pixels and x264 smooths the
// body's fine point pattern: pixel by pixel the round trip alone moves the middle by 7–9
// steps, block by block by 1.7–1.9 (measured below, oblique view), while the body a frame's
// time later (11° of turn at 5 rad/s and 25 fps; 6° in the slow-motion case) moves it by 4.8
// to 6.7.
// (Another region, as fractions of the width and height, for the inset.)
struct Region {
  double x0 = 0.25, y0 = 0.2, x1 = 0.75, y1 = 0.8;
};
double difference(const render::Image& a, const render::Image& b, Region r = {}) {
  if (a.width != b.width || a.height != b.height || a.rgba.empty()) return 1e9;
  constexpr int kBlock = 4;
  double sum = 0;
  long count = 0;
  for (int by = static_cast<int>(a.height * r.y0) / kBlock;
       by < static_cast<int>(a.height * r.y1) / kBlock; ++by)
    for (int bx = static_cast<int>(a.width * r.x0) / kBlock;
         bx < static_cast<int>(a.width * r.x1) / kBlock; ++bx)
      for (int c = 0; c < 3; ++c) {
        int sa = 0, sb = 0;
        for (int y = by * kBlock; y < (by + 1) * kBlock; ++y)
          for (int x = bx * kBlock; x < (bx + 1) * kBlock; ++x) {
            const std::size_t i = 4 * (static_cast<std::size_t>(y) * a.width + x) + c;
            sa += a.rgba[i];
            sb += b.rgba[i];
          }
        sum += std::abs(sa - sb) / static_cast<double>(kBlock * kBlock);
        ++count;
      }
  return sum / static_cast<double>(count);
}

// The right time against the next frame's: 3 separates 1.9 from 4.8.
constexpr double kRoundTrip = 3.0;

// The middle of a --both frame below its text, which is larger than a still's (1.4 times: at
// 320×180 the title and two read-out lines reach 30 % of the way down, and the inset's title
// 64 % across from the left).
constexpr Region kBelowBothText{0.25, 0.35, 0.6, 0.75};
// There, at t = 0.36 s, a --both frame against the still of its own spin differs by 2.6–2.8
// (the round trip; the body fills more of this region than of the whole middle), against the
// other spin's by 21.2–21.4: 8 tells them apart with room both ways.
constexpr double kSpinsApart = 8.0;

// The left (0) or right (1) half of a side-by-side frame.
render::Image half(const render::Image& both, int which) {
  render::Image out;
  out.width = both.width / 2;
  out.height = both.height;
  for (int y = 0; y < both.height; ++y) {
    const auto row =
        both.rgba.begin() + 4 * (static_cast<std::ptrdiff_t>(y) * both.width + which * out.width);
    out.rgba.insert(out.rgba.end(), row, row + 4 * out.width);
  }
  return out;
}

}  // namespace

// Frame k of a video is the still at t_k = k · playback / fps: first, middle and last frame, at
// 25 and 30 fps and in slow motion; and the frame is not the still of the next frame's time.
TEST(VideoContent, FrameKIsTheStillAtItsTime) {
  struct Case {
    int fps;
    double playback;
  };
  for (const Case c : {Case{25, 1.0}, Case{30, 1.0}, Case{25, 0.5}}) {
    const fs::path mp4 = scratch(std::to_string(c.fps) + "fps.mp4");
    const double duration = 1.0;
    ASSERT_EQ(rattleback("render scenes/rattleback.yaml -q --duration 1 --fps " +
                         std::to_string(c.fps) + " --playback " + std::to_string(c.playback) +
                         " --size 320x180 -o " + mp4.string()),
              0);
    const std::vector<render::Image> frames = decodeFrames(mp4);
    const int expected = static_cast<int>(std::lround(duration / c.playback * c.fps));
    ASSERT_EQ(static_cast<int>(frames.size()), expected) << mp4;
    for (const int k : {0, expected / 2, expected - 1}) {
      const double t = k * c.playback / c.fps;
      char time[32];
      std::snprintf(time, sizeof time, "%.9g", t);
      const double same =
          difference(frames[k], still("scenes/rattleback.yaml --t " + std::string(time)));
      std::snprintf(time, sizeof time, "%.9g", t + 1.0 / c.fps);
      const double next =
          difference(frames[k], still("scenes/rattleback.yaml --t " + std::string(time)));
      EXPECT_LT(same, kRoundTrip) << c.fps << " fps, playback " << c.playback << ", frame " << k;
      EXPECT_GT(next, kRoundTrip) << c.fps << " fps, playback " << c.playback << ", frame " << k;
      EXPECT_GT(next, 2 * same) << c.fps << " fps, playback " << c.playback << ", frame " << k;
    }
    // A spinning body moves between consecutive frames.
    EXPECT_GT(difference(frames[10], frames[11]), 1.0) << mp4;
  }
}

// A video rendered with --duration, --fps and --playback: `still` with the same options draws
// its frame's inset (time axis 0–1 s, the curve through the video's frames), and without them
// (the scene's 8 s axis) it does not. Measured in the inset: 1.2 with the options, 7.3 without.
TEST(VideoContent, StillTakesTheVideosTimingOptions) {
  const fs::path mp4 = scratch("timed.mp4");
  const std::string timing = " --duration 1 --fps 30 --playback 0.5";
  ASSERT_EQ(rattleback("render scenes/rattleback.yaml -q --size 320x180" + timing + " -o " +
                       mp4.string()),
            0);
  const std::vector<render::Image> frames = decodeFrames(mp4);
  ASSERT_EQ(frames.size(), 60u);
  const Region inset{0.68, 0.76, 0.98, 0.97};
  const double with =
      difference(frames[45], still("scenes/rattleback.yaml --t 0.75" + timing), inset);
  const double without = difference(frames[45], still("scenes/rattleback.yaml --t 0.75"), inset);
  EXPECT_LT(with, kRoundTrip);
  EXPECT_GT(without, 2 * kRoundTrip);
}

// After the YUV round trip the top is still red and the bottom still blue: seen from the side,
// both show (red: r > 150 with g, b < 100; blue: b > 120 with r < 90), and a swap of the
// chroma planes or of R and B would turn one into the other.
TEST(VideoContent, RedTopAndBlueBottomSurviveTheRoundTrip) {
  const fs::path mp4 = scratch("side.mp4");
  ASSERT_EQ(
      rattleback("render scenes/rattleback.yaml -q --duration 0.2 --view side --size 320x180 -o " +
                 mp4.string()),
      0);
  const std::vector<render::Image> frames = decodeFrames(mp4);
  ASSERT_FALSE(frames.empty());
  long red = 0, blue = 0;
  const render::Image& f = frames[0];
  double red_y = 0, blue_y = 0;
  for (int y = 0; y < f.height; ++y)
    for (int x = 0; x < f.width; ++x) {
      const unsigned char* p = &f.rgba[4 * (static_cast<std::size_t>(y) * f.width + x)];
      if (p[0] > 150 && p[1] < 100 && p[2] < 100) ++red, red_y += y;
      if (p[2] > 120 && p[0] < 90 && p[2] > p[1] + 30) ++blue, blue_y += y;
    }
  EXPECT_GT(red, 50);
  EXPECT_GT(blue, 50);
  if (red > 0 && blue > 0) {
    EXPECT_LT(red_y / red, blue_y / blue) << "the red top above the blue bottom";
  }
}

// --both: each file has the frames of the duration, and each one's first frame is the still of
// its own spin (−5 reverses, +5 is the preferred way), not of the other's.
TEST(VideoContent, BothFilesHoldTheirOwnSpin) {
  const fs::path base = scratch("pair");
  ASSERT_EQ(
      rattleback(
          "render scenes/rattleback.yaml -q --both --duration 0.4 --fps 25 --size 320x180 -o " +
          base.string()),
      0);
  const auto reversed = decodeFrames(base.string() + "-reversed.mp4");
  const auto preferred = decodeFrames(base.string() + "-preferred.mp4");
  const auto both = decodeFrames(base.string() + "-both.mp4");
  ASSERT_EQ(reversed.size(), 10u);
  ASSERT_EQ(preferred.size(), 10u);
  ASSERT_EQ(both.size(), 10u);
  EXPECT_EQ(both[0].width, 2 * kWidth);
  // A dark grey line two pixels wide between the halves, on every row (48 as drawn; ±12 for the
  // YUV round trip beside the light floor), and the floor just beside it.
  for (int y = 0; y < kHeight; ++y)
    for (int x : {kWidth - 1, kWidth})
      for (int c = 0; c < 3; ++c) {
        const int v = both[0].rgba[4 * (static_cast<std::size_t>(y) * both[0].width + x) + c];
        ASSERT_NEAR(v, 48, 12) << "x " << x << ", y " << y;
      }
  const int beside =
      both[0].rgba[4 * (static_cast<std::size_t>(kHeight / 2) * both[0].width + kWidth - 4)];
  EXPECT_GT(beside, 100);
  // At t = 0 the two spins look alike but for their read-outs; a frame later they have
  // turned 11° apart. Compare the last frames with the stills at t = 0.36 s (below --both's
  // larger text).
  const render::Image minus = still("scenes/rattleback.yaml --spin -5 --t 0.36");
  const render::Image plus = still("scenes/rattleback.yaml --spin 5 --t 0.36");
  EXPECT_LT(difference(reversed.back(), minus, kBelowBothText), kSpinsApart);
  EXPECT_LT(difference(preferred.back(), plus, kBelowBothText), kSpinsApart);
  EXPECT_GT(difference(reversed.back(), plus, kBelowBothText), kSpinsApart);
  EXPECT_GT(difference(preferred.back(), minus, kBelowBothText), kSpinsApart);
}

// --both's left half is the run spun against the body's preferred way (the one that reverses),
// the right half the preferred one, whichever way the scene spins it (a teacher's trial: the
// order followed the scene's spin). The default body prefers counter-clockwise: spun +5 (the
// preferred way) by the scene, its left half is still the −5 run, and so it is spun −5.
TEST(VideoContent, BothShowsTheRunSpunAgainstItsPreferredWayOnTheLeft) {
  const render::Image minus = still("scenes/rattleback.yaml --spin -5 --t 0.36");
  const render::Image plus = still("scenes/rattleback.yaml --spin 5 --t 0.36");
  for (const char* spin : {"5", "-5"}) {
    const fs::path base = scratch(std::string("order") + spin);
    ASSERT_EQ(rattleback("render scenes/rattleback.yaml -q --both --spin " + std::string(spin) +
                         " --duration 0.4 --fps 25 --size 320x180 -o " + base.string()),
              0);
    const auto both = decodeFrames(base.string() + "-both.mp4");
    ASSERT_EQ(both.size(), 10u);
    const render::Image left = half(both.back(), 0), right = half(both.back(), 1);
    EXPECT_LT(difference(left, minus, kBelowBothText), kSpinsApart) << "scene spun " << spin;
    EXPECT_GT(difference(left, plus, kBelowBothText), kSpinsApart) << "scene spun " << spin;
    EXPECT_LT(difference(right, plus, kBelowBothText), kSpinsApart) << "scene spun " << spin;
    EXPECT_GT(difference(right, minus, kBelowBothText), kSpinsApart) << "scene spun " << spin;
  }
}

// A video played slower or faster than real time says so in its title ("rattleback, at 0.5×
// speed: …"), which a still of the same moment does not (a still has no speed): the title's
// line of the first frame is the still's at playback 1 and not at 0.5. Measured in the title's
// line: 1.1 at playback 1 (the round trip), 8.7 at 0.5 (the words after "rattleback" move).
TEST(VideoContent, AVideoNotInRealTimeSaysItsSpeedInItsTitle) {
  const Region title{0.0, 0.0, 0.75, 0.1};
  const render::Image first = still("scenes/rattleback.yaml --t 0");
  for (const char* playback : {"1", "0.5"}) {
    const fs::path mp4 = scratch(std::string("speed") + playback + ".mp4");
    ASSERT_EQ(rattleback("render scenes/rattleback.yaml -q --duration 0.2 --fps 10 --playback " +
                         std::string(playback) + " --size 320x180 -o " + mp4.string()),
              0);
    const auto frames = decodeFrames(mp4);
    ASSERT_FALSE(frames.empty());
    const double apart = difference(frames.front(), first, title);
    if (std::string(playback) == "1")
      EXPECT_LT(apart, kRoundTrip);
    else
      EXPECT_GT(apart, 2 * kRoundTrip);
  }
}

// The views frame the whole body over the whole run: in every frame of every shipped scene, in
// every view, no body pixel (red top, blue bottom) lies on the image's border. (Sampled at 5
// frames per second; the seed's bodies for their first 3 s, in which they topple and settle.)
TEST(VideoContent, EveryViewKeepsTheBodyInsideTheFrame) {
  struct Scene {
    const char* name;
    double duration;
  };
  for (const Scene scene : {Scene{"rattleback", 8}, Scene{"kane-levinson", 8},
                            Scene{"seed-flip-ccw", 3}, Scene{"seed-flip-cw", 3}}) {
    for (const char* view : {"oblique", "above", "front", "side", "follow"}) {
      const fs::path mp4 = scratch(std::string(scene.name) + "-" + view + ".mp4");
      ASSERT_EQ(rattleback("render scenes/" + std::string(scene.name) + ".yaml -q --fps 5 --view " +
                           view + " --size 320x180 --duration " + std::to_string(scene.duration) +
                           " -o " + mp4.string()),
                0);
      const auto frames = decodeFrames(mp4);
      ASSERT_FALSE(frames.empty());
      int touching = -1;
      for (std::size_t k = 0; k < frames.size() && touching < 0; ++k) {
        const render::Image& f = frames[k];
        auto body = [&](int x, int y) {
          const unsigned char* p = &f.rgba[4 * (static_cast<std::size_t>(y) * f.width + x)];
          return (p[0] > 150 && p[1] < 90 && p[2] < 90) || (p[2] > 140 && p[0] < 80 && p[1] < 110);
        };
        for (int x = 0; x < f.width; ++x)
          if (body(x, 0) || body(x, f.height - 1)) touching = static_cast<int>(k);
        for (int y = 0; y < f.height; ++y)
          if (body(0, y) || body(f.width - 1, y)) touching = static_cast<int>(k);
      }
      EXPECT_EQ(touching, -1) << scene.name << ", " << view
                              << ": the body touches the border in frame " << touching << " ("
                              << mp4 << ")";
    }
  }
}

// Follow is a chase camera: it turns with the body, so its frames are not oblique's.
TEST(VideoContent, FollowIsNotOblique) {
  const render::Image oblique = still("scenes/rattleback.yaml --t 1 --view oblique --no-readouts");
  const render::Image follow = still("scenes/rattleback.yaml --t 1 --view follow --no-readouts");
  EXPECT_GT(difference(oblique, follow), 10.0);
}

// still --transparent: nothing but the body and its shadow. The corners (floor and background
// elsewhere) are fully transparent; the body's red and blue pixels opaque; the shadow partly
// transparent black (alpha between 0 and 255, colour dark).
// An opaque still is an RGB PNG (colour type 2, byte 25 of the file); a transparent one keeps
// its alpha (colour type 6); both read back to the same pixels as drawn.
TEST(Still, OpaqueStillsAreRgbAndTransparentOnesRgba) {
  for (const auto& [extra, type] : {std::pair{"", 2}, std::pair{" --transparent", 6}}) {
    const fs::path png = scratch(std::string("type") + std::to_string(type) + ".png");
    ASSERT_EQ(rattleback(std::string("still scenes/rattleback.yaml --t 1 --size 320x180 -q -o ") +
                         png.string() + extra),
              0);
    std::ifstream in(png, std::ios::binary);
    std::string head(26, '\0');
    in.read(head.data(), 26);
    EXPECT_EQ(static_cast<int>(static_cast<unsigned char>(head[25])), type) << extra;
    render::Image image;
    ASSERT_TRUE(render::readPng(png.string(), image).ok());
    EXPECT_EQ(image.width, 320);
  }
}

// A transparent still's colours are straight, as PNG stores them (not multiplied by alpha):
// at the body's smoothed edge a red sphere keeps its red while its alpha falls, so in the
// partly transparent red pixels red exceeds alpha, which premultiplied colour (c·a ≤ a) never
// does. Measured: 1307 of 2193 such pixels, where premultiplied colour gives none (found by a
// new user: every one was premultiplied, so slides showed the outline darkened).
TEST(Still, TransparentColoursAreStraightNotPremultiplied) {
  // At the scene's 1280 × 720, where the spheres' edges are smoothed (small frames draw them
  // hard: tests/render_test.cpp).
  const fs::path png = scratch("straight.png");
  ASSERT_EQ(rattleback("still scenes/rattleback.yaml --t 1 --transparent -q -o " + png.string()),
            0);
  render::Image image;
  ASSERT_TRUE(render::readPng(png.string(), image).ok());
  long red_edge = 0, red_above_alpha = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const int r = image.rgba[i], g = image.rgba[i + 1], a = image.rgba[i + 3];
    if (a < 20 || a > 128 || r < g + 40) continue;  // partly covered and red
    ++red_edge;
    if (r > a) ++red_above_alpha;
  }
  ASSERT_GT(red_edge, 50);
  EXPECT_GT(red_above_alpha, red_edge / 4);
}

TEST(Still, TransparentKeepsOnlyTheBodyAndItsShadow) {
  const render::Image image = still("scenes/rattleback.yaml --t 1 --view above --transparent");
  ASSERT_FALSE(image.rgba.empty());
  auto at = [&](int x, int y) {
    return &image.rgba[4 * (static_cast<std::size_t>(y) * image.width + x)];
  };
  for (auto [x, y] : {std::pair{0, 0}, std::pair{kWidth - 1, 0}, std::pair{0, kHeight - 1},
                      std::pair{kWidth - 1, kHeight - 1}, std::pair{kWidth / 10, kHeight / 2}})
    EXPECT_EQ(at(x, y)[3], 0) << x << "," << y;
  long opaque_body = 0, shadow = 0, transparent = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const unsigned char* p = at(x, y);
      if (p[3] == 255 && ((p[0] > 120 && p[1] < 90) || (p[2] > 120 && p[0] < 90))) ++opaque_body;
      if (p[3] > 10 && p[3] < 200 && p[0] < 40 && p[1] < 40 && p[2] < 40) ++shadow;
      if (p[3] == 0) ++transparent;
    }
  EXPECT_GT(opaque_body, 100);  // measured 229 at 320 × 180
  EXPECT_GT(shadow, 20);
  EXPECT_GT(transparent, kWidth * kHeight / 2);
}

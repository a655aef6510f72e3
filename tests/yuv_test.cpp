// The RGBA → yuv420p conversion the encoder uses (render/yuv.cpp): the 8-bit values of
// BT.709 for 100 % colour bars, every sample of a random picture against the standard's
// formulas evaluated in double precision, and where the chroma sits; and that frames
// converted before the encoder encode as those it converts.
#include "render/yuv.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

#include "render/encoder.hpp"

namespace {

namespace fs = std::filesystem;

struct Yuv420 {
  int width, height;
  std::vector<std::uint8_t> y, u, v;
  Yuv420(int w, int h) : width(w), height(h), y(w * h), u(w * h / 4), v(w * h / 4) {}
  render::Yuv420Planes planes() { return {y.data(), u.data(), v.data(), width, width / 2}; }
};

// A picture of random bytes (alpha too, which the conversion ignores).
render::Image noise(int w, int h, unsigned seed) {
  render::Image image{w, h, std::vector<unsigned char>(4 * w * h)};
  std::mt19937 random(seed);
  for (auto& c : image.rgba) c = static_cast<unsigned char>(random() & 255);
  return image;
}

render::Image flat(int w, int h, int r, int g, int b) {
  render::Image image{w, h, {}};
  for (int i = 0; i < w * h; ++i)
    image.rgba.insert(image.rgba.end(),
                      {static_cast<unsigned char>(r), static_cast<unsigned char>(g),
                       static_cast<unsigned char>(b), 255});
  return image;
}

// ITU-R BT.709-6 items 3.2 and 4.6, in double precision: Y, Cb, Cr before rounding, for R, G, B
// in 0 … 255.
std::array<double, 3> bt709(double r, double g, double b) {
  const double ey = (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255;
  return {16 + 219 * ey, 128 + 224 * (b / 255 - ey) / 1.8556, 128 + 224 * (r / 255 - ey) / 1.5748};
}

}  // namespace

// 100 % colour bars in 8-bit BT.709 (SMPTE RP 219, the values the standard's formulas round to).
TEST(Yuv, ColourBarsHaveTheirBt709Values) {
  struct Bar {
    int r, g, b, y, cb, cr;
  };
  const Bar bars[] = {{255, 255, 255, 235, 128, 128}, {255, 255, 0, 219, 16, 138},
                      {0, 255, 255, 188, 154, 16},    {0, 255, 0, 173, 42, 26},
                      {255, 0, 255, 78, 214, 230},    {255, 0, 0, 63, 102, 240},
                      {0, 0, 255, 32, 240, 118},      {0, 0, 0, 16, 128, 128}};
  render::Yuv420Converter converter;
  for (const Bar& bar : bars) {
    Yuv420 out(8, 4);
    converter.convert(flat(8, 4, bar.r, bar.g, bar.b), out.planes());
    for (auto y : out.y) EXPECT_EQ(y, bar.y) << bar.r << "," << bar.g << "," << bar.b;
    for (auto u : out.u) EXPECT_EQ(u, bar.cb) << bar.r << "," << bar.g << "," << bar.b;
    for (auto v : out.v) EXPECT_EQ(v, bar.cr) << bar.r << "," << bar.g << "," << bar.b;
  }
}

// Every sample of a random picture (every value of every channel occurs) is the standard's
// formula in double precision, rounded: within 0.53 of the exact value, the 0.03 because the
// fixed-point weights (14 fraction bits, each ≤ 0.5/2¹⁴ off; ≤ 0.02 on a value) may round a
// value that near a half the other way. Luma is per pixel; chroma is the mean of its two rows
// and of columns 2i−1, 2i, 2i+1 weighted ¼, ½, ¼ (H.264's default site, left; column 0 stands
// in for column −1). The width 38 is no multiple of a vector's lanes: the loops' tails count.
TEST(Yuv, EverySampleIsTheStandardsFormulaRounded) {
  const int w = 38, h = 10;
  const render::Image image = noise(w, h, 7);
  Yuv420 out(w, h);
  render::Yuv420Converter().convert(image, out.planes());
  auto at = [&](int x, int y, int c) { return double(image.rgba[4 * (y * w + x) + c]); };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      EXPECT_NEAR(out.y[y * w + x], bt709(at(x, y, 0), at(x, y, 1), at(x, y, 2))[0], 0.5 + 0.03)
          << x << "," << y;
  for (int j = 0; j < h / 2; ++j)
    for (int i = 0; i < w / 2; ++i) {
      std::array<double, 3> mean{};
      const int columns[3] = {i == 0 ? 0 : 2 * i - 1, 2 * i, 2 * i + 1};
      const double weights[3] = {0.25, 0.5, 0.25};
      for (int row : {2 * j, 2 * j + 1})
        for (int k = 0; k < 3; ++k)
          for (int c = 0; c < 3; ++c) mean[c] += 0.5 * weights[k] * at(columns[k], row, c);
      const auto expected = bt709(mean[0], mean[1], mean[2]);
      EXPECT_NEAR(out.u[j * w / 2 + i], expected[1], 0.5 + 0.03) << i << "," << j;
      EXPECT_NEAR(out.v[j * w / 2 + i], expected[2], 0.5 + 0.03) << i << "," << j;
    }
}

// A red field meeting a blue one at column 2k: chroma sample k weighs column 2k−1 (red) by ¼
// and columns 2k, 2k+1 (blue) by ¾, so it is the colour (¼·255, 0, ¾·255); a sample centred
// between the columns (as swscale's default) would be half and half.
TEST(Yuv, ChromaIsSitedOnTheLeftPixelOfEachPair) {
  const int w = 16, h = 2, edge = 8;
  render::Image image = flat(w, h, 255, 0, 0);
  for (int y = 0; y < h; ++y)
    for (int x = edge; x < w; ++x)
      image.rgba[4 * (y * w + x)] = 0, image.rgba[4 * (y * w + x) + 2] = 255;
  Yuv420 out(w, h);
  render::Yuv420Converter().convert(image, out.planes());
  const auto seam = bt709(0.25 * 255, 0, 0.75 * 255);
  EXPECT_EQ(out.u[edge / 2], std::lround(seam[1]));
  EXPECT_EQ(out.v[edge / 2], std::lround(seam[2]));
  EXPECT_EQ(out.u[edge / 2 - 1], 102);  // pure red, the bars' value
  EXPECT_EQ(out.u[edge / 2 + 1], 240);  // pure blue
}

// The one-buffer picture the drawing thread converts into (app/video.cpp) holds exactly what
// the converter writes into separate planes: Y, then U, then V, rows without padding.
TEST(Yuv, OneBufferHoldsThePlanesInOrder) {
  const int w = 38, h = 10;
  const render::Image image = noise(w, h, 11);
  Yuv420 planes(w, h);
  render::Yuv420Converter converter;
  converter.convert(image, planes.planes());
  render::Yuv420Image picture;
  converter.convert(image, picture);
  ASSERT_EQ(picture.data.size(), std::size_t{w * h * 3 / 2});
  EXPECT_TRUE(std::equal(planes.y.begin(), planes.y.end(), picture.y()));
  EXPECT_TRUE(std::equal(planes.u.begin(), planes.u.end(), picture.u()));
  EXPECT_TRUE(std::equal(planes.v.begin(), planes.v.end(), picture.v()));
}

// Frames converted by the caller (render's drawing thread) and frames the encoder converts
// itself (the bench's encoding alone) give the same file, byte for byte; a picture of another
// size is refused.
TEST(Yuv, EncodingConvertedFramesWritesTheSameVideo) {
  const int w = 64, h = 48;
  const fs::path folder =
      fs::temp_directory_path() / ("rattleback_yuv_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  render::EncoderSettings settings;
  settings.width = w;
  settings.height = h;
  settings.fps = 25;
  std::mt19937 random(3);
  std::vector<render::Image> frames;
  for (int k = 0; k < 5; ++k) {
    render::Image image{w, h, std::vector<unsigned char>(4 * w * h)};
    for (int i = 0; i < w * h; ++i)
      for (int c = 0; c < 3; ++c)
        image.rgba[4 * i + c] =
            static_cast<unsigned char>((i % w) * 4 + k * 20 + c * 50 + (random() & 15));
    frames.push_back(std::move(image));
  }
  auto encode = [&](const fs::path& path, bool converted) {
    auto opened = render::VideoEncoder::open(path.string(), settings);
    EXPECT_TRUE(opened) << (opened ? "" : opened.error().text());
    if (!opened) return;
    render::Yuv420Converter converter;
    render::Yuv420Image picture;
    for (const auto& image : frames) {
      if (converted) converter.convert(image, picture);
      const auto added = converted ? opened.value()->add(picture) : opened.value()->add(image);
      EXPECT_TRUE(added) << (added ? "" : added.error().text());
    }
    EXPECT_TRUE(opened.value()->finish());
  };
  encode(folder / "rgba.mp4", false);
  encode(folder / "yuv.mp4", true);
  auto bytes = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_GT(bytes(folder / "rgba.mp4").size(), 1000u);
  EXPECT_EQ(bytes(folder / "rgba.mp4"), bytes(folder / "yuv.mp4"));

  auto opened = render::VideoEncoder::open((folder / "small.mp4").string(), settings);
  ASSERT_TRUE(opened);
  render::Yuv420Image small;
  small.resize(w / 2, h);
  EXPECT_FALSE(opened.value()->add(small));
  fs::remove_all(folder);
}

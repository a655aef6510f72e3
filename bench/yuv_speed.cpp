// Milliseconds per 1280 × 720 frame of the RGBA → yuv420p conversion: ours (render/yuv.cpp)
// beside swscale's with the same BT.709 coefficients (the encoder's conversion before it),
// on one random picture, each the median of 5 passes of 100 frames, interleaved.
// Usage: rattleback_yuv_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

extern "C" {
#include <libswscale/swscale.h>
}

#include "render/yuv.hpp"

namespace {

constexpr int kWidth = 1280, kHeight = 720, kFrames = 100, kPasses = 5;

template <typename Convert>
double millisecondsPerFrame(Convert convert) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kFrames; ++i) convert();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
             .count() /
         kFrames;
}

}  // namespace

int main() {
  render::Image image{kWidth, kHeight, std::vector<unsigned char>(4 * kWidth * kHeight)};
  std::mt19937 random(1);
  for (auto& c : image.rgba) c = static_cast<unsigned char>(random());
  std::vector<std::uint8_t> y(kWidth * kHeight), u(kWidth * kHeight / 4), v(kWidth * kHeight / 4);
  render::Yuv420Converter ours;
  const render::Yuv420Planes planes{y.data(), u.data(), v.data(), kWidth, kWidth / 2};
  SwsContext* sws = sws_getContext(kWidth, kHeight, AV_PIX_FMT_RGBA, kWidth, kHeight,
                                   AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(sws, bt709, 1, bt709, 0, 0, 1 << 16, 1 << 16);
  const std::uint8_t* source[1] = {image.rgba.data()};
  const int source_stride[1] = {4 * kWidth};
  std::uint8_t* const out[3] = {y.data(), u.data(), v.data()};
  const int out_stride[3] = {kWidth, kWidth / 2, kWidth / 2};
  std::vector<double> ours_ms, sws_ms;
  for (int pass = 0; pass < kPasses; ++pass) {
    ours_ms.push_back(millisecondsPerFrame([&] { ours.convert(image, planes); }));
    sws_ms.push_back(millisecondsPerFrame(
        [&] { sws_scale(sws, source, source_stride, 0, kHeight, out, out_stride); }));
  }
  sws_freeContext(sws);
  std::sort(ours_ms.begin(), ours_ms.end());
  std::sort(sws_ms.begin(), sws_ms.end());
  const double a = ours_ms[kPasses / 2], b = sws_ms[kPasses / 2];
  std::printf("RGBA -> yuv420p, BT.709, %dx%d, ms per frame (median of %d passes of %d)\n", kWidth,
              kHeight, kPasses, kFrames);
  std::printf("render/yuv.cpp  %.3f\nswscale         %.3f  (%.1fx ours)\n", a, b, b / a);
  return 0;
}

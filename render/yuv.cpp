#include "render/yuv.hpp"

#include <cassert>
#include <cstddef>

namespace render {
namespace {

// BT.709 (ITU-R BT.709-6, item 3.2): E'y = 0.2126 R + 0.7152 G + 0.0722 B, and the colour
// differences E'cb = (B − E'y) / 1.8556, E'cr = (R − E'y) / 1.5748; quantised to 8 bits
// (item 4.6) as Y = 16 + 219 E'y, Cb = 128 + 224 E'cb, Cr = 128 + 224 E'cr with R, G, B in
// 0 … 1. The weights below take R, G, B in 0 … 255, in fixed point with 14 fraction bits.
constexpr double kKr = 0.2126, kKb = 0.0722, kKg = 1 - kKr - kKb;
constexpr int kBits = 14;
constexpr int fixed(double v) {
  return static_cast<int>(v * (1 << kBits) + (v < 0 ? -0.5 : 0.5));
}
constexpr double kLuma = 219.0 / 255, kCb = 224.0 / 255 / (2 * (1 - kKb)),
                 kCr = 224.0 / 255 / (2 * (1 - kKr));
constexpr int kYr = fixed(kLuma * kKr), kYg = fixed(kLuma * kKg), kYb = fixed(kLuma * kKb);
constexpr int kUr = fixed(-kCb * kKr), kUg = fixed(-kCb * kKg), kUb = fixed(kCb * (1 - kKb));
constexpr int kVr = fixed(kCr * (1 - kKr)), kVg = fixed(-kCr * kKg), kVb = fixed(-kCr * kKb);

// Luma of two rows, and each column's R, G, B summed over both (for the chroma). The loops
// are plain so that the compiler vectorises them; built for AVX2 as well, chosen at run time.
__attribute__((target_clones("avx2", "default"))) void lumaOfRowPair(
    const std::uint8_t* __restrict a, const std::uint8_t* __restrict b,
    std::uint8_t* __restrict y_a, std::uint8_t* __restrict y_b, std::int16_t* __restrict sums,
    int width) {
  constexpr int offset = (16 << kBits) + (1 << (kBits - 1));  // +16, rounded
  std::int16_t* __restrict r_sum = sums;
  std::int16_t* __restrict g_sum = sums + width;
  std::int16_t* __restrict b_sum = sums + 2 * width;
  for (int x = 0; x < width; ++x) {
    const int ra = a[4 * x], ga = a[4 * x + 1], ba = a[4 * x + 2];
    const int rb = b[4 * x], gb = b[4 * x + 1], bb = b[4 * x + 2];
    y_a[x] = static_cast<std::uint8_t>((kYr * ra + kYg * ga + kYb * ba + offset) >> kBits);
    y_b[x] = static_cast<std::uint8_t>((kYr * rb + kYg * gb + kYb * bb + offset) >> kBits);
    r_sum[x] = static_cast<std::int16_t>(ra + rb);
    g_sum[x] = static_cast<std::int16_t>(ga + gb);
    b_sum[x] = static_cast<std::int16_t>(ba + bb);
  }
}

// One chroma row from a row pair's column sums: the sample of columns 2i and 2i+1 is centred
// on column 2i, so it weighs columns 2i−1, 2i, 2i+1 by ¼, ½, ¼ (column 0 stands in for −1).
// With the two rows that is 8 × the mean colour.
__attribute__((target_clones("avx2", "default"))) void chromaOfRowPair(
    const std::int16_t* __restrict sums, std::uint8_t* __restrict u, std::uint8_t* __restrict v,
    int width) {
  constexpr int shift = kBits + 3;                             // ÷ 8 for the weights
  constexpr int offset = (128 << shift) + (1 << (shift - 1));  // +128, rounded
  const std::int16_t* r = sums;
  const std::int16_t* g = sums + width;
  const std::int16_t* b = sums + 2 * width;
  auto sample = [&](int i, int left) {
    const int c = 2 * i, right = 2 * i + 1;
    const int rs = r[left] + 2 * r[c] + r[right], gs = g[left] + 2 * g[c] + g[right],
              bs = b[left] + 2 * b[c] + b[right];
    u[i] = static_cast<std::uint8_t>((kUr * rs + kUg * gs + kUb * bs + offset) >> shift);
    v[i] = static_cast<std::uint8_t>((kVr * rs + kVg * gs + kVb * bs + offset) >> shift);
  };
  sample(0, 0);
  for (int i = 1; i < width / 2; ++i) sample(i, 2 * i - 1);
}

}  // namespace

void Yuv420Image::resize(int w, int h) {
  width = w;
  height = h;
  data.resize(static_cast<std::size_t>(w) * h * 3 / 2);
}

Yuv420Planes Yuv420Image::planes() {
  std::uint8_t* y = data.data();
  std::uint8_t* u = y + static_cast<std::size_t>(width) * height;
  std::uint8_t* v = u + static_cast<std::size_t>(width / 2) * (height / 2);
  return {y, u, v, width, width / 2};
}

void Yuv420Converter::convert(const Image& image, Yuv420Image& out) {
  out.resize(image.width, image.height);
  convert(image, out.planes());
}

void Yuv420Converter::convert(const Image& image, const Yuv420Planes& out) {
  assert(image.width % 2 == 0 && image.height % 2 == 0);
  const int w = image.width;
  sums_.resize(3 * static_cast<std::size_t>(w));
  const std::size_t row = 4 * static_cast<std::size_t>(w);
  for (int top = 0; top < image.height; top += 2) {
    const std::uint8_t* a = image.rgba.data() + top * row;
    std::uint8_t* y = out.y + static_cast<std::ptrdiff_t>(top) * out.y_stride;
    lumaOfRowPair(a, a + row, y, y + out.y_stride, sums_.data(), w);
    const std::ptrdiff_t c = static_cast<std::ptrdiff_t>(top / 2) * out.uv_stride;
    chromaOfRowPair(sums_.data(), out.u + c, out.v + c, w);
  }
}

}  // namespace render

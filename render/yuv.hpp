// RGBA → yuv420p for the encoder: the BT.709 matrix, limited range (Y 16–235, Cb/Cr 16–240),
// chroma sited left of each pixel pair and between its two rows (H.264's default chroma
// location, type 0). Written here rather than taken from swscale: the same conversion took
// 1.95 ms a 720p frame in swscale 6.7 and 0.49 ms here (bench/yuv_speed.cpp); libyuv, faster
// still, has no BT.709 conversion from RGB in Debian 12.
#pragma once

#include <cstdint>
#include <vector>

#include "render/frame.hpp"

namespace render {

/// Where a yuv420p picture goes: its three planes and their row strides, bytes.
struct Yuv420Planes {
  std::uint8_t* y = nullptr;
  std::uint8_t* u = nullptr;
  std::uint8_t* v = nullptr;
  int y_stride = 0, uv_stride = 0;
};

/// A yuv420p picture in one buffer: the Y plane (width × height), then U and V (each
/// width/2 × height/2), rows without padding. 1.5 bytes a pixel, where RGBA takes 4.
struct Yuv420Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> data;

  /// Sizes the buffer for a picture of w × h (even numbers).
  void resize(int w, int h);
  Yuv420Planes planes();
  const std::uint8_t* y() const { return data.data(); }
  const std::uint8_t* u() const { return y() + static_cast<std::size_t>(width) * height; }
  const std::uint8_t* v() const { return u() + static_cast<std::size_t>(width / 2) * (height / 2); }
};

class Yuv420Converter {
 public:
  /// Converts `image` (even width and height; alpha ignored) into `out`, which must hold it.
  void convert(const Image& image, const Yuv420Planes& out);
  /// Converts `image` into `out`, sized to it (its buffer reused).
  void convert(const Image& image, Yuv420Image& out);

 private:
  std::vector<std::int16_t> sums_;  ///< a row pair's R, G and B summed over its two rows
};

}  // namespace render

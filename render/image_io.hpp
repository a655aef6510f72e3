// PNG files (libpng) and image comparison for snapshot tests.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/frame.hpp"
#include "util/picture.hpp"
#include "util/result.hpp"

namespace render {

/// Writes an RGBA PNG under a temporary name and renames it into place (through links, in
/// place to a device: util/output_place.hpp); an error line naming the file when anything
/// fails (nothing is left behind then).
rb::Status writePng(const std::string& path, const Image& image);
/// The image as PNG bytes (RGB when every pixel is opaque, else RGBA).
rb::Result<std::vector<unsigned char>> encodePng(const Image& image);
/// Reads a PNG as RGBA; an error line naming the file when it cannot.
rb::Status readPng(const std::string& path, Image& image);

/// How two images differ: a pixel differs when any channel differs by more than
/// `channel_tolerance` (0–255).
struct Comparison {
  bool same_size = false;
  long long pixels = 0;
  long long differing = 0;    ///< pixels beyond the channel tolerance
  int max_channel_delta = 0;  ///< largest channel difference anywhere
  double fraction() const { return pixels ? static_cast<double>(differing) / pixels : 1.0; }
  /// Bounding box of the differing pixels (x0, y0, x1, y1), when any.
  int box[4] = {0, 0, 0, 0};
  /// The side of the largest square of pixels that all differ, and its top-left corner: a
  /// changed thing of some size, where scattered edge pixels (another CPU's rasteriser) make
  /// lines one or two pixels wide.
  int square = 0;
  int square_at[2] = {0, 0};
};

Comparison compareImages(const Image& a, const Image& b, int channel_tolerance);

/// The verdict of a comparison under a tolerance: false for images of different sizes.
bool matches(const Comparison& c, const Tolerance& tolerance);
/// The square rule alone: a square of differing pixels `square` a side or more was found.
bool squareDiffers(const Comparison& c, const Tolerance& tolerance);
/// An image that shows where a and b differ: grey copy of `a` with differing pixels in magenta.
Image diffImage(const Image& a, const Image& b, int channel_tolerance);

}  // namespace render

// Read-outs drawn over a rendered frame on the CPU: text (FreeType, DejaVu) and a small
// plot of the spin so far.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "render/frame.hpp"

namespace render {

using Rgba = std::array<unsigned char, 4>;

class Overlay {
 public:
  Overlay();
  ~Overlay();
  /// Loads the first font of assets/fonts.txt that exists, at `pixels` high; an error message
  /// when none can be loaded.
  std::string load(int pixels);
  /// Draws UTF-8 text with its baseline at y; returns the x after it.
  int text(Image& image, int x, int y, const std::string& utf8, Rgba color);
  /// How far text() would advance for this text, pixels.
  int width(const std::string& utf8);
  int lineHeight() const { return pixels_; }

 private:
  struct Glyph {
    int width = 0, rows = 0, left = 0, top = 0, advance = 0;
    std::vector<unsigned char> alpha;
  };
  const Glyph& glyph(char32_t code);
  struct Face;
  std::unique_ptr<Face> face_;
  std::map<char32_t, Glyph> glyphs_;
  int pixels_ = 16;
};

/// Blends `color` (its alpha as opacity) over the rectangle [x0, x1) × [y0, y1).
void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgba color);
/// An anti-aliased line about `width` pixels wide.
void drawLine(Image& image, float x0, float y0, float x1, float y1, float width, Rgba color);

/// The top row of the inset in a frame of this height (it sits in the bottom-right corner).
int insetTop(int image_height);

/// A length as a caption gives it: "2 cm", "5 mm", "1 m" (the unit that makes it at least 1).
std::string lengthText(double metres);

/// One line in a box at the bottom left, level with the inset's bottom (the floor's scale).
void drawScaleLabel(Image& image, Overlay& font, const std::string& text);

/// The inset: n(t) so far against a fixed time axis [0, duration] and spin axis ±range.
void drawSpinInset(Image& image, Overlay& font, std::span<const std::array<float, 2>> history,
                   double duration, double range);

}  // namespace render

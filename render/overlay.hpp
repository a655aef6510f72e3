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

/// A box of the frame's text: [x0, x1) × [y0, y1), pixels.
struct Box {
  int x0, y0, x1, y1;
  /// Whether (x, y) lies within it or within `margin` pixels of it.
  bool near(float x, float y, float margin) const {
    return x > x0 - margin && x < x1 + margin && y > y0 - margin && y < y1 + margin;
  }
};

/// One line in a box at the bottom left, level with the inset's bottom (the floor's scale).
void drawScaleLabel(Image& image, Overlay& font, const std::string& text);
/// The box drawScaleLabel draws `text` in.
Box scaleLabelBox(const Image& image, Overlay& font, const std::string& text);

/// The inset: n(t) so far against a fixed time axis [0, duration] and spin axis ±range, with a
/// tick at each of `reversals` (s) that lies within the curve drawn so far.
void drawSpinInset(Image& image, Overlay& font, std::span<const std::array<float, 2>> history,
                   double duration, double range, std::span<const double> reversals = {});
/// The box drawSpinInset draws in.
Box spinInsetBox(const Image& image, Overlay& font, double duration, double range);

/// The spin cue's colours (docs/commands.md "The spin cue"): from Okabe and Ito's palette, told
/// apart with any colour vision and unlike the body's red top and blue bottom.
inline constexpr Rgba kCounterClockwiseColor{230, 159, 0, 255};  ///< orange: n > 0
inline constexpr Rgba kClockwiseColor{0, 158, 115, 255};         ///< bluish green: n < 0
/// The reversal label's background: Okabe and Ito's yellow, under dark text.
inline constexpr Rgba kReversalColor{240, 228, 66, 255};
/// The slowest spin given a direction (the read-out's words, the cue's arrow), rad/s.
inline constexpr double kSlowestShownSpin = 0.05;
/// How long a frame says "reversal" after one, s: about two rocking periods of the default
/// body, long enough to read at the back of a classroom.
inline constexpr double kReversalShownFor = 1.5;

/// `arc` without the points at either end that lie within `margin` pixels of any of `boxes`
/// (text drawn over the arrow): an end stops short of a box rather than running under it.
std::span<const std::array<float, 2>> endsClearOf(std::span<const std::array<float, 2>> arc,
                                                  std::span<const Box> boxes, float margin);
/// An arrow along `arc` (pixels, in the order of travel), `width` pixels wide, with a dark
/// edge for contrast on the light floor and a head at the arc's end.
void drawArrow(Image& image, std::span<const std::array<float, 2>> arc, float width, Rgba color);
/// A filled, anti-aliased triangle.
void fillTriangle(Image& image, const std::array<std::array<float, 2>, 3>& corners, Rgba color);
/// "reversal at T s" (the run's `number`th reversal from the second: "reversal 2 at T s") in a
/// yellow box whose right edge is at `right`, text on `baseline`.
void drawReversalLabel(Image& image, Overlay& font, int right, int baseline, double t_reversal,
                       int number = 1);

}  // namespace render

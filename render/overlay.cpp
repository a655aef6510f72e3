#include "render/overlay.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "render/gl.hpp"

namespace render {

struct Overlay::Face {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  ~Face() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }
};

Overlay::Overlay() = default;
Overlay::~Overlay() = default;

std::string Overlay::load(int pixels) {
  pixels_ = pixels;
  face_ = std::make_unique<Face>();
  if (FT_Init_FreeType(&face_->library)) return "cannot start FreeType";
  const std::string list = assetsDir() + "/fonts.txt";
  std::ifstream in(list);
  // No list at all: the assets folder is not where it was looked for (a RATTLEBACK_ASSETS set wrong
  // said "install fonts-dejavu-core", which would not help).
  if (!in)
    return list + ": cannot read the font list (set RATTLEBACK_ASSETS to the assets folder, " +
           "share/rattleback where rattleback is installed, or unset it)";
  std::string path;
  while (std::getline(in, path)) {
    if (path.empty() || path[0] == '#') continue;
    if (FT_New_Face(face_->library, path.c_str(), 0, &face_->face) == 0) {
      FT_Set_Pixel_Sizes(face_->face, 0, pixels);
      return "";
    }
  }
  return "no usable font listed in " + list + " (install fonts-dejavu-core)";
}

const Overlay::Glyph& Overlay::glyph(char32_t code) {
  auto it = glyphs_.find(code);
  if (it != glyphs_.end()) return it->second;
  Glyph g;
  if (face_ && face_->face && FT_Load_Char(face_->face, code, FT_LOAD_RENDER) == 0) {
    const FT_GlyphSlot slot = face_->face->glyph;
    g.width = static_cast<int>(slot->bitmap.width);
    g.rows = static_cast<int>(slot->bitmap.rows);
    g.left = slot->bitmap_left;
    g.top = slot->bitmap_top;
    g.advance = static_cast<int>(slot->advance.x >> 6);
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.width; ++c)
        g.alpha.push_back(slot->bitmap.buffer[r * slot->bitmap.pitch + c]);
  }
  return glyphs_.emplace(code, std::move(g)).first->second;
}

namespace {

// Decodes UTF-8 (well-formed input assumed: it comes from our own format strings).
std::vector<char32_t> decode(const std::string& s) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < s.size();) {
    const unsigned char c = s[i];
    int extra = c < 0x80 ? 0 : c < 0xE0 ? 1 : c < 0xF0 ? 2 : 3;
    char32_t code = extra == 0 ? c : c & (0x3F >> extra);
    for (int k = 1; k <= extra && i + k < s.size(); ++k) code = (code << 6) | (s[i + k] & 0x3F);
    out.push_back(code);
    i += extra + 1;
  }
  return out;
}

// One channel's value `old` blended towards `target` by `a` (0–1), rounded.
unsigned char blendChannel(unsigned char old, unsigned char target, float a) {
  return static_cast<unsigned char>(old + (target - old) * a + 0.5f);
}

void blend(Image& image, int x, int y, Rgba color, float coverage) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || coverage <= 0) return;
  unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
  const float a = coverage * color[3] / 255.0f;
  for (int k = 0; k < 3; ++k) p[k] = blendChannel(p[k], color[k], a);
}

}  // namespace

int Overlay::text(Image& image, int x, int y, const std::string& utf8, Rgba color) {
  for (char32_t code : decode(utf8)) {
    const Glyph& g = glyph(code);
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.width; ++c)
        blend(image, x + g.left + c, y - g.top + r, color, g.alpha[r * g.width + c] / 255.0f);
    x += g.advance;
  }
  return x;
}

int Overlay::width(const std::string& utf8) {
  int x = 0;
  for (char32_t code : decode(utf8)) x += glyph(code).advance;
  return x;
}

void fillRect(Image& image, int x0, int y0, int x1, int y1, Rgba color) {
  // Every pixel gets the same blend, so each channel's result is a function of its old value
  // alone: a table of 256 per channel, of blend()'s own values (the same as pixel by pixel, at
  // a fraction of the cost: the inset is 6 % of a frame).
  const float a = color[3] / 255.0f;
  std::array<std::array<unsigned char, 256>, 3> table;
  for (int v = 0; v < 256; ++v)
    for (int k = 0; k < 3; ++k)
      table[k][v] = blendChannel(static_cast<unsigned char>(v), color[k], a);
  const int xa = std::max(0, x0), xb = std::min(image.width, x1);
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    unsigned char* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + xa) * 4];
    for (int x = xa; x < xb; ++x, p += 4)
      for (int k = 0; k < 3; ++k) p[k] = table[k][p[k]];
  }
}

void drawLine(Image& image, float x0, float y0, float x1, float y1, float width, Rgba color) {
  // Coverage of each pixel near the segment from its distance to the segment: a one-pixel
  // soft edge around a core `width` wide.
  const int xa = static_cast<int>(std::floor(std::min(x0, x1) - width - 1));
  const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + width + 1));
  const int ya = static_cast<int>(std::floor(std::min(y0, y1) - width - 1));
  const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + width + 1));
  const float dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy;
  for (int y = ya; y <= yb; ++y) {
    for (int x = xa; x <= xb; ++x) {
      const float px = x + 0.5f - x0, py = y + 0.5f - y0;
      const float u = length2 > 0 ? std::clamp((px * dx + py * dy) / length2, 0.0f, 1.0f) : 0;
      const float ex = px - u * dx, ey = py - u * dy;
      const float d = std::sqrt(ex * ex + ey * ey);  // (hypot guards against overflow: slow)
      blend(image, x, y, color, std::clamp(width / 2 + 0.5f - d, 0.0f, 1.0f));
    }
  }
}

namespace {
// The inset is 2/9 of the frame's height, a 40th above its bottom edge. (Not taller with
// larger text, though its title then takes more of it: taller, it met the spin cue's arrow
// head in the oblique view.)
int insetHeight(int image_height) {
  return image_height * 2 / 9;
}
int insetMargin(int image_height) {
  return image_height / 40;
}
}  // namespace

int insetTop(int image_height) {
  return image_height - insetHeight(image_height) - insetMargin(image_height);
}

std::string lengthText(double metres) {
  char text[32];
  // Squares are 1, 2 or 5 × 10ⁿ m in float (0.01f is 0.0099999998): %g's six digits drop the
  // float's last bits, and the unit is chosen with as much room.
  const double m = metres * (1 + 1e-6);
  if (m >= 1)
    std::snprintf(text, sizeof text, "%g m", metres);
  else if (m >= 0.01)
    std::snprintf(text, sizeof text, "%g cm", metres * 100);
  else
    std::snprintf(text, sizeof text, "%g mm", metres * 1000);
  return text;
}

Box scaleLabelBox(const Image& image, Overlay& font, const std::string& text) {
  const int pad = font.lineHeight() / 2;
  const int margin = insetMargin(image.height);
  const int w = font.width(text) + 2 * pad, h = font.lineHeight() + 2 * pad;
  const int x0 = margin, y1 = image.height - margin;
  return {x0, y1 - h, x0 + w, y1};
}

void drawScaleLabel(Image& image, Overlay& font, const std::string& text) {
  const Box box = scaleLabelBox(image, font, text);
  fillRect(image, box.x0, box.y0, box.x1, box.y1, {255, 255, 255, 200});
  const int pad = font.lineHeight() / 2;
  font.text(image, box.x0 + pad, box.y1 - pad - font.lineHeight() / 4, text, {40, 40, 40, 255});
}

namespace {
std::string insetLabel(double duration, double range) {
  char label[64];
  std::snprintf(label, sizeof label, "n ±%g rad/s, 0–%g s", range, duration);
  return label;
}
}  // namespace

Box spinInsetBox(const Image& image, Overlay& font, double duration, double range) {
  const int pad = font.lineHeight() / 2;
  const int margin = insetMargin(image.height);
  // Three tenths of the width, and at least its title's (a narrow frame's text is relatively
  // wider), within the frame.
  const int w =
      std::min(std::max(image.width * 3 / 10, font.width(insetLabel(duration, range)) + 2 * pad),
               image.width - 2 * margin);
  const int x0 = image.width - w - margin, y0 = insetTop(image.height);
  return {x0, y0, x0 + w, y0 + insetHeight(image.height)};
}

void drawSpinInset(Image& image, Overlay& font, std::span<const std::array<float, 2>> history,
                   double duration, double range, std::span<const double> reversals) {
  const std::string label = insetLabel(duration, range);
  const int pad = font.lineHeight() / 2;
  const Box box = spinInsetBox(image, font, duration, range);
  const int x0 = box.x0, y0 = box.y0, w = box.x1 - box.x0, h = box.y1 - box.y0;
  fillRect(image, x0, y0, x0 + w, y0 + h, {255, 255, 255, 200});
  const float left = x0 + pad, right = x0 + w - pad;
  // The curve a 240th of the frame's height wide, at least 2 px (3 px at 720p): 2 px alone
  // was a hairline from the back of a room. The small frames (the goldens', 180 px) keep 2 px.
  const float curve = std::max(2.0f, image.height / 240.0f);
  // The curve's band starts below the title's descenders (the title's line ends at
  // y0 + pad + lineHeight) with room for half the curve's width and its antialiased edge,
  // so the curve never runs through the title.
  const float room = curve / 2 + 1;
  const float top = y0 + pad + font.lineHeight() + 0.5f * pad + room;
  const float bottom = y0 + h - pad - room;
  const float mid = 0.5f * (top + bottom);
  drawLine(image, left, mid, right, mid, std::max(1.0f, curve / 2), {90, 90, 90, 255});  // n = 0
  font.text(image, x0 + pad, y0 + pad + font.lineHeight() * 3 / 4, label, {40, 40, 40, 255});
  auto to_screen = [&](const std::array<float, 2>& p) {
    const float x = left + (right - left) * static_cast<float>(p[0] / duration);
    const float y =
        mid - (bottom - top) / 2 * static_cast<float>(std::clamp(p[1] / range, -1.0, 1.0));
    return std::array<float, 2>{x, y};
  };
  // A reversal the curve has reached: a dark tick across the band, under the curve, where n
  // crosses zero for good.
  // (In the history's float: a still drawn at its reversal, t = the reversal's double, had the
  // curve end a float's rounding before it, and no tick.)
  const float now = history.empty() ? 0 : history.back()[0];
  for (double t : reversals) {
    if (static_cast<float>(t) > now || t > duration) continue;
    const float x = to_screen({static_cast<float>(t), 0})[0];
    drawLine(image, x, top, x, bottom, curve, {30, 30, 30, 255});
  }
  for (std::size_t i = 1; i < history.size(); ++i) {
    const auto a = to_screen(history[i - 1]), b = to_screen(history[i]);
    drawLine(image, a[0], a[1], b[0], b[1], curve, {20, 60, 160, 255});
  }
}

void fillTriangle(Image& image, const std::array<std::array<float, 2>, 3>& corners, Rgba color) {
  // Coverage from the signed distance to the nearest edge: a one-pixel soft edge, as drawLine's.
  float area = 0;
  for (int i = 0; i < 3; ++i) {
    const auto &a = corners[i], &b = corners[(i + 1) % 3];
    area += a[0] * b[1] - b[0] * a[1];
  }
  if (area == 0) return;
  const float sign = area > 0 ? 1.0f : -1.0f;
  float xa = 1e9f, xb = -1e9f, ya = 1e9f, yb = -1e9f;
  for (const auto& c : corners) {
    xa = std::min(xa, c[0]), xb = std::max(xb, c[0]);
    ya = std::min(ya, c[1]), yb = std::max(yb, c[1]);
  }
  for (int y = static_cast<int>(std::floor(ya)) - 1; y <= static_cast<int>(std::ceil(yb)); ++y)
    for (int x = static_cast<int>(std::floor(xa)) - 1; x <= static_cast<int>(std::ceil(xb)); ++x) {
      float inside = 1e9f;  // pixels from the nearest edge, > 0 inside
      for (int i = 0; i < 3; ++i) {
        const auto &a = corners[i], &b = corners[(i + 1) % 3];
        const float ex = b[0] - a[0], ey = b[1] - a[1];
        const float cross = ex * (y + 0.5f - a[1]) - ey * (x + 0.5f - a[0]);
        inside = std::min(inside, sign * cross / std::sqrt(ex * ex + ey * ey));
      }
      blend(image, x, y, color, std::clamp(inside + 0.5f, 0.0f, 1.0f));
    }
}

namespace {
// The arrow's head at the end of `arc`: a triangle `length` long pointing along its last segment.
std::array<std::array<float, 2>, 3> arrowHead(std::span<const std::array<float, 2>> arc,
                                              float length) {
  const auto &a = arc[arc.size() - 2], &b = arc.back();
  float dx = b[0] - a[0], dy = b[1] - a[1];
  const float norm = std::max(std::sqrt(dx * dx + dy * dy), 1e-6f);
  dx /= norm, dy /= norm;
  const float half = 0.6f * length;
  return {{{b[0] + dx * length, b[1] + dy * length},
           {b[0] - dy * half, b[1] + dx * half},
           {b[0] + dy * half, b[1] - dx * half}}};
}
}  // namespace

std::span<const std::array<float, 2>> endsClearOf(std::span<const std::array<float, 2>> arc,
                                                  std::span<const Box> boxes, float margin) {
  auto covered = [&](const std::array<float, 2>& p) {
    return std::any_of(boxes.begin(), boxes.end(),
                       [&](const Box& b) { return b.near(p[0], p[1], margin); });
  };
  std::size_t first = 0, last = arc.size();
  while (first < last && covered(arc[first])) ++first;
  while (last > first && covered(arc[last - 1])) --last;
  return arc.subspan(first, last - first);
}

void drawArrow(Image& image, std::span<const std::array<float, 2>> arc, float width, Rgba color) {
  if (arc.size() < 2) return;
  const float head = 3.5f * width;
  // A dark edge a pixel wide each side first, then the colour: orange on the light floor alone
  // has too little contrast to read at a distance.
  const Rgba edge{30, 30, 30, 200};
  for (int pass = 0; pass < 2; ++pass) {
    const float w = pass == 0 ? width + 2 : width;
    const Rgba c = pass == 0 ? edge : color;
    for (std::size_t i = 1; i < arc.size(); ++i)
      drawLine(image, arc[i - 1][0], arc[i - 1][1], arc[i][0], arc[i][1], w, c);
    auto corners = arrowHead(arc, pass == 0 ? head + 2 : head);
    if (pass == 0) {  // the edge's triangle a pixel larger all round: from its centroid
      const float cx = (corners[0][0] + corners[1][0] + corners[2][0]) / 3;
      const float cy = (corners[0][1] + corners[1][1] + corners[2][1]) / 3;
      for (auto& p : corners) {
        const float dx = p[0] - cx, dy = p[1] - cy, d = std::sqrt(dx * dx + dy * dy);
        if (d > 0) p = {p[0] + 1.5f * dx / d, p[1] + 1.5f * dy / d};
      }
    }
    fillTriangle(image, corners, c);
  }
}

namespace {
// The first reversal plainly; a later one with its number, which the class asks for when a
// body reverses three times and the badge shows the third.
std::string reversalText(double t_reversal, int number) {
  char text[64];
  if (number > 1)
    std::snprintf(text, sizeof text, "reversal %d at %.2f s", number, t_reversal);
  else
    std::snprintf(text, sizeof text, "reversal at %.2f s", t_reversal);
  return text;
}
}  // namespace

int reversalLabelWidth(Overlay& font) {
  return font.width(reversalText(88.88, 88)) + 2 * (font.lineHeight() / 2);
}

void drawReversalLabel(Image& image, Overlay& font, int right, int baseline, double t_reversal,
                       int number) {
  const std::string text = reversalText(t_reversal, number);
  const int pad = font.lineHeight() / 2;
  const int w = font.width(text) + 2 * pad;
  const int x0 = right - w, y0 = baseline - font.lineHeight() - pad / 2;
  fillRect(image, x0, y0, right, baseline + pad, kReversalColor);
  font.text(image, x0 + pad, baseline, text, {20, 20, 20, 255});
}

}  // namespace render

#include "render/image_io.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "util/output_place.hpp"

namespace render {

namespace {

struct File {
  FILE* f = nullptr;
  ~File() {
    if (f) std::fclose(f);
  }
};

}  // namespace

rb::Result<std::vector<unsigned char>> encodePng(const Image& image) {
  std::vector<unsigned char> bytes;
  std::string software = image.drawn_by;  // (before setjmp, as everything with a destructor)
  png_text text{};
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return rb::Error{"", "cannot start libpng"};
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return rb::Error{"", "encoding PNG failed"};
  }
  png_set_write_fn(
      png, &bytes,
      [](png_structp p, png_bytep data, png_size_t size) {
        auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(p));
        out->insert(out->end(), data, data + size);
      },
      [](png_structp) {});
  // RGB when every pixel is opaque (a quarter smaller, and what viewers expect of a frame);
  // RGBA only when some alpha says something (still --transparent).
  bool opaque = true;
  for (std::size_t i = 3; i < image.rgba.size() && opaque; i += 4) opaque = image.rgba[i] == 255;
  png_set_IHDR(png, info, image.width, image.height, 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // What drew it, as PNG's own keyword says it (no date: the same picture, the same bytes).
  if (!software.empty()) {
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = const_cast<char*>("Software");
    text.text = software.data();
    png_set_text(png, info, &text, 1);
  }
  png_write_info(png, info);
  if (opaque) png_set_filler(png, 0, PNG_FILLER_AFTER);  // rows stay RGBA; the A is dropped
  for (int y = 0; y < image.height; ++y)
    png_write_row(png, &image.rgba[static_cast<std::size_t>(y) * image.width * 4]);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

rb::Status writePng(const std::string& path, const Image& image) {
  const rb::OutputPlace place = rb::outputPlace(path);
  const bool special = place.temporary.empty();  // written in place
  const std::string temp = special ? place.target : place.temporary;
  // Every failure after the file was opened is the machine's (a full disk, a size limit).
  auto fail = [&](const std::string& why) -> rb::Status {
    if (!special) std::remove(temp.c_str());
    return rb::Status::fault(path + ": " + why);
  };
  auto bytes = encodePng(image);
  if (!bytes) return rb::Status::fail(path + ": " + bytes.error().text());
  File file;
  file.f = std::fopen(temp.c_str(), "wb");
  if (!file.f) return rb::Status::fail(rb::cannotWriteIn(path, errno));
  const bool written = std::fwrite(bytes->data(), 1, bytes->size(), file.f) == bytes->size();
  const bool flushed = written && std::fflush(file.f) == 0 && !std::ferror(file.f);
  const int close_status = std::fclose(file.f);
  file.f = nullptr;
  if (!flushed || close_status != 0)
    return fail(std::string("writing failed: ") + std::strerror(errno));
  if (special) return {};
  std::error_code ec;
  std::filesystem::rename(temp, place.target, ec);
  if (ec) return fail("cannot move the finished file into place: " + ec.message());
  return {};
}

rb::Status readPng(const std::string& path, Image& image) {
  // The stored values, as they are: libpng's simplified reader would convert them by the
  // file's gAMA/cHRM chunks (ffmpeg writes them), and a pixel comparison must not.
  File file;
  file.f = std::fopen(path.c_str(), "rb");
  if (!file.f) return rb::Status::fail(path + ": cannot read: " + std::strerror(errno));
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, 8, file.f) != 8 || png_sig_cmp(signature, 0, 8)) {
    // A clone without Git LFS's files holds, in each PNG's place, the pointer text LFS writes
    // (git-lfs's spec: its first line is "version https://git-lfs..."): the way out is LFS's.
    char rest[16] = {};
    if (std::memcmp(signature, "version ", 8) == 0 && std::fread(rest, 1, 15, file.f) == 15 &&
        std::strcmp(rest, "https://git-lfs") == 0)
      return rb::Status::fail(path +
                              ": cannot read the PNG: a Git LFS pointer, not the image (git lfs "
                              "pull fetches it)");
    return rb::Status::fail(path + ": cannot read the PNG: not a PNG file");
  }
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows;  // before setjmp: nothing with a destructor is made after it
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return rb::Status::fail(path + ": cannot start libpng");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return rb::Status::fail(path + ": cannot decode the PNG");
  }
  png_init_io(png, file.f);
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  png_textp text = nullptr;
  int texts = 0;
  image.drawn_by.clear();
  png_get_text(png, info, &text, &texts);
  for (int i = 0; i < texts; ++i)
    if (std::strcmp(text[i].key, "Software") == 0 && text[i].text) image.drawn_by = text[i].text;
  // Any PNG as 8-bit RGBA: palettes and grey expanded, 16 bits scaled, opaque alpha added.
  png_set_expand(png);
  png_set_scale_16(png);
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  image.width = static_cast<int>(png_get_image_width(png, info));
  image.height = static_cast<int>(png_get_image_height(png, info));
  image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
  rows.resize(image.height);
  for (int y = 0; y < image.height; ++y)
    rows[y] = &image.rgba[static_cast<std::size_t>(y) * image.width * 4];
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return {};
}

Comparison compareImages(const Image& a, const Image& b, int channel_tolerance) {
  Comparison c;
  c.same_size = a.width == b.width && a.height == b.height;
  if (!c.same_size) return c;
  c.pixels = static_cast<long long>(a.width) * a.height;
  c.box[0] = a.width;
  c.box[1] = a.height;
  // side[x]: the largest square of differing pixels whose bottom-right corner is (x, y), kept
  // for this row and the one above (the square at (x, y) is one more than the smallest of those
  // at its left, above and above-left).
  std::vector<int> above(static_cast<std::size_t>(a.width) + 1, 0), side(above.size(), 0);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * a.width + x) * 4;
      int delta = 0;
      for (int k = 0; k < 4; ++k) delta = std::max(delta, std::abs(a.rgba[i + k] - b.rgba[i + k]));
      c.max_channel_delta = std::max(c.max_channel_delta, delta);
      int& here = side[static_cast<std::size_t>(x) + 1];
      here = 0;
      if (delta > channel_tolerance) {
        ++c.differing;
        c.box[0] = std::min(c.box[0], x);
        c.box[1] = std::min(c.box[1], y);
        c.box[2] = std::max(c.box[2], x);
        c.box[3] = std::max(c.box[3], y);
        here = 1 + std::min({side[static_cast<std::size_t>(x)], above[static_cast<std::size_t>(x)],
                             above[static_cast<std::size_t>(x) + 1]});
        if (here > c.square) {
          c.square = here;
          c.square_at[0] = x - here + 1;
          c.square_at[1] = y - here + 1;
        }
      }
    }
    std::swap(above, side);
  }
  return c;
}

Image diffImage(const Image& a, const Image& b, int channel_tolerance) {
  Image out = a;
  if (a.width != b.width || a.height != b.height) return out;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int delta = 0;
    for (int k = 0; k < 4; ++k) delta = std::max(delta, std::abs(a.rgba[i + k] - b.rgba[i + k]));
    const unsigned char grey =
        static_cast<unsigned char>((a.rgba[i] + a.rgba[i + 1] + a.rgba[i + 2]) / 6 + 128);
    const bool differs = delta > channel_tolerance;
    out.rgba[i] = differs ? 255 : grey;
    out.rgba[i + 1] = differs ? 0 : grey;
    out.rgba[i + 2] = differs ? 255 : grey;
    out.rgba[i + 3] = 255;
  }
  return out;
}

// A fraction of the pixels alone lets a small thing changed whole pass (a 40×40 patch is 0.17 % of
// a 1280×720 frame, within 0.2 %): a square of differing pixels `square` a side differs too.
// Another CPU's rasteriser moves pixels on edges, in lines one or two pixels wide, which make no
// such square.
bool squareDiffers(const Comparison& c, const Tolerance& tolerance) {
  return tolerance.square > 0 && c.square >= tolerance.square;
}

bool matches(const Comparison& c, const Tolerance& tolerance) {
  return c.same_size && c.fraction() <= tolerance.pixels && !squareDiffers(c, tolerance);
}

}  // namespace render

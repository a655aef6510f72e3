// H.264 in MP4 through libavcodec / libavformat (docs/commands.md "rattleback render"): RGBA frames
// converted to yuv420p by render/yuv.hpp (here, or by the caller), BT.709 tagged, moov atom
// first (+faststart), a fixed thread count for repeatable bytes. Written under a temporary
// name and renamed into place by finish().
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "render/frame.hpp"
#include "render/yuv.hpp"
#include "util/result.hpp"

namespace render {

struct EncoderSettings {
  int width = 1280, height = 720;  ///< even numbers (yuv420p)
  int fps = 30;
  int crf = 20;  ///< x264 quality, 0–51 (lower is better)
  std::string preset = "veryfast";
  int threads = 2;  ///< fixed, so the same frames give the same bytes
};

class VideoEncoder {
 public:
  /// Opens the temporary output; an error line naming `path` when impossible.
  static rb::Result<std::unique_ptr<VideoEncoder>> open(const std::string& path,
                                                        const EncoderSettings& settings);
  ~VideoEncoder();  ///< without finish(): removes the temporary file

  /// Encodes one RGBA frame (rows top to bottom, the settings' size); an error line on failure.
  rb::Status add(const Image& frame);
  /// Encodes one frame already converted to yuv420p (render/yuv.hpp): the conversion can then
  /// run on another thread than the encoding.
  rb::Status add(const Yuv420Image& frame);
  /// Flushes the encoder, writes the index and renames the file into place: to the path it
  /// was opened with, or to `final_path` (in the same folder) when given.
  rb::Status finish(const std::string& final_path = "");
  long long frames() const;
  /// The file being written until finish() renames it into place.
  const std::string& temporaryPath() const;

 private:
  VideoEncoder();
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace render

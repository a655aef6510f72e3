// x264's presets (x264 --fullhelp): the names --preset takes, for the checks and --help alike.
// Header only, so that the command line lists them without linking libav.
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace media {

inline constexpr std::array<std::string_view, 10> kPresets = {
    "ultrafast", "superfast", "veryfast", "faster",   "fast",
    "medium",    "slow",      "slower",   "veryslow", "placebo"};

/// "ultrafast | superfast | …": for --help.
inline std::string presetNames() {
  std::string out;
  for (std::string_view p : kPresets) out.append(out.empty() ? "" : " | ").append(p);
  return out;
}

}  // namespace media

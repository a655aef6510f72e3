// Where an output file goes and how it is written, one rule for every writer (tables, PNGs,
// plots, videos): written under a temporary name beside the file it replaces (".NAME.part-PID":
// hidden, and not ending in the output's extension, so no `*.csv` or `*.mp4` glob picks it up)
// and renamed over it once whole. A symbolic link is written through: the file it leads to is
// replaced and the link stays (renaming over the link itself would turn it into a file, and
// `-o /dev/stdout` into a file named /dev/stdout). Devices, pipes and the process's own
// descriptors (/dev/stdout, /dev/full, /proc/self/fd/N) are written in place: they cannot be
// renamed over, and a program writing to them is expected to open them as they are.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "util/result.hpp"

namespace rb {

struct OutputPlace {
  std::string target;     ///< the file replaced: the path, or the file its links lead to
  std::string temporary;  ///< written first, then renamed over `target`; "" to write in place
};

inline OutputPlace outputPlace(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  auto device = [&ec](const fs::path& p) {
    const std::string s = p.string();
    return (s.starts_with("/dev/") || s.starts_with("/proc/")) && fs::exists(p, ec);
  };
  const fs::file_status status = fs::status(path, ec);  // through links
  if (device(path) ||
      (fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)))
    return {path, ""};
  // Follow the links one by one (a relative link is relative to its own folder), so that one
  // to a file not yet made leads to where that file will be.
  fs::path target = path;
  for (int hop = 0; hop < 40 && fs::is_symlink(fs::symlink_status(target, ec)); ++hop) {
    const fs::path next = fs::read_symlink(target, ec);
    if (ec) break;
    target = next.is_absolute() ? next : target.parent_path() / next;
    if (device(target)) return {path, ""};  // a link to /dev/stdout or /proc/self/fd/1
  }
  std::string name = ".";
  name += target.filename().string();
  name += ".part-" + std::to_string(::getpid());
  return {target.string(), (target.parent_path() / name).string()};
}

/// How the caller named the output, for the way out an error line suggests: "-o" on the command
/// line (the default), "--plot" for a plot, "to_csv" or "save" from Python. Per thread: a
/// writer reads it on the thread that asked for the file.
inline thread_local const char* output_named_by = "-o";
/// What the caller gives output_named_by, for the same way out: "a path in a folder" (a file's
/// path, the default), or "a folder" where it takes the folder itself (`report DIR`).
inline thread_local const char* output_named_as = "a path in a folder";

/// Sets output_named_by and output_named_as for as long as it lives (then puts back the ones
/// before).
class OutputNamedBy {
 public:
  explicit OutputNamedBy(const char* name, const char* as = "a path in a folder")
      : before_(output_named_by), before_as_(output_named_as) {
    output_named_by = name;
    output_named_as = as;
  }
  ~OutputNamedBy() {
    output_named_by = before_;
    output_named_as = before_as_;
  }
  OutputNamedBy(const OutputNamedBy&) = delete;
  OutputNamedBy& operator=(const OutputNamedBy&) = delete;

 private:
  const char* before_;
  const char* before_as_;
};

/// The one error line for an output file that cannot be made where it was asked for (every
/// writer: tables, PNGs, plots, videos): the path, the folder, the system's reason and the
/// way out, in the caller's terms (output_named_by, output_named_as).
inline std::string cannotWriteIn(const std::string& path, const std::string& reason) {
  const std::filesystem::path folder =
      std::filesystem::path(outputPlace(path).target).parent_path();
  return path + ": cannot write a file in " +
         (folder.empty() ? std::string("this folder") : folder.string()) + ": " + reason +
         " (give " + output_named_by + " " + output_named_as + " you can write)";
}
inline std::string cannotWriteIn(const std::string& path, int error) {
  return cannotWriteIn(path, std::strerror(error ? error : EACCES));
}

/// An output name whose extension says another format than the one written is refused:
/// "-o x.avi: writes MP4 video; give a name ending in .mp4", named as the caller names the
/// output (output_named_by: -o, --plot, --diff; render's output in Python). `base_allowed`: a
/// name with no extension is taken (render --both's base name).
inline Status checkExtension(const std::string& output, const std::string& wanted,
                             const std::string& format, bool base_allowed) {
  if (output.empty()) return {};
  // A folder of that name is refused here, before the work, as the tables' writer refuses it (a
  // still into a folder named x.png was drawn, then failed to be moved into place: exit 4 after the
  // work, for a mistake in the input).
  std::error_code ec;
  if (std::filesystem::is_directory(output, ec))
    return Status::fail(output + ": is a folder, not a file (give " + output_named_by +
                        " a file's name, e.g. one in that folder)");
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == wanted || (base_allowed && ext.empty())) return {};
  return Status::fail(std::string(output_named_by) + " " + output + ": writes " + format +
                      "; give a name ending in " + wanted);
}

/// A table or text output (simulate's CSV, analyze's text or JSON, a sweep's table) is taken under
/// most names, but not over one of the command's inputs (`simulate s.yaml -o s.yaml` had replaced
/// the scene with its telemetry) nor under a name that says a picture, a video or a scene (`sweep
/// -o s.png` wrote CSV as s.png): "-o s.png: writes a CSV table, not a .png file; give a name
/// ending in .csv". `format` as the message says it: "a CSV table", "the analysis".
inline Status checkDataOutput(const std::string& output, const std::string& format,
                              const std::string& wanted, const std::vector<std::string>& inputs) {
  if (output.empty() || output == "-") return {};
  std::error_code ec;
  const std::filesystem::path out = std::filesystem::weakly_canonical(output, ec);
  for (const std::string& input : inputs) {
    std::error_code ec2;
    if (!ec && !input.empty() && std::filesystem::exists(input, ec2) &&
        out == std::filesystem::weakly_canonical(input, ec2) && !ec2)
      return Status::fail(std::string(output_named_by) + " " + output +
                          ": is one of its own inputs, which it would replace with " + format +
                          "; give it a name of its own, ending in " + wanted);
  }
  std::string ext = std::filesystem::path(output).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  // (A mesh's names too: a table named hull.stl would replace the body a scene reads.)
  for (const char* other : {".yaml", ".yml", ".png", ".jpg", ".jpeg", ".svg", ".pdf", ".mp4",
                            ".html", ".stl", ".obj", ".ply"})
    if (ext == other && ext != wanted)
      return Status::fail(std::string(output_named_by) + " " + output + ": writes " + format +
                          ", not a " + ext + " file; give a name ending in " + wanted);
  return {};
}

}  // namespace rb

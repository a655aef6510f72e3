// Output files that appear whole or not at all: written under a temporary name beside the
// target (".NAME.part-PID": hidden, and not ending in the output's extension, so no `*.csv` or
// `*.mp4` glob picks it up) and renamed over it only once everything is written and flushed.
#pragma once

#include <fstream>
#include <string>

#include "util/result.hpp"

namespace app {

/// The temporary name beside `path` used while writing it.
std::string temporaryPath(const std::string& path);

/// Creates the folder `path` will be written into, when missing. The same rule for a default
/// output (out/…) and one given with -o; an error line naming the folder and the system's
/// reason when it cannot be made.
rb::Status makeParentFolder(const std::string& path);

/// Removes every temporary file registered and not yet committed; async-signal-safe, for
/// SIGINT/SIGTERM handlers (see app/interrupt).
void removeTemporaryFilesNow();
void registerTemporary(const std::string& temp);
void unregisterTemporary(const std::string& temp);

class AtomicOutput {
 public:
  /// Opens the temporary file; an error line naming `path` when that is impossible.
  static rb::Result<AtomicOutput> open(const std::string& path);
  AtomicOutput(AtomicOutput&&) noexcept;
  AtomicOutput& operator=(AtomicOutput&&) = delete;
  ~AtomicOutput();  ///< removes the temporary file unless committed

  std::ostream& stream() { return out_; }
  /// Flushes, closes and renames into place; an error line when any write failed.
  rb::Status commit();

 private:
  AtomicOutput(std::string path, std::string temp);
  std::string path_, temp_;
  std::ofstream out_;
  bool done_ = false;
};

}  // namespace app

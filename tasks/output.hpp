// Output files that appear whole or not at all: written under a temporary name beside the
// file they replace and renamed over it only once everything is written and flushed
// (util/output_place.hpp says where, for every writer).
#pragma once

#include <fstream>
#include <string>

#include "util/output_place.hpp"
#include "util/result.hpp"

namespace tasks {

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
  AtomicOutput(std::string path, rb::OutputPlace place);
  std::string path_;    ///< as given, for messages
  std::string target_;  ///< the file replaced (through links)
  std::string temp_;    ///< "" when written in place
  std::ofstream out_;
  bool done_ = false;
};

}  // namespace tasks

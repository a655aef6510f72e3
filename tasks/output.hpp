// Output files that appear whole or not at all: written under a temporary name beside the
// file they replace and renamed over it only once everything is written and flushed
// (util/output_place.hpp says where, for every writer).
#pragma once

#include <fstream>
#include <string>
#include <vector>

#include "util/output_place.hpp"
#include "util/result.hpp"

namespace tasks {

/// The folders a command made for its outputs, removed again when it ends if still empty
/// (deepest first): a command refused, or a run that stops, leaves no empty folder behind.
class MadeFolders {
 public:
  MadeFolders() = default;
  MadeFolders(const MadeFolders&) = delete;
  MadeFolders& operator=(const MadeFolders&) = delete;
  ~MadeFolders();
  void add(const std::string& folder) { made_.push_back(folder); }

 private:
  std::vector<std::string> made_;  ///< in the order made: each after the one holding it
};

/// Creates the folder `path` will be written into, when missing. The same rule for a default
/// output (out/…) and one given with -o; an error line naming the folder and the system's
/// reason when it cannot be made. The folders it made are added to `made`, when given.
rb::Status makeParentFolder(const std::string& path, MadeFolders* made = nullptr);

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
  const std::string& path() const { return path_; }  ///< as given
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

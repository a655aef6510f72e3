// Output files that appear whole or not at all: written under a temporary name beside the
// target and renamed over it only once everything is written and flushed.
#pragma once

#include <fstream>
#include <optional>
#include <string>
#include <variant>

namespace app {

class AtomicOutput {
 public:
  /// Opens the temporary file; an error line naming `path` when that is impossible.
  static std::variant<AtomicOutput, std::string> open(const std::string& path);
  AtomicOutput(AtomicOutput&&) noexcept;
  AtomicOutput& operator=(AtomicOutput&&) = delete;
  ~AtomicOutput();  ///< removes the temporary file unless committed

  std::ostream& stream() { return out_; }
  /// Flushes, closes and renames into place; an error line when any write failed.
  std::optional<std::string> commit();

 private:
  AtomicOutput(std::string path, std::string temp);
  std::string path_, temp_;
  std::ofstream out_;
  bool done_ = false;
};

}  // namespace app

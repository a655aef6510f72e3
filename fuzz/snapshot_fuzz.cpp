// libFuzzer target for the snapshot suite reader: any bytes must give either a suite or one
// non-empty line of error naming the file — never a crash, a hang or a sanitizer report. The
// reader reads no scene (the runner loads those), so any input is quick.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/snapshot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto suite = scene::parseSnapshotSuite(text, "fuzz/suite.yaml");
  if (!suite) {
    const std::string message = suite.error().text();
    if (message.empty() || message.find('\n') != std::string::npos ||
        !message.starts_with("fuzz/suite.yaml:"))
      __builtin_trap();
    return 0;
  }
  // A suite read has cases, each with a name that is a plain file name and a scene.
  if (suite->cases.empty()) __builtin_trap();
  for (const scene::SnapshotCase& c : suite->cases)
    if (c.name.empty() || c.name.find('/') != std::string::npos || c.scene.empty())
      __builtin_trap();
  return 0;
}

// Shared helpers of the rendering tests, which run the programs: a scratch folder per test and
// per OpenGL backend (CTest runs these tests once per backend, at the same time), and
// `rattleback ARGS` run from the source tree.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace render_support {

namespace fs = std::filesystem;

inline const fs::path kSource = RATTLEBACK_SOURCE_DIR;

/// The backend the program is run with: $RATTLEBACK_BACKEND, or auto.
inline std::string backendName() {
  const char* backend = std::getenv("RATTLEBACK_BACKEND");
  return backend && *backend ? backend : "auto";
}

/// A file in the running test's own scratch folder (removed first when it exists). The folder
/// is the process's own: two checkouts tested at once on one machine shared it, and one's
/// stills were removed under the other.
inline fs::path scratch(const std::string& name) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir =
      fs::path(testing::TempDir()) /
      (std::string("rattleback_render-") + backendName() + "-" + std::to_string(::getpid())) /
      (std::string(info->test_suite_name()) + "." + info->name());
  fs::create_directories(dir);
  fs::remove(dir / name);
  return dir / name;
}

/// Runs rattleback from the source tree (scene paths in the arguments are relative to it),
/// stderr into the scratch folder's stderr.txt; returns the exit status.
inline int rattleback(const std::string& args) {
  const std::string command = "cd " + kSource.string() + " && " + RATTLEBACK_BIN + " " + args +
                              " >/dev/null 2>" + scratch("stderr.txt").string();
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

}  // namespace render_support

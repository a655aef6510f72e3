#include "util/assets.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace rb {

std::string assetsDir() {
  if (const char* env = std::getenv("RATTLEBACK_ASSETS"); env && *env) return env;
  // The file this code was linked into: the program, or the Python package's module.
  std::error_code error;
  Dl_info info{};
  std::filesystem::path self;
  if (::dladdr(reinterpret_cast<void*>(&assetsDir), &info) != 0 && info.dli_fname &&
      std::strchr(info.dli_fname, '/'))
    self = std::filesystem::canonical(info.dli_fname, error);
  if (self.empty() || error) self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return RATTLEBACK_ASSETS_RELATIVE;
  const std::filesystem::path dir = self.parent_path();
  // The installed layout (bin/ → share/rattleback, relative so the prefix can move), the build
  // tree's copy in <build>/share/rattleback beside <build>/app, <build>/tests, …, and for the
  // Python package <build>/python/rattleback or <prefix>/lib/python3/dist-packages/rattleback.
  const std::filesystem::path candidates[] = {
      dir / RATTLEBACK_ASSETS_RELATIVE, dir / "../share/rattleback", dir / "../../share/rattleback",
      dir / "../../../../share/rattleback"};
  for (const auto& candidate : candidates)
    if (std::filesystem::is_directory(candidate / "shaders", error))
      return candidate.lexically_normal().string();
  return (dir / RATTLEBACK_ASSETS_RELATIVE).lexically_normal().string();
}

std::string docsDir() {
  const std::filesystem::path installed =
      (std::filesystem::path(assetsDir()) / "../doc/rattleback").lexically_normal();
  std::error_code error;
  return std::filesystem::is_regular_file(installed / "getting-started.md", error)
             ? installed.string()
             : std::string();
}

std::string docPage(const std::string& page) {
  const std::string installed = docsDir();
  return installed.empty() ? "docs/" + page : installed + "/" + page;
}

}  // namespace rb

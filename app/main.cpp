// rattleback: simulate a rattleback and report what it does. This program never loads the
// rendering libraries: for render, still, compare and snapshot it becomes rattleback-render (exec,
// same process and arguments), found beside it or in the installed libexec folder.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>

#include "app/cli.hpp"
#include "app/tell.hpp"

namespace {

std::filesystem::path renderProgram() {
  std::error_code error;
  const std::filesystem::path exe_dir =
      std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  // The build tree keeps both programs in one folder; an install puts the second in libexec.
  for (const auto& candidate :
       {exe_dir / "rattleback-render", exe_dir / RATTLEBACK_LIBEXEC_RELATIVE / "rattleback-render"})
    if (::access(candidate.c_str(), X_OK) == 0) return candidate.lexically_normal();
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  app::Cli cli(argc > 1 ? argv[1] : "");
  if (auto status = cli.parse(argc, argv)) return *status;
  if (!cli.chosen().draws) return app::runGuarded(cli);
  const std::filesystem::path program = renderProgram();
  if (program.empty()) {
    app::tell(app::Tone::Error, std::string("rattleback: ") + cli.chosen().name +
                                    " needs rattleback-render, which is neither beside this "
                                    "program nor in " RATTLEBACK_LIBEXEC_RELATIVE
                                    "; reinstall rattleback");
    return app::kMachine;
  }
  ::execv(program.c_str(), argv);
  app::tell(app::Tone::Error,
            "rattleback: cannot run " + program.string() + ": " + std::strerror(errno));
  return app::kMachine;
}

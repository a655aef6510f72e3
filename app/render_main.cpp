// rattleback-render: the commands of `rattleback` that draw (render, still, compare, snapshot), in
// a program of their own so that the others start without OSMesa, EGL or libav. `rattleback` runs
// it with its own arguments; run alone, it takes the same command line.
#include "app/cli.hpp"

int main(int argc, char** argv) {
  app::Cli cli(argc > 1 ? argv[1] : "");
  if (auto status = cli.parse(argc, argv)) return *status;
  return app::runGuarded(cli);
}

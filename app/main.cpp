// rattleback: simulate a rattleback and report what it does.
#include <CLI/CLI.hpp>
#include <iostream>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  CLI::App cli{"rattleback: simulate the rattleback (celt) that spins back"};
  cli.set_version_flag("--version", "rattleback 0.1.0");
  cli.require_subcommand(1);

  app::SimulateArgs sim_args;
  CLI::App* simulate = cli.add_subcommand(
      "simulate", "Run a scene; write CSV telemetry and print a summary");
  simulate->add_option("scene", sim_args.scene, "Scene file (YAML)")->required();
  simulate->add_option("-o,--output", sim_args.output,
                       "CSV telemetry file (default out/<scene>.csv)");
  simulate->add_option("--duration", sim_args.duration, "Simulated time, s (overrides the scene)");
  simulate->add_option("--dt", sim_args.dt, "Time step, s (overrides the scene)");
  simulate->add_option("--integrator", sim_args.integrator, "euler | symplectic | rk4");
  simulate->add_option("--rate", sim_args.rate,
                       "Telemetry samples per simulated second (default ~500)");
  simulate->add_flag("-q,--quiet", sim_args.quiet, "No summary and no progress bar");

  app::AnalyzeArgs analyze_args;
  CLI::App* analyze = cli.add_subcommand(
      "analyze", "Print the body's mass properties and what the contact allows");
  analyze->add_option("scene", analyze_args.scene, "Scene file (YAML)")->required();
  analyze->add_flag("--json", analyze_args.json, "Print JSON");

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "rattleback: " << e.what() << " (see --help)\n";
    return app::kBadInput;
  }
  if (*simulate) return app::simulateCommand(sim_args);
  if (*analyze) return app::analyzeCommand(analyze_args);
  return app::kBadInput;
}

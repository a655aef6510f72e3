// A mistyped command ("simulat") or option ("--fsp") named with the nearest one, instead of
// CLI11's "A subcommand is required" or "The following arguments were not expected".
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace app {

/// The line to print for a command-line error: when the first word is no command, it says so
/// and names the nearest one; when a word of a known command is none of its options ("--fsp"),
/// it names the nearest option; otherwise CLI11's message and a pointer to --help.
std::string explainParseError(const CLI::App& cli, int argc, char** argv, const std::string& what);

}  // namespace app

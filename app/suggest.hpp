// A mistyped command ("simulat") named with the nearest one, instead of CLI11's "A subcommand
// is required".
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace app {

/// Levenshtein distance between two words.
std::size_t editDistance(const std::string& a, const std::string& b);

/// The line to print for a command-line error: when the first word is no command, it says so
/// and names the nearest one; otherwise CLI11's message and a pointer to --help.
std::string explainParseError(const CLI::App& cli, int argc, char** argv, const std::string& what);

}  // namespace app

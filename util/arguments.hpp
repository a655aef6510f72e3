// How the front end that called the library names its arguments in a message: the command line
// by its options ("--crf: must be …"), Python by its keyword arguments ("argument crf: must be
// …"). A library message that names an argument asks here, so each front end says it in its own
// words (docs/commands.md "Messages"); a scene key is named as the key, the same everywhere.
#pragma once

#include <atomic>
#include <string>
#include <string_view>

namespace rb {

/// Option: the command line's ("--dt"); Keyword: Python's ("argument dt"); Key: a file's own key
/// where a command reads its arguments from a file (a snapshot suite's "backend egl").
enum class ArgumentStyle { Option, Keyword, Key };

/// Set once by the front end as it starts (the command line's is the default). Process-wide: a
/// process holds one front end, and its worker threads write its messages too.
inline std::atomic<ArgumentStyle> argument_style{ArgumentStyle::Option};

/// The argument `name` as the front end names it: "--dt", "argument dt" or "dt".
inline std::string argumentName(std::string_view name) {
  const ArgumentStyle style = argument_style.load(std::memory_order_relaxed);
  if (style == ArgumentStyle::Keyword) return "argument " + std::string(name);
  if (style == ArgumentStyle::Key) return std::string(name);
  return "--" + std::string(name);
}

/// The argument `name` given `value`: "--backend egl", "argument backend='egl'" or "backend egl".
inline std::string argumentGiven(std::string_view name, std::string_view value) {
  const ArgumentStyle style = argument_style.load(std::memory_order_relaxed);
  if (style == ArgumentStyle::Keyword)
    return "argument " + std::string(name) + "='" + std::string(value) + "'";
  if (style == ArgumentStyle::Key) return std::string(name) + " " + std::string(value);
  return "--" + std::string(name) + " " + std::string(value);
}

}  // namespace rb

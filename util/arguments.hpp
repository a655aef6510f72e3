// How the front end that called the library names its arguments in a message: the command line
// by its options ("--crf: must be …"), Python by its keyword arguments ("argument crf: must be
// …"). A library message that names an argument asks here, so each front end says it in its own
// words (docs/commands.md "Messages"); a scene key is named as the key, the same everywhere.
#pragma once

#include <atomic>
#include <string>
#include <string_view>

namespace rb {

enum class ArgumentStyle { Option, Keyword };

/// Set once by the front end as it starts (the command line's is the default). Process-wide: a
/// process holds one front end, and its worker threads write its messages too.
inline std::atomic<ArgumentStyle> argument_style{ArgumentStyle::Option};

/// The argument `name` as the front end names it: "--dt" or "argument dt".
inline std::string argumentName(std::string_view name) {
  if (argument_style.load(std::memory_order_relaxed) == ArgumentStyle::Keyword)
    return "argument " + std::string(name);
  return "--" + std::string(name);
}

/// The argument `name` given `value`: "--backend egl" or "argument backend='egl'".
inline std::string argumentGiven(std::string_view name, std::string_view value) {
  if (argument_style.load(std::memory_order_relaxed) == ArgumentStyle::Keyword)
    return "argument " + std::string(name) + "='" + std::string(value) + "'";
  return "--" + std::string(name) + " " + std::string(value);
}

}  // namespace rb

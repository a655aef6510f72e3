// A number as messages print it: %g, six significant digits ("1e+09", "0.0001"); a count with
// its noun.
#pragma once

#include <cstdio>
#include <string>

namespace rb {

inline std::string show(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

/// A count and its noun, singular for 1: counted(1, "run") is "1 run", counted(3, "run") "3
/// runs", counted(1, "switch", "switches") "1 switch".
inline std::string counted(long long n, const std::string& one, const std::string& many = "") {
  return std::to_string(n) + " " + (n == 1 ? one : many.empty() ? one + "s" : many);
}

}  // namespace rb

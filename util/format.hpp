// A number as messages print it: %g, six significant digits ("1e+09", "0.0001").
#pragma once

#include <cstdio>
#include <string>

namespace rb {

inline std::string show(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace rb

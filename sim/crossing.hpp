// The time at which a quantity crosses zero between two times where its signs differ: what
// the Rollout uses to place a spin reversal on the interpolant between steps.
#pragma once

#include <algorithm>
#include <cmath>

namespace sim {

/// The zero of f in [a, b], given fa = f(a) and fb = f(b) of opposite signs (or one of them
/// zero): regula falsi with the Illinois rule (the end kept twice in a row has its value
/// halved, so the bracket shrinks from both sides), to 1e-14 relative or 60 evaluations.
/// Exact, to rounding, for a linear f; superlinear for a smooth simple root.
template <typename F>
double zeroCrossing(F&& f, double a, double b, double fa, double fb) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  int side = 0;
  for (int i = 0; i < 60 && b - a > 1e-14 * std::max(1.0, std::abs(b)); ++i) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = f(c);
    if (fc * fb > 0) {
      b = c, fb = fc;
      if (side == -1) fa /= 2;
      side = -1;
    } else if (fc * fa > 0) {
      a = c, fa = fc;
      if (side == 1) fb /= 2;
      side = 1;
    } else {
      return c;
    }
  }
  return fa == fb ? a : (a * fb - b * fa) / (fb - fa);
}

}  // namespace sim

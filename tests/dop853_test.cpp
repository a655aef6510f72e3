// Dormand–Prince 8(5,3) (sim/dop853.hpp): its order on a problem with a known solution, the
// order of its interpolant, its error control, and the rattleback's reversal against dopri5.
#include "sim/dop853.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support.hpp"

using namespace testing_support;

namespace {

// y' = 1 + y², y(t) = tan(t): nonlinear, so that the order conditions of every tree count (a
// linear problem checks only one per order).
const auto kTangent = [](const std::array<double, 1>& y, std::array<double, 1>& dydt, double) {
  dydt[0] = 1 + y[0] * y[0];
};

// One step of h from t0 = 0.3 with a tolerance no step can fail: the step's error, and the
// interpolant's at the step's middle, against tan.
struct OneStep {
  double end, middle;
};
OneStep oneStep(double h) {
  const double t0 = 0.3;
  sim::Dop853<1> dop(1e6);
  dop.initialize(kTangent, {std::tan(t0)}, t0, h);
  dop.step(kTangent);
  EXPECT_EQ(dop.time(), t0 + h);  // taken as offered
  std::array<double, 1> mid;
  dop.at(kTangent, t0 + h / 2, mid);
  return {std::abs(dop.state()[0] - std::tan(t0 + h)), std::abs(mid[0] - std::tan(t0 + h / 2))};
}

// An eighth-order method errs by O(h⁹) in a step: halving h divides the error by 2⁹ = 512.
// Three halvings, each ratio held to within a factor of √2 of that (the next term of the
// error's series still shows at h = 0.4).
TEST(Dop853, StepErrorFallsAsTheNinthPowerOfTheStep) {
  for (double h : {0.4, 0.2}) {
    const OneStep a = oneStep(h), b = oneStep(h / 2);
    ASSERT_GT(b.end, 0) << "at rounding: the test would say nothing";
    EXPECT_GT(std::log2(a.end / b.end), 8.5) << "h " << h << ": " << a.end << " then " << b.end;
  }
}

// The continuous extension is of order 7: its error inside a step is O(h⁸), 256 a halving.
TEST(Dop853, InterpolantErrorFallsAsTheEighthPowerOfTheStep) {
  for (double h : {0.4, 0.2}) {
    const OneStep a = oneStep(h), b = oneStep(h / 2);
    ASSERT_GT(b.middle, 0);
    EXPECT_GT(std::log2(a.middle / b.middle), 7.5)
        << "h " << h << ": " << a.middle << " then " << b.middle;
  }
}

// Error control: tan over 0 … 1.5 (where it reaches 14 and steepens), the global error within
// a few hundred tolerances of the solution's size at each tolerance (errors of the steps add,
// and grow with the solution), and smaller as the tolerance is; a tighter tolerance costs
// evaluations as tol^(−1/8), far less than dopri5's tol^(−1/5).
TEST(Dop853, ErrorControlHoldsTheSolutionToTheTolerance) {
  double last_error = 1;
  long last_evaluations = 0;
  for (double tolerance : {1e-6, 1e-9, 1e-12}) {
    sim::Dop853<1> dop(tolerance);
    dop.initialize(kTangent, {0.0}, 0, 1e-3);
    while (dop.time() < 1.5) dop.step(kTangent);
    std::array<double, 1> y;
    dop.at(kTangent, 1.5, y);
    const double error = std::abs(y[0] - std::tan(1.5)) / std::tan(1.5);
    EXPECT_LT(error, 300 * tolerance) << tolerance;
    EXPECT_LT(error, last_error) << tolerance;
    if (last_evaluations) {
      EXPECT_LT(dop.evaluations(), 3 * last_evaluations) << tolerance;  // 1000^(1/8) = 2.4
    }
    last_error = error;
    last_evaluations = dop.evaluations();
  }
}

// The rattleback under rolling, spun the reversing way: its first reversal and the state at
// 4 s by DOP853 and by dopri5, both at tolerance 1e-11, agree to what either method's own
// error is there (dopri5 at 1e-11 differs from 1e-12 by about 1e-7 s), and DOP853 does it in
// fewer evaluations.
TEST(Dop853, AgreesWithDopri5OnTheRattlebackAtTightTolerance) {
  std::string text = kRolling;
  const std::string fixed = "simulation: {integrator: rk4, dt: 1.0e-3, duration: 3.0}";
  text.replace(text.find(fixed), fixed.size(), "simulation: {tolerance: 1.0e-11, duration: 4.0}");
  sim::SceneSpec spec = parse(text);
  spec.simulation.integrator = "dopri5";
  const Recorded dopri5 = record(build(spec), 0.5);
  spec.simulation.integrator = "dop853";
  const Recorded dop853 = record(build(spec), 0.5);
  ASSERT_TRUE(dopri5.summary.first_reversal_s.has_value());
  ASSERT_TRUE(dop853.summary.first_reversal_s.has_value());
  EXPECT_NEAR(*dop853.summary.first_reversal_s, *dopri5.summary.first_reversal_s, 1e-6);
  ASSERT_EQ(dop853.samples.size(), dopri5.samples.size());
  for (std::size_t i = 0; i < dopri5.samples.size(); ++i) {
    EXPECT_NEAR(dop853.samples[i].spin, dopri5.samples[i].spin, 1e-6) << dopri5.samples[i].t;
    EXPECT_NEAR(dop853.samples[i].energy, dopri5.samples[i].energy, 1e-9) << dopri5.samples[i].t;
  }
  EXPECT_LT(dop853.summary.evaluations, dopri5.summary.evaluations / 2);
}

}  // namespace

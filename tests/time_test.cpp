// Time a user chooses (issue "Time a user chooses"): samples and frames at exact times whatever
// the step, the interpolant between steps and its order, adaptive steps with a tolerance, the
// reversal detector, and a body built once and shared by cheap runs.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "kane_levinson.hpp"
#include "media/spin_history.hpp"
#include "sim/crossing.hpp"
#include "support.hpp"

using namespace testing_support;

namespace {

/// Kane & Levinson's ellipsoid (scenes/kane-levinson.yaml, without air drag) for 60 s.
sim::SceneSpec kaneLevinsonSixtySeconds() {
  return kaneLevinson({{"contact.air_drag", "0.0"}, {"simulation.duration", "60.0"}});
}

sim::Model withStep(sim::SceneSpec spec, const std::string& integrator, double dt) {
  spec.simulation.integrator = integrator;
  spec.simulation.dt = dt;
  spec.simulation.tolerance = sim::kUnset;
  return build(spec);
}

sim::Model withTolerance(sim::SceneSpec spec, double tolerance) {
  spec.simulation.integrator = "dopri5";
  spec.simulation.dt = sim::kUnset;
  spec.simulation.tolerance = tolerance;
  return build(spec);
}

sim::State stateAt(const sim::Model& model, double t) {
  sim::Rollout rollout(model);
  EXPECT_TRUE(rollout.advanceTo(t));
  return rollout.stateAt(t);
}

// Distance between two poses: CM (m, scaled by the body's 0.1 m size) and orientation (the
// quaternion's chord, dimensionless).
double poseDistance(const sim::State& a, const sim::State& b) {
  const double dq =
      std::min((a.q.coeffs() - b.q.coeffs()).norm(), (a.q.coeffs() + b.q.coeffs()).norm());
  return (a.x_world - b.x_world).norm() / 0.1 + dq;
}

}  // namespace

// Sample times are k / rate exactly, whatever the step: 3000 Hz with a 1 ms step (three
// samples a step) and 30 Hz with a step that divides no frame (1e-4 · 1/30 is 333.3 steps).
TEST(Time, SamplesFallAtExactTimesWhateverTheStep) {
  for (auto [rate, dt] : {std::pair{3000.0, 1e-3}, std::pair{30.0, 1e-4}, std::pair{7.0, 3e-4}}) {
    sim::SceneSpec spec = parse(kRolling);
    spec.simulation.duration = 0.5;
    const sim::Model model = withStep(spec, "rk4", dt);
    std::vector<double> times;
    sim::Rollout rollout(model);
    sim::sampleRun(rollout, rate, [&](const sim::Telemetry& t) { times.push_back(t.t); });
    ASSERT_FALSE(times.empty());
    const auto whole = static_cast<std::size_t>(std::floor(0.5 * rate + 1e-9)) + 1;
    for (std::size_t k = 0; k < whole && k < times.size(); ++k)
      EXPECT_EQ(times[k], static_cast<double>(k) / rate) << "rate " << rate << " sample " << k;
    // And the end of the run, when it is not one of them.
    EXPECT_DOUBLE_EQ(times.back(), 0.5);
    EXPECT_EQ(times.size(), whole + (std::abs((whole - 1) / rate - 0.5) > 1e-12 ? 1 : 0));
  }
}

// Between steps the state is a cubic Hermite interpolant with the rates at both ends, so its
// error is O(h⁴), the order of rk4 itself: the pose at a time between steps, against a fine
// reference, falls ~16× per halving of the step (measured 18.8× and 17.4×; we ask > 10×,
// which a second-order rule such as slerp with a linear CM, 4× per halving, cannot give).
TEST(Time, ThePoseBetweenStepsConvergesAtFourthOrder) {
  const sim::SceneSpec spec = parse(kRolling);
  const double t = 1.2345678;  // on no step of any ladder below
  const sim::State reference = stateAt(withStep(spec, "rk4", 1e-3 / 64), t);
  std::vector<double> errors;
  for (double h : {8e-3, 4e-3, 2e-3})
    errors.push_back(poseDistance(stateAt(withStep(spec, "rk4", h), t), reference));
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    EXPECT_GT(errors[i] / errors[i + 1], 10.0) << "h = " << 8e-3 / (1 << i) << ": " << errors[i];
  }
  // And at a time that is a step of both runs, the interpolant is not used at all: the state
  // is the step's own.
  const sim::Model model = withStep(spec, "rk4", 1e-3);
  sim::Rollout a(model);
  ASSERT_TRUE(a.advanceTo(0.5));
  EXPECT_EQ(a.stateAt(0.5).q.coeffs(), a.current().q.coeffs());
}

// The interpolated pose equals the pose of a run whose step lands exactly on that time, to the
// integrators' error: both are rk4 at about 1 ms, whose own pose error is ~1e-9 here
// (measured difference 2.1e-10; we allow 1e-8).
TEST(Time, APoseBetweenStepsMatchesARunThatStepsOntoIt) {
  const sim::SceneSpec spec = parse(kRolling);
  const double t = 1.0 + 1e-3 / 3;  // a third of the way into a 1 ms step
  const sim::State between = stateAt(withStep(spec, "rk4", 1e-3), t);
  const sim::State landing = stateAt(withStep(spec, "rk4", t / 1000), t);  // 1000 steps onto t
  EXPECT_LT(poseDistance(between, landing), 1e-8);
}

// The reversal time is the zero crossing of n found on the states between steps: rk4 reversal
// times at dt and dt/2 agree to far less than dt (1 ms): measured 5.0 µs at 2 ms vs 1 ms; we
// allow 50 µs, 1/20 of the finer step. (A detector that reported the step after the crossing
// would be off by up to a whole step.)
TEST(Time, ReversalTimesAgreeToFarLessThanTheStep) {
  const sim::SceneSpec spec = parse(kRolling);
  const auto coarse = runFrom(withStep(spec, "rk4", 2e-3), sim::initialState(build(spec)), 0.1,
                              [](const sim::Telemetry&) {});
  const auto fine = runFrom(withStep(spec, "rk4", 1e-3), sim::initialState(build(spec)), 0.1,
                            [](const sim::Telemetry&) {});
  ASSERT_TRUE(coarse.first_reversal_s && fine.first_reversal_s);
  EXPECT_NEAR(*coarse.first_reversal_s, *fine.first_reversal_s, 5e-5);
}

// Adaptive steps (dopri5): the reversal time's error falls as the tolerance does, and at a
// tight tolerance it is the fixed-step answer. Errors against rk4 at 0.125 ms (whose own
// error is ~1e-10 s): measured 2.7e-3, 3.8e-5, 5.3e-7, 5.6e-9 s at 1e-4, 1e-6, 1e-8, 1e-10
// (156, 378, 913, 2283 steps). We ask each to fall below the one before (20% slack) and the
// tightest to be within 1e-7 s.
TEST(Adaptive, TheReversalErrorFallsWithTheTolerance) {
  const sim::SceneSpec spec = parse(kRolling);
  sim::Rollout reference_run(withStep(spec, "rk4", 1.25e-4));
  reference_run.advanceTo(3.0);
  ASSERT_TRUE(reference_run.summary().first_reversal_s);
  const double reference = *reference_run.summary().first_reversal_s;
  std::vector<double> errors;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    sim::Rollout run(withTolerance(spec, tol));
    run.advanceTo(3.0);
    ASSERT_TRUE(run.summary().first_reversal_s) << tol;
    errors.push_back(std::abs(*run.summary().first_reversal_s - reference));
    EXPECT_GT(run.summary().steps, 0);
    EXPECT_GE(run.summary().rejected, 0);
    // Every try costs six evaluations (FSAL), the start one: the counts add up.
    EXPECT_EQ((run.summary().evaluations - 1) % 6, 0) << run.summary().evaluations;
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i)
    EXPECT_LT(errors[i + 1], 1.2 * errors[i] + 1e-9) << "tolerance step " << i;
  EXPECT_LT(errors.back(), 1e-7);
}

// Under rolling the adaptive stepper integrates only the CM's place on the floor, the attitude
// and ω: the height and velocity follow from the constraint. The place must still move as the
// no-slip constraint says. The path's slope, a central difference of samples 10 µs apart
// (its own error (10 µs)² |x⃛| / 6 with |x⃛| ≈ ω² |v| ≈ 30 m/s³, about 5e-10 m/s), is the
// velocity −ω × r within 1e-8 m/s against speeds up to 0.03 m/s (measured 7.7e-10 m/s); and
// after 3 s the place agrees with rk4 at 0.125 ms, which integrates ẋ = −ω × r on the whole
// state, within 1e-8 m (measured 1.7e-10 m; it is 0.7 mm from the start).
TEST(Adaptive, ARollingBodysPlaceOnTheFloorMovesWithoutSlipping) {
  const sim::SceneSpec spec = parse(kRolling);
  sim::Rollout run(withTolerance(spec, 1e-10));
  double worst = 0, speed = 0;
  for (double t : {0.5, 1.0, 1.5, 2.0, 2.5}) {
    ASSERT_TRUE(run.advanceTo(t + 1e-5));
    const sim::State s = run.stateAt(t);
    const Eigen::Vector3d slope =
        (run.stateAt(t + 1e-5).x_world - run.stateAt(t - 1e-5).x_world) / 2e-5;
    worst = std::max(worst, (slope.head<2>() - s.v_world.head<2>()).norm());
    speed = std::max(speed, s.v_world.head<2>().norm());
  }
  EXPECT_LT(worst, 1e-8);
  EXPECT_GT(speed, 1e-3);
  ASSERT_TRUE(run.advanceTo(3.0));
  const sim::State fixed = stateAt(withStep(spec, "rk4", 1.25e-4), 3.0);
  const sim::State adaptive = run.stateAt(3.0);
  EXPECT_LT((adaptive.x_world - fixed.x_world).norm(), 1e-8);
}

// Rolling conserves energy exactly; an adaptive run's drift stays within its error budget:
// each accepted step errs by at most `tolerance` relative to the body's scales, so over N steps
// the energy (a smooth function of the state, of order one in those scales) can drift by at
// most about N · tolerance. Measured over 60 s: 2.2e-6 at 1e-8 (34947 steps, budget 3.5e-4)
// and 2.1e-8 at 1e-10 (86196 steps, budget 8.6e-6).
TEST(Adaptive, RollingEnergyOverSixtySecondsStaysWithinTheToleranceBudget) {
  const sim::SceneSpec spec = kaneLevinsonSixtySeconds();
  for (double tol : {1e-8, 1e-10}) {
    const sim::Model model = withTolerance(spec, tol);
    double worst = 0, e0 = 0;
    const sim::RunSummary summary =
        runFrom(model, sim::initialState(model), 0.05, [&](const sim::Telemetry& t) {
          if (t.t == 0) e0 = t.energy;
          worst = std::max(worst, std::abs(t.energy - e0) / e0);
        });
    EXPECT_FALSE(summary.divergence);
    EXPECT_LT(worst, static_cast<double>(summary.steps) * tol) << "tolerance " << tol;
  }
}

// Kane & Levinson's body without air drag keeps reversing: four reversals in 60 s, as the
// no-slip studies report (Kane & Levinson 1982 show repeated reversals; Moffatt & Tokieda 2008
// an infinite succession in the reduced model). Two independent integrations, rk4 at a fixed
// 0.1 ms and dopri5 at tolerance 1e-12, agree on every reversal time within 0.2 ms (measured:
// the first two to 1e-7 s, the third and fourth to 2.0e-5 and 1.9e-5 s: near the third the
// spin lingers close to zero and small errors move it; runs at tolerance 1e-9 already differ
// there by 3 ms).
TEST(Adaptive, KaneLevinsonWithoutDragReversesFourTimesInSixtySeconds) {
  const sim::SceneSpec spec = kaneLevinsonSixtySeconds();
  sim::Rollout fixed(withStep(spec, "rk4", 1e-4));
  sim::Rollout adaptive(withTolerance(spec, 1e-12));
  fixed.advanceTo(60);
  adaptive.advanceTo(60);
  const auto& a = fixed.summary().reversals;
  const auto& b = adaptive.summary().reversals;
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(b.size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(a[i], b[i], 2e-4) << "reversal " << i;
}

// The same 60 s with fixed steps (scenes/kane-levinson-long.yaml): rk4 at 0.2, 0.1, 0.05 ms.
// Energy: nothing dissipates, so the drift is the integrator's own; rk4's local error is fifth
// order, and over a run of a fixed length the drift falls at least 16× per halving (fourth
// order; measured 31.7× and 31.6×: 1.9e-7, 6.1e-9, 1.9e-10 relative). At 0.1 ms it must stay
// below 1e-7. Reversals: four at every step, each the same within 1e-5 s (measured: ≤ 2.1e-6 s
// on the fourth, 1e-9 s on the first).
TEST(LongRuns, FixedStepsKeepTheEnergyAndAgreeOnEveryReversal) {
  const sim::SceneSpec spec = kaneLevinsonSixtySeconds();
  std::vector<double> drift;
  std::vector<std::vector<double>> reversals;
  for (double dt : {2e-4, 1e-4, 5e-5}) {
    sim::Rollout run(withStep(spec, "rk4", dt));
    const double e0 = run.sampleAt(0).energy;
    ASSERT_TRUE(run.advanceTo(60));
    drift.push_back(std::abs(run.sampleAt(60).energy / e0 - 1));
    reversals.push_back(run.summary().reversals);
    ASSERT_EQ(reversals.back().size(), 4u) << "dt " << dt;
  }
  EXPECT_LT(drift[1], 1e-7);
  EXPECT_GT(drift[0] / drift[1], 16);
  EXPECT_GT(drift[1] / drift[2], 16);
  for (std::size_t run = 1; run < 3; ++run)
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_NEAR(reversals[run][i], reversals[0][i], 1e-5) << "reversal " << i << ", run " << run;
}

// A body built once, runs that are cheap: copying a Model shares the body (no points are
// copied), and two runs of one body with opposite spins are mirror images in n.
TEST(SharedBody, RunsShareOneBodyAndCopyingAModelCopiesNoPoints) {
  const sim::Model model = build(parse(kRolling));
  sim::Model other = model;
  other.initial.spin = -model.initial.spin;
  EXPECT_EQ(other.body.get(), model.body.get());
  EXPECT_EQ(model.body.use_count(), 2);
  sim::Rollout a(model), b(other);
  EXPECT_NE(a.current().L_world.z(), b.current().L_world.z());
}

// A stop request ends a run at its next step, and says so.
TEST(Rollout, AStopRequestEndsTheRun) {
  const sim::Model model = build(parse(kRolling));
  sim::Rollout run(model);
  ASSERT_TRUE(run.advanceTo(0.5));
  run.requestStop();
  EXPECT_FALSE(run.advanceTo(1.0));
  EXPECT_TRUE(run.summary().stop_requested);
  EXPECT_LT(run.current().t, 0.5 + 2e-3);
  std::stop_source source;
  sim::Rollout watched(model);
  watched.stopWith(source.get_token());
  source.request_stop();
  EXPECT_FALSE(watched.advanceTo(0.1));
}

// Sampling has no side effects: samples at times of the last step, in any order
// and as often as wished, give the same telemetry, and the summary's `last` is the time that
// advanceTo asked for, sampled or not. Exact equality: the same state, the same arithmetic.
TEST(Rollout, SamplingChangesNothing) {
  sim::SceneSpec spec = parse(kRolling);
  spec.simulation.dt = 0.01;  // steps long enough to sample inside
  const sim::Model model = build(spec);
  sim::Rollout run(model), twin(model);
  ASSERT_TRUE(run.advanceTo(0.505));
  ASSERT_TRUE(twin.advanceTo(0.505));
  const double t0 = run.current().t - 0.01;
  const sim::Telemetry late = run.sampleAt(0.505), early = run.sampleAt(t0 + 0.001);
  EXPECT_EQ(run.sampleAt(0.505).spin, late.spin);
  EXPECT_EQ(run.sampleAt(t0 + 0.001).energy, early.energy);
  EXPECT_EQ(run.summary().last.t, 0.505);
  EXPECT_EQ(run.summary().last.spin, late.spin);
  // The sampled run and the twin never sampled go on alike.
  ASSERT_TRUE(run.advanceTo(1.0));
  ASSERT_TRUE(twin.advanceTo(1.0));
  EXPECT_EQ(run.current().L_world, twin.current().L_world);
  EXPECT_EQ(run.summary().last.spin, twin.summary().last.spin);
  EXPECT_EQ(twin.summary().last.t, 1.0);
}

// The reversal detector's root finder on signals whose zero is known: exact (to rounding) for
// a straight line, as regula falsi's first secant is the line itself; to 1e-14 s for smooth
// simple roots (the sine's π, the exponential's ln 2, a cubic's 0.3 far off the bracket's
// middle); and few evaluations: Illinois converges superlinearly (≈1.44 per step, Dowell &
// Jarratt 1971), so 60 is a generous cap that a slow, linearly converging method would hit.
TEST(Reversal, TheCrossingIsExactForKnownSignals) {
  int calls = 0;
  auto counted = [&](auto f) {
    return [&calls, f](double t) {
      ++calls;
      return f(t);
    };
  };
  auto line = [](double t) { return -4.0 * (t - 2.3); };
  EXPECT_NEAR(sim::zeroCrossing(counted(line), 2.0, 2.5, line(2.0), line(2.5)), 2.3, 1e-15);
  EXPECT_LE(calls, 2);

  calls = 0;
  auto sine = [](double t) { return std::sin(t); };
  EXPECT_NEAR(sim::zeroCrossing(counted(sine), 3.0, 3.4, sine(3.0), sine(3.4)), M_PI, 1e-14);
  EXPECT_LE(calls, 12);

  calls = 0;
  auto exponential = [](double t) { return std::exp(t) - 2.0; };
  EXPECT_NEAR(sim::zeroCrossing(counted(exponential), 0.0, 1.0, exponential(0.0), exponential(1.0)),
              std::log(2.0), 1e-14);
  EXPECT_LE(calls, 15);

  calls = 0;
  auto cubic = [](double t) { return (t - 0.3) * (t * t + 1.0); };
  EXPECT_NEAR(sim::zeroCrossing(counted(cubic), 0.0, 5.0, cubic(0.0), cubic(5.0)), 0.3, 1e-14);
  EXPECT_LE(calls, 30);

  // A zero at an end is that end.
  EXPECT_EQ(sim::zeroCrossing(sine, 0.0, 1.0, 0.0, sine(1.0)), 0.0);
}

// The inset's spin so far (media::SpinHistory): for the default body over 3 s in a 320-wide
// image (96 columns of 31.25 ms, sampled every 4.46 ms), every sample lies within its column's
// kept extremes, the kept points are the run's own spin at their times, in time order, at
// most two a column; and the history built frame by frame (render) equals the one built in
// one go (still) at the same time.
TEST(SpinHistory, KeepsEachColumnsExtremesAndIsTheSameFrameByFrame) {
  const sim::Model model = build(parse(kRolling));
  const double drawn = 2.5;
  sim::Rollout whole(model);
  media::SpinHistory at_once(model.duration, 320);
  ASSERT_TRUE(at_once.advanceTo(whole, drawn));
  ASSERT_TRUE(whole.advanceTo(drawn));
  const sim::Telemetry now = whole.sampleAt(drawn);
  const auto span = at_once.with(now);
  const std::vector<std::array<float, 2>> kept(span.begin(), span.end());

  sim::Rollout framed(model);
  media::SpinHistory by_frame(model.duration, 320);
  for (int k = 0; k / 30.0 < drawn; ++k) {  // 30 fps
    ASSERT_TRUE(by_frame.advanceTo(framed, k / 30.0));
    ASSERT_TRUE(framed.advanceTo(k / 30.0));
    by_frame.with(framed.sampleAt(k / 30.0));
  }
  ASSERT_TRUE(by_frame.advanceTo(framed, drawn));
  ASSERT_TRUE(framed.advanceTo(drawn));
  const auto again = by_frame.with(framed.sampleAt(drawn));
  EXPECT_TRUE(std::equal(kept.begin(), kept.end(), again.begin(), again.end()));

  ASSERT_GE(kept.size(), 2u);
  EXPECT_EQ(kept.back()[0], static_cast<float>(drawn));
  EXPECT_LE(kept.size(), 2u * 96 * drawn / 3 + 3);
  for (std::size_t i = 1; i < kept.size(); ++i) EXPECT_LT(kept[i - 1][0], kept[i][0]) << i;

  // Every 5 ms sample of the spin from a run of its own, against its column's kept points.
  const double column = 3.0 / 96, step = column / 7;  // ceil(31.25 / 5) = 7 samples a column
  sim::Rollout reference(model);
  for (int j = 0; j * step < drawn; ++j) {
    const double t = j * step;
    ASSERT_TRUE(reference.advanceTo(t));
    const float spin = static_cast<float>(reference.sampleAt(t).spin);
    const int c = j / 7;
    float low = INFINITY, high = -INFINITY;
    // Column c holds the kept points of [c, c + 1) columns; their times are floats, 0.25 µs
    // apart near 3 s, so a 1 µs margin puts a point on a boundary in the column it opened.
    for (const auto& p : kept)
      if (p[0] >= c * column - 1e-6 && p[0] < (c + 1) * column - 1e-6) {
        low = std::min(low, p[1]);
        high = std::max(high, p[1]);
      }
    EXPECT_GE(spin, low) << "t " << t;
    EXPECT_LE(spin, high) << "t " << t;
  }
  // The kept points are the run's spin at their times (the drawn time's too), within what
  // their float storage allows: 5 rad/s to 7 digits, and a time rounded to float (60 ns) at a
  // spin changing by at most about 20 rad/s².
  sim::Rollout check(model);
  for (const auto& p : kept) {
    ASSERT_TRUE(check.advanceTo(p[0]));
    EXPECT_NEAR(check.sampleAt(p[0]).spin, p[1], 1e-5) << "t " << p[0];
  }
}

// A Rollout driven a step at a time, copied, and set to a new state mid-run (what Python's
// rattleback.Simulation does): the same steps as advanceTo, copies that go on alone, and states
// put back on the rolling constraint.
#include <gtest/gtest.h>

#include <cmath>

#include "support.hpp"

using namespace testing_support;

namespace {

void expectSameState(const sim::State& a, const sim::State& b) {
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.x_world, b.x_world);
  EXPECT_EQ(a.v_world, b.v_world);
  EXPECT_EQ(a.q.coeffs(), b.q.coeffs());
  EXPECT_EQ(a.L_world, b.L_world);
}

}  // namespace

// One step at a time is advanceTo's own loop: the same states to the bit, with fixed steps and
// adaptive ones, and the same reversal.
TEST(RolloutControl, SteppingOneAtATimeTakesTheStepsOfAdvanceTo) {
  for (const bool adaptive : {false, true}) {
    const sim::Model model = rollingModel(adaptive);
    sim::Rollout whole(model), stepped(model);
    ASSERT_TRUE(whole.advanceTo(2.9));
    for (std::int64_t n = 1; stepped.current().t < whole.current().t; ++n) {
      ASSERT_TRUE(stepped.advanceOneStep());
      ASSERT_EQ(stepped.current().step, n) << "one step at a time";
    }
    expectSameState(stepped.current(), whole.current());
    EXPECT_EQ(stepped.reversals(), whole.reversals());
    ASSERT_EQ(whole.reversals().size(), 1u)
        << "the default body reverses at about 2.3 s, confirmed 0.2 s later";
  }
}

// A copy goes on alone: advanced to where the original went it takes the same steps (its
// adaptive stepper copied, step size and all), and neither a step nor a new state of one
// touches the other.
TEST(RolloutControl, ACopyGoesOnAloneFromWhereItWas) {
  for (const bool adaptive : {false, true}) {
    sim::Rollout original(rollingModel(adaptive));
    ASSERT_TRUE(original.advanceTo(1.0));
    sim::Rollout copy(original);
    const sim::State at_copy = copy.current();
    ASSERT_TRUE(original.advanceTo(2.0));
    expectSameState(copy.current(), at_copy);
    ASSERT_TRUE(copy.advanceTo(2.0));
    expectSameState(copy.current(), original.current());
    const sim::State at_original = original.current();
    sim::State struck = copy.current();
    struck.L_world *= 2;
    copy.setState(struck);
    ASSERT_TRUE(copy.advanceOneStep());
    EXPECT_NE(copy.current().L_world, at_original.L_world);
    expectSameState(original.current(), at_original);
  }
}

// Under rolling a state set mid-run is put back on the constraint: the contact point on the
// floor (z_cm = −r_z) and not sliding (v = −ω × r), whatever height and velocity it had; the
// time and step stay the run's. A run stopped by a stop request takes no more steps.
TEST(RolloutControl, AStateSetUnderRollingIsPutBackOnTheConstraint) {
  const sim::Model model = rollingModel(false);
  sim::Rollout run(model);
  ASSERT_TRUE(run.advanceTo(0.5));
  sim::State s = run.current();
  s.x_world.z() += 0.01;
  s.v_world = Eigen::Vector3d(1, 2, 3);
  s.t = 99;
  run.setState(s);
  const sim::State& now = run.current();
  EXPECT_EQ(now.t, 0.5);
  const Eigen::Matrix3d R = now.q.toRotationMatrix();
  const Eigen::Vector3d r =
      R * sim::lowestSurfacePoint(*model.body, R.transpose() * -Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d w = sim::angularVelocity(model, now);
  // Rounding of a few products of numbers of the body's size (cm, rad/s).
  EXPECT_NEAR(now.x_world.z(), -r.z(), 1e-15);
  EXPECT_LT((now.v_world + w.cross(r)).norm(), 1e-15);
  run.requestStop();
  EXPECT_FALSE(run.advanceOneStep());
  EXPECT_EQ(run.current().t, 0.5);
}

// Stepped only until the reversal rule confirms the first reversal (what a sweep listing only
// first_reversal_s does), a run gives the whole run's first reversal to the bit: it took the
// same steps (the steps do not depend on how far the run is asked to go: fixed ones are k·dt,
// adaptive ones the error control's), fed the same rule, and a counted reversal is never
// undone (sim/reversals.hpp). It stops at the step that confirms it: at least the hold time
// after the crossing, and well before the end (the default body reverses at about 2.3 s).
TEST(RolloutControl, StoppedOnceItsReversalIsConfirmedARunGivesTheWholeRunsFirstReversal) {
  for (const bool adaptive : {false, true}) {
    sim::SceneSpec spec = parse(kRolling);
    spec.simulation.duration = 8.0;  // long enough for a second reversal to matter, had it one
    if (adaptive) {
      spec.simulation.integrator = "dopri5";
      spec.simulation.dt = sim::kUnset;
      spec.simulation.tolerance = 1e-8;
    }
    const sim::Model model = build(spec);
    sim::Rollout whole(model), early(model);
    ASSERT_TRUE(whole.advanceTo(whole.endTime()));
    ASSERT_TRUE(early.advanceToReversal(early.endTime()));
    ASSERT_FALSE(whole.reversals().empty());
    ASSERT_EQ(early.reversals().size(), 1u) << "adaptive " << adaptive;
    EXPECT_EQ(early.reversals().front(), whole.reversals().front()) << "adaptive " << adaptive;
    EXPECT_GE(early.current().t - early.reversals().front(), sim::ReversalDetector::kHoldTime);
    EXPECT_LT(early.current().t, 3.5) << "stopped at the confirmation, not at the end";
    // The step before the stop had not confirmed it: stepped on from there, the rule counts
    // nothing new at the previous step's end.
    sim::Rollout before(model);
    ASSERT_TRUE(before.advanceTo(early.previousTime()));
    EXPECT_TRUE(before.reversals().empty()) << "adaptive " << adaptive;
  }
}

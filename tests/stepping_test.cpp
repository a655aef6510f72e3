// The steps of a run on their own (sim/stepping.hpp), driven without a Rollout: fixed steps are
// the method's own, a copy goes on alone, and a restart starts the adaptive stepper afresh and
// keeps its counts.
#include "sim/stepping.hpp"

#include <gtest/gtest.h>

#include "support.hpp"

using namespace testing_support;

namespace {

// The same motion to the bit: time, position, velocity, orientation and angular momentum (the
// step index aside).
void expectSameMotion(const sim::State& a, const sim::State& b) {
  EXPECT_EQ(a.t, b.t);
  EXPECT_EQ(a.x_world, b.x_world);
  EXPECT_EQ(a.v_world, b.v_world);
  EXPECT_EQ(a.q.coeffs(), b.q.coeffs());
  EXPECT_EQ(a.L_world, b.L_world);
}

}  // namespace

// Fixed steps are the method's own, to the bit: after n steps the state is where n calls of
// sim::step leave it, at t = n·dt exactly (an integer times the step, never a sum of steps), and
// each step starts where the one before ended.
TEST(Stepping, FixedStepsAreTheMethodsOwnAndEndAtWholeMultiplesOfTheStep) {
  const sim::Model model = rollingModel(false);
  sim::State by_hand = sim::initialState(model);
  sim::Stepping steps(model, by_hand);
  for (std::int64_t n = 1; n <= 300; ++n) {
    const sim::State before = steps.current();
    steps.step(model);
    sim::step(model, by_hand);
    expectSameMotion(steps.previous(), before);
    expectSameMotion(steps.current(), by_hand);
    ASSERT_EQ(steps.current().step, n);
    ASSERT_EQ(steps.current().t, static_cast<double>(n) * model.dt);
  }
  EXPECT_EQ(steps.evaluations(), 0) << "fixed steps count no evaluations";
}

// A copy goes on alone: advanced as far as the original it takes the same steps to the bit (its
// adaptive stepper copied, step size and dense output), gives the same states between the last
// step's ends and the same counts, and the original's steps do not move it.
TEST(Stepping, ACopyGoesOnAloneTakingTheSameSteps) {
  for (const bool adaptive : {false, true}) {
    const sim::Model model = rollingModel(adaptive);
    sim::Stepping original(model, sim::initialState(model));
    for (int n = 0; n < 50; ++n) original.step(model);
    sim::Stepping copy(original);
    const sim::State at_copy = copy.current();
    for (int n = 0; n < 50; ++n) original.step(model);
    expectSameMotion(copy.current(), at_copy);
    for (int n = 0; n < 50; ++n) copy.step(model);
    expectSameMotion(copy.current(), original.current());
    const double t = 0.5 * (original.previous().t + original.current().t);
    expectSameMotion(copy.stateAt(t, model), original.stateAt(t, model));
    EXPECT_EQ(copy.evaluations(), original.evaluations());
    EXPECT_EQ(copy.rejected(), original.rejected());
  }
}

// A state set mid-run (Rollout::setState) starts the adaptive stepper afresh: from there it takes
// the steps a new stepper takes from that state, to the bit, and the counts go on from the old
// stepper's (a run's evaluations and rejected steps never go back).
TEST(Stepping, ARestartStartsTheStepperAfreshAndKeepsItsCounts) {
  const sim::Model model = rollingModel(true);
  sim::Stepping steps(model, sim::initialState(model));
  for (int n = 0; n < 40; ++n) steps.step(model);
  const std::int64_t evaluations = steps.evaluations(), rejected = steps.rejected();
  const sim::State from = steps.current();
  steps.startFrom(model, from);
  expectSameMotion(steps.previous(), from);  // a step of no length at the state set
  expectSameMotion(steps.current(), from);
  // A new stepper from the same state, its step count started at 0 (its rejected steps are its
  // tries less the steps it took).
  sim::State from_zero = from;
  from_zero.step = 0;
  sim::Stepping fresh(model, from_zero);
  for (int n = 0; n < 40; ++n) {
    steps.step(model);
    fresh.step(model);
  }
  expectSameMotion(steps.current(), fresh.current());
  EXPECT_EQ(steps.current().step, 80);
  EXPECT_EQ(steps.evaluations(), evaluations + fresh.evaluations());
  EXPECT_EQ(steps.rejected(), rejected + fresh.rejected());
  EXPECT_GT(evaluations, 0);
}

// A stepper started from a state at a later step (a Rollout started from a state it was given)
// counts what one started at step 0 counts: the steps it rejected are its own tries less its own
// steps, not less the step index.
TEST(Stepping, AStartAtALaterStepCountsItsOwnRejectedSteps) {
  const sim::Model model = rollingModel(true);
  sim::State at_zero = sim::initialState(model);
  sim::State later = at_zero;
  later.step = 1000;
  sim::Stepping from_zero(model, at_zero), from_later(model, later);
  for (int n = 0; n < 60; ++n) {
    from_zero.step(model);
    from_later.step(model);
  }
  EXPECT_EQ(from_later.current().step, 1060);
  EXPECT_EQ(from_later.evaluations(), from_zero.evaluations());
  EXPECT_EQ(from_later.rejected(), from_zero.rejected());
  EXPECT_GE(from_later.rejected(), 0);
}

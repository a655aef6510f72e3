// contact.model auto's switch (sim/auto_switch.hpp) on scripted states, without a Rollout:
// which mode a run starts in, how long the contact must stick before rolling resumes, and
// where inside a step rolling gives way to sliding.
#include "sim/auto_switch.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/rolling.hpp"
#include "sim/switching.hpp"
#include "support.hpp"

using namespace testing_support;

namespace {

// The default body with the smooth contact's constants auto needs.
const char* kAuto = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}
  dents: {scale: 0.45, at: [0.73, 4.50], inset: 0.1}
  grid: {dx: 0.05, dy: 0.05, dz: 0.05}
  mass: 0.059
contact: {model: auto, stiffness: 2.0e4, damping: 4, friction: 0.5, air_drag: 5.9e-6}
initial: {spin: -5.0, tilt: [0.5, 0.5]}
simulation: {integrator: rk4, dt: 5.0e-4, duration: 4.0}
)";

// The body resting on the smooth contact's spring, still: no slip, the spring pressing M g.
sim::State restingOnTheSpring(const sim::Model& run) {
  sim::State s;
  s.x_world.z() = sim::restingHeight(run, Eigen::Matrix3d::Identity());
  s.t = 1.0;
  return s;
}

}  // namespace

// At rest on the floor rolling holds, so auto starts rolling, on rolling's constraint with the
// spring's compression at rest (M g / k = 29 µm) as its depth; released in the air it starts
// sliding, from the very state it was given.
TEST(AutoSwitch, StartsRollingOnTheFloorAndSlidingInTheAir) {
  const sim::Model run = build(parse(kAuto));
  const sim::AutoSwitch on_floor(run);
  sim::State s = sim::initialState(run);
  const sim::Model first = on_floor.start(s);
  EXPECT_EQ(first.contact.model, sim::ContactModel::Rolling);
  EXPECT_NEAR(first.rolling_depth, run.body->mass * run.gravity / run.contact.stiffness, 1e-12);
  EXPECT_TRUE(sim::rollingMargins(first, s).hold());

  sim::SceneSpec spec = parse(kAuto);
  spec.initial.height = 2.0;  // cm
  const sim::Model dropped = build(spec);
  sim::State air = sim::initialState(dropped);
  const sim::State given = air;
  EXPECT_EQ(sim::AutoSwitch(dropped).start(air).contact.model, sim::ContactModel::Smooth);
  EXPECT_EQ(air.x_world, given.x_world);
  EXPECT_EQ(air.v_world, given.v_world);
}

// Rolling resumes only after the contact point has stuck (slip below ε, the spring pressing)
// for kStickTime = 50 ms: not after 51 steps of 1/1024 s (49.8 ms), after 52 (50.8 ms; steps
// of a power of two add up exactly); at the end of the step that completed it, once; and a
// slipping step starts the count again.
TEST(AutoSwitch, RollingResumesAfterTheContactHasStuckForTheStickTime) {
  const sim::Model run = build(parse(kAuto));
  const sim::Model smooth = sim::modeOf(run, sim::ContactModel::Smooth, 0);
  const sim::State still = restingOnTheSpring(run);
  sim::State slipping = still;
  slipping.v_world.x() = 0.1;  // m/s, far above ε
  sim::AutoSwitch sw(run);
  const auto noState = [](double) -> sim::State {
    ADD_FAILURE() << "sliding locates nothing inside a step";
    return {};
  };
  const double h = 1.0 / 1024;  // s
  for (int k = 0; k < 51; ++k) {
    sw.countStuck(smooth, still, h);
    EXPECT_FALSE(sw.afterStep(smooth, still, still, noState));
  }
  EXPECT_FALSE(sw.handBack());
  sw.countStuck(smooth, slipping, h);
  EXPECT_EQ(sw.stuckFor(), 0);
  for (int k = 0; k < 52; ++k) sw.countStuck(smooth, still, h);
  EXPECT_EQ(sw.stuckFor(), 52 * h);
  EXPECT_FALSE(sw.afterStep(smooth, still, still, noState));  // sliding changes at the next step
  const std::optional<sim::ModeChange> back = sw.handBack();
  ASSERT_TRUE(back);
  EXPECT_EQ(back->next.contact.model, sim::ContactModel::Rolling);
  EXPECT_DOUBLE_EQ(back->t_s, still.t);
  // Rolling holds the spring's compression, M g / k = 29 µm, to rounding.
  EXPECT_NEAR(back->next.rolling_depth, run.body->mass * run.gravity / run.contact.stiffness,
              1e-15);
  EXPECT_FALSE(sw.handBack());
}

// Rolling gives way to sliding at the first time inside the step that a margin failing at the
// step's end reaches zero: a body tipped over through a 10 ms step from upright to 80° (its
// lowest point past the rim of the flat top at the end) switches inside the step, where the
// first of those margins is zero to the zero finder's accuracy (1e-9 of margins of order 0.1 N
// and 1 mm) and the others still positive, as they all are a hair before; the smooth model
// takes over from the state there.
TEST(AutoSwitch, RollingGivesWayWhereTheFirstMarginReachesZero) {
  const sim::Model run = build(parse(kAuto));
  const double depth = run.body->mass * run.gravity / run.contact.stiffness;
  const sim::Model rolling = sim::modeOf(run, sim::ContactModel::Rolling, depth);
  const double h = 0.01, tilt_end = 80 * M_PI / 180;
  const auto state_at = [&](double t) {
    sim::State s;
    s.q = Eigen::Quaterniond(Eigen::AngleAxisd(tilt_end * t / h, Eigen::Vector3d::UnitX()));
    s.t = t;
    sim::enforceRolling(rolling, s);
    return s;
  };
  sim::AutoSwitch sw(run);
  const std::optional<sim::ModeChange> change =
      sw.afterStep(rolling, state_at(0), state_at(h), state_at);
  ASSERT_TRUE(change);
  EXPECT_GT(change->t_s, 0);
  EXPECT_LT(change->t_s, h);
  EXPECT_EQ(change->next.contact.model, sim::ContactModel::Smooth);
  EXPECT_EQ(change->start.q.coeffs(), state_at(change->t_s).q.coeffs());
  // The margins that fail at the step's end, as they are at the switch and a hair before.
  using Margin = double sim::RollingMargins::*;
  const sim::RollingMargins end = sim::rollingMargins(rolling, state_at(h));
  const sim::RollingMargins at = sim::rollingMargins(rolling, state_at(change->t_s));
  const sim::RollingMargins before = sim::rollingMargins(rolling, state_at(change->t_s - 1e-6 * h));
  double smallest = INFINITY;
  for (Margin m :
       {&sim::RollingMargins::friction, &sim::RollingMargins::normal, &sim::RollingMargins::rim}) {
    if (end.*m > 0) continue;
    EXPECT_GT(at.*m, -1e-9);
    EXPECT_GT(before.*m, 0);
    smallest = std::min(smallest, at.*m);
  }
  EXPECT_NEAR(smallest, 0, 1e-9);
}

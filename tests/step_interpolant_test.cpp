// The step interpolant (sim/step_interpolant.hpp) on scripted step ends, without a Rollout:
// it hits both ends of a step, it is exact for a motion its cubics contain (free flight), a
// step cut by a change of contact model is read from the old mode before the cut, and the spin
// read from an adaptive stepper's dense output is its state's.
#include "sim/step_interpolant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "sim/adaptive.hpp"
#include "support.hpp"

using namespace testing_support;

namespace {

// The stable body released 10 cm above the floor without spin: it falls freely, no contact.
const char* kFalling = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}
  grid: {dx: 0.1, dy: 0.2, dz: 0.005}
  mass: 0.059
contact: {model: smooth, stiffness: 2.0e4, damping: 4, friction: 0.5}
initial: {spin: 0.0, tilt: [10.0, 0.0], height: 10.0}
simulation: {integrator: rk4, dt: 1.0e-4, duration: 1.0}
)";

// Free flight from `start`: x(t) = x0 + v0 t − ½ g t² ẑ, v(t) = v0 − g t ẑ, no rotation.
sim::State flight(const sim::Model& model, const sim::State& start, double t) {
  sim::State s = start;
  const double dt = t - start.t;
  s.x_world = start.x_world + dt * start.v_world;
  s.x_world.z() -= 0.5 * model.gravity * dt * dt;
  s.v_world.z() -= model.gravity * dt;
  s.t = t;
  return s;
}

sim::State launched(const sim::Model& model) {
  sim::State s = sim::initialState(model);
  s.v_world = Eigen::Vector3d(0.3, -0.2, 1.5);  // m/s: thrown up and sideways
  return s;
}

}  // namespace

// Between the ends the cubic Hermite interpolant is exact for a body in free flight, whose x is
// quadratic and v linear in t (the cubic's own terms): at a quarter of a 20 ms step the CM is
// where the ballistic formula puts it to rounding (1e-15 m on 0.1 m).
TEST(StepInterpolant, IsExactForAFreeFlight) {
  const sim::Model model = build(parse(kFalling));
  const sim::State a = launched(model);
  const sim::State b = flight(model, a, a.t + 0.02);
  const sim::StepInterpolant last;
  const sim::State mid = last.at(a.t + 0.005, model, a, b, nullptr);
  const sim::State expected = flight(model, a, a.t + 0.005);
  EXPECT_NEAR((mid.x_world - expected.x_world).norm(), 0, 1e-15);
  EXPECT_NEAR((mid.v_world - expected.v_world).norm(), 0, 1e-14);
  EXPECT_NEAR((mid.q.coeffs() - a.q.coeffs()).norm(), 0, 1e-15);
  EXPECT_DOUBLE_EQ(mid.t, a.t + 0.005);
}

// At the ends of the step the interpolant gives the ends themselves, whatever lies between:
// here a step whose end is no flight from its start at all (moved, turned and spun).
TEST(StepInterpolant, HitsBothEndsOfTheStep) {
  const sim::Model model = build(parse(kFalling));
  const sim::State a = launched(model);
  sim::State b = flight(model, a, a.t + 1e-3);
  b.x_world += Eigen::Vector3d(1e-3, 2e-3, -1e-3);
  b.q = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ())) * a.q;
  b.L_world = Eigen::Vector3d(1e-5, 2e-5, 3e-4);
  const sim::StepInterpolant last;
  for (const sim::State* end : {&a, static_cast<const sim::State*>(&b)}) {
    const sim::State s = last.at(end->t, model, a, b, nullptr);
    EXPECT_EQ(s.x_world, end->x_world);
    EXPECT_EQ(s.v_world, end->v_world);
    EXPECT_EQ(s.q.coeffs(), end->q.coeffs());
    EXPECT_EQ(s.L_world, end->L_world);
  }
}

// A step cut at t_cut by a change of mode: before the cut its states are the old mode's own
// step (towards where that step ended), after it the new mode's; modeAt names the mode each
// time was integrated in. Here the old step is the flight and the new one ends 1 mm aside.
TEST(StepInterpolant, ACutStepIsReadFromTheOldModeBeforeTheCut) {
  const sim::Model model = build(parse(kFalling));
  sim::Model after = model;
  after.contact.model = sim::ContactModel::Points;
  const sim::State a = launched(model);
  const sim::State old_end = flight(model, a, a.t + 0.02);
  sim::State b = old_end;
  b.x_world.x() += 1e-3;
  sim::StepInterpolant last;
  last.cut(a.t + 0.01, model, old_end);
  const sim::State before = last.at(a.t + 0.005, after, a, b, nullptr);
  EXPECT_NEAR((before.x_world - flight(model, a, a.t + 0.005).x_world).norm(), 0, 1e-15);
  const sim::State later = last.at(a.t + 0.015, after, a, b, nullptr);
  EXPECT_GT(later.x_world.x() - flight(model, a, a.t + 0.015).x_world.x(), 1e-4);
  EXPECT_EQ(last.modeAt(a.t + 0.005, after).contact.model, sim::ContactModel::Smooth);
  EXPECT_EQ(last.modeAt(a.t + 0.015, after).contact.model, sim::ContactModel::Points);
  // The cut's own time (to rounding) belongs to the new mode.
  EXPECT_EQ(last.modeAt(a.t + 0.01, after).contact.model, sim::ContactModel::Points);
}

// The spin the reversal rule reads between a step's ends is formed from the dense output's
// integrated variables alone (n = (Rᵀẑ)·ω_body over |q|², or from the whole state for a free
// body): it is the spin of the state at() gives at that time, for each adaptive method and
// both layouts. Rolling: the default body 1.5 s into its run (tilted and rocking, so every
// component of Rᵀẑ and ω counts). Free: the falling body in flight. The two ways differ only
// by rounding (normalising q and turning L there and back): within 1e-12 of |ω|.
TEST(StepInterpolant, TheSpinBetweenStepEndsIsTheStatesSpin) {
  sim::Model falling = build(parse(kFalling));
  falling.tolerance = 1e-8;
  const sim::State thrown = launched(falling);
  sim::State spun = thrown;
  spun.L_world = falling.body->inertia * Eigen::Vector3d(0.7, -1.1, 4.0);
  for (const sim::Integrator method : {sim::Integrator::Dopri5, sim::Integrator::Dop853}) {
    sim::Model rolling = rollingModel(true);
    rolling.integrator = method;
    falling.integrator = method;
    for (const auto& [model, start] :
         {std::pair<const sim::Model*, sim::State>{&rolling, sim::initialState(rolling)},
          std::pair<const sim::Model*, sim::State>{&falling, spun}}) {
      sim::AdaptiveStepper stepper(*model, start);
      sim::State a = start, b = start;
      const double until = model == &rolling ? 1.5 : 0.01;
      for (std::int64_t k = 1; b.t < until; ++k) {
        a = b;
        b = stepper.step(k);
      }
      const sim::StepInterpolant last;
      for (const double part : {0.0, 0.25, 0.5, 0.9}) {
        const double t = a.t + part * (b.t - a.t);
        const sim::State s = last.at(t, *model, a, b, &stepper);
        const Eigen::Vector3d w = sim::angularVelocity(*model, s);
        ASSERT_GT(std::abs(w.x()) + std::abs(w.y()), 1e-3 * w.norm());  // not spinning upright
        EXPECT_NEAR(last.spinAt(t, *model, a, b, &stepper), w.z(), 1e-12 * w.norm())
            << (model == &rolling ? "rolling" : "free") << " at " << part << " of a step";
      }
    }
  }
}

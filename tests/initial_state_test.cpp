// Any initial state (docs/physics.md P5): initial.angular_velocity in body axes (spin its
// shortcut), initial.velocity checked against the contact model, and the tap experiment.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "sim/analysis.hpp"
#include "support.hpp"
#include "tasks/report/captions.hpp"

using namespace testing_support;

namespace {

// The default body (kRolling) at rest, upright, with `initial` in place of its spin and tilt.
std::string restingBody(const std::string& initial, const std::string& contact = "{model: rolling}",
                        const std::string& simulation =
                            "{integrator: rk4, dt: 1.0e-3, "
                            "duration: 3.0}") {
  std::string yaml = kRolling;
  auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = yaml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    yaml.replace(at, from.size(), to);
  };
  swap("initial: {spin: -5.0, tilt: [0.5, 0.5]}", "initial: " + initial);
  swap("contact: {model: rolling}", "contact: " + contact);
  swap("simulation: {integrator: rk4, dt: 1.0e-3, duration: 3.0}", "simulation: " + simulation);
  return yaml;
}

// The CM → contact vector of a body standing upright at rest, body axes, m: the lowest point
// of its smooth surface straight down.
Eigen::Vector3d uprightContact(const sim::Body& body) {
  return sim::lowestSurfacePoint(body, Eigen::Vector3d(0, 0, -1));
}

// The inertia about the contact point r (body axes): I + M (|r|² 1 − r rᵀ), the parallel-axis
// theorem. Rolling without slipping turns the body about its contact point, so its kinetic energy
// is ½ ωᵀ I_P ω (½ ωᵀ I ω of the turning about the CM and ½ M |ω × r|² of the CM's motion).
Eigen::Matrix3d inertiaAboutContact(const sim::Body& body, const Eigen::Vector3d& r) {
  return body.inertia +
         body.mass * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// Tapped about body x at rest, upright, rolling: the first sample's kinetic energy is ½ ωᵀ I_P ω
// about the contact point, its potential M g h with h the CM's height over the contact, both to
// rounding (1e-12 of the energy: a few dozen operations), and the body rocks: it tilts by about
// the angle its energy reaches against gravity's stiffness.
TEST(InitialState, ATapAboutXStartsWithTheEnergyOfRollingAboutTheContactAndRocks) {
  const sim::Model model = build(parse(restingBody("{angular_velocity: [3.0, 0, 0]}")));
  const Eigen::Vector3d w(3.0, 0, 0);
  const Eigen::Vector3d r = uprightContact(*model.body);
  const double kinetic = 0.5 * w.dot(inertiaAboutContact(*model.body, r) * w);
  const double potential = model.body->mass * model.gravity * -r.z();
  const Recorded run = record(model, 1e-2);
  const sim::Telemetry& first = run.samples.front();
  EXPECT_NEAR(first.kinetic, kinetic, 1e-12 * first.energy);
  EXPECT_NEAR(first.potential, potential, 1e-12 * first.energy);
  EXPECT_NEAR(first.energy, kinetic + potential, 1e-12 * first.energy);
  EXPECT_EQ(first.spin, 0.0);
  // It rocks: 3 rad/s about the short axis (pitch, 7 Hz) swings it about 3/(2π 7) rad ≈ 4°.
  EXPECT_GT(run.summary.max_tilt_deg, 2.0);
  EXPECT_LT(run.summary.max_tilt_deg, 10.0);
}

// A smooth (penalty) body takes the given velocity and ω as they are: its kinetic energy is
// ½ ωᵀ I ω + ½ M |v|², to rounding.
TEST(InitialState, ASmoothBodyTakesTheGivenVelocityAsItIs) {
  const std::string contact = "{model: smooth, stiffness: 2.0e4, damping: 4, friction: 0.5}";
  const sim::Model model =
      build(parse(restingBody("{angular_velocity: [1.0, -2.0, 0.5], velocity: [0.03, 0.02, 0]}",
                              contact, "{dt: 2.0e-5, duration: 0.01}")));
  const sim::State s = sim::initialState(model);
  EXPECT_EQ(s.v_world, Eigen::Vector3d(0.03, 0.02, 0));
  const Eigen::Vector3d w(1.0, -2.0, 0.5);  // body axes = world axes upright
  const double kinetic = 0.5 * w.dot(model.body->inertia * w) + 0.5 * model.body->mass * 13e-4;
  EXPECT_NEAR(sim::telemetryOf(model, s).kinetic, kinetic, 1e-12 * kinetic);
}

// Rolling: the velocity follows from ω, v = −ω × r; for ω = (ω_x, 0, 0) upright at rest,
// r = (0, 0, −h), so v = (0, −ω_x h, 0). Given within 1e-3 of that it is accepted and the
// exact one is used; given 1 % off it is refused with one line naming file, line and key.
TEST(InitialState, RollingAcceptsAVelocityThatAgreesAndRefusesOneThatSlides) {
  const sim::Model plain = build(parse(restingBody("{angular_velocity: [3.0, 0, 0]}")));
  const double h = -uprightContact(*plain.body).z();
  auto with = [&](double factor) {
    std::ostringstream initial;
    initial.precision(17);
    initial << "{angular_velocity: [3.0, 0, 0], velocity: [0, " << -3.0 * h * factor << ", 0]}";
    return restingBody(initial.str());
  };
  const sim::Model agrees = build(parse(with(1 + 1e-4)));
  EXPECT_EQ(sim::initialState(agrees).v_world, sim::initialState(plain).v_world);
  EXPECT_EQ(sim::initialState(plain).v_world.y(), -3.0 * h);
  const std::string refused = errorFor(with(1.01));
  EXPECT_EQ(refused.rfind("inline.yaml:10: initial.velocity slides the contact point at ", 0), 0u)
      << refused;
  EXPECT_EQ(refused.find('\n'), std::string::npos);
}

// initial.spin is the shortcut for angular_velocity [0, 0, spin]: the same start to the bit;
// both given is refused, naming the spin's line.
TEST(InitialState, SpinIsTheShortcutForAngularVelocityAndBothAreRefused) {
  const sim::State shortcut =
      sim::initialState(build(parse(restingBody("{spin: -5.0, tilt: [0.5, 0.5]}"))));
  const sim::State full = sim::initialState(
      build(parse(restingBody("{angular_velocity: [0, 0, -5.0], tilt: [0.5, 0.5]}"))));
  EXPECT_EQ(shortcut.L_world, full.L_world);
  EXPECT_EQ(shortcut.v_world, full.v_world);
  EXPECT_EQ(shortcut.x_world, full.x_world);
  EXPECT_EQ(errorFor(restingBody("\n  spin: -5.0\n  angular_velocity: [0, 0, -5.0]\n")),
            "inline.yaml:11: initial.spin is given with initial.angular_velocity: give one of "
            "them (spin n is the shortcut for angular_velocity: [0, 0, n])");
}

// The tap experiment (scenes/tap-end.yaml, scenes/tap-side.yaml): at rest, tapped about body x
// (pitch) or body y (roll), the body spins up the way the averaged theory (docs/physics.md P8.5)
// says at n = 0: C ṅ = −2 k_j E_j, so opposite to the sign of the tapped mode's first-order
// growth k_j; the default body's k_pitch < 0 < k_roll, so the two spin opposite ways, and each
// still spins that way at the run's end.
TEST(InitialState, TappedAboutXAndAboutYTheBodySpinsUpOppositeWaysAsTheTheorySays) {
  const sim::FirstOrder k =
      sim::firstOrderGrowth(build(parse(restingBody("{angular_velocity: [3.0, 0, 0]}"))));
  ASSERT_LT(k.pitch, 0);
  ASSERT_GT(k.roll, 0);
  double final_spin[2];
  for (int i = 0; i < 2; ++i) {
    const char* name = i == 0 ? "/scenes/tap-end.yaml" : "/scenes/tap-side.yaml";
    auto loaded = scene::loadString(readText(RATTLEBACK_SOURCE_DIR + std::string(name)), name);
    ASSERT_TRUE(loaded) << loaded.error().text();
    const sim::Model model = build(loaded->spec);
    const Recorded run = record(model, 1e-2);
    final_spin[i] = run.summary.last.spin;
    // The spin never exceeds what the tap's kinetic energy could become (the video's inset
    // is scaled to it): energy only leaves a body at rest upright, at its lowest.
    for (const sim::Telemetry& sample : run.samples)
      ASSERT_LT(std::abs(sample.spin), sim::spinReach(model)) << name << " at " << sample.t;
  }
  EXPECT_GT(final_spin[0], 0) << "tapped about x: −k_pitch > 0";
  EXPECT_LT(final_spin[1], 0) << "tapped about y: −k_roll < 0";
}

// Spun about the upright z axis, a principal axis of the default body, the kinetic energy is
// ½ C n² and all of it is spin: the reach is the spin itself (to rounding).
TEST(InitialState, ASpinAlonesReachIsItself) {
  const sim::Model model = build(parse(restingBody("{spin: -5.0}")));
  EXPECT_NEAR(sim::spinReach(model), 5.0, 1e-12);
}

// The report says how a run started: a body struck about its x or y axis by its ω (the
// sidecar's model.initial.angular_velocity), not "spun +0 rad/s (no spin)"; a spin alone as
// before.
TEST(InitialState, TheReportSaysAStruckBodyWasStruck) {
  tasks::report::RunRecord struck;
  struck.initial_spin = 0.0;
  struck.model_angular_velocity = {3.0, 0.0, 0.0};
  EXPECT_NE(tasks::report::measuredOf(struck).find("struck at ω = [3, 0, 0] rad/s (body axes)"),
            std::string::npos);
  tasks::report::RunRecord spun;
  spun.initial_spin = -5.0;
  spun.model_angular_velocity = {0.0, 0.0, -5.0};
  EXPECT_EQ(tasks::report::measuredOf(spun).find("spun -5 rad/s (clockwise)"), 0u);
}

// The physics that reverses: the rolling model against an independent solver's reversal time,
// the smooth penalty model against rolling, the linearised theory against runs.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <fstream>
#include <regex>
#include <sstream>

#include "media/video.hpp"
#include "sim/analysis.hpp"
#include "sim/stability.hpp"
#include "support.hpp"

using namespace testing_support;

namespace {

// The default body (docs/scenes.md "Shipped scenes": a=1, p=0.5, s=0.03, top=0.5, dents 0.45 at
// (0.73, 4.50) cm), mass properties on a 0.025 cm grid, rolling without slipping, rk4, tilt
// 0.5°/0.5°, spin −5 rad/s.
const char* kRollingScene = R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}
  dents: {scale: 0.45, at: [0.73, 4.50], inset: 0.1}
  grid: {dx: 0.025, dy: 0.025, dz: 0.025}
  mass: 0.059
contact: {model: rolling, air_drag: 0.0}
initial: {spin: -5.0, tilt: [0.5, 0.5]}
simulation: {integrator: rk4, dt: 5.0e-4, duration: 8.0}
video: {fps: 25}
)";

struct SceneRun {
  sim::RunSummary summary;
  std::vector<sim::Telemetry> samples;
};

SceneRun runScene(const sim::SceneSpec& spec, std::int64_t every = 1) {
  const sim::Model model = build(spec);
  SceneRun out;
  sim::Rollout rollout(model);
  out.summary = sim::sampleRun(rollout, 1 / (static_cast<double>(every) * model.dt),
                               [&](const sim::Telemetry& t) { out.samples.push_back(t); });
  return out;
}

}  // namespace

// A quoted figure: an earlier issue gave about 2.32 s for this body from a no-slip solver with
// the same mass properties (0.025 cm grid) and initial-state convention; that solver is not in
// the repository (the one that is, tests/reference/, checks Kane & Levinson's body below: see
// Rolling.AgreesWithTheIndependentReferenceSolver). Measured here 2.329 s. We allow ±0.015 s
// (0.6%): the figure is quoted to two decimals, and the grid alone moves it by 0.007 s per halving
// (2.340, 2.329, 2.322 s at 0.05, 0.025, 0.0125 cm).
TEST(Rolling, ReversesWhereTheReferenceSolverDoes) {
  const SceneRun r = runScene(parse(kRollingScene), 100);
  ASSERT_TRUE(r.summary.first_reversal_s.has_value());
  EXPECT_NEAR(*r.summary.first_reversal_s, 2.32, 0.015);
  EXPECT_GT(r.summary.last.spin, 4.0);  // and it spins back up the other way
}

// With a light air torque (σ/M = 1e-4 m²/s) the counter-clockwise spin never reverses in 8 s:
// its only growing mode (roll, 0.16/s) is too slow to take the spin before the drag does.
TEST(Rolling, CounterClockwiseWithAirDragDoesNotReverse) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.initial.spin = 5.0;
  spec.contact.air_drag = 1e-4 * spec.body.mass;
  const SceneRun r = runScene(spec, 100);
  EXPECT_FALSE(r.summary.first_reversal_s.has_value());
  EXPECT_GT(r.summary.last.spin, 0);
}

// Without dissipation rolling conserves energy (the constraint force does no work): RK4 at
// the scene's step keeps it to 1e-8 relative over 10 s (measured 1.5e-9 over 8 s).
TEST(Rolling, ConservesEnergyWithoutDrag) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.simulation.duration = 10.0;
  const SceneRun r = runScene(spec, 200);
  double worst = 0;
  for (const auto& t : r.samples) worst = std::max(worst, std::abs(t.energy - r.samples[0].energy));
  EXPECT_LT(worst, 1e-8 * r.samples[0].energy);
}

// The smooth penalty model (k = 2e4 N/m, c = 20 N s/m, μ = 0.5, regularised) rolls almost
// without slipping: its first reversal comes 0.34 % after the rolling model's (2.3475 against
// 2.3395 s). That is the models' difference, not integration error (the smooth run's step moves
// it by 0.013 %: 2.3475, 2.3477, 2.3478 s at dt 20, 10, 5 µs; rolling's rk4 by 3e-6 %): the
// spring's compliance is about half of it (0.15 % at k = 8e4) and the regularised friction's
// creep the rest. We allow 0.5 %.
TEST(Smooth, AgreesWithRollingAtFriction05) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.body.grid = {0.05, 0.05, 0.05};
  spec.simulation.duration = 4.0;
  const SceneRun rolling_run = runScene(spec, 100);
  ASSERT_TRUE(rolling_run.summary.first_reversal_s.has_value());
  const double rolling = *rolling_run.summary.first_reversal_s;
  spec.contact.model = "smooth";
  spec.contact.stiffness = 2e4;
  spec.contact.damping = 20;
  spec.contact.friction = 0.5;
  spec.simulation.integrator = "symplectic";
  spec.simulation.dt = 2e-5;
  const SceneRun smooth = runScene(spec, 2000);
  ASSERT_TRUE(smooth.summary.first_reversal_s.has_value());
  EXPECT_NEAR(*smooth.summary.first_reversal_s / rolling, 1.0, 0.005);
}

namespace {

// Oscillation frequency (Hz) of a signal from its zero crossings, after `skip` seconds.
double crossingFrequency(const std::vector<sim::Telemetry>& samples, int axis, double skip) {
  std::vector<double> times;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double a = samples[i - 1].w_world(axis), b = samples[i].w_world(axis);
    if (samples[i].t > skip && a < 0 && b >= 0)
      times.push_back(samples[i - 1].t + (samples[i].t - samples[i - 1].t) * (-a) / (b - a));
  }
  return (times.size() - 1) / (times.back() - times.front());
}

}  // namespace

// Released without spin and slightly tilted, the body rocks at the linearised frequencies:
// about its long axis (roll: tilt about y, ω_y) and its short axis (pitch: ω_x). 0.5%: the
// crossings are interpolated within 1 ms samples over ~10 and ~20 periods, and 0.2° of tilt
// shifts a frequency by ~1e-5 (amplitude dependence is second order).
TEST(Theory, RockingFrequenciesMatchAnalyze) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.initial.spin = 0;
  spec.simulation.duration = 3.0;
  const sim::Linearisation rest = sim::linearise(build(spec), 0);
  spec.initial.tilt = {0.0, 0.2};
  const double roll = crossingFrequency(runScene(spec, 2).samples, 1, 0.0);
  spec.initial.tilt = {0.2, 0.0};
  const double pitch = crossingFrequency(runScene(spec, 2).samples, 0, 0.0);
  EXPECT_NEAR(roll / rest.roll_hz, 1.0, 0.005) << roll << " Hz vs " << rest.roll_hz;
  EXPECT_NEAR(pitch / rest.pitch_hz, 1.0, 0.005) << pitch << " Hz vs " << rest.pitch_hz;
  // docs/physics.md P8: roll/pitch ≈ 3.5/7.0 Hz for this body.
  EXPECT_NEAR(rest.roll_hz, 3.5, 0.1);
  EXPECT_NEAR(rest.pitch_hz, 7.0, 0.1);
}

// From a tiny tilt the pitch mode grows as e^{σt} long before the spin changes: the rate fitted
// to the tilt's envelope matches the eigenvalue's real part within 2% (the issue's bound;
// measured 1.607 against 1.598 /s, 0.5%).
TEST(Theory, EarlyGrowthMatchesTheEigenvalue) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.initial.tilt = {0.001, 0.001};
  spec.simulation.duration = 3.5;
  const sim::Linearisation l = sim::linearise(build(spec), spec.initial.spin);
  const SceneRun r = runScene(spec, 2);
  // Envelope: the largest tilt in each window of two pitch periods from 2 s (a whole number of
  // periods, so every window sees the same phases of the mode's elliptical tilt), fitted by
  // least squares on its logarithm. Both modes start equal; the roll mode decays (−0.6/s)
  // while pitch grows, so from 2 s pitch outweighs it e^{2.2·2} ≈ 80×, and the tilt is still
  // below 0.3°: linear.
  const double window = 2 / l.pitch_hz;  // s
  std::vector<double> t, log_tilt;
  for (double start = 2.0; start + window <= 3.5; start += window) {
    double peak = 0;
    for (const auto& s : r.samples)
      if (s.t >= start && s.t < start + window) peak = std::max(peak, s.tilt_deg);
    t.push_back(start);
    log_tilt.push_back(std::log(peak));
  }
  const double n = t.size();
  double st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    st += t[i];
    sl += log_tilt[i];
    stt += t[i] * t[i];
    stl += t[i] * log_tilt[i];
  }
  const double rate = (n * stl - st * sl) / (n * stt - st * st);
  EXPECT_NEAR(rate / l.pitch_growth, 1.0, 0.02) << rate << " vs " << l.pitch_growth;
}

// Halving the initial tilt doubles the time the pitch mode needs to grow to the same size:
// the reversal comes ln 2 / σ later (σ the pitch growth rate at the initial spin). Measured
// 0.430 s against 0.434 s (0.9%); 10% allows for the roll mode and the slowly changing spin,
// which shift the growth phase a little.
TEST(Theory, HalvingTheTiltDelaysTheReversalByLn2OverGrowth) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.simulation.duration = 4.0;
  const double sigma = sim::linearise(build(spec), spec.initial.spin).pitch_growth;
  const double full = *runScene(spec, 100).summary.first_reversal_s;
  spec.initial.tilt = {0.25, 0.25};
  const double half = *runScene(spec, 100).summary.first_reversal_s;
  EXPECT_NEAR((half - full) / (std::log(2.0) / sigma), 1.0, 0.1) << half - full;
}

// Bondi's rest condition: the seed's body cannot stand (h = 3.97 cm above a radius of 1.33 cm
// across x); the default body can (h = 0.97 cm, radii 2 and 33 cm). The radii are a/p and a/s
// exactly: 1e-12 m allows only rounding in a 2×2 eigen-decomposition.
TEST(Theory, RestStability) {
  const sim::Rest seed = sim::restOf(build(parse(kSeedScene)));
  EXPECT_FALSE(seed.stable);
  EXPECT_NEAR(seed.radii(0), 0.04 / 3, 1e-12);  // a/p, m
  const sim::Rest stable = sim::restOf(build(parse(kRollingScene)));
  EXPECT_TRUE(stable.stable);
  EXPECT_NEAR(stable.radii(0), 0.02, 1e-12);
  EXPECT_NEAR(stable.radii(1), 0.01 / 0.03, 1e-12);
}

// The dents make the direction: the default body prefers counter-clockwise (docs/physics.md P8:
// clockwise reverses), mirrored dents prefer clockwise, and without dents the rolling body spun the
// reversing way does not reverse.
TEST(Theory, DentsSetThePreferredDirection) {
  sim::SceneSpec spec = parse(kRollingScene);
  spec.body.grid = {0.05, 0.05, 0.05};
  EXPECT_EQ(sim::preferredDirection(build(spec), 5), sim::Direction::Ccw);
  spec.body.dents->at[0] *= -1;
  EXPECT_EQ(sim::preferredDirection(build(spec), 5), sim::Direction::Cw);
  spec.initial.spin = 5;  // the mirrored body reverses when spun counter-clockwise
  spec.simulation.duration = 4;
  EXPECT_TRUE(runScene(spec, 100).summary.first_reversal_s.has_value());
  spec.body.dents.reset();
  spec.initial.spin = -5;
  EXPECT_FALSE(runScene(spec, 100).summary.first_reversal_s.has_value());
}

namespace {

// Kane & Levinson's (1982) ellipsoid in our frame (see scenes/kane-levinson.yaml for the
// conversion from their z-down frame).
const char* kEllipsoidScene = R"(
units: {length: 1.0}
body:
  shape: ellipsoid
  ellipsoid: {semi_axes: [0.03, 0.20, 0.02], center: [0.0, 0.0, 0.01]}
  inertia: [[1.6e-3, -2.0e-5, 0.0], [-2.0e-5, 2.0e-4, 0.0], [0.0, 0.0, 1.7e-3]]
  mass: 1.0
contact: {model: rolling}
initial: {spin: 5.0, tilt: [0.5, 0.5]}
simulation: {integrator: rk4, dt: 1.0e-4, duration: 5.0}
video: {fps: 25}
)";

}  // namespace

// At the bottom of an ellipsoid (0, 0, −c) the radii of curvature are a²/c and b²/c; the CM is
// c − 0.01 m above the contact. Exact formulas: the tolerances (1e-15 m, 1e-14 m for the
// 2 m radius) allow rounding only.
TEST(Ellipsoid, RestGeometryIsClosedForm) {
  const sim::Rest rest = sim::restOf(build(parse(kEllipsoidScene)));
  EXPECT_NEAR(rest.h, 0.01, 1e-15);
  EXPECT_NEAR(rest.radii(0), 0.03 * 0.03 / 0.02, 1e-15);
  EXPECT_NEAR(rest.radii(1), 0.20 * 0.20 / 0.02, 1e-14);
  EXPECT_TRUE(rest.stable);
}

// The product of inertia D sets the direction: D = −2e-5 kg m² turns the least-inertia axis
// clockwise (−0.82°) and the body prefers clockwise spin; spun counter-clockwise it reverses,
// clockwise it does not. Flipping D's sign mirrors all of it. Energy (no dissipation) is kept
// to 1e-8 relative at dt 1e-4 s (measured 2.9e-9 over 5 s).
TEST(Ellipsoid, ProductOfInertiaSetsThePreferredDirection) {
  sim::SceneSpec spec = parse(kEllipsoidScene);
  const sim::Model model = build(spec);
  EXPECT_NEAR(model.body->mass_properties.misalignment_deg,
              0.5 * std::atan2(2 * -2e-5, 1.6e-3 - 2e-4) * 180 / M_PI, 1e-9);
  EXPECT_EQ(sim::preferredDirection(model, 5), sim::Direction::Cw);
  const SceneRun ccw = runScene(spec, 100);
  ASSERT_TRUE(ccw.summary.first_reversal_s.has_value());
  double worst = 0;
  for (const auto& t : ccw.samples)
    worst = std::max(worst, std::abs(t.energy - ccw.samples[0].energy));
  EXPECT_LT(worst, 1e-8 * ccw.samples[0].energy);
  spec.initial.spin = -5;
  EXPECT_FALSE(runScene(spec, 100).summary.first_reversal_s.has_value());
  spec.body.inertia[0][1] = spec.body.inertia[1][0] = 2e-5;
  EXPECT_EQ(sim::preferredDirection(build(spec), 5), sim::Direction::Ccw);
  EXPECT_TRUE(runScene(spec, 100).summary.first_reversal_s.has_value());
}

// An impossible tensor or a key of the other shape is refused, naming the key.
TEST(Ellipsoid, BadBodiesAreRefused) {
  auto error = [](const std::string& yaml) {
    auto loaded = scene::loadString(yaml, "e.yaml");
    if (!loaded) return loaded.error().text();
    auto model = scene::loadModel(loaded.value());
    if (!model) return model.error().text();
    return std::string();
  };
  const std::string base = kEllipsoidScene;
  auto with = [&](const std::string& from, const std::string& to) {
    std::string text = base;
    return text.replace(text.find(from), from.size(), to);
  };
  EXPECT_EQ(error(base), "");
  EXPECT_EQ(error(with("[0.0, 0.0, 1.7e-3]", "[0.0, 0.0, -1.7e-3]")),
            "e.yaml:6: body.inertia must be positive definite");
  EXPECT_EQ(error(with("[0.0, 0.0, 1.7e-3]", "[0.0, 0.0, 1.0]"))
                .rfind("e.yaml:6: body.inertia is impossible", 0),
            0u);
  EXPECT_EQ(error(with("[-2.0e-5, 2.0e-4, 0.0]", "[-3.0e-5, 2.0e-4, 0.0]")),
            "e.yaml:6: body.inertia must be symmetric");
  EXPECT_EQ(error(with("[0.03, 0.20, 0.02]", "[0.03, -0.20, 0.02]"))
                .rfind("e.yaml:5: body.ellipsoid.semi_axes must be > 0", 0),
            0u);
  EXPECT_EQ(error(with("  mass: 1.0", "  mass: 1.0\n  grid: {dx: 1, dy: 1, dz: 1}")),
            "e.yaml:8: body.grid belongs to shape: paraboloid");
  EXPECT_EQ(error(with("[0.03, 0.20, 0.02], center", "[0.03, 0.20], center")),
            "e.yaml:5: body.ellipsoid.semi_axes must be a list of three numbers, not a list of 2");
  // The centre of mass within the ellipsoid: (0.5 / 0.02)² = 625 and 0.02 / 0.02 (on its
  // surface) are refused, 0.0199 (just inside) is not.
  for (const char* outside : {"[0.0, 0.0, 0.5]", "[0.0, 0.0, 0.02]", "[0.03, 0.0, 0.0]"})
    EXPECT_EQ(error(with("[0.0, 0.0, 0.01]", outside))
                  .rfind("e.yaml:5: body.ellipsoid.center puts the centre of mass outside the "
                         "ellipsoid",
                         0),
              0u)
        << outside;
  EXPECT_EQ(error(with("[0.0, 0.0, 0.01]", "[0.0, 0.0, 0.0199]")), "");
}

// Against an independent solver in the repository: tests/reference/rolling_reference.py
// integrates Kane & Levinson's body without drag in another formulation (body-frame vertical
// and angular velocity, Newton–Euler with the no-slip velocity eliminated, written from the
// mechanics, not from sim/), and tests/reference/kane-levinson.txt holds its output, four
// reversals in 50 s (rerun: `python3 tests/reference/rolling_reference.py >
// tests/reference/kane-levinson.txt`). Its two step sizes agree to 1e-7 s on the first two, as
// do our rk4 at 0.1 ms and dopri5 at 1e-12 (Adaptive.KaneLevinson…): 1e-6 s allows both errors
// ten times over. Each reversal's time depends on the whole state at the one before, so
// errors grow from one to the next: on the third and fourth our rk4 moves by 1–2e-6 s between
// steps of 0.1 and 0.05 ms (LongRuns below), hence 1e-5 s there. A wrong sign of a term, an
// inertia about the wrong point or a contact point off the surface moves these times by
// milliseconds or more.
TEST(Rolling, AgreesWithTheIndependentReferenceSolver) {
  std::ifstream table(RATTLEBACK_SOURCE_DIR "/tests/reference/kane-levinson.txt");
  ASSERT_TRUE(table) << "tests/reference/kane-levinson.txt is missing";
  std::string line, last;
  while (std::getline(table, line))
    if (!line.empty() && line[0] != '#') last = line;
  std::istringstream fields(last);
  double step = 0, time = 0;
  std::vector<double> reference;
  ASSERT_TRUE(fields >> step) << "unreadable: " << last;
  while (fields >> time) reference.push_back(time);
  ASSERT_EQ(reference.size(), 4u) << "unreadable: " << last;

  sim::SceneSpec spec = parse(kEllipsoidScene);
  spec.contact.air_drag = 0;
  spec.simulation.duration = 48.0;
  sim::Rollout rollout(build(spec));
  ASSERT_TRUE(rollout.advanceTo(48.0));
  const std::vector<double>& reversals = rollout.summary().reversals;
  ASSERT_EQ(reversals.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR(reversals[i], reference[i], i < 2 ? 1e-6 : 1e-5) << i;
}

// The misalignment is measured from the long axis, whichever of x and y it is: the least-inertia
// axis of the horizontal block [[Ixx, Ixy], [Ixy, Iyy]] of the tensor lies at θ from x with
// θ = ½ atan2(−2 Ixy, Iyy − Ixx) (the eigenvector of its smaller eigenvalue). A body long in x
// is misaligned by that θ (−10.9° here), not by 90° − |θ| read from y (not 89.2° for a
// body misaligned by 0.8°); the same body turned a quarter (long in y) by the same angle from
// y. Closed form: 1e-9° is rounding.
TEST(Ellipsoid, TheMisalignmentIsMeasuredFromTheLongAxis) {
  auto misalignment = [](const std::string& semi_axes, double Ixx, double Iyy, double Ixy) {
    char yaml[600];
    std::snprintf(yaml, sizeof yaml, R"(
body:
  shape: ellipsoid
  ellipsoid: {semi_axes: %s}
  inertia: [[%g, %g, 0.0], [%g, %g, 0.0], [0.0, 0.0, %g]]
  mass: 0.1
contact: {model: rolling}
initial: {spin: 5.0, tilt: [0.5, 0.5]}
simulation: {dt: 1.0e-4, duration: 1.0}
)",
                  semi_axes.c_str(), Ixx, Ixy, Ixy, Iyy, 0.98 * (Ixx + Iyy));
    auto loaded = scene::loadString(yaml, "m.yaml");
    EXPECT_TRUE(loaded) << loaded.error().text();
    auto model = scene::loadModel(loaded.value());
    EXPECT_TRUE(model) << model.error().text();
    return model->body->mass_properties.misalignment_deg;
  };
  const double Ixx = 2.0e-5, Iyy = 1.7e-4, Ixy = 3.0e-5;  // long in x: least inertia about x
  const double expected = 0.5 * std::atan2(-2 * Ixy, Iyy - Ixx) * 180 / M_PI;  // from x
  EXPECT_NEAR(expected, -10.9, 0.1);  // (the closed form's own value, for the reader)
  EXPECT_NEAR(misalignment("[0.15, 0.025, 0.02]", Ixx, Iyy, Ixy), expected, 1e-9);
  // Turned a quarter: x → y, y → −x, so Ixy changes sign and the angle is the same from y.
  EXPECT_NEAR(misalignment("[0.025, 0.15, 0.02]", Iyy, Ixx, -Ixy), expected, 1e-9);
}

// Semi-implicit Euler is refused where the body rolls (Kane & Levinson without
// dissipation lost 17.9 % of their energy in 60 s at 0.1 ms with it), naming what to use; a
// rolling scene that gives a step and no integrator gets rk4, which keeps the energy.
TEST(Ellipsoid, SymplecticIsRefusedWhereTheBodyRolls) {
  std::string yaml = kEllipsoidScene;
  auto compile = [](const std::string& text) {
    auto loaded = scene::loadString(text, "e.yaml");
    EXPECT_TRUE(loaded);
    return scene::loadModel(loaded.value());
  };
  const std::string named =
      std::regex_replace(yaml, std::regex("integrator: rk4"), "integrator: symplectic");
  auto refused = compile(named);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.error().text().rfind(
                "e.yaml:10: simulation.integrator symplectic does not keep the energy", 0),
            0u)
      << refused.error().text();
  EXPECT_NE(refused.error().text().find("use rk4 with a step or dopri5"), std::string::npos);
  auto automatic = compile(std::regex_replace(named, std::regex("model: rolling"),
                                              "model: auto, stiffness: 1e5, damping: 5"));
  EXPECT_FALSE(automatic);
  auto defaulted = compile(std::regex_replace(yaml, std::regex("integrator: rk4, "), ""));
  ASSERT_TRUE(defaulted) << defaulted.error().text();
  EXPECT_EQ(defaulted->integrator, sim::Integrator::Rk4);
}

// The amplification of one step on the undamped oscillator, by the methods' known stability
// functions (Hairer, Nørsett & Wanner I, §IV.2): explicit Euler |1 + iωh| = √(1 + (ωh)²);
// semi-implicit Euler 1 while ωh ≤ 2 and |t/2| + √(t²/4 − 1), t = 2 − (ωh)², beyond; rk4
// |R(iωh)| with R(z) = 1 + z + z²/2 + z³/6 + z⁴/24. 1e-12: rounding in a 2×2 matrix.
TEST(Stability, StepAmplificationIsTheMethodsStabilityFunction) {
  using sim::Integrator;
  for (double x : {0.1, 1.0, 1.9, 2.1, 2.8, 3.0}) {
    const double omega = 50, h = x / omega;
    EXPECT_NEAR(sim::stepAmplification(Integrator::Euler, omega, 0, h), std::sqrt(1 + x * x),
                1e-12);
    const double t = 2 - x * x;
    const double symplectic = x <= 2 ? 1.0 : std::abs(t) / 2 + std::sqrt(t * t / 4 - 1);
    EXPECT_NEAR(sim::stepAmplification(Integrator::Symplectic, omega, 0, h), symplectic, 1e-12)
        << x;
    const std::complex<double> z(0, x);
    const double rk4 = std::abs(1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0);
    EXPECT_NEAR(sim::stepAmplification(Integrator::Rk4, omega, 0, h), rk4, 1e-12) << x;
  }
  // Damping: explicit Euler's eigenvalues 1 − ζωh ± iωh√(1 − ζ²) have modulus² 1 − 2ζωh + (ωh)².
  EXPECT_NEAR(sim::stepAmplification(Integrator::Euler, 50, 0.3, 0.01),
              std::sqrt(1 - 2 * 0.3 * 0.5 + 0.25), 1e-12);
  // Tiny steps: a damped oscillator's step never amplifies (the discriminant's rounding once
  // made the pair real and |λ| = 1 + 1e-8 at ωh = 1e-9, refusing every step above 1e-12 s).
  for (double x : {1e-4, 1e-7, 1e-9, 1e-12})
    for (Integrator i : {Integrator::Symplectic, Integrator::Rk4})
      EXPECT_LE(sim::stepAmplification(i, 50, 0.1, x / 50), 1.0) << x;
}

// A body whose bottom is skewed (q ≠ 0) but has no dents has its curvature and inertia axes
// turned together: no growth either way (the linearised rates are ±1e-11 /s, the
// finite-difference Jacobian's noise, against 40 rad/s rocking), so no preferred direction —
// a new user's such body was called "preferred cw … predicted to reverse".
TEST(Theory, ASkewedBodyWithoutDentsPrefersNoDirection) {
  const sim::Model model = build(parse(R"(
units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 1.0, p: 0.5, q: 0.05, s: 0.03, top: 0.5}
  grid: {dx: 0.1, dy: 0.1, dz: 0.1}
  mass: 0.1
contact: {model: rolling}
initial: {spin: -5, tilt: [0.5, 0.5]}
simulation: {integrator: rk4, dt: 1.0e-3, duration: 5}
)"));
  EXPECT_EQ(sim::preferredDirection(model, 5), sim::Direction::None);
  // The default body's dents still give it one (its rates are 0.6 and 1.6 /s).
  const sim::Model dented = build(parse(kRolling));
  EXPECT_EQ(sim::preferredDirection(dented, 5), sim::Direction::Ccw);
}

// The averaged theory of the first reversal (docs/physics.md P8.5).
namespace {

struct Forecast {
  double predicted, measured;  ///< s
};

// `spec` rolling without drag, spun n rad/s and tilted θ° about both axes: the averaged
// theory's first reversal and a run's (rk4 at `dt`: its reversal times converge to 5 µs at
// 1e-3 s for the default body, docs/physics.md P7).
Forecast forecastAndRun(sim::SceneSpec spec, double n, double tilt_deg, double dt) {
  spec.contact.model = "rolling";
  spec.contact.air_drag = 0;
  spec.initial.spin = n;
  spec.initial.tilt = {tilt_deg, tilt_deg};
  spec.simulation = {"rk4", dt, sim::kUnset, 40.0};
  const sim::Model model = build(spec);
  const sim::ReversalForecast forecast = sim::forecastFirstReversal(model, n, 40.0);
  EXPECT_TRUE(forecast.time) << n;
  sim::Rollout rollout(model);
  rollout.advanceTo(model.duration);
  EXPECT_TRUE(rollout.summary().first_reversal_s) << n;
  return {forecast.time.value_or(0), rollout.summary().first_reversal_s.value_or(1)};
}

sim::SceneSpec kaneLevinson() {
  auto loaded = scene::loadFile(std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/kane-levinson.yaml");
  if (!loaded) ADD_FAILURE() << loaded.error().text();
  return loaded ? loaded->spec : sim::SceneSpec{};
}

}  // namespace

// The theory is first order in n²ρ/g (P8.5). Along runs that keep the rocking's energy in the
// same ratio to the spin's (tilt ∝ n), its relative error must then fall with n; we require 2×
// per halving (measured 2.4× and 4.5× for the default body, 3.8× and 4.0× for Kane &
// Levinson's) and under 1 % at the smallest spin (measured 0.07 % and 0.56 %). Both bodies,
// both directions of their reversing spin.
TEST(Forecast, ConvergesToRunsAsTheSpinGetsSmall) {
  struct Case {
    const char* name;
    sim::SceneSpec spec;
    double spin, tilt, dt;
  };
  for (const Case& c : {Case{"default body", parse(kRolling), -2, 0.4, 1e-3},
                        Case{"Kane & Levinson", kaneLevinson(), 2, 0.04, 2e-4}}) {
    std::vector<double> errors;
    for (double scale : {1.0, 0.5, 0.25}) {
      const Forecast f = forecastAndRun(c.spec, c.spin * scale, c.tilt * scale, c.dt);
      errors.push_back(std::abs(f.predicted - f.measured) / f.measured);
      SCOPED_TRACE(std::string(c.name) + " predicted " + std::to_string(f.predicted) +
                   " s, measured " + std::to_string(f.measured) + " s");
    }
    EXPECT_GT(errors[0] / errors[1], 2.0) << c.name << ": " << errors[0] << " " << errors[1];
    EXPECT_GT(errors[1] / errors[2], 2.0) << c.name << ": " << errors[1] << " " << errors[2];
    EXPECT_LT(errors[2], 0.01) << c.name;
  }
}

// Spun the preferred way with a tilt about one principal axis, the mode that grows (roll) gets
// its energy from the tilt through the spin's mixing of the modes, in proportion to n: counted
// from the modes at rest, where a pitch tilt puts next to nothing in roll, the forecasts were
// 42 % and 23 % late within the range and 109 % beyond it (a researcher's trial, the round-number
// body below, against its own solver as well as ours). Within the range (n²ρ/g 0.041 and 0.010)
// within 1 % of a run (measured 0.45 % and 0.06 % late); beyond it (0.65) within 10 % (9.4 %).
TEST(Forecast, ThePreferredWayIsForecastAsTheOther) {
  sim::SceneSpec spec = parse(R"(units: {length: 0.01}
body: {shape: paraboloid, paraboloid: {a: 2.0, p: 0.6, q: 0.0, s: 0.05, top: 0.5},
       dents: {scale: 0.4, at: [1.0, 7.0]}, grid: {dx: 0.1, dy: 0.1, dz: 0.1}, mass: 0.2}
contact: {model: rolling}
initial: {spin: 1, tilt: [0.25, 0.0]}
simulation: {integrator: rk4, dt: 1.0e-3, duration: 10}
)");
  for (const auto& [spin, tilt, within] :
       {std::tuple{1.0, 0.25, 0.01}, std::tuple{0.5, 0.125, 0.01}, std::tuple{4.0, 1.0, 0.1}}) {
    spec.initial.spin = spin;
    spec.initial.tilt = {tilt, 0};
    spec.simulation.duration = 2.5 / spin * 136;  // (the slowest reverses at 313 s)
    const sim::Model model = build(spec);
    ASSERT_EQ(sim::preferredDirection(model, spin), sim::Direction::Ccw);
    const sim::ReversalForecast forecast = sim::forecastFirstReversal(model, spin, model.duration);
    sim::Rollout rollout(model);
    rollout.advanceTo(model.duration);
    const auto run = rollout.summary().first_reversal_s;
    ASSERT_TRUE(forecast.time && run) << spin;
    EXPECT_NEAR(*forecast.time / *run, 1.0, within)
        << spin << " rad/s: " << *forecast.time << " s against " << *run << " s";
  }
}

// The averaged equations have no scale of their own without drag: spin halved and energies
// quartered take twice as long (1e-9: the Runge–Kutta step scales with the rates, so both
// integrations take the same steps in scaled time, and differ by rounding).
TEST(Forecast, HalfTheSpinAndAQuarterOfTheEnergyTakesTwiceAsLong) {
  sim::SceneSpec spec = parse(kRolling);
  spec.initial.tilt = {0.05, 0.05};
  sim::AveragedModes m = sim::forecastFirstReversal(build(spec), -2, 100).modes;
  const double full = *sim::averagedReversalTime(m, 100);
  m.spin /= 2;
  m.roll.energy /= 4;
  m.pitch.energy /= 4;
  const double half = *sim::averagedReversalTime(m, 100);
  EXPECT_NEAR(half / full, 2.0, 1e-9);
}

// The modes' shares are scaled to add up to the tilt's potential energy, which the averaged
// equations conserve with the spin's (spun, the modes are not orthogonal in the stiffness, and
// their energies add up to more: 1.6× at n²ρ/g = 0.65). 1e-12: rounding.
TEST(Forecast, TheTiltsEnergyIsSharedBetweenTheModes) {
  for (const sim::SceneSpec& spec : {parse(kRolling), kaneLevinson()}) {
    const sim::ReversalForecast f = sim::forecastFirstReversal(build(spec), 5, 10);
    EXPECT_GT(f.modes.roll.energy, 0);
    EXPECT_GT(f.modes.pitch.energy, 0);
    EXPECT_NEAR((f.modes.roll.energy + f.modes.pitch.energy) / f.tilt_energy, 1.0, 1e-12);
  }
}

// Deeper dents turn the principal axes further from the body's (misalignment 2° at the default
// 0.45, 9° at 0.7): each mode's share of the tilt's energy must still go with that mode's own
// growth rate. Named each by its own eigenvector, both shares went to roll from a scale of 0.65
// on, and no reversal was forecast where the run reversed at 0.70 s (a teacher's trial). Both
// shares stay, add up to the tilt's energy, and the forecast stays within P8.5's band beyond
// n²ρ/g = 0.15 (here 0.85): early by at most 12 % (measured 7.2–11.5 %; 11–15 % with the
// shares taken at rest).
TEST(Forecast, DeepDentsKeepEachModesShareWithItsOwnGrowth) {
  for (double scale : {0.45, 0.6, 0.65, 0.8}) {
    sim::SceneSpec spec = parse(kRolling);
    spec.body.dents->scale = scale;
    SCOPED_TRACE("dents.scale " + std::to_string(scale));
    const sim::ReversalForecast f = sim::forecastFirstReversal(build(spec), -5, 10);
    EXPECT_GT(f.modes.roll.energy, 0);
    EXPECT_GT(f.modes.pitch.energy, 0);
    EXPECT_NEAR((f.modes.roll.energy + f.modes.pitch.energy) / f.tilt_energy, 1.0, 1e-6);
    const Forecast run = forecastAndRun(spec, -5, 0.5, 1e-3);
    const double early = (run.measured - run.predicted) / run.measured;
    EXPECT_GT(early, 0) << run.predicted << " s against " << run.measured << " s";
    EXPECT_LT(early, 0.12) << run.predicted << " s against " << run.measured << " s";
  }
}

// One mode without drag has a closed form, n = −N tanh(k N (t − t_r)) (P8.5); the integration
// must agree to its own error (Runge–Kutta h⁴ at h = 1/100 of the rate's time: 1e-8, and the
// cubic's zero), and a decaying mode, or drag alone, never reverses.
TEST(Forecast, IntegrationAgreesWithTheClosedForm) {
  sim::AveragedModes m;
  m.spin = -5;
  m.inertia = 1e-4;
  m.pitch = {-0.32, 0, 7e-6};
  const double closed = *sim::oneModeReversalTime(m.spin, m.pitch.k, m.pitch.energy, m.inertia);
  EXPECT_NEAR(*sim::averagedReversalTime(m, 100), closed, 1e-7 * closed);
  EXPECT_NEAR(closed, 2.04867, 1e-5);  // artanh(5/N)/(0.32 N), N² = 25 + 0.14
  m.spin = 5;                          // k n > 0: the mode decays
  EXPECT_FALSE(sim::oneModeReversalTime(m.spin, m.pitch.k, m.pitch.energy, m.inertia));
  EXPECT_FALSE(sim::averagedReversalTime(m, 100));
  m.pitch.energy = 0;
  m.drag = 5.9e-6;
  EXPECT_FALSE(sim::averagedReversalTime(m, 100));
  // Beyond the horizon: none.
  m.spin = -5;
  m.drag = 0;
  m.pitch.energy = 7e-6;
  EXPECT_FALSE(sim::averagedReversalTime(m, 0.5 * closed));
}

// A spin that dies away is no reversal. The default body with its air drag, spun the preferred
// way, has its spin decay to 1e-163 rad/s by 6,270 s, where the product of two successive spins
// underflowed to zero and was forecast as a reversal there.
TEST(Forecast, ASpinThatDiesAwayIsNoReversal) {
  sim::SceneSpec spec = parse(kRolling);
  spec.contact.air_drag = 5.9e-6;
  spec.simulation.duration = 1e5;
  const sim::Model model = build(spec);
  EXPECT_FALSE(sim::forecastFirstReversal(model, 5, 1e5).time);
  EXPECT_TRUE(sim::forecastFirstReversal(model, -5, 1e5).time);  // the other way it reverses
}

// The linearised model's state matrix (rb.linearize, analyze --json "linearised"). Its tilt rows
// are kinematics alone: u̇ = −ω × u with u = (u_x, u_y, 1) and ω = (w_x, w_y, n) gives
// u̇_x = n u_y − w_y and u̇_y = w_x − n u_x, whatever the body. Its spin column is zero without
// air drag (this scene has none): every spin is a steady state, so nothing changes to first
// order when n does. And its
// eigenvalues are the ones analyze prints. 1e-8: the central differences' error is near 1e-9 of
// the entries (sim/analysis.cpp), and these entries are of order n and 1.
TEST(Theory, TheStateMatrixHasTheKinematicsOfTiltAndAnalyzesEigenvalues) {
  const sim::Model model = build(parse(kRollingScene));
  for (const double n : {-5.0, 0.0, 3.0}) {
    const sim::Linearisation l = sim::linearise(model, n);
    const Eigen::Matrix<double, 5, 5>& A = l.matrix;
    const double expected_u_x[5] = {0, n, 0, -1, 0}, expected_u_y[5] = {-n, 0, 1, 0, 0};
    for (int k = 0; k < 5; ++k) {
      EXPECT_NEAR(A(0, k), expected_u_x[k], 1e-8) << "n " << n << ", row u_x, column " << k;
      EXPECT_NEAR(A(1, k), expected_u_y[k], 1e-8) << "n " << n << ", row u_y, column " << k;
      EXPECT_NEAR(A(k, 4), 0, 1e-8 * A.norm()) << "n " << n << ", the spin's column, row " << k;
    }
    // The matrix's own eigenvalues, matched to the printed ones one by one (each nearest).
    const Eigen::VectorXcd mine =
        Eigen::EigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
    ASSERT_EQ(l.eigenvalues.size(), 5u);
    for (const auto& printed : l.eigenvalues) {
      double nearest = INFINITY;
      for (int i = 0; i < 5; ++i) nearest = std::min(nearest, std::abs(mine(i) - printed));
      EXPECT_LT(nearest, 1e-9 * std::max(1.0, std::abs(printed))) << "n " << n << ": " << printed;
    }
  }
  // The rows of the state table are the matrix's: five, names as Python and the JSON give them.
  EXPECT_EQ(sim::kLinearStates.size(), 5u);
  EXPECT_EQ(sim::kLinearStates[4].name, "w_z");
}

// --both's halves, left first (a teacher's trial: the order followed the scene's spin, and
// neither half said which way it was spun for the body): the spin against the body's preferred
// way on the left, however the scene spins it. The default body prefers ccw (−5 rad/s reverses,
// at 2.37 s), its mirror image cw; without dents it prefers neither and keeps the scene's spin
// on the left.
TEST(Theory, BothPutsTheSpinAgainstThePreferredWayOnTheLeft) {
  auto halves = [](std::string yaml, const std::string& from, const std::string& to, double spin) {
    if (!from.empty()) yaml.replace(yaml.find(from), from.size(), to);
    sim::Model model = testing_support::build(testing_support::parse(yaml));
    model.initial.spin = spin;
    return media::bothHalves(model);
  };
  using testing_support::kRolling;
  const std::string dents = "dents: {scale: 0.45, at: [0.73, 4.50], inset: 0.1}";
  for (double spin : {-5.0, 5.0}) {
    const auto shipped = halves(kRolling, "", "", spin);
    EXPECT_EQ(shipped[0].spin, -5) << "scene spun " << spin;
    EXPECT_EQ(shipped[0].way, "against its preferred way");
    EXPECT_EQ(shipped[1].spin, 5) << "scene spun " << spin;
    EXPECT_EQ(shipped[1].way, "its preferred way");
    const auto mirrored =
        halves(kRolling, dents, "dents: {scale: 0.45, at: [-0.73, 4.50], inset: 0.1}", spin);
    EXPECT_EQ(mirrored[0].spin, 5) << "mirrored, scene spun " << spin;
    EXPECT_EQ(mirrored[1].spin, -5) << "mirrored, scene spun " << spin;
    const auto none = halves(kRolling, dents, "", spin);
    EXPECT_EQ(none[0].spin, spin) << "no dents, scene spun " << spin;
    EXPECT_EQ(none[1].spin, -spin) << "no dents, scene spun " << spin;
    EXPECT_EQ(none[0].way, "");
    EXPECT_EQ(none[1].way, "");
  }
}

// A video played slower or faster says so after the scene's name, before what a title too long
// for the frame loses; at playback 1 the title is the still's.
TEST(Theory, AVideoNotInRealTimeSaysItsSpeedInItsTitle) {
  const std::string title = "mine: spun -5 rad/s, clockwise";
  EXPECT_EQ(media::titleWithPlayback(title, 1), title);
  EXPECT_EQ(media::titleWithPlayback(title, 0.5),
            "mine, at 0.5\u00d7 speed: spun -5 rad/s, clockwise");
  EXPECT_EQ(media::titleWithPlayback(title, 2), "mine, at 2\u00d7 speed: spun -5 rad/s, clockwise");
}

// P8.4: where the rocking grows spun the preferred way too, enough against drag, the body is
// predicted to reverse that way as well, and runs agree. The both-ways scene spun its preferred
// way (−8 rad/s, clockwise) grows 6.9 e-folds as drag slows the spin, where 3.0 take its 0.71°
// start to 14°: predicted, and it reverses (5.35 s, docs/scenes.md); spun −6 rad/s, 3.9:
// predicted, and it reverses (9.15 s); spun −5 rad/s it grows too, 2.6 e-folds: not predicted,
// and it does not reverse in 30 s (a count from the start's growth alone, 6.5, predicted it).
// The default body spun its preferred way (+5 rad/s) grows too, 0.7 e-folds: not predicted, and
// it does not reverse in 30 s. Without drag it is predicted (nothing slows the spin), and it
// reverses (Kane & Levinson's body too: their long scene, four reversals).
TEST(Theory, ReversingEitherWayIsPredictedWhereRunsDoIt) {
  auto shipped = [](const char* name) {
    auto loaded = scene::loadFile(std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/" + name);
    if (!loaded) ADD_FAILURE() << loaded.error().text();
    return loaded ? loaded->spec : sim::SceneSpec{};
  };
  auto reverses = [](const sim::Model& model) {
    sim::Rollout rollout(model);
    rollout.advanceTo(model.duration);
    return rollout.summary().first_reversal_s.has_value();
  };
  const sim::Model both = build(shipped("both-ways.yaml"));
  EXPECT_EQ(sim::preferredDirection(both, 8), sim::Direction::Cw);
  EXPECT_TRUE(sim::growsEitherWay(both, 8));
  EXPECT_TRUE(reverses(both));  // spun −8 rad/s, the way it prefers
  for (const double spin : {-6.0, -5.0}) {
    sim::SceneSpec slower = shipped("both-ways.yaml");
    slower.initial.spin = spin;
    slower.simulation.duration = 30;
    const sim::Model model = build(slower);
    EXPECT_EQ(sim::growsEitherWay(model, spin), reverses(model)) << "spun " << spin;
    EXPECT_EQ(reverses(model), spin == -6.0) << "spun " << spin;
  }

  sim::SceneSpec spec = shipped("rattleback.yaml");
  spec.initial.spin = 5;
  spec.simulation.duration = 30;
  const sim::Model drag = build(spec);
  EXPECT_EQ(sim::preferredDirection(drag, 5), sim::Direction::Ccw);
  EXPECT_FALSE(sim::growsEitherWay(drag, 5));
  EXPECT_FALSE(reverses(drag));

  spec.contact.air_drag = 0;
  const sim::Model free = build(spec);
  EXPECT_TRUE(sim::growsEitherWay(free, 5));
  EXPECT_TRUE(reverses(free));
}

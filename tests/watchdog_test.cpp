// The watchdog (sim/watchdog.hpp, docs/physics.md P6) on scripted step ends, without a body:
// when a run must stop and what it says, and which losses of contact are flights for the
// reversal rule (fed here to sim::ReversalDetector as a Rollout does).
#include "sim/watchdog.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sim/reversals.hpp"

namespace {

sim::StepEnd at(double t, double energy, std::optional<int> contacts = 1) {
  sim::StepEnd end;
  end.t = t;
  end.step = std::lround(t * 1000);
  end.energy = energy;
  end.contacts = contacts;
  return end;
}

// Feeds step ends every millisecond from 0 to `duration` s with `contacts(t)` points below the
// floor; returns the last flight.
template <typename Contacts>
double lastFlightOf(sim::Watchdog& dog, double duration, Contacts contacts) {
  for (int k = 1; k <= std::lround(duration * 1000); ++k) {
    const double t = k * 1e-3;
    EXPECT_FALSE(dog.observe(at(t, 1.0, contacts(t))));
  }
  return dog.lastFlight();
}

}  // namespace

TEST(Watchdog, EnergyFromNowhereStopsBeyondTenPercent) {
  // 10 % of the initial energy is the bound: 1.0999 J after 1 J runs, 1.1001 J stops.
  sim::Watchdog dog(0, 1.0, false, "try a smaller simulation.dt");
  EXPECT_FALSE(dog.observe(at(0.5, 1.0999)));
  const auto stop = dog.observe(at(0.6, 1.1001));
  ASSERT_TRUE(stop);
  EXPECT_EQ(stop->reason, sim::StopReason::EnergyGain);
  EXPECT_DOUBLE_EQ(stop->t, 0.6);
  EXPECT_EQ(stop->step, 600);
  EXPECT_NE(dog.message().find("the energy rose from 1 J to 1.1001 J (+10.01 %"), std::string::npos)
      << dog.message();
  EXPECT_NE(dog.message().find("at t = 0.6 s (step 600); try a smaller simulation.dt"),
            std::string::npos)
      << dog.message();
  // A negative total (the CM below the floor's reference) is bounded by its size: −2 J may
  // rise to −1.8 J.
  sim::Watchdog low(0, -2.0, false, "");
  EXPECT_FALSE(low.observe(at(0.1, -1.81)));
  EXPECT_TRUE(low.observe(at(0.2, -1.79)));
  // Losing energy never stops a run.
  sim::Watchdog loss(0, 1.0, false, "");
  EXPECT_FALSE(loss.observe(at(0.1, 0.01)));
}

TEST(Watchdog, NaNStopsAndNamesTheQuantity) {
  sim::Watchdog dog(0, 1.0, false, "try a smaller simulation.tolerance");
  sim::StepEnd end = at(0.25, std::numeric_limits<double>::quiet_NaN());
  end.non_finite = "the angular momentum";
  const auto stop = dog.observe(end);
  ASSERT_TRUE(stop);
  EXPECT_EQ(stop->reason, sim::StopReason::NonFinite);
  EXPECT_EQ(dog.message(),
            "the angular momentum became NaN or infinite at t = 0.25 s (step 250); try a smaller "
            "simulation.tolerance");
  // An energy that is NaN with finite state variables (cannot be compared) stops too, said to
  // be NaN (it read "the energy rose from 0.066 J to -nan J (-nan %, …)").
  sim::Watchdog nan_energy(0, 1.0, false, "try a smaller simulation.dt");
  const auto other = nan_energy.observe(at(0.1, std::numeric_limits<double>::quiet_NaN()));
  ASSERT_TRUE(other);
  EXPECT_EQ(other->reason, sim::StopReason::NonFinite);
  EXPECT_EQ(nan_energy.message(),
            "the energy became NaN or infinite at t = 0.1 s (step 100); try a smaller "
            "simulation.dt");
}

TEST(Watchdog, ARollingBodyOnTheRimStops) {
  sim::Watchdog dog(0, 1.0, false, "");
  sim::StepEnd end = at(1.5, 0.9, std::nullopt);
  EXPECT_FALSE(dog.observe(end));
  end.rim_tilt_deg = 72.5;
  const auto stop = dog.observe(end);
  ASSERT_TRUE(stop);
  EXPECT_EQ(stop->reason, sim::StopReason::OnRim);
  EXPECT_NE(dog.message().find("tipped onto the edge of its top (tilt 72.5 degrees) at t = 1.5 s"),
            std::string::npos)
      << dog.message();
  // On the rim, the energy's rise that comes of it is not the cause: a smaller step, which
  // that message advises, cannot help (a new user's body started at a tilt of 89°).
  sim::Watchdog risen(0, 1.0, false, "try a smaller simulation.dt");
  sim::StepEnd both = at(0.5, 1.2, std::nullopt);
  both.rim_tilt_deg = 89;
  ASSERT_TRUE(risen.observe(both));
  EXPECT_EQ(risen.message().rfind("the body tipped onto the edge of its top (tilt 89 degrees)", 0),
            0u)
      << risen.message();
  // Started there, it is said to start there.
  sim::Watchdog start(0, 1.0, false, "");
  sim::StepEnd first = at(0, 1.0, std::nullopt);
  first.rim_tilt_deg = 89;
  ASSERT_TRUE(start.observe(first));
  EXPECT_EQ(start.message(),
            "the body starts on the edge of its top (tilt 89 degrees), where rolling on its "
            "smooth bottom does not describe it; use contact.model auto, smooth or points (with a "
            "contact.stiffness, e.g. 2.0e4 N/m), or a smaller initial.tilt");
}

// (Times compare to 1e-12 s: the scripted step ends are k · 1e-3, rounded products.)
TEST(Watchdog, OnlyTenMillisecondsInTheAirIsAFlight) {
  // A hop: 5 ms with no point below the floor at 1 s. No flight.
  sim::Watchdog hop(0, 1.0, false, "");
  EXPECT_EQ(lastFlightOf(hop, 2, [](double t) { return t > 1.0 && t < 1.0055 ? 0 : 1; }),
            -std::numeric_limits<double>::infinity());
  // A bounce: 30 ms in the air from 1 s: a flight, whose last time is the bounce's last step.
  sim::Watchdog bounce(0, 1.0, false, "");
  EXPECT_NEAR(lastFlightOf(bounce, 2, [](double t) { return t > 1.0 && t < 1.0305 ? 0 : 1; }),
              1.030, 1e-12);
  // A drop: in the air from the start, a flight at once; it lasts until the landing at 0.1 s.
  sim::Watchdog drop(0, 1.0, true, "");
  EXPECT_EQ(drop.lastFlight(), 0.0);
  EXPECT_NEAR(lastFlightOf(drop, 1, [](double t) { return t < 0.1005 ? 0 : 1; }), 0.100, 1e-12);
  // Rolling (no contact count: the model keeps the body on the floor) never flies.
  sim::Watchdog rolling(0, 1.0, false, "");
  EXPECT_EQ(lastFlightOf(rolling, 1, [](double) { return std::optional<int>(); }),
            -std::numeric_limits<double>::infinity());
}

TEST(Watchdog, ADampedFloorThatCarriesNothingIsNoFlight) {
  // On a strongly damped floor the force max(0, k d − c v) is zero for up to 50 ms
  // while a point rises out of the floor; the point is still below it, so it is no flight and
  // the reversal 0.3 s later counts. The same history with those 50 ms in the air is a bounce,
  // and a crossing within 0.5 s of it does not count.
  auto run = [](bool in_air) {
    sim::Watchdog dog(0, 1.0, false, "");
    sim::ReversalDetector reversals(-5);
    const double h = 1e-3;
    auto n = [](double t) { return -5 + 5 * t / 1.3; };  // across at 1.3 s
    for (int k = 0; k < 3000; ++k) {
      const double t0 = k * h, t1 = (k + 1) * h;
      const bool lifting = t1 > 1.0 && t1 < 1.05;
      EXPECT_FALSE(dog.observe(at(t1, 1.0, lifting && in_air ? 0 : 1)));
      reversals.step(t0, n(t0), t1, n(t1), dog.lastFlight(), k + 1 == 3000, n);
    }
    return reversals.reversals();
  };
  const std::vector<double> floor = run(false);
  ASSERT_EQ(floor.size(), 1u);
  EXPECT_NEAR(floor[0], 1.3, 1e-9);
  EXPECT_TRUE(run(true).empty());
}

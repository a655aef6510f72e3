#include "sim/watchdog.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "sim/bottom_fit.hpp"

namespace sim {
namespace {

// Why a cap ends where the bottom itself ends (it meets the body's sides or rim there, short of
// the fit's slope limit): a toy that rocks further touches that edge.
std::string capEnd(const StepEnd& end) {
  if (!end.cap_meets_edge) return "";
  std::ostringstream said;
  said << " (the cap ends where the bottom stops being a smooth bowl, at its edge or where it "
          "meets the sides, short of the "
       << kFitSlopeLimitDeg
       << " degrees the fit would take: a printed toy rocking this far rocks onto that edge; a "
          "bowl that rises further before its edge gives a larger cap)";
  return said.str();
}

}  // namespace

Watchdog::Watchdog(double t0, double e0, bool in_air_at_start, std::string advice)
    : t0_(t0),
      e0_(e0),
      bound_(e0 + kEnergyGrowthBound * std::abs(e0) + 1e-12),
      advice_(std::move(advice)) {
  if (in_air_at_start) last_flight_ = in_air_since_ = t0;
}

void Watchdog::restartEnergy(double e0) {
  e0_ = e0;
  bound_ = e0 + kEnergyGrowthBound * std::abs(e0) + 1e-12;
}

std::optional<Stop> Watchdog::observe(const StepEnd& end) {
  if (end.non_finite) {
    std::ostringstream msg;
    msg << end.non_finite << " became NaN or infinite at t = " << end.t << " s (step " << end.step
        << "); " << advice_;
    message_ = msg.str();
    return Stop{StopReason::NonFinite, end.t, end.step};
  }
  // In the air: no point below the floor. Not "no force": a strongly damped floor's clipped
  // force max(0, k d − c v) is zero for tens of ms while a point rises out of it, and that was
  // taken for a bounce, hiding a reversal (k 1e8, c 2e4 N s/m). A start in the air
  // is a flight at once (a drop).
  if (end.contacts) {
    if (*end.contacts == 0) {
      if (!(in_air_since_ <= end.t)) in_air_since_ = end.t;
      if (end.t - in_air_since_ >= kFlightTime || in_air_since_ == t0_) last_flight_ = end.t;
    } else {
      in_air_since_ = std::numeric_limits<double>::quiet_NaN();
    }
  }
  // Rolling is a smooth surface rolling on the floor; tipped onto the edge of its flat top the
  // body pivots on an edge, which that model cannot describe (auto slides instead). Checked
  // before the energy, which such a state also makes rise (or NaN): a smaller step, which that
  // message advises, does not help here. A body started there is said to start there.
  if (end.rim_tilt_deg && end.cap_deg) {
    // A mesh body's smooth bottom is fitted to its mesh only where it can touch (§P11.4).
    // Only a body started there is helped by a smaller initial tilt: one that rocked there grew
    // its rocking itself (the both-ways scene's mesh, from 0.1° as from 0.5°).
    std::ostringstream msg;
    if (end.step == 0)
      msg << "the body starts beyond the mesh's fitted bottom (tilt " << *end.rim_tilt_deg
          << " degrees, beyond its cap of " << *end.cap_deg
          << " degrees), where the smooth bottom does not describe it; give a smaller "
             "initial.tilt (contact.model: points takes the whole mesh, with a "
             "contact.stiffness, but resting on many points it loses a spin within a second: "
             "your-own-body.md, \"The fitted bottom\")";
    else
      msg << "the contact point left the mesh's fitted bottom (tilt " << *end.rim_tilt_deg
          << " degrees, beyond its cap of " << *end.cap_deg << " degrees) at t = " << end.t
          << " s (step " << end.step << ")" << capEnd(end)
          << ": the body rocked further than the smooth bottom describes, and no contact "
             "model follows a mesh body on from there with its spin (contact.model: points, "
             "with a contact.stiffness, shows its rocking and sliding, but resting on many "
             "points it loses the spin within a second: your-own-body.md, \"The fitted "
             "bottom\")";
    message_ = msg.str();
    return Stop{StopReason::OnRim, end.t, end.step};
  }
  if (end.rim_tilt_deg) {
    std::ostringstream msg;
    if (end.step == 0)
      msg << "the body starts on the edge of its top (tilt " << *end.rim_tilt_deg
          << " degrees), where rolling on its smooth bottom does not describe it; use "
             "contact.model auto, smooth or points (with a contact.stiffness, e.g. 2.0e4 N/m), "
             "or a smaller initial.tilt";
    else
      msg << "the body tipped onto the edge of its top (tilt " << *end.rim_tilt_deg
          << " degrees) at t = " << end.t << " s (step " << end.step
          << "), where rolling on its smooth bottom no longer describes it; use "
             "contact.model auto, smooth or points (with a contact.stiffness, e.g. 2.0e4 N/m)";
    message_ = msg.str();
    return Stop{StopReason::OnRim, end.t, end.step};
  }
  if (!std::isfinite(end.energy)) {
    std::ostringstream msg;
    msg << "the energy became NaN or infinite at t = " << end.t << " s (step " << end.step << "); "
        << advice_;
    message_ = msg.str();
    return Stop{StopReason::NonFinite, end.t, end.step};
  }
  if (!(end.energy <= bound_)) {
    std::ostringstream msg;
    msg << "the energy rose from " << e0_ << " J to " << end.energy << " J (" << std::showpos
        << 100 * (end.energy - e0_) / std::abs(e0_) << std::noshowpos << " %, beyond the "
        << 100 * kEnergyGrowthBound << " % that nothing in the model can supply) at t = " << end.t
        << " s (step " << end.step << "); " << advice_;
    message_ = msg.str();
    return Stop{StopReason::EnergyGain, end.t, end.step};
  }
  return std::nullopt;
}

}  // namespace sim

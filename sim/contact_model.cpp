#include "sim/contact_model.hpp"

#include "sim/rolling.hpp"
#include "sim/step.hpp"
#include "sim/telemetry.hpp"

namespace sim {

ContactTraits contactTraits(ContactModel model) {
  switch (model) {
    case ContactModel::Points:
      return {.touch = Touch::Grid, .penalty_at_run_step = true};
    case ContactModel::Smooth:
      return {.touch = Touch::Spring, .penalty_at_run_step = true};
    case ContactModel::Rolling:
      return {.touch = Touch::Constraint, .rolls = true, .stops_on_rim = true};
    case ContactModel::Auto:
      return {.touch = Touch::Spring, .rolls = true, .switches = true};
  }
  return {};
}

void floorLoad(const Model& model, const Kinematics& k, Load& load) {
  switch (model.contact.model) {
    case ContactModel::Smooth:
      load.contact = smoothContact(model, k);
      return;
    case ContactModel::Rolling:
      load.contact = rollingContact(model, k, load.r_contact_world);
      return;
    case ContactModel::Points:
    case ContactModel::Auto:  // never integrated itself (its modes are); read as points
      load.contact = pointContact(model, k);
      return;
  }
}

Eigen::Vector3d cmVelocity(const Model& model, const State& s, const Kinematics& k,
                           const Load& load) {
  // Rolling: the CM moves as the constraint says, v = −ω × r.
  if (heldOnFloor(model.contact.model)) return -k.w_world.cross(load.r_contact_world);
  return s.v_world;
}

void holdOnFloor(const Model& model, State& s) {
  if (heldOnFloor(model.contact.model)) enforceRolling(model, s);
}

EndReading readEnd(const Model& model, const State& s, const Eigen::Vector3d& w_world) {
  // Rolling keeps the body on the floor and has no spring: its energy needs no contact solve
  // (the watchdog reads it every step or millisecond).
  if (heldOnFloor(model.contact.model)) return {rollingEnergy(model, s, w_world), std::nullopt};
  const Telemetry now = telemetryOf(model, s);
  return {now.energy, now.contacts};
}

}  // namespace sim

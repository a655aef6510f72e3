// The door to the contact models (docs/physics.md P4): everything that differs between
// contact.model points, smooth, rolling and auto is asked here, and answered by one `switch`
// per question in sim/contact_model.cpp, as Box2D v3 asks its shapes in shape.c. Each model's
// own mechanics lives in its own file (penalty points and the smooth lowest point in
// sim/contact.cpp, the rolling constraint in sim/rolling.cpp, auto's switching in
// sim/auto_switch.cpp); a new model adds its enum value and name (sim/model.hpp), its file,
// and its cases here. No other file of sim/ tests the model.
#pragma once

#include <Eigen/Dense>
#include <optional>

#include "sim/contact.hpp"
#include "sim/model.hpp"

namespace sim {

struct Load;

/// How a model's body meets the floor.
enum class Touch {
  Grid,        ///< a penalty spring at every grid point below the floor (points)
  Spring,      ///< one penalty spring at the lowest point of the smooth surface (smooth, auto)
  Constraint,  ///< the lowest point held on the floor by rolling without slipping (rolling)
};

/// What a contact model is, one row per model (contactTraits).
struct ContactTraits {
  Touch touch = Touch::Grid;
  /// The body rolls without slipping for all or part of a run (rolling, auto): a fixed step
  /// must resolve its rocking, rk4 is the default and symplectic Euler is refused
  /// (docs/physics.md P8).
  bool rolls = false;
  /// The floor's penalty spring and friction are integrated at the run's own step (points,
  /// smooth): a fixed step must resolve them (sim/stability.hpp). Auto integrates its smooth
  /// phases in sub-steps of their own (sim/switching.hpp: smoothStep).
  bool penalty_at_run_step = false;
  /// The run stops when the lowest point reaches the rim of a flat top, where the constraint
  /// cannot follow it (rolling; auto slides instead).
  bool stops_on_rim = false;
  /// The run changes between rolling and smooth as rolling holds or fails (auto).
  bool switches = false;
};

/// The row of `model` (one switch: the table of the models).
ContactTraits contactTraits(ContactModel model);

/// Whether the rolling constraint holds the body on the floor (Touch::Constraint): the CM's
/// velocity follows from ω, and states are put back on the constraint after each step.
inline bool heldOnFloor(ContactModel model) {
  return contactTraits(model).touch == Touch::Constraint;
}

/// The floor's load on the body at one instant (load.contact, and under rolling
/// load.r_contact_world, the CM → contact vector in world axes, m); gravity and drag are
/// added by loadsOn.
void floorLoad(const Model& model, const Kinematics& k, Load& load);

/// The CM's velocity, world axes, m/s: s.v_world, or under rolling v = −ω × r with r the
/// CM → contact vector of `load`.
Eigen::Vector3d cmVelocity(const Model& model, const State& s, const Kinematics& k,
                           const Load& load);

/// Puts a state back on the model's constraint (rolling: enforceRolling); nothing otherwise.
void holdOnFloor(const Model& model, State& s);

/// What the watchdog reads at a step's end (docs/physics.md P6).
struct EndReading {
  double energy_J = 0;          ///< kinetic + potential + elastic, J
  std::optional<int> contacts;  ///< points below the floor; none under rolling
};
/// The reading at state s with ω = w_world (rad/s, world axes) already at hand.
EndReading readEnd(const Model& model, const State& s, const Eigen::Vector3d& w_world);

}  // namespace sim

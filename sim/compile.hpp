// compile(spec) → Model, or an error naming the offending key. The body and the run are
// compiled apart: compileBody builds the immutable, shared Body once (the expensive part: the
// point grid and its mass properties); compileRun makes a run of it (cheap).
#pragma once

#include <memory>
#include <string>

#include "sim/model.hpp"
#include "sim/spec.hpp"
#include "util/result.hpp"

namespace sim {

/// Largest point-grid size compile() accepts (bounding-box estimate), points.
inline constexpr double kMaxGridPoints = 2.0e8;

/// Most fixed steps a run may take (simulation.duration / simulation.dt): about a day of
/// integrating at 1 µs a step, far past any run a toy's seconds need; more is a typo.
inline constexpr double kMaxSteps = 1e11;

/// Where the scene's body takes its mass properties from: body.mass_properties, or when the
/// scene leaves it out the grid's sums for contact.model points (the seed's rule, so its scenes
/// reproduce its report) and the continuum's integrals for the others.
MassSource massSourceOf(const SceneSpec& spec);

/// Which bodies keep their contact points: those of contact.model points (the default), or
/// every one (for a bench that runs the points model on another model's body).
enum class BodyPoints { ForContact, Always };

/// Checks the body keys and builds the shared body of `spec` (its body, units and, for the
/// mass properties' default, contact.model): mass properties (massSourceOf), contact points
/// relative to the CM (see BodyPoints), SI units.
rb::Result<std::shared_ptr<const Body>> compileBody(const SceneSpec& spec,
                                                    BodyPoints points = BodyPoints::ForContact);

/// What the body's point grid holds: counts and box, walked now (the default body's 120,000
/// columns in a few milliseconds), as only the points model keeps the points themselves.
GridCensus censusOf(const Body& body);

/// Checks the other keys and makes a run of `body`. Refuses a step that the contact stiffness
/// makes unstable, naming the largest stable one.
rb::Result<Model> compileRun(const SceneSpec& spec, std::shared_ptr<const Body> body);

/// compileBody + compileRun.
rb::Result<Model> compile(const SceneSpec& spec);

}  // namespace sim

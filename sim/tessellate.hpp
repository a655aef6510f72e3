// The closed surface of a body we have formulas for, as triangles (docs/physics.md §P11.5): what
// `rattleback export` writes as STL, and what a mesh body made from it is checked against.
#pragma once

#include <optional>

#include "sim/body.hpp"
#include "sim/mesh.hpp"
#include "sim/surface.hpp"
#include "util/result.hpp"

namespace sim {

/// The finest and coarsest `segments` tessellate takes: 8 around is still a closed solid; 4,096
/// around makes about 5.6 million triangles for the paraboloid, 280 MB of STL.
inline constexpr int kMinSegments = 8, kMaxSegments = 4096;
/// Export's default: 24,192 triangles for the paraboloid (1.2 MB of STL), its mass properties
/// within 1e-3 of the body's (docs/commands.md "rattleback export").
inline constexpr int kDefaultSegments = 192;

/// Whether the body's dents lie within it, so that tessellate (and `export`) make its solid on
/// `segments`: true for a body without dents. Unlike tessellate's refusal, it does not work out
/// how deep the dents could go (forty tessellations), which a sweep's `exports` column asks of
/// every row.
bool dentsLieWithin(const Surface& surface, const std::optional<Dents>& dents, int segments);

/// The body's closed surface, wound outwards, geometric frame, metres.
/// - Paraboloid: the bottom and the top are each a height over the rim's ellipse, sampled on
///   `segments` spokes and ⌈segments/6⌉ rings (so that the cells are about square when the
///   ellipse is mapped to a circle), which meet at the rim; the top follows the dents below it.
///   Refused when a dent cuts the bottom or the rim (the top is then not one height a column).
/// - Ellipsoid: `segments` around and segments/2 bands from pole to pole.
/// A mesh body has its own triangles: the caller exports those (the surface keeps only points).
/// `length_unit` (m: the scene's units.length) is the unit a refusal gives a place in.
rb::Result<TriangleMesh> tessellate(const Surface& surface, const std::optional<Dents>& dents,
                                    int segments, double length_unit = 1);

}  // namespace sim

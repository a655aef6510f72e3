// What `analyze` finds about a scene, as one JSON value: mass properties, rest, contact limits,
// the linearised theory and the preferred direction (docs/commands.md "rattleback analyze"). The
// command prints it; Python's analyze() returns it as a dict.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sim/body.hpp"
#include "sim/model.hpp"

namespace tasks {

/// The spin the theory is evaluated at: `spin` when given, else the scene's, else 5 rad/s.
double analysisSpin(const sim::Model& model, const std::optional<double>& spin);

/// Where the mass properties came from (body.mass_properties): scene, grid or continuum.
std::string massSourceText(const sim::Body& body);

/// How early the forecast of the first reversal came beyond the theory's range: the least and
/// largest error measured there, rounded out (docs/physics.md P8.5's table; a test reads it).
inline constexpr const char* kBeyondRangeEarlyBy = "3–17 %";

/// The analysis at `spin` rad/s.
nlohmann::json analysisJson(const sim::Model& model, double spin);

}  // namespace tasks

// JSON for the commands' machine-readable outputs, built with nlohmann::json (never by hand).
// Non-finite numbers (an infinite largest stable step, a NaN) are written as null: that is what
// nlohmann::json's dump() does with them, and docs/commands.md says so.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/model.hpp"
#include "sim/rollout.hpp"

namespace tasks {

/// The run's settings: contact, integrator and step or tolerance, duration, initial state.
nlohmann::json modelJson(const sim::Model& model);
/// What a run found: reversals, final spin and tilt, energy, steps, wall time, and why it
/// stopped when it did.
nlohmann::json runJson(const sim::RunSummary& run);

/// FNV-1a (64 bits) of the texts in turn, as 16 hex digits: a fingerprint of content.
std::string fingerprintOf(const std::vector<std::string>& texts);
/// The fingerprint of a scene file's content (scene::yamlContent: comments and layout do not
/// count), or "" when the file cannot be read.
std::string sceneFingerprint(const std::string& path);

}  // namespace tasks

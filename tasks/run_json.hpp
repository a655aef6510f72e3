// JSON for the commands' machine-readable outputs, built with nlohmann::json (never by hand).
// Non-finite numbers (an infinite largest stable step, a NaN) are written as null: that is what
// nlohmann::json's dump() does with them, and docs/commands.md says so.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "sim/model.hpp"
#include "sim/rollout.hpp"

namespace tasks {

/// The run's settings: contact, integrator and step or tolerance, duration, initial state.
nlohmann::json modelJson(const sim::Model& model);
/// What a run found: reversals, final spin and tilt, energy, steps, wall time, and why it
/// stopped when it did.
nlohmann::json runJson(const sim::RunSummary& run);

/// What a run's reader should be told beside its numbers: `code` names it for programs
/// ("cannot_stand", "implausible_mass", "dents_cut_nothing", "upright_start",
/// "sign_changed_uncounted", "energy_error", "floor_pulled"), `text` says it for people. simulate's
/// summary prints them, the sidecar's result lists them ("warnings"), and the report page shows
/// them beside the run (the page showed "no reversal in 5 s" for a run whose step was too large,
/// which only the terminal said).
struct RunWarning {
  std::string code;
  std::string text;
  /// Of the body itself, as analyze warns (it cannot stand, an implausible mass, dents that cut
  /// nothing), not of how the run went: said first, and after a run that stopped.
  bool aboutTheBody() const {
    return code == "cannot_stand" || code == "implausible_mass" || code == "dents_cut_nothing";
  }
};
/// The warnings of the body alone (each aboutTheBody()), first of runWarnings'.
std::vector<RunWarning> bodyWarnings(const sim::Model& model);
std::vector<RunWarning> runWarnings(const sim::Model& model, const sim::RunSummary& run);
nlohmann::json warningsJson(const std::vector<RunWarning>& warnings);

/// FNV-1a (64 bits) of the texts in turn, as 16 hex digits: a fingerprint of content.
std::string fingerprintOf(const std::vector<std::string>& texts);
/// Which scene an output was made from, as a fingerprint: the scene's content as read and the
/// values put in over it (--set, with_values), in order. The same from a run's sidecar
/// (scene_fingerprint, scene_values), or "" when it lacks them.
std::string madeFrom(const scene::Loaded& scene);
std::string madeFrom(const nlohmann::json& sidecar);

/// The fingerprint of a scene file's content (scene::yamlContent: comments and layout do not
/// count), or "" when the file cannot be read.
std::string sceneFingerprint(const std::string& path);

}  // namespace tasks

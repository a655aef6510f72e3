#include "tasks/run_json.hpp"

#include <cstdint>
#include <cstdio>
#include <string>

#include "scene/loader.hpp"
#include "tasks/outcome.hpp"

namespace tasks {

nlohmann::json modelJson(const sim::Model& model) {
  nlohmann::json j;
  j["contact"] = {{"model", std::string(rb::nameOf(model.contact.model))},
                  {"air_drag", model.contact.air_drag}};
  if (model.contact.model != sim::ContactModel::Rolling) {
    j["contact"]["stiffness"] = model.contact.stiffness;
    j["contact"]["damping"] = model.contact.damping;
    j["contact"]["friction"] = model.contact.friction;
    j["contact"]["friction_law"] = std::string(rb::nameOf(model.contact.law));
  }
  j["integrator"] = std::string(rb::nameOf(model.integrator));
  if (sim::isAdaptive(model.integrator))
    j["tolerance"] = model.tolerance;
  else
    j["dt_s"] = model.dt;
  j["duration_s"] = model.duration;
  j["gravity"] = model.gravity;
  j["initial"] = {
      {"spin", model.initial.spin},
      {"tilt_deg", {model.initial.tilt_x * 180 / M_PI, model.initial.tilt_y * 180 / M_PI}},
      {"height_m", model.initial.height}};
  j["mass_kg"] = model.body->mass;
  j["length_unit_m"] = model.length_unit;
  return j;
}

nlohmann::json runJson(const sim::RunSummary& run) {
  nlohmann::json j;
  const Outcome outcome = outcomeOf(run);
  j["status"] = std::string(rb::nameOf(outcome.ending));
  if (outcome.stop) {
    j["stopped_because"] = outcome.message;
    j["stop"] = {{"reason", std::string(rb::nameOf(outcome.stop->reason))},
                 {"t", outcome.stop->t},
                 {"step", outcome.stop->step}};
  }
  j["first_reversal_s"] = run.first_reversal_s ? nlohmann::json(*run.first_reversal_s) : nullptr;
  j["reversals_s"] = run.reversals;
  j["initial_spin"] = run.first.spin;
  j["final_spin"] = run.last.spin;
  j["final_tilt_deg"] = run.last.tilt_deg;
  j["max_tilt_deg"] = run.max_tilt_deg;
  j["energy_j"] = {{"initial", run.first.energy}, {"final", run.last.energy}};
  j["simulated_s"] = run.last.t;
  j["steps"] = run.steps;
  if (run.evaluations > 0) {
    j["rejected_steps"] = run.rejected;
    j["evaluations"] = run.evaluations;
  }
  nlohmann::json changes = nlohmann::json::array();
  for (const auto& [t, mode] : run.mode_changes)
    changes.push_back({{"t", t}, {"to", std::string(rb::nameOf(mode))}});
  j["mode_changes"] = changes;
  j["floor_pulled_s"] = run.floor_pulled_s ? nlohmann::json(*run.floor_pulled_s) : nullptr;
  j["wall_s"] = run.wall_s;
  return j;
}

std::string fingerprintOf(const std::vector<std::string>& texts) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const std::string& text : texts)
    for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
  return hex;
}

std::string sceneFingerprint(const std::string& path) {
  const auto text = scene::readSceneFile(path);
  return text ? fingerprintOf({scene::yamlContent(text.value())}) : "";  // as Loaded::content
}

}  // namespace tasks

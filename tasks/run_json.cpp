#include "tasks/run_json.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "scene/loader.hpp"
#include "sim/analysis.hpp"
#include "sim/contact_model.hpp"
#include "sim/integrator.hpp"
#include "sim/reversals.hpp"
#include "tasks/analysis.hpp"
#include "tasks/outcome.hpp"
#include "util/assets.hpp"

namespace tasks {

nlohmann::json modelJson(const sim::Model& model) {
  nlohmann::json j;
  j["contact"] = {{"model", std::string(rb::nameOf(model.contact.model))},
                  {"air_drag", model.contact.air_drag}};
  if (!sim::heldOnFloor(model.contact.model)) {
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
      {"height_m", model.initial.height},
      {"angular_velocity", {model.initial.w_x, model.initial.w_y, model.initial.spin}}};
  // The CM's velocity as the scene gave it (m/s, world axes); null: from no slip.
  const std::optional<Eigen::Vector3d>& v = model.initial.velocity;
  j["initial"]["velocity"] = v ? nlohmann::json{v->x(), v->y(), v->z()} : nlohmann::json(nullptr);
  j["mass_kg"] = model.body->mass;
  j["length_unit_m"] = model.length_unit;
  // A mesh body's fitted bottom and its residual (docs/physics.md §P11.4), null for others.
  j["fitted_bottom"] = fittedBottomJson(*model.body);
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
  j["friction_exceeded_s"] =
      run.friction_exceeded_s ? nlohmann::json(*run.friction_exceeded_s) : nullptr;
  j["friction_needed"] =
      std::isfinite(run.friction_needed) ? nlohmann::json(run.friction_needed) : nullptr;
  j["wall_s"] = run.wall_s;
  return j;
}

std::vector<RunWarning> bodyWarnings(const sim::Model& model) {
  std::vector<RunWarning> w;
  // As analyze warns: a body whose CM is above a radius of curvature at the rest contact
  // topples rather than rocks, and what follows is no rattleback's reversal.
  if ((model.body->surface.kind == sim::Surface::Kind::Paraboloid ||
       (model.body->surface.kind == sim::Surface::Kind::Mesh &&
        model.body->surface.mesh.fit.usable())) &&
      !sim::restOf(model).stable)
    w.push_back({"cannot_stand",
                 "the body cannot stand upright (its CM is above a radius of curvature at the rest "
                 "contact; `rattleback analyze` says by how much)"});
  // A mass no material gives a body of this size: a slip of units, as analyze warns.
  if (const auto implausible = implausibleMass(*model.body, model.length_unit))
    w.push_back({"implausible_mass", *implausible});
  // As analyze warns too: dents left outside a body made smaller make no rattleback.
  if (dentsCutShare(*model.body) == 0.0)
    w.push_back({"dents_cut_nothing",
                 "body.dents cut nothing: they lie wholly outside the body, which is the plain "
                 "paraboloid"});
  return w;
}

std::vector<RunWarning> runWarnings(const sim::Model& model, const sim::RunSummary& run) {
  std::vector<RunWarning> w = bodyWarnings(model);
  // Not spun, not tilted, not dropped: nothing moves (a student left initial: out, and read
  // "first reversal none" as the body's doing).
  if (model.initial.angularVelocityBody().isZero(0) && !model.initial.velocity &&
      model.initial.tilt_x == 0 && model.initial.tilt_y == 0 && model.initial.height == 0)
    w.push_back({"nothing_moves",
                 "not spun, not tilted (initial.spin 0, initial.tilt [0, 0]): the body rests as "
                 "it is; give initial: {spin: -5, tilt: [0.5, 0.5]}"});
  // An exactly upright spin is an equilibrium: the rocking that turns it back has nothing to
  // grow from.
  if (!run.first_reversal_s && model.initial.tilt_x == 0 && model.initial.tilt_y == 0 &&
      model.initial.height == 0 && model.initial.spin != 0)
    w.push_back({"upright_start",
                 "it started exactly upright, initial.tilt [0, 0]: with nothing to rock, no spin "
                 "reverses; try tilt: [0.5, 0.5]"});
  // A spin that ended the other way with no reversal counted reads as a contradiction ("first
  // reversal none" for n from −3 to +0.017 rad/s, or for a dropped body from −5 to +5.26): why
  // none was counted (docs/physics.md P7).
  if (!run.first_reversal_s && run.first.spin != 0 && run.last.spin * run.first.spin < 0) {
    const double threshold = sim::ReversalDetector::kFraction * std::abs(run.first.spin);
    char text[600];
    // All but still at the end (its kinetic energy a millionth of the start's): it came to rest
    // with a trace of spin the other way, and running longer shows nothing (the seed's body
    // fallen onto its side at 62.5°, +4e-6 rad/s from −10).
    const bool at_rest = run.last.kinetic <= 1e-6 * std::abs(run.first.kinetic);
    if (at_rest)
      std::snprintf(text, sizeof text,
                    "n ended the other way (%+.3g rad/s, from %+.3g) as the body came to rest "
                    "(kinetic energy %.2g J, from %.2g J): it stopped turning, no reversal",
                    run.last.spin, run.first.spin, run.last.kinetic, run.first.kinetic);
    else if (std::abs(run.last.spin) <= threshold)
      std::snprintf(text, sizeof text,
                    "n ended the other way (%+.3g rad/s, from %+.3g) but is not a reversal yet: "
                    "it must reach 1 %% of the initial spin (%.2g rad/s) the new way; run "
                    "longer to see",
                    run.last.spin, run.first.spin, threshold);
    else
      std::snprintf(text, sizeof text,
                    "n ended the other way (%+.3g rad/s, from %+.3g) but no crossing counted as a "
                    "reversal: one in the air or within %g s of a bounce counts as none, and one "
                    "that n takes back within %g s (%s P7)",
                    run.last.spin, run.first.spin, sim::ReversalDetector::kSettleTime,
                    sim::ReversalDetector::kHoldTime, rb::docPage("physics.md").c_str());
    w.push_back({"sign_changed_uncounted", text});
  }
  // Beyond 0.1 % the reversal time is off too (2.19 s against 1.844 s at dt 0.02, where the
  // energy fell by 9.9 %); rk4 at the shipped steps keeps it within 1e-8.
  const double change = (run.last.energy - run.first.energy) / std::abs(run.first.energy);
  if (model.contact.conservesEnergy() && std::abs(change) > 1e-3)
    w.push_back({"energy_error",
                 "this model keeps the energy exactly: the change is the integrator's error, and "
                 "the step is too large for this run; try a smaller simulation.dt, or "
                 "simulation.tolerance with dopri5"});
  if (run.floor_pulled_s) {
    char text[1000];
    std::snprintf(text, sizeof text,
                  "from %.4g s the floor had to pull the body down (normal force below 0): "
                  "rolling holds it to the floor, where a real body would lift off; run it "
                  "with contact.model: auto (and a contact.stiffness, e.g. 2.0e4 N/m) to let it "
                  "and compare (%s P4.6)",
                  *run.floor_pulled_s, rb::docPage("physics.md").c_str());
    w.push_back({"floor_pulled", text});
  }
  // The regularised friction damps the slip at the rate μ g/ε (docs/physics.md P4.3): a fixed
  // step longer than its time ε/(μ g) steps over it, and the run then depends on the step
  // (smooth with rk4: reversal 6.15, 6.22, 7.44 s and none as dt goes 1, 2, 6 and 8.9 ms,
  // converged 6.169 s; energy lost 4.8 % at 1 ms against 1.24 %). `auto` takes
  // smaller steps of its own in its smooth phases (sim::smoothStep).
  const sim::Contact& c = model.contact;
  const bool regularised_slip = sim::contactTraits(c.model).penalty_at_run_step &&
                                c.law == sim::FrictionLaw::Regularized && c.friction > 0 &&
                                model.gravity > 0;
  if (regularised_slip && !sim::isAdaptive(model.integrator)) {
    const double relax = c.slip_velocity / (c.friction * model.gravity);
    if (model.dt > relax) {
      char text[500];
      std::snprintf(text, sizeof text,
                    "simulation.dt %g s is %.2g times the regularised friction's time, "
                    "contact.slip_velocity / (friction g) = %.2g s: the step passes over the slip "
                    "it damps, and the run depends on the step (--check says by how much); take "
                    "dt at most %.2g s, or a tolerance",
                    model.dt, model.dt / relax, relax, relax);
      w.push_back({"slip_unresolved", text});
    }
  }
  if (run.friction_exceeded_s) {
    char text[1000];
    std::snprintf(text, sizeof text,
                  "from %.4g s rolling needed more friction than contact.friction %g gives (up "
                  "to %.2g of the normal force): rolling holds the contact point still whatever "
                  "that takes, where a real body would slip; run it with contact.model: auto "
                  "(and a contact.stiffness, e.g. 2.0e4 N/m) to let it slip: where its reversal "
                  "is this run's to a few hundredths, the slip does not matter "
                  "(%s P4.6)",
                  *run.friction_exceeded_s, model.contact.friction, run.friction_needed,
                  rb::docPage("physics.md").c_str());
    w.push_back({"friction_exceeded", text});
  }
  return w;
}

nlohmann::json warningsJson(const std::vector<RunWarning>& warnings) {
  nlohmann::json j = nlohmann::json::array();
  for (const RunWarning& w : warnings) j.push_back({{"code", w.code}, {"text", w.text}});
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

namespace {

std::string madeFromParts(const std::string& content_fingerprint,
                          const std::vector<std::pair<std::string, std::string>>& values) {
  std::vector<std::string> parts = {content_fingerprint};
  for (const auto& [key, yaml] : values) parts.insert(parts.end(), {"\n", key, "=", yaml});
  return fingerprintOf(parts);
}

}  // namespace

std::string madeFrom(const scene::Loaded& scene) {
  std::vector<std::pair<std::string, std::string>> values;
  for (const scene::KeyValue& kv : scene.values) values.emplace_back(kv.key, kv.yaml);
  return madeFromParts(fingerprintOf({scene.content}), values);
}

std::string madeFrom(const nlohmann::json& sidecar) {
  if (!sidecar.is_object()) return "";
  const auto content = sidecar.find("scene_fingerprint");
  if (content == sidecar.end() || !content->is_string()) return "";
  std::vector<std::pair<std::string, std::string>> values;
  if (const auto list = sidecar.find("scene_values"); list != sidecar.end() && list->is_array())
    for (const nlohmann::json& kv : *list) {
      if (!kv.is_object() || !kv.contains("key") || !kv.contains("value") ||
          !kv["key"].is_string() || !kv["value"].is_string())
        return "";
      values.emplace_back(kv["key"].get<std::string>(), kv["value"].get<std::string>());
    }
  return madeFromParts(content->get<std::string>(), values);
}

std::string sceneFingerprint(const std::string& path) {
  const auto text = scene::readSceneFile(path);
  return text ? fingerprintOf({scene::yamlContent(text.value())}) : "";  // as Loaded::content
}

}  // namespace tasks

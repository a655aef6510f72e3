#include "tasks/report/sidecars.hpp"

#include <cstdio>
#include <fstream>

#include "tasks/run_json.hpp"

namespace tasks::report {
namespace {

Number numberOf(const nlohmann::json& j) {
  return j.is_number() ? Number(j.get<double>()) : std::nullopt;
}

Text textOf(const nlohmann::json& j) {
  return j.is_string() ? Text(j.get<std::string>()) : std::nullopt;
}

std::vector<Number> numbersOf(const nlohmann::json& list) {
  std::vector<Number> out;
  if (list.is_array())
    for (const nlohmann::json& j : list) out.push_back(numberOf(j));
  return out;
}

std::optional<CheckRecord> checkRecordOf(const nlohmann::json& check) {
  if (!check.is_object()) return std::nullopt;
  return CheckRecord{textOf(field(check, "setting")), numbersOf(field(check, "reversal_errors_s")),
                     numberOf(field(check, "spin_error_rad_s"))};
}

// The scene the run was made from: its name, file, content and the values put in over it.
void readScene(const nlohmann::json& j, RunRecord& run) {
  run.scene = textOf(field(j, "scene"));
  run.scene_path = textOf(field(j, "scene_path"));
  run.from_text = j.is_object() && j.contains("scene_path") && j["scene_path"].is_null();
  run.scene_fingerprint = textOf(field(j, "scene_fingerprint"));
  const nlohmann::json& values = field(j, "scene_values");
  if (values.is_array())
    for (const nlohmann::json& kv : values)
      run.scene_values.emplace_back(textOf(field(kv, "key")), textOf(field(kv, "value")));
  run.made_from = madeFrom(j);
}

// What the run measured (the sidecar's "result").
void readResult(const nlohmann::json& r, RunRecord& run) {
  run.initial_spin = numberOf(field(r, "initial_spin"));
  run.simulated_s = numberOf(field(r, "simulated_s"));
  run.final_spin = numberOf(field(r, "final_spin"));
  run.energy_initial = numberOf(field(field(r, "energy_j"), "initial"));
  run.energy_final = numberOf(field(field(r, "energy_j"), "final"));
  run.reversals_s = numbersOf(field(r, "reversals_s"));
  run.first_reversal_s = numberOf(field(r, "first_reversal_s"));
  const nlohmann::json& warnings = field(r, "warnings");
  if (warnings.is_array())
    for (const nlohmann::json& w : warnings) run.warnings.push_back(textOf(field(w, "text")));
}

}  // namespace

std::optional<nlohmann::json> readJson(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

std::optional<RunRecord> readRunRecord(const fs::path& path) {
  const std::optional<nlohmann::json> j = readJson(path);
  if (!j) return std::nullopt;
  RunRecord run;
  run.command = stringOr(field(*j, "command"), "");
  readScene(*j, run);
  run.rate_hz = numberOf(field(*j, "rate_hz"));
  run.model_spin = numberOf(field(field(field(*j, "model"), "initial"), "spin"));
  run.model_angular_velocity =
      numbersOf(field(field(field(*j, "model"), "initial"), "angular_velocity"));
  run.mass_kg = numberOf(field(field(*j, "model"), "mass_kg"));
  readResult(field(*j, "result"), run);
  run.check = checkRecordOf(field(*j, "check"));
  return run;
}

// j[key] when j is an object that holds it, else null: a hand-edited or foreign file then
// shows "–" in the page instead of stopping the report.
const nlohmann::json& field(const nlohmann::json& j, const char* key) {
  static const nlohmann::json none;
  if (!j.is_object()) return none;
  const auto it = j.find(key);
  return it == j.end() ? none : *it;
}

std::string stringOr(const nlohmann::json& j, const std::string& otherwise) {
  return j.is_string() ? j.get<std::string>() : otherwise;
}

std::string stringOr(const Text& text, const std::string& otherwise) {
  return text ? *text : otherwise;
}

std::string number(const nlohmann::json& j, const char* format) {
  return number(numberOf(j), format);
}

std::string number(const Number& value, const char* format) {
  return value ? number(*value, format) : "–";
}

std::string number(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace tasks::report

// The JSON files the report reads: simulate's telemetry sidecar (NAME.csv.json) as one typed
// record, read in one place, and the helpers for the others (analyze --json, a sweep's sidecar).
// A hand-edited or foreign file never stops the report: what is missing or of another type is
// read as none, and shows as "–" on the page.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace tasks::report {

namespace fs = std::filesystem;

/// A number a file gives, or none where it gives none (or something else).
using Number = std::optional<double>;
/// A text a file gives, or none.
using Text = std::optional<std::string>;

/// simulate --check's estimate of a run's errors (the sidecar's "check").
struct CheckRecord {
  Text setting;                         ///< what the tighter run changed
  std::vector<Number> reversal_errors;  ///< s, one per reversal of the run
  Number spin_error;                    ///< rad/s, the largest of n(t)'s
};

/// simulate's telemetry sidecar, as the report uses it.
struct RunRecord {
  std::string command;     ///< "simulate" for a run ("sweep" for a sweep's table)
  Text scene;              ///< the scene as it was named
  Text scene_path;         ///< the scene file's path, where it was read from one
  bool from_text = false;  ///< scene_path null: made from text (Python's from_yaml), no file
  Text scene_fingerprint;  ///< of the scene file's content
  /// The values put in over the scene file (--set, with_values): key, value.
  std::vector<std::pair<Text, Text>> scene_values;
  std::string made_from;  ///< tasks::madeFrom of the sidecar: its content and values
  Number rate_hz;         ///< samples a simulated second
  Number model_spin;      ///< rad/s, the model's initial spin (model.initial.spin)
  /// rad/s, body axes: the model's initial ω (model.initial.angular_velocity); empty in a
  /// sidecar from before it was written.
  std::vector<Number> model_angular_velocity;
  Number mass_kg;                       ///< the body's mass (model.mass_kg)
  Number initial_spin;                  ///< rad/s, result.initial_spin
  Number simulated_s;                   ///< s
  Number final_spin;                    ///< rad/s
  Number energy_initial, energy_final;  ///< J
  std::vector<Number> reversals_s;      ///< every reversal (result.reversals_s), s
  Number first_reversal_s;              ///< s: the first, in a sidecar without the list
  std::vector<Text> warnings;           ///< what simulate's summary warned of
  std::optional<CheckRecord> check;     ///< present after simulate --check
};

/// A JSON file's content; none where it cannot be read or parsed.
std::optional<nlohmann::json> readJson(const fs::path& path);

/// The telemetry sidecar at `path`; none where it cannot be read or parsed (JSON of another
/// shape gives a record of nones).
std::optional<RunRecord> readRunRecord(const fs::path& path);

/// j[key] when j is an object that holds it, else null.
const nlohmann::json& field(const nlohmann::json& j, const char* key);

/// j as text when it is a string, else `otherwise`.
std::string stringOr(const nlohmann::json& j, const std::string& otherwise);
/// The text, else `otherwise`.
std::string stringOr(const Text& text, const std::string& otherwise);

/// A number as printf's `format` writes it; "–" for none.
std::string number(const nlohmann::json& j, const char* format);
std::string number(const Number& value, const char* format);
std::string number(double value, const char* format);

}  // namespace tasks::report

// Simulating a scene into telemetry: the run sampled at exact times, its rows in one table
// (columns with units), written as CSV with its JSON sidecar. What `rattleback simulate` and the
// Python package's simulate() both call, so that both write the same text.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "scene/loader.hpp"
#include "sim/model.hpp"
#include "sim/rollout.hpp"
#include "tasks/outcome.hpp"
#include "tasks/output.hpp"
#include "tasks/table.hpp"
#include "tasks/telemetry_arrays.hpp"
#include "tasks/telemetry_columns.hpp"
#include "util/result.hpp"

namespace tasks {

constexpr double kDefaultRate = 500;  ///< Hz: samples per simulated second when not given

/// Every column of the telemetry, in the CSV's order: the name, unit and meaning of each row of
/// telemetryTable().
std::span<const Column> telemetryColumns();

/// The CSV's header line (with its newline) and one row per sample (docs/commands.md "The telemetry
/// CSV").
std::string telemetryHeader();
void writeTelemetryRow(std::ostream& out, const sim::Telemetry& s);

/// Checks a sampling rate for a run of `duration` s: > 0, at most 1e7 Hz and 1e8 rows.
rb::Status checkRate(double rate, double duration);

struct SimulateOptions {
  double rate = kDefaultRate;  ///< samples per simulated second
  /// Asked before each sample: true ends the run there (Ctrl-C). May be empty.
  std::function<bool()> cancelled;
  /// Called with each sample, in time order (may be empty).
  std::function<void(const sim::Telemetry&)> each;
};

/// What a run did: its summary and why it ended.
struct SimulateResult {
  sim::RunSummary summary;
  Outcome outcome;
  std::int64_t rows = 0;  ///< samples handed to `each`
};

/// Runs `model` to its end (or a stop), sampling at t_k = k / rate and at the end.
SimulateResult simulate(const sim::Model& model, const SimulateOptions& options);

/// The scene a run was made of, as its sidecar records it: the file as named, and the values put
/// in over it (--set, Python's with_values; scene::Loaded::values), which `report` puts in
/// again to draw the body that ran, and the file's content as read (scene::Loaded::content),
/// whose fingerprint tells `report` whether the file still holds that scene.
struct RunScene {
  std::string file;
  std::vector<scene::KeyValue> values;
  std::string content;
  /// False for a scene made from text (Python's from_yaml, from_dict): `file` is then a name
  /// only, and the sidecar points to no file (a file of that name is not the scene that ran).
  bool has_file = true;
};

/// The sidecar X.csv.json: what the CSV is (program, scene, columns and units, the model) and
/// what the run found.
nlohmann::json telemetrySidecar(const RunScene& scene, const sim::Model& model, double rate,
                                const sim::RunSummary& run, std::int64_t rows,
                                const nlohmann::json& check = nullptr);

/// The telemetry and its sidecar as a run goes: each appears whole at commit() or not at all (no
/// sidecar beside a device such as /dev/stdout, even when the shell sends it to a file). CSV is
/// written as the run goes; arrays (.npz, .h5) are gathered and written at commit().
class TelemetryWriter {
 public:
  /// `format`: by the name's extension when not given (telemetryFormatOf).
  static rb::Result<TelemetryWriter> open(const std::string& path,
                                          std::optional<TelemetryFormat> format = {});
  TelemetryWriter(TelemetryWriter&&) noexcept;
  ~TelemetryWriter();
  void row(const sim::Telemetry& sample);
  /// Rows handed over at once (a finished run's samples), formatted in parallel chunks; written
  /// before this returns. `cancelled` (may be empty) is asked between chunks: true stops there,
  /// and false is returned (the file is then to be dropped, not committed).
  bool rows(std::span<const sim::Telemetry> samples, const std::function<bool()>& cancelled = {});
  std::int64_t rows() const { return rows_; }
  /// The rows the run will hand over, when known: arrays keep room for them (the CSV needs none).
  void expect(std::int64_t rows);
  /// Writes the sidecar and puts both files in place.
  /// `check`: the sidecar's "check" (checkJson), or null.
  rb::Status commit(const RunScene& scene, const sim::Model& model, double rate,
                    const sim::RunSummary& run, const nlohmann::json& check = nullptr);
  /// The same with the sidecar made already (telemetrySidecar, its rows these rows).
  rb::Status commit(const nlohmann::json& sidecar);

 private:
  // Rows are formatted in chunks by threads of the writer's own while the run goes on, and
  // written in order by whichever of them has the next chunk; the run's thread lends a hand only
  // when they fall behind, and at the end (formatting was half of a 10 kHz run:
  // docs/speed.md "Writing the output").
  class Pipeline;
  static constexpr std::size_t kChunkRows = 4096;
  TelemetryWriter(std::unique_ptr<Pipeline> pipeline, std::optional<AtomicOutput> meta);
  void handOff();
  std::unique_ptr<Pipeline> pipeline_;  ///< CSV; else the arrays below
  struct Arrays {
    TelemetryFormat format;
    AtomicOutput file;
    TelemetryArrays columns;
  };
  std::unique_ptr<Arrays> arrays_;
  std::optional<AtomicOutput> meta_;
  std::int64_t rows_ = 0;
  std::vector<sim::Telemetry> pending_;
};

/// Writes the samples as CSV at `path` and the sidecar at `path`.json, each whole or not at all
/// (no sidecar for a device such as /dev/stdout).
rb::Status writeTelemetry(const std::string& path, const RunScene& scene, const sim::Model& model,
                          double rate, const sim::RunSummary& run,
                          const std::vector<sim::Telemetry>& samples,
                          const nlohmann::json& check = nullptr);
/// The same with the sidecar made already (telemetrySidecar with rows = samples.size()).
/// `cancelled` (may be empty) is asked as the rows are written: true stops, and neither file is
/// put in place (what was there stays) — Python's to_csv on Ctrl-C.
/// `format`: by the name's extension when not given.
rb::Status writeTelemetry(const std::string& path, const std::vector<sim::Telemetry>& samples,
                          const nlohmann::json& sidecar,
                          const std::function<bool()>& cancelled = {},
                          std::optional<TelemetryFormat> format = {});

}  // namespace tasks

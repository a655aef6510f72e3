#include "tasks/simulate.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>

#include "tasks/output.hpp"
#include "tasks/run_json.hpp"
#include "util/format.hpp"

namespace tasks {
namespace {

// The CSV's columns, their units and meanings: the header is the first line of the file (so
// that every CSV reader takes it as the header); units and meanings go to the sidecar X.csv.json.
constexpr Column kColumns[] = {
    {"t", "s", "time"},
    {"spin", "rad/s", "n = w.z, + counter-clockwise seen from above"},
    {"energy", "J", "kinetic + potential + elastic"},
    {"kinetic", "J", "M v^2/2 + w.L/2"},
    {"potential", "J", "M g z of the centre of mass"},
    {"elastic", "J", "sum of k depth^2/2 over the contact springs"},
    {"tilt_deg", "deg", "angle between the body's z axis and the vertical"},
    {"x", "m", "centre of mass"},
    {"y", "m", "centre of mass"},
    {"z", "m", "centre of mass"},
    {"wx", "rad/s", "angular velocity, world axes"},
    {"wy", "rad/s", "angular velocity, world axes"},
    {"wz", "rad/s", "angular velocity, world axes"},
    {"Lz", "kg m^2/s", "vertical angular momentum about the centre of mass"},
    {"contacts", "", "count of contact points below the floor"},
    {"normal_force", "N", "total normal force of the floor"},
    {"mode", "",
     "the contact model integrated: points, smooth or rolling (contact.model auto "
     "switches between rolling and smooth)"},
    {"qw", "",
     "attitude: unit quaternion (qw, qx, qy, qz), scalar first, rotating body axes into "
     "world axes (world z up); continuous in time (q and -q are the same rotation)"},
    {"qx", "", "attitude quaternion, x part (see qw)"},
    {"qy", "", "attitude quaternion, y part (see qw)"},
    {"qz", "", "attitude quaternion, z part (see qw)"},
};

}  // namespace

std::span<const Column> telemetryColumns() {
  return kColumns;
}

std::string telemetryHeader() {
  return csvHeader(kColumns) + "\n";
}

Eigen::Quaterniond attitude(const sim::Telemetry& s) {
  // q and −q are the same rotation; the integrated quaternion is kept as it is (never flipped
  // to qw ≥ 0), so that the columns are continuous in time as the body turns round and round.
  return s.orientation.normalized();
}

namespace {

// Room for one row: 20 numbers, the contacts and the mode.
constexpr std::size_t kRowChars = 24 * kNumberChars;

// Every number exactly (shortest round trip), written straight into one buffer: at 10 kHz
// printf's formatting was most of a run's time (issue 27).
char* formatRow(char* line, const sim::Telemetry& s) {
  const Eigen::Quaterniond q = attitude(s);
  char* at = line;
  const auto put = [&](double value) {
    at = writeNumber(at, value);
    *at++ = ',';
  };
  for (double v :
       {s.t, s.spin, s.energy, s.kinetic, s.potential, s.elastic, s.tilt_deg, s.x_world.x(),
        s.x_world.y(), s.x_world.z(), s.w_world.x(), s.w_world.y(), s.w_world.z(), s.L_world.z()})
    put(v);
  at = std::to_chars(at, at + kNumberChars, s.contacts).ptr;
  *at++ = ',';
  put(s.normal_force);
  const std::string_view mode = rb::nameOf(s.mode);
  at = std::copy(mode.begin(), mode.end(), at);
  *at++ = ',';
  for (double v : {q.w(), q.x(), q.y(), q.z()}) put(v);
  at[-1] = '\n';
  return at;
}

// A chunk of rows as text at `out` (room for kRowChars a row); returns its length.
std::size_t formatRows(std::span<const sim::Telemetry> rows, char* out) {
  char* at = out;
  for (const sim::Telemetry& s : rows) at = formatRow(at, s);
  return static_cast<std::size_t>(at - out);
}

}  // namespace

void writeTelemetryRow(std::ostream& out, const sim::Telemetry& s) {
  char line[kRowChars];
  out.write(line, formatRow(line, s) - line);
}

rb::Status checkRate(double rate, double duration) {
  if (!(rate > 0) || !std::isfinite(rate) || rate > 1e7)
    return rb::Status::fail("rate: samples per simulated second must be > 0 and at most 1e7, not " +
                            rb::show(rate));
  // A row of the CSV is about 300 bytes (21 columns of shortest round-trip numbers): 1e7 rows
  // are about 3 GB, more than any plot or fit needs; a rate typed with too many zeros (1e7 for
  // 1e3: 7.4 GB over 2 s, written without a word before) is refused before anything is written.
  if (duration * rate > 1e7)
    return rb::Status::fail("rate: " + rb::show(rate) + " Hz over " + rb::show(duration) +
                            " s is " + rb::show(std::floor(duration * rate) + 1) + " rows, about " +
                            rb::show(std::round(duration * rate * 300 / 1e8) / 10) +
                            " GB of CSV; at most 1e7 rows (about 3 GB): choose a lower rate");
  return {};
}

SimulateResult simulate(const sim::Model& model, const SimulateOptions& options) {
  SimulateResult result;
  sim::Rollout rollout(model);
  std::optional<double> pulled, slipped;
  double needed = std::numeric_limits<double>::quiet_NaN();
  const bool rolling = model.contact.model == sim::ContactModel::Rolling;
  for (double t : sim::sampleTimes(model.duration, options.rate)) {
    if (options.cancelled && options.cancelled()) rollout.requestStop();
    if (!rollout.advanceTo(t)) break;
    const sim::Telemetry sample = rollout.sampleAt(t);
    // What rolling's constraint asks of the floor, which it gives whatever it is (P4.5).
    if (rolling && !pulled && sample.normal_force < 0) pulled = sample.t;
    if (rolling && sample.normal_force > 0) {
      const double ratio = sample.friction_force / sample.normal_force;
      if (!(ratio <= needed)) needed = ratio;  // (and the first: NaN)
      if (!slipped && ratio > model.contact.friction) slipped = sample.t;
    }
    if (options.each) options.each(sample);
    ++result.rows;
  }
  result.summary = rollout.summary();
  result.summary.floor_pulled_s = pulled;
  result.summary.friction_exceeded_s = slipped;
  result.summary.friction_needed = needed;
  result.outcome = outcomeOf(result.summary);
  return result;
}

nlohmann::json telemetrySidecar(const RunScene& scene, const sim::Model& model, double rate,
                                const sim::RunSummary& run, std::int64_t rows,
                                const nlohmann::json& check) {
  nlohmann::json j;
  j["program"] = "rattleback " RATTLEBACK_VERSION;
  j["command"] = "simulate";
  j["scene"] = scene.file;
  // Absolute too, so that `report` run from another folder finds the body for its 3D player;
  // null for a scene made from text, which has no file (report then draws no player for it).
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(scene.file, ec);
  if (!scene.has_file)
    j["scene_path"] = nullptr;
  else
    j["scene_path"] = ec ? scene.file : absolute.lexically_normal().string();
  // The scene's content as it was read for the run, so that `report` can tell when the file has
  // been edited since and its 3D player would draw another body than the one simulated (for a
  // scene with no file, the text run: the same text read from a file gives the same).
  j["scene_fingerprint"] = fingerprintOf({scene.content});
  // The values put in over the file, in order ({"key", "value": YAML text}): the file and these
  // make the scene as run.
  j["scene_values"] = nlohmann::json::array();
  for (const scene::KeyValue& kv : scene.values)
    j["scene_values"].push_back({{"key", kv.key}, {"value", kv.yaml}});
  j["columns"] = columnsJson(kColumns);
  j["rows"] = rows;
  j["rate_hz"] = rate;
  j["model"] = modelJson(model);
  j["result"] = runJson(run);
  j["result"]["warnings"] = warningsJson(runWarnings(model, run));
  if (!check.is_null()) j["check"] = check;
  return j;
}

rb::Result<TelemetryWriter> TelemetryWriter::open(const std::string& path) {
  if (auto made = makeParentFolder(path); !made) return made.error();
  auto csv = AtomicOutput::open(path);
  if (!csv) return csv.error();
  std::optional<AtomicOutput> meta;
  if (!rb::outputPlace(path).temporary.empty()) {
    auto opened = AtomicOutput::open(path + ".json");
    if (!opened) return opened.error();
    meta.emplace(std::move(opened).value());
  }
  csv->stream() << telemetryHeader();
  return TelemetryWriter(std::move(csv).value(), std::move(meta));
}

void TelemetryWriter::row(const sim::Telemetry& sample) {
  pending_.push_back(sample);
  ++rows_;
  if (pending_.size() >= kChunkRows) handOff();
}

std::unique_ptr<char[]> TelemetryWriter::takeText() {
  if (spareText_.empty()) return std::unique_ptr<char[]>(new char[kChunkRows * kRowChars]);
  std::unique_ptr<char[]> text = std::move(spareText_.back());
  spareText_.pop_back();
  return text;
}

void TelemetryWriter::handOff() {
  if (pending_.empty()) return;
  formatting_.push_back(
      std::async(std::launch::async, [rows = std::move(pending_), text = takeText()]() mutable {
        const std::size_t size = formatRows(rows, text.get());
        rows.clear();
        return Formatted{std::move(text), size, std::move(rows)};
      }));
  pending_ = {};
  if (!spareRows_.empty()) {
    pending_ = std::move(spareRows_.back());
    spareRows_.pop_back();
  }
  pending_.reserve(kChunkRows);
  writeFormatted(kChunksInFlight);
}

void TelemetryWriter::rows(std::span<const sim::Telemetry> samples) {
  handOff();
  // Chunks formatted straight from the caller's samples (they outlive the writes: each chunk
  // is written before this returns), not copied into chunks of the writer's own first.
  for (std::size_t at = 0; at < samples.size(); at += kChunkRows) {
    const auto part = samples.subspan(at, std::min(kChunkRows, samples.size() - at));
    formatting_.push_back(std::async(std::launch::async, [part, text = takeText()]() mutable {
      const std::size_t size = formatRows(part, text.get());
      return Formatted{std::move(text), size, {}};
    }));
    writeFormatted(kChunksInFlight);
  }
  writeFormatted(0);
  rows_ += static_cast<std::int64_t>(samples.size());
}

void TelemetryWriter::writeFormatted(std::size_t keep) {
  while (formatting_.size() > keep) {
    Formatted chunk = formatting_.front().get();
    formatting_.pop_front();
    csv_.stream().write(chunk.text.get(), static_cast<std::streamsize>(chunk.size));
    spareText_.push_back(std::move(chunk.text));
    if (chunk.rows.capacity() > 0) spareRows_.push_back(std::move(chunk.rows));
  }
}

rb::Status TelemetryWriter::commit(const RunScene& scene, const sim::Model& model, double rate,
                                   const sim::RunSummary& run, const nlohmann::json& check) {
  handOff();  // rows_ counts the rows still pending too
  return commit(meta_ ? telemetrySidecar(scene, model, rate, run, rows_, check) : nullptr);
}

rb::Status TelemetryWriter::commit(const nlohmann::json& sidecar) {
  handOff();
  writeFormatted(0);
  if (meta_) meta_->stream() << sidecar.dump(2) << "\n";
  if (auto e = csv_.commit(); !e) return e;
  return meta_ ? meta_->commit() : rb::Status();
}

rb::Status writeTelemetry(const std::string& path, const RunScene& scene, const sim::Model& model,
                          double rate, const sim::RunSummary& run,
                          const std::vector<sim::Telemetry>& samples, const nlohmann::json& check) {
  auto writer = TelemetryWriter::open(path);
  if (!writer) return writer.error();
  writer->rows(samples);
  return writer->commit(scene, model, rate, run, check);
}

rb::Status writeTelemetry(const std::string& path, const std::vector<sim::Telemetry>& samples,
                          const nlohmann::json& sidecar) {
  auto writer = TelemetryWriter::open(path);
  if (!writer) return writer.error();
  writer->rows(samples);
  return writer->commit(sidecar);
}

}  // namespace tasks

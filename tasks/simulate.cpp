#include "tasks/simulate.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <mutex>
#include <ostream>
#include <thread>

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
  put(s.t);
  const char* spin = at;
  put(s.spin);
  const std::size_t spin_chars = static_cast<std::size_t>(at - spin);
  for (double v : {s.energy, s.kinetic, s.potential, s.elastic, s.tilt_deg, s.x_world.x(),
                   s.x_world.y(), s.x_world.z(), s.w_world.x(), s.w_world.y()})
    put(v);
  // wz is the spin n = ω·ẑ (sim::telemetryOf): its text again, not formatted twice.
  if (std::bit_cast<std::uint64_t>(s.w_world.z()) == std::bit_cast<std::uint64_t>(s.spin))
    at = std::copy_n(spin, spin_chars, at);
  else
    put(s.w_world.z());
  put(s.L_world.z());
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

// The chunks of a CSV on their way to the file. Each chunk is formatted by whichever thread
// takes it first (the pipeline's workers; the caller's thread when it waits for them), and the
// front chunk, once formatted, is written by whichever is free, so that the file is written in
// order while later chunks are still being formatted. The caller's thread hands chunks over and
// goes on with its run: on two cores the run keeps one and formatting and writing the other, and
// both share the rest once the run is over (docs/speed.md "Writing beside the run (2026-11-27,
// eleventh session; issue 27)").
constexpr unsigned kMaxWorkers = 7;  // more than a few chunks at once gain nothing

class TelemetryWriter::Pipeline {
 public:
  Pipeline(AtomicOutput csv, unsigned workers) : csv_(std::move(csv)), workerCount_(workers) {
    // The workers take buffers back without allocating (a thread's first allocation makes it an
    // arena of its own: 0.1 ms).
    spareText_.reserve(2 * kMaxWorkers + 4);
    spareRows_.reserve(2 * kMaxWorkers + 4);
  }
  ~Pipeline() {
    {
      std::lock_guard lock(mutex_);
      leaving_ = true;  // an abandoned file: what is left unformatted stays so
    }
    changed_.notify_all();
    for (std::thread& worker : workers_) worker.join();
  }

  /// Queues `rows` (the writer's own, kept in `own`, or the caller's, which must outlive their
  /// writing), and then helps until at most `inFlight` chunks are unwritten.
  void push(std::vector<sim::Telemetry> own, std::span<const sim::Telemetry> rows) {
    std::unique_lock lock(mutex_);
    std::unique_ptr<char[]> text;  // made before the chunk is queued, where a worker would see it
    if (spareText_.empty()) {
      text.reset(new char[kChunkRows * kRowChars]);
    } else {
      text = std::move(spareText_.back());
      spareText_.pop_back();
    }
    Chunk& chunk = chunks_.emplace_back();
    chunk.text = std::move(text);
    chunk.own = std::move(own);
    chunk.rows = chunk.own.empty() ? rows : std::span<const sim::Telemetry>(chunk.own);
    // The workers start with a second chunk: a run of fewer rows is formatted by its own thread
    // at the end, with no thread started for it (starting one cost a short run's start-up a
    // fifth; bench/targets.py's start-up line).
    if (workers_.empty() && chunks_.size() + written_ >= 2)
      for (unsigned i = 0; i < workerCount_; ++i) workers_.emplace_back([this] { work(); });
    changed_.notify_one();
    helpUntil(lock, inFlight());
  }

  /// Helps until every chunk is written; then the file has all the rows queued.
  void drain() {
    std::unique_lock lock(mutex_);
    helpUntil(lock, 0);
  }

  /// A buffer for the writer's next chunk of rows (one a written chunk had).
  std::vector<sim::Telemetry> spareRows() {
    std::lock_guard lock(mutex_);
    if (spareRows_.empty()) return {};
    std::vector<sim::Telemetry> rows = std::move(spareRows_.back());
    spareRows_.pop_back();
    return rows;
  }

  /// Once drained: puts the file in place (the error of a failed write, as its writer saw it).
  rb::Status commit() {
    if (writeErrno_ != 0) errno = writeErrno_;
    return csv_.commit();
  }

 private:
  struct Chunk {
    std::vector<sim::Telemetry> own;
    std::span<const sim::Telemetry> rows;
    std::unique_ptr<char[]> text;
    std::size_t size = 0;
    enum class State { queued, formatting, formatted } state = State::queued;
  };

  // Chunks unwritten before the caller's thread stops its own work to help: enough that the
  // workers always have one to take, few enough that memory stays bounded (a chunk holds 4096
  // samples, 0.8 MB, and room for their text, 3 MB).
  std::size_t inFlight() const { return 2 * workerCount_ + 2; }

  // One piece of work, if there is one: the front chunk written, or a queued chunk formatted.
  // Called and returns with `lock` held; works with it released.
  bool step(std::unique_lock<std::mutex>& lock) {
    if (!writing_ && !chunks_.empty() && chunks_.front().state == Chunk::State::formatted) {
      writing_ = true;
      Chunk& chunk = chunks_.front();  // (a deque's elements stay put as others come and go)
      lock.unlock();
      std::ostream& out = csv_.stream();
      out.write(chunk.text.get(), static_cast<std::streamsize>(chunk.size));
      const int failed = out ? 0 : errno;
      lock.lock();
      if (failed != 0 && writeErrno_ == 0) writeErrno_ = failed;
      spareText_.push_back(std::move(chunk.text));
      if (chunk.own.capacity() > 0) {
        chunk.own.clear();
        spareRows_.push_back(std::move(chunk.own));
      }
      chunks_.pop_front();
      ++written_;
      writing_ = false;
      changed_.notify_all();
      return true;
    }
    for (Chunk& chunk : chunks_) {
      if (chunk.state != Chunk::State::queued) continue;
      chunk.state = Chunk::State::formatting;
      lock.unlock();
      chunk.size = formatRows(chunk.rows, chunk.text.get());
      lock.lock();
      chunk.state = Chunk::State::formatted;
      changed_.notify_all();
      return true;
    }
    return false;
  }

  void helpUntil(std::unique_lock<std::mutex>& lock, std::size_t unwritten) {
    while (chunks_.size() > unwritten)
      if (!step(lock)) changed_.wait(lock);
  }

  void work() {
    std::unique_lock lock(mutex_);
    while (!leaving_)
      if (!step(lock)) changed_.wait(lock);
  }

  AtomicOutput csv_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<Chunk> chunks_;  // in the file's order: the front is written next
  std::size_t written_ = 0;   // chunks
  bool writing_ = false;
  bool leaving_ = false;
  unsigned workerCount_;
  int writeErrno_ = 0;
  std::vector<std::unique_ptr<char[]>> spareText_;
  std::vector<std::vector<sim::Telemetry>> spareRows_;
  std::vector<std::thread> workers_;  // last: they start once the rest is made
};

TelemetryWriter::TelemetryWriter(std::unique_ptr<Pipeline> pipeline,
                                 std::optional<AtomicOutput> meta)
    : pipeline_(std::move(pipeline)), meta_(std::move(meta)) {}
TelemetryWriter::TelemetryWriter(TelemetryWriter&&) noexcept = default;
TelemetryWriter::~TelemetryWriter() = default;

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
  // All cores but the run's (one at least).
  const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
  auto pipeline =
      std::make_unique<Pipeline>(std::move(csv).value(), std::min(cores - 1, kMaxWorkers));
  return TelemetryWriter(std::move(pipeline), std::move(meta));
}

void TelemetryWriter::row(const sim::Telemetry& sample) {
  if (pending_.capacity() == 0) {
    pending_ = pipeline_->spareRows();
    pending_.reserve(kChunkRows);
  }
  pending_.push_back(sample);
  ++rows_;
  if (pending_.size() >= kChunkRows) handOff();
}

void TelemetryWriter::handOff() {
  if (pending_.empty()) return;
  pipeline_->push(std::move(pending_), {});
  pending_ = {};
}

bool TelemetryWriter::rows(std::span<const sim::Telemetry> samples,
                           const std::function<bool()>& cancelled) {
  handOff();
  // Chunks formatted straight from the caller's samples, not copied into the writer's own first.
  for (std::size_t at = 0; at < samples.size(); at += kChunkRows) {
    if (cancelled && cancelled()) {
      pipeline_->drain();  // the chunks queued read the caller's samples: done before returning
      return false;
    }
    pipeline_->push({}, samples.subspan(at, std::min(kChunkRows, samples.size() - at)));
  }
  pipeline_->drain();
  rows_ += static_cast<std::int64_t>(samples.size());
  return true;
}

rb::Status TelemetryWriter::commit(const RunScene& scene, const sim::Model& model, double rate,
                                   const sim::RunSummary& run, const nlohmann::json& check) {
  return commit(meta_ ? telemetrySidecar(scene, model, rate, run, rows_, check) : nullptr);
}

rb::Status TelemetryWriter::commit(const nlohmann::json& sidecar) {
  handOff();
  pipeline_->drain();
  if (meta_) meta_->stream() << sidecar.dump(2) << "\n";
  if (auto e = pipeline_->commit(); !e) return e;
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
                          const nlohmann::json& sidecar, const std::function<bool()>& cancelled) {
  auto writer = TelemetryWriter::open(path);
  if (!writer) return writer.error();
  // (Stopped, the writer's files are removed as it goes: the files there before stay.)
  if (!writer->rows(samples, cancelled) || (cancelled && cancelled()))
    return rb::Status::fail(path + ": interrupted");
  return writer->commit(sidecar);
}

}  // namespace tasks

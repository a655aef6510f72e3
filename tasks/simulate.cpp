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

#include "sim/contact_model.hpp"
#include "tasks/output.hpp"
#include "tasks/run_json.hpp"
#include "tasks/telemetry_columns.hpp"
#include "util/format.hpp"

namespace tasks {
namespace {

// The CSV's columns as the sidecar and Python list them (name, unit, meaning): the table's.
const std::vector<Column>& columnsOfTable() {
  static const std::vector<Column> columns = [] {
    std::vector<Column> out;
    for (const TelemetryColumn& c : telemetryTable()) out.push_back(c.column);
    return out;
  }();
  return columns;
}

// Room for one row: kMaxTelemetryColumns fields of at most kNumberChars (a mode's name is
// shorter).
constexpr std::size_t kRowChars = kMaxTelemetryColumns * kNumberChars;

// One field of a row at `at`; returns its end. `starts` holds where each earlier field began
// (a column the same as an earlier one copies that one's text when the doubles are the same).
char* formatField(char* at, const TelemetryColumn& c, double value, const char* const* starts,
                  const double* values) {
  switch (c.kind) {
    case ColumnKind::Count:
      return std::to_chars(at, at + kNumberChars, static_cast<long long>(value)).ptr;
    case ColumnKind::Mode: {
      const auto& names = rb::NameTable<sim::ContactModel>::entries;
      const std::string_view name = names[static_cast<std::size_t>(value)].second;
      return std::copy(name.begin(), name.end(), at);
    }
    case ColumnKind::Number:
      break;
  }
  const int same = c.same_as;
  if (same >= 0 &&
      std::bit_cast<std::uint64_t>(values[same]) == std::bit_cast<std::uint64_t>(value))
    return std::copy(starts[same], starts[same + 1] - 1, at);  // (its text, without the comma)
  return writeNumber(at, value);
}

}  // namespace

std::span<const Column> telemetryColumns() {
  return columnsOfTable();
}

std::string telemetryHeader() {
  return csvHeader(columnsOfTable()) + "\n";
}

namespace {

// Every number exactly (shortest round trip), written straight into one buffer: at 10 kHz
// printf's formatting was most of a run's time (docs/speed.md "Writing the output").
char* formatRow(char* line, const sim::Telemetry& s) {
  const Eigen::Quaterniond q = attitude(s);
  const SampleView view{s, q};
  const std::span<const TelemetryColumn> table = telemetryTable();
  const char* starts[kMaxTelemetryColumns + 1];
  double values[kMaxTelemetryColumns];
  char* at = line;
  for (std::size_t i = 0; i < table.size(); ++i) {
    starts[i] = at;
    values[i] = table[i].value(view);
    at = formatField(at, table[i], values[i], starts, values);
    *at++ = ',';
  }
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
  const bool rolling = sim::heldOnFloor(model.contact.model);
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
  j["columns"] = columnsJson(columnsOfTable());
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
// both share the rest once the run is over (docs/speed.md "Writing the output").
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

rb::Result<TelemetryWriter> TelemetryWriter::open(const std::string& path,
                                                  std::optional<TelemetryFormat> format) {
  if (auto made = makeParentFolder(path); !made) return made.error();
  auto csv = AtomicOutput::open(path);
  if (!csv) return csv.error();
  std::optional<AtomicOutput> meta;
  if (!rb::outputPlace(path).temporary.empty()) {
    auto opened = AtomicOutput::open(path + ".json");
    if (!opened) return opened.error();
    meta.emplace(std::move(opened).value());
  }
  if (const TelemetryFormat f = format.value_or(telemetryFormatOf(path));
      f != TelemetryFormat::Csv) {
    TelemetryWriter writer(nullptr, std::move(meta));
    writer.arrays_.reset(new Arrays{f, std::move(csv).value(), {}});
    return writer;
  }
  csv->stream() << telemetryHeader();
  // All cores but the run's (one at least).
  const unsigned cores = std::max(2u, std::thread::hardware_concurrency());
  auto pipeline =
      std::make_unique<Pipeline>(std::move(csv).value(), std::min(cores - 1, kMaxWorkers));
  return TelemetryWriter(std::move(pipeline), std::move(meta));
}

void TelemetryWriter::row(const sim::Telemetry& sample) {
  if (arrays_) {
    arrays_->columns.add(sample);
    ++rows_;
    return;
  }
  if (pending_.capacity() == 0) {
    pending_ = pipeline_->spareRows();
    pending_.reserve(kChunkRows);
  }
  pending_.push_back(sample);
  ++rows_;
  if (pending_.size() >= kChunkRows) handOff();
}

void TelemetryWriter::expect(std::int64_t rows) {
  if (arrays_ && rows > 0) arrays_->columns.reserve(static_cast<std::size_t>(rows));
}

void TelemetryWriter::handOff() {
  if (pending_.empty() || !pipeline_) return;
  pipeline_->push(std::move(pending_), {});
  pending_ = {};
}

bool TelemetryWriter::rows(std::span<const sim::Telemetry> samples,
                           const std::function<bool()>& cancelled) {
  if (arrays_) {
    expect(rows_ + static_cast<std::int64_t>(samples.size()));
    for (std::size_t k = 0; k < samples.size(); ++k) {
      if (k % kChunkRows == 0 && cancelled && cancelled()) return false;
      arrays_->columns.add(samples[k]);
    }
    rows_ += static_cast<std::int64_t>(samples.size());
    return true;
  }
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
  if (arrays_) {
    if (auto e =
            arrays_->columns.write(arrays_->file.stream(), arrays_->format, arrays_->file.path());
        !e)
      return e;
    if (meta_) meta_->stream() << sidecar.dump(2) << "\n";
    if (auto e = arrays_->file.commit(); !e) return e;
    return meta_ ? meta_->commit() : rb::Status();
  }
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
                          const nlohmann::json& sidecar, const std::function<bool()>& cancelled,
                          std::optional<TelemetryFormat> format) {
  auto writer = TelemetryWriter::open(path, format);
  if (!writer) return writer.error();
  // (Stopped, the writer's files are removed as it goes: the files there before stay.)
  if (!writer->rows(samples, cancelled) || (cancelled && cancelled()))
    return rb::Status::fail(path + ": interrupted");
  return writer->commit(sidecar);
}

}  // namespace tasks

// A sweep beyond one process (docs/commands.md "rattleback sweep"): shards of its rows, the journal
// an interrupted run keeps for --resume, the merge of shard tables, and job scripts for Slurm and
// GNU parallel. The files are the command line's: tasks/sweep.hpp writes them.
#pragma once

#include <cstdint>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/sweep.hpp"
#include "tasks/sweep.hpp"
#include "util/result.hpp"

namespace tasks {

/// Rows I, I + N, I + 2N, … of a sweep.
struct Shard {
  std::int64_t index = 0, count = 1;
};

/// "I/N" with 0 ≤ I < N; nothing when malformed.
std::optional<Shard> parseShard(const std::string& text);
/// OUT.shard-I-of-N.csv beside OUT.csv (`index` may be a shell variable).
std::string shardPath(const std::string& output, const std::string& index, std::int64_t count);
std::string shardPath(const std::string& output, const Shard& shard);
/// The rows of a shard (all rows without one), in order.
std::vector<std::int64_t> shardRows(const scene::Sweep& sweep, const std::optional<Shard>& shard);

/// A sweep's table is a file (its sidecar and journal go beside it), not a device or pipe.
rb::Status checkTableIsAFile(const std::string& output);

/// What a job script runs.
struct JobRequest {
  JobScript kind = JobScript::Slurm;
  int shards = 0;       ///< pieces, 1 … rows
  std::string program;  ///< the rattleback to run (absolute)
  std::string output;   ///< the merged table (the shards go beside it)
  std::string plot;     ///< the merge's heatmap, or empty
  std::string metric = "first_reversal_s";
};
/// The script's text: a Slurm job array whose first task submits the merge, or one command
/// line per shard for GNU parallel.
rb::Result<std::string> jobScript(const scene::Sweep& sweep, const JobRequest& request);

/// The journal an interrupted sweep leaves (OUT.partial): every finished row as soon as it is
/// finished, under the table's header.
class Journal {
 public:
  static std::string pathOf(const std::string& output) { return output + ".partial"; }
  /// The rows a journal kept (those of `rows`), by row; an error when it is missing or not
  /// this sweep's.
  static rb::Result<std::map<std::int64_t, std::string>> read(
      const std::string& path, const scene::Sweep& sweep, const std::vector<std::int64_t>& rows);
  /// Starts the journal of the table `output` (pathOf) afresh with `kept` (from a resumed
  /// journal), and beside it (.json) the fingerprint of the sweep it belongs to. An error names
  /// the table, which is what -o gave (the journal is the program's own).
  static rb::Result<Journal> open(const std::string& output, const std::string& header,
                                  const std::map<std::int64_t, std::string>& kept,
                                  const std::string& fingerprint);
  /// Removes the journal and its fingerprint (the table is in place).
  static void remove(const std::string& path);
  /// Whether another process's sweep holds the journal of the table `output` (open() locks it
  /// while the sweep runs); the error saying so.
  static bool busy(const std::string& output);
  static rb::Error inUse(const std::string& output);
  void append(const std::string& line);
  void close() { out_.close(); }

  Journal(Journal&& other) noexcept
      : out_(std::move(other.out_)), lock_(std::exchange(other.lock_, -1)) {}
  Journal& operator=(Journal&&) = delete;
  ~Journal();

 private:
  Journal(std::ofstream out, int lock) : out_(std::move(out)), lock_(lock) {}
  std::ofstream out_;
  int lock_ = -1;  ///< a descriptor of the journal holding its lock (flock), or −1
};

/// The shards of one sweep recombined: its lines in row order and the first shard's sidecar.
struct Merged {
  std::vector<std::string> keys;
  std::vector<std::vector<std::string>> axis_values;
  SweepColumns columns;  ///< the result columns, as the shards' header names them
  std::vector<std::string> lines;
  nlohmann::json sidecar;
  std::int64_t rows = 0;
};
/// Reads each shard's table and sidecar; an error for a missing, repeated or foreign row.
rb::Result<Merged> mergeShards(const std::vector<std::string>& shards);

/// A fingerprint of the sweep file and its base scene: a journal begun for another text of
/// either is refused by --resume.
std::string sweepFingerprint(const scene::Sweep& sweep);

/// The table's sidecar: program, sweep, base, rows, shard, axes.
nlohmann::json sweepSidecar(const scene::Sweep& sweep, const std::optional<Shard>& shard);

}  // namespace tasks

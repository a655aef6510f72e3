// Running a sweep (scene/sweep.hpp): each row's scene on a pool of threads made and joined
// within runSweep(), each row's outcome typed (SweepRow), and the table's one CSV dialect
// (RFC 4180) and sidecar. `rattleback sweep` and Python's sweep() both call it.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/sweep.hpp"
#include "tasks/simulate.hpp"
#include "tasks/sweep_columns.hpp"
#include "tasks/table.hpp"

namespace tasks {

/// The job scripts `sweep --emit` prints.
enum class JobScript {
  Slurm,     ///< an sbatch job array and its merge
  Parallel,  ///< one command line per shard, for GNU parallel
};

/// What a sweep should know before it runs: an axis whose key the rows' contact model does not
/// use (contact.friction, stiffness, … under rolling) gives the same row all along it, with
/// nothing in the table to say why. One line each; none when the contact model is itself an
/// axis.
std::vector<std::string> sweepNotes(const scene::Sweep& sweep, const scene::SweepScenes& scenes);

/// Reads a sweep file (scene::loadSweep) and checks the columns it lists are the table's.
rb::Result<scene::Sweep> loadSweep(const std::string& path);
/// The same for a sweep written as text (scene::loadSweepText).
rb::Result<scene::Sweep> loadSweepText(const std::string& yaml, const std::string& name,
                                       const scene::SweepBase& base);
/// Sets the columns of a sweep from an argument named `named` (Python's columns=), checked as a
/// sweep file's are.
rb::Status setColumns(scene::Sweep& sweep, const std::vector<std::string>& names,
                      const std::string& named);
/// The result columns of the sweep's table, in its order: those `columns:` lists, or every column
/// shown by default.
SweepColumns tableColumns(const scene::Sweep& sweep);
/// The columns of these names (a table's header), skipping any that are not the table's.
SweepColumns columnsNamed(const std::vector<std::string>& names);

/// The result columns after the axes' (name, unit, meaning), in the table's order: those of
/// sweepResultTable() shown by default.
std::span<const Column> sweepResultColumns();
/// The unit of a sweep table's column: a varied key's from the schema (lengths "file units"),
/// a result column's from sweepResultTable(); "" for none (the sidecar and the plots').
std::string sweepColumnUnit(const std::string& name);

/// The table's header line (no newline) for these axis keys and result columns.
std::string sweepHeader(const std::vector<std::string>& keys, const SweepColumns& columns);
/// "row,value,…," — the part of a line fixed by the sweep, before the results.
std::string sweepRowPrefix(const scene::Sweep& sweep, std::int64_t row);
/// One row as a CSV line (no newline) with these result columns.
std::string sweepLine(const SweepRow& row, const SweepColumns& columns);
/// The sidecar's columns and axes.
nlohmann::json sweepColumnsJson(const std::vector<std::string>& keys, const SweepColumns& columns);
nlohmann::json sweepAxesJson(const scene::Sweep& sweep);

struct SweepOptions {
  int jobs = 0;                     ///< threads; 0: all cores
  std::function<bool()> cancelled;  ///< polled every 50 ms: true stops the pool (may be empty)
  /// Called once per finished row, one at a time, from the pool's threads (a journal).
  std::function<void(const SweepRow&)> finished;
  /// Called from the calling thread every 50 ms with the rows finished so far.
  std::function<void(std::int64_t)> progress;
};

struct SweepRun {
  std::vector<SweepRow> rows;  ///< the rows asked for, in their order; all of them unless
  bool interrupted = false;    ///< … a cancel stopped the pool first (then the finished ones)
  int threads = 0;
  double wall_s = 0;
};

/// Runs `rows` of the sweep (all when empty is not wanted: pass them) on a pool of threads.
SweepRun runSweep(const scene::Sweep& sweep, const scene::SweepScenes& scenes,
                  const std::vector<std::int64_t>& rows, const SweepOptions& options);

/// Writes the table (header, then `lines`) and its sidecar (with `columns` added), each whole.
rb::Status writeSweepTable(const std::string& output, const std::vector<std::string>& keys,
                           const SweepColumns& columns, const std::vector<std::string>& lines,
                           nlohmann::json sidecar);

}  // namespace tasks

namespace rb {
template <>
struct NameTable<tasks::JobScript> {
  static constexpr std::array<std::pair<tasks::JobScript, std::string_view>, 2> entries{{
      {tasks::JobScript::Slurm, "slurm"},
      {tasks::JobScript::Parallel, "parallel"},
  }};
};
}  // namespace rb

#include "tasks/sweep_jobs.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <sstream>

#include "scene/loader.hpp"
#include "tasks/run_json.hpp"
#include "util/format.hpp"
#include "util/output_place.hpp"

namespace tasks {
namespace {

namespace fs = std::filesystem;

// A word for a shell, single-quoted.
std::string shellWord(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string absolute(const std::string& path) {
  return fs::absolute(path).lexically_normal().string();
}

std::string parallelScript(const std::string& exe, const std::string& sweep_file,
                           const std::vector<std::string>& shard_files) {
  // One command line per shard, for `parallel` (GNU parallel reads commands from stdin).
  std::ostringstream out;
  const std::string n = std::to_string(shard_files.size());
  for (std::size_t i = 0; i < shard_files.size(); ++i)
    out << shellWord(exe) << " sweep " << shellWord(sweep_file) << " --shard " << i << "/" << n
        << " -j 1 -q -o " << shellWord(shard_files[i]) << "\n";
  return out.str();
}

std::string slurmScript(const scene::Sweep& sweep, const JobRequest& r, const std::string& exe,
                        const std::string& sweep_file, const std::string& out,
                        const std::vector<std::string>& shard_files) {
  const std::string stem = fs::path(sweep.file).stem().string();
  const std::string log_dir = fs::path(out).parent_path().string();
  const std::string n = std::to_string(r.shards);
  std::string merge = shellWord(exe) + " sweep merge -q " + shellWord(out);
  for (const std::string& f : shard_files) merge.append(" ").append(shellWord(f));
  if (!r.plot.empty())
    merge.append(" --plot ")
        .append(shellWord(absolute(r.plot)))
        .append(" --metric ")
        .append(shellWord(r.metric));
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# " << stem << ": " << rb::counted(sweep.rows(), "run") << " of rattleback sweep "
    << sweep_file << "\n"
    << "# as a Slurm job array of " << rb::counted(r.shards, "task")
    << ", one shard each; the first task also\n"
    << "# submits the merge, which runs once every task has succeeded (afterok) and writes\n"
    << "# " << out << (r.plot.empty() ? "" : " and its heatmap") << ".\n"
    << "# Submit with: sbatch THIS_FILE\n"
    << "#SBATCH --job-name=rattleback-" << stem << "\n"
    << "#SBATCH --array=0-" << r.shards - 1 << "\n"
    << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
    << "#SBATCH --output=" << log_dir << "/slurm-" << stem << "-%A_%a.out\n"
    << "set -euo pipefail\n"
    << "mkdir -p " << shellWord(log_dir) << "\n"
    << "if [ \"$SLURM_ARRAY_TASK_ID\" = 0 ]; then\n"
    << "  sbatch --parsable --job-name=rattleback-" << stem << "-merge"
    << " --dependency=afterok:\"$SLURM_ARRAY_JOB_ID\" --output=" << log_dir << "/slurm-" << stem
    << "-merge-%j.out --wrap=" << shellWord(merge) << "\n"
    << "fi\n"
    << "exec " << shellWord(exe) << " sweep " << shellWord(sweep_file)
    << " --shard \"$SLURM_ARRAY_TASK_ID/" << n << "\" -j \"${SLURM_CPUS_PER_TASK:-1}\" -q"
    << " -o \"" << shardPath(out, "$SLURM_ARRAY_TASK_ID", r.shards) << "\"\n";
  return s.str();
}

// The sidecar of a shard's table, checked to be a sweep's.
rb::Result<nlohmann::json> readShardSidecar(const std::string& path) {
  std::ifstream in(path + ".json");
  if (!in)
    return rb::Error{"", path +
                             ".json: cannot read the shard's sidecar (each shard writes its "
                             "table and TABLE.json beside it)"};
  nlohmann::json meta = nlohmann::json::parse(in, nullptr, false);
  if (meta.is_discarded() || meta.value("command", "") != "sweep" || !meta.contains("rows") ||
      !meta.contains("axes") || !meta["axes"].is_array())
    return rb::Error{"", path + ".json: not the sidecar of a sweep table"};
  return meta;
}

// Adds a shard's lines to `rows` (row → line, file); an error for a row another shard has.
rb::Status readShardRows(const std::string& path, std::string& head,
                         std::map<std::int64_t, std::pair<std::string, std::string>>& rows,
                         const std::string& first) {
  std::ifstream in(path);
  std::string line;
  if (!in || !std::getline(in, line))
    return rb::Status::fail(path + ": cannot read the shard's table");
  if (head.empty()) head = line;
  if (line != head) return rb::Status::fail(path + ": its columns differ from " + first + "'s");
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::int64_t r = std::strtoll(line.c_str(), nullptr, 10);
    if (auto [it, fresh] = rows.try_emplace(r, line, path); !fresh)
      return rb::Status::fail(path + ": row " + std::to_string(r) + " is also in " +
                              it->second.second + "; each row must come from one shard");
  }
  return {};
}

// The text of a file, or "" when it cannot be read.
std::string textOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string sweepFingerprint(const scene::Sweep& sweep) {
  // FNV-1a (64 bits) of the sweep file's and its base scene's content: any edit to either (a
  // duration, a mass) changes it, where the rows' own values catch only a changed axis; a
  // comment or a blank line does not (a new user's comment had made --resume refuse).
  if (!sweep.file_content.empty())  // as read when the sweep was loaded
    return fingerprintOf({sweep.file_content, "\n--\n", sweep.base_content});
  return fingerprintOf(
      {scene::yamlContent(textOf(sweep.file)), "\n--\n", scene::yamlContent(textOf(sweep.base))});
}

std::optional<Shard> parseShard(const std::string& text) {
  char slash = 0, extra = 0;
  long long i = 0, n = 0;
  if (std::sscanf(text.c_str(), "%lld%c%lld%c", &i, &slash, &n, &extra) != 3 || slash != '/' ||
      n < 1 || i < 0 || i >= n)
    return std::nullopt;
  return Shard{i, n};
}

// OUT.csv → OUT.shard-I-of-N.csv; `index` may be a shell expansion for a job script.
std::string shardPath(const std::string& output, const std::string& index, std::int64_t count) {
  fs::path p(output);
  const std::string name = p.stem().string() + ".shard-" + index + "-of-" + std::to_string(count) +
                           p.extension().string();
  return (p.parent_path() / name).string();
}

std::string shardPath(const std::string& output, const Shard& shard) {
  return shardPath(output, std::to_string(shard.index), shard.count);
}

std::vector<std::int64_t> shardRows(const scene::Sweep& sweep, const std::optional<Shard>& shard) {
  std::vector<std::int64_t> rows;
  for (std::int64_t r = shard ? shard->index : 0; r < sweep.rows(); r += shard ? shard->count : 1)
    rows.push_back(r);
  return rows;
}

rb::Status checkTableIsAFile(const std::string& output) {
  // `-` is standard output to simulate and analyze; here it had made files named - and -.json.
  if (output == "-")
    return rb::Status::fail(
        "-o -: a sweep's table is a file (its journal is written beside it as the runs finish), "
        "not standard output; give -o FILE.csv");
  if (rb::outputPlace(output).temporary.empty())
    return rb::Status::fail(output + ": a sweep's table is a file (its sidecar " + output +
                            ".json and its journal go beside it), not a device or pipe");
  return {};
}

rb::Result<std::string> jobScript(const scene::Sweep& sweep, const JobRequest& r) {
  const std::string kind(rb::nameOf(r.kind));
  if (r.shards < 1)
    return rb::Error{"", "--emit " + kind + " needs --shards N (N ≥ 1): how many pieces to run"};
  if (r.shards > sweep.rows())
    return rb::Error{"", "--shards: " + std::to_string(r.shards) + " shards for " +
                             rb::counted(sweep.rows(), "run") + " leaves some empty; at most " +
                             std::to_string(sweep.rows())};
  const std::string sweep_file = absolute(sweep.file);
  const std::string out = absolute(r.output);
  // The merge that plots, with this sweep's names (a template had been given); the shards' glob is
  // the shell's.
  if (r.kind == JobScript::Parallel && !r.plot.empty()) {
    const std::string pattern = shardPath(out, "*", r.shards);
    const std::size_t star = pattern.rfind('*');
    return rb::Error{"", "--plot: GNU parallel runs the shards only; plot when you merge them: " +
                             shellWord(r.program) + " sweep merge " + shellWord(out) + " " +
                             shellWord(pattern.substr(0, star)) + "*" +
                             shellWord(pattern.substr(star + 1)) + " --plot " +
                             shellWord(absolute(r.plot))};
  }
  std::vector<std::string> shard_files;
  for (int i = 0; i < r.shards; ++i) shard_files.push_back(shardPath(out, Shard{i, r.shards}));
  if (r.kind == JobScript::Parallel) return parallelScript(r.program, sweep_file, shard_files);
  return slurmScript(sweep, r, r.program, sweep_file, out, shard_files);
}

rb::Result<std::map<std::int64_t, std::string>> Journal::read(
    const std::string& path, const scene::Sweep& sweep, const std::vector<std::int64_t>& rows) {
  std::ifstream in(path);
  if (!in)
    return rb::Error{"", path +
                             ": nothing to resume (no interrupted run wrote it); run without "
                             "--resume"};
  // The sweep file and its base scene as they were when the journal was begun.
  std::ifstream print_in(path + ".json");
  const nlohmann::json print = nlohmann::json::parse(print_in, nullptr, false);
  if (print.is_discarded() || !print.is_object() ||
      print.value("fingerprint", "") != sweepFingerprint(sweep))
    return rb::Error{"", path +
                             ": the sweep file or its base scene changed since the "
                             "interrupted run (its rows would mix two sweeps); remove it, or "
                             "run without --resume"};
  std::vector<std::string> keys;
  for (const auto& axis : sweep.axes) keys.push_back(axis.key);
  std::string line;
  if (!std::getline(in, line) || line != sweepHeader(keys, tableColumns(sweep)))
    return rb::Error{"", path +
                             ": its columns are not this sweep's; remove it, or run without "
                             "--resume"};
  const std::set<std::int64_t> mine(rows.begin(), rows.end());
  std::map<std::int64_t, std::string> done;
  while (std::getline(in, line)) {
    if (in.eof()) break;  // a last line without its newline was cut short: run it again
    const auto comma = line.find(',');
    const std::int64_t r = std::strtoll(line.substr(0, comma).c_str(), nullptr, 10);
    if (comma == std::string::npos || !mine.count(r) ||
        line.rfind(sweepRowPrefix(sweep, r), 0) != 0)
      return rb::Error{"", path + ": row '" + line.substr(0, 40) +
                               "…' is not one of this sweep's (was the sweep file changed?); "
                               "remove it, or run without --resume"};
    done[r] = line;
  }
  return done;
}

rb::Result<Journal> Journal::open(const std::string& output, const std::string& header,
                                  const std::map<std::int64_t, std::string>& kept,
                                  const std::string& fingerprint) {
  const std::string path = pathOf(output);
  // Locked while the sweep runs, before anything is truncated: a second sweep on the same table is
  // told so, where it had said the first's journal was "an interrupted run". The lock goes with the
  // descriptor, when the process ends whatever way.
  const int lock = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
  if (lock >= 0 && ::flock(lock, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock);
    return inUse(output);
  }
  std::ofstream(path + ".json", std::ios::trunc)
      << nlohmann::json{{"fingerprint", fingerprint}}.dump() << "\n";
  std::ofstream out(path, std::ios::trunc);
  // Named as the table: "t.csv.partial: cannot write …" sent a teacher looking for a file of that
  // name.
  if (!out) {
    const int error = errno;
    if (lock >= 0) ::close(lock);
    return rb::Error{"", rb::cannotWriteIn(output, error)};
  }
  out << header << "\n";
  for (const auto& [r, line] : kept) out << line << "\n";
  out.flush();
  return Journal(std::move(out), lock);
}

Journal::~Journal() {
  if (lock_ >= 0) ::close(lock_);
}

rb::Error Journal::inUse(const std::string& output) {
  return rb::Error{"", output + ": another sweep is writing this table now (its journal " +
                           pathOf(output) +
                           " is in use); wait for it to finish, or give -o another name"};
}

bool Journal::busy(const std::string& output) {
  const int fd = ::open(pathOf(output).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);
  return held;
}

void Journal::remove(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
  std::filesystem::remove(path + ".json", ec);
}

void Journal::append(const std::string& line) {
  out_ << line << "\n";
  out_.flush();
}

rb::Result<Merged> mergeShards(const std::vector<std::string>& shards) {
  std::optional<nlohmann::json> first;
  std::string head;
  std::map<std::int64_t, std::pair<std::string, std::string>> rows;  // row → (line, file)
  for (const std::string& path : shards) {
    auto meta = readShardSidecar(path);
    if (!meta) return meta.error();
    if (first) {
      // One sweep is one content: shards run from the sweep file by different paths (sw.yaml,
      // /abs/sw.yaml, ../sw.yaml) are one sweep, and shards run after an edit (a duration, a mass)
      // are two, whose rows must not be mixed. Shards written before the fingerprint was kept are
      // told apart by path, as they were.
      const nlohmann::json &print = (*first)["fingerprint"], &mine = meta.value()["fingerprint"];
      const bool printed = print.is_string() && mine.is_string();
      if (printed && print != mine)
        return rb::Error{"", path + ": its sweep file or base scene was not as when " +
                                 shards.front() +
                                 " ran (their contents differ); run every shard from the same "
                                 "files"};
      if ((!printed && (*first)["sweep"] != meta.value()["sweep"]) ||
          (*first)["axes"] != meta.value()["axes"])
        return rb::Error{"", path + ": from another sweep than " + shards.front() + " (" +
                                 meta.value().value("sweep", "?") + ")"};
    }
    if (!first) first = meta.value();
    if (auto ok = readShardRows(path, head, rows, shards.front()); !ok) return ok.error();
  }
  Merged merged;
  // The sweep's rows: the product of its axes' sizes (a shard's `rows` counts its own).
  merged.rows = 1;
  for (const auto& axis : (*first)["axes"])
    merged.rows *= static_cast<std::int64_t>(axis.value("values", nlohmann::json::array()).size());
  std::vector<std::int64_t> missing;
  for (std::int64_t r = 0; r < merged.rows && missing.size() < 6; ++r)
    if (!rows.count(r)) missing.push_back(r);
  if (!missing.empty()) {
    // (Appended piece by piece: `"…" + string` trips a false -Wrestrict of GCC 12.)
    std::string e = "sweep merge: rows missing (";
    e.append(std::to_string(merged.rows - static_cast<std::int64_t>(rows.size())))
        .append(" of ")
        .append(std::to_string(merged.rows))
        .append("), e.g.");
    for (std::int64_t r : missing) e.append(" ").append(std::to_string(r));
    return rb::Error{"", e + "; give every shard of the sweep"};
  }
  if (static_cast<std::int64_t>(rows.size()) != merged.rows)
    return rb::Error{"", "sweep merge: rows beyond the sweep's " + std::to_string(merged.rows)};
  for (const auto& axis : (*first)["axes"]) {
    merged.keys.push_back(axis["key"].get<std::string>());
    merged.axis_values.push_back(axis["values"].get<std::vector<std::string>>());
  }
  // The result columns, from the header: those the sweep listed, or the default table's.
  std::istringstream header(head);
  std::vector<std::string> names;
  for (std::string name; std::getline(header, name, ',');) names.push_back(name);
  merged.columns = columnsNamed(std::vector<std::string>(
      names.begin() + std::min(names.size(), 1 + merged.keys.size()), names.end()));
  for (const auto& [r, entry] : rows) merged.lines.push_back(entry.first);
  merged.sidecar = *first;
  merged.sidecar["rows"] = merged.rows;
  merged.sidecar["shard"] = nullptr;
  merged.sidecar["merged_from"] = shards;
  return merged;
}

nlohmann::json sweepSidecar(const scene::Sweep& sweep, const std::optional<Shard>& shard) {
  nlohmann::json sidecar;
  sidecar["program"] = "rattleback " RATTLEBACK_VERSION;
  sidecar["command"] = "sweep";
  // Absolute, as a run's scene_path is (it was relative to the folder the sweep ran from, which the
  // sidecar does not say); a base or sweep with no file (Python's) as named.
  const auto absoluteIfFile = [](const std::string& path) {
    std::error_code ec;
    if (path.empty() || !fs::is_regular_file(path, ec)) return path;
    const fs::path whole = fs::absolute(path, ec);
    return ec ? path : whole.lexically_normal().string();
  };
  sidecar["sweep"] = absoluteIfFile(sweep.file);
  sidecar["base"] = absoluteIfFile(sweep.base);
  // The content it ran (the sweep file and its base scene): what sweep merge compares.
  sidecar["fingerprint"] = sweepFingerprint(sweep);
  sidecar["base_as_written"] = sweep.base_as_written;
  // The rows of this table: a shard's own (rows I, I + N, … of the sweep's), as `rows` of a
  // run's sidecar counts the rows of its CSV; the sweep's are the product of the axes' sizes.
  sidecar["rows"] =
      shard ? (sweep.rows() - shard->index + shard->count - 1) / shard->count : sweep.rows();
  sidecar["shard"] = shard ? nlohmann::json{{"index", shard->index},
                                            {"count", shard->count},
                                            {"sweep_rows", sweep.rows()}}
                           : nlohmann::json(nullptr);
  sidecar["axes"] = sweepAxesJson(sweep);
  // What a key in "file units" is in metres (the base scene's units.length): the plot's labels
  // say "[cm]" from it.
  sidecar["length_unit_m"] = sweep.length_unit;
  return sidecar;
}

}  // namespace tasks

// `rattleback sweep` as a user runs it: the same table whatever the threads or shards, rows
// that equal `simulate` on the same scene, errors that name file, line and key, a bad value
// that refuses its row only, interrupts that keep the finished rows, and the merge's checks.
#include "scene/sweep.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>
#include <vector>

#include "app/sweep_plot.hpp"
#include "tasks/both_ways.hpp"
#include "tasks/sweep.hpp"
#include "tasks/sweep_jobs.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch() {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(testing::TempDir()) / "rattleback_sweep" /
                       (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

struct Outcome {
  int status;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Outcome rattleback(const fs::path& dir, const std::string& args) {
  const std::string command = std::string(RATTLEBACK_BIN) + " " + args + " >" +
                              (dir / "stdout").string() + " 2>" + (dir / "stderr").string() +
                              " </dev/null";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / "stdout"), slurp(dir / "stderr")};
}

const std::string kBase = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/rattleback.yaml";

// Starts `command` in a process of its own, its standard error into `err`; its pid (−1 when
// fork failed), for the signal a test sends it.
pid_t startInBackground(const std::string& command, const fs::path& err) {
  const pid_t pid = fork();
  if (pid == 0) {
    execl("/bin/sh", "sh", "-c", ("exec " + command + " 2>" + err.string()).c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  return pid;
}

// Waits, up to 4 s, until a sweep's journal holds more than `lines` lines (its header and
// rows), for a test that interrupts or joins it.
void waitForRows(const fs::path& journal, int lines) {
  for (int i = 0; i < 400; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const std::string rows = fs::exists(journal) ? slurp(journal) : std::string();
    if (std::count(rows.begin(), rows.end(), '\n') > lines) return;
  }
}

fs::path writeSweep(const fs::path& dir, const std::string& text) {
  const fs::path path = dir / "sweep.yaml";
  std::ofstream(path) << text;
  return path;
}

// A sweep of the default scene started in the background at -j 1 (`vary` and what follows it in
// the sweep file; options after -o), its stderr in dir/stderr, for a test that interrupts or joins
// it. Its journal is table + ".partial".
struct BackgroundSweep {
  fs::path dir, sweep, table, journal;
  std::string command;  ///< the command line it was started with
  pid_t pid = -1;
};
BackgroundSweep startSweep(const std::string& rest, const std::string& options = " -q") {
  BackgroundSweep b;
  b.dir = scratch();
  b.sweep = writeSweep(b.dir, "base: " + kBase + "\nvary:\n" + rest);
  b.table = b.dir / "t.csv";
  b.journal = b.table.string() + ".partial";
  b.command = std::string(RATTLEBACK_BIN) + " sweep " + b.sweep.string() + options + " -j 1 -o " +
              b.table.string();
  b.pid = startInBackground(b.command, b.dir / "stderr");
  return b;
}

// The exit status of a process started in the background, once it ends (-1: not an exit).
int exitStatusOf(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Splits CSV text into rows of fields (RFC 4180 quotes), as Python's csv module reads it.
std::vector<std::vector<std::string>> readCsv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row(1);
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"')
        row.back() += '"', ++i;
      else if (c == '"')
        quoted = false;
      else
        row.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      row.emplace_back();
    } else if (c == '\n') {
      rows.push_back(row);
      row.assign(1, "");
    } else {
      row.back() += c;
    }
  }
  return rows;
}

// The table without its last column (wall_s, the only one that changes from run to run).
// The index of a table's column by its name in the header (rows[0]).
std::size_t at(const std::vector<std::vector<std::string>>& rows, const std::string& name) {
  const auto& header = rows.at(0);
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
}

std::string withoutWall(const std::string& text) {
  std::string out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// Two spins (one reverses, one does not) × two dent scales: the body axis is the fast one, so
// rows that share a body are not neighbours.
const char* kSmallSweep = R"(base: BASE
vary:
  initial.spin: [-5, 5, -7.5]
  body.dents.scale: [0.45, 0.4]
duration: 3.0
)";

std::string smallSweep() {
  std::string text = kSmallSweep;
  text.replace(text.find("BASE"), 4, kBase);
  return text;
}

}  // namespace

TEST(Sweep, TheTableIsTheSameForOneOrTwoThreadsAndForMergedShards) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const Outcome one =
      rattleback(dir, "sweep " + sweep.string() + " -q -j 1 -o " + (dir / "j1.csv").string());
  ASSERT_EQ(one.status, 0) << one.err;
  const Outcome two =
      rattleback(dir, "sweep " + sweep.string() + " -q -j 2 -o " + (dir / "j2.csv").string());
  ASSERT_EQ(two.status, 0) << two.err;
  std::string shards;
  for (int i = 0; i < 3; ++i) {
    const std::string shard = (dir / ("s" + std::to_string(i) + ".csv")).string();
    const Outcome r = rattleback(
        dir, "sweep " + sweep.string() + " -q --shard " + std::to_string(i) + "/3 -o " + shard);
    ASSERT_EQ(r.status, 0) << r.err;
    shards = shard + " " + shards;  // in reverse order: the merge orders the rows itself
  }
  const Outcome merged =
      rattleback(dir, "sweep merge -q " + (dir / "merged.csv").string() + " " + shards);
  ASSERT_EQ(merged.status, 0) << merged.err;

  const std::string reference = withoutWall(slurp(dir / "j1.csv"));
  EXPECT_EQ(withoutWall(slurp(dir / "j2.csv")), reference);
  EXPECT_EQ(withoutWall(slurp(dir / "merged.csv")), reference);
  const auto rows = readCsv(reference);
  ASSERT_EQ(rows.size(), 7u);  // the header and 3 × 2 runs
  EXPECT_EQ(rows[0],
            (std::vector<std::string>{"row", "initial.spin", "body.dents.scale", "status",
                                      "stop_reason", "first_reversal_s", "reversals", "final_spin",
                                      "max_tilt_deg", "energy_lost", "message"}));
  // First axis slowest.
  EXPECT_EQ(rows[1][1], "-5");
  EXPECT_EQ(rows[1][2], "0.45");
  EXPECT_EQ(rows[2][2], "0.4");
  EXPECT_EQ(rows[3][1], "5");
  for (std::size_t i = 1; i < rows.size(); ++i) EXPECT_EQ(rows[i][0], std::to_string(i - 1));
  // The base scene's length unit (units.length: 0.01, centimetres) in the sidecar, also the
  // merged table's, for the plots' labels ("body.dents.at[0] [cm]").
  for (const char* table : {"j1.csv", "merged.csv"})
    EXPECT_EQ(nlohmann::json::parse(slurp(dir / (std::string(table) + ".json")))["length_unit_m"],
              0.01)
        << table;
}

// Each row against `simulate` of the same scene written out by hand: the reversal times, the
// count, the final spin, the largest tilt and the energy lost agree to the table's 10 digits.
TEST(Sweep, EveryRowIsWhatSimulateReportsForItsScene) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 7u);
  const std::string base = slurp(kBase);
  int reversing = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    ASSERT_EQ(row[at(rows, "status")], "ok") << row[at(rows, "status")];
    std::string text = base;
    text.replace(text.find("spin: -5.0"), 10, "spin: " + row[1]);
    text.replace(text.find("scale: 0.45"), 11, "scale: " + row[2]);
    text.replace(text.find("duration: 8.0"), 13, "duration: 3.0");
    const fs::path scene = dir / ("row" + std::to_string(i) + ".yaml");
    std::ofstream(scene) << text;
    const fs::path csv = dir / ("row" + std::to_string(i) + ".csv");
    const Outcome s = rattleback(dir, "simulate " + scene.string() + " -q -o " + csv.string());
    ASSERT_EQ(s.status, 0) << s.err;
    const auto meta = nlohmann::json::parse(slurp(csv.string() + ".json"));
    const auto& result = meta["result"];
    auto near = [](double a, double b) {
      return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b));
    };
    if (result["first_reversal_s"].is_null()) {
      EXPECT_EQ(row[at(rows, "first_reversal_s")], "") << "row " << i;
    } else {
      ++reversing;
      EXPECT_TRUE(near(std::stod(row[at(rows, "first_reversal_s")]),
                       result["first_reversal_s"].get<double>()))
          << "row " << i;
    }
    EXPECT_EQ(std::stoul(row[at(rows, "reversals")]), result["reversals_s"].size()) << "row " << i;
    EXPECT_TRUE(near(std::stod(row[at(rows, "final_spin")]), result["final_spin"].get<double>()))
        << "row " << i;
    EXPECT_TRUE(
        near(std::stod(row[at(rows, "max_tilt_deg")]), result["max_tilt_deg"].get<double>()))
        << "row " << i;
    const double e0 = result["energy_j"]["initial"], e1 = result["energy_j"]["final"];
    EXPECT_TRUE(near(std::stod(row[at(rows, "energy_lost")]), (e0 - e1) / e0)) << "row " << i;
  }
  // Within 3 s the clockwise spins reverse, except -5 with the shallower dents (a smaller
  // misalignment: it reverses only after ≈5 s, as sweeps/dents.yaml shows); the
  // counter-clockwise spin does not: the table is not a column of empty cells.
  EXPECT_EQ(reversing, 3);
}

TEST(Sweep, ErrorsInTheSweepFileNameFileLineAndKey) {
  const fs::path dir = scratch();
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"base: BASE\nvary:\n  initial.spinn: [1, 2]\n",
       "sweep.yaml:3: initial.spinn is not a known key"},
      // A misspelt map above the key set is the line's mistake too (it was blamed on the base's
      // line 1, and every row was refused with exit 0).
      {"base: BASE\nvary:\n  intial.spin: [1, 2]\n",
       "sweep.yaml:3: intial is not a known key; did you mean initial?"},
      // A missing count is said to be missing (it read "count must be a number").
      {"base: BASE\nvary:\n  initial.spin: {from: -5, to: 5}\n",
       "sweep.yaml:3: initial.spin count is required: a range is {from: A, to: B, count: N}"},
      {"base: BASE\nvary:\n  initial.spin: {from: 1, to: 2, count: 0}\n",
       "sweep.yaml:3: initial.spin count must be a whole number from 1 to 1e6"},
      {"base: BASE\nvary:\n  initial.spin: {from: 1, to: 2, count: 3, scale: cubic}\n",
       "sweep.yaml:3: initial.spin scale must be linear or log, not 'cubic'"},
      {"base: BASE\nvary:\n  initial.spin: 5\n",
       "sweep.yaml:3: initial.spin must be a list of values or a range {from, to, count}, e.g. "
       "[5]"},
      // The base as typed, and where it was looked for from the sweep file's folder.
      {"base: nowhere.yaml\nvary:\n  initial.spin: [1]\n", "sweep.yaml:1: base nowhere.yaml: /"},
      // A quoted number is a slip: said before anything runs (its row was refused, exit 0).
      {"base: BASE\nvary:\n  initial.spin: [\"-4\", -2]\n",
       "sweep.yaml:3: initial.spin has the quoted string \"-4\": write the number without quotes "
       "(-4)"},
      {"base: BASE\nvary:\n  initial.spin: {from: \"-4\", to: 2, count: 3}\n",
       "sweep.yaml:3: initial.spin from must be a number, not the quoted string \"-4\""},
      // So is a word where the base scene has a number (a unit written in: its row was
      // refused, exit 0, its cell grey; a teacher's trial), in the scene's own words.
      {"base: BASE\nvary:\n  initial.spin: [5 rad/s, 4]\n",
       "sweep.yaml:3: initial.spin must be a number, not '5 rad/s' (write the number alone, in "
       "rad/s)"},
      {"base: BASE\nvary:\n  initial.spin: [1]\nduraton: 3\n",
       "sweep.yaml:4: duraton is not a key of a sweep"},
      // A scene file given where a sweep goes (it had named only the key).
      {"units: {length: 0.01}\nbody: {mass: 0.06}\n",
       "sweep.yaml:1: units is not a key of a sweep; a scene's key: this is a scene file, not a "
       "sweep"},
      {"base: BASE\nvary:\n  body.dents.at[2]: [1]\n",
       "sweep.yaml:3: body.dents.at[2]: the base scene has no list body.dents.at with an element "
       "2"},
      {"base: BASE\nvary: [1, 2]\n", "sweep.yaml:2: vary must map scene keys to their values"},
      {"base: BASE\nvary:\n  initial.spin: [1\n", "malformed YAML"},
  };
  for (const Case& c : cases) {
    std::string text = c.text;
    if (auto at = text.find("BASE"); at != std::string::npos) text.replace(at, 4, kBase);
    const fs::path sweep = writeSweep(dir, text);
    const Outcome r =
        rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
    EXPECT_EQ(r.status, 2) << c.text;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.text << "\ngot: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.csv")) << c.text;
  }
}

// A value that makes one scene invalid refuses that row, named where the sweep file sets it;
// the other rows run.
TEST(Sweep, ABadValueRefusesItsRowOnly) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(
      dir, "base: " + kBase +
               "\nvary:\n  contact.air_drag: [0.0, -1.0]\n  initial.spin: [-5]\nduration: 1\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 3u);
  const std::size_t status = at(rows, "status"), message = at(rows, "message");
  EXPECT_EQ(rows[1][status], "ok");
  EXPECT_EQ(rows[2][status], "refused");
  EXPECT_EQ(rows[2][at(rows, "stop_reason")], "");
  EXPECT_EQ(rows[2][message].rfind(sweep.string() + ":3: contact.air_drag", 0), 0u)
      << rows[2][message];
  EXPECT_EQ(rows[2][at(rows, "first_reversal_s")], "");
}

// A rolling run never slips: an axis of contact.friction under it gives the same row all along
// (a researcher's trial: a flat friction × spin heatmap with nothing said). The sweep says so
// before it runs, naming the axis's line, and not with -q; where the contact model is itself
// varied, or the key is one rolling uses (air_drag), nothing is said.
TEST(Sweep, AnAxisRollingDoesNotUseIsSaidToBe) {
  const fs::path dir = scratch();
  const std::string table = " -o " + (dir / "t.csv").string();
  const fs::path friction = writeSweep(
      dir, "base: " + kBase +
               "\nvary:\n  contact.friction: [0.1, 0.5]\n  initial.spin: [-5]\nduration: 0.2\n");
  const Outcome said = rattleback(dir, "sweep " + friction.string() + table);
  ASSERT_EQ(said.status, 0) << said.err;
  EXPECT_EQ(said.err.rfind("rattleback: note: " + friction.string() +
                               ":3: contact.friction does not change a rolling run, which never "
                               "slips (",
                           0),
            0u)
      << said.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 3u);
  const std::size_t final_spin = at(rows, "final_spin");
  ASSERT_LT(final_spin, rows[0].size());
  EXPECT_EQ(rows[1][final_spin], rows[2][final_spin]);  // the same to the bit: as the note says
  EXPECT_EQ(rattleback(dir, "sweep " + friction.string() + " -q" + table).err, "");
  for (const char* vary : {"  contact.air_drag: [0.0, 1.0e-5]\n",
                           "  contact.friction: [0.1, 0.5]\n"
                           "  contact.model: [rolling]\n"}) {
    const fs::path quiet =
        writeSweep(dir, "base: " + kBase + "\nvary:\n" + vary + "duration: 0.2\n");
    const Outcome none = rattleback(dir, "sweep " + quiet.string() + table);
    ASSERT_EQ(none.status, 0) << none.err;
    EXPECT_EQ(none.err, "") << vary;
  }
}

// A sweep whose every run is refused made nothing: its values are the input at fault, exit 2
// with the first reason (a teacher's trial: contact.model: [auto] without a stiffness refused
// all four rows, and the command exited 0). As bad input, it writes nothing and keeps a table of
// that name (a table of refusals had replaced it: a CI engineer's trial); one refused row among
// good ones is the table's business, exit 0 (ABadValueRefusesItsRowOnly).
TEST(Sweep, ASweepWhoseEveryRunIsRefusedExitsTwo) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(
      dir, "base: " + kBase + "\nvary:\n  contact.air_drag: [-1.0, -2.0]\nduration: 0.1\n");
  std::ofstream(dir / "t.csv") << "a good table\n";
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string() +
                          " --plot " + (dir / "t.png").string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind(sweep.string() + ": every run was refused, nothing written; the first: " +
                            sweep.string() + ":3: contact.air_drag",
                        0),
            0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(slurp(dir / "t.csv"), "a good table\n");
  for (const char* name : {"t.csv.json", "t.csv.partial", "t.csv.partial.json", "t.png"})
    EXPECT_FALSE(fs::exists(dir / name)) << name;
}

// Where some runs are refused, the summary says why (the first), not only how many: a refused
// cell of the heatmap looks like "no reversal" (a teacher's trial).
TEST(Sweep, TheSummaryNamesTheFirstRefusal) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(
      dir, "base: " + kBase + "\nvary:\n  contact.air_drag: [0.0, -1.0]\nduration: 0.1\n");
  const Outcome r = rattleback(dir, "sweep " + sweep.string() + " -o " + (dir / "t.csv").string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 runs, 1 ok, 1 refused"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("refused         row 1: " + sweep.string() + ":3: contact.air_drag must be"),
            std::string::npos)
      << r.out;
}

// A bad value in the base scene (not varied) refuses the rows naming the base's own line: the
// rows' trees are copies, which keep no lines, and it was named at the base's line 1.
// A base named as a shipped scene is (scenes/rattleback.yaml), with no such file beside the
// sweep, is the shipped scene, as on the command line (such a sweep was refused, and
// offered its own base); ./ names the sweep's folder only. RATTLEBACK_ASSETS stands for the
// installed share/rattleback, here the source tree.
TEST(Sweep, ABaseNamedAsAShippedSceneIsTheShippedOne) {
  const fs::path dir = scratch();
  ::setenv("RATTLEBACK_ASSETS", RATTLEBACK_SOURCE_DIR, 1);
  const fs::path shipped =
      writeSweep(dir, "base: scenes/rattleback.yaml\nvary:\n  initial.spin: [-5]\n");
  auto loaded = scene::loadSweep(shipped.string());
  std::ofstream(dir / "own.yaml")
      << "base: ./scenes/rattleback.yaml\nvary:\n  initial.spin: [-5]\n";
  auto own = scene::loadSweep((dir / "own.yaml").string());
  ::unsetenv("RATTLEBACK_ASSETS");
  ASSERT_TRUE(loaded) << loaded.error().text();
  EXPECT_EQ(fs::path(loaded->base), fs::path(kBase).lexically_normal());
  ASSERT_FALSE(own);
  EXPECT_NE(own.error().text().find("cannot open the scene file"), std::string::npos)
      << own.error().text();
}

TEST(Sweep, ABadValueInTheBaseNamesTheBasesLine) {
  const fs::path dir = scratch();
  std::string base = slurp(kBase);
  const std::size_t at = base.find("  mass: 0.059");
  ASSERT_NE(at, std::string::npos);
  base.replace(at, 13, "  mass: -1");
  const int line = static_cast<int>(std::count(base.begin(), base.begin() + at, '\n')) + 1;
  std::ofstream(dir / "base.yaml") << base;
  const fs::path sweep =
      writeSweep(dir, "base: base.yaml\nvary:\n  initial.spin: [-5]\nduration: 0.1\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 2) << r.err;  // (its one run refused: ASweepWhoseEveryRunIsRefusedExitsTwo)
  EXPECT_EQ(r.err, sweep.string() + ": every run was refused, nothing written; the first: " +
                       (dir / "base.yaml").string() + ":" + std::to_string(line) +
                       ": body.mass must be > 0, not -1\n");
}

// An error about the map around the varied key (the grid as a whole, for a spacing typed as
// 1e-9) is named at the sweep file's line too, not at the base scene's first line.
TEST(Sweep, AnErrorAboutTheVariedKeysMapNamesTheSweepsLine) {
  const fs::path dir = scratch();
  const fs::path sweep =
      writeSweep(dir, "base: " + kBase + "\nvary:\n  body.grid.dx: [0.05, 1e-9]\nduration: 0.01\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1][at(rows, "status")], "ok");
  EXPECT_EQ(rows[2][at(rows, "status")], "refused");
  const std::string& message = rows[2][at(rows, "message")];
  EXPECT_EQ(message.rfind(sweep.string() + ":3: body.grid makes about", 0), 0u) << message;
}

// A row whose run stops (rolling cannot hold the default body spun at 45 rad/s: it tips onto
// its rim, past 50°) says why, and still gives its largest tilt, past the 50° it stopped at;
// the values only a finished run has stay empty.
TEST(Sweep, AStoppedRowKeepsItsLargestTilt) {
  const fs::path dir = scratch();
  const fs::path sweep =
      writeSweep(dir, "base: " + kBase + "\nvary:\n  initial.spin: [-5, -45]\nduration: 1\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 3u);
  const std::size_t status = at(rows, "status"), tilt = at(rows, "max_tilt_deg");
  ASSERT_LT(tilt, rows[0].size());
  EXPECT_EQ(rows[1][status], "ok");
  // A word to group by, a code for why, and the run's words.
  EXPECT_EQ(rows[2][status], "stopped");
  EXPECT_EQ(rows[2][at(rows, "stop_reason")], "on_rim");
  const std::string& message = rows[2][at(rows, "message")];
  EXPECT_EQ(message.rfind("the body tipped onto the edge of its top", 0), 0u) << message;
  ASSERT_FALSE(rows[2][tilt].empty());
  EXPECT_GT(std::stod(rows[2][tilt]), 50.0);
  EXPECT_EQ(rows[2][at(rows, "final_spin")], "");  // no final spin
}

// A second sweep on a table another sweep is writing is told so, and the first's journal is
// left alone (it had been called "an interrupted run", and with --resume the two would have
// written one journal: a CI engineer's trial); once the first is stopped, --resume takes its
// journal (the lock went with the process).
TEST(Sweep, ASecondSweepOnATableBeingWrittenIsToldSo) {
  const BackgroundSweep first = startSweep(
      "  initial.spin: {from: -8, to: 8, count: 161}\n"
      "  contact.air_drag: [0, 1e-6, 2e-6, 3e-6]\nduration: 30\n");
  const auto& [dir, sweep, table, journal, command, pid] = first;
  ASSERT_GE(pid, 0);
  waitForRows(journal, 2);
  for (const char* resume : {"", " --resume"}) {
    const Outcome second =
        rattleback(dir, "sweep " + sweep.string() + " -q -o " + table.string() + resume);
    EXPECT_EQ(second.status, 2) << resume;
    EXPECT_EQ(second.err, table.string() +
                              ": another sweep is writing this table now (its "
                              "journal " +
                              journal.string() +
                              " is in use); wait for it to finish, or give -o another name\n")
        << resume;
  }
  kill(pid, SIGINT);
  ASSERT_EQ(exitStatusOf(pid), 130) << slurp(dir / "stderr");
  const std::string kept = slurp(journal);
  ASSERT_GT(std::count(kept.begin(), kept.end(), '\n'), 2) << "the first's journal was cut";
  const pid_t again = startInBackground(command + " --resume", dir / "again.err");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(again, SIGINT);
  const int status = exitStatusOf(again);
  EXPECT_TRUE(status == 130 || status == 0) << slurp(dir / "again.err");
  EXPECT_EQ(slurp(dir / "again.err").find("another sweep"), std::string::npos);
}

// A sweep started with SIGINT ignored, as a script's background job is (`rattleback sweep … &`:
// the terminal's Ctrl-C is the script's to stop), keeps ignoring it; SIGTERM still stops it (a
// CI engineer's trial: it had taken the script's Ctrl-C as its own).
TEST(Sweep, ASweepStartedIgnoringCtrlCKeepsIgnoringIt) {
  const fs::path dir = scratch();
  const fs::path sweep =
      writeSweep(dir, "base: " + kBase +
                          "\nvary:\n  initial.spin: {from: -8, to: 8, count: 161}\nduration: 8\n");
  const fs::path table = dir / "t.csv";
  const pid_t pid = fork();
  if (pid == 0) {
    signal(SIGINT, SIG_IGN);  // kept across exec, as a shell's background job has it
    const std::string command = std::string("exec ") + RATTLEBACK_BIN + " sweep " + sweep.string() +
                                " -q -j 1 -o " + table.string() + " 2>/dev/null";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  ASSERT_GE(pid, 0);
  const fs::path journal = table.string() + ".partial";
  waitForRows(journal, 0);
  kill(pid, SIGINT);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  // 143 for the SIGTERM, or 0 had the sweep finished first; 130 would be the ignored SIGINT's.
  EXPECT_NE(WEXITSTATUS(status), 130);
  EXPECT_TRUE(WEXITSTATUS(status) == 143 || WEXITSTATUS(status) == 0) << WEXITSTATUS(status);
}

// One Ctrl-C delivered twice within moments (`timeout -s INT` signals the program, then its
// process group) is one request: the sweep stops as for one and says so. Ending at once on the
// second had left 4 sweeps of 10 stopped with nothing said.
TEST(Sweep, ACtrlCDeliveredTwiceAtOnceIsOneRequest) {
  const BackgroundSweep b =
      startSweep("  initial.spin: {from: -8, to: 8, count: 161}\nduration: 8\n");
  ASSERT_GE(b.pid, 0);
  waitForRows(b.journal, 2);
  kill(b.pid, SIGINT);
  // Long enough for the first to have been handled (the two are otherwise merged into one
  // pending signal, and the test would show nothing), well within the window.
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(b.pid, SIGINT);
  EXPECT_EQ(exitStatusOf(b.pid), 130);
  EXPECT_NE(slurp(b.dir / "stderr").find("interrupted; "), std::string::npos)
      << slurp(b.dir / "stderr");
}

// A resumed sweep whose columns: list no status counts the journal's rows apart from the
// statuses of the rows run now: its summary adds up (it had said "100000 runs, 83665 ok, 879
// stopped (15456 from the journal…, 84544 run now)").
TEST(Sweep, AResumedSweepWithoutAStatusColumnSaysWhatItCounted) {
  const BackgroundSweep b = startSweep(
      "  initial.spin: {from: -8, to: 8, count: 161}\nduration: 8\ncolumns: [first_reversal_s]\n");
  const auto& [dir, sweep, table, journal, command, pid] = b;
  ASSERT_GE(pid, 0);
  waitForRows(journal, 3);
  kill(pid, SIGINT);
  exitStatusOf(pid);
  const std::string kept = slurp(journal);
  const auto journal_rows = std::count(kept.begin(), kept.end(), '\n') - 1;
  ASSERT_GT(journal_rows, 0);
  const Outcome resumed =
      rattleback(dir, "sweep " + sweep.string() + " -j 1 --resume -o " + table.string());
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("161 runs (" + std::to_string(journal_rows) +
                             " from the journal of the interrupted run; of the " +
                             std::to_string(161 - journal_rows) + " run now, "),
            std::string::npos)
      << resumed.out;
}

// Ctrl-C keeps the finished rows (in OUT.partial) and writes no table; --resume runs the rest,
// and the table equals an uninterrupted run's.
TEST(Sweep, AnInterruptKeepsTheFinishedRowsAndResumeCompletesThem) {
  const BackgroundSweep b =
      startSweep("  initial.spin: {from: -8, to: 8, count: 161}\nduration: 8\n");
  const auto& [dir, sweep, table, journal, command, pid] = b;
  ASSERT_GE(pid, 0);
  // Wait until some rows are in the journal, then interrupt.
  waitForRows(journal, 5);
  kill(pid, SIGINT);
  ASSERT_EQ(exitStatusOf(pid), 130) << slurp(dir / "stderr");
  EXPECT_FALSE(fs::exists(table));
  const std::string kept = slurp(journal);
  const auto kept_rows = std::count(kept.begin(), kept.end(), '\n') - 1;
  EXPECT_GT(kept_rows, 0);
  EXPECT_LT(kept_rows, 161);
  EXPECT_NE(slurp(dir / "stderr").find("--resume"), std::string::npos);

  // The same command typed again without --resume keeps the journal and says how to go on.
  const Outcome again = rattleback(dir, "sweep " + sweep.string() + " -q -o " + table.string());
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.err.find("holds " + std::to_string(kept_rows) + " finished runs"),
            std::string::npos)
      << again.err;
  EXPECT_EQ(slurp(journal), kept);
  EXPECT_FALSE(fs::exists(table));

  const Outcome resumed =
      rattleback(dir, "sweep " + sweep.string() + " --resume -o " + table.string());
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_FALSE(fs::exists(journal));
  // The summary counts the journal's rows and this run's (a fresh run mentions no journal).
  const std::string split = "(" + std::to_string(kept_rows) +
                            " from the journal of the interrupted run, " +
                            std::to_string(161 - kept_rows) + " run now)";
  EXPECT_NE(resumed.out.find(split), std::string::npos) << resumed.out;
  const Outcome whole =
      rattleback(dir, "sweep " + sweep.string() + " -o " + (dir / "whole.csv").string());
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_EQ(whole.out.find("journal"), std::string::npos) << whole.out;
  EXPECT_EQ(withoutWall(slurp(table)), withoutWall(slurp(dir / "whole.csv")));
}

// Ctrl-C before any run has finished leaves no journal (one of its header alone was left behind,
// with "0 of 2 runs kept" and --resume offered: a researcher's trial).
TEST(Sweep, AnInterruptBeforeAnyRunFinishedLeavesNoJournal) {
  const BackgroundSweep b = startSweep("  initial.spin: [-5, -4]\nduration: 100000\n", "");
  const auto& [dir, sweep, table, journal, command, pid] = b;
  ASSERT_GE(pid, 0);
  waitForRows(journal, 0);  // the runs have begun
  EXPECT_TRUE(fs::exists(journal));
  kill(pid, SIGINT);  // (each run of 1e5 s takes minutes)
  EXPECT_EQ(exitStatusOf(pid), 130);
  EXPECT_EQ(slurp(dir / "stderr"),
            sweep.string() + ": interrupted before any run finished; nothing kept\n");
  EXPECT_FALSE(fs::exists(journal));
  EXPECT_FALSE(fs::exists(journal.string() + ".json"));
  EXPECT_FALSE(fs::exists(table));
}

// --resume refuses a journal begun for another content of the sweep or its base scene: a changed
// duration or mass leaves every row's axis values as they were, and the resumed table mixed two
// sweeps' rows (a new user's first try: 16 rows of 25 s runs beside 4 of 6 s, exit 0).
TEST(Sweep, ResumeRefusesAJournalOfAChangedSweep) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const fs::path table = dir / "t.csv";
  auto interrupted = [&] {  // a journal as an interrupted run leaves it: header and one row
    ASSERT_EQ(rattleback(dir, "sweep " + sweep.string() + " -q -o " + table.string()).status, 0);
    std::ifstream in(table);
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    tasks::Journal::open(table.string(), header, {{0, row}},
                         tasks::sweepFingerprint(scene::loadSweep(sweep.string()).value()))
        .value()
        .close();
    fs::remove(table);
  };
  interrupted();
  EXPECT_EQ(rattleback(dir, "sweep " + sweep.string() + " -q --resume -o " + table.string()).status,
            0);
  // A comment and a blank line change nothing the sweep does: the journal is used.
  interrupted();
  std::ofstream(sweep, std::ios::app) << "\n# the same sweep, with a note\n";
  const Outcome noted =
      rattleback(dir, "sweep " + sweep.string() + " -q --resume -o " + table.string());
  EXPECT_EQ(noted.status, 0) << noted.err;
  interrupted();
  std::string text = slurp(sweep);
  text.replace(text.find("duration:"), std::string("duration:").size(), "duration: 0.2 #");
  std::ofstream(sweep) << text;
  const Outcome changed =
      rattleback(dir, "sweep " + sweep.string() + " -q --resume -o " + table.string());
  EXPECT_EQ(changed.status, 2);
  EXPECT_NE(changed.err.find("changed since the interrupted run"), std::string::npos)
      << changed.err;
  EXPECT_FALSE(fs::exists(table));
}

TEST(Sweep, TheMergeRefusesAMissingOrRepeatedRow) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  for (int i = 0; i < 2; ++i) {
    const Outcome r =
        rattleback(dir, "sweep " + sweep.string() + " -q --shard " + std::to_string(i) + "/2 -o " +
                            (dir / ("s" + std::to_string(i) + ".csv")).string());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const std::string s0 = (dir / "s0.csv").string(), s1 = (dir / "s1.csv").string();
  const Outcome missing = rattleback(dir, "sweep merge -q " + (dir / "m.csv").string() + " " + s0);
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("rows missing (3 of 6), e.g. 1 3 5"), std::string::npos)
      << missing.err;
  const Outcome repeated = rattleback(
      dir, "sweep merge -q " + (dir / "m.csv").string() + " " + s0 + " " + s1 + " " + s0);
  EXPECT_EQ(repeated.status, 2);
  EXPECT_NE(repeated.err.find("row 0 is also in"), std::string::npos) << repeated.err;
  EXPECT_FALSE(fs::exists(dir / "m.csv"));
  // A table has its sidecar and journal beside it: a device is refused, and nothing is made
  // beside the descriptor's link (it would be /dev/stdout.json).
  fs::remove(dir / "out.csv");
  fs::create_symlink("/proc/self/fd/1", dir / "out.csv");
  for (const std::string& command :
       {"sweep " + sweep.string() + " -q -o " + (dir / "out.csv").string(),
        "sweep merge -q " + (dir / "out.csv").string() + " " + s0 + " " + s1}) {
    const Outcome device = rattleback(dir, command);
    EXPECT_EQ(device.status, 2) << command;
    EXPECT_NE(device.err.find("a sweep's table is a file"), std::string::npos) << device.err;
  }
  EXPECT_FALSE(fs::exists(dir / "out.csv.json"));
  EXPECT_FALSE(fs::exists(dir / "out.csv.partial"));
}

// A sweep is its content: shards run from one sweep file by different paths merge, shards run
// after an edit to the sweep or its base scene are refused (their rows had been mixed, exit 0: a
// CI engineer's trial), and the merged table may not be one of its shards.
TEST(Sweep, TheMergeTellsSweepsApartByTheirContent) {
  const fs::path dir = fs::weakly_canonical(scratch());
  const fs::path sweep = writeSweep(dir, smallSweep());
  fs::create_directories(dir / "sub");
  const std::string s0 = (dir / "s0.csv").string(), s1 = (dir / "s1.csv").string();
  ASSERT_EQ(rattleback(dir, "sweep " + sweep.string() + " -q --shard 0/2 -o " + s0).status, 0);
  const std::string from_sub = "cd " + (dir / "sub").string() + " && " + RATTLEBACK_BIN +
                               " sweep ../sweep.yaml -q --shard 1/2 -o " + s1;
  ASSERT_EQ(std::system(from_sub.c_str()), 0);
  const Outcome same =
      rattleback(dir, "sweep merge -q " + (dir / "m.csv").string() + " " + s0 + " " + s1);
  EXPECT_EQ(same.status, 0) << same.err;
  std::string text = slurp(sweep);
  text.replace(text.find("duration:"), std::string("duration:").size(), "duration: 0.2 #");
  std::ofstream(sweep) << text;
  ASSERT_EQ(rattleback(dir, "sweep " + sweep.string() + " -q --shard 1/2 -o " + s1).status, 0);
  const Outcome edited =
      rattleback(dir, "sweep merge -q " + (dir / "e.csv").string() + " " + s0 + " " + s1);
  EXPECT_EQ(edited.status, 2);
  EXPECT_NE(edited.err.find(s1 + ": its sweep file or base scene was not as when " + s0 + " ran"),
            std::string::npos)
      << edited.err;
  EXPECT_FALSE(fs::exists(dir / "e.csv"));
  const std::string before = slurp(s0);
  const Outcome over = rattleback(dir, "sweep merge -q " + s0 + " " + s0 + " " + s1);
  EXPECT_EQ(over.status, 2);
  EXPECT_NE(over.err.find(s0 + ": is one of its own inputs, which it would replace"),
            std::string::npos)
      << over.err;
  EXPECT_EQ(slurp(s0), before);
  // `-o -` is standard output to simulate; a sweep had made files named - and -.json.
  const std::string dash = "cd " + (dir / "sub").string() + " && " + RATTLEBACK_BIN + " sweep " +
                           sweep.string() + " -q -o - 2>/dev/null";
  const int raw = std::system(dash.c_str());
  EXPECT_EQ(WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, 2);
  EXPECT_TRUE(fs::is_empty(dir / "sub"));
}

// The sidecar's base is the base scene's absolute path, wherever the sweep ran from, beside the
// path as the sweep file writes it (it was relative to the folder the sweep ran from, which the
// sidecar does not say: "../mine.yaml", a researcher's trial).
TEST(Sweep, TheSidecarsBaseIsAbsolute) {
  const fs::path dir = fs::weakly_canonical(scratch());
  fs::copy_file(kBase, dir / "mine.yaml", fs::copy_options::overwrite_existing);
  writeSweep(dir, "base: mine.yaml\nvary:\n  initial.spin: [-5]\nduration: 0.1\n");
  fs::create_directories(dir / "sub");
  const std::string command =
      "cd " + (dir / "sub").string() + " && " + RATTLEBACK_BIN + " sweep ../sweep.yaml -q -o t.csv";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const nlohmann::json meta = nlohmann::json::parse(slurp(dir / "sub" / "t.csv.json"));
  EXPECT_EQ(meta.value("base", ""), (dir / "mine.yaml").string());
  EXPECT_EQ(meta.value("base_as_written", ""), "mine.yaml");
}

// The merge lists its table and plot in the folder's manifest as an in-process sweep does, and
// the report shows the merged sweep once, its shards as its parts (each shard had been a
// "Sweep:" section of its own saying it held all the sweep's runs). A shard's sidecar counts
// its own rows.
TEST(Sweep, TheMergeIsListedAndTheReportShowsTheSweepOnce) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const fs::path par = dir / "par";  // made by the shards
  std::string shards;
  for (int i = 0; i < 3; ++i) {
    const std::string shard = tasks::shardPath((par / "t.csv").string(), tasks::Shard{i, 3});
    const Outcome r = rattleback(
        dir, "sweep " + sweep.string() + " -q --shard " + std::to_string(i) + "/3 -o " + shard);
    ASSERT_EQ(r.status, 0) << r.err;
    shards += " " + shard;
  }
  const nlohmann::json shard_meta =
      nlohmann::json::parse(slurp(par / "t.shard-1-of-3.csv.json"), nullptr, false);
  EXPECT_EQ(shard_meta.value("rows", -1), 2) << shard_meta.dump();  // rows 1 and 4 of 6
  EXPECT_EQ(shard_meta["shard"].value("sweep_rows", -1), 6) << shard_meta.dump();
  EXPECT_EQ(shard_meta.value("base_as_written", ""), kBase);

  // Not merged yet: each shard says it is one.
  ASSERT_EQ(rattleback(dir, "report -q " + par.string()).status, 0);
  const std::string before = slurp(par / "index.html");
  EXPECT_NE(before.find("2 runs of the sweep's 6 (shard 1 of 3, not merged here)"),
            std::string::npos)
      << before;

  const Outcome merged = rattleback(dir, "sweep merge -q " + (par / "t.csv").string() + shards +
                                             " --plot " + (par / "t.png").string());
  ASSERT_EQ(merged.status, 0) << merged.err;
  const nlohmann::json manifest =
      nlohmann::json::parse(slurp(par / "rattleback-manifest.json"), nullptr, false);
  std::map<std::string, std::string> kinds;
  for (const auto& e : manifest["outputs"]) kinds[e["file"]] = e["kind"];
  EXPECT_EQ(kinds["t.csv"], "sweep") << manifest.dump();
  EXPECT_EQ(kinds["t.png"], "sweep_plot") << manifest.dump();
  EXPECT_EQ(nlohmann::json::parse(slurp(par / "t.csv.json"))["rows"], 6);

  ASSERT_EQ(rattleback(dir, "report -q " + par.string()).status, 0);
  const std::string page = slurp(par / "index.html");
  std::size_t sections = 0;
  for (std::size_t at = page.find("<h2>Sweep: "); at != std::string::npos;
       at = page.find("<h2>Sweep: ", at + 1))
    ++sections;
  EXPECT_EQ(sections, 1u) << page;
  EXPECT_NE(page.find("<h2>Sweep: t</h2>"), std::string::npos) << page;
  EXPECT_NE(page.find("6 runs of"), std::string::npos) << page;
  EXPECT_NE(page.find("merged from 3 shards: <a href=\"t.shard-0-of-3.csv\">"), std::string::npos)
      << page;
  EXPECT_NE(page.find("<img src=\"t.png\""), std::string::npos) << page;
}

// The Slurm script: a job array of N tasks, one shard each, and the merge after all of them.
TEST(Sweep, EmitSlurmWritesAJobArrayAndItsMerge) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const Outcome r = rattleback(
      dir, "sweep " + sweep.string() + " --emit slurm --shards 3 -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("#SBATCH --array=0-2\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("--dependency=afterok:\"$SLURM_ARRAY_JOB_ID\""), std::string::npos);
  EXPECT_NE(r.out.find("--shard \"$SLURM_ARRAY_TASK_ID/3\""), std::string::npos);
  std::ofstream(dir / "job.sh") << r.out;
  EXPECT_EQ(std::system(("bash -n " + (dir / "job.sh").string()).c_str()), 0);
  const Outcome p = rattleback(dir, "sweep " + sweep.string() + " --emit parallel --shards 3");
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(std::count(p.out.begin(), p.out.end(), '\n'), 3);
  const Outcome none = rattleback(dir, "sweep " + sweep.string() + " --emit slurm");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--shards"), std::string::npos);
  // The table's folder is made with the script: its #SBATCH --output logs go there, and Slurm
  // opens them before the script runs (every task failed, silently, into a new folder).
  const Outcome fresh = rattleback(dir, "sweep " + sweep.string() + " --emit slurm --shards 2 -o " +
                                            (dir / "new" / "t.csv").string());
  ASSERT_EQ(fresh.status, 0) << fresh.err;
  EXPECT_NE(fresh.out.find("#SBATCH --output=" + (dir / "new").string() + "/slurm-"),
            std::string::npos)
      << fresh.out;
  EXPECT_TRUE(fs::is_directory(dir / "new"));
}

// --plot goes to the merge job (it was dropped: the merge made no heatmap); GNU parallel runs
// only the shards, so there it is refused with the command that plots.
TEST(Sweep, EmitKeepsThePlotForTheMerge) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, smallSweep());
  const Outcome r = rattleback(dir, "sweep " + sweep.string() + " --emit slurm --shards 2 -o " +
                                        (dir / "t.csv").string() + " --plot " +
                                        (dir / "t.png").string() + " --metric final_spin");
  ASSERT_EQ(r.status, 0) << r.err;
  // (Quoted twice: a word of the merge's --wrap, itself one shell word.)
  EXPECT_NE(
      r.out.find("--plot '\\''" + (dir / "t.png").string() + "'\\'' --metric '\\''final_spin"),
      std::string::npos)
      << r.out;
  // GNU parallel runs the shards only: the message gives the merge that plots, with this
  // sweep's names (it gave a template), and no folder is left made.
  const Outcome p =
      rattleback(dir, "sweep " + sweep.string() + " --emit parallel --shards 2 -o " +
                          (dir / "new" / "t.csv").string() + " --plot " + (dir / "t.png").string());
  EXPECT_EQ(p.status, 2);
  EXPECT_NE(p.err.find(" sweep merge '" + (dir / "new" / "t.csv").string() + "' '" +
                       (dir / "new" / "t.shard-").string() + "'*'-of-2.csv' --plot '" +
                       (dir / "t.png").string() + "'"),
            std::string::npos)
      << p.err;
  EXPECT_FALSE(fs::exists(dir / "new"));
}

// The commands that only simulate start without the rendering libraries (OSMesa and LLVM behind
// it, EGL, libav): `rattleback` is not linked to them; rattleback-render is, beside it.
TEST(Sweep, TheProgramThatSimulatesLoadsNoRenderingLibrary) {
  const fs::path dir = scratch();
  const std::string bin = RATTLEBACK_BIN;
  const int raw = std::system(("ldd " + bin + " > " + (dir / "ldd").string()).c_str());
  ASSERT_EQ(WEXITSTATUS(raw), 0);
  const std::string libraries = slurp(dir / "ldd");
  for (const char* heavy :
       {"libOSMesa", "libEGL", "libGL", "libLLVM", "libavcodec", "libavformat", "libswscale"})
    EXPECT_EQ(libraries.find(heavy), std::string::npos) << heavy << " in\n" << libraries;
  EXPECT_TRUE(fs::exists(fs::path(bin).parent_path() / "rattleback-render"));
}

// `columns:` is a sweep key like the others: a list of the table's columns, each once; a
// misspelt name or key is one line naming the file, the line (the entry's own) and the nearest
// name, exit 2, nothing written. A plot of a column the table does not hold is refused too.
TEST(Sweep, ColumnsAreListedOnceFromTheTablesOwnAndATypoIsNamedWithTheNearest) {
  const fs::path dir = scratch();
  struct Case {
    std::string text, expected;
  };
  const std::string head = "base: BASE\nvary:\n  initial.spin: [-5]\n";
  const Case cases[] = {
      {head + "columns: [first_reversl_s]\n",
       "sweep.yaml:4: columns: first_reversl_s is not a column of the table; did you mean "
       "first_reversal_s?"},
      // The entry's own line, in a block list.
      {head + "columns:\n  - status\n  - forcast_s\n",
       "sweep.yaml:6: columns: forcast_s is not a column of the table; did you mean forecast_s?"},
      {head + "columns: [status, status]\n", "sweep.yaml:4: columns: status is listed twice"},
      {head + "columns: first_reversal_s\n", "sweep.yaml:4: columns must be a list"},
      {head + "columns: []\n", "sweep.yaml:4: columns must be a list"},
      {head + "colums: [status]\n",
       "sweep.yaml:4: colums is not a key of a sweep; did you mean columns?"},
  };
  for (const Case& c : cases) {
    std::string text = c.text;
    text.replace(text.find("BASE"), 4, kBase);
    const fs::path sweep = writeSweep(dir, text);
    const Outcome r =
        rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
    EXPECT_EQ(r.status, 2) << c.text;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.text << "\ngot: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "t.csv")) << c.text;
  }
  std::string text = head + "columns: [first_reversal_s]\n";
  text.replace(text.find("BASE"), 4, kBase);
  const fs::path sweep = writeSweep(dir, text);
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q --metric final_spin --plot " +
                          (dir / "p.png").string() + " -o " + (dir / "t.csv").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--metric final_spin: the sweep's columns: does not list it"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "t.csv"));
  // A misspelt metric is named with the nearest, as a misspelt column is.
  const Outcome typo = rattleback(
      dir, "sweep " + sweep.string() + " -q --metric final_spn -o " + (dir / "t.csv").string());
  EXPECT_EQ(typo.status, 2);
  EXPECT_NE(typo.err.find("--metric: 'final_spn' is not a column to plot; did you mean "
                          "final_spin? (one of "),
            std::string::npos)
      << typo.err;
}

// A sweep that lists its columns holds those (after the row and the axes, in the order listed),
// with the values the whole table gives: first_reversal_s from runs stopped once it is confirmed
// (RolloutControl.StoppedOnceItsReversalIsConfirmed… says why it is the same number), and a
// column that needs the whole run (max_tilt_deg: the rocking can grow after the reversal) from a
// run kept to its end. Its shards merge to the same table.
TEST(Sweep, AColumnsSweepHoldsItsColumnsWithTheWholeRunsValues) {
  const fs::path dir = scratch();
  const fs::path full = writeSweep(dir, smallSweep());
  ASSERT_EQ(
      rattleback(dir, "sweep " + full.string() + " -q -o " + (dir / "full.csv").string()).status,
      0);
  const auto reference = readCsv(slurp(dir / "full.csv"));
  struct Listed {
    std::string columns;
    std::vector<std::string> names;
  };
  for (const Listed& listed :
       {Listed{"[first_reversal_s, status]", {"first_reversal_s", "status"}},
        Listed{"[max_tilt_deg, first_reversal_s]", {"max_tilt_deg", "first_reversal_s"}}}) {
    const fs::path sweep = dir / "listed.yaml";
    std::ofstream(sweep) << smallSweep() << "columns: " << listed.columns << "\n";
    const Outcome r =
        rattleback(dir, "sweep " + sweep.string() + " -q -j 2 -o " + (dir / "t.csv").string());
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = readCsv(slurp(dir / "t.csv"));
    std::vector<std::string> header{"row", "initial.spin", "body.dents.scale"};
    header.insert(header.end(), listed.names.begin(), listed.names.end());
    ASSERT_EQ(rows.at(0), header) << listed.columns;
    ASSERT_EQ(rows.size(), reference.size());
    int reversed = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      for (const std::string& name : listed.names)
        EXPECT_EQ(rows[i][at(rows, name)], reference[i][at(reference, name)])
            << name << ", row " << i << ", columns " << listed.columns;
      reversed += !rows[i][at(rows, "first_reversal_s")].empty();
    }
    EXPECT_EQ(reversed, 3) << "the table is not a column of empty cells";
    const auto sidecar = nlohmann::json::parse(slurp(dir / "t.csv.json"));
    ASSERT_EQ(sidecar["columns"].size(), header.size());
    for (std::size_t i = 0; i < header.size(); ++i)
      EXPECT_EQ(sidecar["columns"][i]["name"], header[i]);
  }
  // Shards of the listed sweep merge to its table (the merge reads the columns from the header).
  const fs::path sweep = dir / "listed.yaml";
  for (int i = 0; i < 2; ++i)
    ASSERT_EQ(rattleback(dir, "sweep " + sweep.string() + " -q --shard " + std::to_string(i) +
                                  "/2 -o " + (dir / ("s" + std::to_string(i) + ".csv")).string())
                  .status,
              0);
  const Outcome merged =
      rattleback(dir, "sweep merge -q " + (dir / "m.csv").string() + " " +
                          (dir / "s0.csv").string() + " " + (dir / "s1.csv").string() +
                          " --metric max_tilt_deg --plot " + (dir / "m.png").string());
  ASSERT_EQ(merged.status, 0) << merged.err;
  EXPECT_EQ(slurp(dir / "m.csv"), slurp(dir / "t.csv"));
}

// forecast_s is the number `analyze` prints for the row's scene (predicted_first_reversal's
// time_s, the same computation, to the bit), empty where analyze gives none: spins the theory
// forecasts (−5, −2 rad/s), the preferred way (+5: none within the run), one far outside its
// range (−30 rad/s: n²ρ/g ≈ 31, where the averaged theory is not used) and a scene not spun
// (which analyze's theory takes at +5 rad/s: with the dents mirrored, the way that reverses).
// forecast_note says which of these each row is, as analyze's range and time say it.
TEST(Sweep, TheForecastColumnIsAnalyzesForecast) {
  const fs::path dir = scratch();
  std::string text =
      "base: BASE\nvary:\n  initial.spin: [-5, -2, 5, -30, 0]\n  body.dents.at[0]: [0.73, "
      "-0.73]\ncolumns: [forecast_s, forecast_note]\n";
  text.replace(text.find("BASE"), 4, kBase);
  const fs::path sweep = writeSweep(dir, text);
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 11u);
  const std::string base = slurp(kBase);
  int forecast = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::string scene_text = base;
    scene_text.replace(scene_text.find("spin: -5.0"), 10, "spin: " + rows[i][1]);
    scene_text.replace(scene_text.find("at: [0.73"), 9, "at: [" + rows[i][2]);
    const fs::path scene = dir / ("row" + std::to_string(i) + ".yaml");
    std::ofstream(scene) << scene_text;
    const std::string cell = rows[i][at(rows, "forecast_s")];
    const std::string note = rows[i][at(rows, "forecast_note")];
    if (rows[i][1] == "0") {
      EXPECT_EQ(note, "not_spun");
      const Outcome a = rattleback(dir, "analyze " + scene.string());
      ASSERT_EQ(a.status, 0) << a.err;
      EXPECT_NE(a.out.find("first reversal   none: the scene is not spun"), std::string::npos)
          << a.out;
      EXPECT_EQ(cell, "");
      continue;
    }
    const Outcome a = rattleback(dir, "analyze " + scene.string() + " --json");
    ASSERT_EQ(a.status, 0) << a.err;
    const auto predicted = nlohmann::json::parse(a.out)["predicted_first_reversal"];
    const auto time = predicted["time_s"];
    const std::string range = predicted["range"].get<std::string>();
    if (time.is_null()) {
      EXPECT_EQ(cell, "") << "spin " << rows[i][1];
      EXPECT_EQ(note, range == "outside" ? "outside_range" : "none_in_run")
          << "spin " << rows[i][1];
    } else {
      EXPECT_EQ(note, range) << "spin " << rows[i][1];
      ++forecast;
      ASSERT_NE(cell, "") << "spin " << rows[i][1];
      EXPECT_EQ(std::stod(cell), time.get<double>()) << "spin " << rows[i][1];
    }
  }
  EXPECT_EQ(forecast, 3) << "−5 and −2 rad/s with the dents as shipped, +5 with them mirrored";
}

// `exports` says what `export` does with each row's body: scales either side of the shipped
// dents' edge (they reach the bottom from 0.49, docs/getting-started.md), each checked by running
// export on the row's scene, whose refusal is exit 2.
TEST(Sweep, TheExportsColumnIsWhatExportDoes) {
  const fs::path dir = scratch();
  const fs::path sweep = writeSweep(dir, "base: " + kBase +
                                             "\nvary:\n  body.dents.scale: [0.3, 0.48, 0.49, "
                                             "0.6]\ncolumns: [exports]\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 5u);
  int yes = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::string scale = rows[i][1], cell = rows[i][at(rows, "exports")];
    const Outcome e = rattleback(dir, "export " + kBase + " --set body.dents.scale=" + scale +
                                          " -o " + (dir / ("b" + scale + ".stl")).string());
    ASSERT_TRUE(e.status == 0 || e.status == 2) << e.err;
    EXPECT_EQ(cell, e.status == 0 ? "yes" : "no") << "scale " << scale << ": " << e.err;
    yes += cell == "yes";
  }
  EXPECT_EQ(yes, 2) << "0.3 and 0.48 export; 0.49 and 0.6 reach through the bottom";
}

// A mesh body whose bottom a quadric fits has analyze's theory (§P11.4), so its forecast too: the
// sweep's column left every mesh body's empty while analyze gave it.
TEST(Sweep, AMeshBodysForecastIsAnalyzes) {
  const fs::path dir = scratch();
  const std::string printed = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/printed.yaml";
  const fs::path sweep = writeSweep(
      dir, "base: " + printed + "\nvary:\n  initial.spin: [-5, 5]\ncolumns: [forecast_s]\n");
  const Outcome r =
      rattleback(dir, "sweep " + sweep.string() + " -q -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  ASSERT_EQ(rows.size(), 3u);
  const Outcome a = rattleback(dir, "analyze " + printed + " --json");
  ASSERT_EQ(a.status, 0) << a.err;
  const auto time = nlohmann::json::parse(a.out)["predicted_first_reversal"]["time_s"];
  ASSERT_TRUE(time.is_number()) << a.out;
  ASSERT_NE(rows[1][at(rows, "forecast_s")], "");
  EXPECT_EQ(std::stod(rows[1][at(rows, "forecast_s")]), time.get<double>());
  EXPECT_EQ(rows[2][at(rows, "forecast_s")], "") << "spun the preferred way: none within the run";
}

// The summary of a search over bodies spun each way says how many reverse both ways and how many
// of those export, as counted here from its table (rows alike but for initial.spin are one body;
// it reverses both ways where its spin -8 and its spin 8 row each have a first reversal), and
// names the first such body that exports, in the table's order.
TEST(Sweep, TheBothWaysLineIsWhatTheTableSays) {
  const fs::path dir = scratch();
  const std::string search = std::string(RATTLEBACK_SOURCE_DIR) + "/sweeps/both-ways-search.yaml";
  const Outcome r = rattleback(dir, "sweep " + search + " -j 2 -o " + (dir / "t.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(slurp(dir / "t.csv"));
  const std::size_t spin = at(rows, "initial.spin"), first = at(rows, "first_reversal_s"),
                    exports = at(rows, "exports");
  std::map<std::string, std::vector<std::size_t>> bodies;  // the dents' three values: rows
  for (std::size_t i = 1; i < rows.size(); ++i)
    bodies[rows[i][1] + " " + rows[i][2] + " " + rows[i][3]].push_back(i);
  int both = 0, exporting = 0;
  std::size_t first_row = rows.size();
  for (const auto& [dents, lines] : bodies) {
    ASSERT_EQ(lines.size(), 2u) << dents;
    bool clockwise = false, anticlockwise = false, solid = true;
    for (std::size_t i : lines) {
      const bool reversed = !rows[i][first].empty();
      (std::stod(rows[i][spin]) < 0 ? clockwise : anticlockwise) |= reversed;
      solid &= rows[i][exports] == "yes";
    }
    if (!clockwise || !anticlockwise) continue;
    ++both;
    if (!solid) continue;
    ++exporting;
    first_row = std::min(first_row, lines.front());
  }
  ASSERT_LT(first_row, rows.size());
  const std::string line =
      "both ways       " + std::to_string(both) + " of " + std::to_string(bodies.size()) +
      " bodies reverse both ways (a first reversal spun each way), " + std::to_string(exporting) +
      " of them exporting a solid; the first that exports: "
      "body.dents.at[0] " +
      rows[first_row][1] + ", body.dents.at[1] " + rows[first_row][2] + ", body.dents.scale " +
      rows[first_row][3] + " (rows " + rows[first_row][0] + ", " + rows[first_row + 1][0] + ")\n";
  EXPECT_NE(r.out.find(line), std::string::npos) << r.out << "\nexpected: " << line;
  EXPECT_GT(both, exporting) << "deeper dents reverse both ways and cut through the bottom";
}

// Where the rows alike but for the spin differ in other than the body (a tilt), they are the
// tilt's settings, not bodies; a group of many rows lists its first three and last two (a
// sweep of 50 spins had listed 50 rows and called its tilts "bodies").
TEST(Sweep, BothWaysNamesWhatItGroupsAndShortensALongListOfRows) {
  tasks::BothWays found;
  found.bodies = 8;
  found.both = 7;
  found.other_keys = {"initial.tilt[0]"};
  found.first_values = {"initial.tilt[0] 0.8"};
  for (std::int64_t row = 1; row < 400; row += 8) found.first_rows.push_back(row);
  EXPECT_EQ(
      tasks::describe(found),
      "7 of 8 settings of initial.tilt[0] reverse both ways (a first reversal spun each way); "
      "the first: initial.tilt[0] 0.8 (rows 1, 9, 17, …, 385, 393: 50 rows)");
  found.other_keys = {"body.dents.scale"};
  found.first_values = {"body.dents.scale 0.5"};
  found.first_rows = {4, 5};
  EXPECT_EQ(tasks::describe(found),
            "7 of 8 bodies reverse both ways (a first reversal spun each way); the first: "
            "body.dents.scale 0.5 (rows 4, 5)");
}

// A sweep of spins alone is one body: the line names the first run that reverses each way
// (stopped runs are not reversals), not "1 of 1 body" and all its rows.
TEST(Sweep, BothWaysOfOneBodyNamesItsFirstReversalEachWay) {
  const fs::path file =
      writeSweep(scratch(), "base: " + kBase + "\nvary:\n  initial.spin: [-6, -4, -1, 1, 2]\n");
  auto sweep = scene::loadSweep(file.string());
  ASSERT_TRUE(sweep) << sweep.error().text();
  const double none = std::numeric_limits<double>::quiet_NaN();
  auto found = tasks::bothWays(sweep.value(), {none, 3.16, none, none, 0.69});
  ASSERT_TRUE(found);
  EXPECT_EQ(tasks::describe(*found),
            "the body reverses both ways: first spun clockwise in row 1 (initial.spin -4), "
            "counter-clockwise in row 4 (initial.spin 2)");
  found = tasks::bothWays(sweep.value(), {none, none, none, 0.9, 0.69});
  ASSERT_TRUE(found);
  EXPECT_EQ(tasks::describe(*found),
            "the body reverses one way only: no run spun clockwise reverses");
}

// The theory's forecast is the scene's, drawn whatever became of its run (a run that stopped on
// a mesh's rim had lost its forecast from the plot); the runs' own first reversals only where
// the run was ok.
TEST(SweepPlot, AStoppedRunKeepsItsForecastButNotItsReversal) {
  const tasks::SweepColumns columns =
      tasks::columnsNamed({"status", "first_reversal_s", "forecast_s"});
  const std::vector<std::string> lines = {"0,-6,stopped,,1.88", "1,-4,ok,3.16,3.37", "2,-2,ok,,"};
  const std::vector<double> forecast =
      app::forecastsOf(lines, 1, columns, tasks::SweepMetric::FirstReversal);
  ASSERT_EQ(forecast.size(), 3u);
  EXPECT_EQ(forecast[0], 1.88);
  EXPECT_EQ(forecast[1], 3.37);
  EXPECT_TRUE(std::isnan(forecast[2]));
  EXPECT_TRUE(std::isnan(app::metricOf(lines[0], 1, columns, tasks::SweepMetric::FirstReversal)));
  EXPECT_EQ(app::metricOf(lines[1], 1, columns, tasks::SweepMetric::FirstReversal), 3.16);
}

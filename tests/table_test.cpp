// The tables' numbers (docs/commands.md "The telemetry CSV"): every number the CSV writes reads
// back as exactly the double that was computed, in the shortest text that does, and the same text
// as the JSON sidecars.
#include "tasks/table.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "support.hpp"
#include "tasks/shortest.hpp"
#include "tasks/simulate.hpp"

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

}  // namespace

// Doubles of every magnitude, and the awkward ones: subnormals, the extremes, −0, and values
// one ulp apart (which a fixed count of digits below 17 cannot tell apart).
TEST(Numbers, EveryDoubleReadsBackExactly) {
  std::mt19937_64 bits(27);
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                0.1,
                                1e-4,
                                2.3158,
                                -4.999619237890977,
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                std::nextafter(0.1, 1.0),
                                std::nextafter(2.3158, 0.0)};
  for (int i = 0; i < 50000; ++i) {
    double v;
    const std::uint64_t b = bits();
    std::memcpy(&v, &b, sizeof v);
    if (std::isfinite(v)) values.push_back(v);
  }
  for (double v : values) {
    const std::string text = tasks::number(v);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), v) << text;
    ASSERT_NE(text, "-0");
    // The shortest: it has no more significant digits than the fewest that %.*g needs to
    // read back as v.
    int needed = 1;
    for (char fewer[40];; ++needed) {
      std::snprintf(fewer, sizeof fewer, "%.*g", needed, v);
      if (std::strtod(fewer, nullptr) == v) break;
    }
    std::string significant;
    for (char c : text.substr(0, text.find('e')))
      if (std::isdigit(static_cast<unsigned char>(c))) significant += c;
    significant.erase(0, significant.find_first_not_of('0'));
    significant.erase(significant.find_last_not_of('0') + 1);
    ASSERT_LE(static_cast<int>(significant.size()), std::max(needed, 1)) << text;
  }
  EXPECT_EQ(tasks::number(std::nullopt), "");
  EXPECT_EQ(tasks::number(std::numeric_limits<double>::quiet_NaN()), "");
  EXPECT_EQ(tasks::number(-0.0), "0");
  EXPECT_EQ(tasks::number(0.1), "0.1");
  EXPECT_EQ(tasks::number(2.5e-5), "2.5e-05");
}

// Our formatter (tasks/shortest.cpp, faster) writes what libstdc++'s std::to_chars writes, an
// independent implementation (Ryu): byte for byte over doubles of every exponent, and where a
// formatter goes wrong: the ends of each binade (where the lower neighbour is nearer), powers of
// ten and their neighbours, subnormals, whole numbers, decimals of every length (whose doubles
// lie on or next to a rounding boundary: 4192 of the 19 million tried here differed before the
// exact products of 5^k were seen to).
TEST(Numbers, OurShortestIsToCharsByteForByte) {
  std::vector<double> values;
  std::mt19937_64 random(2711);
  for (int i = 0; i < 1000000; ++i) values.push_back(std::bit_cast<double>(random()));
  std::uniform_real_distribution<double> telemetryLike(-3, 3);
  for (int i = 0; i < 300000; ++i) values.push_back(telemetryLike(random));
  for (int e = -1074; e <= 1023; ++e) {
    const double p = std::ldexp(1.0, e);
    values.insert(values.end(), {p, std::nextafter(p, 0.0), std::nextafter(p, 2 * p)});
  }
  for (int e = -325; e <= 308; ++e) {
    double x = std::pow(10.0, e);
    for (int j = 0; j < 4; ++j) x = std::nextafter(x, 0.0);
    for (int j = 0; j < 8; ++j, x = std::nextafter(x, HUGE_VAL)) values.push_back(x);
  }
  for (std::uint64_t i = 1; i < 100000; ++i) values.push_back(std::bit_cast<double>(i));
  for (int i = -100000; i < 100000; ++i)
    values.insert(values.end(), {double(i), i / 10.0, i / 1000.0, i * 1e-7, i * 1e15});
  std::uniform_int_distribution<int> length(1, 17), exponent(-30, 30);
  for (int i = 0; i < 300000; ++i) {
    std::uint64_t digits = random() % 100000000000000000ULL;
    for (int j = length(random); j < 17; ++j) digits /= 10;
    const std::string text = std::to_string(digits) + "e" + std::to_string(exponent(random));
    values.push_back(std::strtod(text.c_str(), nullptr));
  }
  values.insert(values.end(), {0.0, -0.0, std::numeric_limits<double>::max()});
  std::size_t tried = 0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    char want[40], got[40];
    const std::string_view expected(
        want, std::to_chars(want, want + sizeof want, v, std::chars_format::general).ptr);
    const std::string_view ours(got, tasks::writeShortest(got, v));
    ASSERT_EQ(ours, expected) << std::bit_cast<std::uint64_t>(v);
    ++tried;
  }
  EXPECT_GT(tried, 2000000u);
}

// A telemetry row is the sample, exactly: each column read back with strtod equals the value
// the run computed, as the JSON sidecars' numbers do.
TEST(Numbers, TelemetryRowsAreTheSamplesExactly) {
  using namespace testing_support;
  sim::SceneSpec spec = parse(kStableScene);
  spec.simulation.duration = 0.05;
  const Recorded run = record(build(spec), 1e-3);
  ASSERT_GT(run.samples.size(), 40u);
  const auto header =
      split(tasks::telemetryHeader().substr(0, tasks::telemetryHeader().size() - 1));
  for (const sim::Telemetry& s : run.samples) {
    std::ostringstream out;
    tasks::writeTelemetryRow(out, s);
    std::string line = out.str();
    ASSERT_EQ(line.back(), '\n');
    line.pop_back();
    const auto fields = split(line);
    ASSERT_EQ(fields.size(), header.size());
    const Eigen::Quaterniond q = tasks::attitude(s);
    const auto table = tasks::telemetryTable();
    for (std::size_t i = 0; i < header.size(); ++i) {
      ASSERT_EQ(header[i], table[i].column.name);
      if (table[i].kind == tasks::ColumnKind::Mode) {
        EXPECT_EQ(fields[i], std::string(rb::nameOf(s.mode)));
        continue;
      }
      const double value = table[i].value({s, q});
      ASSERT_EQ(std::strtod(fields[i].c_str(), nullptr), value) << header[i] << " = " << fields[i];
      // The sidecars' JSON (nlohmann's dump) reads back as the same double.
      ASSERT_EQ(nlohmann::json::parse(nlohmann::json(value).dump()).get<double>(), value);
    }
    // And the columns are what their names say, read from the sample by hand.
    const auto at = [&](const std::string& name) {
      const auto i = std::find(header.begin(), header.end(), name) - header.begin();
      return std::strtod(fields.at(static_cast<std::size_t>(i)).c_str(), nullptr);
    };
    const std::map<std::string, double> expected = {{"t", s.t},
                                                    {"spin", s.spin},
                                                    {"energy", s.energy},
                                                    {"kinetic", s.kinetic},
                                                    {"potential", s.potential},
                                                    {"elastic", s.elastic},
                                                    {"tilt_deg", s.tilt_deg},
                                                    {"x", s.x_world.x()},
                                                    {"y", s.x_world.y()},
                                                    {"z", s.x_world.z()},
                                                    {"wx", s.w_world.x()},
                                                    {"wy", s.w_world.y()},
                                                    {"wz", s.w_world.z()},
                                                    {"Lz", s.L_world.z()},
                                                    {"contacts", s.contacts},
                                                    {"normal_force", s.normal_force},
                                                    {"qw", q.w()},
                                                    {"qx", q.x()},
                                                    {"qy", q.y()},
                                                    {"qz", q.z()}};
    for (const auto& [name, value] : expected) ASSERT_EQ(at(name), value) << name;
  }
}

// A stable scene's 0.1 s sampled at 100 kHz: 10,001 rows, three chunks of 4,096 and a rest.
static std::pair<sim::Model, testing_support::Recorded> tenThousandRows() {
  using namespace testing_support;
  sim::SceneSpec spec = parse(kStableScene);
  spec.simulation.duration = 0.1;
  sim::Model model = build(spec);
  Recorded run = record(model, 1e-5);
  return {std::move(model), std::move(run)};
}

// The file at `path` holds `expected` byte for byte; then it and its sidecar are removed.
static void expectTheFileHolds(const std::string& path, const std::string& expected) {
  std::stringstream written;
  written << std::ifstream(path).rdbuf();
  EXPECT_TRUE(written.str() == expected);  // (not EXPECT_EQ: 3 MB of text on a failure)
  EXPECT_EQ(written.str().size(), expected.size());
  std::filesystem::remove(path);
  std::filesystem::remove(path + ".json");
}

// The CSV is formatted in chunks of rows on threads of their own and written in order: the
// file is the header and every row as writeTelemetryRow writes it, in time order, across chunk
// boundaries (10,001 rows: three chunks of 4,096 and a rest).
TEST(Numbers, AChunkedCsvIsTheRowsInOrder) {
  const auto [model, run] = tenThousandRows();
  ASSERT_EQ(run.samples.size(), 10001u);
  const std::string path =
      (std::filesystem::temp_directory_path() / "rattleback-chunked.csv").string();
  ASSERT_TRUE(tasks::writeTelemetry(path, {"s.yaml", {}}, model, 1e5, run.summary, run.samples));
  std::ostringstream expected;
  expected << tasks::telemetryHeader();
  for (const sim::Telemetry& s : run.samples) tasks::writeTelemetryRow(expected, s);
  expectTheFileHolds(path, expected.str());
}

// Python's to_csv on Ctrl-C: the writing stops between chunks, nothing is put in place, and the
// file that was there stays as it was, its sidecar too (it had finished, replaced the file and
// only then raised KeyboardInterrupt: a researcher's trial).
TEST(Numbers, AWriteStoppedPutsNothingInPlace) {
  const auto [model, run] = tenThousandRows();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "rattleback-stopped-write";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "t.csv").string();
  std::ofstream(path) << "the file there before\n";
  std::ofstream(path + ".json") << "{}\n";
  const nlohmann::json sidecar =
      tasks::telemetrySidecar({"s.yaml", {}}, model, 1e5, run.summary, 10001);
  int asked = 0;
  const rb::Status stopped =
      tasks::writeTelemetry(path, run.samples, sidecar, [&] { return ++asked > 1; });
  EXPECT_FALSE(stopped);
  EXPECT_EQ(asked, 2);  // asked before each chunk, and stopped at the second
  std::stringstream csv, json;
  csv << std::ifstream(path).rdbuf();
  json << std::ifstream(path + ".json").rdbuf();
  EXPECT_EQ(csv.str(), "the file there before\n");
  EXPECT_EQ(json.str(), "{}\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 2);  // no part files
  // Never asked to stop: the whole table.
  ASSERT_TRUE(tasks::writeTelemetry(path, run.samples, sidecar, [] { return false; }));
  std::ostringstream expected;
  expected << tasks::telemetryHeader();
  for (const sim::Telemetry& s : run.samples) tasks::writeTelemetryRow(expected, s);
  expectTheFileHolds(path, expected.str());
  std::filesystem::remove_all(dir);
}

// Rows handed over one at a time, as `simulate` writes while it runs: the writer's threads format
// chunks while more come, and write them in order (40,004 rows: ten chunks, more than are let
// wait at once, so that the caller's thread helps too).
TEST(Numbers, ACsvWrittenAsTheRunGoesIsTheRowsInOrder) {
  const auto [model, run] = tenThousandRows();
  const std::string path =
      (std::filesystem::temp_directory_path() / "rattleback-as-it-goes.csv").string();
  auto writer = tasks::TelemetryWriter::open(path);
  ASSERT_TRUE(writer);
  std::ostringstream expected;
  expected << tasks::telemetryHeader();
  for (int pass = 0; pass < 4; ++pass)
    for (const sim::Telemetry& s : run.samples) {
      writer->row(s);
      tasks::writeTelemetryRow(expected, s);
    }
  ASSERT_EQ(writer->rows(), 40004);
  ASSERT_TRUE(writer->commit({"s.yaml", {}}, model, 1e5, run.summary));
  expectTheFileHolds(path, expected.str());
}

// The telemetry's reader's page lists every column of the table, in its order: the header line
// it quotes is the writer's, and each column has a row of the page's table (a column added to
// tasks::telemetryTable without a word for the reader fails here).
TEST(Docs, TheTelemetryPageListsEveryColumn) {
  std::ifstream in(std::string(RATTLEBACK_SOURCE_DIR) + "/docs/commands.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const std::string header = tasks::telemetryHeader();
  EXPECT_NE(text.find("\n" + header), std::string::npos) << "the header line " << header;
  for (const tasks::TelemetryColumn& c : tasks::telemetryTable()) {
    const std::string name = c.column.name;
    // A row names it alone (`| `spin` |`) or among its fellows (`| `x, y, z` |`).
    const bool alone = text.find("| `" + name + "` |") != std::string::npos;
    const bool among = text.find("| `" + name + ", ") != std::string::npos ||
                       text.find(", " + name + "` |") != std::string::npos ||
                       text.find(", " + name + ", ") != std::string::npos;
    EXPECT_TRUE(alone || among) << name << " has no row in docs/commands.md \"The telemetry CSV\"";
  }
  // Each row's unit is spelled as the files spell it (— for none): a reader holding the page
  // beside an .h5's attributes had found ° and kg m²/s where the files say deg and kg m^2/s.
  const std::size_t table = text.find("| column | unit | meaning |");
  ASSERT_NE(table, std::string::npos);
  std::istringstream lines(text.substr(table));
  int rows = 0;
  for (std::string line; std::getline(lines, line) && line.rfind("|", 0) == 0;) {
    if (line.rfind("| `", 0) != 0) continue;
    const std::size_t end = line.find("` |");
    if (end == std::string::npos) continue;
    const std::string names = line.substr(3, end - 3);
    const std::size_t unit_end = line.find(" |", end + 3);
    if (unit_end == std::string::npos) continue;
    const std::string unit = line.substr(end + 4, unit_end - end - 4);
    for (const tasks::TelemetryColumn& c : tasks::telemetryTable()) {
      const std::string name = c.column.name;
      if (names != name && names.find(name + ", ") != 0 &&
          names.find(", " + name) == std::string::npos)
        continue;
      const std::string expected = *c.column.unit == 0 ? "—" : std::string(c.column.unit);
      EXPECT_EQ(unit, expected) << name;
      ++rows;
    }
  }
  EXPECT_EQ(rows, static_cast<int>(tasks::telemetryTable().size()));
}

// Snapshot suite files (scene/snapshot.cpp) read against the table of their keys, and a still's
// named times (tasks/still_time.cpp) against the run's own reversal.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/loader.hpp"
#include "scene/snapshot.hpp"
#include "sim/compile.hpp"
#include "tasks/still_time.hpp"

namespace {

constexpr const char* kSuite = R"(goldens: ../golden
size: 320x180
tolerance: 3
cases:
  - {name: rest, scene: ../scenes/rattleback.yaml}
  - name: at-reversal
    scene: /abs/x.yaml
    t: reversal
    view: above
    size: 640x360
    backend: osmesa
    pixels: 0.01
    square: 0
    title: At the reversal
)";

TEST(SnapshotSuite, ReadsCasesWithTheSuitesDefaultsAndPathsRelativeToTheFile) {
  auto suite = scene::parseSnapshotSuite(kSuite, "ci/suite.yaml");
  ASSERT_TRUE(suite) << suite.error().text();
  EXPECT_EQ(suite->goldens, "golden");  // ci/../golden
  ASSERT_EQ(suite->cases.size(), 2u);
  const scene::SnapshotCase& rest = suite->cases[0];
  EXPECT_EQ(rest.scene, "scenes/rattleback.yaml");
  EXPECT_EQ(rest.place, "ci/suite.yaml:5");
  EXPECT_EQ((*rest.size)[0], 320);
  EXPECT_EQ(rest.tolerance.channel, 3);
  EXPECT_EQ(rest.tolerance.pixels, render::Tolerance{}.pixels);
  EXPECT_FALSE(rest.t.named);
  EXPECT_EQ(rest.t.seconds, 0);
  const scene::SnapshotCase& c = suite->cases[1];
  EXPECT_EQ(c.scene, "/abs/x.yaml");
  EXPECT_EQ(c.t.named, sim::NamedTime::Reversal);
  EXPECT_EQ(c.view, render::View::Above);
  EXPECT_EQ((*c.size)[1], 360);
  EXPECT_EQ(c.backend, render::Backend::OsMesa);
  EXPECT_FALSE(rest.backend);
  EXPECT_EQ(c.tolerance.pixels, 0.01);
  EXPECT_EQ(c.tolerance.square, 0);
  EXPECT_EQ(c.title, "At the reversal");
}

// Each bad file: the one line names the file, the line and the key.
TEST(SnapshotSuite, ABadFileIsOneLineNamingFileLineAndKey) {
  const std::pair<const char*, const char*> bad[] = {
      {"cases: [{name: a, scene: s.yaml, colour: red}]", "s.yaml:1: cases[0].colour is not a key"},
      {"cases:\n  - {name: a, scene: s.yaml}\n  - {name: a, scene: t.yaml}",
       "s.yaml:3: cases[1].name 'a' names the case at line 2 too: each case needs its own golden"},
      {"cases:\n  - {name: a}", "s.yaml:2: cases[0].scene is required"},
      {"cases:\n  - {name: a, scene: s.yaml, t: soon}", "s.yaml:2: cases[0].t must be a time"},
      {"cases:\n  - {name: a, scene: s.yaml, t: -1}", "s.yaml:2: cases[0].t must be a time"},
      {"size: 640\ncases: [{name: a, scene: s.yaml}]", "s.yaml:1: size must be WIDTHxHEIGHT"},
      {"tolerance: 300\ncases: [{name: a, scene: s.yaml}]", "s.yaml:1: tolerance must be a whole"},
      {"pixels: \"0.1\"\ncases: [{name: a, scene: s.yaml}]", "s.yaml:1: pixels must be a number"},
      {"pixels: 2\ncases: [{name: a, scene: s.yaml}]", "s.yaml:1: pixels must be a fraction"},
      {"cases: [{name: ../up, scene: s.yaml}]", "s.yaml:1: cases[0].name must be a name"},
      {"cases: [{name: a, scene: s.yaml, view: top}]", "s.yaml:1: cases[0].view must be oblique"},
      {"goldens: g\ngoldens: h\ncases: [{name: a, scene: s.yaml}]",
       "s.yaml:2: goldens is given twice"},
      {"name: a\ncases: [{name: a, scene: s.yaml}]", "s.yaml:1: name is not a key of a suite"},
      // A typo is offered the key it is near; names that one file system reads as one collide.
      {"tolerence: 3\ncases: [{name: a, scene: s.yaml}]",
       "s.yaml:1: tolerence is not a key of a suite (goldens, cases, view, size, backend, "
       "tolerance, pixels, square); did you mean tolerance?"},
      {"cases:\n  - {name: Front, scene: s.yaml}\n  - {name: front, scene: t.yaml}",
       "s.yaml:3: cases[1].name 'front' names the case at line 2 too ('Front', as a file system "
       "that ignores case reads it)"},
      {"goldens: g", "s.yaml:1: cases must be a list"},
      {"cases: [{name: a, scene: s.yaml}", "s.yaml:1: malformed YAML"},
  };
  for (const auto& [text, said] : bad) {
    auto suite = scene::parseSnapshotSuite(text, "s.yaml");
    ASSERT_FALSE(suite) << text;
    EXPECT_TRUE(suite.error().text().starts_with(said)) << suite.error().text();
    EXPECT_EQ(suite.error().text().find('\n'), std::string::npos);
  }
}

// The reader takes its keys from the table: an unknown key's message lists exactly the keys the
// table allows there, so a row added to the table is read (and said) without another edit.
// The keys an unknown key's message lists: the words in its last parentheses.
std::set<std::string> listed(const std::string& message) {
  const auto open = message.rfind('('), close = message.rfind(')');
  std::set<std::string> words;
  std::string list = message.substr(open + 1, close - open - 1) + ", ";
  for (std::size_t at = 0, comma; (comma = list.find(", ", at)) != std::string::npos;
       at = comma + 2)
    words.insert(list.substr(at, comma - at));
  return words;
}

TEST(SnapshotSuite, AnUnknownKeyNamesTheTablesKeysForItsPlace) {
  auto top = scene::parseSnapshotSuite("colour: red\ncases: [{name: a, scene: s}]", "s.yaml");
  auto inCase = scene::parseSnapshotSuite("cases: [{name: a, scene: s, colour: red}]", "s.yaml");
  ASSERT_FALSE(top);
  ASSERT_FALSE(inCase);
  std::set<std::string> at_top, in_case;
  for (const scene::SnapshotKey& k : scene::snapshotKeys()) {
    if (k.where != scene::SnapshotWhere::Case) at_top.insert(std::string(k.name));
    if (k.where != scene::SnapshotWhere::Top) in_case.insert(std::string(k.name));
  }
  EXPECT_EQ(listed(top.error().text()), at_top) << top.error().text();
  EXPECT_EQ(listed(inCase.error().text()), in_case) << inCase.error().text();
  EXPECT_EQ(at_top.size() + in_case.size(), 12u + 6u);  // the six of both are listed twice
}

sim::Model defaultScene(const std::string& values = "") {
  auto loaded = scene::loadWithValues(
      scene::readSceneFile(RATTLEBACK_SOURCE_DIR "/scenes/rattleback.yaml").value(),
      "rattleback.yaml",
      values.empty() ? std::vector<scene::KeyValue>{}
                     : std::vector<scene::KeyValue>{{"initial.spin", values}},
      "test");
  EXPECT_TRUE(loaded) << loaded.error().text();
  auto model = scene::loadModel(loaded.value());
  EXPECT_TRUE(model) << model.error().text();
  return model.value();
}

// `still --t reversal` is the reversal `simulate` reports, to the last bit: the run stopped
// soon after it, in slices, steps as the whole run does.
TEST(StillTime, ReversalIsTheRunsOwnFirstReversal) {
  const sim::Model model = defaultScene();
  sim::Rollout whole(model);
  whole.advanceTo(whole.endTime());
  ASSERT_TRUE(whole.summary().first_reversal_s);
  for (const char* name : {"reversal", "first_reversal"}) {
    sim::Rollout run(model);
    auto t = tasks::resolveStillTime(tasks::parseStillTime(name, "--t").value(), run, "--t");
    ASSERT_TRUE(t) << t.error().text();
    EXPECT_EQ(t.value(), *whole.summary().first_reversal_s) << name;
    // Stopped soon after: the rule holds a crossing 0.2 s, and the slices are 50 ms.
    EXPECT_LT(run.current().t, t.value() + 0.3) << name;
  }
  sim::Rollout run(model);
  EXPECT_EQ(
      tasks::resolveStillTime(tasks::parseStillTime("end", "--t").value(), run, "--t").value(),
      model.duration);
  EXPECT_EQ(tasks::parseStillTime("1.25", "--t")->seconds, 1.25);
}

TEST(StillTime, ARunWithoutReversalAndAWrongWordAreRefusedByName) {
  sim::Rollout run(defaultScene("5.0"));  // counter-clockwise: the default body does not reverse
  auto t = tasks::resolveStillTime({0, sim::NamedTime::Reversal}, run, "--t");
  ASSERT_FALSE(t);
  EXPECT_TRUE(t.error().text().starts_with("--t reversal: the run has no reversal within its 8 s"))
      << t.error().text();
  for (const char* wrong : {"soon", "1.5s", "", "Reversal"}) {
    auto parsed = tasks::parseStillTime(wrong, "--time");
    ASSERT_FALSE(parsed) << wrong;
    EXPECT_TRUE(parsed.error().text().starts_with("--time: a time in s")) << wrong;
  }
}

}  // namespace

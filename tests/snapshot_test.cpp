// `rattleback snapshot` and `still --t reversal`, run as a user's CI runs them: suites in a
// scratch folder, goldens written, compared, renamed and changed.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "render_support.hpp"

namespace fs = std::filesystem;
using namespace render_support;

namespace {

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Runs rattleback in `dir` (with `env`, "NAME=value ...", set) with stdout and stderr into
// `said`; the exit status.
int runIn(const fs::path& dir, const std::string& args, std::string* said = nullptr,
          const std::string& env = "") {
  const fs::path out = dir / "said.txt";
  const std::string command = "cd " + dir.string() + " && " + env + (env.empty() ? "" : " ") +
                              RATTLEBACK_BIN + " " + args + " >" + out.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  if (said) *said = slurp(out);
  fs::remove(out);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

// The default scene with its tilt's first angle given (its file says [0.5, 0.5]).
std::string sceneWithTilt(const std::string& first) {
  std::string text = slurp(kSource / "scenes/rattleback.yaml");
  const std::string from = "tilt: [0.5, 0.5]";
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos);
  return text.replace(at, from.size(), "tilt: [" + first + ", 0.5]");
}

// A suite of two cases of one scene, small frames: at rest and at the reversal.
std::string suiteOf(const std::string& scene, const std::string& goldens) {
  return "goldens: " + goldens + "\nsize: 320x180\nbackend: " + backendName() +
         "\ncases:\n  - {name: rest, scene: " + scene +
         ", view: oblique}\n  - {name: turning, scene: " + scene + ", t: reversal, view: above}\n";
}

// A fresh folder in the test's scratch folder (scratch() removes files, not folders).
fs::path folder(const std::string& name) {
  const fs::path dir = scratch("said.txt").parent_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

// `still --t reversal` draws the frame at the time `simulate` reports as the first reversal:
// the same PNG, byte for byte, as `--t` given that time.
TEST(StillAt, ReversalIsTheFrameAtTheReversalSimulateReports) {
  const fs::path dir = folder("reversal");
  ASSERT_EQ(
      runIn(dir, "simulate " + (kSource / "scenes/rattleback.yaml").string() + " -q -o run.csv"),
      0);
  std::smatch m;
  const std::string sidecar = slurp(dir / "run.csv.json");
  ASSERT_TRUE(std::regex_search(sidecar, m, std::regex("\"first_reversal_s\": ([0-9.e+-]+)")));
  const std::string still =
      "still " + (kSource / "scenes/rattleback.yaml").string() + " --size 320x180 --view above -q ";
  std::string said;
  ASSERT_EQ(runIn(dir, still + "--t reversal -o named.png", &said), 0) << said;
  ASSERT_EQ(runIn(dir, still + "--t " + m[1].str() + " -o given.png", &said), 0) << said;
  EXPECT_TRUE(slurp(dir / "named.png") == slurp(dir / "given.png")) << "named.png differs";
  EXPECT_EQ(runIn(dir, still + "--t soon -o x.png", &said), 2);
  EXPECT_EQ(said.rfind("--t: a time in s (e.g. 1.5) or reversal, first_reversal or end", 0), 0u)
      << said;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// From nothing: each golden is missing (exit 1, and the message says --update writes it);
// --update adds them; the suite then passes and its stale report goes; a second --update says
// every golden unchanged and rewrites none of them (their times stay).
TEST(Snapshot, MissingThenUpdatedThenPassingAndAnUnchangedUpdateWritesNothing) {
  const fs::path dir = folder("cycle");
  put(dir / "scenes/mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "suite.yaml", suiteOf("scenes/mine.yaml", "goldens"));
  std::string said;
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml -q", &said), 1) << said;
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml", &said), 1) << said;
  EXPECT_NE(said.find("missing  rest  goldens/rest.png does not exist"), std::string::npos) << said;
  EXPECT_NE(said.find("--update writes it"), std::string::npos) << said;
  EXPECT_TRUE(fs::exists(dir / "snapshot-report/index.html"));
  EXPECT_FALSE(fs::exists(dir / "goldens"));
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update", &said), 0) << said;
  EXPECT_NE(said.find("2 added, 0 changed, 0 unchanged"), std::string::npos) << said;
  const auto when = fs::last_write_time(dir / "goldens/turning.png");
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml", &said), 0) << said;
  EXPECT_FALSE(fs::exists(dir / "snapshot-report"));
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update -j 1", &said), 0) << said;
  EXPECT_NE(said.find("0 added, 0 changed, 2 unchanged"), std::string::npos) << said;
  EXPECT_EQ(fs::last_write_time(dir / "goldens/turning.png"), when);
}

// The picture depends only on what it shows: the scene renamed into another folder, the suite
// in another folder run from elsewhere, and one thread instead of all, draw the same bytes.
TEST(Snapshot, AGoldenSurvivesRenamingTheSceneMovingTheSuiteAndTheThreadCount) {
  const fs::path dir = folder("rename");
  put(dir / "a/mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "a/suite.yaml", suiteOf("mine.yaml", "goldens"));
  std::string said;
  ASSERT_EQ(runIn(dir, "snapshot a/suite.yaml --update -q", &said), 0) << said;
  put(dir / "b/deeper/renamed-body.yaml", slurp(dir / "a/mine.yaml"));
  put(dir / "b/ci.yaml", suiteOf("deeper/renamed-body.yaml", "../a/goldens"));
  EXPECT_EQ(runIn(dir / "b/deeper", "snapshot ../ci.yaml -j 1", &said), 0) << said;
  put(dir / "c/ci.yaml", suiteOf("../b/deeper/renamed-body.yaml", "goldens"));
  ASSERT_EQ(runIn(dir, "snapshot c/ci.yaml --update -q -j 1", &said), 0) << said;
  for (const char* name : {"rest.png", "turning.png"})
    EXPECT_TRUE(slurp(dir / "a/goldens" / name) == slurp(dir / "c/goldens" / name)) << name;
}

// A tilt 0.1° larger at the start is caught 1.5 s on, as the body rocks, and the report shows
// that case; the terminal says how to bless it.
TEST(Snapshot, ATiltChangedByATenthOfADegreeIsCaughtAndReported) {
  const fs::path dir = folder("tilt");
  put(dir / "mine.yaml", sceneWithTilt("0.5"));
  put(dir / "suite.yaml",
      "size: 320x180\ncases:\n  - {name: rocking, scene: mine.yaml, t: 1.5, "
      "view: above}\n");
  std::string said;
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update -q", &said), 0) << said;
  put(dir / "mine.yaml", sceneWithTilt("0.6"));
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml --report out/report", &said), 1) << said;
  EXPECT_NE(said.find("DIFFERS  rocking"), std::string::npos) << said;
  // The way out on the terminal, not only on the report's page.
  EXPECT_NE(said.find("rattleback snapshot suite.yaml --update makes the images drawn now the "
                      "goldens"),
            std::string::npos)
      << said;
  const std::string page = slurp(dir / "out/report/index.html");
  EXPECT_NE(page.find("id=\"rocking\""), std::string::npos);
  for (const char* image : {"rocking-golden.png", "rocking-new.png", "rocking-diff.png"})
    EXPECT_TRUE(fs::exists(dir / "out/report" / image)) << image;
}

// A bad suite: one line naming file, line and key, exit 2, and nothing written; a report folder
// of someone else's files is refused, not replaced.
TEST(Snapshot, ABadSuiteIsOneLineAndWritesNothing) {
  const fs::path dir = folder("bad");
  put(dir / "mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "suite.yaml", suiteOf("mine.yaml", "goldens") +
                              "  - {name: x, scene: mine.yaml, "
                              "view: top}\n");
  std::string said;
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml --update", &said), 2);
  EXPECT_EQ(said,
            "suite.yaml:7: cases[2].view must be oblique, above, front, side or follow, not "
            "'top'\n");
  put(dir / "suite.yaml", suiteOf("mine.yaml", "goldens") + "  - {name: x, scene: none.yaml}\n");
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml", &said), 2);
  EXPECT_EQ(said.rfind("suite.yaml:7: x: ", 0), 0u) << said;
  put(dir / "suite.yaml", suiteOf("mine.yaml", "goldens"));
  put(dir / "mine-notes/notes.txt", "mine");
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml --report mine-notes", &said), 2);
  EXPECT_NE(said.find("not an earlier snapshot report"), std::string::npos) << said;
  EXPECT_EQ(slurp(dir / "mine-notes/notes.txt"), "mine");
  // A report that cannot be made is refused before anything is drawn (it had been tried after,
  // turning a suite's verdict into exit 2, and not tried at all when every case matched).
  for (const char* report : {"mine-notes/notes.txt/report", "/proc/report"}) {
    EXPECT_EQ(runIn(dir, std::string("snapshot suite.yaml --update -q --report ") + report, &said),
              2)
        << report;
    EXPECT_NE(said.find(std::string("--report ") + report + ": cannot make the report's folder: "),
              std::string::npos)
        << said;
  }
  EXPECT_FALSE(fs::exists(dir / "goldens"));
  EXPECT_FALSE(fs::exists(dir / "snapshot-report"));
  // One that can be made is tried, and no folder made for the trial stays.
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml --update -q --report new/deeper/report", &said), 0)
      << said;
  EXPECT_TRUE(fs::exists(dir / "goldens/rest.png"));
  EXPECT_FALSE(fs::exists(dir / "new"));
}

// A size the suite's top gives every case is named at its own line, once (it had been blamed on
// the first case, then "the same for 3 more cases"); a case's own size is named with the case.
TEST(Snapshot, AnOddSizeIsNamedWhereItIsGiven) {
  const fs::path dir = folder("odd-size");
  put(dir / "mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  std::string suite = suiteOf("mine.yaml", "goldens");
  suite.replace(suite.find("size: 320x180"), 13, "size: 321x180");  // line 2
  put(dir / "suite.yaml", suite);
  std::string said;
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml -q", &said), 2);
  EXPECT_EQ(said.rfind("suite.yaml:2: size: video.size sides must be even", 0), 0u) << said;
  EXPECT_NE(said.find("not 321x180: try 322x180"), std::string::npos) << said;
  put(dir / "suite.yaml",
      suiteOf("mine.yaml", "goldens") + "  - {name: odd, scene: mine.yaml, size: 160x91}\n");
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml -q", &said), 2);
  EXPECT_EQ(said.rfind("suite.yaml:7: odd: size: video.size sides must be even", 0), 0u) << said;
  EXPECT_FALSE(fs::exists(dir / "goldens"));
}

// A golden that is not a PNG (what a clone without Git LFS's files holds in its place) is the
// input at fault: exit 2, the reason and the way out on standard error, the case in the report.
// --update replaces it and removes the report that stood for the failure; a golden no case
// names is said, and left where it is.
TEST(Snapshot, AnUnreadableGoldenIsBadInputThatUpdateReplaces) {
  const fs::path dir = folder("unreadable");
  put(dir / "mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "suite.yaml", suiteOf("mine.yaml", "goldens"));
  std::string said;
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update -q", &said), 0) << said;
  put(dir / "goldens/rest.png", "version https://git-lfs.github.com/spec/v1\noid sha256:00\n");
  fs::copy_file(dir / "goldens/turning.png", dir / "goldens/gone.png");
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml", &said), 2) << said;
  EXPECT_NE(said.find("goldens/rest.png: cannot read the PNG: a Git LFS pointer, not the image "
                      "(git lfs pull fetches it); it is case rest's golden: rattleback snapshot "
                      "suite.yaml --update replaces it"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("1 same, 0 differ, 0 missing, 1 unreadable"), std::string::npos) << said;
  EXPECT_NE(said.find("1 golden belongs to no case of this suite (a case removed or renamed?): "
                      "goldens/gone.png"),
            std::string::npos)
      << said;
  EXPECT_NE(slurp(dir / "snapshot-report/index.html").find("the golden cannot be read"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "snapshot-report/rest-new.png"));
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update", &said), 0) << said;
  EXPECT_NE(said.find("replaced   rest"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(dir / "snapshot-report"));
  EXPECT_TRUE(fs::exists(dir / "goldens/gone.png"));
  EXPECT_EQ(runIn(dir, "snapshot suite.yaml -q", &said), 0) << said;
}

// An OpenGL that will not start fails every case for one reason: said once, in the suite's
// words (its key, not an option the snapshot command does not have), the other cases named
// after it; exit 4, a fault of the machine. (glvnd finds no EGL vendor where its list is empty.)
TEST(Snapshot, AnOpenGLThatWillNotStartIsSaidOnce) {
  const fs::path dir = folder("no-egl");
  put(dir / "mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "suite.yaml",
      "size: 320x180\nbackend: egl\ncases:\n  - {name: rest, scene: "
      "mine.yaml}\n  - {name: turning, scene: mine.yaml, t: 2}\n");
  std::string said;
  EXPECT_EQ(
      runIn(dir, "snapshot suite.yaml -q", &said, "__EGL_VENDOR_LIBRARY_FILENAMES=/none.json"), 4)
      << said;
  EXPECT_EQ(said.rfind("suite.yaml:4: rest: backend egl: ", 0), 0u) << said;
  EXPECT_NE(said.find("; backend osmesa draws on the CPU\n"), std::string::npos) << said;
  EXPECT_NE(said.find("rattleback: note: the same for 1 more case: turning\n"), std::string::npos)
      << said;
  EXPECT_EQ(said.find("--backend"), std::string::npos) << said;
  EXPECT_FALSE(fs::exists(dir / "goldens"));
}

// A golden drawn by another rasteriser (Mesa's softpipe against llvmpipe, chosen by
// GALLIUM_DRIVER) differs by a few per cent of the pixels: the verdict names both, the likely
// cause, as compare does, and the report shows them.
TEST(Snapshot, AGoldenOfAnotherRasteriserIsSaidSo) {
  const fs::path dir = folder("rasteriser");
  put(dir / "mine.yaml", slurp(kSource / "scenes/rattleback.yaml"));
  put(dir / "suite.yaml",
      "size: 320x180\nbackend: osmesa\ncases:\n  - {name: rest, scene: "
      "mine.yaml}\n");
  std::string said;
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml --update -q", &said, "GALLIUM_DRIVER=llvmpipe"), 0)
      << said;
  ASSERT_EQ(runIn(dir, "snapshot suite.yaml", &said, "GALLIUM_DRIVER=softpipe"), 1) << said;
  EXPECT_NE(said.find("; the golden was drawn by Mesa/X.org llvmpipe"), std::string::npos) << said;
  EXPECT_NE(said.find(", this by Mesa/X.org softpipe"), std::string::npos) << said;
  EXPECT_NE(slurp(dir / "snapshot-report/index.html").find("<td>the golden by</td>"),
            std::string::npos);
}

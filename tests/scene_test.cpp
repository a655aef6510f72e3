// Scene files: the shipped scenes load, and every kind of bad input gets one line naming the
// file, the line and the key.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "media/video_plan.hpp"
#include "support.hpp"

using namespace testing_support;

namespace {

// Line numbers below refer to this text.
const char* kBase = R"(units: {length: 0.01}
body:
  shape: paraboloid
  paraboloid: {a: 4, p: 3, q: 0, s: 0.15, top: 2}
  dents: {scale: 0.375, at: [1.04, 9.23], inset: 0.1}
  grid: {dx: 0.52, dy: 1.42, dz: 0.2}
  mass: 0.5
contact: {model: points, stiffness: 2.0e4, damping: 20, friction: 0.3, friction_law: coulomb}
initial: {spin: 0.0, tilt: [0.0, 0.0]}
simulation: {integrator: symplectic, dt: 1.0e-5, duration: 1.0}
video: {fps: 25, size: [320, 180], view: oblique}
)";

struct BadCase {
  const char* from;  // text in kBase to replace ("" appends `to`)
  const char* to;
  const char* expected;  // the start of the message after "inline.yaml:"
};

const BadCase kBadCases[] = {
    {"mass: 0.5", "mass: -1", "7: body.mass must be > 0"},
    // What people type, said with the likely slip (a teacher's trial).
    {"model: points,", "model: pionts,",
     "8: contact.model must be points, smooth, rolling or auto, not 'pionts'; did you mean "
     "points?"},
    {"shape: paraboloid", "shape: parabolid",
     "3: body.shape must be paraboloid, ellipsoid or mesh, not 'parabolid'; did you mean "
     "paraboloid?"},
    {"mass: 0.5", "mass: 0,5",
     "7: body.mass must be a number, not '0,5' (a decimal comma: write 0.5)"},
    {"mass: 0.5", "mass: 500 g",
     "7: body.mass must be a number, not '500 g' (write the number alone, in kg)"},
    // With no space too (a teacher's trial: "5rad/s" had no hint).
    {"spin: 0.0", "spin: 5rad/s",
     "9: initial.spin must be a number, not '5rad/s' (write the number alone, in rad/s)"},
    {"top: 2}", "top: 2 cm}",
     "4: body.paraboloid.top must be a number, not '2 cm' (write the number alone, in the "
     "file's length unit, units.length)"},
    {"tilt: [0.0, 0.0]", "tilt: [0.0 0.0]",
     "9: initial.tilt must be a list of two numbers, not a list of 1 ('0.0 0.0': separate the "
     "numbers with commas)"},
    {"dt: 1.0e-5", "dt: 1,0e-5",
     "10: simulation.0e-5 is not a known key: a number where a key stands, as a decimal comma "
     "makes"},
    {"spin: 0.0,", "spin: 0.0,,",
     "9: initial.null is not a known key: an empty entry, as two commas in a row make"},
    {"", "spin: 3\n",
     "12: spin is not a known key; it is initial.spin (under initial:) (known here: units,"},
    {"  mass: 0.5\n", "  mass: 0.5\n  mass_properties: exact\n",
     "8: body.mass_properties must be continuum or grid, not 'exact'"},
    {"shape: paraboloid", "shape: ellipsoid\n  mass_properties: grid",
     "4: body.mass_properties belongs to shape: paraboloid"},
    {"mass: 0.5", "mass: 0", "7: body.mass must be > 0"},
    {"mass: 0.5", "mass: heavy", "7: body.mass must be a number"},
    {"mass: 0.5", "mass: .nan", "7: body.mass must be > 0, not nan"},
    {"mass: 0.5", "mass: [1, 2]", "7: body.mass must be a number"},
    {"  mass: 0.5\n", "", "2: body.mass is required, e.g. mass: 0.059 (kg)"},
    // A missing key the README's first scene may leave out names a line that would do.
    {"  paraboloid: {a: 4, p: 3, q: 0, s: 0.15, top: 2}\n", "",
     "2: body.paraboloid is required, e.g. "
     "paraboloid: {a: 1.0, p: 0.5, q: 0.0, s: 0.03, top: 0.5}"},
    {"  grid: {dx: 0.52, dy: 1.42, dz: 0.2}\n", "",
     "2: body.grid is required, e.g. grid: {dx: 0.05, dy: 0.05, dz: 0.05}"},
    {"stiffness: 2.0e4, ", "",
     "8: contact.stiffness is required, e.g. stiffness: 2.0e4 (N/m), or model: rolling"},
    {" duration: 1.0", "", "10: simulation.duration is required, e.g. duration: 8.0 (s)"},
    {"  mass: 0.5\n", "  mass: 0.5\n  mass: 0.6\n", "8: body.mass is given twice"},
    {"  mass: 0.5\n", "  mass: 0.5\n  colour: red\n", "8: body.colour is not a known key"},
    {"", "extra: 1\n", "12: extra is not a known key (known here:"},  // near no key: no guess
    // A key one or two edits from a known one is named as the likely typo.
    {"  mass: 0.5\n", "  mass: 0.5\n  mas: 0.6\n",
     "8: body.mas is not a known key; did you mean mass? (known here:"},
    {"body:\n", "body: [\n", ""},  // malformed: checked separately for its line
    {"dt: 1.0e-5", "dt: 0", "10: simulation.dt must be > 0"},
    {"dt: 1.0e-5", "dt: -1e-5", "10: simulation.dt must be > 0"},
    {"dt: 1.0e-5", "dt: 0.01", "10: simulation.dt 0.01 s is too large for contact.stiffness"},
    {"duration: 1.0", "duration: 1e9",
     "10: simulation.dt 1e-05 s over simulation.duration 1e+09 s makes more than 1e11 steps"},
    {"duration: 1.0", "duration: .inf", "10: simulation.duration must be > 0, not inf"},
    {"integrator: symplectic", "integrator: leapfrog", "10: simulation.integrator must be"},
    {"stiffness: 2.0e4", "stiffness: -5", "8: contact.stiffness must be > 0"},
    {"stiffness: 2.0e4", "stiffness: 0", "8: contact.stiffness must be > 0"},
    {"friction: 0.3", "friction: -1", "8: contact.friction must be ≥ 0"},
    {"damping: 20", "damping: -.inf", "8: contact.damping must be ≥ 0"},
    {"friction_law: coulomb", "friction_law: sticky", "8: contact.friction_law must be"},
    {"model: points", "model: magic", "8: contact.model must be points, smooth, rolling or auto"},
    // A misspelt model without a stiffness: the model is what is wrong, not a missing stiffness.
    {"model: points, stiffness: 2.0e4,", "model: rollin,",
     "8: contact.model must be points, smooth, rolling or auto, not 'rollin'"},
    {"shape: paraboloid", "shape: cube", "3: body.shape must be paraboloid, ellipsoid or mesh"},
    {"a: 4,", "a: 0,", "4: body.paraboloid.a must be > 0"},
    {"top: 2}", "top: -5}", "4: body.paraboloid.top must be above the apex"},
    {"dz: 0.2}", "dz: -0.2}", "6: body.grid.dz must be > 0"},
    {"dx: 0.52,", "dx: 1e-6,", "6: body.grid makes about"},
    // Spacings so small that the counts pass any integer (1e-9 aborted the program
    // with std::length_error; the int column count overflowed past the check).
    {"dx: 0.52,", "dx: 1e-9,", "6: body.grid makes about"},
    {"dz: 0.2}", "dz: 1e-12}", "6: body.grid makes about"},
    // Too coarse says the body's height, and the unit: a body given in metres in a file of
    // centimetres showed only as a grid to make finer (a new user's trial).
    {"dz: 0.2}", "dz: 50}",
     "6: body.grid is too coarse: the body has fewer than two levels of points (it is 6 high "
     "against dz 50, both in units.length, 0.01 m:"},
    {"dx: 0.52, dy: 1.42, dz: 0.2", "dx: 1e-300, dy: 1e-300, dz: 1e-300", "6: body.grid makes"},
    {"{scale: 0.375, ", "{", "5: body.dents.scale is required"},
    // Dents that cut the body away are named as such, not as a grid to make finer (a teacher's
    // trial: scale 100).
    {"{scale: 0.375, ", "{scale: 100, ",
     "5: body.dents.scale cuts the body away: with the dents the grid finds fewer than two "
     "levels of points, without them the body is there"},
    {"length: 0.01", "length: 0", "1: units.length must be > 0"},
    {"tilt: [0.0, 0.0]", "tilt: 5", "9: initial.tilt must be a list of two numbers"},
    {"tilt: [0.0, 0.0]", "tilt: [181, 0]", "9: initial.tilt must lie within ±180 degrees, not 181"},
    {"tilt: [0.0, 0.0]", "tilt: [1, 2, 3]",
     "9: initial.tilt must be a list of two numbers, not a list of 3"},
    // A key with no value was called 'a list or map' (a new user's trial).
    {"  mass: 0.5\n", "  mass: ~\n",
     "7: body.mass must be a number, not empty (the key has no value)"},
    {"  mass: 0.5\n", "  mass:\n",
     "7: body.mass must be a number, not empty (the key has no value)"},
    {"  mass: 0.5\n", "  mass: [0.5]\n", "7: body.mass must be a number, not a list"},
    {"  mass: 0.5\n", "  mass: {kg: 0.5}\n", "7: body.mass must be a number, not a map"},
    {"spin: 0.0", "spin: .inf", "9: initial.spin must be a finite number"},
    {"fps: 25", "fps: 0", "11: video.fps must be within"},
    {"size: [320, 180]", "size: [100000, 100000]", "11: video.size sides must be within"},
    {"fps: 25", "fps: 29.97", "11: video.fps must be a whole number, not '29.97': use 30"},
    {"fps: 25", "fps: 241", "11: video.fps must be within 1 … 240"},
    {"size: [320, 180]", "size: [321, 180]", "11: video.size sides must be even"},
    {"view: oblique", "view: sideways", "11: video.view must be"},
    {"", "video: {fps: 25}\n", "12: video is given twice"},
    // More of the same families: types, ranges, shapes and absurd sizes.
    {"mass: 0.5", "mass: 1e400", "7: body.mass must be"},
    {"mass: 0.5", "mass: \"0.5\"", "7: body.mass must be a number"},
    {"mass: 0.5", "mass: {kg: 1}", "7: body.mass must be a number"},
    {"mass: 0.5", "mass: ", "7: body.mass must be a number"},
    {"dx: 0.52, dy: 1.42, dz: 0.2", "dx: 1e-4, dy: 1e-4, dz: 1e-4", "6: body.grid makes about"},
    {"dz: 0.2}", "dz: .nan}", "6: body.grid.dz must be > 0"},
    {"p: 3,", "p: -3,", "4: body.paraboloid.p must be > 0"},
    {"q: 0,", "q: 40,", "4: body.paraboloid.q too large"},
    {"s: 0.15,", "s: .inf,", "4: body.paraboloid.s must be"},
    {"at: [1.04, 9.23]", "at: [1.04]", "5: body.dents.at must be a list of two numbers"},
    {"paraboloid: {a: 4,", "paraboloid: {b: 1, a: 4,", "4: body.paraboloid.b is not a known key"},
    {"shape: paraboloid", "shape: [paraboloid]", "3: body.shape must be a word"},
    {"initial: {spin: 0.0, tilt: [0.0, 0.0]}", "initial: 5", "9: initial"},
    {"friction: 0.3", "friction: 0.3, slip_velocity: 0", "8: contact.slip_velocity must be > 0"},
    {"friction: 0.3", "friction: 0.3, air_drag: -1", "8: contact.air_drag must be ≥ 0"},
    {"friction: 0.3", "friction: .nan", "8: contact.friction must be ≥ 0"},
    {"", "gravity: -9.81\n", "12: gravity must be ≥ 0"},
    {"", "gravity: [0, 0, -9.81]\n", "12: gravity must be a number"},
    {"spin: 0.0", "spin: 0.0, height: -1", "9: initial.height must be ≥ 0"},
    {"spin: 0.0", "spin: 0.0, height: .nan", "9: initial.height must be ≥ 0"},
    {"tilt: [0.0, 0.0]", "tilt: [.nan, 0]", "9: initial.tilt must be a finite number"},
    {"integrator: symplectic", "integrator: 4", "10: simulation.integrator must be"},
    {"duration: 1.0", "duration: -1", "10: simulation.duration must be > 0"},
    {"dt: 1.0e-5", "dt: 1.0e-5, tolerance: 1.0e-8",
     "10: simulation.dt and simulation.tolerance are both given"},
    {"dt: 1.0e-5, ", "", "10: simulation.dt or simulation.tolerance is required"},
    {"dt: 1.0e-5", "tolerance: 0", "10: simulation.tolerance must be > 0"},
    {"dt: 1.0e-5", "tolerance: 1.0e-8", "10: simulation.integrator symplectic takes a fixed step"},
    {"integrator: symplectic, dt: 1.0e-5", "integrator: dopri5, dt: 1.0e-5",
     "10: simulation.integrator dopri5 chooses its own steps"},
    {"size: [320, 180]", "size: [320]", "11: video.size must be a list of two"},
    {"size: [320, 180]", "size: [-320, 180]", "11: video.size sides must be within"},
    {"fps: 25", "fps: 1e9", "11: video.fps must be"},
    {"fps: 25", "fps: 25, playback: 0", "11: video.playback must be a speed > 0"},
    {"units: {length: 0.01}", "units: {length: 0.01, mass: 1}", "1: units.mass is not a known key"},
    {"units: {length: 0.01}", "units: {length: .inf}", "1: units.length must be"},
};

std::string mutate(const BadCase& c) {
  std::string text = kBase;
  if (*c.from == 0) return text + c.to;
  const auto at = text.find(c.from);
  EXPECT_NE(at, std::string::npos) << c.from;
  return text.replace(at, std::strlen(c.from), c.to);
}

// The one line `simulate` prints for a scene (load and compile), or "" when it runs.
std::string simulationErrorFor(const std::string& yaml) {
  auto loaded = scene::loadString(yaml, "inline.yaml");
  if (!loaded) return loaded.error().text();
  auto model = scene::loadModel(loaded.value());
  if (!model) return model.error().text();
  return "";
}

// A case whose error is in the video section's values: only the drawing commands see it.
bool videoValueCase(const BadCase& c) {
  return std::string(c.expected).find(": video.") != std::string::npos &&
         std::string(c.expected).find("whole number") == std::string::npos &&
         std::string(c.expected).find("list of") == std::string::npos &&
         std::string(c.expected).find("given twice") == std::string::npos;
}

}  // namespace

TEST(Scenes, TheBaseSceneCompiles) {
  EXPECT_EQ(errorFor(kBase), "");
}

TEST(Scenes, ShippedScenesLoadAndCompile) {
  for (const char* name : {"rattleback", "seed-flip-cw", "seed-flip-ccw", "kane-levinson",
                           "kane-levinson-long", "tap-end", "tap-side", "both-ways"}) {
    const std::string path = std::string(RATTLEBACK_SOURCE_DIR) + "/scenes/" + name + ".yaml";
    auto loaded = scene::loadFile(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().text();
    auto model = scene::loadModel(loaded.value());
    EXPECT_TRUE(model.ok()) << model.error().text();
  }
}

// body.mass_properties: named, it is used; left out, the points model keeps the seed's grid
// sums (its scenes reproduce the report: 4256 points) and the others take the continuum.
TEST(Scenes, MassPropertiesComeFromTheNamedSourceOrTheContactModel) {
  auto sourceOf = [](const std::string& yaml) {
    auto loaded = scene::loadString(yaml, "inline.yaml");
    EXPECT_TRUE(loaded.ok());
    auto model = scene::loadModel(loaded.value());
    EXPECT_TRUE(model.ok()) << model.error().text();
    return model.ok() ? model->body->mass_source : sim::MassSource::Grid;
  };
  std::string text = kBase;
  EXPECT_EQ(sourceOf(text), sim::MassSource::Grid);
  text.replace(text.find("model: points"), 13, "model: smooth");
  EXPECT_EQ(sourceOf(text), sim::MassSource::Continuum);
  text.replace(text.find("  mass: 0.5\n"), 12, "  mass: 0.5\n  mass_properties: grid\n");
  EXPECT_EQ(sourceOf(text), sim::MassSource::Grid);
  text.replace(text.find("mass_properties: grid"), 21, "mass_properties: continuum");
  text.replace(text.find("model: smooth"), 13, "model: points");
  EXPECT_EQ(sourceOf(text), sim::MassSource::Continuum);
}

TEST(BadScenes, EachGetsOneLineNamingFileLineAndKey) {
  for (const BadCase& c : kBadCases) {
    const std::string message = errorFor(mutate(c));
    EXPECT_FALSE(message.empty()) << "accepted: " << c.to;
    if (message.empty()) continue;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    if (*c.expected) {
      EXPECT_EQ(message.rfind(std::string("inline.yaml:") + c.expected, 0), 0u)
          << "got: " << message;
    }
  }
}

TEST(BadScenes, MalformedYamlNamesTheLine) {
  const std::string message = errorFor("units: {length: 0.01}\nbody: [\n  shape: x\n");
  EXPECT_NE(message.find("inline.yaml:"), std::string::npos) << message;
  EXPECT_NE(message.find("malformed YAML"), std::string::npos) << message;
  // The line is the one at fault: a key indented deeper than its neighbours on line 4.
  const std::string indented =
      errorFor("units: {length: 0.01}\nbody:\n  shape: paraboloid\n   mass: 1\n");
  EXPECT_EQ(indented.rfind("inline.yaml:4: malformed YAML", 0), 0u) << indented;
  // yaml-cpp's words ("end of map not found", "illegal map value") get the usual causes (a
  // teacher's trial): a key indented unlike its neighbours, or one without its colon.
  for (const std::string& text :
       {std::string("units: {length: 0.01}\nbody:\n  shape: paraboloid\n mass: 1\n"),
        std::string("units: {length: 0.01}\nbody:\n  shape paraboloid\n  mass: 1\n")}) {
    const std::string said = errorFor(text);
    EXPECT_NE(said.find("(at or just above this line: a key indented unlike its neighbours, or a "
                        "key without its colon, key: value)"),
              std::string::npos)
        << said;
  }
  // A tab in the indentation is named as such (yaml-cpp says "illegal map value" there).
  const std::string tabbed = errorFor("units: {length: 0.01}\nbody:\n\tshape: paraboloid\n");
  EXPECT_EQ(tabbed.rfind("inline.yaml:3: malformed YAML: a tab in this line's indentation", 0), 0u)
      << tabbed;
  EXPECT_EQ(errorFor("").rfind("inline.yaml:1: the scene is empty", 0), 0u);
  EXPECT_EQ(errorFor("- 1\n- 2\n").rfind("inline.yaml:1: scene must be a map", 0), 0u);
}

// yaml-cpp reports an unclosed { or [ at the end of the file; the error names the line that
// opened it (a new user's file of 10 lines was told "line 11: end of map flow not found").
TEST(BadScenes, AnUnclosedBracketIsNamedWhereItOpens) {
  const std::string message = errorFor(
      "units: {length: 0.01}\nbody:\n  paraboloid: {a: 1, p: 0.5, s: 0.03, top: 0.5\n"
      "  mass: 0.05\ngravity: 9.81\n");
  EXPECT_EQ(
      message.rfind("inline.yaml:3: malformed YAML: a { or [ on this line is never closed", 0), 0u)
      << message;
  // A ] left out inside a { … }: its } closes the [, which yaml-cpp calls an "illegal flow end".
  const std::string crossed =
      errorFor("units: {length: 0.01}\ninitial: {spin: -5, tilt: [0.5, 0.5}\n");
  EXPECT_EQ(crossed.rfind("inline.yaml:2: malformed YAML: a ] or } on this line does not close the "
                          "bracket open before it",
                          0),
            0u)
      << crossed;
  // Brackets in quotes and comments are not counted; the last one left open is named.
  EXPECT_EQ(scene::unclosedFlowLine("a: \"{\"  # {\nb: [1, 2]\nc: {d: [1\ne: 2\n"), 3);
  EXPECT_EQ(scene::unclosedFlowLine("a: {b: '['}\nc: [1, {d: 2}]\n"), 0);
}

TEST(BadScenes, AMissingFileIsNamedWithTheSystemsReason) {
  auto loaded = scene::loadFile("/nonexistent/scene.yaml");
  ASSERT_FALSE(loaded.ok());
  EXPECT_EQ(loaded.error().text(),
            "/nonexistent/scene.yaml: cannot open the scene file: No such file or directory");
  // A file of a near name beside it is offered (a teacher typed base.yml for base.yaml); none
  // where nothing is near.
  const std::string scenes = RATTLEBACK_SOURCE_DIR "/scenes/";
  EXPECT_EQ(scene::loadFile(scenes + "rattleback.yml").error().text(),
            scenes + "rattleback.yml: cannot open the scene file: No such file or directory; did " +
                "you mean " + scenes + "rattleback.yaml?");
  EXPECT_EQ(scene::loadFile(scenes + "spinning-top.yaml").error().text(),
            scenes + "spinning-top.yaml: cannot open the scene file: No such file or directory");
}

// A shipped scene's name mistyped from a folder of one's own (scenes/ is not here): the near
// names are the shipped ones, which are found by name from any folder (RATTLEBACK_ASSETS stands
// for the installed share/rattleback, here the source tree with its scenes/).
TEST(BadScenes, AMistypedShippedNameOffersTheShippedOne) {
  const std::filesystem::path here = std::filesystem::current_path();
  const std::filesystem::path empty = std::filesystem::temp_directory_path() / "rb-no-scenes-here";
  std::filesystem::create_directories(empty);
  std::filesystem::current_path(empty);
  ::setenv("RATTLEBACK_ASSETS", RATTLEBACK_SOURCE_DIR, 1);
  const std::string said = scene::loadFile("scenes/ratleback.yaml").error().text();
  // Its name alone, without the folder: the shipped one, with its folder.
  const std::string bare = scene::loadFile("rattleback.yaml").error().text();
  const std::string bare_typo = scene::loadFile("both_ways.yaml").error().text();
  // Names near none: nothing offered (nope.yaml had been offered tap-end.yaml,
  // and mine.yaml printed.yaml).
  const std::string far = scene::loadFile("nope.yaml").error().text();
  const std::string mine = scene::loadFile("mine.yaml").error().text();
  ::unsetenv("RATTLEBACK_ASSETS");
  std::filesystem::current_path(here);
  EXPECT_EQ(said,
            "scenes/ratleback.yaml: cannot open the scene file: No such file or directory; did "
            "you mean scenes/rattleback.yaml (a shipped scene, found by name from any folder)?");
  EXPECT_EQ(bare,
            "rattleback.yaml: cannot open the scene file: No such file or directory; did you "
            "mean scenes/rattleback.yaml (a shipped scene, found by name from any folder)?");
  EXPECT_NE(bare_typo.find("did you mean scenes/both-ways.yaml"), std::string::npos) << bare_typo;
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_EQ(mine.find("did you mean"), std::string::npos) << mine;
}

TEST(BadScenes, AFolderIsNamedAsAFolder) {
  auto loaded = scene::loadFile(RATTLEBACK_SOURCE_DIR "/scenes");
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error().text().find("is a folder, not a scene file"), std::string::npos)
      << loaded.error().text();
}

// The simulation never reads the video section's values (docs/scenes.md "Scene files"): a scene
// whose only fault is there simulates, and the drawing commands refuse it.
TEST(BadScenes, VideoValuesStopOnlyTheDrawingCommands) {
  int seen = 0;
  for (const BadCase& c : kBadCases) {
    if (!videoValueCase(c)) continue;
    ++seen;
    EXPECT_EQ(simulationErrorFor(mutate(c)), "") << c.to;
    EXPECT_NE(errorFor(mutate(c)), "") << c.to;
  }
  EXPECT_GE(seen, 6);
}

TEST(BadScenes, EachExitsTwoFromTheCommandLineWithOneLineAndNoOutput) {
  // The same battery through the program: exit status 2, one line on stderr starting with the
  // file's path and line, nothing on stdout, and no telemetry file left behind.
  const std::filesystem::path dir =
      std::filesystem::path(testing::TempDir()) / "rattleback_battery";
  std::filesystem::create_directories(dir);
  int index = 0;
  for (const BadCase& c : kBadCases) {
    const std::filesystem::path yaml = dir / ("case" + std::to_string(index++) + ".yaml");
    std::ofstream(yaml) << mutate(c);
    const std::filesystem::path csv = dir / (videoValueCase(c) ? "out.png" : "out.csv"),
                                err = dir / "stderr", out = dir / "stdout";
    std::filesystem::remove(csv);
    // Faults in the video section's values reach only the drawing commands: those go to still.
    const std::string command = std::string(RATTLEBACK_BIN) +
                                (videoValueCase(c) ? " still " : " simulate ") + yaml.string() +
                                " -o " + csv.string() + " >" + out.string() + " 2>" + err.string();
    const int raw = std::system(command.c_str());
    std::ifstream in(err);
    std::stringstream text;
    text << in.rdbuf();
    const std::string message = text.str();
    EXPECT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 2) << c.to << ": status " << raw;
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    EXPECT_EQ(message.rfind(yaml.string() + ":", 0), 0u) << message;
    EXPECT_EQ(std::filesystem::file_size(out), 0u) << c.to;
    EXPECT_FALSE(std::filesystem::exists(csv)) << c.to;
  }
}

TEST(BadScenes, ControlCharactersInTheFileStayOnOneLine) {
  // Found by the fuzzer: yaml-cpp quotes a bad escape's character back, here a newline; and a
  // quoted key can hold one too. The message escapes them.
  for (const std::string& yaml :
       {std::string("units: {length: \"\\\n\"}\n"), std::string("\"bad\\nkey\": 1\n"),
        std::string("uits:\377\377\377\377~\377 \377\377{\022\000\n", 18)}) {
    const std::string message = errorFor(yaml);
    EXPECT_FALSE(message.empty());
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find('\0'), std::string::npos) << message;
  }
}

// A step set on top of a scene replaces its tolerance and the other way round, as --dt and
// --tolerance do (the default scene has a tolerance; Python's with_values and a
// sweep of simulation.dt over it must still work). Both at once stay refused.
TEST(SceneValues, AStepReplacesTheScenesToleranceAndTheOtherWayRound) {
  const std::string adaptive = std::string(testing_support::kStableScene);
  const std::string with_tolerance =
      adaptive.substr(0, adaptive.find("simulation:")) +
      "simulation: {tolerance: 1.0e-8, duration: 1.0}\nvideo: {fps: 25}\n";
  auto stepped =
      scene::loadWithValues(with_tolerance, "t.yaml", {{"simulation.dt", "2.0e-5"}}, "with_values");
  ASSERT_TRUE(stepped) << stepped.error().text();
  EXPECT_EQ(stepped->spec.simulation.dt, 2e-5);
  EXPECT_TRUE(std::isnan(stepped->spec.simulation.tolerance));
  auto tolerant = scene::loadWithValues(adaptive, "s.yaml", {{"simulation.tolerance", "1.0e-7"}},
                                        "with_values");
  ASSERT_TRUE(tolerant) << tolerant.error().text();
  EXPECT_EQ(tolerant->spec.simulation.tolerance, 1e-7);
  EXPECT_TRUE(std::isnan(tolerant->spec.simulation.dt));
  // The scene's integrator goes with the setting it took (a new user's rk4 scene given a
  // tolerance was refused: "rk4 takes a fixed step"), unless the values name one.
  const std::string rk4 =
      adaptive.substr(0, adaptive.find("simulation:")) +
      "simulation: {integrator: rk4, dt: 1.0e-4, duration: 1.0}\nvideo: {fps: 25}\n";
  auto to_tolerance =
      scene::loadWithValues(rk4, "r.yaml", {{"simulation.tolerance", "1.0e-7"}}, "with_values");
  ASSERT_TRUE(to_tolerance) << to_tolerance.error().text();
  auto compiled = scene::loadModel(to_tolerance.value());
  ASSERT_TRUE(compiled) << compiled.error().text();
  EXPECT_EQ(compiled->integrator, sim::Integrator::Dopri5);
  auto kept = scene::loadWithValues(rk4, "r.yaml", {{"simulation.dt", "5.0e-5"}}, "with_values");
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->spec.simulation.integrator, "rk4");  // nothing replaced: the integrator stays
  auto both = scene::loadWithValues(
      with_tolerance, "t.yaml", {{"simulation.dt", "2.0e-5"}, {"simulation.tolerance", "1.0e-7"}},
      "with_values");
  ASSERT_TRUE(both) << both.error().text();
  const auto refused = scene::loadModel(both.value());
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().text().find("both given"), std::string::npos) << refused.error().text();
}

// So with the start's motion: initial.angular_velocity set on top of a scene's initial.spin
// replaces it, and the other way round (the default scene's spin had left with_values
// {initial.angular_velocity: …} refused, with no key to take the spin out). Both set at once, or
// both in one file, stay refused.
TEST(SceneValues, AnAngularVelocityReplacesTheScenesSpinAndTheOtherWayRound) {
  const std::string spun = std::string(testing_support::kStableScene);  // initial: {spin: -5, …}
  auto tapped = scene::loadWithValues(
      spun, "s.yaml", {{"initial.angular_velocity", "[0.1, 0, -5]"}}, "with_values");
  ASSERT_TRUE(tapped) << tapped.error().text();
  auto model = scene::loadModel(tapped.value());
  ASSERT_TRUE(model) << model.error().text();
  EXPECT_EQ(model->initial.angularVelocityBody(), Eigen::Vector3d(0.1, 0, -5));
  std::string with_w = spun;
  const std::string spin_line = "initial: {spin: -5.0,";
  ASSERT_NE(with_w.find(spin_line), std::string::npos);
  with_w.replace(with_w.find(spin_line), spin_line.size(),
                 "initial: {angular_velocity: [0.1, 0, -5],");
  auto back = scene::loadWithValues(with_w, "t.yaml", {{"initial.spin", "3"}}, "with_values");
  ASSERT_TRUE(back) << back.error().text();
  auto spun_again = scene::loadModel(back.value());
  ASSERT_TRUE(spun_again) << spun_again.error().text();
  EXPECT_EQ(spun_again->initial.angularVelocityBody(), Eigen::Vector3d(0, 0, 3));
  auto both = scene::loadWithValues(
      spun, "s.yaml", {{"initial.angular_velocity", "[0.1, 0, 0]"}, {"initial.spin", "2"}},
      "with_values");
  ASSERT_TRUE(both) << both.error().text();
  const auto refused = scene::loadModel(both.value());
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().text().find("is given with initial.angular_velocity"),
            std::string::npos)
      << refused.error().text();
}

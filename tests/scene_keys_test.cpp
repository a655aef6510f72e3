// The table of scene keys (scene/keys.cpp) is what the loader accepts, no more and no less:
// every key in it loads into its own member, takes the default the reference page shows when
// left out, is required exactly when the table says (with the table's example in the message),
// belongs to the shape it says, and takes exactly its choices; every map refuses any other key,
// naming the table's keys. docs/scene-reference.md is generated from the same table
// (Docs.SceneReferenceIsTheLoadersTable checks that the committed page is current).
#include <gtest/gtest.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "media/video_plan.hpp"
#include "scene/keys.hpp"
#include "support.hpp"
#include "tasks/scene_options.hpp"

namespace {

// Whether `path` or a map it sits in is left out, or belongs to the other shape than `shape`
// (unless it is under `also`, which is written whatever the shape).
bool excluded(const std::string& path, const std::string& shape,
              const std::set<std::string>& leave_out, const std::string& also) {
  for (std::size_t end = path.find('.');; end = path.find('.', end + 1)) {
    const std::string prefix = path.substr(0, end);
    if (leave_out.count(prefix)) return true;
    const scene::Key* key = scene::findKey(prefix);
    sim::BodySpec body;
    body.shape = shape;
    const bool other = !scene::belongsTo(*key, body);
    if (other && prefix != also) return true;
    if (end == std::string::npos) return false;
  }
}

// A complete scene written from the table's samples (block YAML, one key a line): every key
// of a `shape` body but those left out (and what they hold), with `values` in place of the
// samples. The samples give simulation.dt; simulation.tolerance is written when dt is left out,
// and initial.angular_velocity when initial.spin is (each pair is refused given together).
std::string sampleScene(const std::string& shape, const std::set<std::string>& leave_out = {},
                        const std::map<std::string, std::string>& values = {},
                        const std::string& also = "") {
  std::string yaml;
  std::vector<std::string> open;  // the maps written along the current key's path
  for (const scene::Key& key : scene::keys()) {
    const std::string path(key.path);
    if (scene::isMap(key) || excluded(path, shape, leave_out, also)) continue;
    if (path == "simulation.tolerance" && !leave_out.count("simulation.dt")) continue;
    if (path == "initial.angular_velocity" && !leave_out.count("initial.spin")) continue;
    std::vector<std::string> parts;
    for (std::size_t start = 0, dot = 0; dot != std::string::npos; start = dot + 1) {
      dot = path.find('.', start);
      parts.push_back(path.substr(start, dot == std::string::npos ? dot : dot - start));
    }
    std::string prefix;
    for (std::size_t depth = 0; depth + 1 < parts.size(); ++depth) {
      prefix += (depth ? "." : "") + parts[depth];
      if (open.size() > depth && open[depth] == prefix) continue;
      open.resize(depth);
      open.push_back(prefix);
      yaml += std::string(2 * depth, ' ') + parts[depth] + ":\n";
    }
    open.resize(parts.size() - 1);
    const std::string value = values.count(path)     ? values.at(path)
                              : path == "body.shape" ? shape
                                                     : std::string(key.sample);
    yaml += std::string(2 * (parts.size() - 1), ' ') + parts.back() + ": " + value + "\n";
  }
  return yaml;
}

// YAML flow text with each number as its shortest round-trip text and no spaces: "[0.73, 4.50]"
// and "[0.73, 4.5]" read the same.
std::string normal(const std::string& yaml) {
  std::string out;
  for (std::size_t i = 0; i < yaml.size();) {
    char* end = nullptr;
    const double v = std::strtod(yaml.c_str() + i, &end);
    // A number where one starts; a '.' or '-' that starts none (a file's ".obj") is a letter:
    // taken as a number that read nothing, it held i in place forever.
    if (std::string("+-.0123456789").find(yaml[i]) != std::string::npos &&
        end != yaml.c_str() + i) {
      char text[32];
      out.append(text, std::to_chars(text, text + sizeof text, v).ptr);
      i = end - yaml.c_str();
    } else {
      if (yaml[i] != ' ') out += yaml[i];
      ++i;
    }
  }
  return out;
}

bool endsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

std::string shapeOf(const scene::Key& key) {
  if (key.shape == scene::Shape::Mesh || key.need == scene::Need::Mesh ||
      key.path.starts_with("body.mesh"))
    return "mesh";
  return key.shape == scene::Shape::Ellipsoid || key.shape == scene::Shape::EllipsoidOrMesh ||
                 key.need == scene::Need::Ellipsoid || key.path.starts_with("body.ellipsoid")
             ? "ellipsoid"
             : "paraboloid";
}

// The values a sample scene of `shape` needs beyond the samples: a mesh body touches only by its
// points (contact.model points), 1440 of them on the sample's flat bottom (tests/meshes/box.obj),
// so a spring of 20 N/m and a damper of 0.005 N s/m each (2.9e4 N/m and 7.2 N s/m in all) where
// one point of the paraboloid's grid has 2e4 and 4: the sample's step stays stable.
std::map<std::string, std::string> valuesFor(const std::string& shape) {
  if (shape != "mesh") return {};
  return {{"contact.model", "points"}, {"contact.stiffness", "20"}, {"contact.damping", "0.005"}};
}

}  // namespace

// Every leaf key set to its sample, in a scene of each shape and with either step setting (and
// with the spin or, adaptive, the angular velocity): the scene loads, compiles and plans its
// video, and each key's member holds its own sample (the samples differ from the defaults and
// from each other where a mix-up could hide).
TEST(SceneKeys, EveryKeyLoadsItsValueIntoItsOwnMember) {
  for (const std::string shape : {"paraboloid", "ellipsoid", "mesh"})
    for (const bool adaptive : {false, true}) {
      const std::set<std::string> leave_out =
          adaptive ? std::set<std::string>{"simulation.dt", "simulation.integrator", "initial.spin"}
                   : std::set<std::string>{};
      const std::string yaml = sampleScene(shape, leave_out, valuesFor(shape));
      ASSERT_EQ(testing_support::errorFor(yaml), "") << yaml;
      auto loaded = scene::loadString(yaml, "inline.yaml");
      int checked = 0;
      for (const scene::Key& key : scene::keys()) {
        const std::string path(key.path);
        if (scene::isMap(key) || excluded(path, shape, leave_out, "") ||
            ((path == "simulation.tolerance" || path == "initial.angular_velocity") && !adaptive))
          continue;
        const std::string sample = path == "body.shape"           ? shape
                                   : valuesFor(shape).count(path) ? valuesFor(shape).at(path)
                                                                  : std::string(key.sample);
        EXPECT_EQ(normal(scene::valueOf(key, loaded.value())), normal(sample)) << path;
        ++checked;
      }
      EXPECT_GE(checked, 20);
    }
}

// A key that is not required, left out of a complete scene: the scene loads, and the member
// holds the default the reference page shows (or the key's note says what is chosen).
TEST(SceneKeys, AnOptionalKeyLeftOutHoldsTheDocumentedDefault) {
  for (const scene::Key& key : scene::keys()) {
    const std::string path(key.path);
    if (key.need != scene::Need::Optional || path == "simulation.dt" ||
        path == "simulation.tolerance")  // exactly one of them: see the next test
      continue;
    auto loaded = scene::loadString(sampleScene(shapeOf(key), {path}), "inline.yaml");
    ASSERT_TRUE(loaded) << path << ": " << loaded.error().text();
    if (scene::isMap(key) || !key.default_note.empty()) continue;
    EXPECT_NE(scene::defaultOf(key), "") << path;
    EXPECT_EQ(scene::valueOf(key, loaded.value()), scene::defaultOf(key)) << path;
  }
  // The step settings: one of the two, and the scene runs with either.
  EXPECT_EQ(testing_support::errorFor(
                sampleScene("paraboloid", {"simulation.dt", "simulation.integrator"})),
            "");
  EXPECT_NE(testing_support::errorFor(
                sampleScene("paraboloid", {"simulation.dt", "simulation.tolerance"})),
            "");
}

// A required key left out: refused with the loader's one line, naming the key and, where the
// table has one, the line that would do. A key required only unless rolling may be left out
// with rolling.
TEST(SceneKeys, ARequiredKeyLeftOutIsNamedWithTheTablesExample) {
  int checked = 0;
  for (const scene::Key& key : scene::keys()) {
    if (key.need == scene::Need::Optional) continue;
    const std::string path(key.path);
    const std::map<std::string, std::string> points{{"contact.model", "points"}};
    auto loaded = scene::loadString(
        sampleScene(
            shapeOf(key), {path},
            key.need == scene::Need::UnlessRolling ? points : std::map<std::string, std::string>{}),
        "inline.yaml");
    ASSERT_FALSE(loaded) << path << " left out loads";
    // The only key of a required map (body.mesh.file) leaves no map behind: the map is named.
    const scene::Key* map = scene::findKey(scene::parentOf(key.path));
    const scene::Key& named =
        map && map->need != scene::Need::Optional && scene::keysIn(map->path).size() == 1 ? *map
                                                                                          : key;
    EXPECT_TRUE(endsWith(loaded.error().text(),
                         ": " + std::string(named.path) + " " + scene::requiredMessage(named)))
        << loaded.error().text();
    if (key.need == scene::Need::UnlessRolling) {
      EXPECT_TRUE(scene::loadString(
          sampleScene("paraboloid", {path}, {{"contact.model", "rolling"}}), "inline.yaml"));
    }
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

// A key of the other shape's body is refused, whole maps and single keys alike.
TEST(SceneKeys, AKeyOfTheOtherShapeIsRefused) {
  int checked = 0;
  for (const scene::Key& key : scene::keys()) {
    const std::string path(key.path);
    if (key.shape == scene::Shape::Any) continue;
    // Every shape the key does not belong to.
    for (const std::string other : {"paraboloid", "ellipsoid", "mesh"}) {
      sim::BodySpec body;
      body.shape = other;
      if (scene::belongsTo(key, body)) continue;
      auto loaded =
          scene::loadString(sampleScene(other, {}, valuesFor(other), path), "inline.yaml");
      ASSERT_FALSE(loaded) << path;
      EXPECT_TRUE(endsWith(loaded.error().text(),
                           ": " + path + " belongs to shape: " + scene::shapeWords(key.shape)))
          << loaded.error().text();
      ++checked;
    }
  }
  // paraboloid, dents, grid, mass_properties (each refused for two shapes); ellipsoid (two);
  // mesh, center_of_mass (two each); inertia (one: the paraboloid)
  EXPECT_EQ(checked, 4 * 2 + 2 + 2 * 2 + 1);
}

// Every map (and the top level) refuses a key the table does not list, and names the ones it
// does, in the table's order.
TEST(SceneKeys, EveryMapRefusesAnUnknownKeyNamingTheTablesKeys) {
  std::vector<std::string> maps{""};
  for (const scene::Key& key : scene::keys())
    if (scene::isMap(key)) maps.emplace_back(key.path);
  for (const std::string& map : maps) {
    std::string known;
    for (const scene::Key* key : scene::keysIn(map))
      known += (known.empty() ? "" : ", ") + std::string(scene::nameIn(key->path));
    const std::string unknown = map.empty() ? "zzz" : map + ".zzz";
    const scene::Key* key = scene::findKey(map);
    auto loaded = scene::loadWithValues(sampleScene(key ? shapeOf(*key) : "paraboloid"),
                                        "inline.yaml", {{unknown, "1"}}, "with_values");
    ASSERT_FALSE(loaded) << unknown;
    EXPECT_EQ(loaded.error().text(),
              "with_values: " + unknown + " is not a known key (known here: " + known + ")");
  }
  EXPECT_EQ(maps.size(), 12u);  // the top level, units, body and its five, contact, … video
}

// A misspelt map above the key set ("intial" of intial.spin) is the setting's mistake, named by
// it: it was blamed on the file's line 1, where nothing is wrong.
TEST(SceneKeys, AnUnknownMapAboveAKeySetIsNamedByTheSetting) {
  for (const char* key : {"intial.spin", "bdy.paraboloid.a"}) {
    auto loaded = scene::loadWithValues(sampleScene("paraboloid"), "inline.yaml", {{key, "1"}},
                                        "with_values");
    ASSERT_FALSE(loaded) << key;
    const std::string word = std::string(key).substr(0, std::string(key).find('.'));
    EXPECT_EQ(loaded.error().text().rfind(
                  "with_values: " + word + " is not a known key; did you mean ", 0),
              0u)
        << loaded.error().text();
    ASSERT_TRUE(loaded.error().where);
    EXPECT_EQ(loaded.error().where->line, 0) << key;
  }
}

// A word takes each of its choices (the name table its checker reads) and nothing else: an
// unknown word is refused with a message that lists every choice.
TEST(SceneKeys, AWordTakesEachOfItsChoicesAndNoOther) {
  for (const scene::Key& key : scene::keys()) {
    if (!key.choices) continue;
    const std::string path(key.path);
    EXPECT_EQ(scene::typeOf(key), "word") << path;
    for (std::string_view name : key.choices()) {
      const std::string word(name);
      // dopri5 takes a tolerance and the others a step; an ellipsoid its own keys.
      const std::set<std::string> leave_out =
          word == "dopri5" ? std::set<std::string>{"simulation.dt"} : std::set<std::string>{};
      const std::string yaml =
          sampleScene(path == "body.shape" ? word : shapeOf(key), leave_out, {{path, word}});
      auto loaded = scene::loadString(yaml, "inline.yaml");
      ASSERT_TRUE(loaded) << path << ": " << word << ": " << loaded.error().text();
      EXPECT_EQ(scene::valueOf(key, loaded.value()), word);
      // Another key may object to the combination (rolling with a height), never this one.
      EXPECT_EQ(testing_support::errorFor(yaml).find(path + " must be"), std::string::npos)
          << testing_support::errorFor(yaml);
    }
    const std::string refused =
        testing_support::errorFor(sampleScene(shapeOf(key), {}, {{path, "zzz"}}));
    EXPECT_NE(refused.find(path + " must be"), std::string::npos) << refused;
    for (std::string_view name : key.choices())
      EXPECT_NE(refused.find(std::string(name)), std::string::npos) << refused;
  }
}

// The complete scene that docs/scenes.md shows loads, and names every key of the table (as a
// key or, for the other shape's and the other step's, in a comment).
TEST(SceneKeys, TheDocsCompleteSceneLoadsAndNamesEveryKey) {
  std::ifstream in(RATTLEBACK_SOURCE_DIR "/docs/scenes.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const auto heading = text.find("## A complete scene");
  ASSERT_NE(heading, std::string::npos);
  const auto start = text.find("```yaml\n", heading) + 8;
  const std::string yaml = text.substr(start, text.find("```", start) - start);
  EXPECT_EQ(testing_support::errorFor(yaml), "") << yaml;
  for (const scene::Key& key : scene::keys())
    EXPECT_NE(yaml.find(std::string(scene::nameIn(key.path)) + ":"), std::string::npos) << key.path;
}

// Every option that sets a scene key (tasks::sceneOptions) puts its value into that key's own
// member, the one the loader fills from a file: a row that wrote another key's member, or a
// key the loader does not know, fails here. Each key's sample differs from the empty scene's
// value, so that the change is seen.
TEST(SceneOptions, EachPutsItsValueIntoItsKeysOwnMember) {
  std::set<std::string> names;
  for (const tasks::SceneOptionRow& row : tasks::sceneOptions()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name << " twice";
    EXPECT_EQ(&tasks::rowOf(row.option), &row) << row.name;
    const scene::Key* key = scene::findKey(row.key);
    ASSERT_NE(key, nullptr) << row.key;
    const std::string sample(key->sample);
    tasks::OptionValue value;
    value.number = std::strtod(sample.c_str(), nullptr);
    value.name = sample;
    if (row.kind == tasks::OptionKind::Size) {
      ASSERT_EQ(std::sscanf(sample.c_str(), "[%d, %d]", &value.size[0], &value.size[1]), 2);
    }
    scene::Loaded loaded;
    ASSERT_NE(normal(scene::valueOf(*key, loaded)), normal(sample)) << row.key;
    row.apply(loaded, value);
    EXPECT_EQ(normal(scene::valueOf(*key, loaded)), normal(sample)) << row.name;
  }
  EXPECT_EQ(names.size(), 11u);
}

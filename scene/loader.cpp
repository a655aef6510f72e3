#include "scene/loader.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "scene/key_path.hpp"
#include "scene/keys.hpp"
#include "scene/mesh_file.hpp"
#include "scene/tree.hpp"
#include "sim/model.hpp"
#include "util/nearest.hpp"

namespace scene {
namespace {

// Thrown inside the loader only; turned into an rb::Error at its edge.
struct Failure {
  int line;
  std::string key;
  std::string message;
  bool unknown_key = false;  ///< `key` is not a scene key (which a key set from elsewhere can make)
};

std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

// Reads one YAML map whose keys must be those scene/keys.cpp lists inside it: an unknown or
// repeated key is rejected before anything else is read. Records the line of every key it sees.
class MapReader {
 public:
  /// `path` is the map's dotted key ("" for the whole file), `line` where it stands (1 for the
  /// whole file).
  MapReader(const YAML::Node& node, std::string path, int line, Loaded& out,
            const std::map<std::string, int>& copied_lines)
      : path_(std::move(path)), line_(line), out_(out), copied_lines_(copied_lines) {
    if (!node.IsMap())
      throw Failure{line_, path_.empty() ? "scene" : path_, "must be a map of keys (key: value)"};
    const std::vector<const Key*> allowed = keysIn(path_);
    std::set<std::string> seen;
    for (const auto& entry : node) {
      const std::string key = entry.first.as<std::string>();
      const int line = lineIn(entry.first, join(path_, key));
      if (!seen.insert(key).second) throw Failure{line, join(path_, key), "is given twice"};
      if (std::none_of(allowed.begin(), allowed.end(),
                       [&](const Key* known) { return nameIn(known->path) == key; })) {
        std::string names;
        std::vector<std::string_view> words;
        for (const Key* known : allowed) {
          names += (names.empty() ? "" : ", ") + std::string(nameIn(known->path));
          words.push_back(nameIn(known->path));
        }
        const std::optional<std::string> nearest = rb::nearestWord(key, words);
        throw Failure{line, join(path_, key),
                      "is not a known key" + (nearest ? "; did you mean " + *nearest + "?" : "") +
                          misplaced(key, entry.first) + " (known here: " + names + ")",
                      true};
      }
      out_.lines[join(path_, key)] = line;
      present_[key] = entry.second;
      key_lines_[key] = line;
    }
  }

  // What an unknown key more likely is: a number or nothing where a key stands is a comma inside a
  // value ({dt: 1,0e-4} is dt: 1 and a key 0e-4; [-5,,] an empty entry), and a key of another map
  // given here is named with its place (spin: at the top level is initial.spin).
  std::string misplaced(const std::string& key, const YAML::Node& key_node) const {
    double number = 0;
    if (key_node.IsNull() || key == "null" || key == "~")
      return ": an empty entry, as two commas in a row make";
    if (YAML::convert<double>::decode(key_node, number))
      return ": a number where a key stands, as a decimal comma makes ({dt: 1,0e-4} is dt: 1 "
             "and a key 0e-4; write 1.0e-4)";
    std::string elsewhere;
    for (const Key& known : keys())
      if (nameIn(known.path) == key && parentOf(known.path) != path_)
        elsewhere += (elsewhere.empty() ? "" : " or ") + std::string(known.path);
    return elsewhere.empty()
               ? ""
               : "; it is " + elsewhere + " (under " +
                     std::string(parentOf(elsewhere.substr(0, elsewhere.find(' ')))) + ":)";
  }

  bool has(const std::string& key) const { return present_.count(key) > 0; }

  /// A key's line: for a tree copied from a file (a sweep's rows: YAML::Clone keeps no marks)
  /// where the file had it, else where the parser found it.
  int lineIn(const YAML::Node& key_node, const std::string& dotted) const {
    if (auto it = copied_lines_.find(dotted); it != copied_lines_.end()) return it->second;
    return lineOf(key_node);
  }

  /// Reads a leaf key into the member the table names.
  void read(const std::string& key, const Field& field) {
    std::visit(
        [&](auto member) {
          if constexpr (!std::is_same_v<decltype(member), std::monostate>) read(key, member(out_));
        },
        field);
  }

  void read(const std::string& key, double& value) {
    if (auto node = take(key)) value = number(*node, key);
  }
  void read(const std::string& key, int& value) {
    if (auto node = take(key)) value = whole(*node, key);
  }
  void read(const std::string& key, std::string& value) {
    if (auto node = take(key)) {
      if (!node->IsScalar()) fail(key, "must be a word");
      value = node->Scalar();
    }
  }
  template <typename T, std::size_t N>
  void read(const std::string& key, std::array<T, N>& value) {
    auto node = take(key);
    if (!node) return;
    if (!node->IsSequence() || node->size() != N)
      fail(key, std::string(N == 2 ? "must be a list of two numbers"
                                   : "must be a list of three numbers") +
                    ", not " +
                    (node->IsSequence() ? "a list of " + std::to_string(node->size())
                                        : described(*node)) +
                    // [0.5 0.5] is a list of one word: the commas are missing.
                    (node->IsSequence() && node->size() == 1 && (*node)[0].IsScalar() &&
                             (*node)[0].Scalar().find(' ') != std::string::npos
                         ? " ('" + (*node)[0].Scalar() + "': separate the numbers with commas)"
                         : ""));
    for (std::size_t i = 0; i < N; ++i) {
      if constexpr (std::is_same_v<T, int>)
        value[i] = whole((*node)[i], key);
      else
        value[i] = number((*node)[i], key);
    }
  }

  void read(const std::string& key, sim::Matrix3Spec& value) {
    auto node = take(key);
    if (!node) return;
    if (!node->IsSequence() || node->size() != 3) fail(key, "must be three rows of three numbers");
    for (std::size_t i = 0; i < 3; ++i) {
      const YAML::Node row = (*node)[i];
      if (!row.IsSequence() || row.size() != 3) fail(key, "must be three rows of three numbers");
      for (std::size_t j = 0; j < 3; ++j) value[i][j] = number(row[j], key);
    }
  }

  /// A nested map, or nothing when the key is absent.
  std::optional<MapReader> child(const std::string& key) {
    auto node = take(key);
    if (!node) return std::nullopt;
    return MapReader(*node, join(path_, key), key_lines_.at(key), out_, copied_lines_);
  }

  /// The message names the table's line that would do (scene/keys.cpp), so that it shows the
  /// way out.
  void require(const Key& key) const {
    const std::string name(nameIn(key.path));
    if (!has(name)) throw Failure{line_, join(path_, name), requiredMessage(key)};
  }

  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw Failure{key_lines_.at(key), join(path_, key), message};
  }

  const std::string& path() const { return path_; }

 private:
  std::optional<YAML::Node> take(const std::string& key) {
    auto it = present_.find(key);
    if (it == present_.end()) return std::nullopt;
    return it->second;
  }

  // What a value that is not the number it should be is: its text, or what kind of thing
  // (`mass: ~` or `mass:` with nothing after was called 'a list or map').
  static std::string described(const YAML::Node& node) {
    if (node.IsScalar()) return "'" + node.Scalar() + "'";
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a map";
    return "empty (the key has no value)";
  }

  // A number written with a unit ("59 g", or "5rad/s" with no space): the number alone, in the
  // key's unit as the table gives it (body.mass: kg).
  std::string unitHint(const YAML::Node& node, const std::string& key) const {
    if (!node.IsScalar()) return "";
    const std::string text = node.Scalar();
    double v = 0;
    const char* const begin = text.data();
    const auto [end, ec] = std::from_chars(begin, begin + text.size(), v);
    const std::size_t at = static_cast<std::size_t>(end - begin);
    const std::size_t word = text.find_first_not_of(' ', at);
    if (ec != std::errc() || at == 0 || word == std::string::npos ||
        !(std::isalpha(static_cast<unsigned char>(text[word])) || text[word] == '%' ||
          static_cast<unsigned char>(text[word]) >= 0x80))  // a letter, %, or ° and the like
      return "";
    const Key* known = findKey(join(path_, key));
    if (!known || known->unit.empty()) return " (write the number alone)";
    // Lengths are in the file's unit (units.length), the rest in SI.
    const std::string unit(known->unit);
    return " (write the number alone, in " +
           (unit == "file units" ? std::string("the file's length unit, units.length") : unit) +
           ")";
  }

  // units.length given as a unit's name ("cm"): the metres it stands for.
  std::string lengthUnitHint(const YAML::Node& node, const std::string& key) const {
    if (join(path_, key) != "units.length" || !node.IsScalar()) return "";
    static const std::map<std::string, std::string> metres = {
        {"m", "1"}, {"cm", "0.01"}, {"mm", "0.001"}, {"in", "0.0254"}, {"inch", "0.0254"}};
    const auto known = metres.find(node.Scalar());
    return known == metres.end()
               ? " (the metres in one length unit: 0.01 for cm, 0.001 for mm)"
               : " (the metres in one length unit: " + known->second + " for " + known->first + ")";
  }

  // A decimal comma (0,059): the number with a point.
  static std::string commaHint(const YAML::Node& node) {
    if (!node.IsScalar()) return "";
    std::string text = node.Scalar();
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) return "";
    text[comma] = '.';
    double v = 0;
    if (!YAML::convert<double>::decode(YAML::Node(text), v)) return "";
    return " (a decimal comma: write " + text + ")";
  }

  double number(const YAML::Node& node, const std::string& key) const {
    double v = 0;
    // A quoted scalar ("0.5") is a string: its tag is "!" rather than the plain "?".
    if (node.IsScalar() && node.Tag() == "!")
      fail(key, "must be a number, not the quoted string \"" + node.Scalar() + "\"");
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, v))
      fail(key, "must be a number, not " + described(node) + unitHint(node, key) + commaHint(node) +
                    lengthUnitHint(node, key));
    return v;
  }

  int whole(const YAML::Node& node, const std::string& key) const {
    const double v = number(node, key);
    // A fraction is named with the whole number nearest it (video.fps 29.97, the NTSC rate
    // typed from a camera's settings, is 30 here).
    if (std::isfinite(v) && v != std::floor(v) && std::abs(v) <= 1e9)
      fail(key, "must be a whole number, not '" + node.Scalar() + "': use " +
                    std::to_string(std::lround(v)));
    if (!std::isfinite(v) || std::abs(v) > 1e9)
      fail(key, "must be a whole number, not '" + node.Scalar() + "'");
    return static_cast<int>(v);
  }

  std::string path_;
  int line_;
  Loaded& out_;
  const std::map<std::string, int>& copied_lines_;  // see lineIn
  std::map<std::string, YAML::Node> present_;
  std::map<std::string, int> key_lines_;
};

// Checks one key of a map: a key of the other shape is refused, a missing required key is
// named with the line that would do (scene/keys.cpp); a leaf's value goes to its member.
void checkKey(MapReader& reader, const Key& key, Loaded& out) {
  const std::string name(nameIn(key.path));
  if (reader.has(name) && !belongsTo(key, out.spec.body))
    reader.fail(name, "belongs to shape: " + shapeWords(key.shape));
  if (requiredIn(key, out.spec)) reader.require(key);
  reader.read(name, key.field);
}

// Reads one map in the table's order: its plain keys first, then whether its nested maps may and
// must be there, then the nested maps that are given, the same way. A missing optional key or
// map keeps the spec's default. The words other keys depend on (body.shape, contact.model) come
// first in their maps, so they are read before they are asked.
void readKeys(MapReader& reader, Loaded& out) {
  const std::vector<const Key*> inside = keysIn(reader.path());
  for (const bool maps : {false, true})
    for (const Key* key : inside)
      if (isMap(*key) == maps) checkKey(reader, *key, out);
  for (const Key* key : inside) {
    if (!isMap(*key)) continue;
    if (auto child = reader.child(std::string(nameIn(key->path)))) {
      if (key->given) key->given(out);
      readKeys(*child, out);
    }
  }
}

std::string format(const std::string& file, int line, const std::string& key,
                   const std::string& message) {
  std::ostringstream s;
  s << file << ":" << line << ": " << key << " " << message;
  return printable(s.str());
}

// An error in a scene: one line naming file, line and key, and the same three apart.
rb::Error located(const std::string& file, int line, const std::string& key,
                  const std::string& message) {
  rb::Error e{"", format(file, line, key, message)};
  e.where = rb::Error::Where{file, line, key};
  return e;
}

// An error in a key set from outside the file, named by what set it: an option for the key
// alone ("--fps: must be …"), else with the key: "--set body.mass=-3: body.mass must be > 0",
// "with_values: body.mass …", a sweep's line.
rb::Error setBy(const std::string& place, const std::string& set_key, const rb::Error& error) {
  // An option or argument of one key is named alone ("--spin: must be …"); Python's sweep
  // argument vary sets many, so it is named with the key, as a sweep file's line is.
  const bool option =
      place.rfind("--", 0) == 0 || (place.rfind("argument ", 0) == 0 && place != "argument vary");
  const bool alone = option && place.find('=') == std::string::npos && error.key == set_key;
  rb::Error e{"", printable(place + ": " + (alone ? "" : error.key + " ") + error.message)};
  e.where = rb::Error::Where{place, 0, error.key};
  return e;
}

// body.mesh.file as a path from here: the key's is relative to the scene file.
std::filesystem::path meshPath(const Loaded& loaded) {
  std::filesystem::path path(loaded.spec.body.mesh.file);
  if (path.is_relative()) path = std::filesystem::path(loaded.file).parent_path() / path;
  return path;
}

// body.mesh.file, relative to the scene file, read into the spec (scene/mesh_file.hpp): an error
// names the scene's file, line and key, then the mesh file and its cause.
std::optional<rb::Error> readBodyMesh(Loaded& out,
                                      const std::map<std::string, std::string>& places) {
  sim::MeshSpec& mesh = out.spec.body.mesh;
  auto read = readMesh(meshPath(out).string());
  if (read) {
    mesh.data = std::make_shared<const sim::TriangleMesh>(std::move(read).value());
    return std::nullopt;
  }
  const rb::Error error{"body.mesh.file", read.error().message};
  if (const auto place = places.find(error.key); place != places.end())
    return setBy(place->second, error.key, error);
  const auto line = out.lines.find(error.key);
  return located(out.file, line == out.lines.end() ? 0 : line->second, error.key, error.message);
}

}  // namespace

namespace {

rb::Error malformed(const std::string& name, const YAML::Exception& e) {
  return malformedYaml(name, "", e);
}

}  // namespace

namespace {

// Every map's keys are checked before any key is found missing: a misspelt key inside body was
// named only after contact, missing, had been added ("x.yaml:1: contact is required" for `body:
// {mas: 1}`).
void checkKnownKeys(const YAML::Node& node, const std::string& path, int line,
                    const std::map<std::string, int>& lines) {
  Loaded scratch;
  const MapReader reader(node, path, line, scratch, lines);  // (refuses an unknown key)
  for (const auto& entry : node) {
    const std::string key = join(path, entry.first.as<std::string>());
    if (entry.second.IsMap() && !keysIn(key).empty())
      checkKnownKeys(entry.second, key, reader.lineIn(entry.first, key), lines);
  }
}

}  // namespace

rb::Result<Loaded> loadTree(const YAML::Node& root_node, const std::string& name,
                            const std::map<std::string, std::string>& places,
                            const std::map<std::string, int>& lines,
                            std::shared_ptr<const sim::TriangleMesh> mesh) {
  Loaded out;
  out.file = name;
  out.overrides = places;
  try {
    if (!root_node.IsDefined() || root_node.IsNull())
      return rb::Error{"", printable(name) +
                               ":1: the scene is empty; expected keys such as "
                               "body, contact, simulation"};
    if (root_node.IsMap()) checkKnownKeys(root_node, "", 1, lines);
    MapReader root(root_node, "", 1, out, lines);
    readKeys(root, out);
  } catch (const Failure& f) {
    // A key set from elsewhere (a sweep's axis, --set) is named where it was set.
    for (const auto& [key, place] : places)
      if (f.key == key || f.key.rfind(key + ".", 0) == 0)
        return setBy(place, key, rb::Error{f.key, f.message});
    // An unknown key above the one set ("intial" of --set intial.spin=3) was made by the setting:
    // the file has no such key, and its line 1 is not where the mistake is.
    if (f.unknown_key)
      for (const auto& [key, place] : places)
        if (key.rfind(f.key + ".", 0) == 0) return setBy(place, key, rb::Error{f.key, f.message});
    return located(name, f.line, f.key, f.message);
  } catch (const YAML::Exception& e) {
    return malformed(name, e);
  }
  if (out.spec.body.shape == "mesh") {
    if (mesh)
      out.spec.body.mesh.data = std::move(mesh);
    else if (auto e = readBodyMesh(out, places))
      return *e;
  }
  return out;
}

rb::Result<Loaded> loadString(const std::string& yaml, const std::string& name) {
  YAML::Node root;
  return loadString(yaml, name, root);
}

rb::Result<Loaded> loadString(const std::string& yaml, const std::string& name, YAML::Node& root) {
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    return malformedYaml(name, yaml, e);  // syntax errors: yaml-cpp knows the line but no key
  }
  std::string content = YAML::Dump(root);  // yamlContent(yaml), without parsing it again
  auto loaded = loadTree(root, name, {});
  if (loaded) loaded->content = std::move(content);
  return loaded;
}

namespace {

// The tree of `yaml` with each value put at its key; `places` gets where each key was set and
// `content` the text's content before the values went in (yamlContent's, without parsing again).
rb::Result<YAML::Node> treeWithValues(const std::string& yaml, const std::string& name,
                                      const std::vector<KeyValue>& values, const std::string& place,
                                      std::map<std::string, std::string>& places,
                                      std::string& content) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    return malformedYaml(name, yaml, e);
  }
  content = YAML::Dump(root);
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const KeyValue& kv : values) {
    auto fail = [&](const std::string& message) {
      rb::Error e{"", printable(place + ": " + kv.key + " " + message)};
      e.where = rb::Error::Where{place, 0, kv.key};
      return e;
    };
    const auto path = splitKey(kv.key);
    if (!path)
      return fail(
          "is not a scene key: give dotted keys such as initial.spin or "
          "body.dents.at[0]");
    if (!root.IsMap()) return fail("cannot be set: the scene is not a map of keys");
    YAML::Node value;
    try {
      value = YAML::Load(kv.yaml);
    } catch (const YAML::Exception& e) {
      return fail("has a malformed value: " + e.msg);
    }
    if (path->index) {
      const YAML::Node list = find(root, *path);
      if (!list.IsSequence() || list.size() <= *path->index)
        return fail("names element " + std::to_string(*path->index) + " of " +
                    withoutIndex(kv.key) + ", which the scene does not have");
    }
    put(root, *path, 0, value);
    // An option names each value as typed ("--set body.mass=-3"); with_values by its name.
    places[withoutIndex(kv.key)] =
        place.rfind("--", 0) == 0 ? place + " " + kv.key + "=" + kv.yaml : place;
  }
  return root;
}

}  // namespace

rb::Result<std::string> yamlWithValues(const std::string& yaml, const std::string& name,
                                       const std::vector<KeyValue>& values,
                                       const std::string& place) {
  std::map<std::string, std::string> places;
  std::string content;
  auto root = treeWithValues(yaml, name, values, place, places, content);
  if (!root) return root.error();
  return YAML::Dump(root.value()) + "\n";
}

rb::Result<Loaded> loadWithValues(const std::string& yaml, const std::string& name,
                                  const std::vector<KeyValue>& values, const std::string& place,
                                  std::shared_ptr<const sim::TriangleMesh> mesh) {
  std::map<std::string, std::string> places;
  std::string content;
  auto tree = treeWithValues(yaml, name, values, place, places, content);
  if (!tree) return tree.error();
  YAML::Node root = tree.value();
  replaceAlternatives(root, places);
  auto loaded = loadTree(root, name, places, {}, std::move(mesh));
  if (loaded) {
    loaded->values = values;
    loaded->content = std::move(content);
  }
  return loaded;
}

std::string valuesSaid(const std::vector<KeyValue>& values, const std::string& equals) {
  // An inertia is nine numbers of 17 digits: in full it buries the message's cause.
  constexpr std::size_t kShown = 40;
  std::vector<const KeyValue*> last;
  for (const KeyValue& v : values) {
    std::erase_if(last, [&](const KeyValue* seen) { return seen->key == v.key; });
    last.push_back(&v);
  }
  std::string said;
  for (const KeyValue* v : last)
    said += (said.empty() ? "" : ", ") + v->key + equals +
            (v->yaml.size() > kShown ? v->yaml.substr(0, kShown) + "…" : v->yaml);
  return said;
}

std::vector<std::string> filesRead(const Loaded& loaded) {
  std::vector<std::string> files;
  if (!loaded.file.empty()) files.push_back(loaded.file);
  if (loaded.spec.body.mesh.data) files.push_back(meshPath(loaded).string());
  return files;
}

rb::Result<Loaded> loadFile(const std::string& path) {
  auto text = readSceneFile(path);
  if (!text) return text.error();
  return loadString(text.value(), path);
}

// The option or sweep line that set `key`, a key inside it (body.grid's error for a varied
// body.grid.dx), or the map around it.
std::map<std::string, std::string>::const_iterator overrideOf(const Loaded& loaded,
                                                              const std::string& key) {
  if (auto it = loaded.overrides.find(key); it != loaded.overrides.end() || key.empty()) return it;
  for (auto it = loaded.overrides.begin(); it != loaded.overrides.end(); ++it)
    if (it->first.rfind(key + ".", 0) == 0) return it;
  for (auto it = loaded.overrides.begin(); it != loaded.overrides.end(); ++it)
    if (key.rfind(it->first + ".", 0) == 0) return it;
  return loaded.overrides.end();
}

rb::Error locate(const Loaded& loaded, const rb::Error& error) {
  if (auto it = overrideOf(loaded, error.key); it != loaded.overrides.end())
    return setBy(it->second, it->first, error);
  // A key of the file's whose error comes of a value set from outside it (the step count of
  // the file's dt over a --duration) is named by that option, with the key.
  for (const std::string& other : error.involves)
    if (auto it = overrideOf(loaded, other); it != loaded.overrides.end())
      return setBy(it->second, "", error);
  // The key's own line, else the nearest enclosing key that the file has.
  std::string key = error.key;
  while (!key.empty()) {
    if (auto it = loaded.lines.find(key); it != loaded.lines.end())
      return located(loaded.file, it->second, error.key, error.message);
    const auto dot = key.rfind('.');
    key = dot == std::string::npos ? "" : key.substr(0, dot);
  }
  return located(loaded.file, 1, error.key, error.message);
}

std::string describe(const Loaded& loaded, const rb::Error& error) {
  return locate(loaded, error).message;
}

rb::Result<sim::Model> loadModel(const Loaded& loaded) {
  auto compiled = sim::compile(loaded.spec);
  if (!compiled) return locate(loaded, compiled.error());
  return std::move(compiled).value();
}

}  // namespace scene

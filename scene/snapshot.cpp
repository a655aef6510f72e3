#include "scene/snapshot.hpp"

#include <yaml-cpp/yaml.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string_view>
#include <vector>

#include "scene/tree.hpp"
#include "util/nearest.hpp"

namespace scene {
namespace {

using K = SnapshotKind;
using W = SnapshotWhere;

constexpr std::array<SnapshotKey, 12> kKeys{{
    {"goldens", K::Folder, W::Top,
     "folder of the golden images NAME.png, relative to this file (default goldens)"},
    {"cases", K::Cases, W::Top, "the cases: a list of maps of the case keys"},
    {"name", K::Name, W::Case,
     "the case's name, unique: letters, digits, - _ . (its golden is GOLDENS/NAME.png; the "
     "frame's title says it)"},
    {"scene", K::Scene, W::Case, "the scene file, relative to this file"},
    {"t", K::Time, W::Case,
     "the time drawn, s, or reversal, first_reversal (the first reversal counted) or end "
     "(default 0)"},
    {"title", K::Title, W::Case, "the frame's title instead of the case's name"},
    {"view", K::View, W::Both, "oblique, above, front, side or follow (default the scene's)"},
    {"size", K::Size, W::Both, "WIDTHxHEIGHT in pixels, even (default the scene's)"},
    {"backend", K::Backend, W::Both,
     "auto, egl or osmesa (default $RATTLEBACK_BACKEND, else auto)"},
    {"tolerance", K::Channel, W::Both,
     "largest difference in a channel, 0–255, that counts as equal (default 2)"},
    {"pixels", K::Fraction, W::Both,
     "fraction of the pixels allowed to differ beyond it, 0–1 (default 0.002)"},
    {"square", K::Side, W::Both,
     "a square of differing pixels this many a side fails whatever pixels allows (default 4; 0 "
     "off)"},
}};

// A suite file that cannot be used, at a line and key.
struct Bad {
  int line;
  std::string key;
  std::string message;
};

std::string scalarOf(const YAML::Node& node, int line, const std::string& key) {
  if (!node.IsScalar()) throw Bad{line, key, "must be a single value, not a list or map"};
  return node.Scalar();
}

// A number written as one: quoted text ("2") is refused, as a scene refuses it.
double numberOf(const YAML::Node& node, int line, const std::string& key) {
  double v = 0;
  const std::string text = scalarOf(node, line, key);
  if (node.Tag() == "!" || !YAML::convert<double>::decode(node, v) || !std::isfinite(v))
    throw Bad{line, key, "must be a number, not '" + text + "'"};
  return v;
}

int wholeIn(const YAML::Node& node, int line, const std::string& key, int lo, int hi) {
  const double v = numberOf(node, line, key);
  if (v != std::floor(v) || v < lo || v > hi)
    throw Bad{line, key,
              "must be a whole number within " + std::to_string(lo) + " … " + std::to_string(hi) +
                  ", not " + scalarOf(node, line, key)};
  return static_cast<int>(v);
}

template <typename E>
E wordOf(const YAML::Node& node, int line, const std::string& key) {
  const std::string text = scalarOf(node, line, key);
  const auto value = rb::parseName<E>(text);
  if (!value) throw Bad{line, key, "must be " + rb::choices<E>() + ", not '" + text + "'"};
  return *value;
}

sim::RunTime timeOf(const YAML::Node& node, int line, const std::string& key) {
  const std::string text = scalarOf(node, line, key);
  if (const auto named = rb::parseName<sim::NamedTime>(text)) return {0, named};
  double v = 0;
  if (node.Tag() == "!" || !YAML::convert<double>::decode(node, v) || !std::isfinite(v) || v < 0)
    throw Bad{line, key,
              "must be a time ≥ 0 s or " + rb::choices<sim::NamedTime>() + ", not '" + text + "'"};
  return {v, std::nullopt};
}

std::array<int, 2> sizeOf(const YAML::Node& node, int line, const std::string& key) {
  const std::string text = scalarOf(node, line, key);
  int w = 0, h = 0;
  char x = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || (x != 'x' && x != 'X') ||
      w <= 0 || h <= 0)
    throw Bad{line, key, "must be WIDTHxHEIGHT in pixels such as 640x360, not '" + text + "'"};
  return {w, h};
}

// A name that is a file's name in any folder and on any system: no path, nothing hidden.
std::string nameOf(const YAML::Node& node, int line, const std::string& key) {
  const std::string text = scalarOf(node, line, key);
  const bool plain = !text.empty() && text.size() <= 100 && text[0] != '.' &&
                     text.find_first_not_of(
                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                         "0123456789-_.") == std::string::npos;
  if (!plain)
    throw Bad{line, key,
              "must be a name of letters, digits, - _ and . (not first), at most 100, not '" +
                  text + "'"};
  return text;
}

// Puts one value into a case (or the suite's defaults, which every case starts from).
void putValue(const SnapshotKey& k, const YAML::Node& v, int line, const std::string& key,
              SnapshotCase& c) {
  switch (k.kind) {
    case K::Name:
      c.name = nameOf(v, line, key);
      break;
    case K::Scene:
      c.scene_as_written = scalarOf(v, line, key);
      break;
    case K::Time:
      c.t = timeOf(v, line, key);
      c.t_text = v.Scalar();
      break;
    case K::Title:
      c.title = scalarOf(v, line, key);
      break;
    case K::View:
      c.view = wordOf<render::View>(v, line, key);
      break;
    case K::Size:
      c.size = sizeOf(v, line, key);
      break;
    case K::Backend:
      c.backend = wordOf<render::Backend>(v, line, key);
      break;
    case K::Channel:
      c.tolerance.channel = wholeIn(v, line, key, 0, 255);
      break;
    case K::Fraction:
      c.tolerance.pixels = numberOf(v, line, key);
      if (c.tolerance.pixels < 0 || c.tolerance.pixels > 1)
        throw Bad{line, key, "must be a fraction within 0 … 1 (0.002 = 0.2 %), not " + v.Scalar()};
      break;
    case K::Side:
      c.tolerance.square = wholeIn(v, line, key, 0, 100000);
      break;
    case K::Folder:
    case K::Cases:
      break;  // the suite's own, read by readSuite
  }
}

bool allowedIn(const SnapshotKey& k, W where) {
  return k.where == W::Both || k.where == where;
}

// The map's keys, each checked against the table (unknown and repeated keys refused, naming
// the keys that may stand there); calls `take` with each key's row, value, line and dotted name.
template <typename Take>
void readMap(const YAML::Node& node, W where, int line, const std::string& prefix, Take take) {
  if (!node.IsMap())
    throw Bad{line, prefix.empty() ? "suite" : prefix.substr(0, prefix.size() - 1),
              "must be a map of keys (key: value)"};
  std::set<std::string> seen;
  for (const auto& entry : node) {
    const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    const int at = lineOf(entry.first);
    const std::string key = prefix + name;
    if (!seen.insert(name).second) throw Bad{at, key, "is given twice"};
    const SnapshotKey* row = nullptr;
    std::string known;
    std::vector<std::string_view> names;
    for (const SnapshotKey& k : kKeys) {
      if (!allowedIn(k, where)) continue;
      known += (known.empty() ? "" : ", ") + std::string(k.name);
      names.push_back(k.name);
      if (k.name == name) row = &k;
    }
    if (!row) {
      const auto nearest = rb::nearestWord(name, names);
      throw Bad{at, key,
                std::string("is not a key of ") + (where == W::Top ? "a suite" : "a case") + " (" +
                    known + ")" + (nearest ? "; did you mean " + *nearest + "?" : "")};
    }
    take(*row, entry.second, at, key);
  }
}

std::string resolved(const std::string& folder, const std::string& path) {
  const std::filesystem::path p(path);
  return (p.is_absolute() ? p : std::filesystem::path(folder) / p).lexically_normal().string();
}

SnapshotCase readCase(const YAML::Node& node, const SnapshotCase& defaults, int index,
                      const std::string& file) {
  SnapshotCase c = defaults;
  const int line = lineOf(node);
  const std::string prefix = "cases[" + std::to_string(index) + "].";
  c.place = file + ":" + std::to_string(line);
  c.line = line;
  readMap(node, W::Case, line, prefix,
          [&](const SnapshotKey& k, const YAML::Node& v, int at, const std::string& key) {
            putValue(k, v, at, key, c);
            if (k.kind == K::Size) c.top_size_place.clear();  // its own
          });
  for (const char* needed : {"name", "scene"})
    if (!node[needed])
      throw Bad{line, prefix + needed,
                std::string("is required (a case is at least {name: NAME, scene: FILE.yaml})")};
  return c;
}

SnapshotSuite readSuite(const YAML::Node& root, const std::string& path) {
  SnapshotSuite suite;
  suite.file = path;
  const std::filesystem::path here = std::filesystem::path(path).parent_path();
  const std::string folder = here.empty() ? "." : here.string();
  std::string goldens = "goldens";
  SnapshotCase defaults;
  YAML::Node cases;
  int cases_line = 1;
  readMap(root, W::Top, 1, "",
          [&](const SnapshotKey& k, const YAML::Node& v, int at, const std::string& key) {
            if (k.kind == K::Folder) goldens = scalarOf(v, at, key);
            if (k.kind == K::Cases) {
              cases = v;
              cases_line = at;
            }
            if (k.where == W::Both) putValue(k, v, at, key, defaults);
            if (k.kind == K::Size) defaults.top_size_place = path + ":" + std::to_string(at);
          });
  if (!cases || !cases.IsSequence() || cases.size() == 0)
    throw Bad{cases_line, "cases",
              "must be a list of one case or more (cases: [{name: NAME, scene: FILE.yaml}])"};
  // Names as a folder of goldens tells them apart: on macOS's and Windows' file systems A.png and
  // a.png are one file, so names that differ only by case would share a golden there.
  std::map<std::string, std::pair<std::string, int>> names;  // folded: as written, its line
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SnapshotCase c = readCase(cases[i], defaults, static_cast<int>(i), path);
    std::string folded = c.name;
    for (char& ch : folded) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (const auto [earlier, fresh] = names.emplace(folded, std::pair{c.name, lineOf(cases[i])});
        !fresh) {
      const auto& [name, line] = earlier->second;
      throw Bad{
          lineOf(cases[i]), "cases[" + std::to_string(i) + "].name",
          "'" + c.name + "' names the case at line " + std::to_string(line) + " too" +
              (name == c.name ? ""
                              : " ('" + name + "', as a file system that ignores case reads it)") +
              ": each case needs its own golden"};
    }
    c.scene = resolved(folder, c.scene_as_written);
    suite.cases.push_back(std::move(c));
  }
  suite.goldens = resolved(folder, goldens);
  return suite;
}

}  // namespace

std::span<const SnapshotKey> snapshotKeys() {
  return kKeys;
}

rb::Result<SnapshotSuite> parseSnapshotSuite(const std::string& text, const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return malformedYaml(path, text, e);
  }
  try {
    return readSuite(root, path);
  } catch (const Bad& bad) {
    rb::Error e{
        "", printable(path + ":" + std::to_string(bad.line) + ": " + bad.key + " " + bad.message)};
    e.where = rb::Error::Where{path, bad.line, bad.key};
    return e;
  } catch (const YAML::Exception& e) {
    return malformedYaml(path, text, e);
  }
}

rb::Result<SnapshotSuite> loadSnapshotSuite(const std::string& path) {
  std::error_code ec;
  const rb::Error::Where where{path, 0, ""};
  if (std::filesystem::is_directory(path, ec))
    return rb::Error{"", path + ": is a folder, not a snapshot suite (give its .yaml file)", where};
  std::ifstream in(path, std::ios::binary);
  if (!in) return rb::Error{"", path + ": no such snapshot suite (or it cannot be read)", where};
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parseSnapshotSuite(text, path);
}

}  // namespace scene

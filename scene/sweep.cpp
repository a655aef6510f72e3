#include "scene/sweep.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <set>

#include "scene/direct_rows.hpp"
#include "scene/key_path.hpp"
#include "scene/tree.hpp"
#include "util/assets.hpp"
#include "util/nearest.hpp"

namespace scene {
namespace {

constexpr std::int64_t kMaxRows = 100'000'000;

// A sweep that cannot be used; `where` names the file, line and key when the thrower knows
// them better than the part being read (parseSweep's `place`).
struct SweepFailure {
  std::string message;
  std::optional<rb::Error::Where> where = std::nullopt;
};

// An error of a sweep file at `where`: as a scene's names its file, line and key (Python raises
// SceneError for it).
rb::Error sweepError(std::string message, rb::Error::Where where) {
  rb::Error e{"", std::move(message)};
  e.where = std::move(where);
  return e;
}

std::string flowText(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out.SetMapFormat(YAML::Flow);
  out << node;
  return out.c_str();
}

// Twelve significant digits: what a range's value is, so the table's text is the value run.
std::string rangeValue(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.12g", v + 0.0);  // + 0.0: no "-0"
  return text;
}

double number(const YAML::Node& node, const std::string& where, const std::string& what) {
  double v = 0;
  // Missing is said as missing (rather than "count must be a number" for {from: -5, to: 5}),
  // with what the range needs.
  if (!node.IsDefined())
    throw SweepFailure{where + " " + what +
                       " is required: a range is {from: A, to: B, count: N} (count: how many "
                       "values, ends included)"};
  if (node.IsScalar() && node.Tag() == "!" && YAML::convert<double>::decode(node, v))
    throw SweepFailure{where + " " + what + " must be a number, not the quoted string \"" +
                       node.Scalar() + "\""};
  if (!node.IsScalar() || node.Tag() == "!" || !YAML::convert<double>::decode(node, v) ||
      !std::isfinite(v))
    throw SweepFailure{where + " " + what + " must be a number"};
  return v;
}

std::vector<std::string> rangeValues(const YAML::Node& spec, const std::string& where) {
  std::set<std::string> seen;
  for (const auto& entry : spec) {
    const std::string key = entry.first.as<std::string>();
    if (key != "from" && key != "to" && key != "count" && key != "scale")
      throw SweepFailure{where + " has '" + key +
                         "', not a key of a range (from, to, count, scale)"};
  }
  const double from = number(spec["from"], where, "from");
  const double to = number(spec["to"], where, "to");
  const double count_value = number(spec["count"], where, "count");
  if (count_value != std::floor(count_value) || count_value < 1 || count_value > 1e6)
    throw SweepFailure{where + " count must be a whole number from 1 to 1e6, not " +
                       rangeValue(count_value)};
  const auto count = static_cast<int>(count_value);
  std::string scale = "linear";
  if (spec["scale"]) {
    if (!spec["scale"].IsScalar()) throw SweepFailure{where + " scale must be linear or log"};
    scale = spec["scale"].Scalar();
  }
  if (scale != "linear" && scale != "log")
    throw SweepFailure{where + " scale must be linear or log, not '" + scale + "'"};
  if (scale == "log" && !(from > 0 && to > 0))
    throw SweepFailure{where + " a log range needs from and to above 0 (from " + rangeValue(from) +
                       ", to " + rangeValue(to) + ")"};
  if (count == 1 && from != to)
    throw SweepFailure{where + " count 1 needs from = to (or give a list of one value)"};
  std::vector<std::string> values;
  for (int k = 0; k < count; ++k) {
    const double f = count == 1 ? 0.0 : static_cast<double>(k) / (count - 1);
    const double v = k == count - 1   ? to
                     : scale == "log" ? from * std::pow(to / from, f)
                                      : from + (to - from) * f;
    values.push_back(rangeValue(v));
  }
  return values;
}

// An unknown key of a sweep, with the nearest known one. (Python's sweep gives its columns as
// an argument of their own: its text has no columns key.)
std::string unknownKey(const std::string& at, const std::string& key, bool given) {
  const std::vector<std::string> known =
      given ? std::vector<std::string>{"vary", "duration"}
            : std::vector<std::string>{"base", "vary", "duration", "columns"};
  std::string known_list;
  for (const std::string& k : known) known_list += (known_list.empty() ? "" : ", ") + k;
  const std::optional<std::string> nearest = rb::nearestWord(key, known);
  // A scene's own section (units, body, initial…): a scene file given where a sweep goes.
  const std::string scene_file =
      !nearest && !given && findKey(key)
          ? "; a scene's key: this is a scene file, not a sweep (a sweep names its scene as "
            "base: and what it varies under vary:, docs/scenes.md \"Sweep files\"); "
            "rattleback simulate runs a scene"
          : "";
  return at + ": " + key + " is not a key of a sweep" +
         (nearest ? "; did you mean " + *nearest + "?" : "") + scene_file +
         " (known: " + known_list + ")";
}

// `columns:`, a list of column names, each once: its form only (which names are columns is the
// table's to say, tasks::checkColumns). `where` names the file and the key, its line each name's.
std::vector<SweepColumnName> columnNames(const YAML::Node& node, const std::string& at,
                                         rb::Error::Where where, bool lines) {
  if (!node.IsSequence() || node.size() == 0)
    throw SweepFailure{at +
                       ": columns must be a list of the table's columns, e.g. "
                       "[first_reversal_s, forecast_s]"};
  std::vector<SweepColumnName> out;
  std::set<std::string> seen;
  for (const auto& entry : node) {
    where.line = lines ? lineOf(entry) : 0;
    const std::string here = lines ? where.file + ":" + std::to_string(where.line) : where.file;
    if (!entry.IsScalar() || entry.Scalar().empty())
      throw SweepFailure{here + ": columns: each entry is a column's name, e.g. first_reversal_s",
                         where};
    if (!seen.insert(entry.Scalar()).second)
      throw SweepFailure{here + ": columns: " + entry.Scalar() + " is listed twice", where};
    out.push_back({entry.Scalar(), where});
  }
  return out;
}

}  // namespace

std::int64_t Sweep::rows() const {
  std::int64_t n = 1;
  for (const SweepAxis& axis : axes) n *= static_cast<std::int64_t>(axis.values.size());
  return n;
}

std::vector<int> Sweep::coordinates(std::int64_t row) const {
  std::vector<int> at(axes.size());
  for (std::size_t i = axes.size(); i-- > 0;) {
    const auto n = static_cast<std::int64_t>(axes[i].values.size());
    at[i] = static_cast<int>(row % n);
    row /= n;
  }
  return at;
}

std::int64_t Sweep::bodyGroup(std::int64_t row) const {
  const std::vector<int> at = coordinates(row);
  std::int64_t group = 0;
  for (std::size_t i = 0; i < axes.size(); ++i)
    if (axes[i].body) group = group * static_cast<std::int64_t>(axes[i].values.size()) + at[i];
  return group;
}

std::int64_t Sweep::bodyGroups() const {
  std::int64_t n = 1;
  for (const SweepAxis& axis : axes)
    if (axis.body) n *= static_cast<std::int64_t>(axis.values.size());
  return n;
}

struct SweepScenes::Impl {
  Sweep sweep;
  std::string base_name;
  YAML::Node base;
  std::vector<KeyPath> paths;
  std::map<std::string, std::string> places;  // varied key (without index) → its place
  std::map<std::string, int> base_lines;      // the base file's keys → their lines
  // yaml-cpp's nodes share reference-counted memory that is not safe to touch from two threads
  // at once: the base tree is copied under this lock, and the copy is the row's own.
  mutable std::mutex mutex;
  // Rows made without a tree (DirectRows); empty when the sweep's axes do not allow it.
  DirectRows direct;

  rb::Result<Loaded> scene(const std::vector<int>& at) const {
    if (std::optional<Loaded> loaded = direct.scene(at)) return std::move(*loaded);
    return build(at);
  }

  // Each row's tree is a fresh copy with fresh values parsed from their text: a node put into
  // another tree merges the two trees' memory for good in yaml-cpp, so values kept from row to
  // row would collect every row's nodes (and each row would take longer than the last). Only
  // the copy holds the lock: reading the row's scene from its own tree (0.15 ms a row, most of
  // it) had been done under it too, one row at a time on every thread.
  rb::Result<Loaded> build(const std::vector<int>& at) const {
    YAML::Node root;
    {
      std::lock_guard lock(mutex);
      root = YAML::Clone(base);
    }
    for (std::size_t i = 0; i < paths.size(); ++i)
      put(root, paths[i], 0, YAML::Load(sweep.axes[i].values[at[i]]));
    return loadTree(root, base_name, places, base_lines);
  }
};

SweepScenes::SweepScenes(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
SweepScenes::SweepScenes(SweepScenes&&) noexcept = default;
SweepScenes::~SweepScenes() = default;

rb::Result<Loaded> SweepScenes::scene(std::int64_t row) const {
  return impl_->scene(impl_->sweep.coordinates(row));
}

rb::Result<Loaded> SweepScenes::sceneFromTree(std::int64_t row) const {
  return impl_->build(impl_->sweep.coordinates(row));
}

rb::Result<SweepScenes> SweepScenes::open(const Sweep& sweep) {
  auto impl = std::make_unique<Impl>();
  impl->sweep = sweep;
  impl->base_name = sweep.base;
  try {
    impl->base = YAML::Load(sweep.base_text);
    if (!impl->base.IsDefined() || impl->base.IsNull())
      impl->base = YAML::Node(YAML::NodeType::Map);
    // The rows' trees are copies, which keep no lines: an error in a key of the base names the
    // base's line from these (it named line 1).
    if (sweep.base_lines)
      impl->base_lines = *sweep.base_lines;
    else if (auto loaded = loadTree(impl->base, sweep.base, {}))
      impl->base_lines = loaded->lines;
    for (const KeyValue& kv : sweep.base_values) {
      put(impl->base, *splitKey(kv.key), 0, YAML::Load(kv.yaml));
      impl->places[withoutIndex(kv.key)] = "with_values";
    }
    if (sweep.duration) {
      const KeyPath path{{"simulation", "duration"}, std::nullopt};
      put(impl->base, path, 0, YAML::Load(rangeValue(*sweep.duration)));
    }
    for (const SweepAxis& axis : sweep.axes) {
      impl->paths.push_back(*splitKey(axis.key));
      impl->places[withoutIndex(axis.key)] = axis.place;
    }
    replaceAlternatives(impl->base, impl->places);
    impl->direct = DirectRows::open(impl->base, sweep.axes, [&] {
      return loadTree(YAML::Clone(impl->base), impl->base_name, impl->places, impl->base_lines);
    });
  } catch (const YAML::Exception& e) {
    return sweepError(sweep.base + ": " + e.msg, {sweep.base, 0, ""});
  }
  return SweepScenes(std::move(impl));
}

namespace {

// What a sweep's text is read with: its file, whether messages name its lines (a file's) or
// the name alone (Python's argument), and the part being read, which an error names unless it
// knows better: the file, the line and the key (the sweep's own, base, vary or duration, or a
// varied scene key).
struct SweepText {
  const std::string& path;
  bool lines;
  rb::Error::Where place{path, lines ? 1 : 0, ""};

  std::string at(const YAML::Node& node) const {
    return lines ? path + ":" + std::to_string(lineOf(node)) : path;
  }
  std::string top() const { return lines ? path + ":1" : path; }
  void reading(const YAML::Node& node, const std::string& key) {
    place = {path, lines ? lineOf(node) : 0, key};
  }
  void readingTop(const std::string& key) { place = {path, lines ? 1 : 0, key}; }
};

// A sweep's own keys (base, vary, duration, columns), each with its key's node for its line.
// (A default-constructed YAML::Node is a defined null, so presence is kept apart.)
struct SweepKeys {
  YAML::Node base_key, vary_key, duration_key, columns_key;
  YAML::Node base, vary, duration, columns;
  bool has_base = false, has_vary = false, has_duration = false, has_columns = false;
};

SweepKeys sweepKeys(const YAML::Node& root, SweepText& in, bool given) {
  if (!root.IsMap())
    throw SweepFailure{in.top() +
                       ": a sweep is a map with the keys base, vary, duration and columns"};
  SweepKeys k;
  for (const auto& entry : root) {
    const std::string key = entry.first.as<std::string>();
    in.reading(entry.first, key);
    if (key == "base" && !given)
      k.base_key = entry.first, k.base = entry.second, k.has_base = true;
    else if (key == "vary")
      k.vary_key = entry.first, k.vary = entry.second, k.has_vary = true;
    else if (key == "duration")
      k.duration_key = entry.first, k.duration = entry.second, k.has_duration = true;
    else if (key == "columns" && !given)
      k.columns_key = entry.first, k.columns = entry.second, k.has_columns = true;
    else
      throw SweepFailure{unknownKey(in.at(entry.first), key, given)};
  }
  in.readingTop("");
  return k;
}

// The base of a sweep made without a file (Python's): its scene as given.
void givenBase(Sweep& sweep, const SweepBase& given) {
  sweep.base = sweep.base_as_written = given.name;
  sweep.base_text = given.yaml;
  sweep.base_values = given.values;
  auto loaded_base = loadWithValues(given.yaml, given.name, given.values, "with_values");
  if (!loaded_base) throw SweepFailure{loaded_base.error().text(), loaded_base.error().where};
  sweep.length_unit = loaded_base->spec.units.length;
}

// The base a sweep file names (relative to the file's folder), read and loaded; its tree kept
// in `base_tree`.
void fileBase(Sweep& sweep, const YAML::Node& root, const SweepKeys& k, SweepText& in,
              YAML::Node& base_tree) {
  namespace fs = std::filesystem;
  if (!k.has_base)
    throw SweepFailure{in.top() + ": base is required: the scene file the runs start from",
                       rb::Error::Where{in.path, in.lines ? 1 : 0, "base"}};
  in.reading(k.base_key, "base");
  if (!k.base.IsScalar() || k.base.Scalar().empty())
    throw SweepFailure{in.at(k.base_key) + ": base must be the path of a scene file"};
  sweep.base_as_written = k.base.Scalar();
  fs::path base = k.base.Scalar();
  if (base.is_relative()) base = fs::path(in.path).parent_path() / base;
  // Not beside the sweep, and named as a shipped scene is (scenes/rattleback.yaml): the shipped
  // one, as a scene named on the command line is found (the message for a missing base said so,
  // and a sweep beside no scenes/ folder was refused with its own base offered).
  // ./ and ../ name the sweep's folder only.
  if (std::error_code ec; !fs::exists(base, ec) && fs::path(k.base.Scalar()).is_relative() &&
                          !k.base.Scalar().starts_with("./") &&
                          !k.base.Scalar().starts_with("../")) {
    const fs::path shipped = fs::path(rb::assetsDir()) / k.base.Scalar();
    if (fs::is_regular_file(shipped, ec)) base = shipped;
  }
  sweep.base = base.lexically_normal().string();
  auto base_text = readSceneFile(sweep.base);
  // Named as typed too, where the folder's path changed it ("../top.yaml" is top.yaml here).
  const std::string base_named = sweep.base == sweep.base_as_written
                                     ? std::string("base: ")
                                     : "base " + sweep.base_as_written + ": ";
  if (!base_text)
    throw SweepFailure{in.at(k.base_key) + ": " + base_named + base_text.error().text()};
  sweep.base_text = base_text.value();
  auto loaded_base = loadString(sweep.base_text, sweep.base, base_tree);
  if (!loaded_base)
    throw SweepFailure{in.at(k.base_key) + ": " + base_named + loaded_base.error().text()};
  sweep.length_unit = loaded_base->spec.units.length;
  sweep.file_content = YAML::Dump(root);  // scene::yamlContent(text), without parsing again
  sweep.base_content = loaded_base->content;
  sweep.base_lines = loaded_base->lines;
}

// An axis's values as written: a list (each a value a scene key can take) or a range.
std::vector<std::string> axisValues(const YAML::Node& spec, const std::string& where,
                                    const YAML::Node& base_tree, const KeyPath& key_path,
                                    const SweepAxis& axis, const Sweep& sweep) {
  if (spec.IsMap()) return rangeValues(spec, where);
  if (!spec.IsSequence())
    throw SweepFailure{where + " must be a list of values or a range {from, to, count}, e.g. [" +
                       (spec.IsScalar() ? spec.Scalar() : std::string("-5, 5")) + "]"};
  if (spec.size() == 0) throw SweepFailure{where + " has no values"};
  // The base scene's value, where it is a number: a word swept in its place ("5 rad/s", a unit
  // written in) is a slip too.
  YAML::Node in_base = find(base_tree, key_path);
  if (key_path.index && in_base.IsSequence() && in_base.size() > *key_path.index)
    in_base = in_base[*key_path.index];
  double base_number = 0;
  const bool numeric = in_base.IsScalar() && YAML::convert<double>::decode(in_base, base_number);
  std::vector<std::string> values;
  for (const auto& value : spec) {
    // A quoted number is always a slip (a scene refuses it, and a refused row shows as "no
    // reversal" on the heatmap): said before anything runs.
    double number = 0;
    if (value.IsScalar() && value.Tag() == "!" && YAML::convert<double>::decode(value, number))
      throw SweepFailure{where + " has the quoted string \"" + value.Scalar() +
                         "\": write the number without quotes (" + value.Scalar() + ")"};
    // Said before anything runs, in the scene's words (with the key's unit), where a row was
    // refused and its heatmap cell left grey, as "no reversal".
    if (numeric && value.IsScalar() && !YAML::convert<double>::decode(value, number)) {
      YAML::Node probe = YAML::Clone(base_tree);
      put(probe, key_path, 0, value);
      const auto refused = loadTree(probe, sweep.base, {{withoutIndex(axis.key), axis.place}});
      if (!refused && refused.error().message.rfind(axis.place + ":", 0) == 0)
        throw SweepFailure{refused.error().message};
    }
    values.push_back(flowText(value));
  }
  return values;
}

// Whether the base scene takes the axis's key: an element of a list needs the list; the key
// must be one the scene knows (its first value put into the base: the loader rejects the key
// itself, where a bad value only refuses rows); a list swept with single numbers is said once.
void checkAxisKey(const SweepAxis& axis, const KeyPath& key_path, const YAML::Node& base_tree,
                  const Sweep& sweep, const std::string& where) {
  if (key_path.index) {
    const YAML::Node list = find(base_tree, key_path);
    if (!list.IsSequence() || list.size() <= *key_path.index)
      throw SweepFailure{where + ": the base scene has no list " + withoutIndex(axis.key) +
                         " with an element " + std::to_string(*key_path.index)};
  }
  YAML::Node probe = YAML::Clone(base_tree);
  put(probe, key_path, 0, YAML::Load(axis.values.front()));
  replaceAlternatives(probe, std::set<std::string>{withoutIndex(axis.key)});
  auto loaded = loadTree(probe, sweep.base, {{withoutIndex(axis.key), axis.place}});
  if (!loaded && loaded.error().message.find("is not a known key") != std::string::npos &&
      loaded.error().message.rfind(axis.place + ":", 0) == 0)
    throw SweepFailure{loaded.error().message};
  // ("must be a list of two numbers, not '0.5'" for every row otherwise)
  const YAML::Node listed = key_path.index ? YAML::Node() : find(base_tree, key_path);
  if (!loaded && listed.IsSequence() && YAML::Load(axis.values.front()).IsScalar())
    throw SweepFailure{where + " is a list (the base scene's is " + flowText(listed) +
                       "): give lists as its values, e.g. [" + flowText(listed) +
                       "], or vary one element, as " + axis.key + "[0]"};
}

// One entry of `vary`: its key checked against the base scene, and its values.
SweepAxis readAxis(const YAML::Node& key_node, const YAML::Node& spec, const YAML::Node& base_tree,
                   const Sweep& sweep, SweepText& in, std::set<std::string>& keys) {
  SweepAxis axis;
  axis.key = key_node.as<std::string>();
  axis.place = in.at(key_node);
  in.reading(key_node, axis.key);
  const std::string where = axis.place + ": " + axis.key;
  const auto key_path = splitKey(axis.key);
  if (!key_path)
    throw SweepFailure{where +
                       " is not a scene key (dotted, e.g. contact.air_drag or body.dents.at[0])"};
  if (!keys.insert(axis.key).second) throw SweepFailure{where + " is varied twice"};
  if (key_path->parts.front() == "video")
    throw SweepFailure{where + ": a sweep only simulates; video keys do not change a run"};
  // Axes that change the compiled body: its keys, the units, and the contact model (which picks
  // the mass properties' source when the body does not name one).
  axis.body = key_path->parts.front() == "body" || key_path->parts.front() == "units" ||
              axis.key == "contact.model";
  axis.values = axisValues(spec, where, base_tree, *key_path, axis, sweep);
  checkAxisKey(axis, *key_path, base_tree, sweep, where);
  return axis;
}

// A sweep's keys from its text: the base from `base:` (a file, relative to the sweep file's
// folder) or, for a sweep made without a file, from `given`; `lines`: whether messages name the
// text's lines (a file's) or the name alone (Python's argument).
rb::Result<Sweep> parseSweep(const std::string& text, const std::string& path, bool lines,
                             const SweepBase* given) {
  Sweep sweep;
  sweep.file = path;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return malformedYaml(path, text, e);
  }
  SweepText in{path, lines};
  try {
    const SweepKeys k = sweepKeys(root, in, given != nullptr);
    YAML::Node base_tree;
    if (given)
      givenBase(sweep, *given);
    else
      fileBase(sweep, root, k, in, base_tree);
    if (k.has_duration) {
      in.reading(k.duration_key, "duration");
      const double d = number(k.duration, in.at(k.duration_key) + ":", "duration");
      if (!(d > 0)) throw SweepFailure{in.at(k.duration_key) + ": duration must be above 0 s"};
      sweep.duration = d;
    }
    if (k.has_columns) {
      in.reading(k.columns_key, "columns");
      sweep.columns = columnNames(k.columns, in.at(k.columns_key), {path, 0, "columns"}, lines);
    }
    if (k.has_vary)
      in.reading(k.vary_key, "vary");
    else
      in.readingTop("vary");
    if (!k.has_vary || !k.vary.IsMap() || k.vary.size() == 0)
      throw SweepFailure{(k.has_vary ? in.at(k.vary_key) : in.top()) +
                         ": vary must map scene keys to their values, e.g. initial.spin: [-5, 5]"};

    if (given) base_tree = YAML::Load(sweep.base_text);
    if (!base_tree.IsDefined() || base_tree.IsNull()) base_tree = YAML::Node(YAML::NodeType::Map);
    for (const KeyValue& kv : sweep.base_values)
      put(base_tree, *splitKey(kv.key), 0, YAML::Load(kv.yaml));
    std::set<std::string> keys;
    double runs = 1;
    for (const auto& entry : k.vary) {
      SweepAxis axis = readAxis(entry.first, entry.second, base_tree, sweep, in, keys);
      runs *= static_cast<double>(axis.values.size());
      if (runs > static_cast<double>(kMaxRows))
        throw SweepFailure{axis.place + ": " + axis.key + ": the axes so far make " +
                           rangeValue(runs) + " runs; at most 1e8 in one sweep (split it)"};
      sweep.axes.push_back(std::move(axis));
    }
  } catch (const SweepFailure& f) {
    return sweepError(f.message, f.where.value_or(in.place));
  } catch (const YAML::Exception& e) {
    const int line = e.mark.is_null() ? 1 : e.mark.line + 1;
    return sweepError((lines ? path + ":" + std::to_string(line) : path) + ": " + e.msg,
                      {path, lines ? line : 0, in.place.key});
  }
  return sweep;
}

}  // namespace

rb::Result<Sweep> loadSweep(const std::string& path) {
  std::error_code ec;
  const rb::Error::Where file{path, 0, ""};
  if (std::filesystem::is_directory(path, ec))
    return sweepError(path +
                          ": is a folder, not a sweep file (give a .yaml file, e.g. "
                          "sweeps/spin-drag.yaml)",
                      file);
  if (!std::filesystem::exists(path, ec)) return sweepError(path + ": no such sweep file", file);
  std::ifstream in(path, std::ios::binary);
  if (!in) return sweepError(path + ": cannot open the sweep file", file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parseSweep(text, path, true, nullptr);
}

rb::Result<Sweep> loadSweepText(const std::string& yaml, const std::string& name,
                                const SweepBase& base) {
  return parseSweep(yaml, name, false, &base);
}

}  // namespace scene

// The text of a scene or sweep file before it is a tree: reading it, its YAML errors named at
// the line a reader would fix, and any text made safe to print on one line.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "scene/loader.hpp"
#include "scene/tree.hpp"
#include "util/assets.hpp"
#include "util/nearest.hpp"

namespace scene {

std::string printable(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (c == '\n')
      out += "\\n";
    else if (c == '\t')
      out += "\\t";
    else if (c == '\r')
      out += "\\r";
    else if (c < 0x20 || c == 0x7f) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string yamlContent(const std::string& text) {
  try {
    return YAML::Dump(YAML::Load(text));
  } catch (const YAML::Exception&) {
    return text;
  }
}

int unclosedFlowLine(const std::string& text) {
  std::vector<int> open;  // the lines of the brackets not yet closed
  int line = 1;
  char quote = 0;
  bool comment = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      comment = false;
      if (quote == '\'') quote = 0;  // a single-quoted scalar on one line, as scenes write them
      continue;
    }
    if (comment) continue;
    if (quote) {
      if (c == quote && !(quote == '"' && i > 0 && text[i - 1] == '\\')) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(text[i - 1])))) {
      comment = true;
    } else if (c == '{' || c == '[') {
      open.push_back(line);
    } else if ((c == '}' || c == ']') && !open.empty()) {
      open.pop_back();
    }
  }
  return open.empty() ? 0 : open.back();
}

rb::Error malformedYaml(const std::string& name, const std::string& text,
                        const YAML::Exception& e) {
  int line = e.mark.is_null() ? 1 : e.mark.line + 1;
  std::string message = e.msg;
  if (e.msg.find("flow not found") != std::string::npos)
    if (const int opened = unclosedFlowLine(text); opened > 0) {
      line = opened;
      message = "a { or [ on this line is never closed (" + e.msg + ")";
    }
  // A ] or } that closes the other kind of bracket, or none (`tilt: [0.5, 0.5}`, a ] left out
  // inside a { … }): yaml-cpp's "illegal flow end" says neither.
  if (e.msg == YAML::ErrorMsg::FLOW_END)
    message =
        "a ] or } on this line does not close the bracket open before it (a [ closes with "
        "], a { with }: is one left out?) (" +
        e.msg + ")";
  // A tab in the indentation: yaml-cpp names what it then misreads ("illegal map value").
  int at = 1;
  for (std::size_t start = 0; start < text.size() && at <= line; ++at) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::size_t first = text.find_first_not_of(' ', start);
    if (first < end && text[first] == '\t') {
      line = at;
      message = "a tab in this line's indentation: YAML indents with spaces only (" + e.msg + ")";
      break;
    }
    start = end + 1;
  }
  // yaml-cpp's words for a key off its column or a line without its colon say neither ("end of map
  // not found"): the usual causes, where the parser noticed.
  if (message == e.msg && (e.msg.find("end of map not found") != std::string::npos ||
                           e.msg.find("illegal map value") != std::string::npos))
    message +=
        " (at or just above this line: a key indented unlike its neighbours, or a key "
        "without its colon, key: value)";
  rb::Error error{"",
                  printable(name + ":" + std::to_string(line) + ": malformed YAML: " + message)};
  error.where = rb::Error::Where{name, line, ""};
  return error;
}

// The names of the files in `folder` (the first 1,000), each after `prefix`.
static std::vector<std::string> filesIn(const std::filesystem::path& folder,
                                        const std::string& prefix = "") {
  std::vector<std::string> files;
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(folder, ec);
       !ec && it != std::filesystem::directory_iterator() && files.size() < 1000; it.increment(ec))
    if (it->is_regular_file(ec)) files.push_back(prefix + it->path().filename().string());
  return files;
}

// The YAML file of `files` (each after `prefix`) whose name without its extension is nearest
// `name`'s: base.yml finds base.yaml. Whole names, sharing ".yaml" and "scenes/", had let a
// third of their length count as typos (nope.yaml found tap-end.yaml, mine.yaml printed.yaml).
static std::optional<std::string> nearestFile(const std::string& name,
                                              const std::vector<std::string>& files,
                                              const std::string& prefix = "") {
  std::vector<std::string> stems, names;
  for (const std::string& file : files) {
    const std::filesystem::path f(file.substr(prefix.size()));
    if (f.extension() != ".yaml" && f.extension() != ".yml") continue;
    stems.push_back(f.stem().string());
    names.push_back(file);
  }
  const std::optional<std::string> near =
      rb::nearestWord(std::filesystem::path(name).stem().string(), stems);
  if (!near) return std::nullopt;
  return names[static_cast<std::size_t>(std::find(stems.begin(), stems.end(), *near) -
                                        stems.begin())];
}

rb::Result<std::string> readSceneFile(const std::string& path) {
  std::error_code ec;
  auto fail = [&](const std::string& message) {
    rb::Error e{"", printable(path) + ": " + message};
    e.where = rb::Error::Where{path, 0, ""};
    return e;
  };
  if (std::filesystem::is_directory(path, ec))
    return fail("is a folder, not a scene file (give a .yaml file, e.g. scenes/rattleback.yaml)");
  // A mesh given where a scene goes (rattleback analyze toy.stl): a scene names it.
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".stl" || ext == ".obj" || ext == ".ply")
    return fail(
        "is a mesh, not a scene: write a scene that names it, body: {shape: mesh, mesh: "
        "{file: " +
        std::filesystem::path(path).filename().string() +
        "}, mass: …} (docs/your-own-body.md), or copy scenes/printed.yaml");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int error = errno;
    // A file of a near name beside it: "did you mean base.yaml?" (a teacher typed base.yml).
    std::string near;
    if (error == ENOENT) {
      const std::filesystem::path named(path);
      std::filesystem::path folder = named.has_parent_path() ? named.parent_path() : ".";
      // A relative name whose folder is not here may be a shipped scene's, mistyped
      // (scenes/ratleback.yaml from a folder of one's own): its near names are the shipped ones.
      const bool shipped_name = named.is_relative() && !path.starts_with("./") &&
                                !path.starts_with("../") &&
                                !std::filesystem::is_directory(folder, ec);
      if (shipped_name) folder = std::filesystem::path(rb::assetsDir()) / folder;
      std::optional<std::string> nearest = nearestFile(named.filename().string(), filesIn(folder));
      // A bare name not here, which a shipped scene has (rattleback.yaml for
      // scenes/rattleback.yaml): the shipped one, with its folder.
      const bool bare = !named.has_parent_path() && !nearest;
      if (bare)
        nearest = nearestFile(named.filename().string(),
                              filesIn(std::filesystem::path(rb::assetsDir()) / "scenes", "scenes/"),
                              "scenes/");
      if (nearest)
        near = "; did you mean " + printable((named.parent_path() / *nearest).string()) +
               (shipped_name || bare ? " (a shipped scene, found by name from any folder)?" : "?");
      // A relative name read from elsewhere than the user thought: say where it was looked
      // for, and that the shipped scenes are found by name from any folder only where
      // rattleback is installed (a build tree's Python did not find scenes/rattleback.yaml
      // from another folder). ./ and ../ name this folder's only, as the user meant.
      else if (named.is_relative() && !path.starts_with("./") && !path.starts_with("../"))
        near = " (looked for in " + printable(std::filesystem::current_path(ec).string()) +
               "; an installed rattleback also finds its shipped scenes/… and sweeps/… by name "
               "from any folder: else give the file's full path)";
    }
    return fail(std::string("cannot open the scene file: ") + std::strerror(error) + near);
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return fail(std::string("cannot read the scene file: ") + std::strerror(errno));
  return text.str();
}

}  // namespace scene

#include "scene/mesh_file.hpp"

// The library's implementation is compiled here, in double precision (scene/CMakeLists.txt).
#define TINYOBJLOADER_USE_DOUBLE
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "util/format.hpp"

namespace scene {
namespace {

rb::Error fileError(std::string_view name, const std::string& message) {
  return rb::Error{"", std::string(name) + ": " + message};
}

// A position's bits, −0 made +0 (adding 0.0 does), mixed (splitmix64's finaliser) into a slot.
std::uint64_t hashOf(const Eigen::Vector3d& p) {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    h ^= std::bit_cast<std::uint64_t>(p[i] + 0.0) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    h ^= h >> 31;
  }
  return h;
}

std::size_t slotsFor(std::size_t n) {
  return std::bit_ceil(std::max<std::size_t>(16, 2 * n));
}

}  // namespace

VertexWelder::VertexWelder(std::size_t expected_corners)
    // A closed mesh has about a sixth as many vertices as corners: a third of the corners fill
    // the table at most half.
    : slots_(slotsFor(expected_corners / 3), -1), mask_(slots_.size() - 1) {
  mesh_.vertices.reserve(expected_corners / 5);
  mesh_.faces.reserve(expected_corners / 3);
}

int VertexWelder::add(const Eigen::Vector3d& p) {
  if (2 * mesh_.vertices.size() >= slots_.size()) {  // half full: twice the slots
    slots_.assign(2 * slots_.size(), -1);
    mask_ = slots_.size() - 1;
    for (std::size_t i = 0; i < mesh_.vertices.size(); ++i) {
      std::size_t s = hashOf(mesh_.vertices[i]) & mask_;
      while (slots_[s] >= 0) s = (s + 1) & mask_;
      slots_[s] = static_cast<int>(i);
    }
  }
  std::size_t s = hashOf(p) & mask_;
  for (; slots_[s] >= 0; s = (s + 1) & mask_)
    if (mesh_.vertices[slots_[s]] == p) return slots_[s];  // == takes −0 for +0
  slots_[s] = static_cast<int>(mesh_.vertices.size());
  mesh_.vertices.push_back(p);
  return slots_[s];
}

namespace {

std::string tooMany(std::int64_t triangles) {
  return "holds " + rb::show(static_cast<double>(triangles)) + " triangles, more than the " +
         rb::show(static_cast<double>(kMaxMeshTriangles)) +
         " memory allows (about 120 bytes each): decimate it (Blender: the Decimate modifier)";
}

// Binary STL: an 80-byte header, a 32-bit little-endian count, then 50 bytes a triangle (normal,
// three corners as 32-bit floats, two bytes of attributes). The normal is not read: the winding
// says which way a face looks (sim/mesh.hpp).
rb::Result<sim::TriangleMesh> parseBinaryStl(std::string_view bytes, std::string_view name,
                                             std::uint32_t count) {
  if (count > kMaxMeshTriangles) return fileError(name, tooMany(count));
  VertexWelder welder(3 * static_cast<std::size_t>(count));
  const char* at = bytes.data() + 84;
  for (std::uint32_t t = 0; t < count; ++t, at += 50) {
    float corners[9];
    std::memcpy(corners, at + 12, sizeof corners);
    std::array<int, 3> face{};
    for (int k = 0; k < 3; ++k)
      face[k] = welder.add(Eigen::Vector3d(corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]));
    welder.mesh().faces.push_back(face);
  }
  return std::move(welder.mesh());
}

// ASCII STL, token by token: "vertex x y z" three times a facet; the other words of the format
// (facet, normal and its numbers, outer loop, endloop, endfacet, and solid and endsolid with
// their names) are skipped, and a word that is none of them is named at its line: a misspelt
// "vertx" had been skipped too, and said only at the facet's end as a facet of two vertices.
// Lines are counted for messages.
class StlText {
 public:
  StlText(std::string_view text, std::string_view name) : text_(text), name_(name) {}
  rb::Result<sim::TriangleMesh> parse();

 private:
  std::string_view next();
  void skipLine();
  std::string_view text_, name_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

std::string_view StlText::next() {
  while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
    line_ += text_[pos_++] == '\n';
  const std::size_t start = pos_;
  while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
  return text_.substr(start, pos_ - start);
}

// The rest of the line: a solid's name, which may be any words.
void StlText::skipLine() {
  while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

// The words of ASCII STL other than "vertex", which parse() skips.
bool skippedStlWord(std::string_view word) {
  for (std::string_view known : {"facet", "outer", "loop", "endloop", "endfacet"})
    if (word == known) return true;
  return false;
}

rb::Result<sim::TriangleMesh> StlText::parse() {
  // The shortest facet ("facet normal 0 0 0 outer loop vertex 0 0 0 …") is about 100 bytes.
  if (static_cast<std::int64_t>(text_.size() / 100) > kMaxMeshTriangles)
    return fileError(name_, tooMany(static_cast<std::int64_t>(text_.size() / 100)));
  VertexWelder welder(text_.size() / 40);
  std::array<int, 3> face{};
  int corners = 0;
  for (std::string_view word = next(); !word.empty(); word = next()) {
    if (word == "endloop" || word == "endfacet") {
      if (corners != 0)
        return fileError(name_, "line " + std::to_string(line_) + ": a facet with " +
                                    std::to_string(corners) + " vertices; STL facets have three");
      continue;
    }
    if (word == "solid" || word == "endsolid") {
      skipLine();
      continue;
    }
    if (word == "normal") {  // its numbers (three, or none from some exporters): not needed
      for (int i = 0; i < 3; ++i) {
        const std::size_t pos = pos_;
        const int line = line_;
        const std::string_view number = next();
        if (number == "vertex" || skippedStlWord(number)) {  // a word: read it next
          pos_ = pos, line_ = line;
          break;
        }
      }
      continue;
    }
    if (skippedStlWord(word)) continue;
    if (word != "vertex")
      return fileError(name_, "line " + std::to_string(line_) + ": '" +
                                  std::string(word.substr(0, 20)) +
                                  "' is not a word of ASCII STL (solid, facet normal, outer loop, "
                                  "vertex, endloop, endfacet, endsolid); is the file damaged? "
                                  "export it again");
    Eigen::Vector3d p;
    for (int i = 0; i < 3; ++i) {
      const std::string_view number = next();
      if (number.empty())
        return fileError(name_, "ends inside a vertex (line " + std::to_string(line_) +
                                    "): the file is truncated; export it again");
      const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), p[i]);
      if (ec != std::errc() || end != number.data() + number.size())
        return fileError(name_, "line " + std::to_string(line_) + ": a vertex coordinate '" +
                                    std::string(number.substr(0, 20)) +
                                    "' is not a number; is the file complete?");
    }
    face[corners++] = welder.add(p);
    if (corners == 3) {
      welder.mesh().faces.push_back(face);
      corners = 0;
    }
  }
  if (corners != 0)
    return fileError(name_, "ends inside a facet (line " + std::to_string(line_) +
                                "): the file is truncated; export it again");
  return std::move(welder.mesh());
}

rb::Result<sim::TriangleMesh> parseStl(std::string_view bytes, std::string_view name) {
  if (bytes.size() >= 84) {
    std::uint32_t count;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::uint64_t>(count))
      return parseBinaryStl(bytes, name, count);
  }
  if (bytes.substr(0, 5) == "solid" && bytes.find("facet") != std::string_view::npos)
    return StlText(bytes, name).parse();
  // Text throughout its start (no byte below a space but tab and line ends; a binary STL's count
  // and coordinates have them within their first triangles): a notes file, or an ASCII STL that
  // lists no triangles, is said to be text rather than measured as a binary one.
  const std::string_view start = bytes.substr(0, 4096);
  const bool text = std::all_of(start.begin(), start.end(), [](char c) {
    return static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r';
  });
  if (text && !bytes.empty())
    return fileError(name, bytes.substr(0, 5) == "solid"
                               ? "is an ASCII STL with no triangles (no 'facet'): export it again"
                               : "is text, not an STL (an ASCII STL begins with 'solid' and lists "
                                 "each triangle as 'facet … endfacet'): is it an STL file?");
  if (bytes.size() < 84)
    return fileError(name, "is " + std::to_string(bytes.size()) +
                               " bytes, too short for a binary STL (84 at least) and not an "
                               "ASCII one (\"solid …\"): is it an STL file?");
  std::uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  return fileError(name, "a binary STL of " + std::to_string(count) + " triangles is " +
                             std::to_string(84 + 50 * static_cast<std::uint64_t>(count)) +
                             " bytes, but the file has " + std::to_string(bytes.size()) +
                             ": it is truncated or not an STL file; export it again");
}

// The first line of tinyobjloader's message (it can hold several).
std::string firstLine(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// OBJ through tinyobjloader, its polygons cut into triangles; materials are not read.
rb::Result<sim::TriangleMesh> parseObj(std::string_view bytes, std::string_view name) {
  if (static_cast<std::int64_t>(bytes.size() / 20) > kMaxMeshTriangles)  // "f 1 2 3\n" and a vertex
    return fileError(name, tooMany(static_cast<std::int64_t>(bytes.size() / 20)));
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(std::string(bytes), "", config))
    return fileError(name, firstLine(reader.Error()) + " (as OBJ): is the file complete?");
  const std::vector<tinyobj::real_t>& xyz = reader.GetAttrib().vertices;
  std::size_t corners = 0;
  for (const auto& shape : reader.GetShapes()) corners += shape.mesh.indices.size();
  VertexWelder welder(corners);
  for (const auto& shape : reader.GetShapes()) {
    const auto& indices = shape.mesh.indices;
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
      std::array<int, 3> face{};
      for (int k = 0; k < 3; ++k) {
        const auto v = static_cast<std::size_t>(indices[i + k].vertex_index);
        if (3 * v + 2 >= xyz.size())
          return fileError(name, "a face names vertex " + std::to_string(v + 1) + " of " +
                                     std::to_string(xyz.size() / 3) + ": the file is damaged");
        face[k] = welder.add(Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
      }
      welder.mesh().faces.push_back(face);
    }
  }
  return std::move(welder.mesh());
}

}  // namespace

rb::Result<MeshFormat> meshFormatOf(std::string_view path) {
  std::string ext(path.substr(std::min(path.size(), path.rfind('.'))));
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".stl") return MeshFormat::Stl;
  if (ext == ".obj") return MeshFormat::Obj;
  return fileError(path,
                   "is not a mesh file the program reads: give an .stl (binary or ASCII) "
                   "or an .obj file");
}

rb::Result<sim::TriangleMesh> parseMesh(std::string_view bytes, std::string_view name,
                                        MeshFormat format) {
  return format == MeshFormat::Stl ? parseStl(bytes, name) : parseObj(bytes, name);
}

std::string binaryStl(const sim::TriangleMesh& mesh, double scale, std::string_view header) {
  static_assert(std::endian::native == std::endian::little, "STL's numbers are little-endian");
  std::string out(84 + 50 * mesh.faces.size(), '\0');
  std::string text(header.substr(0, 80));
  text.resize(80, ' ');
  std::memcpy(out.data(), text.data(), 80);
  const auto count = static_cast<std::uint32_t>(mesh.faces.size());
  std::memcpy(out.data() + 80, &count, 4);
  char* at = out.data() + 84;
  for (const auto& face : mesh.faces) {
    Eigen::Vector3f corner[3];
    for (int k = 0; k < 3; ++k)
      corner[k] =
          (mesh.vertices[static_cast<std::size_t>(face[static_cast<std::size_t>(k)])] * scale)
              .cast<float>();
    Eigen::Vector3f normal = (corner[1] - corner[0]).cross(corner[2] - corner[0]);
    if (normal.norm() > 0) normal.normalize();
    std::memcpy(at, normal.data(), 12);
    for (int k = 0; k < 3; ++k) std::memcpy(at + 12 + 12 * k, corner[k].data(), 12);
    at += 50;  // the last two bytes, the "attribute byte count", stay 0
  }
  return out;
}

rb::Result<sim::TriangleMesh> readMesh(const std::string& path) {
  auto format = meshFormatOf(path);
  if (!format) return format.error();
  // Memory, estimated from the size before reading: a triangle takes at least 50 bytes of a
  // binary STL and 8 of an OBJ ("f 1 2 3" and its line's end).
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec &&
      static_cast<double>(size) / (format.value() == MeshFormat::Stl ? 50 : 8) > kMaxMeshTriangles)
    return fileError(
        path,
        tooMany(static_cast<std::int64_t>(size / (format.value() == MeshFormat::Stl ? 50 : 8))));
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             std::fclose);
  if (!file) return fileError(path, std::string("cannot be read: ") + std::strerror(errno));
  std::string bytes;
  if (!ec) bytes.reserve(size);
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0;)
    bytes.append(buffer, n);
  if (std::ferror(file.get()))
    return fileError(path, std::string("cannot be read: ") + std::strerror(errno));
  return parseMesh(bytes, path, format.value());
}

}  // namespace scene

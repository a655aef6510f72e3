// Reading a body's mesh from a file a scene names (body.mesh.file): binary and ASCII STL by our
// own reader, OBJ through tinyobjloader (Debian's libtinyobjloader-dev). Identical vertices are
// welded (STL repeats each corner in every triangle it belongs to), so that the edges can be
// checked (sim/mesh.hpp checkMesh). Nothing else about the mesh is changed.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "sim/mesh.hpp"
#include "util/result.hpp"

namespace scene {

enum class MeshFormat { Stl, Obj };

/// The most triangles a file may hold: each costs about 120 bytes while it is read, welded and
/// checked, so 2e7 is 2.4 GB. Estimated from the file's size before reading.
inline constexpr std::int64_t kMaxMeshTriangles = 20'000'000;

/// The format of a file by its extension (.stl, .obj, any case), or an error naming the file.
rb::Result<MeshFormat> meshFormatOf(std::string_view path);

/// The mesh in `bytes`, a file's contents; `name` (the file) starts every message. STL is read as
/// binary when its size is exactly 84 + 50 × its triangle count, else as ASCII when it starts with
/// "solid". Messages: one line, naming the file, the cause and the way out.
rb::Result<sim::TriangleMesh> parseMesh(std::string_view bytes, std::string_view name,
                                        MeshFormat format);

/// Reads and parses the file at `path` (its format by its extension).
rb::Result<sim::TriangleMesh> readMesh(const std::string& path);

/// The mesh as binary STL, every coordinate multiplied by `scale` (the file's units per vertex
/// unit) and rounded to single precision as the format has it; each facet's normal is that of its
/// rounded corners. `header` fills the 80-byte header (cut or padded with spaces): STL has no
/// unit, so the header is where a reader of the file can see it.
std::string binaryStl(const sim::TriangleMesh& mesh, double scale, std::string_view header);

/// Triangles given corner by corner (three positions a face) as a mesh with each distinct
/// position once: two corners are one vertex when their coordinates are equal to the bit (−0 and
/// +0 alike).
class VertexWelder {
 public:
  explicit VertexWelder(std::size_t expected_corners);
  /// The index of `p`, new or found.
  int add(const Eigen::Vector3d& p);
  sim::TriangleMesh& mesh() { return mesh_; }

 private:
  std::vector<int> slots_;  // open addressing: −1 empty, else a vertex index
  std::size_t mask_;
  sim::TriangleMesh mesh_;
};

}  // namespace scene

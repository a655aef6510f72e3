#include "sim/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include "util/format.hpp"

namespace sim {
namespace {

using rb::show;

std::string at(const Eigen::Vector3d& p) {
  // Appended piece by piece: GCC 12's -Wrestrict misreads "(" + std::string.
  std::string out = "(";
  out += show(p.x());
  out += ", ";
  out += show(p.y());
  out += ", ";
  out += show(p.z());
  return out += ")";
}

}  // namespace

Eigen::AlignedBox3d meshBounds(const TriangleMesh& mesh) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices) box.extend(v);
  return box;
}

// Each face and the origin o span a tetrahedron whose signed volume is d/6, d = a·(b × c) with
// a, b, c the corners relative to o; the signed tetrahedra of a closed surface add up to the
// solid (the divergence theorem, docs/physics.md eq. P11.1). Over a tetrahedron with one corner at
// o, ∫r dV = (d/24)(a + b + c) and ∫r rᵀ dV = (d/120)(a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a + b + c.
// The origin is taken at the box's centre so that a mesh far from zero loses no digits.
MeshMoments meshMoments(const TriangleMesh& mesh) {
  MeshMoments m;
  if (mesh.vertices.empty()) return m;
  m.origin = meshBounds(mesh).center();
  double six_volume = 0;
  Eigen::Vector3d first24 = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second120 = Eigen::Matrix3d::Zero();
  for (const auto& f : mesh.faces) {
    const Eigen::Vector3d a = mesh.vertices[f[0]] - m.origin;
    const Eigen::Vector3d b = mesh.vertices[f[1]] - m.origin;
    const Eigen::Vector3d c = mesh.vertices[f[2]] - m.origin;
    const double d = a.dot(b.cross(c));
    const Eigen::Vector3d s = a + b + c;
    six_volume += d;
    first24 += d * s;
    second120 +=
        d * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  m.volume = six_volume / 6;
  m.first = first24 / 24;
  m.second = second120 / 120;
  return m;
}

// CM = o + ∫r dV / V; covariance C = ∫r rᵀ dV / V − (CM − o)(CM − o)ᵀ; I = M (tr C · 1 − C), the
// same step as PointMoments::properties.
MassProperties meshMassProperties(const TriangleMesh& mesh, double mass) {
  const MeshMoments m = meshMoments(mesh);
  MassProperties out;
  out.mass = mass;
  const Eigen::Vector3d c = m.first / m.volume;
  out.com = m.origin + c;
  const Eigen::Matrix3d cov = m.second / m.volume - c * c.transpose();
  out.inertia = mass * (cov.trace() * Eigen::Matrix3d::Identity() - cov);
  principalAxes(out);
  return out;
}

namespace {

std::optional<MeshProblem> checkIndices(const TriangleMesh& mesh, std::string_view name) {
  const std::string file(name);
  if (mesh.faces.empty())
    return MeshProblem{MeshFault::Empty,
                       file + ": the mesh has no triangles: is it the file you meant?"};
  const auto n = static_cast<std::int64_t>(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.faces.size(); ++i)
    for (int v : mesh.faces[i])
      if (v < 0 || v >= n)
        return MeshProblem{MeshFault::BadIndex, file + ": face " + std::to_string(i + 1) +
                                                    " names vertex " + std::to_string(v + 1) +
                                                    " of " + std::to_string(n) +
                                                    ": the file is damaged; export it again"};
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite())
      return MeshProblem{MeshFault::NotFinite,
                         file + ": vertex " + std::to_string(i + 1) +
                             " has a coordinate that is not a finite number: export it again"};
  return std::nullopt;
}

// A face is degenerate when its area is below 1e-12 of the square of the box's diagonal: a
// sliver that thin is rounding, not shape (float coordinates carry 7 digits).
std::optional<MeshProblem> checkAreas(const TriangleMesh& mesh, std::string_view name) {
  const double diagonal = meshBounds(mesh).diagonal().norm();
  const double least = 1e-12 * diagonal * diagonal;
  std::int64_t count = 0;
  std::size_t first = 0;
  for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
    const auto& f = mesh.faces[i];
    const Eigen::Vector3d& a = mesh.vertices[f[0]];
    const double area = 0.5 * (mesh.vertices[f[1]] - a).cross(mesh.vertices[f[2]] - a).norm();
    if (!(area > least) && count++ == 0) first = i;
  }
  if (count == 0) return std::nullopt;
  return MeshProblem{MeshFault::Degenerate,
                     std::string(name) + ": " + rb::counted(count, "face") +
                         " of zero area (the first, face " + std::to_string(first + 1) + ", at " +
                         at(mesh.vertices[mesh.faces[first][0]]) +
                         "): remove them (Blender: Mesh > Clean Up > Degenerate Dissolve) and "
                         "export again"};
}

// Every edge of a closed surface wound one way has exactly two faces, which walk it in opposite
// directions. Each face edge u→v becomes one number: (min, max) in the high bits, the direction
// (u > v) in the lowest; sorted, an edge's uses sit together.
struct EdgeCensus {
  std::int64_t open = 0, crowded = 0, same_way = 0;
  std::array<int, 2> open_edge{}, crowded_edge{}, same_way_edge{};
};

EdgeCensus edgeCensus(const TriangleMesh& mesh) {
  std::vector<std::uint64_t> uses;
  uses.reserve(3 * mesh.faces.size());
  for (const auto& f : mesh.faces)
    for (int k = 0; k < 3; ++k) {
      const auto u = static_cast<std::uint64_t>(f[k]),
                 v = static_cast<std::uint64_t>(f[(k + 1) % 3]);
      uses.push_back(((std::min(u, v) << 32 | std::max(u, v)) << 1) | (u > v ? 1 : 0));
    }
  std::sort(uses.begin(), uses.end());
  EdgeCensus census;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && (uses[j] >> 1) == (uses[i] >> 1)) ++j;
    const std::array<int, 2> edge = {static_cast<int>(uses[i] >> 33),
                                     static_cast<int>((uses[i] >> 1) & 0xffffffffu)};
    if (j - i == 1 && census.open++ == 0) census.open_edge = edge;
    if (j - i > 2 && census.crowded++ == 0) census.crowded_edge = edge;
    if (j - i == 2 && (uses[i] & 1) == (uses[i + 1] & 1) && census.same_way++ == 0)
      census.same_way_edge = edge;
    i = j;
  }
  return census;
}

std::optional<MeshProblem> checkEdges(const TriangleMesh& mesh, std::string_view name) {
  const EdgeCensus e = edgeCensus(mesh);
  const auto edge = [&](const std::array<int, 2>& ends) {
    return "from " + at(mesh.vertices[ends[0]]) + " to " + at(mesh.vertices[ends[1]]);
  };
  const std::string file(name);
  if (e.open > 0)
    return MeshProblem{MeshFault::Open,
                       file + ": the mesh is not closed: " + rb::counted(e.open, "open edge") +
                           " (one " + edge(e.open_edge) +
                           "); a solid needs a closed surface: fill the holes (Blender: Select "
                           "> All by Trait > Non Manifold, then Face > Fill) and export again"};
  if (e.crowded > 0)
    return MeshProblem{MeshFault::NonManifold,
                       file + ": " + rb::counted(e.crowded, "edge") +
                           " shared by three faces or more (one " + edge(e.crowded_edge) +
                           ") (a face given twice, or parts touching along an edge): delete "
                           "duplicate faces, or join the parts into one solid (Blender: a Union "
                           "boolean)"};
  if (e.same_way > 0)
    return MeshProblem{MeshFault::Inconsistent,
                       file +
                           ": faces are wound inconsistently: " + rb::counted(e.same_way, "edge") +
                           " walked the same way by both its faces (one " + edge(e.same_way_edge) +
                           "): recalculate the normals (Blender: Mesh > Normals > Recalculate "
                           "Outside) and export again"};
  return std::nullopt;
}

// The pieces of a closed mesh wound outwards, by the faces' shared corners: each piece's signed
// volume and one of its corners. A piece of negative volume is a cavity inside another (a hollow
// body, wound inwards as a cavity's surface is); two pieces of positive volume are two solids.
std::optional<MeshProblem> checkPieces(const TriangleMesh& mesh, std::string_view name) {
  std::vector<int> root(mesh.vertices.size());
  for (std::size_t i = 0; i < root.size(); ++i) root[i] = static_cast<int>(i);
  const auto find = [&](int v) {
    while (root[static_cast<std::size_t>(v)] != v)
      v = root[static_cast<std::size_t>(v)] =
          root[static_cast<std::size_t>(root[static_cast<std::size_t>(v)])];
    return v;
  };
  for (const auto& f : mesh.faces)
    for (int k = 1; k < 3; ++k) root[static_cast<std::size_t>(find(f[k]))] = find(f[0]);
  std::map<int, double> volume;  // piece (its root) → 6 × signed volume
  for (const auto& f : mesh.faces)
    volume[find(f[0])] += mesh.vertices[f[0]].dot(mesh.vertices[f[1]].cross(mesh.vertices[f[2]]));
  std::vector<int> solids;
  for (const auto& [piece, v6] : volume)
    if (v6 > 0) solids.push_back(piece);
  if (solids.size() < 2) return std::nullopt;
  return MeshProblem{
      MeshFault::Pieces,
      std::string(name) + ": the mesh is " + std::to_string(solids.size()) +
          " separate solids (one at " + at(mesh.vertices[static_cast<std::size_t>(solids[0])]) +
          ", another at " + at(mesh.vertices[static_cast<std::size_t>(solids[1])]) +
          "), not one body: keep one per file (Blender: Mesh > Separate > By Loose Parts) or "
          "join them into one solid (a Union boolean)"};
}

// The candidates a user's file is most likely in, m per unit, and their names.
struct UnitGuess {
  double metres;
  const char* name;
};
constexpr UnitGuess kUnits[] = {{0.001, "mm"}, {0.01, "cm"}, {0.0254, "inches"}, {1.0, "m"}};

std::optional<MeshProblem> checkSize(const TriangleMesh& mesh, std::string_view name, double unit) {
  const double length = meshBounds(mesh).sizes().maxCoeff();  // file units
  const double metres = length * unit;
  if (metres >= kHandMin && metres <= kHandMax) return std::nullopt;
  // The unit that makes it nearest a 10 cm toy, in ratio.
  const UnitGuess* best = nullptr;
  for (const UnitGuess& u : kUnits)
    if (!best || std::abs(std::log(length * u.metres / 0.1)) <
                     std::abs(std::log(length * best->metres / 0.1)))
      best = &u;
  std::string message = std::string(name) + ": the mesh is " + show(length) + " units long, so " +
                        show(metres) + " m with units.length: " + show(unit) +
                        ", not a size a hand holds (" + show(kHandMin) + " … " + show(kHandMax) +
                        " m)";
  const double fixed = length * best->metres;
  if (best->metres != unit && fixed >= kHandMin && fixed <= kHandMax)
    message += ": in " + std::string(best->name) + "? units.length: " + show(best->metres) +
               " makes it " + show(fixed) + " m";
  return MeshProblem{MeshFault::WrongSize, message};
}

}  // namespace

std::optional<MeshProblem> checkMesh(const TriangleMesh& mesh, std::string_view name, double unit) {
  if (auto p = checkIndices(mesh, name)) return p;
  if (auto p = checkAreas(mesh, name)) return p;
  if (auto p = checkEdges(mesh, name)) return p;
  // Closed and wound one way: the volume's sign says whether that way is outwards.
  const double volume = meshMoments(mesh).volume;
  if (!(volume > 0))
    return MeshProblem{MeshFault::InsideOut,
                       std::string(name) +
                           ": the mesh is inside out: its faces wind inwards "
                           "(signed volume " +
                           show(volume) +
                           " cubic units); flip them (Blender: Mesh > Normals > Flip) and "
                           "export again"};
  if (auto p = checkPieces(mesh, name)) return p;
  return checkSize(mesh, name, unit);
}

}  // namespace sim

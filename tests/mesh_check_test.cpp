// The checks a mesh passes before its mass properties mean anything (sim/mesh.hpp checkMesh):
// each fault on a small mesh broken by hand, its one-line message naming the file, the count
// derived from how the mesh was broken, and the way out.
#include <gtest/gtest.h>

#include <limits>

#include "mesh_shapes.hpp"

using namespace mesh_shapes;

namespace {

// The fault checkMesh finds, with its message (fails the test when it finds none).
sim::MeshProblem problemOf(const sim::TriangleMesh& mesh, double unit = 0.01) {
  const auto problem = sim::checkMesh(mesh, "toy.stl", unit);
  if (!problem) {
    ADD_FAILURE() << "no fault found";
    return {sim::MeshFault::Empty, ""};
  }
  EXPECT_EQ(problem->message.rfind("toy.stl: ", 0), 0u) << problem->message;
  EXPECT_EQ(problem->message.find('\n'), std::string::npos) << problem->message;
  return *problem;
}

}  // namespace

// A box 10 units (cm) on a side and an icosphere pass: closed, wound outwards, hand-sized.
TEST(MeshCheck, ClosedOutwardMeshesOfAHandSizePass) {
  EXPECT_FALSE(sim::checkMesh(box(10, 4, 2), "toy.stl", 0.01));
  EXPECT_FALSE(sim::checkMesh(icosphere(3, Eigen::Vector3d(3, 20, 2)), "toy.stl", 0.01));
}

// One triangle taken out of a closed box leaves its three edges with one face each.
TEST(MeshCheck, AHoleIsAnOpenMeshWithItsEdgesCounted) {
  sim::TriangleMesh mesh = box(10, 4, 2);
  mesh.faces.pop_back();
  const sim::MeshProblem p = problemOf(mesh);
  EXPECT_EQ(p.fault, sim::MeshFault::Open);
  EXPECT_NE(p.message.find("3 open edges"), std::string::npos) << p.message;
  EXPECT_NE(p.message.find("fill the holes"), std::string::npos) << p.message;
}

// One face of a box wound the other way: each of its three edges is then walked the same way
// by it and by its neighbour.
TEST(MeshCheck, OneFaceTurnedIsAnInconsistentWinding) {
  sim::TriangleMesh mesh = box(10, 4, 2);
  std::swap(mesh.faces[4][1], mesh.faces[4][2]);
  const sim::MeshProblem p = problemOf(mesh);
  EXPECT_EQ(p.fault, sim::MeshFault::Inconsistent);
  EXPECT_NE(p.message.find("3 edges walked the same way"), std::string::npos) << p.message;
}

// Two boxes apart in one file (a print plate of two toys) are two solids, not one body: refused,
// with both named. A box with a smaller box inside it wound inwards is one hollow solid (the
// cavity's volume counts negative) and passes, its volume 80 − 4 = 76.
TEST(MeshCheck, TwoSolidsApartAreRefusedAndACavityIsNot) {
  auto join = [](sim::TriangleMesh a, const sim::TriangleMesh& b, const Eigen::Vector3d& shift) {
    const int offset = static_cast<int>(a.vertices.size());
    for (const auto& v : b.vertices) a.vertices.push_back(v + shift);
    for (auto f : b.faces) a.faces.push_back({f[0] + offset, f[1] + offset, f[2] + offset});
    return a;
  };
  const sim::MeshProblem p = problemOf(join(box(10, 4, 2), box(10, 4, 2), {20, 0, 0}));
  EXPECT_EQ(p.fault, sim::MeshFault::Pieces);
  EXPECT_NE(p.message.find("the mesh is 2 separate solids"), std::string::npos) << p.message;
  EXPECT_NE(p.message.find("By Loose Parts"), std::string::npos) << p.message;
  const sim::TriangleMesh hollow = join(box(10, 4, 2), flipped(box(2, 2, 1)), {1, 1, 0.5});
  EXPECT_FALSE(sim::checkMesh(hollow, "toy.stl", 0.01));
  EXPECT_NEAR(sim::meshMoments(hollow).volume, 76, 1e-12);
}

// Every face turned: closed and consistent, but wound inwards, so the signed volume is
// −(10·4·2) = −80 and the mesh is refused (never flipped silently).
TEST(MeshCheck, EveryFaceTurnedIsInsideOutAndRefused) {
  const sim::MeshProblem p = problemOf(flipped(box(10, 4, 2)));
  EXPECT_EQ(p.fault, sim::MeshFault::InsideOut);
  EXPECT_NE(p.message.find("signed volume -80 "), std::string::npos) << p.message;
  EXPECT_NE(p.message.find("Flip"), std::string::npos) << p.message;
}

// A closed box with one more face along an edge, its third corner at the edge's midpoint: zero
// area though its three vertices are distinct.
TEST(MeshCheck, AFaceOfZeroAreaIsDegenerate) {
  sim::TriangleMesh mesh = box(10, 4, 2);
  mesh.vertices.emplace_back(5, 0, 0);  // the middle of the edge from corner 0 to corner 1
  mesh.faces.push_back({0, 1, 8});
  const sim::MeshProblem p = problemOf(mesh);
  EXPECT_EQ(p.fault, sim::MeshFault::Degenerate);
  EXPECT_NE(p.message.find("1 face of zero area (the first, face 13,"), std::string::npos)
      << p.message;
}

// Two tetrahedra that share only an edge: that edge has four faces.
TEST(MeshCheck, TwoSolidsMeetingAtAnEdgeAreNotAManifold) {
  sim::TriangleMesh mesh = cornerTetrahedron(5, 5, 5);
  mesh.vertices.emplace_back(-5, 0, 0);  // 4
  mesh.vertices.emplace_back(0, -5, 0);  // 5: with 0 and 3, a second tetrahedron on edge 0–3
  mesh.faces.insert(mesh.faces.end(), {{0, 4, 5}, {0, 3, 4}, {0, 5, 3}, {3, 5, 4}});
  const sim::MeshProblem p = problemOf(mesh);
  EXPECT_EQ(p.fault, sim::MeshFault::NonManifold);
  EXPECT_NE(p.message.find("1 edge shared by three faces or more"), std::string::npos) << p.message;
}

// A 120-unit box read in metres is 120 m long; in mm it is 0.12 m, the nearest of the common
// units to a 10 cm toy. In cm (12 units) the same: 0.12 m. Given the right unit, it passes.
TEST(MeshCheck, ASizeNoHandHoldsNamesTheUnitThatFitsIt) {
  const sim::MeshProblem mm = problemOf(box(120, 40, 20), 1.0);
  EXPECT_EQ(mm.fault, sim::MeshFault::WrongSize);
  EXPECT_NE(mm.message.find("the mesh is 120 units long, so 120 m"), std::string::npos)
      << mm.message;
  EXPECT_NE(mm.message.find("in mm? units.length: 0.001 makes it 0.12 m"), std::string::npos)
      << mm.message;
  const sim::MeshProblem cm = problemOf(box(12, 4, 2), 1.0);
  EXPECT_NE(cm.message.find("in cm? units.length: 0.01 makes it 0.12 m"), std::string::npos)
      << cm.message;
  // 0.12 units in mm: 0.12 mm, too small; read in metres it would be 0.12 m.
  const sim::MeshProblem m = problemOf(box(0.12, 0.04, 0.02), 0.001);
  EXPECT_NE(m.message.find("in m? units.length: 1 makes it 0.12 m"), std::string::npos)
      << m.message;
  EXPECT_FALSE(sim::checkMesh(box(120, 40, 20), "toy.stl", 0.001));
}

TEST(MeshCheck, ADamagedFileIsNamedAsSuch) {
  sim::TriangleMesh empty;
  EXPECT_EQ(problemOf(empty).fault, sim::MeshFault::Empty);
  sim::TriangleMesh bad = box(10, 4, 2);
  bad.faces[3][2] = 8;  // one past the last vertex
  EXPECT_EQ(problemOf(bad).fault, sim::MeshFault::BadIndex);
  sim::TriangleMesh nan = box(10, 4, 2);
  nan.vertices[5].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(problemOf(nan).fault, sim::MeshFault::NotFinite);
}

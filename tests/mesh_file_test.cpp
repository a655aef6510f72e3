// Reading meshes (scene/mesh_file.hpp): binary and ASCII STL and OBJ files written here byte by
// byte, read back to the same solid (its volume a closed form), and damaged files refused with
// one line naming the file and the cause.
#include "scene/mesh_file.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "mesh_shapes.hpp"

using namespace mesh_shapes;

namespace {

// Binary STL as the format's description has it: 80 bytes of header, a 32-bit count, then per
// triangle 12 floats (a zero normal, the corners) and 2 bytes of attributes.
std::string binaryStl(const sim::TriangleMesh& mesh) {
  std::string out(80, ' ');
  const auto count = static_cast<std::uint32_t>(mesh.faces.size());
  out.append(reinterpret_cast<const char*>(&count), 4);
  for (const auto& f : mesh.faces) {
    float values[12] = {};
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i)
        values[3 + 3 * k + i] = static_cast<float>(mesh.vertices[f[k]][i]);
    out.append(reinterpret_cast<const char*>(values), sizeof values);
    out.append(2, '\0');
  }
  return out;
}

std::string asciiStl(const sim::TriangleMesh& mesh) {
  std::string out = "solid test\n";
  for (const auto& f : mesh.faces) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (int k : f) {
      const Eigen::Vector3d& v = mesh.vertices[k];
      out += "      vertex " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " +
             std::to_string(v.z()) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid test\n";
}

sim::TriangleMesh parsed(const std::string& bytes, scene::MeshFormat format) {
  auto mesh = scene::parseMesh(bytes, "toy", format);
  EXPECT_TRUE(mesh) << mesh.error().text();
  return mesh ? mesh.value() : sim::TriangleMesh{};
}

std::string errorOf(const std::string& bytes, scene::MeshFormat format) {
  auto mesh = scene::parseMesh(bytes, "toy.stl", format);
  EXPECT_FALSE(mesh);
  if (mesh) return "";
  EXPECT_EQ(mesh.error().message.rfind("toy.stl: ", 0), 0u) << mesh.error().message;
  EXPECT_EQ(mesh.error().message.find('\n'), std::string::npos) << mesh.error().message;
  return mesh.error().message;
}

}  // namespace

// A box's 12 triangles repeat each of its 8 corners 4 or 5 times: welded back to 8 vertices, the
// solid is whole again (closed, V = abc), from binary and from ASCII STL alike.
TEST(MeshFile, StlBinaryAndAsciiWeldBackToTheClosedBox) {
  const sim::TriangleMesh box_mesh = box(10, 4, 2);
  for (const std::string& bytes : {binaryStl(box_mesh), asciiStl(box_mesh)}) {
    const sim::TriangleMesh mesh = parsed(bytes, scene::MeshFormat::Stl);
    EXPECT_EQ(mesh.vertices.size(), 8u);
    EXPECT_EQ(mesh.faces.size(), 12u);
    EXPECT_FALSE(sim::checkMesh(mesh, "toy", 0.01));
    EXPECT_NEAR(sim::meshMoments(mesh).volume, 80.0, 1e-12);
  }
}

// An OBJ of the unit cube with one quad a side (and a negative index, as the format allows):
// cut into 12 triangles, volume 1.
TEST(MeshFile, ObjQuadsAreCutIntoTrianglesOfTheSameSolid) {
  const std::string obj =
      "# unit cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
      "f 1 3 4 2\nf 5 6 8 7\nf 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 -5\n";
  const sim::TriangleMesh mesh = parsed(obj, scene::MeshFormat::Obj);
  EXPECT_EQ(mesh.faces.size(), 12u);
  EXPECT_FALSE(sim::checkMesh(mesh, "toy", 0.1));
  EXPECT_NEAR(sim::meshMoments(mesh).volume, 1.0, 1e-14);
}

// −0 and +0 are one position: a box with a corner written as −0 is still closed.
TEST(MeshFile, MinusZeroAndZeroAreOneVertex) {
  sim::TriangleMesh mesh = box(10, 4, 2);
  mesh.vertices.push_back(Eigen::Vector3d(-0.0, -0.0, -0.0));
  mesh.faces[0][0] = 8;  // corner 0, written as −0 in one of its triangles
  const sim::TriangleMesh read = parsed(binaryStl(mesh), scene::MeshFormat::Stl);
  EXPECT_EQ(read.vertices.size(), 8u);
  EXPECT_FALSE(sim::checkMesh(read, "toy", 0.01));
}

TEST(MeshFile, ATruncatedBinaryStlSaysHowLongItShouldBe) {
  std::string bytes = binaryStl(box(10, 4, 2));
  bytes.resize(bytes.size() - 10);
  const std::string message = errorOf(bytes, scene::MeshFormat::Stl);
  EXPECT_NE(message.find("12 triangles is 684 bytes, but the file has 674"), std::string::npos)
      << message;  // 84 + 12 × 50
}

TEST(MeshFile, AsciiStlFaultsNameTheirLine) {
  std::string text = asciiStl(cornerTetrahedron(1, 2, 3));
  text.replace(text.find("vertex 0.000000"), 15, "vertex 0.0x0000");  // line 4
  EXPECT_NE(errorOf(text, scene::MeshFormat::Stl).find("line 4: a vertex coordinate '0.0x0000'"),
            std::string::npos);
  std::string short_vertex = asciiStl(cornerTetrahedron(1, 2, 3));
  short_vertex.resize(short_vertex.find("vertex") + 20);  // "vertex 0.000000 0.00"
  EXPECT_NE(errorOf(short_vertex, scene::MeshFormat::Stl).find("ends inside a vertex"),
            std::string::npos);
  std::string cut = asciiStl(cornerTetrahedron(1, 2, 3));
  cut.resize(cut.find("vertex", cut.find("vertex", cut.find("vertex") + 1) + 1));  // two corners
  EXPECT_NE(errorOf(cut, scene::MeshFormat::Stl).find("ends inside a facet"), std::string::npos);
  EXPECT_NE(errorOf("solid x\nfacet\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n",
                    scene::MeshFormat::Stl)
                .find("a facet with 2 vertices"),
            std::string::npos);
  EXPECT_NE(errorOf("hello", scene::MeshFormat::Stl).find("is it an STL file?"), std::string::npos);
  // A misspelt word is named at its own line, not skipped to fault the facet at its end.
  std::string typo = asciiStl(cornerTetrahedron(1, 2, 3));
  typo.replace(typo.find("vertex"), 6, "vertx");  // line 4
  EXPECT_NE(
      errorOf(typo, scene::MeshFormat::Stl).find("line 4: 'vertx' is not a word of ASCII STL"),
      std::string::npos)
      << errorOf(typo, scene::MeshFormat::Stl);
  // A solid's name may be any words, several solids may follow one another, and a facet's normal
  // may be any three tokens (exporters write nan): all read.
  std::string named = asciiStl(cornerTetrahedron(1, 2, 3));
  named.replace(0, named.find('\n'), "solid my hull vertex facet 2 (mm)");
  const std::size_t normal = named.find("normal") + 7;
  named.replace(normal, named.find('\n', normal) - normal, "nan nan nan");
  const sim::TriangleMesh twice = parsed(named + named, scene::MeshFormat::Stl);
  EXPECT_EQ(twice.faces.size(), 8u);
  // A normal written without its numbers is read too (the next word is the facet's).
  std::string bare = asciiStl(cornerTetrahedron(1, 2, 3));
  for (std::size_t at = bare.find("normal 0 0 0"); at != std::string::npos;
       at = bare.find("normal 0 0 0"))
    bare.replace(at, 12, "normal");
  EXPECT_EQ(parsed(bare, scene::MeshFormat::Stl).faces.size(), 4u);
}

// A text file named .stl is said to be text (it had been measured as a binary STL: "a binary STL
// of 1634692206 triangles is 81734610384 bytes, but the file has 1180"); a binary STL whose
// header is text is still read as one.
TEST(MeshFile, ATextFileIsSaidToBeTextNotATruncatedBinaryStl) {
  const std::string notes(1180, 'x');
  EXPECT_NE(errorOf("My rattleback\n" + notes + "\n", scene::MeshFormat::Stl)
                .find("is text, not an STL (an ASCII STL begins with 'solid'"),
            std::string::npos);
  EXPECT_NE(errorOf("solid empty\nendsolid empty\n" + notes, scene::MeshFormat::Stl)
                .find("is an ASCII STL with no triangles"),
            std::string::npos);
  std::string binary = binaryStl(box(10, 4, 2));
  binary.replace(0, 20, "solid exported by us");  // a header of text, as many exporters write
  EXPECT_EQ(parsed(binary, scene::MeshFormat::Stl).faces.size(), 12u);
}

TEST(MeshFile, FilesThatCannotBeReadAreNamed) {
  auto missing = scene::readMesh("/nonexistent/toy.stl");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error().message,
            "/nonexistent/toy.stl: cannot be read: No such file or directory");
  auto ply = scene::readMesh("toy.ply");
  ASSERT_FALSE(ply);
  EXPECT_NE(ply.error().message.find("give an .stl (binary or ASCII) or an .obj"),
            std::string::npos);
  auto obj = scene::parseMesh("v 0 0 0\nf 1 2 3\n", "toy.obj", scene::MeshFormat::Obj);
  ASSERT_FALSE(obj);
  EXPECT_EQ(obj.error().message.rfind("toy.obj: ", 0), 0u) << obj.error().message;
}

// A file on disk, read through readMesh: the ASCII corner tetrahedron's volume abc/6.
TEST(MeshFile, ReadsAFileFromDisk) {
  const auto path = std::filesystem::temp_directory_path() / "rattleback_mesh_file_test.STL";
  std::ofstream(path) << asciiStl(cornerTetrahedron(1, 2, 3));
  auto mesh = scene::readMesh(path.string());
  ASSERT_TRUE(mesh) << mesh.error().text();
  EXPECT_NEAR(sim::meshMoments(mesh.value()).volume, 1.0, 1e-12);
  std::filesystem::remove(path);
}

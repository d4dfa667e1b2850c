#include "tetblend/meshing/tet_mesh_io.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <string>
#include <vector>

#include "io_test_support.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using io_test::TempDir;
using io_test::writeText;

// As for surfaces, every writer stores float64 or the shortest exact decimal
// form: round trips are compared bitwise (tolerance zero).

std::string messageOf(const std::string& path) {
  try {
    readTetMesh(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TetMesh hardTetMesh() {
  TetMesh m;
  m.vertices = io_test::hardVertices();
  m.tets.resize(3, 4);
  m.tets << 0, 1, 2, 3, 5, 4, 3, 2, 1, 3, 5, 0;
  return m;
}

TetMesh randomTetMesh(std::mt19937& rng, int vertexCount, int tetCount) {
  const SurfaceMesh s = io_test::randomSurface(rng, vertexCount, tetCount);
  std::uniform_int_distribution<int> vertex(0, vertexCount - 1);
  TetMesh m;
  m.vertices = s.vertices;
  m.tets.resize(tetCount, 4);
  for (int t = 0; t < tetCount; ++t) {
    int d = vertex(rng);
    while (d == s.triangles(t, 0) || d == s.triangles(t, 1) || d == s.triangles(t, 2))
      d = vertex(rng);
    m.tets.row(t) << s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2), d;
  }
  return m;
}

void expectSame(const TetMesh& expected, const TetMesh& actual) {
  ASSERT_EQ(expected.vertices.rows(), actual.vertices.rows());
  EXPECT_TRUE(io_test::sameBits(expected.vertices, actual.vertices));
  EXPECT_EQ(expected.tets, actual.tets);
}

TEST(TetMeshIo, RoundTripIsBitExactInEveryFormat) {
  TempDir dir;
  std::mt19937 rng(io_test::testSeed("TetMeshIo.RoundTripIsBitExactInEveryFormat"));
  const std::vector<TetMesh> meshes = {hardTetMesh(), randomTetMesh(rng, 300, 700)};
  // .ele written, .node read: either name stands for the pair.
  const std::vector<std::pair<std::string, std::string>> names = {
      {"m.vtu", "m.vtu"}, {"m.ele", "m.node"}, {"m.mesh", "m.mesh"}, {"U.VTU", "U.VTU"}};
  for (const auto& [written, read] : names) {
    for (const TetMesh& mesh : meshes) {
      SCOPED_TRACE(written);
      writeTetMesh(dir.file(written), mesh);
      expectSame(mesh, readTetMesh(dir.file(read)));
    }
  }
}

TEST(TetMeshIo, TetGenFilesZeroAndOneBasedWithAttributesAndMarkers) {
  TempDir dir;
  Vertices expected(5, 3);
  expected << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1;
  Tets tets(2, 4);
  tets << 0, 1, 2, 3, 1, 2, 3, 4;
  for (const int base : {0, 1}) {
    SCOPED_TRACE(base);
    std::string node = "# points\n5 3 1 1\n";
    const char* rows[] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1", "1 1 1"};
    for (int v = 0; v < 5; ++v) node += std::to_string(v + base) + "  " + rows[v] + " 0.5 1\n";
    std::string ele = "2 4 1\n";
    for (int t = 0; t < 2; ++t) {
      ele += std::to_string(t + base);
      for (int c = 0; c < 4; ++c) ele += " " + std::to_string(tets(t, c) + base);
      ele += " 7  # region\n";
    }
    writeText(dir.file("t.node"), node);
    writeText(dir.file("t.ele"), ele);
    const TetMesh m = readTetMesh(dir.file("t.ele"));
    EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
    EXPECT_EQ(tets, m.tets);
  }
}

TEST(TetMeshIo, MeditSkipsBoundarySectionsAndReadsFreeFormTokens) {
  TempDir dir;
  writeText(dir.file("a.mesh"),
            "MeshVersionFormatted 1\n# comment\nDimension\n3\nVertices\n4\n0 0 0 1\n1 0 0 1\n"
            "0 1 0 1\n0 0 1 2\nEdges 1\n1 2 0\nTriangles\n2\n1 3 2 5 1 2 4 5\n"
            "Corners 1 3\nTetrahedra\n1\n1 2 3 4 0\nEnd\n");
  const TetMesh m = readTetMesh(dir.file("a.mesh"));
  Vertices expected(4, 3);
  expected << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
  Tets tets(1, 4);
  tets << 0, 1, 2, 3;
  EXPECT_EQ(tets, m.tets);
}

struct Malformed {
  const char* file;
  const char* content;
  const char* expected;  // substring of the message, with the line number
};

// Writes each case's file and expects reading it to fail with its message.
// A valid partner file (one tet beside a .node, four points beside a .ele)
// makes the error come from the file under test.
void expectMessages(const std::vector<Malformed>& cases) {
  TempDir dir;
  for (const Malformed& c : cases) {
    SCOPED_TRACE(c.content);
    writeText(dir.file(c.file), c.content);
    if (std::string(c.file) == "a.node") writeText(dir.file("a.ele"), "1 4 0\n0 0 1 2 3\n");
    if (std::string(c.file) == "a.ele") {
      writeText(dir.file("a.node"), "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n");
    }
    const std::string message = messageOf(dir.file(c.file));
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(TetMeshIo, MalformedFilesThrowInputErrorNamingLineAndValue) {
  const std::vector<Malformed> cases = {
      {"a.node", "4 2 0 0\n", "a.node:1: dimension '2' is not 3"},
      {"a.node", "1 3 0 0\n5 0 0 0\n", "a.node:2: first point index 5 is neither 0 nor 1"},
      {"a.node", "2 3 0 0\n0 0 0 0\n2 0 0 0\n", "a.node:3: point index 2 where 1 was expected"},
      {"a.node", "2 3 0 0\n0 0 0 0\n1 0 nan 0\n", "a.node:3: NaN coordinate at vertex 1"},
      {"a.node", "2 3 0 0\n0 0 0 0\n1 0 0\n", "a.node:3: expected 3 coordinates for vertex 1"},
      {"a.node", "3 3 0 0\n0 0 0 0\n", "a.node:2: file ends after 1 of 3 points"},
      {"a.ele", "1 10 0\n", "a.ele:1: 10 nodes per tet: only linear 4-node tets"},
      {"a.ele", "# header\n1 4 0\n0 0 1 2 9\n",
       "a.ele:3: tet 0 (0-based): index 9 out of range 0..3"},
      {"a.ele", "1 4 0\n0 0 1 2\n",
       "a.ele:2: tet 0 (0-based): expected an index and 4 vertex indices"},
      {"a.mesh", "MeshVersionFormatted 2\nDimension 2\n", "a.mesh:2: Dimension 2: only 3D"},
      {"a.mesh", "Dimension 3\nVertices 1\n0 0 inf 1\n",
       "a.mesh:3: infinite coordinate at vertex 0"},
      {"a.mesh",
       "Dimension 3\nVertices 4\n0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 0\nTetrahedra 1\n1 2 3 0 0\n",
       "a.mesh:5: tet 0 (0-based): index 0 out of range 1..4"},
      {"a.mesh", "Dimension 3\nVertices 1\n0 0 0 0\nHexahedra 0\n",
       "a.mesh:4: section 'Hexahedra'"},
      {"a.mesh", "Dimension 3\nFoo 1\n", "a.mesh:2: unknown keyword 'Foo'"},
      {"a.mesh", "Dimension 3\nVertices 2\n0 0 0 0\n1 1 x 0\n",
       "a.mesh:4: expected a number for coordinate of vertex 1, found 'x'"},
      {"a.mesh", "Dimension 3\nVertices 2\n0 0 0 0\n1 1", "a.mesh:4: file ends before vertex 1"},
      {"a.mesh", "Dimension 3\nVertices 2\n0 0 0 0\n1 1 1\n",
       "a.mesh:4: file ends before the reference of vertex 1"},
      // Issue 11 (fuzzing, fuzz_medit): a second section replaced the first,
      // leaving tets that refer to vertices that no longer exist.
      {"a.mesh",
       "Dimension 3\nVertices 4\n0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 0\nTetrahedra 1\n1 2 3 4 0\n"
       "Vertices 1\n0 0 0 0\n",
       "a.mesh:6: a second Vertices section (first on line 2): a file holds one"},
      {"a.mesh",
       "Dimension 3\nVertices 4\n0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 0\nTetrahedra 1\n1 2 3 4 0\n"
       "Tetrahedra 0\n",
       "a.mesh:6: a second Tetrahedra section (first on line 4): a file holds one"},
  };
  expectMessages(cases);
}

// Issue 11, item 2: a count near 2^31 in a header allocated gigabytes
// (std::bad_alloc, no file named) before the data was read. Rows are now
// allocated for what the data can hold, and the reader fails where it ends.
TEST(TetMeshIo, HeaderCountsBeyondTheDataEndInOneErrorNamingTheFile) {
  const std::vector<Malformed> cases = {
      {"a.node", "2147483647 3 0 0\n0 0 0 0\n", "a.node:2: file ends after 1 of 2147483647 points"},
      {"a.ele", "2147483647 4 0\n0 0 1 2 3\n", "a.ele:2: file ends after 1 of 2147483647 tets"},
      {"a.mesh", "Dimension 3\nVertices 2147483647\n0 0 0 0\n",
       "a.mesh:3: file ends before vertex 1"},
      {"a.mesh", "Dimension 3\nVertices 1\n0 0 0 0\nTetrahedra 2147483647\n1 1 1 1 0\n",
       "a.mesh:5: file ends before tet 1 (0-based)"},
  };
  expectMessages(cases);
}

TEST(TetMeshIo, VtuWithNonTetCellsIsRefused) {
  TempDir dir;
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int i = 0; i < 8; ++i) points->InsertNextPoint(i & 1, (i >> 1) & 1, i >> 2);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType tet[4] = {0, 1, 2, 4};
  const vtkIdType hex[8] = {0, 1, 3, 2, 4, 5, 7, 6};
  grid->InsertNextCell(VTK_TETRA, 4, tet);
  grid->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  writer->SetInputData(grid);
  writer->SetFileName(dir.file("hex.vtu").c_str());
  ASSERT_EQ(writer->Write(), 1);
  const std::string message = messageOf(dir.file("hex.vtu"));
  EXPECT_NE(message.find("cell 1 (0-based) is vtkHexahedron (VTK type 12)"), std::string::npos)
      << message;
}

TEST(TetMeshIo, MissingFilesAndUnknownExtensionThrow) {
  TempDir dir;
  EXPECT_NE(messageOf(dir.file("none.vtu")).find("no such file"), std::string::npos);
  EXPECT_NE(messageOf(dir.file("none.mesh")).find("no such file"), std::string::npos);
  writeText(dir.file("only.node"), "1 3 0 0\n0 0 0 0\n");
  EXPECT_NE(messageOf(dir.file("only.node")).find("only.ele: no such file"), std::string::npos);
  writeText(dir.file("a.msh"), "$MeshFormat\n");
  EXPECT_NE(messageOf(dir.file("a.msh")).find("unknown tet mesh extension '.msh'"),
            std::string::npos);
}

TEST(TetMeshIo, WriterRefusesBadMeshesAndKeepsTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("keep.mesh");
  writeText(path, "old content\n");
  TetMesh bad = hardTetMesh();
  bad.tets(1, 3) = -1;
  for (const char* name : {"keep.mesh", "keep.vtu", "keep.node"}) {
    EXPECT_THROW(writeTetMesh(dir.file(name), bad), InputError) << name;
  }
  TetMesh inf = hardTetMesh();
  inf.vertices(0, 0) = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(writeTetMesh(path, inf), InputError);
  MeshDataArrays data;
  data.cellData.push_back({"quality", 1, std::vector<double>(3, 1.0)});
  EXPECT_THROW(writeTetMesh(path, hardTetMesh(), data), InputError);  // .mesh has no arrays
  EXPECT_THROW(writeTetMesh(dir.file("a.vtk"), hardTetMesh()), InputError);
  EXPECT_EQ(io_test::readText(path), "old content\n");
  EXPECT_EQ(dir.entryCount(), 1);  // no partial or temporary file left
}

}  // namespace
}  // namespace tetblend

#include "tetblend/meshing/surface_io.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <string>
#include <vector>

#include "io_test_support.h"
#include "tetblend/core/error.h"

namespace tetblend {
namespace {

using io_test::TempDir;
using io_test::writeText;

// Every writer prints the shortest decimal that reads back to the same double
// (std::to_chars) or stores raw float64, so round trips are bit-exact: the
// tolerance is zero and positions are compared bitwise.

std::string messageOf(const std::string& path) {
  try {
    readSurface(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

SurfaceMesh hardSurface() {
  SurfaceMesh m;
  m.vertices = io_test::hardVertices();
  m.triangles.resize(4, 3);
  m.triangles << 0, 1, 2, 2, 3, 4, 5, 4, 3, 0, 5, 1;
  return m;
}

void expectSame(const SurfaceMesh& expected, const SurfaceMesh& actual) {
  ASSERT_EQ(expected.vertices.rows(), actual.vertices.rows());
  EXPECT_TRUE(io_test::sameBits(expected.vertices, actual.vertices));
  EXPECT_EQ(expected.triangles, actual.triangles);
}

TEST(SurfaceIo, RoundTripIsBitExactInEveryWritableFormat) {
  TempDir dir;
  std::mt19937 rng(io_test::testSeed("SurfaceIo.RoundTripIsBitExactInEveryWritableFormat"));
  const std::vector<SurfaceMesh> meshes = {hardSurface(), io_test::randomSurface(rng, 200, 500)};
  for (const char* name : {"m.obj", "m.off", "m.ply", "ascii.ply", "m.vtp", "UPPER.OBJ"}) {
    for (const SurfaceMesh& mesh : meshes) {
      SCOPED_TRACE(name);
      const std::string path = dir.file(name);
      SurfaceWriteOptions options;
      options.plyBinary = std::string(name) != "ascii.ply";
      writeSurface(path, mesh, {}, options);
      expectSame(mesh, readSurface(path));
    }
  }
}

TEST(SurfaceIo, ObjAcceptsTextureNormalAndRelativeIndices) {
  TempDir dir;
  const std::string path = dir.file("a.obj");
  writeText(path,
            "# comment\nmtllib x.mtl\no thing\nv 1 2 3 1.0\nv 4 5 6\r\nvt 0 0\nvn 0 0 1\n"
            "g group\ns off\nv 7 8 9 0.5 0.5 0.5\nusemtl m\nf 1/1/1 2/1/1 3/1/1\n"
            "v -1 -2 -3\nf -1 -2//1 -4/1\n");
  const SurfaceMesh m = readSurface(path);
  Vertices expected(4, 3);
  expected << 1, 2, 3, 4, 5, 6, 7, 8, 9, -1, -2, -3;
  EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
  Triangles triangles(2, 3);
  triangles << 0, 1, 2, 3, 2, 0;
  EXPECT_EQ(triangles, m.triangles);
}

TEST(SurfaceIo, OffAcceptsColoursCommentsAndCountsOnTheHeaderLine) {
  TempDir dir;
  const std::string path = dir.file("a.off");
  writeText(path,
            "COFF 4 2 0\n# comment\n0 0 0 255 0 0 255\n1 0 0 1 1 1 1\n0 1 0 0 0 0 0\n"
            "0 0 1 9 9 9 9\n\n3 0 2 1 255 0 0\n3 0 1 3\n");
  const SurfaceMesh m = readSurface(path);
  Vertices expected(4, 3);
  expected << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
  Triangles triangles(2, 3);
  triangles << 0, 2, 1, 0, 1, 3;
  EXPECT_EQ(triangles, m.triangles);
}

// A PLY file built byte by byte: float x y z plus a uchar colour, faces as
// "list uchar uint", an extra element after the faces.
std::string binaryPly(bool little) {
  io_test::ByteBuilder b(little);
  b.text(std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
         " 1.0\ncomment test\nelement vertex 3\nproperty float x\nproperty uchar red\n"
         "property float y\nproperty float z\nelement face 1\n"
         "property list uchar uint vertex_indices\nproperty short flags\n"
         "element edge 1\nproperty list uchar int pair\nend_header\n");
  const float xyz[3][3] = {{0.5f, -1.25f, 3.0f}, {1e-3f, 2.0f, -0.0f}, {7.0f, 8.0f, 9.5f}};
  for (const auto& p : xyz) b.put(p[0]).put(std::uint8_t{200}).put(p[1]).put(p[2]);
  b.put(std::uint8_t{3}).put(std::uint32_t{2}).put(std::uint32_t{0}).put(std::uint32_t{1});
  b.put(std::int16_t{-5});
  b.put(std::uint8_t{2}).put(std::int32_t{0}).put(std::int32_t{1});
  return b.bytes();
}

TEST(SurfaceIo, PlyBinaryBothByteOrdersWithExtraPropertiesAndElements) {
  TempDir dir;
  Vertices expected(3, 3);
  expected << 0.5, -1.25, 3.0, static_cast<double>(1e-3f), 2.0, -0.0, 7.0, 8.0, 9.5;
  Triangles triangles(1, 3);
  triangles << 2, 0, 1;
  for (const bool little : {true, false}) {
    SCOPED_TRACE(little ? "little endian" : "big endian");
    const std::string path = dir.file(little ? "le.ply" : "be.ply");
    writeText(path, binaryPly(little));
    const SurfaceMesh m = readSurface(path);
    EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
    EXPECT_EQ(triangles, m.triangles);
  }
}

TEST(SurfaceIo, StlMergesCoincidentCornersInFirstAppearanceOrder) {
  TempDir dir;
  // Two triangles sharing the edge (1,0,0)-(0,1,0); the second lists -0 for a
  // coordinate the first gave as +0: exactly coincident, so merged.
  const std::string ascii =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\n  outer loop\n  vertex 1 -0 0\n  vertex 1 1 0\n"
      "  vertex 0 1 0\n  endloop\nendfacet\nendsolid s\n";
  io_test::ByteBuilder binary(true);
  binary.text("solid but binary" + std::string(64, ' ')).put(std::uint32_t{2});
  const float corners[6][3] = {{0, 0, 0},     {1, 0, 0}, {0, 1, 0},
                               {1, -0.0f, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int f = 0; f < 2; ++f) {
    binary.put(0.0f).put(0.0f).put(1.0f);
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k) binary.put(corners[3 * f + c][k]);
    }
    binary.put(std::uint16_t{0});
  }
  Vertices expected(4, 3);
  expected << 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0;
  Triangles triangles(2, 3);
  triangles << 0, 1, 2, 1, 3, 2;
  for (const auto& [name, bytes] :
       {std::pair<std::string, std::string>{"a.stl", ascii}, {"b.stl", binary.bytes()}}) {
    SCOPED_TRACE(name);
    writeText(dir.file(name), bytes);
    const SurfaceMesh m = readSurface(dir.file(name));
    EXPECT_TRUE(io_test::sameBits(expected, m.vertices));
    EXPECT_EQ(triangles, m.triangles);
  }
}

TEST(SurfaceIo, StlWeldingAgreesWithVtkStlReader) {
  // Oracle: VTK's vtkSTLReader merges exactly coincident points with
  // vtkMergePoints, numbering them in order of first appearance too.
  TempDir dir;
  std::mt19937 rng(io_test::testSeed("SurfaceIo.StlWeldingAgreesWithVtkStlReader"));
  const SurfaceMesh mesh = io_test::randomSurface(rng, 300, 900);
  io_test::ByteBuilder stl(true);
  stl.text(std::string(80, ' ')).put(static_cast<std::uint32_t>(mesh.triangles.rows()));
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    stl.put(0.0f).put(0.0f).put(0.0f);
    for (int c = 0; c < 3; ++c) {
      for (int k = 0; k < 3; ++k)
        stl.put(static_cast<float>(mesh.vertices(mesh.triangles(f, c), k)));
    }
    stl.put(std::uint16_t{0});
  }
  const std::string path = dir.file("random.stl");
  writeText(path, stl.bytes());
  const SurfaceMesh ours = readSurface(path);

  auto reader = vtkSmartPointer<vtkSTLReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* theirs = reader->GetOutput();
  ASSERT_EQ(ours.vertices.rows(), theirs->GetNumberOfPoints());
  ASSERT_EQ(ours.triangles.rows(), theirs->GetNumberOfPolys());
  for (vtkIdType v = 0; v < theirs->GetNumberOfPoints(); ++v) {
    double p[3];
    theirs->GetPoint(v, p);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(ours.vertices(v, k), p[k]);
  }
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  theirs->GetPolys()->InitTraversal();
  for (Eigen::Index f = 0; theirs->GetPolys()->GetNextCell(count, ids) != 0; ++f) {
    ASSERT_EQ(count, 3);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(ours.triangles(f, c), ids[c]);
  }
}

struct Malformed {
  const char* file;
  const char* content;
  const char* expected;  // substring of the message, with the line number
};

// Writes each case's file and expects reading it to fail with its message.
void expectMessages(const std::vector<Malformed>& cases) {
  TempDir dir;
  for (const Malformed& c : cases) {
    SCOPED_TRACE(c.content);
    writeText(dir.file(c.file), c.content);
    const std::string message = messageOf(dir.file(c.file));
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

TEST(SurfaceIo, MalformedFilesThrowInputErrorNamingLineAndValue) {
  const std::vector<Malformed> cases = {
      {"a.obj", "v 1 2\n", "a.obj:1: expected 3 coordinates for vertex 0"},
      {"a.obj", "v 1 2 x\n", "a.obj:1: expected a number for coordinate of vertex 0, found 'x'"},
      {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nv nan 0 0\n", "a.obj:5: NaN coordinate at vertex 3"},
      {"a.obj", "v 0 0 inf\n", "a.obj:1: infinite coordinate at vertex 0"},
      {"a.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n",
       "a.obj:3: face 0 (0-based) has 2 vertices: a face needs 3"},
      {"a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
       "a.obj:4: face 0 (0-based): index 99 out of range 1..3"},
      {"a.obj", "v 0 0 0\nf 1 -2 1\n", "a.obj:2: face 0 (0-based): relative index -2"},
      {"a.obj", "v 0 0 0\nf 1 a 1\n", "a.obj:2: expected an integer"},
      {"a.off", "OFX\n", "a.off:1: expected the header 'OFF'"},
      {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n", "a.off:4: file ends after 2 of 3 vertices"},
      {"a.off", "OFF\n2 1 0\n0 0 0\n1 0 0\n2 0 1\n",
       "a.off:5: face 0 (0-based) has 2 vertices: a face needs 3"},
      {"a.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n4 0 1 2\n",
       "a.off:7: face 0 (0-based): expected 4 vertex indices, found 3"},
      {"a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
       "a.off:6: face 0 (0-based): index 7 out of range 0..2"},
      {"a.off", "OFF\n1 0 0\n0 -nan 0\n", "a.off:3: NaN coordinate at vertex 0"},
      {"a.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n",
       "a.ply:4: the header has no 'end_header' line"},
      {"a.ply",
       "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
       "1 1 0\n2 0 1\n",
       "a.ply:14: face 0 (0-based) has 2 vertices: a face needs 3"},
      {"a.ply",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
       "3 0 1 50\n",
       "a.ply:13: face 0 (0-based): index 50 out of range 0..2"},
      {"a.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "end_header\n0 inf 0\n",
       "a.ply:8: infinite coordinate at vertex 0"},
      {"a.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty double x\n"
       "property double y\nproperty double z\nend_header\n\x01\x02\x03",
       "a.ply: byte offset 118: file ends inside property 'x' of vertex 0"},
      {"a.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n",
       "a.stl:4: expected 3 coordinates after 'vertex', found 2"},
      {"a.stl",
       "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
       "vertex 1 1 0\nendloop\nendfacet\nendsolid\n",
       "a.stl:7: facet 0 (0-based) has more than 3 vertices: triangulate it first"},
      {"a.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n",
       "a.stl:4: NaN coordinate at vertex 0"},
      {"a.stl", "garbage", "a.stl:1: neither ascii STL"},
      {"a.vtp", "<VTKFile type=\"PolyData\"> broken", "a.vtp: VTK could not read the file"},
      {"a.vtp", "solid s\n", "a.vtp: not a VTK XML PolyData file"},
  };
  expectMessages(cases);
}

// Issue 11, item 1: the vertex matrix was sized from the last 'element vertex'
// while the rows of every declaration were read into it (heap overflow).
TEST(SurfaceIo, PlyElementDeclaredTwiceIsRefusedNamingBothLines) {
  TempDir dir;
  const std::string header =
      "element vertex 40\nproperty double x\nproperty double y\nproperty double z\n"
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
  io_test::ByteBuilder ascii(true), binary(true);
  ascii.text("ply\nformat ascii 1.0\n" + header);
  binary.text("ply\nformat binary_little_endian 1.0\n" + header);
  for (int row = 0; row < 43; ++row) {
    ascii.text("1 2 3\n");
    binary.put(1.0).put(2.0).put(3.0);
  }
  for (const auto* builder : {&ascii, &binary}) {
    writeText(dir.file("twice.ply"), builder->bytes());
    const std::string message = messageOf(dir.file("twice.ply"));
    EXPECT_NE(message.find("twice.ply:7: element 'vertex' is declared again (first on line 3)"),
              std::string::npos)
        << message;
  }
}

// Issue 11, item 2: a count near 2^31 in a header allocated gigabytes
// (std::bad_alloc, no file named) before the data was read. Rows are now
// allocated for what the data can hold, and the reader fails where it ends.
TEST(SurfaceIo, HeaderCountsBeyondTheDataEndInOneErrorNamingTheFile) {
  const std::vector<Malformed> cases = {
      {"a.ply",
       "ply\nformat ascii 1.0\nelement vertex 2147483647\nproperty double x\nproperty double "
       "y\nproperty double z\nend_header\n0 0 0\n",
       "a.ply:8: file ends before vertex 1 (0-based): the file is truncated"},
      {"a.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float "
       "y\nproperty float z\nelement face 2147483647\nproperty list uchar int vertex_indices\n"
       "end_header\n\x03",
       "a.ply: byte offset 179: file ends inside list entry of face 0 (0-based)"},
      {"a.ply", "ply\nformat ascii 1.0\nelement vertex 2147483647\nproperty double y\nend_header\n",
       "a.ply: the vertex element lacks x, y or z properties"},
      {"a.off", "OFF\n2147483647 0 0\n0 0 0\n",
       "a.off:3: file ends after 1 of 2147483647 vertices"},
      {"a.off", "OFF 0 2147483000 0\n", "a.off:1: file ends after 0 of 2147483000 faces"},
  };
  expectMessages(cases);
}

// Issue 11 (no crash on any input): a list length read as NaN, a fraction or
// 1e30 (a float count type) was converted to int (undefined behaviour, an
// abort under UBSan) and the row misread.
TEST(SurfaceIo, PlyListLengthThatIsNotACountIsRefused) {
  TempDir dir;
  for (const float length : {std::nanf(""), 2.5f, 1e30f}) {
    SCOPED_TRACE(length);
    io_test::ByteBuilder b(true);
    b.text(
        "ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nproperty "
        "float y\nproperty float z\nproperty list float int extra\nend_header\n");
    b.put(0.0f).put(0.0f).put(0.0f).put(length).put(std::int32_t{1}).put(std::int32_t{2});
    writeText(dir.file("list.ply"), b.bytes());
    const std::string message = messageOf(dir.file("list.ply"));
    EXPECT_NE(message.find("list.ply: byte offset 145: list length "), std::string::npos)
        << message;
    EXPECT_NE(message.find(" of vertex 0 (0-based) is not a whole number of entries"),
              std::string::npos)
        << message;
  }
}

// Issue 11 (fuzzing, fuzz_ply): a face index of a float-typed list that was
// NaN or beyond int was converted to int (undefined behaviour, an abort under
// UBSan), a fraction was truncated to a vertex, and a list length of -1e300
// was converted to long long for the message.
TEST(SurfaceIo, PlyFloatIndexThatIsNotAVertexNumberIsRefused) {
  const struct {
    float length;
    float index;  // the third corner; the first two are 0 and 1
    const char* expected;
  } cases[] = {
      {3.0f, std::nanf(""), "face 0 (0-based): index nan out of range 0..2"},
      {3.0f, 1e30f, "face 0 (0-based): index 1.0000000150474662e+30 out of range 0..2"},
      {3.0f, -1.0f, "face 0 (0-based): index -1 out of range 0..2"},
      {3.0f, 1.5f, "face 0 (0-based): index 1.5 is not a whole number"},
      {-1e30f, 0.0f, "negative list length"},
  };
  TempDir dir;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.expected);
    io_test::ByteBuilder b(true);
    b.text(
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty "
        "float y\nproperty float z\nelement face 1\nproperty list float float vertex_indices\n"
        "end_header\n");
    for (int v = 0; v < 3; ++v) b.put(float(v == 1)).put(float(v == 2)).put(0.0f);
    b.put(c.length).put(0.0f).put(1.0f).put(c.index);
    writeText(dir.file("float.ply"), b.bytes());
    const std::string message = messageOf(dir.file("float.ply"));
    EXPECT_NE(message.find("float.ply: byte offset "), std::string::npos) << message;
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
  }
}

// Issue 11 (fuzzing, fuzz_ply): the rows of an element without properties
// were counted one by one, 2^31 of them in a binary file (a 10 s timeout),
// and in ascii each took the next data line, misreading the file.
TEST(SurfaceIo, PlyElementWithoutPropertiesHoldsNoRows) {
  const std::string header =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element empty 2147483647\nelement face 1\nproperty list uchar int vertex_indices\n"
      "end_header\n";
  io_test::ByteBuilder ascii(true), binary(true);
  ascii.text("ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  binary.text("ply\nformat binary_little_endian 1.0\n" + header);
  for (int v = 0; v < 3; ++v) binary.put(float(v == 1)).put(float(v == 2)).put(0.0f);
  binary.put(std::uint8_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2});
  TempDir dir;
  for (const auto* builder : {&ascii, &binary}) {
    writeText(dir.file("empty.ply"), builder->bytes());
    const SurfaceMesh mesh = readSurface(dir.file("empty.ply"));
    ASSERT_EQ(mesh.triangles.rows(), 1);
    EXPECT_EQ(mesh.triangles.row(0), Eigen::RowVector3i(0, 1, 2));
    EXPECT_EQ(mesh.vertices.rows(), 3);
  }
}

// Issue 11, item 3: tokens quoted in errors went to the terminal verbatim,
// control bytes and megabytes included.
TEST(SurfaceIo, QuotedTokensAreEscapedAndShortened) {
  // Far longer than any quoted token may be; the message must stay a line.
  constexpr std::size_t kHugeToken = 100000;
  constexpr std::size_t kMaxMessage = 300;
  TempDir dir;
  const std::string hostile = "1\x1b[2J\x07" + std::string(kHugeToken, '9');
  writeText(dir.file("evil.obj"), "v 0 0 " + hostile + "x\n");
  writeText(dir.file("evil.off"), "\x1b]0;owned\x07OFX\n");
  for (const char* name : {"evil.obj", "evil.off"}) {
    SCOPED_TRACE(name);
    const std::string message = messageOf(dir.file(name));
    EXPECT_NE(message.find("\\x1b"), std::string::npos) << message;
    EXPECT_LT(message.size(), kMaxMessage) << message;
    for (const char c : message) EXPECT_GE(static_cast<unsigned char>(c), 0x20) << message;
  }
  EXPECT_NE(messageOf(dir.file("evil.obj")).find("found '1\\x1b[2J\\x07999"), std::string::npos);
  EXPECT_NE(messageOf(dir.file("evil.obj")).find("99...'"), std::string::npos);
}

// Issue 11, item 4 (backstop under the command line's own check): the atomic
// writer renamed over whatever the target was.
TEST(SurfaceIo, WriterRefusesTargetsThatAreNotRegularFiles) {
  TempDir dir;
  writeText(dir.file("kept.obj"), "v 0 0 0\n");
  io_test::fs::create_directory(dir.file("folder.obj"));
  io_test::fs::create_symlink(dir.file("kept.obj"), dir.file("link.obj"));
  const struct {
    const char* name;
    const char* reason;
  } cases[] = {{"folder.obj", "is a directory"}, {"link.obj", "is a symbolic link"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    std::string message = "no InputError";
    try {
      writeSurface(dir.file(c.name), hardSurface());
    } catch (const InputError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(dir.file(c.name) + ": " + c.reason), std::string::npos) << message;
  }
  EXPECT_TRUE(io_test::fs::is_directory(dir.file("folder.obj")));
  EXPECT_TRUE(io_test::fs::is_symlink(dir.file("link.obj")));
  EXPECT_EQ(io_test::readText(dir.file("kept.obj")), "v 0 0 0\n");
  EXPECT_EQ(dir.entryCount(), 3);
}

// One triangle, one quad and one pentagon (the quad's second corner is the
// triangle's third), as every reader must split them: the fan from each
// face's first corner, in face order.
constexpr char kPolygonObj[] =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 2 0 0\nv 2 1 0\nv 3 0.5 0\n"
    "f 1 2 3\nf 2 5 6 4\nf 5 7 6 4 2\n";
constexpr char kPolygonOff[] =
    "OFF\n7 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n2 1 0\n3 0.5 0\n"
    "3 0 1 2\n4 1 4 5 3\n5 4 6 5 3 1\n";
constexpr char kPolygonPly[] =
    "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
    "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n0 1 0\n1 1 0\n2 0 0\n2 1 0\n3 0.5 0\n"
    "3 0 1 2\n4 1 4 5 3\n5 4 6 5 3 1\n";

Triangles polygonFans() {
  Triangles triangles(6, 3);
  triangles << 0, 1, 2,           // the triangle
      1, 4, 5, 1, 5, 3,           // the quad (1 4 5 3)
      4, 6, 5, 4, 5, 3, 4, 3, 1;  // the pentagon (4 6 5 3 1)
  return triangles;
}

TEST(SurfaceIo, PolygonsAreSplitIntoTheFanFromTheirFirstCornerInEveryFormat) {
  TempDir dir;
  writeText(dir.file("p.obj"), kPolygonObj);
  writeText(dir.file("p.off"), kPolygonOff);
  writeText(dir.file("p.ply"), kPolygonPly);
  auto points = vtkSmartPointer<vtkPoints>::New();
  const SurfaceMesh fromObj = readSurface(dir.file("p.obj"));
  for (Eigen::Index v = 0; v < fromObj.vertices.rows(); ++v) {
    points->InsertNextPoint(fromObj.vertices(v, 0), fromObj.vertices(v, 1), fromObj.vertices(v, 2));
  }
  auto polygons = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType triangle[3] = {0, 1, 2};
  const vtkIdType quad[4] = {1, 4, 5, 3};
  const vtkIdType pentagon[5] = {4, 6, 5, 3, 1};
  polygons->InsertNextCell(3, triangle);
  polygons->InsertNextCell(4, quad);
  polygons->InsertNextCell(5, pentagon);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polygons);
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(poly);
  writer->SetFileName(dir.file("p.vtp").c_str());
  ASSERT_EQ(writer->Write(), 1);
  for (const char* name : {"p.obj", "p.off", "p.ply", "p.vtp"}) {
    SCOPED_TRACE(name);
    const SurfaceMesh mesh = readSurface(dir.file(name));
    EXPECT_EQ(mesh.vertices.rows(), 7);
    EXPECT_EQ(mesh.triangles, polygonFans());
  }
}

TEST(SurfaceIo, VtpWithStripsIsRefused) {
  TempDir dir;
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int i = 0; i < 4; ++i) points->InsertNextPoint(i & 1, i >> 1, 0);
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[4] = {0, 1, 3, 2};
  quads->InsertNextCell(4, quad);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(poly);
  poly->SetPolys(vtkSmartPointer<vtkCellArray>::New());
  poly->SetStrips(quads);
  writer->SetFileName(dir.file("strip.vtp").c_str());
  ASSERT_EQ(writer->Write(), 1);
  EXPECT_NE(messageOf(dir.file("strip.vtp")).find("strip cells"), std::string::npos);
}

TEST(SurfaceIo, MissingFileAndUnknownExtensionThrow) {
  TempDir dir;
  for (const char* name : {"missing.obj", "missing.ply", "missing.stl", "missing.vtp"}) {
    EXPECT_NE(messageOf(dir.file(name)).find("no such file"), std::string::npos) << name;
  }
  writeText(dir.file("a.xyz"), "1 2 3\n");
  EXPECT_NE(messageOf(dir.file("a.xyz")).find("unknown surface extension '.xyz'"),
            std::string::npos);
}

TEST(SurfaceIo, WriterRefusesBadMeshesAndKeepsTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("keep.obj");
  writeText(path, "old content\n");
  SurfaceMesh bad = hardSurface();
  bad.triangles(2, 1) = 6;  // one past the last vertex
  for (const char* name : {"keep.obj", "keep.off", "keep.ply", "keep.vtp"}) {
    EXPECT_THROW(writeSurface(dir.file(name), bad), InputError) << name;
  }
  SurfaceMesh nan = hardSurface();
  nan.vertices(1, 2) = std::nan("");
  EXPECT_THROW(writeSurface(path, nan), InputError);
  MeshDataArrays data;
  data.pointData.push_back({"a", 1, std::vector<double>(6, 0.0)});
  EXPECT_THROW(writeSurface(path, hardSurface(), data), InputError);  // OBJ has no arrays
  EXPECT_THROW(writeSurface(dir.file("a.stl"), hardSurface()), InputError);
  EXPECT_EQ(io_test::readText(path), "old content\n");
  EXPECT_EQ(dir.entryCount(), 1);  // no partial or temporary file left
}

}  // namespace
}  // namespace tetblend

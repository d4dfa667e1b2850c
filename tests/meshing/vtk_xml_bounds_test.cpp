// Issue 11 (fuzzing): VTK's XML readers allocate from the sizes a file
// declares before reading its data. A NumberOfPoints/NumberOfCells of 2e9 in
// a 2 KB file, or a compressed block header claiming 2^32 blocks or a 2 GB
// block, asked for gigabytes (found by fuzz_vtp/fuzz_vtu); a decompression
// error was printed by VTK instead of reaching the error message.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io_test_support.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/procedural_shapes.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_boundary.h"
#include "tetblend/meshing/tet_mesh_io.h"

namespace tetblend {
namespace {

using io_test::TempDir;

// A closed tetrahedron surface and the one tet it bounds.
SurfaceMesh tetraSurface() {
  SurfaceMesh m;
  m.vertices.resize(4, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.triangles.resize(4, 3);
  m.triangles << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3;
  return m;
}

TetMesh tetraMesh() {
  TetMesh m;
  m.vertices = tetraSurface().vertices;
  m.tets.resize(1, 4);
  m.tets << 0, 1, 2, 3;
  return m;
}

std::string messageOf(const std::string& path) {
  try {
    if (io_test::fs::path(path).extension() == ".vtu") {
      readTetMesh(path);
    } else {
      readSurface(path);
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

// Byte offset of the first compressed block header of the raw appended data
// (the writers' layout: UInt32 words, little endian).
std::size_t firstHeader(const std::string& bytes) {
  return bytes.find('_', bytes.find("<AppendedData")) + 1;
}

std::uint32_t wordAt(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

void setWord(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((value >> (8 * i)) & 0xff);
}

void replaceOnce(std::string& bytes, const std::string& from, const std::string& to) {
  const std::size_t at = bytes.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  bytes.replace(at, from.size(), to);
}

struct Mutation {
  const char* name;
  const char* file;  // .vtp or .vtu, as written by the library
  void (*mutate)(std::string& bytes);
  const char* expected;  // substring of the message
};

TEST(VtkXmlBounds, DeclaredSizesBeyondTheFileAreRefusedBeforeVtkAllocates) {
  constexpr std::uint32_t kHugeBlocks = 0xfffffff0u;  // 32 GB of block sizes in a UInt32 header
  constexpr std::uint32_t kHugeBlock = 0x7ffffff0u;   // a 2 GB block from a few bytes
  const std::vector<Mutation> cases = {
      {"points", "a.vtp",
       [](std::string& b) {
         replaceOnce(b, "NumberOfPoints=\"4\"", "NumberOfPoints=\"2000000000\"");
       },
       "a.vtp: NumberOfPoints 2000000000 is more than its "},
      {"cells", "a.vtu",
       [](std::string& b) {
         replaceOnce(b, "NumberOfCells=\"1\"", "NumberOfCells=\"2000000000\"");
       },
       "a.vtu: NumberOfCells 2000000000 is more than its "},
      {"blocks", "a.vtp", [](std::string& b) { setWord(b, firstHeader(b), kHugeBlocks); },
       "a.vtp: a compressed array declares 4294967280 blocks in "},
      {"block size", "a.vtp",
       [](std::string& b) {
         setWord(b, firstHeader(b) + 4, kHugeBlock);
         setWord(b, firstHeader(b) + 8, kHugeBlock);
       },
       "a.vtp: a compressed array declares blocks of 2147483632 bytes in "},
      // Appended arrays without the appended data section: the bounds check
      // read past the end of the file (found by fuzz_vtp, fuzz_vtu).
      {"no appended data", "a.vtu", [](std::string& b) { b.erase(b.find("<AppendedData")); },
       "a.vtu: VTK could not read the file"},
      // Found by fuzz_vtu: an array whose format attribute is missing is
      // still read from the appended data, so its header must be checked.
      {"no format attribute", "a.vtu",
       [](std::string& b) {
         replaceOnce(b, "format=\"appended\"", "fromat=\"appended\"");
         setWord(b, firstHeader(b) + 12, kHugeBlock);
       },
       "a.vtu: compressed block 0 of 2147483632 bytes declares "},
      // Found by fuzz_vtu: VTK sized the array as tuples × components (5e11
      // components asked for 4 TB and spun for minutes).
      {"components", "a.vtp",
       [](std::string& b) {
         replaceOnce(b, "NumberOfComponents=\"3\"", "NumberOfComponents=\"508075688772\"");
       },
       "a.vtp: NumberOfComponents 508075688772 for 4 tuples is more than its "},
      // Found by fuzz_vtu: no block but a partial last block; VTK's size
      // arithmetic wrapped around and it read a block table it never made.
      {"no block", "a.vtu", [](std::string& b) { setWord(b, firstHeader(b), 0); },
       "a.vtu: a compressed array declares no block but a last block of "},
      // Found by fuzz_vtu: VTK skips the first character after the tag
      // unseen, so a stray byte before '_' shifted every header by one.
      {"stray byte", "a.vtu", [](std::string& b) { b.insert(firstHeader(b) - 1, "\xb2"); },
       "a.vtu: the appended data does not start with '_'"},
      // Within what the block can inflate to, so VTK decompresses it and
      // finds the size wrong: its own message must reach the error line.
      {"wrong size", "a.vtp",
       [](std::string& b) {
         const std::size_t at = firstHeader(b);
         setWord(b, at + 4, wordAt(b, at + 4) + 8);
         setWord(b, at + 8, wordAt(b, at + 8) + 8);
       },
       "Decompression produced incorrect size"},
  };
  TempDir dir;
  for (const Mutation& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string path = dir.file(c.file);
    if (io_test::fs::path(path).extension() == ".vtu") {
      writeTetMesh(path, tetraMesh());
    } else {
      writeSurface(path, tetraSurface());
    }
    std::string bytes = io_test::readText(path);
    c.mutate(bytes);
    io_test::writeText(path, bytes);
    ::testing::internal::CaptureStderr();
    const std::string message = messageOf(path);
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(printed, "") << "VTK printed instead of reporting";
  }
}

// Found by fuzz_vtp/fuzz_vtu: VTK sizes a cell array's connectivity from its
// last offset, a value in the data. An offset beyond memory threw a
// std::bad_alloc that escaped the reader; one of 2^28 to 2^40 was allocated
// (gigabytes from a kilobyte file). The offsets are now bounded by what the
// file can hold before VTK reads it.
TEST(VtkXmlBounds, CellOffsetsBeyondTheFileAreRefusedBeforeVtkAllocates) {
  for (const char* offset : {"1125899906842624", "268435456"}) {  // 2^50 and 2^28 ids
    SCOPED_TRACE(offset);
    const std::string vtp =
        std::string(
            "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">"
            "<PolyData><Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\">"
            "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
            "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points><Polys>"
            "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 "
            "2</DataArray><DataArray type=\"Int64\" Name=\"offsets\" "
            "format=\"ascii\">") +
        offset + "</DataArray></Polys></Piece></PolyData></VTKFile>\n";
    TempDir dir;
    io_test::writeText(dir.file("a.vtp"), vtp);
    const std::string message = messageOf(dir.file("a.vtp"));
    EXPECT_NE(message.find(std::string("a.vtp: a cell offset ") + offset + " is more than its "),
              std::string::npos)
        << message;
  }
}

// Found by fuzz_vtu: a VTK_TETRA cell whose offsets give it fewer than four
// points; the reader read ids past the end of VTK's list (a null pointer).
TEST(VtkXmlBounds, TetrahedronWithTooFewPointsIsAnInputError) {
  const std::string vtu =
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">"
      "<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">"
      "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
      "0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points><Cells>"
      "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>"
      "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4 4</DataArray>"
      "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10 10</DataArray>"
      "</Cells></Piece></UnstructuredGrid></VTKFile>\n";
  TempDir dir;
  io_test::writeText(dir.file("a.vtu"), vtu);
  const std::string message = messageOf(dir.file("a.vtu"));
  EXPECT_NE(message.find("a.vtu: cell 1 (0-based) is a tetrahedron with 0 vertices"),
            std::string::npos)
      << message;
}

// The checks let real files through: VTK's writer, raw appended data with
// every compressor tetblend writes, a model with many cells spanning several
// blocks, and a short array in one partial block (its header still names
// the nominal 32 KB block size, which an LZ4 array of 60 bytes cannot hold:
// the block-size check refused every LZ4 file with a small array).
TEST(VtkXmlBounds, ValidFilesOfEveryCompressorPass) {
  TetMesh mesh = boxTetMesh(40, 40, 10, Eigen::Vector3d(1, 1, 0.25));  // 96k tets: 768 KB of ids
  const SurfaceMesh surface = boundarySurface(mesh);
  MeshDataArrays shortArrays;  // 4 values: one partial block
  shortArrays.cellData.push_back({"short", 1, std::vector<double>(4, 0.5)});
  for (const VtkCompressor compressor :
       {VtkCompressor::zlib, VtkCompressor::lz4, VtkCompressor::none}) {
    SCOPED_TRACE(vtkCompressorName(compressor));
    const VtkCompression compression{compressor, 5};
    TempDir dir;
    writeTetMesh(dir.file("a.vtu"), mesh, {}, compression);
    EXPECT_TRUE(readTetMesh(dir.file("a.vtu")).tets == mesh.tets);
    writeSurface(dir.file("a.vtp"), surface, {}, {true, compression});
    EXPECT_TRUE(readSurface(dir.file("a.vtp")).triangles == surface.triangles);
    writeSurface(dir.file("tetra.vtp"), tetraSurface(), shortArrays, {true, compression});
    EXPECT_TRUE(readSurface(dir.file("tetra.vtp")).vertices == tetraSurface().vertices);
  }
}

}  // namespace
}  // namespace tetblend

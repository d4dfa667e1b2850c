// ParaView-facing output: .vtu/.vtp read back with VTK's own readers (counts,
// cell types, array names, components and values, no reader warnings), the
// boundary surface, .pvd collections parsed back as XML, atomic writes.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "io_test_support.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"
#include "tetblend/meshing/pvd_collection.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_mesh_io.h"

namespace tetblend {
namespace {

using io_test::TempDir;
namespace fs = std::filesystem;

// Counts VTK errors and warnings: ParaView shows the same ones to the user.
class MessageCounter : public vtkCommand {
 public:
  static MessageCounter* New() { return new MessageCounter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++count; }
  int count = 0;
};

template <typename Reader>
vtkSmartPointer<Reader> readWithVtk(const std::string& path, int& messages) {
  auto reader = vtkSmartPointer<Reader>::New();
  auto counter = vtkSmartPointer<MessageCounter>::New();
  for (vtkObject* o :
       {static_cast<vtkObject*>(reader), static_cast<vtkObject*>(reader->GetExecutive())}) {
    o->AddObserver(vtkCommand::ErrorEvent, counter);
    o->AddObserver(vtkCommand::WarningEvent, counter);
  }
  reader->SetReaderErrorObserver(counter);
  reader->SetParserErrorObserver(counter);
  reader->SetFileName(path.c_str());
  reader->Update();
  messages = counter->count;
  return reader;
}

// Cube [0,1]^3 with its centre as vertex 4 (between the corners 0..3 and
// 5..8): 12 positively oriented tets, one per boundary triangle.
TetMesh centredCube() {
  TetMesh m;
  m.vertices.resize(9, 3);
  m.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 0.5, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1,
      1;
  // Outward triangles of the cube over corner indices (0..3 bottom, 5..8 top).
  const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {5, 6, 7}, {5, 7, 8}, {0, 1, 6}, {0, 6, 5},
                            {3, 8, 7}, {3, 7, 2}, {0, 5, 8}, {0, 8, 3}, {1, 2, 7}, {1, 7, 6}};
  m.tets.resize(12, 4);
  // (a, c, b, centre) is positive when (a, b, c) faces away from the centre.
  for (int f = 0; f < 12; ++f) m.tets.row(f) << faces[f][0], faces[f][2], faces[f][1], 4;
  return m;
}

std::vector<double> ramp(std::size_t n, double scale) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = scale * static_cast<double>(i) + 0.25;
  return v;
}

void expectArray(vtkDataSetAttributes* attributes, const NamedArray& expected) {
  vtkDataArray* array = attributes->GetArray(expected.name.c_str());
  ASSERT_NE(array, nullptr) << expected.name;
  EXPECT_EQ(array->GetNumberOfComponents(), expected.components);
  ASSERT_EQ(static_cast<std::size_t>(array->GetNumberOfValues()), expected.values.size());
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i) {
    EXPECT_EQ(
        array->GetComponent(i / expected.components, static_cast<int>(i % expected.components)),
        expected.values[static_cast<std::size_t>(i)]);
  }
}

TEST(VtkOutput, VtuHoldsTetsPointsAndArraysExactlyAsVtkReadsThem) {
  TempDir dir;
  const TetMesh mesh = centredCube();
  MeshDataArrays data;
  data.pointData.push_back({"displacement", 3, ramp(27, -0.1)});
  data.pointData.push_back({"weight", 1, ramp(9, 1e-7)});
  data.cellData.push_back({"volume_ratio", 1, ramp(12, 3.0)});
  data.cellData.push_back({"rotation_log", 3, ramp(36, 0.01)});
  const std::string path = dir.file("cube.vtu");
  writeTetMesh(path, mesh, data);

  int messages = -1;
  const auto reader = readWithVtk<vtkXMLUnstructuredGridReader>(path, messages);
  EXPECT_EQ(messages, 0);
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), 9);
  ASSERT_EQ(grid->GetNumberOfCells(), 12);
  EXPECT_EQ(grid->GetPoints()->GetDataType(), VTK_DOUBLE);
  for (vtkIdType v = 0; v < 9; ++v) {
    double p[3];
    grid->GetPoint(v, p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], mesh.vertices(v, c));
  }
  for (vtkIdType t = 0; t < 12; ++t) {
    EXPECT_EQ(grid->GetCellType(t), VTK_TETRA);
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    grid->GetCellPoints(t, count, ids);
    ASSERT_EQ(count, 4);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(ids[c], mesh.tets(t, c));
  }
  EXPECT_EQ(grid->GetPointData()->GetNumberOfArrays(), 2);
  EXPECT_EQ(grid->GetCellData()->GetNumberOfArrays(), 2);
  for (const NamedArray& a : data.pointData) expectArray(grid->GetPointData(), a);
  for (const NamedArray& a : data.cellData) expectArray(grid->GetCellData(), a);

  const std::string text = io_test::readText(path);
  EXPECT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
  EXPECT_NE(text.find("format=\"appended\""), std::string::npos);
}

TEST(VtkOutput, VtpSurfaceCarriesPointAndCellArrays) {
  TempDir dir;
  std::mt19937 rng(io_test::testSeed("VtkOutput.VtpSurfaceCarriesPointAndCellArrays"));
  const SurfaceMesh mesh = io_test::randomSurface(rng, 50, 80);
  MeshDataArrays data;
  data.pointData.push_back({"normal", 3, ramp(150, 0.5)});
  data.cellData.push_back({"area", 1, ramp(80, 2.0)});
  const std::string path = dir.file("s.vtp");
  writeSurface(path, mesh, data);
  int messages = -1;
  const auto reader = readWithVtk<vtkXMLPolyDataReader>(path, messages);
  EXPECT_EQ(messages, 0);
  vtkPolyData* poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfPoints(), 50);
  EXPECT_EQ(poly->GetNumberOfPolys(), 80);
  expectArray(poly->GetPointData(), data.pointData[0]);
  expectArray(poly->GetCellData(), data.cellData[0]);
}

TEST(VtkOutput, BoundaryVtpKeepsInputOrderAndMapsBack) {
  TempDir dir;
  const TetMesh mesh = centredCube();
  const NamedArray temperature{"temperature", 1, ramp(9, 10.0)};
  const std::string path = dir.file("boundary.vtp");
  writeTetMeshBoundary(path, mesh, {temperature});
  int messages = -1;
  const auto reader = readWithVtk<vtkXMLPolyDataReader>(path, messages);
  EXPECT_EQ(messages, 0);
  vtkPolyData* poly = reader->GetOutput();
  ASSERT_EQ(poly->GetNumberOfPoints(), 8);  // the centre is interior
  ASSERT_EQ(poly->GetNumberOfPolys(), 12);
  vtkDataArray* index = poly->GetPointData()->GetArray("input_vertex_index");
  ASSERT_NE(index, nullptr);
  const std::vector<int> expectedIndex = {0, 1, 2, 3, 5, 6, 7, 8};
  vtkDataArray* t = poly->GetPointData()->GetArray("temperature");
  ASSERT_NE(t, nullptr);
  for (vtkIdType v = 0; v < 8; ++v) {
    const int input = expectedIndex[static_cast<std::size_t>(v)];
    EXPECT_EQ(index->GetComponent(v, 0), input);
    EXPECT_EQ(t->GetComponent(v, 0), temperature.values[static_cast<std::size_t>(input)]);
    double p[3];
    poly->GetPoint(v, p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], mesh.vertices(input, c));
  }
  // Oracle for orientation: on a convex body centred at c, each outward
  // triangle's normal points away from c.
  const SurfaceMesh read = readSurface(path);
  const Eigen::RowVector3d centre(0.5, 0.5, 0.5);
  std::set<std::array<int, 3>> faces;
  for (Eigen::Index f = 0; f < read.triangles.rows(); ++f) {
    const Eigen::RowVector3d a = read.vertices.row(read.triangles(f, 0));
    const Eigen::RowVector3d b = read.vertices.row(read.triangles(f, 1));
    const Eigen::RowVector3d c = read.vertices.row(read.triangles(f, 2));
    EXPECT_GT((b - a).cross(c - a).dot((a + b + c) / 3.0 - centre), 0.0) << "triangle " << f;
    std::array<int, 3> key = {read.triangles(f, 0), read.triangles(f, 1), read.triangles(f, 2)};
    std::sort(key.begin(), key.end());
    faces.insert(key);
  }
  EXPECT_EQ(faces.size(), 12u);  // no face twice
}

TEST(VtkOutput, BadArraysAndEmptyMeshesAreRefusedAndWriteNothing) {
  TempDir dir;
  const TetMesh mesh = centredCube();
  const auto withCellArray = [](NamedArray a) {
    MeshDataArrays d;
    d.cellData.push_back(std::move(a));
    return d;
  };
  const std::vector<std::pair<MeshDataArrays, std::string>> cases = {
      {withCellArray({"volume ratio", 1, ramp(12, 1)}), "without whitespace"},
      {withCellArray({"", 1, ramp(12, 1)}), "non-empty"},
      {withCellArray({"q", 1, ramp(11, 1)}), "has 11 values, expected 12 tuples x 1"},
      {withCellArray({"q", 0, {}}), "has 0 components"},
      {{{{"a", 1, ramp(9, 1)}, {"a", 1, ramp(9, 1)}}, {}}, "'a' is given twice"},
  };
  for (const auto& [data, expected] : cases) {
    try {
      writeTetMesh(dir.file("x.vtu"), mesh, data);
      ADD_FAILURE() << "no InputError for " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(writeTetMesh(dir.file("x.vtu"), TetMesh{Vertices(0, 3), Tets(0, 4)}), InputError);
  EXPECT_THROW(
      writeTetMeshBoundary(dir.file("x.vtp"), mesh, {{"input_vertex_index", 1, ramp(9, 1)}}),
      InputError);
  EXPECT_THROW(writeTetMeshBoundary(dir.file("x.vtp"), mesh, {{"t", 1, ramp(8, 1)}}), InputError);
  EXPECT_THROW(writeTetMeshBoundary(dir.file("x.obj"), mesh), InputError);
  EXPECT_THROW(writeTetMesh(dir.file("no_such_dir/x.vtu"), mesh), InputError);
  EXPECT_EQ(dir.entryCount(), 0);
}

TEST(VtkOutput, PvdCollectionParsesBackWithRelativeExistingFiles) {
  TempDir dir;
  const TetMesh mesh = centredCube();
  std::vector<PvdDataSet> sets;
  const std::vector<double> times = {0.0, 0.1, 1.0 / 3.0};
  fs::create_directories(dir.path() / "frames");
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string name = "frames/f&" + std::to_string(i) + ".vtu";
    writeTetMesh(dir.file(name), mesh);
    // Alternate relative and absolute paths: both must come out relative.
    sets.push_back({times[i], i % 2 == 0 ? name : dir.file(name), static_cast<int>(i % 2)});
  }
  const std::string pvd = dir.file("series.pvd");
  writePvdCollection(pvd, sets);

  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  auto counter = vtkSmartPointer<MessageCounter>::New();
  parser->AddObserver(vtkCommand::ErrorEvent, counter);
  parser->SetFileName(pvd.c_str());
  ASSERT_EQ(parser->Parse(), 1);
  EXPECT_EQ(counter->count, 0);
  vtkXMLDataElement* root = parser->GetRootElement();
  ASSERT_NE(root, nullptr);
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  ASSERT_EQ(root->GetNumberOfNestedElements(), 1);
  vtkXMLDataElement* collection = root->GetNestedElement(0);
  EXPECT_STREQ(collection->GetName(), "Collection");
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 3);
  for (int i = 0; i < 3; ++i) {
    vtkXMLDataElement* d = collection->GetNestedElement(i);
    EXPECT_STREQ(d->GetName(), "DataSet");
    EXPECT_EQ(std::stod(d->GetAttribute("timestep")), times[static_cast<std::size_t>(i)]);
    EXPECT_EQ(std::stoi(d->GetAttribute("part")), i % 2);
    const std::string file = d->GetAttribute("file");
    EXPECT_EQ(file, "frames/f&" + std::to_string(i) + ".vtu");
    EXPECT_TRUE(fs::is_regular_file(dir.path() / file)) << file;
    int messages = -1;
    const auto reader =
        readWithVtk<vtkXMLUnstructuredGridReader>((dir.path() / file).string(), messages);
    EXPECT_EQ(messages, 0);
    EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 12);
  }
}

TEST(VtkOutput, PvdRefusesBadEntriesAndWritesNothing) {
  TempDir dir;
  const std::string pvd = dir.file("bad.pvd");
  EXPECT_THROW(writePvdCollection(pvd, {}), InputError);
  EXPECT_THROW(writePvdCollection(pvd, {{std::nan(""), "a.vtu", 0}}), InputError);
  EXPECT_THROW(writePvdCollection(pvd, {{0.0, "", 0}}), InputError);
  EXPECT_THROW(writePvdCollection(pvd, {{0.0, "a.vtu", -1}}), InputError);
  EXPECT_EQ(dir.entryCount(), 0);
}

TEST(AtomicFile, FailedWriterLeavesNoPartialFileAndKeepsTheOldOne) {
  TempDir dir;
  const std::string path = dir.file("target.txt");
  const auto failing = [](const std::string& temp) {
    io_test::writeText(temp, "partial");
    throw InputError("simulated failure");
  };
  EXPECT_THROW(writeFileAtomically(path, failing), InputError);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(dir.entryCount(), 0);
  io_test::writeText(path, "old");
  EXPECT_THROW(writeFileAtomically(path, failing), InputError);
  EXPECT_EQ(io_test::readText(path), "old");
  EXPECT_EQ(dir.entryCount(), 1);
  writeFileAtomically(path, [](const std::string& temp) { io_test::writeText(temp, "new"); });
  EXPECT_EQ(io_test::readText(path), "new");
  EXPECT_EQ(dir.entryCount(), 1);
}

}  // namespace
}  // namespace tetblend

// VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu) through VTK's own
// readers and writers. VTK reports problems through ErrorEvent/WarningEvent;
// an observer collects them (so nothing is printed) and they become
// InputError. Files are written binary appended (raw, not base64),
// compressed as asked (VtkCompression), with float64 points.

#include <cmath>
#include <filesystem>
#include <new>
#include <set>
#include <string>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkCommand.h>
#include <vtkDataCompressor.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLWriterBase.h>

#include "formats.h"
#include "polygon_fan.h"
#include "tetblend/core/error.h"
#include "tetblend/meshing/atomic_file.h"
#include "text_parsing.h"
#include "vtk_xml_bounds.h"

namespace tetblend::detail {
namespace {

// Collects VTK error and warning messages of the object it observes.
class VtkMessages : public vtkCommand {
 public:
  static VtkMessages* New() { return new VtkMessages; }
  void Execute(vtkObject*, unsigned long, void* callData) override {
    std::string message = callData != nullptr ? static_cast<const char*>(callData) : "unknown";
    // VTK prefixes "ERROR: In <file>, line <n>\n<class> (<address>): ": keep the rest.
    const std::size_t start = message.find("): ");
    if (start != std::string::npos) message = message.substr(start + 3);
    for (char& c : message) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    while (!message.empty() && message.back() == ' ') message.pop_back();
    if (!text.empty()) text += " / ";
    text += message;
  }
  std::string text;
};

// Routes the errors and warnings of `algorithm` and of its executive (which
// reports failed pipeline requests) to one collector.
vtkSmartPointer<VtkMessages> observe(vtkAlgorithm* algorithm) {
  auto messages = vtkSmartPointer<VtkMessages>::New();
  for (vtkObject* object :
       {static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive())}) {
    object->AddObserver(vtkCommand::ErrorEvent, messages);
    object->AddObserver(vtkCommand::WarningEvent, messages);
  }
  return messages;
}

template <typename Reader>
vtkSmartPointer<Reader> runReader(const std::string& path, const char* kind) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(path + ": no such file; check the path");
  }
  auto reader = vtkSmartPointer<Reader>::New();
  const auto messages = observe(reader);
  // The reader's internal reader and XML parser report through these.
  reader->SetReaderErrorObserver(messages);
  reader->SetParserErrorObserver(messages);
  if (reader->CanReadFile(path.c_str()) == 0) {
    throw InputError(path + ": not a VTK XML " + kind + " file (or unreadable): check the file");
  }
  checkVtkXmlBounds(path, readFileBytes(path));
  reader->SetFileName(path.c_str());
  // The header pass creates the decompressor, which reports through its own
  // events (unobserved, VTK prints them): observe it before the data pass.
  reader->UpdateInformation();
  if (vtkXMLDataParser* parser = reader->GetXMLParser()) {
    if (vtkDataCompressor* compressor = parser->GetCompressor()) {
      compressor->AddObserver(vtkCommand::ErrorEvent, messages);
      compressor->AddObserver(vtkCommand::WarningEvent, messages);
    }
  }
  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    // A size VTK takes from the data itself (a cell array's last offset sizes
    // its connectivity) rather than from the header checked above.
    throw InputError(path +
                     ": VTK ran out of memory for the sizes the file declares: the file is "
                     "damaged, or too large for this machine");
  }
  if (!messages->text.empty() || reader->GetErrorCode() != 0) {
    throw InputError(path + ": VTK could not read the file (" + messages->text +
                     "): the file is damaged or truncated");
  }
  return reader;
}

Vertices pointsToVertices(vtkPoints* points, const std::string& path) {
  const vtkIdType count = points != nullptr ? points->GetNumberOfPoints() : 0;
  Vertices vertices(count, 3);
  for (vtkIdType v = 0; v < count; ++v) {
    double p[3];
    points->GetPoint(v, p);
    vertices.row(v) << p[0], p[1], p[2];
    checkFiniteVertex(vertices.row(v), path, " point data", static_cast<int>(v));
  }
  return vertices;
}

vtkSmartPointer<vtkPoints> verticesToPoints(const Vertices& vertices) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vertices.rows());
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    points->SetPoint(v, vertices(v, 0), vertices(v, 1), vertices(v, 2));
  }
  return points;
}

void addArrays(vtkDataSetAttributes* attributes, const std::vector<NamedArray>& arrays,
               vtkIdType count, const std::string& path, const char* kind,
               std::set<std::string>& names) {
  for (const NamedArray& a : arrays) {
    const std::string label = std::string(kind) + " array '" + a.name + "'";
    if (a.name.empty() || a.name.find_first_of(" \t\r\n") != std::string::npos) {
      throw InputError(path + ": " + label +
                       ": names must be non-empty without whitespace "
                       "(ParaView shows them as is); rename it");
    }
    if (!names.insert(a.name).second) {
      throw InputError(path + ": " + label + " is given twice; rename one");
    }
    if (a.components < 1) {
      throw InputError(path + ": " + label + " has " + std::to_string(a.components) +
                       " components; it needs at least 1");
    }
    if (a.values.size() !=
        static_cast<std::size_t>(count) * static_cast<std::size_t>(a.components)) {
      throw InputError(path + ": " + label + " has " + std::to_string(a.values.size()) +
                       " values, expected " + std::to_string(count) + " tuples x " +
                       std::to_string(a.components) + " components");
    }
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(a.name.c_str());
    array->SetNumberOfComponents(a.components);
    array->SetNumberOfTuples(count);
    std::copy(a.values.begin(), a.values.end(), array->GetPointer(0));
    attributes->AddArray(array);
  }
}

int vtkCompressorType(VtkCompressor compressor) {
  switch (compressor) {
    case VtkCompressor::lz4:
      return vtkXMLWriterBase::LZ4;
    case VtkCompressor::none:
      return vtkXMLWriterBase::NONE;
    case VtkCompressor::zlib:
      break;
  }
  return vtkXMLWriterBase::ZLIB;
}

template <typename Writer, typename Data>
void runWriter(const std::string& path, Data* data, const VtkCompression& compression) {
  writeFileAtomically(path, [&](const std::string& tempPath) {
    auto writer = vtkSmartPointer<Writer>::New();
    const auto messages = observe(writer);
    writer->SetInputData(data);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetCompressorType(vtkCompressorType(compression.compressor));
    if (compression.compressor != VtkCompressor::none)
      writer->SetCompressionLevel(compression.level);
    writer->SetFileName(tempPath.c_str());
    if (writer->Write() != 1 || !messages->text.empty()) {
      throw InputError(path + ": VTK could not write the file (" + messages->text +
                       "): check the directory and free space");
    }
  });
}

void refuseEmpty(Eigen::Index points, Eigen::Index cells, const std::string& path) {
  if (points == 0 || cells == 0) {
    throw InputError(path + ": empty mesh (" + std::to_string(points) + " points, " +
                     std::to_string(cells) + " cells): nothing to write");
  }
}

}  // namespace

SurfaceMesh readVtp(const std::string& path) {
  const auto reader = runReader<vtkXMLPolyDataReader>(path, "PolyData");
  vtkPolyData* poly = reader->GetOutput();
  if (poly->GetNumberOfVerts() + poly->GetNumberOfLines() + poly->GetNumberOfStrips() > 0) {
    throw InputError(path +
                     ": the file holds vertex, line or strip cells; only polygons are "
                     "supported (apply Triangulate and keep only surfaces)");
  }
  SurfaceMesh mesh;
  mesh.vertices = pointsToVertices(poly->GetPoints(), path);
  vtkCellArray* polys = poly->GetPolys();
  PolygonFaces polygons;
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType f = 0; f < polys->GetNumberOfCells(); ++f) {
    polys->GetCellAtId(f, ids);
    if (ids->GetNumberOfIds() < 3) {
      throw InputError(path + ": polygon " + std::to_string(f) + " (0-based) has " +
                       std::to_string(ids->GetNumberOfIds()) + " vertices: a face needs 3");
    }
    for (vtkIdType c = 0; c < ids->GetNumberOfIds(); ++c) {
      const vtkIdType index = ids->GetId(c);
      if (index < 0 || index >= mesh.vertices.rows()) {
        throw InputError(path + ": polygon " + std::to_string(f) + " (0-based): index " +
                         std::to_string(index) + " out of range 0.." +
                         std::to_string(mesh.vertices.rows() - 1) + ": fix the file");
      }
      polygons.corners.push_back(static_cast<int>(index));
    }
    polygons.closeFace();
  }
  mesh.triangles = fanTriangles(polygons);
  return mesh;
}

TetMesh readVtu(const std::string& path) {
  const auto reader = runReader<vtkXMLUnstructuredGridReader>(path, "UnstructuredGrid");
  vtkUnstructuredGrid* grid = reader->GetOutput();
  TetMesh mesh;
  mesh.vertices = pointsToVertices(grid->GetPoints(), path);
  mesh.tets.resize(grid->GetNumberOfCells(), 4);
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType t = 0; t < grid->GetNumberOfCells(); ++t) {
    const int type = grid->GetCellType(t);
    if (type != VTK_TETRA) {
      const char* name = vtkCellTypes::GetClassNameFromTypeId(type);
      throw InputError(path + ": cell " + std::to_string(t) + " (0-based) is " +
                       (name != nullptr ? name : "unknown") + " (VTK type " + std::to_string(type) +
                       "): only linear tetrahedra (VTK_TETRA, 10) are "
                       "supported; tetrahedralise the mesh first");
    }
    grid->GetCellPoints(t, ids);
    if (ids->GetNumberOfIds() != 4) {
      throw InputError(path + ": cell " + std::to_string(t) + " (0-based) is a tetrahedron with " +
                       std::to_string(ids->GetNumberOfIds()) +
                       " vertices (its offsets are damaged): fix the file");
    }
    for (int c = 0; c < 4; ++c) {
      const vtkIdType index = ids->GetId(c);
      if (index < 0 || index >= mesh.vertices.rows()) {
        throw InputError(path + ": cell " + std::to_string(t) + " (0-based): index " +
                         std::to_string(index) + " out of range 0.." +
                         std::to_string(mesh.vertices.rows() - 1) + ": fix the file");
      }
      mesh.tets(t, c) = static_cast<int>(index);
    }
  }
  return mesh;
}

void writeVtp(const std::string& path, const SurfaceMesh& mesh, const MeshDataArrays& data,
              const std::vector<int>& inputVertexIndex, const VtkCompression& compression) {
  checkMeshForWriting(mesh, path);
  refuseEmpty(mesh.vertices.rows(), mesh.triangles.rows(), path);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(verticesToPoints(mesh.vertices));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateExact(mesh.triangles.rows(), mesh.triangles.rows() * 3);
  for (Eigen::Index f = 0; f < mesh.triangles.rows(); ++f) {
    const vtkIdType ids[3] = {mesh.triangles(f, 0), mesh.triangles(f, 1), mesh.triangles(f, 2)};
    cells->InsertNextCell(3, ids);
  }
  poly->SetPolys(cells);
  std::set<std::string> pointNames;
  std::set<std::string> cellNames;
  if (!inputVertexIndex.empty()) {
    auto index = vtkSmartPointer<vtkIntArray>::New();
    index->SetName("input_vertex_index");
    index->SetNumberOfTuples(static_cast<vtkIdType>(inputVertexIndex.size()));
    std::copy(inputVertexIndex.begin(), inputVertexIndex.end(), index->GetPointer(0));
    poly->GetPointData()->AddArray(index);
    pointNames.insert("input_vertex_index");
  }
  addArrays(poly->GetPointData(), data.pointData, mesh.vertices.rows(), path, "point", pointNames);
  addArrays(poly->GetCellData(), data.cellData, mesh.triangles.rows(), path, "cell", cellNames);
  runWriter<vtkXMLPolyDataWriter>(path, poly.Get(), compression);
}

void writeVtu(const std::string& path, const TetMesh& mesh, const MeshDataArrays& data,
              const VtkCompression& compression) {
  checkMeshForWriting(mesh, path);
  refuseEmpty(mesh.vertices.rows(), mesh.tets.rows(), path);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(verticesToPoints(mesh.vertices));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->AllocateExact(mesh.tets.rows(), mesh.tets.rows() * 4);
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) {
    const vtkIdType ids[4] = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    cells->InsertNextCell(4, ids);
  }
  grid->SetCells(VTK_TETRA, cells);
  std::set<std::string> pointNames;
  std::set<std::string> cellNames;
  addArrays(grid->GetPointData(), data.pointData, mesh.vertices.rows(), path, "point", pointNames);
  addArrays(grid->GetCellData(), data.cellData, mesh.tets.rows(), path, "cell", cellNames);
  runWriter<vtkXMLUnstructuredGridWriter>(path, grid.Get(), compression);
}

}  // namespace tetblend::detail

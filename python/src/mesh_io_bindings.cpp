// Mesh readers and writers of the Python module (surface_io.h, tet_mesh_io.h).

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "numpy_arrays.h"
#include "tetblend/meshing/surface_io.h"
#include "tetblend/meshing/tet_mesh_io.h"

namespace py = pybind11;

namespace tetblend::python {

void bindMeshIo(py::module_& m) {
  m.def(
      "read_surface",
      [](const std::string& path) {
        SurfaceMesh mesh = readSurface(path);
        return py::make_tuple(std::move(mesh.vertices), std::move(mesh.triangles));
      },
      py::arg("path"),
      "Reads a triangle surface (.obj, .off, .ply, .stl, .vtp, by extension).\n\n"
      "Returns (vertices, triangles): float64 (n, 3) positions in file units and int32 (f, 3)\n"
      "zero-based indices, in file order. Raises InputError naming the file and the problem.");
  m.def(
      "write_surface",
      [](const std::string& path, py::handle vertices, py::handle triangles) {
        SurfaceMesh mesh;
        mesh.vertices = toVertices(vertices, "vertices");
        mesh.triangles = toIndices<3>(triangles, "triangles", mesh.vertices.rows());
        writeSurface(path, mesh);
      },
      py::arg("path"), py::arg("vertices"), py::arg("triangles"),
      "Writes a triangle surface (.obj, .off, .ply or .vtp, by extension), atomically.\n\n"
      "vertices: (n, 3) real; triangles: (f, 3) integer indices into vertices. Positions\n"
      "round-trip exactly in every format.");
  m.def(
      "read_tet_mesh",
      [](const std::string& path) {
        TetMesh mesh = readTetMesh(path);
        return py::make_tuple(std::move(mesh.vertices), std::move(mesh.tets));
      },
      py::arg("path"),
      "Reads a tet mesh (.vtu, .node/.ele, .mesh, by extension).\n\n"
      "Returns (vertices, tets): float64 (n, 3) positions and int32 (t, 4) zero-based indices.");
  m.def(
      "write_tet_mesh",
      [](const std::string& path, py::handle vertices, py::handle tets) {
        TetMesh mesh;
        mesh.vertices = toVertices(vertices, "vertices");
        mesh.tets = toIndices<4>(tets, "tets", mesh.vertices.rows());
        writeTetMesh(path, mesh);
      },
      py::arg("path"), py::arg("vertices"), py::arg("tets"),
      "Writes a tet mesh (.vtu, .node/.ele or .mesh, by extension), atomically.\n\n"
      "vertices: (n, 3) real; tets: (t, 4) integer indices into vertices.");
}

}  // namespace tetblend::python

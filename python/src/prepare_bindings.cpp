// tetblend.prepare: surfaces in memory to a Model, as 'tetblend prepare'
// does from files. Only in the full module: prepare needs meshing (CGAL,
// TetGen, VTK). The GIL is released while the model is prepared.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.h"
#include "model.h"
#include "numpy_arrays.h"
#include "tetblend/pipeline/prepare_model.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

std::shared_ptr<Model> prepare(py::handle restVertices, py::handle triangles,
                               py::iterable exampleVertices, double quality,
                               std::optional<double> maxVolume, bool tetrise, bool fillHoles,
                               bool strict) {
  SurfaceMesh rest;
  rest.vertices = toVertices(restVertices, "rest_vertices");
  rest.triangles = toIndices<3>(triangles, "triangles", rest.vertices.rows());
  std::vector<SurfaceMesh> examples;
  std::vector<std::string> names;
  for (py::handle example : exampleVertices) {
    names.push_back("example_vertices[" + std::to_string(examples.size()) + "]");
    examples.push_back(SurfaceMesh{toVertices(example, names.back()), rest.triangles});
  }
  PrepareOptions options;
  options.radiusEdgeRatio = quality;
  options.maxVolume = maxVolume;
  options.tetrise = tetrise;
  options.fillHoles = fillHoles;
  options.strict = strict;
  std::vector<std::string> warnings;
  PrepareMessages messages;
  messages.warning = [&warnings](const std::string& line) { warnings.push_back(line); };
  ModelData data;
  {
    py::gil_scoped_release release;
    data = prepareModel(rest, examples, "rest_vertices", names, options, messages);
  }
  for (const std::string& line : warnings) {
    if (PyErr_WarnEx(PyExc_UserWarning, line.c_str(), 1) != 0) throw py::error_already_set();
  }
  return std::make_shared<Model>(std::move(data));
}

}  // namespace

void bindPrepare(py::module_& m) {
  m.def("prepare", &prepare, py::arg("rest_vertices"), py::arg("triangles"),
        py::arg("example_vertices"), py::kw_only(), py::arg("quality") = 2.0,
        py::arg("max_volume") = py::none(), py::arg("tetrise") = false,
        py::arg("fill_holes") = true, py::arg("strict") = false,
        "Prepares a model from surfaces in memory, as 'tetblend prepare' does from files.\n\n"
        "rest_vertices: (n, 3) real; triangles: (f, 3) integer, shared by every example;\n"
        "example_vertices: a sequence of (n, 3) real arrays, one per example, same units.\n"
        "quality: TetGen's radius-edge bound (> 1, or 0 for none; default 2). max_volume:\n"
        "TetGen's volume bound in units cubed (default None: none). tetrise: one tet per\n"
        "triangle instead of TetGen (no interior). fill_holes: close the holes of an open\n"
        "rest with triangles between its boundary vertices before TetGen runs (default True;\n"
        "Model.surface_triangles stays the input's); False refuses an open rest. strict:\n"
        "refuse examples whose tets cannot all be embedded, a rest that intersects itself\n"
        "and parts of the rest no interior fits (default: exclude those tets with a\n"
        "UserWarning, mesh a separated copy or a clean example, give those parts a tet per\n"
        "face).\n"
        "Raises InputError naming the array and the element at fault.");
}

}  // namespace tetblend::python

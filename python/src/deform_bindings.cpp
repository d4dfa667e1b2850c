// tetblend.deform: the probe/skinning deformer of `tetblend deform`
// (handle_deformer.h).

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>

#include "bindings.h"
#include "numpy_arrays.h"
#include "tetblend/pipeline/handle_deformer.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

Vertices deform(py::handle vertices, py::handle handles, py::handle weights,
                const std::string& method, double falloff) {
  const Vertices rest = toVertices(vertices, "vertices");
  const std::string text = py::module_::import("json")
                               .attr("dumps")(py::dict(py::arg("handles") = handles))
                               .cast<std::string>();
  const HandleSpec spec = parseHandleSpec(text, "handles");
  const HandleBlend blend = parseHandleBlend(method);
  Eigen::MatrixXd w;
  if (weights.is_none()) {
    w = distanceWeights(rest, spec.handles, falloff);
  } else {
    w = toMatrix(weights, "weights", rest.rows(), static_cast<Eigen::Index>(spec.handles.size()));
  }
  py::gil_scoped_release release;
  return deformByHandles(rest, spec.handles, w, blend);
}

}  // namespace

void bindDeform(py::module_& m) {
  m.def("deform", &deform, py::arg("vertices"), py::arg("handles"), py::arg("weights") = py::none(),
        py::arg("method") = "kaji", py::arg("falloff") = 2.0,
        "Moves each vertex u by a per-vertex blend of the handles' affine maps, as\n"
        "'tetblend deform' does: u -> Blend(w_1(u), ..., w_n(u), A_1, ..., A_n) u.\n\n"
        "vertices: (V, 3) real. handles: a list of dicts in the handle file's format,\n"
        "{'name': str, 'centre': [x, y, z], and 'matrix': 4x4 rows or 'translation': [3],\n"
        "'rotation': rotation vector in radians of any length, 'stretch_log': 3x3}.\n"
        "weights: (V, n) real, one column per handle, or None for distance weights\n"
        "w_i ~ (|u - c_i| + delta)^-falloff normalised (delta = 1e-3 of the bounding-box\n"
        "diagonal). method: 'lbs', 'dq' (rigid handles; alias 'dqs'), 'kaji' or 'kaji-frechet'.\n"
        "Returns float64 (V, 3).");
}

}  // namespace tetblend::python

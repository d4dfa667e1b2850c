// Model and load, shared by both Python modules (tetblend and the VTK-free
// tetblend_blend). The GIL is released while a model is loaded, saved or
// blended, so threads can blend one model concurrently.

#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.h"
#include "model.h"
#include "numpy_arrays.h"
#include "tetblend/pipeline/blended_shape.h"
#include "tetblend/pipeline/make_blender.h"

namespace py = pybind11;

namespace tetblend::python {
namespace {

py::array_t<int> intArray(const std::vector<int>& values) {
  return py::array_t<int>(static_cast<py::ssize_t>(values.size()), values.data());
}

py::list methodNames() {
  py::list names;
  for (BlendMethod method : allBlendMethods()) names.append(blendMethodName(method));
  return names;
}

constexpr const char* kBlendArguments =
    "weights: one per example, any reals (1-D, length example_count); the rest gets\n"
    "1 - sum(weights), so zeros give the rest and a unit vector an example.\n"
    "method: one of tetblend.methods() (default 'kaji', Kaji-Ochiai's Blend).\n"
    "consistency: consistent rotation logarithms across neighbouring tets (Kaji-Ochiai\n"
    "Alg. 1; kaji, liebodies). nonlinear: when the linear stitch leaves inverted tets,\n"
    "run the nonlinear stitch that removes them.\n"
    "The first blend with a (method, consistency, nonlinear) parametrises the examples and\n"
    "factors the stitch; later ones reuse them. The GIL is released: threads may blend\n"
    "one model at once.";

}  // namespace

void bindModel(py::module_& m) {
  // module_local: both modules register this class; each keeps its own.
  py::class_<Model, std::shared_ptr<Model>>(
      m, "Model", py::module_local(),
      "A prepared model: the rest tet mesh and the examples' compatible tet "
      "meshes (what\n'tetblend prepare' saves). Made by tetblend.prepare or "
      "tetblend.load.")
      .def_property_readonly(
          "rest_vertices", [](const Model& model) { return model.data().rest.vertices; },
          "float64 (n, 3): the rest tet mesh's vertices; the surface's come first.")
      .def_property_readonly(
          "tets", [](const Model& model) { return model.data().rest.tets; },
          "int32 (t, 4): the tets, positively oriented, shared by the rest and every example.")
      .def_property_readonly(
          "surface_triangles", [](const Model& model) { return model.data().surfaceTriangles; },
          "int32 (f, 3): the rest surface's triangles as the input has them: indices into\n"
          "the input's vertices (see surface_vertex_rows).")
      .def_property_readonly(
          "surface_vertex_count",
          [](const Model& model) { return model.data().surfaceVertexCount; },
          "Number of surface vertices: the first rows of rest_vertices and of every blend.")
      .def_property_readonly(
          "surface_vertex_rows",
          [](const Model& model) {
            const ModelData& data = model.data();
            std::vector<int> rows = data.inputVertexRows;
            if (rows.empty()) {
              for (int i = 0; i < data.surfaceVertexCount; ++i) rows.push_back(i);
            }
            return intArray(rows);
          },
          "int32 (u,): per input surface vertex, its row of rest_vertices and of every\n"
          "blend; copies of a vertex split along a texture or normal seam share a row, and a\n"
          "vertex no face uses has a row after the tets' vertices (blended linearly).\n"
          "blend(w)[surface_vertex_rows] with surface_triangles is the blended surface.")
      .def_property_readonly(
          "examples", [](const Model& model) { return model.data().examples; },
          "list of float64 (n, 3): each example's vertices, in the rest's order.")
      .def_property_readonly(
          "example_count", [](const Model& model) { return model.data().examples.size(); },
          "Number of examples (the length of a weight vector).")
      .def_property_readonly(
          "excluded_tets", [](const Model& model) { return intArray(model.data().excludedTets); },
          "int32 (x,): tets some example cannot embed, left out of the stitch (ascending).")
      .def_property_readonly(
          "rest_source", [](const Model& model) { return model.data().restSource; },
          "Where the rest surface came from (a file name, or 'rest_vertices').")
      .def_property_readonly(
          "example_sources", [](const Model& model) { return model.data().exampleSources; },
          "Where each example came from.")
      .def(
          "save",
          [](const Model& model, const std::string& path, std::optional<bool> fastLoad) {
            py::gil_scoped_release release;
            if (!fastLoad || *fastLoad == model.data().blendCache.has_value()) {
              writeModelFile(path, model.data());
              return;
            }
            ModelData data = model.data();
            if (*fastLoad) {
              data.blendCache = blendCacheOf(data);
            } else {
              data.blendCache.reset();
            }
            writeModelFile(path, data);
          },
          py::arg("path"), py::kw_only(), py::arg("fast_load") = py::none(),
          "Writes the model file (the format of 'tetblend prepare'), atomically. fast_load:\n"
          "True also keeps the stitch factor and the kaji parameters in it, as 'tetblend\n"
          "prepare --fast-load' (a file several times larger that loads in a fraction of the\n"
          "time); False leaves them out; None (default) keeps them if the model has them.")
      .def(
          "blend",
          [](const Model& model, py::handle weights, const std::string& method, bool consistency,
             bool nonlinear) {
            const std::vector<double> w = toWeights(weights, "weights");
            const BlendMethod blendMethod = blendMethodFromName(method);
            py::gil_scoped_release release;
            return checkedBlend(*model.blender(blendMethod, consistency, nonlinear), w, blendMethod)
                .vertices;
          },
          py::arg("weights"), py::arg("method") = "kaji", py::arg("consistency") = true,
          py::arg("nonlinear") = false,
          (std::string("The blended shape's vertices: float64 (n, 3), the model's vertex "
                       "order, in\nmodel units (the surface's vertices first: "
                       "[:surface_vertex_count]).\n\n") +
           kBlendArguments)
              .c_str())
      .def(
          "blend_with_quality",
          [](const Model& model, py::handle weights, const std::string& method, bool consistency,
             bool nonlinear) {
            const std::vector<double> w = toWeights(weights, "weights");
            const BlendMethod blendMethod = blendMethodFromName(method);
            std::optional<BlendedShape> shape;
            {
              py::gil_scoped_release release;
              shape = blendShape(*model.blender(blendMethod, consistency, nonlinear), model.data(),
                                 w, blendMethod);
            }
            py::dict cells;
            for (const NamedArray& array : shape->cellData)
              cells[array.name.c_str()] = toNumpy(array.values);
            return py::make_tuple(std::move(shape->vertices), cells);
          },
          py::arg("weights"), py::arg("method") = "kaji", py::arg("consistency") = true,
          py::arg("nonlinear") = false,
          (std::string("As blend, with the per-tet quality arrays of 'tetblend blend': returns\n"
                       "(vertices, cells), cells a dict of float64 (t,) arrays: volume_ratio "
                       "(det F_j),\ninverted (1 or 0), distortion (sigma_max / sigma_min), "
                       "rotation_angle (radians),\ntarget_residual (||F_j - B_j||_F; not for "
                       "vertex-linear) and, when the model\nexcludes tets, excluded.\n\n") +
           kBlendArguments)
              .c_str())
      .def("__repr__", [](const Model& model) {
        return "<tetblend.Model: " + std::to_string(model.data().rest.vertices.rows()) +
               " vertices, " + std::to_string(model.data().rest.tets.rows()) + " tets, " +
               std::to_string(model.data().examples.size()) + " examples>";
      });

  m.def(
      "load",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return std::make_shared<Model>(readModelFile(path));
      },
      py::arg("path"), "Reads a model file written by 'tetblend prepare' or Model.save.");
  m.def("methods", &methodNames, "The names of the blend methods, for Model.blend's method.");
}

}  // namespace tetblend::python

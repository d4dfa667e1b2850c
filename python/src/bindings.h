#pragma once
// The parts of the tetblend Python module, each adding its functions and
// classes to the module.

#include <pybind11/pybind11.h>

namespace tetblend::python {

/// read_surface, write_surface, read_tet_mesh, write_tet_mesh.
void bindMeshIo(pybind11::module_& module);

/// Model, prepare, load and the list of blend methods.
void bindModel(pybind11::module_& module);

/// Model.variations and Model.pca (after bindModel).
void bindVariations(pybind11::module_& module);

/// deform, the handle deformer.
void bindDeform(pybind11::module_& module);

}  // namespace tetblend::python

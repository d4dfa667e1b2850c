#pragma once
// The parts of the tetblend Python modules, each adding its functions and
// classes to a module. The VTK-free module tetblend_blend (the one ParaView
// imports) has the errors and bindModel; tetblend has them all.

#include <pybind11/pybind11.h>

namespace tetblend::python {

/// read_surface, write_surface, read_tet_mesh, write_tet_mesh.
void bindMeshIo(pybind11::module_& module);

/// Model, load and the list of blend methods.
void bindModel(pybind11::module_& module);

/// prepare (after bindModel; needs meshing, hence VTK).
void bindPrepare(pybind11::module_& module);

/// Model.variations and Model.pca (after bindModel).
void bindVariations(pybind11::module_& module);

/// deform, the handle deformer.
void bindDeform(pybind11::module_& module);

}  // namespace tetblend::python

// tetblend_blend: the part of the tetblend module that links no VTK — load a
// model, blend it, the quality arrays — for ParaView's pvpython, which
// crashes when Debian's VTK 9.1 is loaded into it (paraview_plugin/tetblend_plugin.py
// imports this module). Same classes and functions as in tetblend.

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "errors.h"

PYBIND11_MODULE(tetblend_blend, m) {
  using namespace tetblend::python;
  m.doc() =
      "tetblend_blend: load() a Model written by 'tetblend prepare' and Model.blend(weights)\n"
      "or Model.blend_with_quality(weights); the VTK-free subset of the tetblend module (for\n"
      "ParaView's pvpython). Arrays: vertices float64 (n, 3), tets int32 (t, 4).";
  registerErrors(m);
  bindModel(m);
}

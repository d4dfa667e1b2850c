// The tetblend Python module: prepare or load a model, blend it, read and
// write meshes. numpy arrays in and out: vertices float64 (n, 3), triangles
// int32 (f, 3), tets int32 (t, 4); positions in the units of the input.

#include <pybind11/pybind11.h>

#include "bindings.h"
#include "errors.h"

PYBIND11_MODULE(tetblend, m) {
  using namespace tetblend::python;
  m.doc() =
      "tetblend: blend compatible shapes through per-tet affine maps (Kaji-Ochiai, Lie bodies,\n"
      "dual quaternions) and a least-squares stitch. prepare() or load() a Model, then\n"
      "Model.blend(weights). Arrays: vertices float64 (n, 3), triangles int32 (f, 3), tets\n"
      "int32 (t, 4). Errors: tetblend.Error and its subclasses InputError, DomainError\n"
      "(both ValueError) and NumericalError (ArithmeticError); TypeError for a wrong dtype.";
  registerErrors(m);
  bindMeshIo(m);
  bindModel(m);
  bindPrepare(m);
  bindVariations(m);
  bindDeform(m);
}

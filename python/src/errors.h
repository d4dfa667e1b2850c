#pragma once
// tetblend's typed errors as Python exceptions (shown here for the module
// tetblend; tetblend_blend has the same classes):
//   tetblend.Error(Exception)                 base of every tetblend error
//   tetblend.InputError(Error, ValueError)    bad data: file, element, value
//   tetblend.DomainError(Error, ValueError)   a mathematical precondition failed
//   tetblend.NumericalError(Error, ArithmeticError)  a solver did not converge
// Each carries the library's one-line message unchanged. Wrong dtypes raise
// the built-in TypeError (numpy_arrays.h).

#include <pybind11/pybind11.h>

namespace tetblend::python {

/// Adds the exception classes to `module` and translates tetblend::Error and
/// its subclasses into them.
void registerErrors(pybind11::module_& module);

}  // namespace tetblend::python
